"""Publish-time snapshots: a generated function per message type that checks every field and copies what is mutable.

rclpy serialises a message when it is published, so what subscribers receive
is the message as it was at that moment, whatever the publisher does with the
object afterwards, and a field holding a value of the wrong type or out of
range fails at ``publish()``.  actors never serialises in process; instead
``Publisher.publish`` passes the message through :func:`snapshotter`'s
function for its type, which

- checks each field against its ROS type (``str`` for ``string``, an int in
  range for ``int32``, at most N items for ``T[<=N]``...) and raises
  :class:`~actors.errors.MessageValidationError` naming the field path, the
  type and the value ("field 'data' of std_msgs/msg/String: expected a str,
  got the int 42");
- returns a copy: a new struct for the message and each nested message, a new
  list or ``array.array`` for each array; immutable leaves (str, int, float,
  bytes) are shared, not copied;
- canonicalises what it accepts beyond the exact type: an int (or numpy
  number) for a float field becomes a float, a bool for an int field an int
  (rclpy accepts both: it sends 1), a numeric array given as a list, a tuple
  or a numpy array the ``array.array`` of its typecode (see
  :mod:`actors.messages.arrays`), any other array given as a tuple a list,
  a bytearray ``bytes``.

A message without fields is its own snapshot: nothing in it can change.
A publisher may name fields that its own code fills with values of the
field's canonical type that fit (a simulated scan, a stamp from the clock, a
covariance it never changes): the function made for those *trusted* fields
does not look at them, and the snapshot copies what of them is mutable all
the same (a nested message, a float array as an ``array.array``); arrays of
anything but floats are checked even there.
:func:`adopter` gives the variant for a message nobody else holds (a service
response the handler did not keep): the same checks and canonical values,
written into the message itself, with only its mutable parts copied.

The function is Python source generated from the type's field layout
(:func:`actors.messages._fields.layout`) and compiled once per type at first use:
nested messages are inlined, so a ``Twist`` is two attribute reads and an
identity test per field plus three struct copies, with no loop over a field
list and no call per field.  A numeric array that is already an ``array.array``
of its typecode is copied with one slice (such an array cannot hold a value out
of the field's range); other arrays take a C-speed fast path (the counted
element types, ``min``/``max`` for ranges) and fall back to a per-element
check only when that fails, to name the culprit or convert it.
"""

from __future__ import annotations

import functools
import itertools
import math
import numbers
import struct
import sys
from array import array
from collections.abc import Callable, Mapping
from typing import Any

from actors.errors import MessageValidationError
from actors.messages._fields import MessageLayout, layout
from actors.messages.arrays import TYPECODES, typecode
from actors.messages.idl import FLOATS, INTEGER_RANGES, OCTETS, STRINGS, FieldType

__all__ = ["snapshotter", "checker", "adopter", "snapshot", "FLOAT32_MAX", "ALONE"]

#: The largest finite float32; a float32 field holding a larger finite value is refused.
FLOAT32_MAX: float = struct.unpack("<f", b"\xff\xff\x7f\x7f")[0]

Snapshot = Callable[[Any], Any]
Trusted = frozenset[str]  # dotted paths of float array fields a publisher's own code fills validly
_cache: dict[type | tuple[type, Trusted], Snapshot] = {}  # entry points, by class (and trusted fields)
_bodies: dict[type, Snapshot] = {}  # bodies for array elements (they raise _Invalid), by class
_checks: dict[type | tuple[type, Trusted], Callable[[Any], None]] = {}  # the checks without the copy, likewise
_adopters: dict[type, Snapshot] = {}  # the snapshots in place, by class


def _held_by_one_local() -> int:
    fresh = object()
    return sys.getrefcount(fresh)


#: What ``sys.getrefcount(x)`` reports when a function's local variable ``x`` is the only
#: reference to the object: measured, not assumed, since interpreters count borrowed
#: references differently (3.14 borrows some).  More means someone else holds it too.
ALONE: int = _held_by_one_local()


