"""The rclpy overlay: unmodified rclpy programs run on actors.

``actors run talker.py`` runs a script written for ROS 2 as it is: inside that
process ``import rclpy`` is :mod:`actors.compat.rclpy` and ``from std_msgs.msg
import String`` is ``interfaces.std_msgs.msg`` (:mod:`actors.compat.overlay`).
Outside it nothing is shadowed: a real rclpy in the same environment keeps
working.  ``install()``/``uninstall()`` (or ``with overlaid():``) do the same for
code that wants it explicitly, and :mod:`actors.testing` grades scripts with it.

The design
==========

rclpy is blocking and thread-based: a script's main thread calls
``rclpy.spin(node)`` and callbacks run *in the thread that spins* (or in an
executor's pool threads), only while it spins.  actors is an asyncio runtime:
nodes are actors whose callbacks run in one event loop.  The overlay joins the
two without changing either.

**Two kinds of threads.**  The runtime (its loop, every node of a ``--graph``
file, the control endpoint) lives on a thread of its own, a
:class:`~actors.compat.session.Session`.  The script runs on the main thread, as
it would under ROS (signals, KeyboardInterrupt, ``sys.exit`` behave as usual),
plus whatever threads its executors start.  Script threads never touch the
runtime's state: every call into it (create a publisher, publish, declare a
parameter, read the graph) runs on the loop thread and returns its result
(:meth:`Session.call`), and a publish returns once every subscriber has the
message, so the script may reuse it.  Blocking calls (``wait_for_service``,
``Client.call``, ``Rate.sleep``, spinning) wait on the runtime without blocking
it.

**Script nodes are native nodes driven by the script.**  A node the script
creates is built by the native constructor (it is registered, the command line
sees it, its parameter services answer) with a
:class:`~actors.compat.dispatch.ScriptActor` instead of the runtime's actor.
Its entities' callbacks are the overlay's *catchers*: on the loop thread they
only queue the item (message, timer tick, request, response) on the overlay's
entity and wake the node's executor.  The executor, on the script's thread,
takes one item at a time, asks the callback group, and runs the script's
callback there.  So a node's callbacks run only while the script spins it, in
the spinning thread or the executor's pool, exactly as in rclpy, and a script's
main thread never races its own callbacks.  The node's own native entities
(parameter services, and with them on-set parameter callbacks) wait the same
way and run on the loop thread while the spinning thread waits for them.
Nodes of a graph file are ordinary actors and keep running on their own.

Queues keep rclpy's semantics: a subscription holds at most its QoS depth
(KEEP_LAST drops the oldest, counted as a drop), ticks of a timer nobody took
merge into one, a service request waits for the spin (its catcher awaits the
answer in a task of its own, so a slow service never holds up the node's other
entities), a client's future is done only once its node has been spun after
the response came.  Callback groups (mutually exclusive, reentrant, a script's
own subclass) decide what runs at the same time; coroutine callbacks are rclpy
tasks stepped by the executor, resumed when the Future they await is done.

**Virtual time.**  On the virtual clock the loop jumps to the next timer when
nothing is ready, but never while a script thread is *busy*: running Python
that might look at the clock or publish.  A thread is *waiting* when it is
blocked in one of the overlay's waits (spinning with nothing to do, a service
wait, ``Rate.sleep``, ``time.sleep`` under the launcher on virtual time).
:mod:`~actors.compat.activity` keeps a token per script thread, and per callback
handed to an executor until it has run (it may run on a pool thread); whoever
wakes a waiting thread marks it busy first, and every timeout is a loop timer,
so all waits are measured on the runtime clock and a wake-up is never lost to
a jump.  A thread a script starts is busy from ``start()`` until it first waits
on the runtime (``threading.Thread(target=rclpy.spin)`` must not miss a tick,
however late the OS runs it); before that, it does not count while it is
parked in a wait of :mod:`threading` outside the overlay's calls (a pool's idle
worker).  A thread blocked elsewhere (``thread.join()``, a lock, a socket)
counts as busy and holds virtual time still, except one that has never waited
on the runtime: after 5 s of real time a warning names it and virtual time goes
on without it (a thread reading the keyboard must not stop a run).

**What it costs native users: nothing.**  Native nodes, publish, delivery and
timers run exactly the code they ran before; the hooks the overlay uses are a
node's actor handed in through :class:`~actors.ros.node.SpawnRequest` and the
virtual-time loop's ``threads_busy()``.
"""

from __future__ import annotations

from actors.compat.overlay import install, installed, overlaid, uninstall
from actors.compat.rclpy.context import use_session
from actors.compat.session import Session

__all__ = ["install", "installed", "overlaid", "uninstall", "Session", "use_session"]
