"""Assemble the namespace of a library registered with :func:`ivy.register_framework`: the shared
layer bound to its Array API namespace, and the host bridge for what the standard lacks."""

from __future__ import annotations

import importlib
import sys
import types
from typing import Any

from ivy.backends._assemble import assemble
from ivy.backends.array_api._helpers import helpers_for, host_bridge

# Functions that take the user's callables or change global state cannot run through numpy:
# the shared layer has them all (control_flow, gradients, compilation); never bridge these.
_NEVER_BRIDGED = frozenset(
    {
        "scan",
        "fori_loop",
        "while_loop",
        "cond",
        "value_and_grad_native",
        "jacobian_native",
        "compile_native",
    }
)


def assemble_registered(name: str, spec: Any) -> types.ModuleType:
    """Build, register and return ``ivy.backends.<name>`` for the registered library ``spec``."""
    xp = spec.namespace
    if isinstance(xp, str):
        xp = importlib.import_module(xp)
    module = types.ModuleType(
        spec.module,
        f"ivy's {name} backend: ivy's shared layer bound to the Array API namespace "
        f"{xp.__name__} (registered with ivy.register_framework).",
    )
    sys.modules[spec.module] = module
    helpers = helpers_for(xp, name)
    array_type = type(xp.asarray(0))
    helpers["array_types"] = (array_type,)

    def is_array(value: Any) -> bool:
        return isinstance(value, array_type)

    def fallback(fn_name: str):
        if fn_name in _NEVER_BRIDGED:
            return None
        return host_bridge(fn_name, xp, is_array, helpers["dtype_name"], helpers["native_device"])

    module.__ivy_host_bridged__ = []  # the names that run through numpy, for the docs

    def recorded(fn_name: str):
        fn = fallback(fn_name)
        if fn is not None:
            module.__ivy_host_bridged__.append(fn_name)
        return fn

    info = xp.__array_namespace_info__() if hasattr(xp, "__array_namespace_info__") else None

    def devices() -> list:
        return list(info.devices()) if info is not None else []

    return assemble(
        module,
        backend=name,
        native_dtypes=helpers["native_dtypes"],
        xp=xp,
        bind=helpers,
        reals=helpers["reals"],
        capabilities=spec.capabilities,
        fallback=recorded,
        devices=devices,
    )