def snapshotter(cls: type, trusted: Trusted = frozenset()) -> Snapshot:
    """The snapshot function of message class ``cls``, generated at its first use and cached.

    The function takes a message of exactly ``cls`` and returns its checked
    copy; it raises MessageValidationError for a field that does not fit.  A
    class that is not a generated interface type (no ``__ros_definition__``)
    gets the identity: actors cannot know its fields.  ``trusted``: dotted
    paths of fields (``"pose.covariance"``, ``"header"`` for all of it, ``""``
    for the whole message) whose values the caller's own code makes in their
    canonical type, fitting the field (a float array: an ``array.array``, a
    list of floats or a 1-D float numpy array): they are copied where mutable
    (a float array as the ``array.array`` of its typecode), not looked at.
    ValueError for a path that names no field outside arrays of messages.
    """
    return _made(_cache, cls, "copy", _identity, trusted)


def checker(cls: type, trusted: Trusted = frozenset()) -> Callable[[Any], None]:
    """The check of message class ``cls``: :func:`snapshotter`'s function without the copy.

    It raises MessageValidationError for exactly the messages the snapshot
    refuses, and returns None: for a message nobody will receive, checked as
    rclpy's serialisation would check it, with nothing copied.  ``trusted``
    fields, as for :func:`snapshotter`, are not looked at.
    """
    return _made(_checks, cls, "check", _ignore, trusted)


def adopter(cls: type) -> Snapshot:
    """:func:`snapshotter`'s function for a message of ``cls`` that nobody else holds: it returns the message itself.

    Same checks, same errors and the same canonical values as the snapshot,
    written into the message instead of a copy; nested messages and arrays
    are still copied (someone may hold those).  Only for an object whose sole
    reference is the caller's: ``sys.getrefcount(msg) == ALONE`` in the
    caller's frame, where ``msg`` is a local variable.
    """
    return _made(_adopters, cls, "adopt", _identity)


def _made(
    cache: dict[Any, Any], cls: type, mode: str, otherwise: Callable[[Any], Any], trusted: Trusted = frozenset()
) -> Any:
    # The function of ``mode`` for ``cls`` from ``cache``, generated at its first use;
    # ``otherwise`` for a class that is not a generated interface type.
    key = (cls, trusted) if trusted else cls
    found = cache.get(key)
    if found is None:
        try:
            top = layout(cls)
        except TypeError:
            if trusted:
                raise ValueError(f"trusted fields {sorted(trusted)}: {cls!r} has no fields actors knows") from None
            found = otherwise
        else:
            plain = top.placeholder and mode != "check" and not trusted
            found = _identity if plain else _generate(top, entry=True, mode=mode, trusted=trusted)
        cache[key] = found
    return found


def _ignore(msg: Any) -> None:
    return None


def snapshot(msg: Any) -> Any:
    """A checked copy of ``msg`` as subscribers would receive it (see the module docstring)."""
    return snapshotter(type(msg))(msg)


def _identity(msg: Any) -> Any:
    return msg


class _Invalid(Exception):
    """A field does not fit: its path from the message the raising function works on, and why."""

    def __init__(self, path: str, problem: str) -> None:
        super().__init__(path, problem)
        self.path = path
        self.problem = problem


def _invalid(exc: _Invalid, ros_type: str) -> MessageValidationError:
    return MessageValidationError(f"field '{exc.path}' of {ros_type}: {exc.problem}")


# -- the generator ------------------------------------------------------------------


