"""The graph file (``graph.toml``): its schema, loading, and spawning its nodes.

Every key is optional except each node's ``use``::

    [runtime]
    clock = "wall"            # or "virtual"
    duration = 0.0            # seconds; 0 runs until stopped
    log_level = "info"

    [supervisor]
    strategy = "one_for_one"  # one_for_all, rest_for_one
    intensity = 3
    period = 5.0
    backoff = 0.1
    max_backoff = 2.0

    [[nodes]]
    use = "nodes.talker:MinimalPublisher"
    name = "talker"
    namespace = ""
    params = { }
    params_file = "params.yaml"   # ROS parameter file (node_name: ros__parameters:), under params
    remap = { topic = "chatter" }
    restart = "transient"     # permanent, temporary
    delay = 0.0               # start this node so many seconds later (launch's TimerAction)

    [args]                    # launch arguments: name:=value on the command line
    speed = 0.2               # a default; or { default = 0.2, description = "...", choices = [...] }
    world = { description = "the map" }   # no default: required
    # "$(var speed)" in any value below is the argument's value (see actors.launch.graph_args)

    [[include]]               # another graph file's nodes, before this file's own
    file = "world.toml"       # relative to this file, or a shipped graph's name
    args = { map = "signs" }  # its arguments
    namespace = "robot1"      # pushed onto every node it gives

    [transport]               # other processes (and ROS 2 with rmw_zenoh_cpp) see this graph
    kind = "zenoh"
    domain_id = 0             # default: $ROS_DOMAIN_ID, else 0
    connect = ["tcp/127.0.0.1:7447"]
    listen = ["tcp/127.0.0.1:7447", "tcp/127.0.0.1:0"]
    mode = "peer"             # or "client" (through a router)
    config = "zenoh.json5"    # a Zenoh config file for everything else (relative to this file)

``use`` is found as :mod:`actors.launch.importing` says: the folder of the
graph file that names it (an included file's, for its nodes), then the working
directory, then installed packages (``nodes`` and ``world`` are the shipped
``actors.nodes`` and ``actors.world`` when nothing else has them, and always
for the shipped graphs); a ``params_file`` is beside the file that names it.  ``load_graph`` also takes the bare name
of a shipped graph (``turtlebot``).

Any error names the file, the key path and the problem, as one line.  Beyond
each key's type, the file must name at least one node; numbers must be finite
and in range (durations, periods and delays at most :data:`~actors.core.tomlfile.MAX_SECONDS`,
``intensity`` at most 1,000,000, ``max_backoff`` at least ``backoff``); and
no two nodes may have the same full name, delayed or not (a node without a
``name`` has the one its class gives ``super().__init__``, when the class
says it plainly).
"""

from __future__ import annotations

import ast
import inspect
import textwrap
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Annotated, Any, Literal

import msgspec

from actors.core.tomlfile import MAX_SECONDS, convert_toml, read_toml
from actors.errors import GraphFileError, InvalidNameError, RosArgsError
from actors.launch.graph_args import argument_values, declared_arguments, substitute
from actors.launch.importing import find_graph, import_use
from actors.launch.rosargs import load_params_file, node_key_matches, values_for
from actors.messages.discovery import add_workspace
from actors.ros.names import expand, fully_qualified, normalize_namespace, validate_node_name
from actors.ros.node import Node
from actors.system.supervisor import RestartType, Strategy, SupervisorPolicy

__all__ = [
    "RuntimeSection",
    "SupervisorSection",
    "NodeEntry",
    "TransportSection",
    "IncludeEntry",
    "GraphFile",
    "load_graph",
    "argument_rows",
    "import_node_class",
    "default_node_name",
]

Seconds = Annotated[float, msgspec.Meta(ge=0, le=MAX_SECONDS)]


class RuntimeSection(msgspec.Struct, frozen=True, kw_only=True, forbid_unknown_fields=True):
    """``[runtime]``: how the graph runs."""

    clock: Literal["wall", "virtual"] = "wall"
    duration: Seconds = 0.0
    log_level: Literal["debug", "info", "warn", "warning", "error", "fatal"] = "info"


