"""numpy backend: data types. ``result_type`` is numpy's own for arrays and dtypes (mixed kinds
promote as numpy does: int64 with float32 gives float64; Python scalars by ivy's rules);
``can_cast`` follows the Array API's table (never across kinds); ``finfo``, ``iinfo`` and
``isdtype`` accept dtype names too and return Python numbers, as the Array API asks."""

from __future__ import annotations

import numpy as np

from ivy.backends.numpy._helpers import NATIVE_DTYPES, check_device, native_dtype
from ivy.backends.numpy._helpers import dtype_name as _native_name
from ivy.core import _dtype_rules as rules

_PYTHON_SCALARS = (bool, int, float, complex)


def result_type(*arrays_and_dtypes):
    """numpy's, but Python scalars promote by ivy's rules (a float next to an integer array
    gives float32, not float64)."""
    scalars = [v for v in arrays_and_dtypes if type(v) in _PYTHON_SCALARS]
    if not scalars:
        return np.result_type(*arrays_and_dtypes)
    names = [_name(v) for v in arrays_and_dtypes if type(v) not in _PYTHON_SCALARS]
    return np.dtype(NATIVE_DTYPES[rules.result_type(names, scalars)])


def can_cast(from_, to, /):
    """By the Array API's table (numpy's own casts bool to int8 and int64 to float64)."""
    return rules.can_cast(_name(from_), _name(to))


def astype(x, dtype, /, *, copy=True, device=None):
    check_device(device)
    return x.astype(native_dtype(dtype), copy=copy)


def _name(dtype_or_array) -> str:
    dt = getattr(dtype_or_array, "dtype", None)
    if dt is not None and not isinstance(dtype_or_array, type):
        return _native_name(dt)
    return _native_name(native_dtype(dtype_or_array))


def finfo(type, /):
    return rules.finfo(_name(type), NATIVE_DTYPES.__getitem__)


def iinfo(type, /):
    return rules.iinfo(_name(type), NATIVE_DTYPES.__getitem__)


def isdtype(dtype, kind):
    return rules.isdtype(_name(dtype), kind, _name)
