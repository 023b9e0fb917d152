"""Parameters as in rclpy: declared, typed, described, range-checked, overridable, observable.

Each node has a :class:`ParameterStore`.  Values are bool, int, float, str,
bytes, or lists of bool/int/float/str; the type is inferred from the value or
taken from the descriptor.  A set is checked in this order: declared, not
read-only, right type, in range, accepted by every on-set callback; a refused
set leaves the old value and says why.  Accepted changes are published once on
``/parameter_events``.  One difference from rclpy, on purpose: an int is
accepted for a double parameter (``param set /node speed 1`` just works).

The store also answers the node's parameter services (``~/get_parameters``,
``~/set_parameters``, ``~/list_parameters``, ``~/describe_parameters``) with the
``rcl_interfaces`` types, for the command line.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from enum import IntEnum
from typing import Any, Protocol

from actors.clock import Clock
from actors.errors import ParameterError
from interfaces.rcl_interfaces.msg import (
    ListParametersResult,
    ParameterDescriptor,
    ParameterEvent,
    ParameterValue,
    SetParametersResult,
)
from interfaces.rcl_interfaces.msg import Parameter as ParameterMsg

__all__ = [
    "Parameter",
    "ParameterType",
    "ParameterHost",
    "ParameterStore",
    "value_to_msg",
    "value_from_msg",
]


class ParameterType(IntEnum):
    """Parameter types, numbered as ``rcl_interfaces/msg/ParameterType``."""

    NOT_SET = 0
    BOOL = 1
    INTEGER = 2
    DOUBLE = 3
    STRING = 4
    BYTE_ARRAY = 5
    BOOL_ARRAY = 6
    INTEGER_ARRAY = 7
    DOUBLE_ARRAY = 8
    STRING_ARRAY = 9


# ParameterValue's field for each type.
_FIELDS = {
    ParameterType.BOOL: "bool_value",
    ParameterType.INTEGER: "integer_value",
    ParameterType.DOUBLE: "double_value",
    ParameterType.STRING: "string_value",
    ParameterType.BYTE_ARRAY: "byte_array_value",
    ParameterType.BOOL_ARRAY: "bool_array_value",
    ParameterType.INTEGER_ARRAY: "integer_array_value",
    ParameterType.DOUBLE_ARRAY: "double_array_value",
    ParameterType.STRING_ARRAY: "string_array_value",
}
_ELEMENT = {bool: ParameterType.BOOL_ARRAY, int: ParameterType.INTEGER_ARRAY, float: ParameterType.DOUBLE_ARRAY, str: ParameterType.STRING_ARRAY}


def infer_type(value: Any) -> ParameterType:
    """The parameter type of ``value``; ValueError for a value no parameter can hold."""
    if value is None:
        return ParameterType.NOT_SET
    if isinstance(value, bool):
        return ParameterType.BOOL
    if isinstance(value, int):
        return ParameterType.INTEGER
    if isinstance(value, float):
        return ParameterType.DOUBLE
    if isinstance(value, str):
        return ParameterType.STRING
    if isinstance(value, (bytes, bytearray)):
        return ParameterType.BYTE_ARRAY
    if isinstance(value, (list, tuple)) and value:
        kinds = {type(v) for v in value}
        if kinds <= {int, float} and float in kinds:
            return ParameterType.DOUBLE_ARRAY
        if len(kinds) == 1 and (kind := kinds.pop()) in _ELEMENT:
            return _ELEMENT[kind]
    raise ValueError(
        f"a parameter holds bool, int, float, str, bytes or a non-empty list of one of "
        f"bool/int/float/str; got {value!r}"
    )


def _coerce(value: Any, type_: ParameterType) -> Any:
    """``value`` as stored for ``type_`` (ints widen to floats; sequences become lists)."""
    if type_ is ParameterType.DOUBLE and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    if type_ is ParameterType.DOUBLE_ARRAY:
        return [float(v) for v in value]
    if type_ is ParameterType.BYTE_ARRAY:
        return bytes(value)
    if isinstance(value, tuple):
        return list(value)
    return value


def value_to_msg(value: Any, type_: ParameterType | None = None) -> ParameterValue:
    """A Python value as ``rcl_interfaces/msg/ParameterValue``."""
    type_ = infer_type(value) if type_ is None else type_
    msg = ParameterValue(type=int(type_))
    if type_ is not ParameterType.NOT_SET:
        setattr(msg, _FIELDS[type_], _coerce(value, type_))
    return msg


def value_from_msg(msg: ParameterValue) -> Any:
    """The Python value held by an ``rcl_interfaces/msg/ParameterValue``."""
    if msg.type == ParameterType.NOT_SET:
        return None
    try:
        return getattr(msg, _FIELDS[ParameterType(msg.type)])
    except ValueError:
        raise ParameterError(f"unknown parameter type number {msg.type}") from None


class Parameter:
    """A named parameter value, as ``rclpy.parameter.Parameter``: ``Parameter(name, type_, value)``."""

    Type = ParameterType
    __slots__ = ("name", "type_", "value")

    def __init__(self, name: str, type_: ParameterType | None = None, value: Any = None) -> None:
        if type_ is None:
            type_ = infer_type(value)
        self.name = name
        self.type_ = ParameterType(type_)
        self.value = value

    def __repr__(self) -> str:
        return f"Parameter({self.name!r}, {self.type_.name}, {self.value!r})"

    def get_parameter_value(self) -> ParameterValue:
        """The value as ``rcl_interfaces/msg/ParameterValue`` (``.string_value`` etc.)."""
        return value_to_msg(self.value, self.type_)

    def to_parameter_msg(self) -> ParameterMsg:
        """This parameter as ``rcl_interfaces/msg/Parameter``."""
        return ParameterMsg(name=self.name, value=self.get_parameter_value())

    @classmethod
    def from_parameter_msg(cls, msg: ParameterMsg) -> Parameter:
        """A Parameter from ``rcl_interfaces/msg/Parameter``."""
        return cls(msg.name, ParameterType(msg.value.type), value_from_msg(msg.value))


OnSet = Callable[[list[Parameter]], SetParametersResult]


class ParameterHost(Protocol):
    """What a parameter store needs from its node: a name, a clock, services, the events topic."""

    fqn: str
    clock: Clock

    @property
    def parameter_events(self) -> Any: ...

    def create_service(self, srv_type: type, name: str, handler: Callable[[Any, Any], Any]) -> Any: ...


class ParameterStore:
    """One node's parameters, descriptors and on-set callbacks."""

    __slots__ = ("_core", "_values", "_descriptors", "_callbacks", "_overrides")

    def __init__(self, core: ParameterHost, overrides: Mapping[str, Any]) -> None:
        self._core = core
        self._values: dict[str, Parameter] = {}
        self._descriptors: dict[str, ParameterDescriptor] = {}
        self._callbacks: list[OnSet] = []
        self._overrides = dict(overrides)

    # -- declaring and reading ------------------------------------------------

    def declare(self, name: str, value: Any = None, descriptor: ParameterDescriptor | None = None,
                ignore_override: bool = False) -> Parameter:
        """Declare ``name`` with a default, overridden by the graph or spawn().

        Raises ParameterError if already declared, or if the value (default or
        override) does not fit the declared type or range.
        """
        if name in self._values:
            raise ParameterError(f"parameter {name!r} of {self._core.fqn} is already declared")
        descriptor = ParameterDescriptor() if descriptor is None else descriptor
        descriptor.name = name
        overridden = not ignore_override and name in self._overrides
        try:
            # The default (or the descriptor) fixes the type; an override must match it.
            if not descriptor.type and (value is not None or overridden):
                descriptor.type = int(infer_type(value if value is not None else self._overrides[name]))
            if overridden:
                value = self._overrides[name]
            type_ = infer_type(value) if value is not None else ParameterType(descriptor.type)
        except ValueError as exc:
            raise ParameterError(f"parameter {name!r} of {self._core.fqn}: {exc}") from None
        problem = self._check(descriptor, value, type_)
        if problem is not None:
            raise ParameterError(f"parameter {name!r} of {self._core.fqn}: {problem}")
        declared = ParameterType(descriptor.type)
        param = Parameter(name, declared, _coerce(value, declared) if value is not None else None)
        self._values[name] = param
        self._descriptors[name] = descriptor
        self._publish_event(new=[param])
        return param

    def get(self, name: str) -> Parameter:
        """The parameter ``name``; ParameterError if it is not declared."""
        try:
            return self._values[name]
        except KeyError:
            raise ParameterError(f"parameter {name!r} is not declared on {self._core.fqn}") from None

    def has(self, name: str) -> bool:
        """Whether ``name`` is declared."""
        return name in self._values

    def names(self) -> list[str]:
        """Every declared name, sorted."""
        return sorted(self._values)

    def describe(self, name: str) -> ParameterDescriptor:
        """The descriptor of ``name``; ParameterError if it is not declared."""
        self.get(name)
        return self._descriptors[name]

    def undeclare(self, name: str) -> None:
        """Forget ``name``; ParameterError if undeclared or read-only."""
        param = self.get(name)
        if self._descriptors[name].read_only:
            raise ParameterError(f"parameter {name!r} of {self._core.fqn} is read-only")
        del self._values[name], self._descriptors[name]
        self._publish_event(deleted=[param])

    # -- setting --------------------------------------------------------------

    def add_callback(self, callback: OnSet) -> OnSet:
        """Call ``callback(parameters)`` before each set; it returns a SetParametersResult."""
        self._callbacks.append(callback)
        return callback

    def remove_callback(self, callback: OnSet) -> None:
        """Stop calling ``callback``."""
        self._callbacks.remove(callback)

    def set(self, parameters: Sequence[Parameter]) -> list[SetParametersResult]:
        """Set each parameter on its own; one result per parameter, with the reason if refused."""
        results = []
        for param in parameters:
            result = self._validate(param)
            if result.successful:
                self._apply([param])
            results.append(result)
        return results

    def set_atomically(self, parameters: Sequence[Parameter]) -> SetParametersResult:
        """Set all parameters or none; the first refusal's reason is returned."""
        for param in parameters:
            result = self._validate(param, run_callbacks=False)
            if not result.successful:
                return result
        result = self._run_callbacks(list(parameters))
        if result.successful:
            self._apply(parameters)
        return result

    def _validate(self, param: Parameter, *, run_callbacks: bool = True) -> SetParametersResult:
        if param.name not in self._values:
            return SetParametersResult(successful=False, reason=f"parameter {param.name!r} is not declared")
        descriptor = self._descriptors[param.name]
        if descriptor.read_only:
            return SetParametersResult(successful=False, reason=f"parameter {param.name!r} is read-only")
        problem = self._check(descriptor, param.value, param.type_)
        if problem is not None:
            return SetParametersResult(successful=False, reason=problem)
        return self._run_callbacks([param]) if run_callbacks else SetParametersResult(successful=True)

    def _run_callbacks(self, params: list[Parameter]) -> SetParametersResult:
        for callback in self._callbacks:
            result = callback(params)
            if not isinstance(result, SetParametersResult):
                raise TypeError(f"on-set parameters callback {callback!r} must return a SetParametersResult")
            if not result.successful:
                return result
        return SetParametersResult(successful=True)

    def _check(self, descriptor: ParameterDescriptor, value: Any, type_: ParameterType) -> str | None:
        declared = ParameterType(descriptor.type) if descriptor.type else type_
        if value is None or type_ is ParameterType.NOT_SET:
            return None
        widened = declared is ParameterType.DOUBLE and type_ is ParameterType.INTEGER
        widened |= declared is ParameterType.DOUBLE_ARRAY and type_ is ParameterType.INTEGER_ARRAY
        if type_ is not declared and not widened and not descriptor.dynamic_typing:
            return f"wrong type: expected {declared.name}, got {type_.name} ({value!r})"
        for bounds in descriptor.integer_range:
            if not bounds.from_value <= value <= bounds.to_value or (
                bounds.step and (value - bounds.from_value) % bounds.step
            ):
                return f"{value} is out of range [{bounds.from_value}, {bounds.to_value}] step {bounds.step}"
        for bounds in descriptor.floating_point_range:
            low, high = bounds.from_value, bounds.to_value
            if not low - 1e-9 <= value <= high + 1e-9:
                return f"{value} is out of range [{low}, {high}]"
            if bounds.step and not math.isclose(
                round((value - low) / bounds.step) * bounds.step, value - low, abs_tol=1e-9
            ):
                return f"{value} is not on a step of {bounds.step} from {low}"
        return None

    def _apply(self, params: Sequence[Parameter]) -> None:
        changed = []
        for param in params:
            declared = ParameterType(self._descriptors[param.name].type)
            stored = Parameter(param.name, declared, _coerce(param.value, declared))
            self._values[param.name] = stored
            changed.append(stored)
        self._publish_event(changed=changed)

    def _publish_event(self, new: Sequence[Parameter] = (), changed: Sequence[Parameter] = (),
                       deleted: Sequence[Parameter] = ()) -> None:
        publisher = self._core.parameter_events
        if not publisher._subs:
            return
        event = ParameterEvent(
            stamp=self._core.clock.now().to_msg(),
            node=self._core.fqn,
            new_parameters=[p.to_parameter_msg() for p in new],
            changed_parameters=[p.to_parameter_msg() for p in changed],
            deleted_parameters=[p.to_parameter_msg() for p in deleted],
        )
        publisher.publish(event)

    # -- the parameter services --------------------------------------------------

    def serve(self) -> None:
        """Create the node's get/set/list/describe parameter services."""
        from interfaces.rcl_interfaces.srv import (
            DescribeParameters,
            GetParameters,
            ListParameters,
            SetParameters,
        )

        core = self._core
        core.create_service(GetParameters, "~/get_parameters", self._on_get)
        core.create_service(SetParameters, "~/set_parameters", self._on_set)
        core.create_service(ListParameters, "~/list_parameters", self._on_list)
        core.create_service(DescribeParameters, "~/describe_parameters", self._on_describe)

    def _on_get(self, request: Any, response: Any) -> Any:
        response.values = [
            self._values[n].get_parameter_value() if n in self._values else ParameterValue()
            for n in request.names
        ]
        return response

    def _on_set(self, request: Any, response: Any) -> Any:
        response.results = self.set([Parameter.from_parameter_msg(p) for p in request.parameters])
        return response

    def _on_list(self, request: Any, response: Any) -> Any:
        prefixes = list(request.prefixes)
        names = [n for n in self.names() if not prefixes or any(n == p or n.startswith(p + ".") for p in prefixes)]
        response.result = ListParametersResult(
            names=names, prefixes=sorted({n.rsplit(".", 1)[0] for n in names if "." in n})
        )
        return response

    def _on_describe(self, request: Any, response: Any) -> Any:
        response.descriptors = [
            self._descriptors.get(n) or ParameterDescriptor(name=n) for n in request.names
        ]
        return response