class SupervisorSection(msgspec.Struct, frozen=True, kw_only=True, forbid_unknown_fields=True):
    """``[supervisor]``: restart strategy, intensity and backoff."""

    strategy: Strategy = Strategy.ONE_FOR_ONE
    intensity: Annotated[int, msgspec.Meta(ge=0, le=1_000_000)] = 3
    period: Annotated[float, msgspec.Meta(gt=0, le=MAX_SECONDS)] = 5.0
    backoff: Seconds = 0.1
    max_backoff: Seconds = 2.0

    def __post_init__(self) -> None:
        if self.max_backoff < self.backoff:
            raise ValueError(f"max_backoff ({self.max_backoff:g}) must be at least backoff ({self.backoff:g})")

    def policy(self) -> SupervisorPolicy:
        """These settings as the runtime's SupervisorPolicy."""
        return SupervisorPolicy(**msgspec.structs.asdict(self))


class NodeEntry(msgspec.Struct, frozen=True, kw_only=True, forbid_unknown_fields=True):
    """``[[nodes]]``: one node to start."""

    use: str
    name: str | None = None
    namespace: str = ""
    params: dict[str, Any] = {}
    params_file: str | None = None  # a ROS parameter file, relative to the graph file; params win over it
    remap: dict[str, str] = {}
    restart: RestartType = RestartType.TRANSIENT
    delay: Seconds = 0.0  # seconds after the graph starts, as launch's TimerAction


class TransportSection(msgspec.Struct, frozen=True, kw_only=True, forbid_unknown_fields=True):
    """``[transport]``: how the graph reaches other processes (see actors.transport.zenoh.config).

    ``None`` means the default: ``$ROS_DOMAIN_ID`` for the domain; for the
    endpoints, a peer that listens on and connects to loopback only.
    """

    kind: Literal["zenoh"] = "zenoh"
    domain_id: Annotated[int, msgspec.Meta(ge=0, le=232)] | None = None
    connect: list[str] | None = None
    listen: list[str] | None = None
    mode: Literal["peer", "client"] = "peer"
    config: str = ""


class IncludeEntry(msgspec.Struct, frozen=True, kw_only=True, forbid_unknown_fields=True):
    """``[[include]]``: another graph file's nodes, as launch's IncludeLaunchDescription gives them.

    Only its ``[args]`` and nodes are read: how the graph runs is the including file's to say.
    """

    file: str
    args: dict[str, Any] = {}
    namespace: str = ""


class GraphFile(msgspec.Struct, frozen=True, kw_only=True, forbid_unknown_fields=True):
    """A whole graph file."""

    args: dict[str, Any] = {}  # as declared: actors.launch.graph_args reads them
    include: list[IncludeEntry] = []
    runtime: RuntimeSection = RuntimeSection()
    supervisor: SupervisorSection = SupervisorSection()
    nodes: list[NodeEntry] = []
    transport: TransportSection | None = None


def import_node_class(use: str, graph: Path | None = None) -> type[Node]:
    """Import ``"module:Class"`` as graph file ``graph`` names it, and check it is a Node subclass.

    Where the module comes from is :mod:`actors.launch.importing`'s business (the graph's
    folder, the working directory, installed code).  ValueError says why it
    cannot be had.
    """
    module_name, sep, attr = use.partition(":")
    if not sep or not module_name or not attr:
        raise ValueError(f"expected 'module:Class', got {use!r}")
    module = import_use(module_name, graph)
    cls: Any = module
    for part in attr.split("."):
        cls = getattr(cls, part, None)
        if cls is None:
            raise ValueError(f"module {module_name!r} has no {attr!r}")
    if not (isinstance(cls, type) and issubclass(cls, Node)):
        raise ValueError(f"{use!r} is not a subclass of actors.Node")
    return cls


