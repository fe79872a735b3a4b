"""The helpers that the shared layer binds for a library registered with
:func:`ivy.register_framework`, written with the Array API alone: dtypes by name, devices,
ivy's rule for functions of real numbers (integer and bool inputs compute in float32), and the
host bridge for what the standard does not define."""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from typing import Any

import numpy as np

from ivy import framework_handler as _fh
from ivy.dtypes import DTYPE_NAMES

_FLOATING = ("real floating", "complex floating")


def helpers_for(xp: Any, backend: str) -> dict[str, Any]:
    """Everything the shared layer's functions find besides ``xp``, for the namespace ``xp``."""
    native_dtypes = {n: getattr(xp, n, None) for n in DTYPE_NAMES}
    names = {dt: n for n, dt in native_dtypes.items() if dt is not None}
    info = xp.__array_namespace_info__() if hasattr(xp, "__array_namespace_info__") else None
    default_device = info.default_device() if info is not None else xp.asarray(0).device

    def native_dtype(dtype):
        if dtype is None:
            return None
        if isinstance(dtype, str):
            found = native_dtypes.get(dtype)
            if found is None:
                raise TypeError(
                    f"Unknown dtype {dtype!r} on the {backend} backend; use one of "
                    f"{', '.join(names.values())}."
                )
            return found
        if dtype in names:
            return dtype
        name = np.dtype(dtype).name  # numpy's dtypes and scalar types, e.g. np.float32
        return native_dtype(name)

    def dtype_name(dtype) -> str:
        return names[dtype]

    def native_device(device):
        if device is None or device in ("cpu", "cpu:0"):
            return None if device is None else default_device
        if not isinstance(device, (str, int)) and (info is None or device in info.devices()):
            return device  # a native device object
        from ivy.errors import unavailable_device

        raise unavailable_device(device, _fh.load_backend(backend))

    def device_name(device) -> str:
        return "cpu" if device == default_device else str(device)

    def as_inexact(x):
        x = xp.asarray(x)
        return x if xp.isdtype(x.dtype, _FLOATING) else xp.astype(x, xp.float32)

    return {
        "native_dtypes": native_dtypes,
        "native_dtype": native_dtype,
        "dtype_name": dtype_name,
        "native_device": native_device,
        "device_name": device_name,
        "as_inexact": as_inexact,
        "reals": reals_wrappers(xp),
        "concrete": lambda value: True,
    }


def reals_wrappers(xp: Any) -> dict[str, Callable]:
    """ivy's rule for functions of real numbers, for a library that refuses integer inputs:
    integer and boolean arrays are converted to float32 before the call (next to a floating
    array, an integer one takes that array's floating dtype)."""

    def exact(x) -> bool:
        return hasattr(x, "dtype") and not xp.isdtype(x.dtype, _FLOATING)

    def unary(native: Callable, name: str) -> Callable:
        def fn(x, /):
            return native(xp.astype(x, xp.float32) if exact(x) else x)

        return _named(fn, native, name)

    def binary(native: Callable, name: str) -> Callable:
        def fn(x1, x2, /):
            e1, e2 = exact(x1), exact(x2)
            if e1 and e2:
                x1, x2 = xp.astype(x1, xp.float32), xp.astype(x2, xp.float32)
            elif e1:
                x1 = xp.astype(x1, x2.dtype if hasattr(x2, "dtype") else xp.float32)
            elif e2:
                x2 = xp.astype(x2, x1.dtype if hasattr(x1, "dtype") else xp.float32)
            return native(x1, x2)

        return _named(fn, native, name)

    def options(native: Callable, name: str) -> Callable:
        def fn(x, /, *args, **kwargs):
            return native(xp.astype(x, xp.float32) if exact(x) else x, *args, **kwargs)

        try:  # the native's parameters, not ``*args, **kwargs``
            fn.__signature__ = inspect.signature(native)
        except (TypeError, ValueError):
            pass
        return _named(fn, native, name)

    return {"unary": unary, "binary": binary, "options": options}


def _named(fn: Callable, native: Callable, name: str) -> Callable:
    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = f"{name}, with integer and boolean inputs computed in float32."
    fn.__ivy_reals__ = True
    return fn


def host_bridge(
    name: str, xp: Any, is_array: Callable[[Any], bool], dtype_name, native_device=None
) -> Callable:
    """``ivy.numpy.<name>`` for arrays of ``xp``: array arguments go to numpy (by DLPack), native
    dtypes by name, and numpy results come back as ``xp`` arrays. For the functions the Array API
    does not define, on libraries whose arrays live in host memory. A ``device=`` is checked by
    the library's ``native_device`` (a device it lacks is refused in its name), then the work is
    numpy's, on the host."""
    target = getattr(_fh.load_backend("numpy"), name)

    def to_host(v):
        if is_array(v):
            return np.asarray(v)
        if isinstance(v, (list, tuple)):
            return type(v)(to_host(i) for i in v)
        if isinstance(v, dict):
            return {k: to_host(i) for k, i in v.items()}
        try:
            return dtype_name(v)
        except (KeyError, TypeError):
            return v

    def back(v):
        if isinstance(v, (np.ndarray, np.generic)):
            return xp.asarray(np.asarray(v))
        if isinstance(v, tuple) and hasattr(v, "_fields"):  # a namedtuple (e.g. SVDResult)
            return type(v)(*(back(i) for i in v))
        if isinstance(v, (list, tuple)):
            return type(v)(back(i) for i in v)
        return v

    @functools.wraps(target)
    def fn(*args, **kwargs):
        if native_device is not None and kwargs.get("device") is not None:
            native_device(kwargs["device"])
            kwargs = {**kwargs, "device": None}
        return back(target(*to_host(args), **to_host(kwargs)))

    fn.__ivy_host_bridge__ = True
    return fn
