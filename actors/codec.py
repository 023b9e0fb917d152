"""Interface types by ROS name, and their codecs: msgpack, JSON, YAML, CDR, JSON Schema, MCAP text.

The registry maps ``pkg/msg/Name`` (and ``pkg/srv/Name``, ``pkg/action/Name``,
``pkg/Name``) to the generated classes, importing a package's module only when one of its types is
first asked for.  It is process-wide, like ``sys.modules``: types are
definitions, not state.  Roots (see :mod:`actors.messages.idl`) are searched newest
registered first, the shipped ``interfaces`` root last.

``encode``/``decode`` (msgpack) and ``encode_json``/``decode_json`` are the
hot paths: encoders are shared, decoders cached per type, and nothing is
validated on encode (a struct does not check its fields when built; the
receiving side's decode does).  JSON cannot carry NaN or infinity: msgspec
writes them as ``null``, which does not decode as a float.

``encode_cdr``/``decode_cdr`` speak ROS 2's own wire format (see
:mod:`actors.messages.cdr`), ``type_hash`` names a type as ROS 2 does (see
:mod:`actors.messages.typehash`).
"""

from __future__ import annotations

import functools
import importlib
import re
import sys
from array import array
from collections.abc import Callable, Hashable
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any, TypeVar, cast

import msgspec
import msgspec.inspect as mi

from actors.core.explain import closest, explain
from actors.errors import InterfaceError, MessageValidationError, UnknownInterfaceError
from actors.messages import cdr, typehash
from actors.messages.discovery import discovered, package_sources
from actors.messages.idl import PRIMITIVES

__all__ = [
    "convert",
    "decode",
    "decode_cdr",
    "decode_json",
    "definition_text",
    "encode",
    "encode_cdr",
    "encode_json",
    "from_yaml",
    "get_type",
    "json_schema",
    "list_types",
    "register_module",
    "register_root",
    "ros_name",
    "to_builtins",
    "type_hash",
    "to_yaml",
    "load_yaml",
    "dump_yaml",
]

T = TypeVar("T")

if TYPE_CHECKING:
    _F = TypeVar("_F", bound=Callable[..., Any])

    # functools.cache, as mypy sees it: the function's own signature.  typeshed's wrapper takes
    # Hashable arguments, and mypy counts no class object (type[T]) as Hashable.
    def _cache(function: _F) -> _F: ...
else:
    _cache = functools.cache

_roots: list[Path] = []  # user roots, newest first; the shipped root is implied last
_registered: dict[str, type[Any]] = {}  # from register_module
_types: dict[str, type[Any]] = {}  # every name already resolved, in the form it was asked for


def _listed(value: Any) -> Any:
    # msgspec knows no array.array (a numeric sequence, see actors.messages.arrays) and no numpy
    # array (decode_cdr's views): each goes as a list.
    if isinstance(value, array) or hasattr(value, "dtype"):
        return value.tolist()
    raise TypeError(f"Encoding objects of type {type(value).__name__} is unsupported")


_msgpack_encoder = msgspec.msgpack.Encoder(enc_hook=_listed)
_json_encoder = msgspec.json.Encoder(enc_hook=_listed)
_msgpack_decoders: dict[Any, msgspec.msgpack.Decoder[Any]] = {}
_json_decoders: dict[Any, msgspec.json.Decoder[Any]] = {}


# --------------------------------------------------------------------------- registry


def get_type(name: str) -> type[Any]:
    """The message, service or action class named ``pkg/msg/Name``, ``pkg/srv/Name``,
    ``pkg/action/Name`` or ``pkg/Name``.

    The short form tries the message first, then the service, then the action.
    A service's ``pkg/srv/Name_Request`` and ``_Response`` are found too, and
    an action's parts and wire types (``pkg/action/Name_Goal``,
    ``Name_SendGoal``, ``Name_FeedbackMessage``...).  Raises
    UnknownInterfaceError when no registered module or root defines it.
    """
    try:
        return _types[name]
    except KeyError:
        pass
    parts = name.split("/")
    if len(parts) == 2:
        candidates = [f"{parts[0]}/{kind}/{parts[1]}" for kind in _KINDS]
    elif len(parts) == 3 and parts[1] in _KINDS:
        candidates = [name]
    else:
        raise UnknownInterfaceError(
            f"{name!r} is not an interface name (expected pkg/msg/Name, pkg/srv/Name, pkg/action/Name or pkg/Name)"
        )
    for full_name in candidates:
        found = _registered.get(full_name) or _import_type(full_name)
        if found is not None:
            _types[name] = found
            return found
    raise UnknownInterfaceError(f"unknown interface type {name!r}{_near_miss(parts)}")


