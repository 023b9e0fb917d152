"""Parameters as in rclpy: declared, typed, described, range-checked, overridable, observable.

Each node has a :class:`ParameterStore`.  Values are bool, int, float, str,
bytes, or lists of bool/int/float/str; a parameter's type is fixed when it is
declared (from its default, or given as ``Parameter.Type.X``) unless its
descriptor asks for ``dynamic_typing``.  A set runs, as rclpy's does: the
pre-set callbacks (which may change the list), then for each parameter the
checks (declared, not read-only, right type, in range) and the on-set callbacks,
which may refuse it; a refused set leaves the old values and says why; an
accepted one is published once on ``/parameter_events`` and then seen by the
post-set callbacks.  Declaring runs the on-set callbacks too, which may refuse
the default.  Setting a dynamically typed parameter to NOT_SET undeclares it.

One difference from rclpy, on purpose: an int is accepted wherever a double is
declared (and int lists for double arrays), and stored as a float, so that
``param set /node speed 1`` and a graph's ``speed = 1`` just work; rclpy refuses
them as the wrong type.

A parameter's value and type (``Parameter``, ``Parameter.Type``) are in
``actors.ros.parameter``, re-exported here; the node's parameter services, which
answer the command line and parameter clients from a store, are in
``actors.ros._param_services``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any, Protocol

import msgspec

from actors.errors import (
    InvalidParameterException,
    InvalidParameterTypeException,
    InvalidParameterValueException,
    ParameterAlreadyDeclaredException,
    ParameterImmutableException,
    ParameterNotDeclaredException,
    ParameterUninitializedException,
)
from actors.ros.parameter import (
    PARAMETER_SEPARATOR_STRING,
    TYPES,
    Parameter,
    ParameterType,
    value_from_msg,
    value_to_msg,
    widen,
)
from actors.ros.time import ROSClock
from interfaces.rcl_interfaces.msg import (
    ListParametersResult,
    ParameterDescriptor,
    ParameterEvent,
    ParameterValue,
    SetParametersResult,
)

__all__ = [
    # Defined in actors.ros.parameter, imported from here by code written before it.
    "Parameter",
    "ParameterType",
    "PARAMETER_SEPARATOR_STRING",
    "value_to_msg",
    "value_from_msg",
    "OnSet",
    "PreSet",
    "PostSet",
    "ParameterHost",
    "ParameterStore",
]

_REL_TOL = 1e-6  # how close a double must be to a range's bound or step, as rclpy


OnSet = Callable[[list[Parameter]], SetParametersResult]
PreSet = Callable[[list[Parameter]], list[Parameter]]
PostSet = Callable[[list[Parameter]], None]


class ParameterHost(Protocol):
    """What a parameter store needs from its node: a name, a clock, the events topic."""

    fqn: str
    clock: ROSClock

    @property
    def parameter_events(self) -> Any: ...


class ParameterStore:
    """One node's parameters, descriptors and set callbacks (rclpy's parameter half of a Node).

    ``overrides`` are the values given from outside (graph, ``spawn(params=)``,
    the node's ``parameter_overrides``): a declaration takes its value from them
    before its default.  With ``allow_undeclared``, setting or reading an
    undeclared name is allowed, as rclpy's ``allow_undeclared_parameters``.
    """

    __slots__ = ("_core", "_values", "_descriptors", "_pre", "_on_set", "_post", "_overrides", "allow_undeclared")

    def __init__(self, core: ParameterHost, overrides: Mapping[str, Any], *, allow_undeclared: bool = False) -> None:
        self._core = core
        self._values: dict[str, Parameter] = {}
        self._descriptors: dict[str, ParameterDescriptor] = {}
        # Newest first, as rclpy calls them.  Tuples, replaced when one is added or removed:
        # most nodes add none, and three empty lists per node were three more objects
        # for the collector to traverse.
        self._pre: tuple[PreSet, ...] = ()
        self._on_set: tuple[OnSet, ...] = ()
        self._post: tuple[PostSet, ...] = ()
        self._overrides = dict(overrides)
        self.allow_undeclared = allow_undeclared

    @property
    def overrides(self) -> dict[str, Any]:
        """The values given from outside, by name."""
        return self._overrides

    # -- declaring --------------------------------------------------------------

    def declare(
        self, name: str, value: Any = None, descriptor: ParameterDescriptor | None = None, ignore_override: bool = False
    ) -> Parameter:
        """Declare ``name``: see :meth:`actors.ros.node.Node.declare_parameter`."""
        if not isinstance(name, str):
            raise TypeError(f"a parameter name is a str, got {name!r}")
        if not name:
            raise InvalidParameterException(f"a parameter name must not be empty (node {self._core.fqn})")
        if descriptor is None:
            # A name alone declares a dynamically typed parameter, as rclpy does.
            descriptor = ParameterDescriptor(dynamic_typing=value is None)
        elif not isinstance(descriptor, ParameterDescriptor):
            raise TypeError(f"parameter {name!r}: the descriptor must be a ParameterDescriptor, got {descriptor!r}")
        else:
            descriptor = _copy(descriptor)
        descriptor.name = name
        if isinstance(value, ParameterType):
            if value is ParameterType.NOT_SET:
                raise ValueError(f"parameter {name!r} cannot be declared with the type NOT_SET")
            if descriptor.dynamic_typing:
                raise ValueError(f"parameter {name!r}: give a type or dynamic_typing=True, not both")
            descriptor.type = int(value)
            value = None
        else:
            if isinstance(value, ParameterValue):
                descriptor.type, value = (0 if descriptor.dynamic_typing else value.type), value_from_msg(value)
            elif not descriptor.dynamic_typing:
                descriptor.type = int(ParameterType.from_parameter_value(value))
            if not descriptor.dynamic_typing and descriptor.type == ParameterType.NOT_SET:
                raise ValueError(
                    f"parameter {name!r} needs a default value, a type (Parameter.Type.X) "
                    f"or a descriptor with dynamic_typing=True"
                )
        if not ignore_override and name in self._overrides:
            value = self._overrides[name]
        if name in self._values:
            raise ParameterAlreadyDeclaredException(f"parameter {name!r} of {self._core.fqn} is already declared")
        try:
            param = Parameter(name, value=value)
        except TypeError as exc:
            raise InvalidParameterTypeException(f"parameter {name!r} of {self._core.fqn}: {exc}") from None
        result = self._set_common([param], {name: descriptor}, allow_not_set=True)
        if not result.successful:
            error = (
                InvalidParameterTypeException
                if result.reason.startswith("Wrong parameter type")
                else InvalidParameterValueException
            )
            raise error(f"parameter {name!r} of {self._core.fqn}: {result.reason}")
        return self._values[name]

    def declare_default(self, param: Parameter, *, announce: bool = True) -> None:
        """Declare ``param`` as it is, or from its override: every node's ``use_sim_time``.

        What :meth:`declare` does with a default and no descriptor, without the
        checks such a default always passes, while no set callback could refuse
        it; an override (of any type) takes :meth:`declare`'s whole path.
        ``announce=False`` publishes no parameter event for it.
        """
        name = param.name
        if name in self._overrides or self._on_set or self._post:
            self.declare(name, param.value)
            return
        if name in self._values:
            raise ParameterAlreadyDeclaredException(f"parameter {name!r} of {self._core.fqn} is already declared")
        self._values[name] = param
        self._descriptors[name] = ParameterDescriptor(name=name, type=int(param.type_))
        if announce:
            self._publish_event(new=(param,))

    def declare_many(
        self, namespace: str, parameters: Sequence[tuple[Any, ...]], ignore_override: bool = False
    ) -> list[Parameter]:
        """Declare ``(name[, value[, descriptor]])`` tuples under ``namespace.``, each in turn.

        A name given twice is declared once, with its last entry's value and
        descriptor (rclpy ends there too); the list returned has one
        Parameter per entry.
        """
        for index, entry in enumerate(parameters):
            if not isinstance(entry, tuple) or not 1 <= len(entry) <= 3:
                raise TypeError(f"parameters[{index}] must be (name[, value[, descriptor]]), got {entry!r}")
        names = [(f"{namespace}.{e[0]}" if namespace else e[0]) for e in parameters]
        already = [n for n in names if n in self._values]
        if already:
            raise ParameterAlreadyDeclaredException(f"parameters {already} of {self._core.fqn} are already declared")
        last = dict(zip(names, parameters))
        declared = {
            name: self.declare(
                name,
                entry[1] if len(entry) > 1 else None,
                entry[2] if len(entry) > 2 else None,
                ignore_override=ignore_override,
            )
            for name, entry in last.items()
        }
        return [declared[name] for name in names]

    def undeclare(self, name: str) -> None:
        """Forget ``name``; ParameterNotDeclaredException, ParameterImmutableException if read-only."""
        param = self._declared(name)
        if self._descriptors[name].read_only:
            raise ParameterImmutableException(f"parameter {name!r} of {self._core.fqn} is read-only")
        del self._values[name], self._descriptors[name]
        self._publish_event(deleted=[param])

    # -- reading ----------------------------------------------------------------

    def _declared(self, name: str) -> Parameter:
        try:
            return self._values[name]
        except KeyError:
            raise ParameterNotDeclaredException(f"parameter {name!r} is not declared on {self._core.fqn}") from None

    def get(self, name: str) -> Parameter:
        """The parameter ``name``.

        Raises ParameterNotDeclaredException (unless undeclared parameters are
        allowed: then an unset Parameter), ParameterUninitializedException for a
        parameter declared with only a type and never given a value.
        """
        if name not in self._values and self.allow_undeclared:
            return Parameter(name)
        param = self._declared(name)
        if param.type_ is ParameterType.NOT_SET and not self._descriptors[name].dynamic_typing:
            raise ParameterUninitializedException(
                f"parameter {name!r} of {self._core.fqn} was declared as "
                f"{ParameterType(self._descriptors[name].type).name} but has no value yet"
            )
        return param

    def get_or(self, name: str, alternative: Parameter | None = None) -> Parameter:
        """The parameter ``name`` if declared and set, else ``alternative`` (an unset Parameter if None)."""
        param = self._values.get(name)
        if param is None or param.type_ is ParameterType.NOT_SET:
            return Parameter(name) if alternative is None else alternative
        return param

    def get_type(self, name: str) -> ParameterType:
        """The current type of ``name`` (NOT_SET when unset or, if allowed, undeclared)."""
        if name not in self._values and self.allow_undeclared:
            return ParameterType.NOT_SET
        return self._declared(name).type_

    def by_prefix(self, prefix: str) -> dict[str, Parameter]:
        """Parameters named ``prefix.<rest>`` keyed by ``<rest>`` (every parameter for ``""``)."""
        if prefix:
            prefix += PARAMETER_SEPARATOR_STRING
        return {n[len(prefix) :]: p for n, p in self._values.items() if n.startswith(prefix)}

    def has(self, name: str) -> bool:
        """Whether ``name`` is declared."""
        return name in self._values

    def names(self) -> list[str]:
        """Every declared name, in the order they were declared (rclpy's ``list_parameters`` order)."""
        return list(self._values)

    def list_parameters(self, prefixes: Sequence[str] = (), depth: int = 0) -> ListParametersResult:
        """Names under ``prefixes`` (all when empty) at most ``depth`` dots deep (0: any), and their prefixes.

        Raises TypeError for ``prefixes`` that is not a sequence of str (a
        lone str would be read letter by letter) or a ``depth`` not an int,
        ValueError for a negative depth.
        """
        if isinstance(prefixes, str) or not all(isinstance(p, str) for p in prefixes):
            raise TypeError(f"prefixes must be a list of str, got {prefixes!r}")
        if not isinstance(depth, int):
            raise TypeError(f"depth must be an int, got {depth!r}")
        if depth < 0:
            raise ValueError(f"depth must be >= 0, got {depth}")
        sep = PARAMETER_SEPARATOR_STRING

        def shallow(rest: str) -> bool:
            return depth == 0 or rest.count(sep) < depth

        names = [
            n
            for n in self.names()
            if (not prefixes and shallow(n))
            or any(n == p or (n.startswith(p + sep) and shallow(n[len(p) + 1 :])) for p in prefixes)
        ]
        found = []
        for n in names:
            if sep in n and (prefix := n.rsplit(sep, 1)[0]) not in found:
                found.append(prefix)
        return ListParametersResult(names=names, prefixes=found)

    def describe(self, name: str) -> ParameterDescriptor:
        """The descriptor of ``name`` (a blank one if undeclared and allowed); ParameterNotDeclaredException."""
        if name not in self._descriptors and self.allow_undeclared:
            return ParameterDescriptor()
        self._declared(name)
        return self._descriptors[name]

    def set_descriptor(
        self, name: str, descriptor: ParameterDescriptor, alternative_value: ParameterValue | None = None
    ) -> ParameterValue:
        """Give ``name`` a new descriptor, keeping its value if it fits, else ``alternative_value``.

        Raises ParameterNotDeclaredException, ParameterImmutableException for a
        read-only parameter, InvalidParameterValueException when neither value fits.
        """
        if name not in self._values and self.allow_undeclared:
            return ParameterValue()
        current = self._declared(name)
        if self._descriptors[name].read_only:
            raise ParameterImmutableException(f"parameter {name!r} of {self._core.fqn} is read-only")
        descriptor = _copy(descriptor)
        descriptor.name = name
        if not descriptor.type and not descriptor.dynamic_typing:
            descriptor.type = self._descriptors[name].type  # keep the declared type (rclpy would refuse)
        candidates = [current]
        if alternative_value is not None:
            candidates.append(Parameter(name, ParameterType(alternative_value.type), value_from_msg(alternative_value)))
        reason = ""
        for candidate in candidates:
            problem = self._check(candidate, descriptor, check_read_only=False)
            if problem is None:
                self._values[name] = _stored(candidate, descriptor)
                if descriptor.dynamic_typing:
                    descriptor.type = int(candidate.type_)
                self._descriptors[name] = descriptor
                return self._values[name].get_parameter_value()
            reason = problem
        raise InvalidParameterValueException(
            f"parameter {name!r} of {self._core.fqn}: {candidates[-1].value!r} "
            f"does not fit the new descriptor: {reason}"
        )

    # -- callbacks --------------------------------------------------------------

    @property
    def callbacks(self) -> tuple[tuple[PreSet, ...], tuple[OnSet, ...], tuple[PostSet, ...]]:
        """The pre-set, on-set and post-set callbacks, each newest first (the order they run in)."""
        return self._pre, self._on_set, self._post

    def add_pre_set_callback(self, callback: PreSet) -> None:
        """Call ``callback(parameters)`` first on each set; it returns the list to set instead."""
        self._pre = (_callable(callback), *self._pre)

    def add_on_set_callback(self, callback: OnSet) -> OnSet:
        """Call ``callback(parameters)`` to accept or refuse each set and declaration."""
        self._on_set = (_callable(callback), *self._on_set)
        return callback

    def add_post_set_callback(self, callback: PostSet) -> None:
        """Call ``callback(parameters)`` after each accepted set and declaration."""
        self._post = (_callable(callback), *self._post)

    def remove_pre_set_callback(self, callback: PreSet) -> None:
        """Stop calling ``callback``; ValueError if it was not added."""
        self._pre = _without(self._pre, callback)

    def remove_on_set_callback(self, callback: OnSet) -> None:
        """Stop calling ``callback``; ValueError if it was not added."""
        self._on_set = _without(self._on_set, callback)

    def remove_post_set_callback(self, callback: PostSet) -> None:
        """Stop calling ``callback``; ValueError if it was not added."""
        self._post = _without(self._post, callback)

    # -- setting ----------------------------------------------------------------

    def set(self, parameters: Sequence[Parameter]) -> list[SetParametersResult]:
        """Set each parameter on its own (each atomically); one result per parameter.

        Raises ParameterNotDeclaredException at the first undeclared name
        (unless allowed); the parameters before it stay set.
        """
        return [self.set_atomically([param]) for param in parameters]

    def set_atomically(self, parameters: Sequence[Parameter]) -> SetParametersResult:
        """Set all parameters or none; the refusal's reason is returned.

        Raises ParameterNotDeclaredException when a name is undeclared (unless
        allowed), TypeError for something that is not a Parameter.
        """
        params = list(parameters)
        if self._pre:
            params = [p for callback in self._pre for p in callback(params)]
            if not params:
                # rclpy's words: console output reads the same
                reason = (
                    "parameter list cannot be empty, this might be due to pre_set_parameters_callback "
                    "modifying the original parameters list."
                )
                return SetParametersResult(successful=False, reason=reason)
        for param in params:
            if not isinstance(param, Parameter):
                raise TypeError(f"set_parameters takes Parameters, got {param!r}")
        undeclared = [p.name for p in params if p.name not in self._values]
        if undeclared and not self.allow_undeclared:
            raise ParameterNotDeclaredException(f"parameters {undeclared} are not declared on {self._core.fqn}")
        return self._set_common(params)

    def _set_common(
        self,
        params: list[Parameter],
        descriptors: dict[str, ParameterDescriptor] | None = None,
        *,
        allow_not_set: bool = False,
    ) -> SetParametersResult:
        # Check each parameter against its descriptor (the given ones when declaring).
        for param in params:
            descriptor = (descriptors or self._descriptors).get(param.name)
            if descriptor is not None:
                problem = self._check(param, descriptor, check_read_only=descriptors is None)
                if problem is not None:
                    return SetParametersResult(successful=False, reason=problem)
        stored = [_stored(p, (descriptors or self._descriptors).get(p.name)) for p in params]
        for callback in self._on_set:
            result = callback(stored)
            if not isinstance(result, SetParametersResult):
                raise TypeError(f"on-set parameters callback {callback!r} must return a SetParametersResult")
            if not result.successful:
                return result
        new: list[Parameter] = []
        changed: list[Parameter] = []
        deleted: list[Parameter] = []
        for param in stored:
            name = param.name
            if param.type_ is ParameterType.NOT_SET and not allow_not_set:
                deleted.append(param)
                self._values.pop(name, None)
                self._descriptors.pop(name, None)
                continue
            if descriptors is not None:
                self._descriptors[name] = descriptors[name]
            elif name not in self._descriptors:  # an undeclared name, allowed: dynamically typed
                self._descriptors[name] = ParameterDescriptor(name=name, dynamic_typing=True)
            if self._descriptors[name].dynamic_typing:
                self._descriptors[name].type = int(param.type_)
            previous = self._values.get(name)
            (new if previous is None or previous.type_ is ParameterType.NOT_SET else changed).append(param)
            self._values[name] = param
        self._publish_event(new=new, changed=changed, deleted=deleted)
        for after in self._post:
            after(stored)
        return SetParametersResult(successful=True)

    def _check(self, param: Parameter, descriptor: ParameterDescriptor, *, check_read_only: bool) -> str | None:
        """Why ``param`` does not fit ``descriptor``, or None."""
        if check_read_only and descriptor.read_only:
            return f"parameter {param.name!r} is read-only"
        given = param.type_
        if descriptor.dynamic_typing:
            pass  # any type goes, NOT_SET too (it undeclares)
        elif given is ParameterType.NOT_SET:
            if param.name in self._values:
                return "Static parameter cannot be undeclared"  # rclpy's words, as ros2 param prints them
        elif given is not (declared := TYPES[descriptor.type]) and not declared.check(param.value):
            return f"Wrong parameter type, expected 'Type.{declared.name}' got 'Type.{given.name}'"  # rclpy's words
        value = widen(param.value, TYPES[descriptor.type] if descriptor.type else given)
        # Ranges apply to numbers only: a range on a string parameter is ignored, as in rclpy.
        if isinstance(value, int) and not isinstance(value, bool) and descriptor.integer_range:
            return _outside_integer_range(value, descriptor.integer_range[0])
        if isinstance(value, float) and descriptor.floating_point_range:
            return _outside_floating_point_range(value, descriptor.floating_point_range[0])
        return None

    def _publish_event(
        self, new: Sequence[Parameter] = (), changed: Sequence[Parameter] = (), deleted: Sequence[Parameter] = ()
    ) -> None:
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


def _copy(descriptor: ParameterDescriptor) -> ParameterDescriptor:
    # The store fills in name and type: never in the caller's object.
    return msgspec.structs.replace(descriptor)


def _stored(param: Parameter, descriptor: ParameterDescriptor | None) -> Parameter:
    """``param`` as stored under ``descriptor``: an int given for a DOUBLE becomes a float."""
    if descriptor is None or descriptor.dynamic_typing:
        return param
    declared = TYPES[descriptor.type]
    if param.type_ is declared or param.type_ is ParameterType.NOT_SET:
        return param
    return Parameter(param.name, declared, param.value)  # an int for a DOUBLE, [] for a typed array


def _without(callbacks: tuple[Any, ...], callback: Any) -> tuple[Any, ...]:
    rest = list(callbacks)
    rest.remove(callback)  # ValueError when it was never added, as list.remove
    return tuple(rest)


def _callable(callback: Any) -> Any:
    if not callable(callback):
        raise TypeError(f"a parameters callback must be callable, got {callback!r}")
    return callback


def _outside_integer_range(value: int, bounds: Any) -> str | None:
    low, high = sorted((bounds.from_value, bounds.to_value))
    if value in (low, high):
        return None
    if not low < value < high:
        return f"{value} is out of range [{low}, {high}]"
    if bounds.step and (value - low) % bounds.step:
        return f"{value} is not on a step of {bounds.step} from {low}"
    return None


def _outside_floating_point_range(value: float, bounds: Any) -> str | None:
    low, high = sorted((bounds.from_value, bounds.to_value))
    if math.isclose(value, low, rel_tol=_REL_TOL) or math.isclose(value, high, rel_tol=_REL_TOL):
        return None
    if not low < value < high:
        return f"{value} is out of range [{low}, {high}]"
    if bounds.step and not math.isclose(
        low + round((value - low) / bounds.step) * bounds.step, value, rel_tol=_REL_TOL
    ):
        return f"{value} is not on a step of {bounds.step} from {low}"
    return None
