"""jax backend: searching. Indices come in the default int (int64 with x64 enabled, else int32)."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends.jax._helpers import default_int
from ivy.errors import UnsupportedError

argmax = jnp.argmax
argmin = jnp.argmin
count_nonzero = jnp.count_nonzero
where = jnp.where


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