def load_graph(
    path: str | Path, arguments: Mapping[str, Any] | Sequence[tuple[str, Any]] = ()
) -> tuple[GraphFile, list[type[Node]]]:
    """Load and check a graph file: schema, values, names, and that every ``use`` imports.

    ``arguments`` give its ``[args]`` values (text from a command line is read
    as YAML).  Returns the decoded file, with the nodes of its includes first
    and ``$(var name)`` substituted, and the node classes, in that order.
    Raises GraphFileError naming the file, the key path and the problem;
    nothing has started then, so a graph with a mistake anywhere never starts half-way.
    """
    path = _find(path)
    graph, sources = _read(Path(path), dict(arguments), ())
    add_workspace(Path(path).parent)  # the graph's workspace: its interface packages import by name
    if not graph.nodes:
        raise GraphFileError(f'{path}: no nodes: a graph needs at least one [[nodes]] table with use = "module:Class"')
    if graph.transport is not None and graph.transport.config:
        # A Zenoh config file is found beside the graph file, as a relative path reads.
        config = Path(path).parent / graph.transport.config
        if not config.is_file():
            raise GraphFileError(f"{path}: transport.config: no such file: {config}")
        graph = msgspec.structs.replace(graph, transport=msgspec.structs.replace(graph.transport, config=str(config)))
    classes = []
    nodes = list(graph.nodes)
    taken: dict[str, str] = {}  # full node names known before start, and the entry that has each
    for i, entry in enumerate(graph.nodes):
        origin, key = sources[i]
        try:
            cls = import_node_class(entry.use, origin)
        except ValueError as exc:
            raise GraphFileError(f"{origin}: {key}.use: {exc}") from None
        classes.append(cls)
        try:
            if entry.name is not None:
                validate_node_name(entry.name)
            namespace = normalize_namespace(entry.namespace)
        except InvalidNameError as exc:
            field = "name" if entry.name is not None and "node name" in str(exc) else "namespace"
            raise GraphFileError(f"{origin}: {key}.{field}: {exc}") from None
        for source, target in entry.remap.items():
            try:
                expand(source, namespace, entry.name or "node", what="remap source")
                expand(target, namespace, entry.name or "node", what="remap target")
            except InvalidNameError as exc:
                raise GraphFileError(f"{origin}: {key}.remap.{source}: {exc}") from None
        name = entry.name or default_node_name(cls)
        if entry.params_file is not None:
            params = _file_params(origin.parent / entry.params_file, name, namespace, f"{origin}: {key}")
            nodes[i] = msgspec.structs.replace(entry, params={**params, **entry.params})
        if name is not None:
            fqn = fully_qualified(namespace, name)
            if fqn in taken:
                where = "name" if entry.name else "use"
                raise GraphFileError(
                    f"{origin}: {key}.{where}: a node named {fqn} is already {taken[fqn]}; "
                    "give one of them another name"
                )
            taken[fqn] = key if origin == Path(path) else f"{key} of {origin}"
    return msgspec.structs.replace(graph, nodes=nodes), classes


def argument_rows(path: str | Path) -> list[tuple[str, str, str | None, list[Any] | None]]:
    """The graph file's own arguments for :func:`~actors.launch.graph_args.format_arguments`."""
    path = _find(path)
    declared = declared_arguments(read_toml(path, GraphFileError).get("args", {}), str(path))
    return [(name, arg.description, arg.default_text(), arg.choices) for name, arg in declared.items()]


def _find(path: str | Path) -> Path:
    try:
        return find_graph(path)
    except FileNotFoundError as exc:
        raise GraphFileError(str(exc)) from None


_MAX_INCLUDES = 32  # deep enough for any real tree of files; a cycle stops here at the latest