def _generate(top: MessageLayout, *, entry: bool, mode: str = "copy", trusted: Trusted = frozenset()) -> Snapshot:
    """Compile the function for ``top``: nested messages inlined, arrays of messages through their own body.

    An entry point turns a field's _Invalid into MessageValidationError (a
    try block costs nothing until it raises); a body lets it out for the
    array holding it to prefix its index.  ``mode`` "copy" returns the
    checked copy; "adopt" writes what the checks make into ``m`` itself and
    returns it (nested messages and arrays copied all the same); "check"
    makes the same checks and returns None, copying and storing nothing.
    A ``trusted`` field ("" for all) is not looked at: copied when it is a
    message or a float array, skipped by a bare check; arrays of anything but
    floats under it are checked all the same.
    """
    copy = mode != "check"
    indent = "        " if entry else "    "
    name = f"{'check' if mode == 'check' else 'snapshot'}_{top.cls.__name__}"
    lines: list[str] = [f"def {name}(m):"]
    if entry:
        lines.append("    try:")
    if mode == "copy":
        lines.append(f"{indent}c0 = m.__copy__()")
    # __name__ makes its frames ours, not the user's, in the tracebacks actors prints
    names: dict[str, Any] = {**_HELPERS, "ros_type": top.ros_type, "__name__": __name__}
    counter = itertools.count(1)
    untrusted = set(trusted)  # the paths not met yet: any left at the end names no field

    def store(obj: str, field: str, fixed: str, indent: str) -> None:
        # Keep what a check made of the value in the copy; a bare check only needs it made.
        lines.append(f"{indent}{obj}.{field} = {fixed}" if copy else f"{indent}{fixed}")

    def emit(fields: MessageLayout, obj: str, prefix: str, indent: str, vouched: bool = False) -> None:
        # ``vouched``: the publisher trusts every field below (see Publisher.trust).
        for field in fields.fields if not fields.placeholder else ():
            path = prefix + field.name
            ftype = field.type
            untrusted.discard(path)
            sure = vouched or path in trusted
            value = f"v{next(counter)}"
            load = len(lines)
            lines.append(f"{indent}{value} = {obj}.{field.name}")
            if sure and field.nested is not None and not ftype.array:
                # Looked at no more: copied (it is mutable), and its arrays but float ones checked.
                if copy:
                    nested = f"c{next(counter)}"
                    lines.append(f"{indent}{nested} = {value}.__copy__()")
                    emit(field.nested, nested, path + ".", indent, True)
                    lines.append(f"{indent}{obj}.{field.name} = {nested}")
                else:
                    emit(field.nested, value, path + ".", indent, True)
            elif sure and (not ftype.array or ftype.base in FLOATS):
                if copy and ftype.array:
                    held = f"{value}[:] if {_array_test(ftype, value)} else array({TYPECODES[ftype.base]!r}, {value})"
                    lines.append(f"{indent}{obj}.{field.name} = {held}")
            elif ftype.array:
                call = _array_call(ftype, field.nested, value, path, names, "_numbers" if copy else "_check_numbers")
                if typecode(ftype) is None:
                    store(obj, field.name, call, indent)
                elif copy:
                    # The common case inlined: an array of the field's typecode needs only a copy.
                    lines.append(f"{indent}if {_array_test(ftype, value)}:")
                    lines.append(f"{indent}    {obj}.{field.name} = {value}[:]")
                    lines.append(f"{indent}else:")
                    lines.append(f"{indent}    {obj}.{field.name} = {call}")
                else:
                    lines.append(f"{indent}if not ({_array_test(ftype, value)}):")
                    lines.append(f"{indent}    {call}")
            elif field.nested is not None:
                cls_name = _bind(names, field.nested.cls)
                lines.append(f"{indent}if type({value}) is not {cls_name}:")
                lines.append(f"{indent}    _wrong({path!r}, {_describe(ftype)!r}, {value})")
                if copy:
                    nested = f"c{next(counter)}"
                    lines.append(f"{indent}{nested} = {value}.__copy__()")
                    emit(field.nested, nested, path + ".", indent)
                    lines.append(f"{indent}{obj}.{field.name} = {nested}")
                else:
                    emit(field.nested, value, path + ".", indent)
            else:
                test, fix = _scalar(ftype, value, path)
                lines.append(f"{indent}if {test}:")
                store(obj, field.name, fix, indent + "    ")
            if len(lines) == load + 1:
                del lines[load]  # a field nothing is done with: not even read

    top_name = "c0" if mode == "copy" else "m"
    emit(top, top_name, "", indent, "" in trusted)
    untrusted.discard("")
    if untrusted:
        raise ValueError(f"trusted fields {sorted(untrusted)}: no field of {top.ros_type} by that path")
    lines.append(f"{indent}return {top_name if copy else 'None'}")
    if entry:
        lines.append("    except _Invalid as exc:")
        lines.append("        raise _invalid(exc, ros_type) from None")
    source = "\n".join(lines) + "\n"
    exec(compile(source, f"<{mode} of {top.ros_type}>", "exec"), names)
    function: Snapshot = names[name]
    return function


