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
two without changing either, and without a second runtime.

**Script nodes are native nodes driven by the script.**  A node the script
creates is built by the native constructor (it is registered, the command line
sees it, its parameter services answer) with a
:class:`~actors.compat.dispatch.ScriptActor` instead of the runtime's actor.
Its entities' callbacks are the overlay's *catchers*: they only queue the item
(message, timer tick, request, response) on the overlay's entity and wake the
node's executor, which takes one item at a time, asks the callback group, and
runs the script's callback on its own thread, exactly as in rclpy.  Queues keep
rclpy's semantics: a subscription holds at most its QoS depth, ticks of a
timer nobody took merge into one, a service request waits for the spin, a
client's future is done only once its node has been spun after the response
came.

**One execution model: the turn** (:mod:`~actors.compat.turns`).  The runtime
lives on a thread of its own (:class:`~actors.compat.session.Session`).  A
thread that touches the runtime's state holds the session's turn and runs the
call itself; a blocking call is a wait that gives the turn away.  On the wall
clock the turn is a lock the loop lets go while it waits in ``select``; on the
virtual clock it is a baton handed on in the order parties were woken, so
nothing moves while a script runs and a run is repeatable by construction.
DESIGN.md draws one ``spin_until_future_complete`` through it.

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
