"""jax backend: data types. ``result_type`` is jax's own (its promotion lattice: int64 with
float32 gives float32; Python scalars promote by ivy's rules); ``can_cast`` follows the Array API's
table (ivy's rules: never across kinds). ``finfo`` and ``iinfo`` return Python numbers and
jax's dtype objects, as the Array API asks."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ivy.backends.jax._helpers import NATIVE_DTYPES, native_device, native_dtype
from ivy.core import _dtype_rules as rules

_PYTHON_SCALARS = (bool, int, float, complex)


def result_type(*arrays_and_dtypes):
    """jax's, but Python scalars promote by ivy's rules (a float next to an integer array gives
    float32 also with 64-bit types on)."""
    scalars = [v for v in arrays_and_dtypes if type(v) in _PYTHON_SCALARS]
    if not scalars:
        return jnp.result_type(*arrays_and_dtypes)
    names = [_name(v) for v in arrays_and_dtypes if type(v) not in _PYTHON_SCALARS]
    return jnp.dtype(NATIVE_DTYPES[rules.result_type(names, scalars)])


def astype(x, dtype, /, *, copy=True, device=None):
    return jnp.astype(x, native_dtype(dtype), copy=copy, device=native_device(device))


def _dtype(dtype_or_array) -> np.dtype:
    dt = getattr(dtype_or_array, "dtype", None)
    if isinstance(dt, np.dtype):  # an array (jax's dtypes are classes with a dtype attribute)
        return dt
    return np.dtype(native_dtype(dtype_or_array))


def _name(dtype_or_array) -> str:
    return rules.name_of(_dtype(dtype_or_array))


def can_cast(from_, to, /):
    """By the Array API's table (ivy's rules), as the other backends."""
    return rules.can_cast(_name(from_), _name(to))


def finfo(type, /):
    return rules.finfo(_name(type), NATIVE_DTYPES.__getitem__)


def iinfo(type, /):
    return rules.iinfo(_name(type), NATIVE_DTYPES.__getitem__)


def isdtype(dtype, kind):
    return rules.isdtype(_name(dtype), kind, _name)


def enable_float64():
    """jax's 64-bit switch, ``jax_enable_x64``, process-wide."""
    jax.config.update("jax_enable_x64", True)