def _body(nested: MessageLayout) -> Snapshot:
    found = _bodies.get(nested.cls)
    if found is None:
        found = _bodies[nested.cls] = _generate(nested, entry=False)
    return found


def _bind(names: dict[str, Any], value: Any) -> str:
    # A name for ``value`` in the generated function's globals.
    for name, bound in names.items():
        if bound is value:
            return name
    name = f"g{len(names)}"
    names[name] = value
    return name


def _scalar(ftype: FieldType, value: str, path: str) -> tuple[str, str]:
    """The fast test that a scalar needs a closer look, and the call that takes it."""
    base = ftype.base
    if base == "bool":  # the two identity tests cost less than type(): a bool is True or False
        return f"{value} is not True and {value} is not False", f"_bool({value}, {path!r})"
    if base in INTEGER_RANGES:
        low, high = INTEGER_RANGES[base]
        return (f"type({value}) is not int or not {low} <= {value} <= {high}", f"_int({value}, {path!r}, {base!r})")
    if base in FLOATS:
        if base == "float32":
            return (
                f"type({value}) is not float or not -FLOAT32_MAX <= {value} <= FLOAT32_MAX",
                f"_float({value}, {path!r}, True)",
            )
        return f"type({value}) is not float", f"_float({value}, {path!r}, False)"
    assert base in STRINGS, base
    bound = ftype.string_bound
    if bound is None:
        return f"type({value}) is not str", f"_str({value}, {path!r}, None)"
    return f"type({value}) is not str or len({value}) > {bound}", f"_str({value}, {path!r}, {bound})"


def _array_test(ftype: FieldType, value: str) -> str:
    """The test that a numeric array's value is an ``array.array`` of its typecode and size.

    Such an array needs no look at its items: an ``array('f')`` cannot hold a
    float beyond float32's range, nor an ``array('i')`` an int beyond int32's.
    """
    test = f"type({value}) is array and {value}.typecode == {TYPECODES[ftype.base]!r}"
    if ftype.array == "fixed":
        return test + f" and len({value}) == {ftype.size}"
    if ftype.array == "bounded":
        return test + f" and len({value}) <= {ftype.size}"
    return test


def _array_call(
    ftype: FieldType,
    nested: MessageLayout | None,
    value: str,
    path: str,
    names: dict[str, Any],
    numbers: str = "_numbers",
) -> str:
    # ``numbers``: the helper a numeric array goes through (``_check_numbers`` for a bare check).
    shape = (ftype.array, ftype.size, _spelled(ftype))
    if ftype.base in OCTETS:
        return f"_octets({value}, {path!r}, {shape!r})"
    if nested is not None:
        element = _bind(names, nested.cls)
        body = _bind(names, _body(nested))
        return f"_structs({value}, {path!r}, {shape!r}, {element}, {body}, {_describe(ftype)!r})"
    base = ftype.base
    if base == "bool":
        return f"_bools({value}, {path!r}, {shape!r})"
    if base in TYPECODES:
        return f"{numbers}({value}, {path!r}, {shape!r}, {base!r})"
    return f"_strs({value}, {path!r}, {shape!r}, {ftype.string_bound})"


def _spelled(ftype: FieldType) -> str:
    """The field's type as a .msg file spells it: ``float64[9]``, ``int32[<=5]``, ``string<=10[]``."""
    base = ftype.ros_type if ftype.is_nested else ftype.base
    if ftype.string_bound is not None:
        base += f"<={ftype.string_bound}"
    if ftype.array == "fixed":
        return f"{base}[{ftype.size}]"
    if ftype.array == "bounded":
        return f"{base}[<={ftype.size}]"
    return f"{base}[]" if ftype.array else base


