"""jax backend: cumulative sums and products (``jax.lax.cumsum``/``cumprod``, which reverse
natively). Bool and small integers accumulate in the default int (unsigned: the matching
unsigned), which jax would not widen."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends.jax._helpers import default_int, native_dtype


def _accumulator(dtype):
    if jnp.issubdtype(dtype, jnp.unsignedinteger):
        wide = jnp.uint64 if jax.config.jax_enable_x64 else jnp.uint32
        return jnp.promote_types(dtype, wide)
    if dtype == jnp.bool_ or jnp.issubdtype(dtype, jnp.integer):
        return jnp.promote_types(dtype, default_int())
    return dtype


def _cumulative(fn, identity, x, axis, exclusive, reverse, dtype):
    x = jnp.asarray(x)
    x = x.astype(native_dtype(dtype) or _accumulator(x.dtype))
    axis = axis % x.ndim if x.ndim else axis
    out = fn(x, axis=axis, reverse=reverse)
    n = out.shape[axis]
    if exclusive and n:
        fill = jnp.full_like(jax.lax.slice_in_dim(out, 0, 1, axis=axis), identity)
        if reverse:
            out = jnp.concatenate([jax.lax.slice_in_dim(out, 1, n, axis=axis), fill], axis)
        else:
            out = jnp.concatenate([fill, jax.lax.slice_in_dim(out, 0, n - 1, axis=axis)], axis)
    return out


def cumsum(x, /, axis=0, *, exclusive=False, reverse=False, dtype=None):
    return _cumulative(jax.lax.cumsum, 0, x, axis, exclusive, reverse, dtype)


def cumprod(x, /, axis=0, *, exclusive=False, reverse=False, dtype=None):
    return _cumulative(jax.lax.cumprod, 1, x, axis, exclusive, reverse, dtype)