def _near_miss(parts: list[str]) -> str:
    """`` (did you mean 'pkg/msg/Name'?)`` for a known type one part away from ``parts``, or nothing.

    The name is matched within its package, or, with the package misspelt, the
    packages that have a type of exactly that name: only names that exist.
    """
    pkg, leaf = parts[0], parts[-1]
    kinds = parts[1:2] if len(parts) == 3 else list(_KINDS)
    known = [t.split("/") for t in list_types()]
    mine = [t[2] for t in known if t[0] == pkg and t[1] in kinds]
    if mine:
        match = closest(leaf, mine)
        fixed = [*parts[:-1], match] if match else None
    else:
        match = closest(pkg, {t[0] for t in known if t[2] == leaf and t[1] in kinds})
        fixed = [match, *parts[1:]] if match else None
    return f" (did you mean '{'/'.join(fixed)}'?)" if fixed else ""


_KINDS = ("msg", "srv", "action")


def ros_name(type_: Any) -> str:
    """The ROS name (``pkg/msg/Name``) of an interface class or message.

    Raises TypeError for anything that is not a generated interface type.
    """
    name = getattr(type_, "__ros_type__", None)
    if not isinstance(name, str):
        raise TypeError(f"{type_!r} is not an interface type (it has no __ros_type__)")
    return name


def list_types() -> list[str]:
    """The ROS names of every message, service and action known (roots, modules, packages found), sorted.

    Services' ``_Request``/``_Response`` messages are not listed separately,
    nor the parts and wire types of an action.
    """
    from actors.messages.idl import shipped_root

    names = {
        name
        for name in _registered
        if not name.endswith(("_Request", "_Response")) and not ("/action/" in name and "_" in name)
    }
    for root in [*_roots, shipped_root()]:
        for kind in _KINDS:
            names.update(
                f"{source.parent.parent.name}/{kind}/{source.stem}" for source in root.glob(f"*/{kind}/*.{kind}")
            )
    for pkg, folder in discovered().items():
        for kind, sources in package_sources(folder).items():
            names.update(f"{pkg}/{kind}/{source.stem}" for source in sources)
    return sorted(names)


def register_root(path: str | Path) -> None:
    """Make the generated types of a user's interface root findable by name.

    The root's folder name is its top-level package (``my_root.my_pkg.msg``);
    its parent folder is appended to ``sys.path`` when missing.  The newest
    root wins over older ones and over the shipped root.  Raises
    InterfaceError when ``path`` is not a folder.
    """
    root = Path(path).resolve()
    if not root.is_dir():
        raise InterfaceError(f"{root}: no such interface root folder")
    if str(root.parent) not in sys.path:
        sys.path.append(str(root.parent))
    importlib.invalidate_caches()  # its modules may have been generated after start-up
    if root in _roots:
        _roots.remove(root)
    _roots.insert(0, root)
    _types.clear()


def register_module(module: ModuleType | str) -> list[str]:
    """Register every interface class defined in ``module`` (a module or its import name).

    Registered types win over roots.  Returns the ROS names registered.
    Raises ImportError when the module cannot be imported.
    """
    if isinstance(module, str):
        module = importlib.import_module(module)
    found = {
        ros_type: value
        for value in vars(module).values()
        if isinstance(value, type) and isinstance(ros_type := getattr(value, "__ros_type__", None), str)
    }
    _registered.update(found)
    _types.clear()
    return sorted(found)


def _import_type(full_name: str) -> type[Any] | None:
    pkg, kind, name = full_name.split("/")
    if not (pkg.isidentifier() and name.isidentifier()):
        return None
    service, _, part = name.rpartition("_")
    # A service's parts are attributes of the service class; an action's module defines
    # every part and wire type at its top level.
    attribute = service if part in ("Request", "Response") and kind == "srv" else name
    for top in [root.name for root in _roots] + ["interfaces"]:
        module_name = f"{top}.{pkg}.{kind}"
        try:
            module = importlib.import_module(module_name)
        except ModuleNotFoundError as exc:
            if exc.name and module_name.startswith(exc.name):
                continue  # this root has no such package
            raise
        found = getattr(module, attribute, None)
        if found is not None and attribute != name:
            found = getattr(found, part, None)
        if getattr(found, "__ros_type__", None) == full_name:
            return found
    return None


def _resolve(type_: type[T] | str) -> type[T]:
    return get_type(type_) if isinstance(type_, str) else type_


