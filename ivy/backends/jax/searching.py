"""jax backend: searching. Indices come in the default int (int64 with x64 enabled, else int32)."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends.jax._helpers import default_int
from ivy.core import _dtype_rules as rules
from ivy.errors import UnsupportedError

argmax = jnp.argmax
argmin = jnp.argmin
count_nonzero = jnp.count_nonzero
_PYTHON_SCALARS = (bool, int, float, complex)


def where(condition, x1, x2, /):
    """jax's, but a Python float next to an integer array gives float32 (ivy's rule), also with
    64-bit types on."""
    if type(x1) in _PYTHON_SCALARS or type(x2) in _PYTHON_SCALARS:
        arrays = [rules.name_of(v.dtype) for v in (x1, x2) if hasattr(v, "dtype")]
        scalars = [v for v in (x1, x2) if type(v) in _PYTHON_SCALARS]
        dtype = rules.result_type(arrays, scalars) if arrays else rules.default_of(scalars)
        x1, x2 = jnp.asarray(x1, dtype=dtype), jnp.asarray(x2, dtype=dtype)
    return jnp.where(condition, x1, x2)


def nonzero(x, /):
    try:
        return jnp.nonzero(x)
    except jax.errors.ConcretizationTypeError as err:
        raise UnsupportedError(
            "nonzero: inside jax.jit (or vmap) the number of nonzero elements must be known when "
            "tracing. Call it outside the compiled function, or call "
            "jax.numpy.nonzero(x, size=N, fill_value=...) with a static size N."
        ) from err


def searchsorted(x1, x2, /, *, side="left", sorter=None):
    return jnp.searchsorted(x1, x2, side=side, sorter=sorter).astype(default_int())  # not int32
