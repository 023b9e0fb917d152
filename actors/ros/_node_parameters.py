"""The parameter half of Node: rclpy's parameter methods, each delegating to the node's ParameterStore."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Protocol

from actors.ros.parameter_store import OnSet, Parameter, ParameterStore, ParameterType, PostSet, PreSet
from interfaces.rcl_interfaces.msg import (
    ListParametersResult,
    ParameterDescriptor,
    ParameterValue,
    SetParametersResult,
)

__all__ = ["ParameterMethods"]


class _HasParams(Protocol):
    @property
    def params(self) -> ParameterStore: ...


class ParameterMethods:
    """rclpy's ``Node`` parameter API; mixed into :class:`actors.ros.node.Node`."""

    _core: _HasParams

    def declare_parameter(
        self,
        name: str,
        value: Any = None,
        descriptor: ParameterDescriptor | None = None,
        ignore_override: bool = False,
    ) -> Parameter:
        """Declare a parameter and return it with its value: an override (graph, spawn()) or the default.

        ``value`` is the default, which fixes the type; or ``Parameter.Type.X``
        to declare a typed parameter with no value yet (reading it raises
        ParameterUninitializedException until it is set); or None with
        ``ParameterDescriptor(dynamic_typing=True)`` (or no descriptor) for a
        parameter whose type may change.  The descriptor's name and type are
        filled in.  The on-set callbacks run and may refuse the value; the
        post-set callbacks run after.

        Raises ParameterAlreadyDeclaredException, InvalidParameterException for
        an empty name, InvalidParameterTypeException when an override has
        another type, InvalidParameterValueException when a range or an on-set
        callback refuses the value, ValueError for a typed declaration without
        a type (a None default without dynamic typing, ``Parameter.Type.NOT_SET``).
        """
        return self._core.params.declare(name, value, descriptor, ignore_override)

    def declare_parameters(
        self, namespace: str, parameters: Sequence[tuple[Any, ...]], ignore_override: bool = False
    ) -> list[Parameter]:
        """Declare ``(name[, value[, descriptor]])`` tuples as ``namespace.name``, as rclpy.

        Raises ParameterAlreadyDeclaredException, before declaring any, when one
        is already declared; otherwise what :meth:`declare_parameter` raises, at
        the first that fails (those before it stay declared).
        """
        return self._core.params.declare_many(namespace, parameters, ignore_override)

    def undeclare_parameter(self, name: str) -> None:
        """Forget a parameter: ParameterNotDeclaredException, ParameterImmutableException if read-only."""
        self._core.params.undeclare(name)

    def has_parameter(self, name: str) -> bool:
        """Whether ``name`` is declared."""
        return self._core.params.has(name)

    def get_parameter(self, name: str) -> Parameter:
        """The parameter ``name`` (``.value``).

        Raises ParameterNotDeclaredException (with ``allow_undeclared_parameters``:
        returns an unset Parameter instead), ParameterUninitializedException for
        a parameter declared with a type and never given a value.
        """
        return self._core.params.get(name)

    def get_parameters(self, names: Sequence[str]) -> list[Parameter]:
        """Several parameters by name; raises as :meth:`get_parameter`."""
        return [self._core.params.get(n) for n in names]

    def get_parameter_or(self, name: str, alternative_value: Parameter | None = None) -> Parameter:
        """The parameter ``name``, or ``alternative_value`` (an unset Parameter if None) when undeclared or unset."""
        return self._core.params.get_or(name, alternative_value)

    def get_parameters_by_prefix(self, prefix: str) -> dict[str, Parameter]:
        """The parameters named ``prefix.<rest>``, keyed by ``<rest>``; every parameter for ``""``."""
        return self._core.params.by_prefix(prefix)

    def get_parameter_type(self, name: str) -> ParameterType:
        """The type of ``name`` (NOT_SET when unset); ParameterNotDeclaredException."""
        return self._core.params.get_type(name)

    def get_parameter_types(self, names: Sequence[str]) -> list[ParameterType]:
        """The types of several parameters."""
        return [self._core.params.get_type(n) for n in names]

    def list_parameters(self, prefixes: Sequence[str], depth: int) -> ListParametersResult:
        """Names under ``prefixes`` (all if empty) at most ``depth`` parts deep (0: any), and their prefixes."""
        return self._core.params.list_parameters(prefixes, depth)

    def describe_parameter(self, name: str) -> ParameterDescriptor:
        """The descriptor of ``name``; ParameterNotDeclaredException."""
        return self._core.params.describe(name)

    def describe_parameters(self, names: Sequence[str]) -> list[ParameterDescriptor]:
        """The descriptors of several parameters; ParameterNotDeclaredException."""
        return [self._core.params.describe(n) for n in names]

    def set_descriptor(
        self, name: str, descriptor: ParameterDescriptor, alternative_value: ParameterValue | None = None
    ) -> ParameterValue:
        """Give ``name`` a new descriptor, keeping its value if it fits, else ``alternative_value``.

        Returns the value it then has.  Raises ParameterNotDeclaredException,
        ParameterImmutableException for a read-only parameter,
        InvalidParameterValueException when neither value fits.
        """
        return self._core.params.set_descriptor(name, descriptor, alternative_value)

    def set_parameters(self, parameter_list: Sequence[Parameter]) -> list[SetParametersResult]:
        """Set each parameter in turn; a result per parameter says whether, and why not.

        A parameter set to NOT_SET (``Parameter(name)``) is undeclared if it is
        dynamically typed.  Raises ParameterNotDeclaredException at the first
        undeclared name unless ``allow_undeclared_parameters`` (those before it
        stay set).
        """
        return self._core.params.set(parameter_list)

    def set_parameters_atomically(self, parameter_list: Sequence[Parameter]) -> SetParametersResult:
        """Set all parameters or none; raises as :meth:`set_parameters` before setting any."""
        return self._core.params.set_atomically(parameter_list)

    def add_pre_set_parameters_callback(self, callback: PreSet) -> None:
        """Call ``callback(parameters)`` first on each set (not on declarations); it returns the list to set.

        An empty list makes the set fail.
        """
        self._core.params.add_pre_set_callback(callback)

    def add_on_set_parameters_callback(self, callback: OnSet) -> OnSet:
        """Call ``callback(parameters)`` before each set and declaration; ``successful=False`` refuses it.

        The newest callback runs first, as in rclpy.
        """
        return self._core.params.add_on_set_callback(callback)

    def add_post_set_parameters_callback(self, callback: PostSet) -> None:
        """Call ``callback(parameters)`` after each accepted set and declaration."""
        self._core.params.add_post_set_callback(callback)

    def remove_pre_set_parameters_callback(self, callback: PreSet) -> None:
        """Stop calling ``callback``; ValueError if it was not added."""
        self._core.params.remove_pre_set_callback(callback)

    def remove_on_set_parameters_callback(self, callback: OnSet) -> None:
        """Stop calling ``callback``; ValueError if it was not added."""
        self._core.params.remove_on_set_callback(callback)

    def remove_post_set_parameters_callback(self, callback: PostSet) -> None:
        """Stop calling ``callback``; ValueError if it was not added."""
        self._core.params.remove_post_set_callback(callback)
