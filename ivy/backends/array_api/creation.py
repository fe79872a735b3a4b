"""Array creation, written once against ``xp``: float32 by default, as on every backend, and
Python values keep ivy's default dtypes (bool, int64, float32, complex64)."""

from __future__ import annotations

import numpy as np

from ivy.backends._constants import ConstantCache
from ivy.backends._creation_args import (
    beyond_int64,
    check_step,
    has_int_beyond_int64,
    linspace_dtype,
)
from ivy.backends._dlpack import exportable
from ivy.backends.array_api._unbound import (
    backend_name,
    backend_ns,
    native_device,
    native_dtype,
    xp,
)


def _default_dtype(value):
    """The dtype a Python value gets by default: bool, int64, float32 or complex64."""
    if isinstance(value, bool):
        return xp.bool
    if isinstance(value, int):
        return xp.int64
    if isinstance(value, complex):
        return xp.complex64
    return xp.float32


def _has_own_dtype(obj) -> bool:
    while isinstance(obj, (list, tuple)) and obj:
        obj = obj[0]
    return hasattr(obj, "dtype")


def asarray(obj, /, *, dtype=None, device=None, copy=None):
    device = native_device(device)
    if dtype is not None:
        return xp.asarray(obj, dtype=native_dtype(dtype), device=device, copy=copy)
    if not _has_own_dtype(obj) and hasattr(obj, "__dlpack__"):
        obj = xp.from_dlpack(obj)
    try:
        x = xp.asarray(obj, device=device, copy=copy)
    except (OverflowError, TypeError, ValueError):
        if not _has_own_dtype(obj) and has_int_beyond_int64(obj):
            raise beyond_int64(backend_name) from None
        raise
    if not _has_own_dtype(obj):
        if x.dtype == xp.uint64 and has_int_beyond_int64(obj):
            raise beyond_int64(backend_name)  # (read as uint64, as numpy does)
        if x.dtype == xp.float64:
            return xp.astype(x, xp.float32)
        if x.dtype == xp.complex128:
            return xp.astype(x, xp.complex64)
    return x


def zeros(shape, *, dtype=None, device=None):
    return xp.zeros(shape, dtype=native_dtype(dtype) or xp.float32, device=native_device(device))


def ones(shape, *, dtype=None, device=None):
    return xp.ones(shape, dtype=native_dtype(dtype) or xp.float32, device=native_device(device))


def empty(shape, *, dtype=None, device=None):
    return xp.empty(shape, dtype=native_dtype(dtype) or xp.float32, device=native_device(device))


def full(shape, fill_value, *, dtype=None, device=None):
    dtype = native_dtype(dtype) or _default_dtype(fill_value)
    return xp.full(shape, fill_value, dtype=dtype, device=native_device(device))


def arange(start, /, stop=None, step=1, *, dtype=None, device=None):
    check_step(step, backend_name)
    if dtype is None:
        ints = all(isinstance(v, int) for v in (start, stop, step) if v is not None)
        dtype = xp.int64 if ints else xp.float32
    return xp.arange(start, stop, step, dtype=native_dtype(dtype), device=native_device(device))


def linspace(start, stop, /, num, *, dtype=None, device=None, endpoint=True):
    dtype = native_dtype(linspace_dtype(start, stop, dtype, backend_name) or dtype)
    return xp.linspace(
        start, stop, num, dtype=dtype, device=native_device(device), endpoint=endpoint
    )


def eye(n_rows, n_cols=None, /, *, k=0, dtype=None, device=None):
    dtype = native_dtype(dtype) or xp.float32
    return xp.eye(n_rows, n_cols, k=k, dtype=dtype, device=native_device(device))


def zeros_like(x, /, *, dtype=None, device=None):
    return xp.zeros_like(x, dtype=native_dtype(dtype), device=native_device(device))


def ones_like(x, /, *, dtype=None, device=None):
    return xp.ones_like(x, dtype=native_dtype(dtype), device=native_device(device))


def empty_like(x, /, *, dtype=None, device=None):
    return xp.empty_like(x, dtype=native_dtype(dtype), device=native_device(device))


def full_like(x, /, fill_value, *, dtype=None, device=None):
    return xp.full_like(x, fill_value, dtype=native_dtype(dtype), device=native_device(device))


def tril(x, /, *, k=0):
    return xp.tril(x, k=k)


def triu(x, /, *, k=0):
    return xp.triu(x, k=k)


def from_dlpack(x, /, *, device=None, copy=None):
    x, copy_after = exportable(x)
    if copy_after:
        out = xp.from_dlpack(x, device=native_device(device))
        return xp.asarray(out, copy=True) if copy else out
    return xp.from_dlpack(x, device=native_device(device), copy=copy)


def meshgrid(*arrays, indexing="xy"):
    return list(xp.meshgrid(*arrays, indexing=indexing))


_CONSTANTS = ConstantCache()


def constant(value, /, *, dtype=None, device=None):
    """A model constant: as ``asarray``, a numpy array's conversion kept per dtype and device
    (numpy's and a registered library's arrays have no trace to keep out of)."""
    if not isinstance(value, np.ndarray):
        return backend_ns.asarray(value, dtype=dtype, device=device)
    return _CONSTANTS.get(
        value,
        (backend_name, native_dtype(dtype), device),
        lambda v: backend_ns.asarray(v, dtype=dtype, device=device, copy=True),
    )