def _describe(ftype: FieldType) -> str:
    """What a field's element must be, for error texts."""
    if ftype.is_nested:
        return f"a {ftype.ros_type}"
    if ftype.base == "bool":
        return "a bool"
    if ftype.base in INTEGER_RANGES:
        return "an int"
    if ftype.base in FLOATS:
        return "a float"
    return "a str"


# -- the slow paths the generated code calls ------------------------------------------


def _shown(value: Any) -> str:
    kind = getattr(type(value), "__ros_type__", None)
    if kind is not None:
        return f"a {kind}"
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"the {type(value).__name__} {text}"


def _wrong(path: str, expected: str, value: Any) -> Any:
    raise _Invalid(path, f"expected {expected}, got {_shown(value)}")


def _bool(value: Any, path: str) -> bool:
    return value if isinstance(value, bool) else _wrong(path, "a bool", value)


def _int(value: Any, path: str, base: str) -> int:
    if not isinstance(value, int):
        _wrong(path, "an int", value)
    low, high = INTEGER_RANGES[base]
    if not low <= value <= high:
        raise _Invalid(path, f"{value} is out of range for {base} ({low}..{high})")
    return int(value)


def _float(value: Any, path: str, single: bool) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        _wrong(path, "a float", value)
    number = float(value)
    if single and math.isfinite(number) and abs(number) > FLOAT32_MAX:
        raise _Invalid(path, f"{value!r} is out of range for float32 (±{FLOAT32_MAX:.8g})")
    return number


def _str(value: Any, path: str, bound: int | None) -> str:
    if not isinstance(value, str):
        _wrong(path, "a str", value)
    if bound is not None and len(value) > bound:
        raise _Invalid(path, f"expected at most {bound} characters (string<={bound}), got {len(value)}")
    return str(value)


Shape = tuple[str, int | None, str]  # array kind, size, the type as spelled in .msg


def _sized(items: Any, path: str, shape: Shape) -> None:
    kind, size, spelled = shape
    if kind == "fixed" and len(items) != size:
        raise _Invalid(path, f"expected {size} items ({spelled}), got {len(items)}")
    if kind == "bounded" and len(items) > size:  # type: ignore[operator]  # a bounded shape has its size: no None test on the copy path
        raise _Invalid(path, f"expected at most {size} items ({spelled}), got {len(items)}")


def _listed(value: Any, path: str, shape: Shape) -> list[Any]:
    """``value`` as a new list of its items: a list, a tuple, a numpy array, any other sequence."""
    if type(value) is list:
        return value.copy()
    if isinstance(value, (str, bytes, bytearray, Mapping)) or not hasattr(value, "__iter__"):
        raise _Invalid(path, f"expected a list ({shape[2]}), got {_shown(value)}")
    tolist = getattr(value, "tolist", None)  # numpy arrays and array.array: Python scalars at C speed
    return list(tolist() if tolist is not None else value)


def _each(items: list[Any], path: str, check: Callable[[Any, str], Any]) -> list[Any]:
    for i, item in enumerate(items):
        items[i] = check(item, f"{path}[{i}]")
    return items


def _all(items: list[Any], kind: type) -> bool:
    # Whether every item is exactly a ``kind``: counting it among the types costs half a set of them.
    return list(map(type, items)).count(kind) == len(items)


def _floats(value: Any, path: str, shape: Shape, single: bool) -> list[float]:
    if _float_vector(value):
        items = value.tolist()  # a new list of Python floats, made in C: no type to look at
    else:
        items = _listed(value, path, shape)
        if not _all(items, float):
            _sized(items, path, shape)
            return _each(items, path, lambda item, where: _float(item, where, single))
    _sized(items, path, shape)
    if single and not _fits_float32(items):
        return _each(items, path, lambda item, where: _float(item, where, True))
    return items


def _numbers(value: Any, path: str, shape: Shape, base: str) -> array[Any]:
    """``value`` as a new, checked ``array.array`` of ``base``'s typecode: from an array, a list, a numpy vector..."""
    code = TYPECODES[base]
    if type(value) is array and value.typecode == code:
        _sized(value, path, shape)
        return value[:]
    items = _floats(value, path, shape, base == "float32") if base in FLOATS else _ints(value, path, shape, base)
    return array(code, items)