def _read(path: Path, arguments: dict[str, Any], chain: tuple[Path, ...]) -> tuple[GraphFile, list[tuple[Path, str]]]:
    """One file with its arguments applied and its includes' nodes before its own; beside each
    node, the file it comes from and its key there."""
    if len(chain) > _MAX_INCLUDES or path.resolve() in chain:
        shown = " -> ".join(str(p) for p in (*chain, path.resolve()))
        raise GraphFileError(f"{chain[-1]}: include: the files include each other: {shown}")
    data = read_toml(path, GraphFileError)
    declared = declared_arguments(data.get("args", {}), str(path))
    values = argument_values(declared, arguments, str(path))
    rest = substitute({k: v for k, v in data.items() if k != "args"}, values, str(path))
    graph = convert_toml({**rest, "args": data.get("args", {})}, GraphFile, path, GraphFileError)
    nodes: list[NodeEntry] = []
    sources: list[tuple[Path, str]] = []
    for i, include in enumerate(graph.include):
        local = path.parent / include.file
        try:
            file = local if local.exists() else find_graph(include.file)
        except FileNotFoundError as exc:
            raise GraphFileError(f"{path}: include[{i}].file: {exc}") from None
        included, origins = _read(file, include.args, (*chain, path.resolve()))
        for entry, (origin, key) in zip(included.nodes, origins, strict=True):
            if include.namespace:
                namespace = "/".join(p.strip("/") for p in (include.namespace, entry.namespace) if p.strip("/"))
                entry = msgspec.structs.replace(entry, namespace="/" + namespace)
            nodes.append(entry)
            sources.append((origin, key))
    for i, entry in enumerate(graph.nodes):
        nodes.append(entry)
        sources.append((path, f"nodes[{i}]"))
    return msgspec.structs.replace(graph, nodes=nodes), sources


def _file_params(file: Path, name: str | None, namespace: str, where: str) -> dict[str, Any]:
    """What a ROS parameter file gives the node ``name``: matched by its full name, as rcl does.

    ``name`` is the entry's, or the one its class gives itself plainly; None when
    only running it would tell.
    """
    try:
        rules = load_params_file(file)
    except RosArgsError as exc:
        raise GraphFileError(f"{where}.params_file: {exc}") from None
    if name is not None:
        return values_for(rules, fully_qualified(namespace, name))
    # A name computed at run time is known only once the node runs: only keys that match any
    # node name (wildcards) can be applied here.
    named = [rule.node_key for rule in rules if not _any_name(rule.node_key, namespace)]
    if named:
        raise GraphFileError(
            f"{where}.params_file: {file} has parameters for {', '.join(named)}: give the node a `name` "
            f"so that they can be matched"
        )
    return values_for(rules, fully_qualified(namespace, "any"))


def _any_name(node_key: str, namespace: str) -> bool:
    return all(node_key_matches(node_key, fully_qualified(namespace, name)) for name in ("a", "b"))


def default_node_name(cls: type[Node]) -> str | None:
    """The name ``cls`` gives ``super().__init__`` when its source says it plainly, else None.

    ``super().__init__("talker")`` or ``super().__init__(node_name="talker")``
    in the class's own ``__init__`` (or the nearest base that has one).  A name
    computed at run time is None: the runtime still refuses a duplicate when
    it starts the node.  Read once per class (its source does not change while
    the process runs, and reading it is not cheap: a launch of many nodes asks often).
    """
    if cls not in _default_names:
        _default_names[cls] = _default_name(cls)
    return _default_names[cls]


_default_names: dict[type[Node], str | None] = {}


def _default_name(cls: type[Node]) -> str | None:
    for klass in cls.__mro__:
        if klass is Node or "__init__" not in vars(klass):
            continue
        try:
            tree = ast.parse(textwrap.dedent(inspect.getsource(vars(klass)["__init__"])))
        except (OSError, TypeError, SyntaxError):
            return None
        for node in ast.walk(tree):
            if (
                isinstance(node, ast.Call)
                and isinstance(node.func, ast.Attribute)
                and node.func.attr == "__init__"
                and isinstance(node.func.value, ast.Call)
                and getattr(node.func.value.func, "id", None) == "super"
            ):
                given = (
                    node.args[0] if node.args else next((k.value for k in node.keywords if k.arg == "node_name"), None)
                )
                if isinstance(given, ast.Constant) and isinstance(given.value, str):
                    return given.value
                return None
        return None
    return None
