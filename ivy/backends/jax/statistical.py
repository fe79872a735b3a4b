"""jax backend: reductions. Integer sums and products accumulate in the default int."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends.jax._helpers import default_int, native_dtype

min = jnp.min
max = jnp.max


def sum(x, /, *, axis=None, dtype=None, keepdims=False):
    return jnp.sum(x, axis=axis, dtype=native_dtype(dtype), keepdims=keepdims)


def prod(x, /, *, axis=None, dtype=None, keepdims=False):
    return jnp.prod(x, axis=axis, dtype=native_dtype(dtype), keepdims=keepdims)


cumulative_sum = jnp.cumulative_sum


def cumulative_prod(x, /, *, axis=None, dtype=None, include_initial=False):
    """jax.numpy's own, with integers and bools accumulated in the default (unsigned) integer as
    ``cumulative_sum`` does (jax keeps int8 products in int8)."""
    x = jnp.asarray(x)
    if dtype is None and (x.dtype == jnp.bool_ or jnp.issubdtype(x.dtype, jnp.integer)):
        dtype = default_int()
        if jnp.issubdtype(x.dtype, jnp.unsignedinteger):
            dtype = jnp.uint64 if dtype == jnp.int64 else jnp.uint32
    return jnp.cumulative_prod(
        x, axis=axis, dtype=native_dtype(dtype), include_initial=include_initial
    )


def logsumexp(x, /, *, axis=None, keepdims=False):
    x = jnp.asarray(x)
    if not jnp.issubdtype(x.dtype, jnp.inexact):
        x = x.astype(jnp.float32)
    return jax.nn.logsumexp(x, axis=axis, keepdims=keepdims)
