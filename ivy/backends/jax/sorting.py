"""jax backend: sorting (jax.numpy's own: NaN is the largest value, last ascending and first
descending; a stable descending sort keeps equal elements in their order)."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ivy.backends._sample_args import top_k_axis
from ivy.backends.jax._helpers import default_int
from ivy.core._results import TopKResult

argsort = jnp.argsort


def sort(x, /, *, axis=-1, descending=False, stable=True):
    """``jnp.sort``; descending, the reverse of the ascending sort of the reversed array, so that
    equal elements (``-0`` and ``+0`` among them) keep their order as numpy's stable sort and the
    other backends keep it (``jnp.sort(descending=True)`` reverses the ascending sort, which
    reverses them)."""
    if not descending:
        return jnp.sort(x, axis=axis, stable=stable)
    return jnp.flip(jnp.sort(jnp.flip(x, axis), axis=axis, stable=stable), axis)


_BITS = {
    np.dtype(jnp.float16): jnp.int16,
    np.dtype(jnp.bfloat16): jnp.int16,
    np.dtype(jnp.float32): jnp.int32,
    np.dtype(jnp.float64): jnp.int64,
}


def _order_key(x):
    """Integers that order as ``sort`` orders ``x``: -0.0 equal to 0.0 and NaN the largest.

    (``lax.top_k`` orders floats by their bits: 0.0 above -0.0, and a NaN with the sign bit set,
    as 0.0 / 0.0 makes on x86, below -inf.)
    """
    if x.dtype == jnp.bool_:
        return x.astype(jnp.int8)
    bits = _BITS.get(x.dtype)
    if bits is None:
        return x
    x = jnp.where(jnp.isnan(x), jnp.nan, jnp.where(x == 0, 0, x))  # one NaN, one zero
    b = jax.lax.bitcast_convert_type(x, bits)
    # Negative floats: larger bits mean smaller numbers. Flipping all bits but the sign fixes that.
    return jnp.where(b < 0, b ^ jnp.iinfo(bits).max, b)


def top_k(x, k, /, *, axis=-1, largest=True, sorted=True):
    """``lax.top_k`` of an integer key (it puts equal elements in index order); the values are
    gathered from ``x``, so that gradients flow to them."""
    x = jnp.asarray(x)
    axis = top_k_axis(x.shape, k, axis)
    key = _order_key(x)
    _, indices = jax.lax.top_k(key if largest else ~key, k, axis=axis)
    indices = indices.astype(default_int())
    return TopKResult(jnp.take_along_axis(x, indices, axis=axis), indices)
