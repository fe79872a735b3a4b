"""Data types, written once: ``xp.astype``, ``xp.can_cast`` and ``xp.result_type`` with dtype
names accepted, and ``finfo``, ``iinfo`` and ``isdtype`` by ivy's own rules
(``ivy/core/_dtype_rules.py``), which return Python numbers and the backend's dtype objects."""

from __future__ import annotations

from ivy.backends.array_api._unbound import (
    array_types,
    backend_name,
    backend_ns,
    native_device,
    native_dtype,
    native_dtypes,
    xp,
)
from ivy.core import _dtype_rules as rules
from ivy.errors import UnsupportedError


def _native(value):
    """An array as it is; a dtype (name or object) as the native dtype."""
    return value if hasattr(value, "shape") else native_dtype(value)


def astype(x, dtype, /, *, copy=True, device=None):
    out = xp.astype(x, native_dtype(dtype), copy=copy)
    if device is not None:
        out = xp.asarray(out, device=native_device(device))
    return out


def can_cast(from_, to, /):
    """By the Array API's table (ivy's rules): never across kinds."""
    return rules.can_cast(_name(from_), _name(to))


_PYTHON_SCALARS = (bool, int, float, complex)


def result_type(*arrays_and_dtypes):
    """By ivy's rules (``ivy/core/_dtype_rules.py``): a Python float next to an integer array
    gives float32 (numpy's would be float64)."""
    scalars = [v for v in arrays_and_dtypes if type(v) in _PYTHON_SCALARS]
    if not scalars:
        return xp.result_type(*(_native(a) for a in arrays_and_dtypes))
    names = [_name(v) for v in arrays_and_dtypes if type(v) not in _PYTHON_SCALARS]
    return native_dtypes[rules.result_type(names, scalars)]


def _name(dtype_or_array) -> str:
    dt = getattr(dtype_or_array, "dtype", None)
    if dt is not None and hasattr(dtype_or_array, "shape"):
        return dtype_name(dt)
    return dtype_name(native_dtype(dtype_or_array))


def finfo(type, /):  # noqa: A002 - the Array API name
    return rules.finfo(_name(type), native_dtypes.__getitem__)


def iinfo(type, /):  # noqa: A002
    return rules.iinfo(_name(type), native_dtypes.__getitem__)


def isdtype(dtype, kind):
    return rules.isdtype(_name(dtype), kind, _name)


def dtype_name(dtype, /):
    """The ivy name of a native dtype, an array's dtype, a name or a numpy scalar type."""
    if isinstance(dtype, array_types):
        dtype = dtype.dtype
    if not isinstance(dtype, (str, type)):
        for name, native in native_dtypes.items():
            if native is not None and native == dtype:
                return name
    return rules.name_of(dtype)


def enable_float64():
    """Nothing to switch: the library holds 64-bit types, or says it cannot."""
    if not backend_ns.capabilities.float64:
        raise UnsupportedError(
            f"the backend {backend_name!r} has no float64 (it was registered with "
            f"float64=False); compute in float32 on it, or choose another framework."
        )
