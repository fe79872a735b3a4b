"""numpy backend: searching."""

from __future__ import annotations

import numpy as np

from ivy.core import _dtype_rules as rules


def argmax(x, /, *, axis=None, keepdims=False):
    return np.asarray(np.argmax(x, axis=axis, keepdims=keepdims), dtype=np.int64)


def argmin(x, /, *, axis=None, keepdims=False):
    return np.asarray(np.argmin(x, axis=axis, keepdims=keepdims), dtype=np.int64)


_PYTHON_SCALARS = (bool, int, float, complex)


def where(condition, x1, x2, /):
    """numpy's, but a Python scalar promotes by ivy's rules (1.5 with an int32 array gives
    float32, not float64)."""
    if type(x1) in _PYTHON_SCALARS or type(x2) in _PYTHON_SCALARS:
        arrays = [v.dtype.name for v in (x1, x2) if hasattr(v, "dtype")]
        scalars = [v for v in (x1, x2) if type(v) in _PYTHON_SCALARS]
        dtype = rules.result_type(arrays, scalars) if arrays else rules.default_of(scalars)
        x1, x2 = np.asarray(x1, dtype=dtype), np.asarray(x2, dtype=dtype)
    return np.where(condition, x1, x2)


count_nonzero = np.count_nonzero  # int64 (numpy's intp)
nonzero = np.nonzero  # a tuple of int64 index arrays; 0-d input raises
searchsorted = np.searchsorted
