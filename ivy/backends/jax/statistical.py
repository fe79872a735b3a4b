"""jax backend: reductions. Integer sums and products accumulate in the default int."""

from __future__ import annotations

import jax.numpy as jnp

from ivy.backends.jax._helpers import native_dtype

__all__ = ["sum", "prod", "mean", "min", "max", "var", "std"]

mean = jnp.mean
min = jnp.min
max = jnp.max
var = jnp.var  # takes ``correction=`` as the Array API does
std = jnp.std


def sum(x, /, *, axis=None, dtype=None, keepdims=False):
    return jnp.sum(x, axis=axis, dtype=native_dtype(dtype), keepdims=keepdims)


def prod(x, /, *, axis=None, dtype=None, keepdims=False):
    return jnp.prod(x, axis=axis, dtype=native_dtype(dtype), keepdims=keepdims)
