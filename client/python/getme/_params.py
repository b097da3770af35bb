"""Keyword arguments → getme.v1.SmoothingParameters, field by field from the proto's descriptor,
so every field of params.proto is accepted by its name and nothing else is (besides
max_iterations and the aliases of _wire.PARAMETER_ALIASES, e.g. feature_angle)."""

from __future__ import annotations

import numbers
from typing import Any, Dict

from google.protobuf.descriptor import FieldDescriptor

from getme._stubs import params_pb2
from getme._wire import (ITERATION_COUNTERS, PARAMETER_ALIASES, PER_TYPE_KEYS, boundary_name,
                         boundary_names, boundary_value, is_method, method_names, method_value)

# The CLI's --max-iterations: one cap for every phase (client/cmdline/smoothing_flags.cc), i.e.
# every max_iterations_field of _wire.ITERATION_COUNTERS and the polish's worst-element and
# worst-cluster stages, whose sweeps and rounds the result counts with the polish's sweeps.
MAX_ITERATIONS = "max_iterations"
_ALSO_CAPPED = ("polish_worst_max_sweeps", "polish_cluster_max_rounds")

_FIELDS = {f.name: f for f in params_pb2.SmoothingParameters.DESCRIPTOR.fields}


def parameter_names():
    """The names smooth() accepts as parameters, sorted."""
    return sorted(list(_FIELDS) + [MAX_ITERATIONS] + list(PARAMETER_ALIASES))


def check_names(params: Dict[str, Any]) -> None:
    """TypeError naming every unknown parameter."""
    unknown = sorted(name for name in params if name not in _FIELDS and name != MAX_ITERATIONS
                     and name not in PARAMETER_ALIASES)
    if unknown:
        raise TypeError(f"unknown smoothing parameter{'s' if len(unknown) > 1 else ''} "
                        f"{', '.join(unknown)} (known: {', '.join(parameter_names())})")


def _method(value) -> int:
    if isinstance(value, str):
        method = method_value(value)
        if method is not None:
            return method
        choices = ", ".join(method_names())
        raise ValueError(f"parameter method: unknown method {value!r} (one of {choices})")
    if isinstance(value, numbers.Integral) and not isinstance(value, bool):
        if is_method(int(value)):
            return int(value)
        raise ValueError(f"parameter method: {value} is no getme.v1.Method value")
    raise TypeError(f"parameter method: expected a method name such as 'getme', got {value!r}")


def _boundary(value) -> int:
    if isinstance(value, str):
        boundary = boundary_value(value)
        if boundary is not None:
            return boundary
        raise ValueError(f"parameter boundary: unknown boundary {value!r} "
                         f"(one of {', '.join(boundary_names())})")
    if isinstance(value, numbers.Integral) and not isinstance(value, bool):
        if boundary_name(int(value)) in boundary_names():
            return int(value)
        raise ValueError(f"parameter boundary: {value} is no getme.v1.Boundary value "
                         f"(one of {', '.join(boundary_names())})")
    raise TypeError(f"parameter boundary: expected one of {', '.join(boundary_names())}, "
                    f"got {value!r}")


def _resolve_aliases(values: Dict[str, Any]) -> None:
    """Replaces each alias (feature_angle) by the field it spells; TypeError if both are given."""
    for alias, field in PARAMETER_ALIASES.items():
        if alias not in values:
            continue
        value = values.pop(alias)
        if values.get(field) is not None and value is not None:
            raise TypeError(f"parameters {alias} and {field} are the same parameter: give one")
        if value is not None:
            values[field] = value


def _set_per_type(name: str, value, message) -> None:
    if isinstance(value, params_pb2.PerType):
        message.CopyFrom(value)
        return
    if not isinstance(value, dict):
        raise TypeError(f"parameter {name}: expected a dict of element type → value "
                        f"(keys {', '.join(sorted(PER_TYPE_KEYS))}), got {value!r}")
    seen = {}
    for key, type_value in value.items():
        wire_key = PER_TYPE_KEYS.get(key)
        if wire_key is None:
            raise ValueError(f"parameter {name}: unknown element type {key!r} "
                             f"(one of {', '.join(sorted(PER_TYPE_KEYS))})")
        if wire_key in seen:
            raise ValueError(f"parameter {name}: {key!r} and {seen[wire_key]!r} name the same type")
        seen[wire_key] = key
        if type_value is None:
            continue
        _check_number(f"{name}[{key!r}]", type_value, integral=False)
        setattr(message, wire_key, float(type_value))


def _check_number(name: str, value, integral: bool) -> None:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"parameter {name}: expected a number, got {value!r}")
    if integral and not isinstance(value, numbers.Integral):
        raise TypeError(f"parameter {name}: expected an integer, got {value!r}")


def to_proto(params: Dict[str, Any]):
    """The SmoothingParameters for smooth()'s keyword arguments. A value None leaves the field
    unset (the server's default); max_iterations sets every *_max_iterations not given itself.
    TypeError for unknown names or values of the wrong type, ValueError for unknown method or
    element type or boundary names. Value ranges, and combinations such as free_boundary=True
    with boundary="slide", are the server's to check (INVALID_ARGUMENT naming the fields)."""
    check_names(params)
    message = params_pb2.SmoothingParameters()
    values = dict(params)
    _resolve_aliases(values)
    cap = values.pop(MAX_ITERATIONS, None)
    if cap is not None:
        capped = [counter.max_iterations_field for counter in ITERATION_COUNTERS
                  if counter.max_iterations_field is not None]
        for name in capped + list(_ALSO_CAPPED):
            if values.get(name) is None:
                values[name] = cap
    for name, value in values.items():
        if value is None:
            continue
        descriptor = _FIELDS[name]
        if name == "method":
            message.method = _method(value)
        elif name == "boundary":
            message.boundary = _boundary(value)
        elif descriptor.type == FieldDescriptor.TYPE_MESSAGE:
            _set_per_type(name, value, getattr(message, name))
        elif descriptor.type == FieldDescriptor.TYPE_BOOL:
            if not isinstance(value, bool) and type(value).__name__ != "bool_":
                raise TypeError(f"parameter {name}: expected True or False, got {value!r}")
            setattr(message, name, bool(value))
        elif descriptor.type in (FieldDescriptor.TYPE_DOUBLE, FieldDescriptor.TYPE_FLOAT):
            _check_number(name, value, integral=False)
            setattr(message, name, float(value))
        else:
            _check_number(name, value, integral=True)
            try:
                setattr(message, name, int(value))
            except ValueError as error:  # out of the field's integer range
                raise ValueError(f"parameter {name}: {error}") from error
    return message


__all__ = ["to_proto", "check_names", "parameter_names"]