def _invalid(type_: Any, problem: object) -> MessageValidationError:
    return MessageValidationError(f"{_name(type_)}: {problem}")


def _name(type_: Any) -> str:
    return str(getattr(type_, "__ros_type__", getattr(type_, "__name__", repr(type_))))


def _misfit(type_: Any, exc: msgspec.MsgspecError, data: Any) -> MessageValidationError:
    """A value that does not fit, in our words: ``field 'data' of std_msgs/msg/Bool: expected a bool, ...``."""
    path, problem, unknown = explain(exc, type_, data)
    if unknown:
        return MessageValidationError(f"{_name(type_)} has no field '{path}'{problem.removeprefix('unknown field')}")
    if path:
        return MessageValidationError(f"field '{path}' of {_name(type_)}: {problem}")
    return _invalid(type_, problem)


# --------------------------------------------------------------------------- binary codecs


def encode(msg: Any) -> bytes:
    """``msg`` as msgpack bytes (a map of field names).  Raises TypeError for an unencodable value."""
    return _msgpack_encoder.encode(msg)


def decode(data: bytes, type_: type[T] | str) -> T:
    """A ``type_`` message from msgpack ``data``, fully validated.

    ``type_`` is a class or a ROS name.  Raises MessageValidationError naming
    the type and field path (``std_msgs/msg/UInt8: Expected `int` <= 255 -
    at `$.data```), UnknownInterfaceError for an unknown name.
    """
    return _decode(_msgpack_decoders, msgspec.msgpack.Decoder, data, type_)


def encode_json(msg: Any) -> bytes:
    """``msg`` as compact JSON bytes.  Raises TypeError for an unencodable value."""
    return _json_encoder.encode(msg)


def decode_json(data: bytes | str, type_: type[T] | str) -> T:
    """A ``type_`` message from JSON ``data``; raises as :func:`decode` does."""
    return _decode(_json_decoders, msgspec.json.Decoder, data, type_)


def encode_cdr(msg: Any) -> bytes:
    """``msg`` as ROS 2's CDR (little-endian, with its 4-byte header), as a ROS middleware sends it.

    Raises TypeError for an object that is not a generated message, CdrError
    (a MessageValidationError) naming the field for a value its ROS type
    cannot carry.
    """
    return cdr.encode(msg)


def decode_cdr(data: bytes | bytearray | memoryview, type_: type[T] | str, *, views: bool = False) -> T:
    """A ``type_`` message (a class or a ROS name) from CDR ``data``, either endianness.

    ``views=True`` makes every numeric array field (``uint8[]`` included,
    ``bool[]`` aside) a read-only numpy view of ``data``, no copy: see
    :func:`actors.messages.cdr.decode`.  Raises CdrError naming the type and
    field path for truncated or malformed data, UnknownInterfaceError for an
    unknown name.
    """
    return cdr.decode(data, _resolve(type_), views=views)


def type_hash(type_: type[Any] | str) -> str:
    """``RIHS01_<64 hex>``: the hash ROS 2 names a message, service or action type by (REP 2016).

    Raises UnknownInterfaceError for an unknown name, TypeError for a class
    that is not an interface type.
    """
    return typehash.type_hash(_resolve(type_))


def _decode(decoders: dict[Any, Any], factory: Callable[[type], Any], data: Any, type_: Any) -> Any:
    decoder = decoders.get(type_)
    if decoder is None:
        decoder = decoders[type_] = factory(_resolve(type_))
    try:
        return decoder.decode(data)
    except msgspec.DecodeError as exc:
        try:  # the value as it came, to say what was wrong with it
            plain = msgspec.msgpack.decode(data) if factory is msgspec.msgpack.Decoder else msgspec.json.decode(data)
        except (msgspec.DecodeError, RecursionError):
            raise _invalid(decoder.type, f"malformed data: {exc}") from None
        raise _misfit(decoder.type, exc, plain) from None


# --------------------------------------------------------------------------- plain data and YAML


def convert(obj: Any, type_: type[T] | str) -> T:
    """A ``type_`` message from plain data (dicts, lists, numbers, strings), validated.

    Missing fields take their defaults; unknown fields are errors.  Ints are
    accepted for float fields, numeric strings too (YAML reads ``1e-3`` as a
    string), and lists of ints for ``uint8[]``/``byte[]`` fields.  Raises
    MessageValidationError naming the type and the field path.
    """
    cls = _resolve(type_)
    data = _coerce(obj, _info(cls))
    try:
        return msgspec.convert(data, cls)
    except msgspec.ValidationError as exc:
        raise _misfit(cls, exc, data) from None