def _check_numbers(value: Any, path: str, shape: Shape, base: str) -> None:
    """What :func:`_numbers` checks, without the array: a float numpy vector is checked where it is."""
    if base in FLOATS and _float_vector(value):
        _sized(value, path, shape)
        if base == "float64" or value.dtype.char == "f" or _vector_fits_float32(value):
            return
    _numbers(value, path, shape, base)  # anything else, and to name the value that does not fit


def _vector_fits_float32(vector: Any) -> bool:
    # No finite value beyond float32's range (infinities and NaN fit): whatever lies beyond
    # it is an infinity.  Five calls into numpy, none of which makes a Python float.
    numpy = sys.modules["numpy"]
    return numpy.count_nonzero(numpy.abs(vector) > FLOAT32_MAX) == numpy.count_nonzero(numpy.isinf(vector))


def _float_vector(value: Any) -> bool:
    """Whether ``value`` is a 1-D numpy array of float64 or float32 (whose ``tolist()`` gives floats)."""
    numpy = sys.modules.get("numpy")  # not imported: no numpy array can exist
    return numpy is not None and type(value) is numpy.ndarray and value.ndim == 1 and value.dtype.char in "df"


# The Struct of n float32s ("<360f"): compiled once for the lengths that recur.
_float32s = functools.lru_cache(maxsize=256)(struct.Struct)


def _fits_float32(items: list[float]) -> bool:
    # struct refuses a finite float beyond float32's range (and takes inf and nan), in C.
    try:
        _float32s(f"<{len(items)}f").pack(*items)
    except OverflowError:
        return False
    return True


def _ints(value: Any, path: str, shape: Shape, base: str) -> list[int]:
    items = _listed(value, path, shape)
    _sized(items, path, shape)
    low, high = INTEGER_RANGES[base]
    if _all(items, int) and (not items or (low <= min(items) and max(items) <= high)):
        return items
    return _each(items, path, lambda item, where: _int(item, where, base))


def _bools(value: Any, path: str, shape: Shape) -> list[bool]:
    items = _listed(value, path, shape)
    _sized(items, path, shape)
    if _all(items, bool):
        return items
    return _each(items, path, _bool)


def _strs(value: Any, path: str, shape: Shape, bound: int | None) -> list[str]:
    items = _listed(value, path, shape)
    _sized(items, path, shape)
    if _all(items, str) and (bound is None or not items or max(map(len, items)) <= bound):
        return items
    return _each(items, path, lambda item, where: _str(item, where, bound))


def _octets(value: Any, path: str, shape: Shape) -> bytes:
    if type(value) is not bytes:
        if isinstance(value, (str, Mapping)) or not hasattr(value, "__iter__"):
            raise _Invalid(path, f"expected bytes ({shape[2]}), got {_shown(value)}")
        try:
            value = bytes(value)
        except (TypeError, ValueError) as exc:
            raise _Invalid(path, f"expected bytes ({shape[2]}): {exc}") from None
    _sized(value, path, shape)
    return value


def _structs(value: Any, path: str, shape: Shape, cls: type, body: Snapshot, expected: str) -> list[Any]:
    items = _listed(value, path, shape)
    _sized(items, path, shape)
    for i, item in enumerate(items):
        if type(item) is not cls:
            _wrong(f"{path}[{i}]", expected, item)
        try:
            items[i] = body(item)
        except _Invalid as exc:
            raise _Invalid(f"{path}[{i}].{exc.path}", exc.problem) from None
    return items


_HELPERS: Mapping[str, Any] = {
    "FLOAT32_MAX": FLOAT32_MAX,
    "array": array,
    "_Invalid": _Invalid,
    "_invalid": _invalid,
    "_wrong": _wrong,
    "_bool": _bool,
    "_int": _int,
    "_float": _float,
    "_str": _str,
    "_numbers": _numbers,
    "_check_numbers": _check_numbers,
    "_bools": _bools,
    "_strs": _strs,
    "_octets": _octets,
    "_structs": _structs,
}