def from_yaml(text: str, type_: type[T] | str) -> T:
    """A ``type_`` message from YAML or JSON text, as ``ros2 topic pub`` takes it.

    ``"data: true"``, ``"{linear: {x: 0.2}, angular: {z: 0.5}}"``; an empty
    text means all defaults.  Raises MessageValidationError for text that is
    not a YAML mapping, or as :func:`convert` does.
    """
    cls = _resolve(type_)
    try:
        obj = load_yaml(text)
    except ValueError as exc:
        raise _invalid(cls, f"invalid YAML: {exc}") from None
    if obj is None:
        obj = {}
    if not isinstance(obj, dict):
        raise _invalid(cls, f"expected a mapping such as 'field: value', got {text!r}")
    return convert(obj, cls)


def to_builtins(msg: Any) -> dict[str, Any]:
    """``msg`` as plain dicts and lists in field order; bytes become lists of ints, floats stay floats."""
    return _plain(msg, _info(type(msg)))


def to_yaml(msg: Any) -> str:
    """``msg`` as block-style YAML, the shape ``ros2 topic echo`` prints (without its ``---``)."""
    return dump_yaml(to_builtins(msg))


def load_yaml(text: str, *, merge_repeated_keys: bool = False) -> Any:
    """The value of YAML (or JSON) ``text``; ValueError naming the problem in one line.

    A key repeated in one mapping keeps its last value; with
    ``merge_repeated_keys`` two mappings under the same key are merged instead
    (the later one's keys winning), as rcl reads a parameter file: ``/**:``
    written twice gives every node the parameters of both.
    """
    import yaml

    try:
        return yaml.load(text, Loader=_MergingLoader()) if merge_repeated_keys else yaml.safe_load(text)
    except yaml.YAMLError as exc:
        raise ValueError(" ".join(str(getattr(exc, "problem", None) or exc).split())) from None


def dump_yaml(data: Any, *, flow_style: bool = False) -> str:
    """Plain data as block-style YAML, keys in their order, as ROS tools print it (no line wrapping).

    ``flow_style`` writes sequences (and what they hold) in flow style, and
    mappings outside them in block style: what ``ros2 topic echo --flow-style``
    prints, its own representer leaving mappings to the block default.
    """
    import sys

    import yaml

    dumper = _FlowSequences() if flow_style else yaml.SafeDumper
    return yaml.dump(
        data, Dumper=dumper, sort_keys=False, default_flow_style=False, allow_unicode=True, width=sys.maxsize
    )


@_cache
def _FlowSequences() -> type:  # a class, made once yaml is imported
    import yaml

    class FlowSequences(yaml.SafeDumper):
        def represent_list(self, data: Any) -> Any:
            return self.represent_sequence("tag:yaml.org,2002:seq", data, flow_style=True)

    FlowSequences.add_representer(list, FlowSequences.represent_list)
    return FlowSequences


@_cache
def _MergingLoader() -> type:  # a class, made once yaml is imported
    import yaml

    class MergingLoader(yaml.SafeLoader):
        def construct_mapping(self, node: Any, deep: bool = False) -> dict[Any, Any]:
            self.flatten_mapping(node)
            mapping: dict[Any, Any] = {}
            for key_node, value_node in node.value:
                key = self.construct_object(key_node, deep=True)
                if not isinstance(key, Hashable):  # as SafeLoader says it: one YAMLError, not a TypeError
                    raise yaml.constructor.ConstructorError(
                        "while constructing a mapping", node.start_mark, "found unhashable key", key_node.start_mark
                    )
                value = self.construct_object(value_node, deep=True)
                earlier = mapping.get(key)
                if isinstance(earlier, dict) and isinstance(value, dict):
                    value = _merged(earlier, value)
                mapping[key] = value
            return mapping

    MergingLoader.add_constructor("tag:yaml.org,2002:map", MergingLoader.construct_mapping)
    return MergingLoader


def _merged(earlier: dict[Any, Any], later: dict[Any, Any]) -> dict[Any, Any]:
    merged = dict(earlier)
    for key, value in later.items():
        before = merged.get(key)
        merged[key] = _merged(before, value) if isinstance(before, dict) and isinstance(value, dict) else value
    return merged


@_cache
def _info(cls: type) -> mi.Type:
    return mi.type_info(cls)


def _plain(value: Any, info: mi.Type) -> Any:
    if isinstance(info, mi.StructType):
        return {field.name: _plain(getattr(value, field.name), field.type) for field in info.fields}
    if isinstance(info, (mi.ListType, mi.BytesType)) and hasattr(value, "dtype"):
        value = value.tolist()  # a numpy view (decode_cdr's views=True): Python numbers, as YAML takes
    if isinstance(info, mi.ListType):
        return [_plain(item, info.item_type) for item in value]
    if isinstance(info, mi.BytesType):
        return list(value)
    if isinstance(info, mi.FloatType):
        return float(value)
    return value


def _coerce(obj: Any, info: mi.Type) -> Any:
    """``obj`` with the loosenings :func:`convert` allows applied; msgspec checks the rest."""
    if isinstance(info, mi.StructType) and isinstance(obj, dict):
        fields = {field.encode_name: field.type for field in info.fields}
        return {key: _coerce(value, fields[key]) if key in fields else value for key, value in obj.items()}
    if isinstance(info, mi.ListType) and isinstance(obj, list):
        return [_coerce(item, info.item_type) for item in obj]
    try:
        if isinstance(info, mi.BytesType) and isinstance(obj, list):
            return bytes(obj)
        if isinstance(info, mi.FloatType) and isinstance(obj, str):
            return float(obj)
    except (TypeError, ValueError):
        pass  # left as is, so that msgspec's error names the field
    return obj


# --------------------------------------------------------------------------- schemas


def json_schema(type_: type[Any] | str) -> dict[str, Any]:
    """The JSON Schema of a message type: an ``object`` titled with its ROS name.

    Nested message types are under ``$defs``, each titled with its ROS name.
    Raises UnknownInterfaceError for an unknown name.
    """
    cls = _resolve(type_)
    dependencies = _dependencies(cls)
    schema = msgspec.json.schema(cls)
    definitions: dict[str, Any] = schema["$defs"]
    # msgspec names a definition after its class, or after its module path
    # when two classes share a name; mirror that to find each class's entry.
    short_names = [c.__name__ for c in (cls, *dependencies)]
    for dependency in (cls, *dependencies):
        key = dependency.__name__
        if short_names.count(key) > 1:
            key = f"{dependency.__module__}.{dependency.__qualname__}"
        definitions[key]["title"] = dependency.__ros_type__
        definitions[key].pop("description", None)  # the generated docstring only repeats the name
        if dependency is cls:
            top = definitions.pop(key)
    return {**top, "$defs": definitions} if definitions else top


def definition_text(type_: type[Any] | str) -> str:
    """The MCAP ``ros2msg`` schema text of a message type, exactly as rosbag2 writes it.

    Its own definition, then for each message type it names (in the order of
    a sorted set of the names *as written*, ``std_msgs/Header`` or
    ``pkg/msg/Name``, a bare ``Name`` taken as the same package's), depth
    first and each once: a newline, a line of 80 ``=``, ``MSG: `` and the
    name as written, and that type's text.  Raises UnknownInterfaceError for
    an unknown name.
    """
    cls = _resolve(type_)
    seen: set[str] = set()

    def text_of(cls: type[Any]) -> str:
        text = cls.__ros_definition__
        for name in sorted(_named_types(text, cls.__ros_type__.split("/")[0])):
            if name not in seen:
                seen.add(name)
                text += "\n" + "=" * 80 + f"\nMSG: {name}\n" + text_of(get_type(name))
        return text

    return text_of(cls)


# rosbag2 finds a definition's types with this pattern: the first word of a line, less any [..].
_FIELD_TYPE = re.compile(r"(?:^|\n)\s*([a-zA-Z0-9_/]+)(?:\[[^\]]*\])?\s+")
_PRIMITIVE_NAMES = frozenset(PRIMITIVES) | {"byte", "char"}


def _named_types(text: str, package: str) -> set[str]:
    """The message types a definition names, as written (``Name`` becomes ``package/Name``)."""
    found = set()
    for match in _FIELD_TYPE.finditer(text):
        name = match.group(1)
        if name not in _PRIMITIVE_NAMES:
            found.add(name if "/" in name else f"{package}/{name}")
    return found


def _dependencies(cls: type[Any]) -> list[type[Any]]:
    """Message classes ``cls`` uses, transitively, each once, depth first."""
    found: dict[type[Any], None] = {}

    def visit(info: mi.StructType) -> None:
        for field in info.fields:
            nested = field.type.item_type if isinstance(field.type, mi.ListType) else field.type
            if isinstance(nested, mi.StructType) and nested.cls not in found:
                found[nested.cls] = None
                visit(nested)

    visit(cast(mi.StructType, _info(cls)))  # a message class is a msgspec Struct
    return list(found)
