"""jax backend: max and average pools, channel-last, with ``jax.lax.reduce_window``.

Average pools divide each window's sum by its number of real (unpadded) entries, as tf does for
'SAME'.
"""

from __future__ import annotations

import math

import jax.numpy as jnp
from jax import lax

from ivy.backends import _nn_args as A
from ivy.backends.jax.convolutions import flatten_batch


def _pool(x, kernel, strides, padding, nd, fn, average):
    x = jnp.asarray(x)
    A.check_pool_input(x.shape, nd, fn)
    k = A.as_tuple(kernel, nd, "kernel", fn)
    s = A.as_tuple(strides, nd, "strides", fn)
    x, lead = flatten_batch(x, nd)
    sizes = x.shape[1:-1]
    pads = A.pool_pads(padding, sizes, k, s, fn)
    window, steps, full_pads = (1, *k, 1), (1, *s, 1), ((0, 0), *pads, (0, 0))
    if average:
        total = lax.reduce_window(x, 0.0, lax.add, window, steps, full_pads)
        if any(p != (0, 0) for p in pads):
            counts = A.window_counts(sizes, k, s, pads)[None, ..., None]
            y = total / jnp.asarray(counts, total.dtype)
        else:
            y = total / math.prod(k)
    else:
        low = -jnp.inf if jnp.issubdtype(x.dtype, jnp.floating) else jnp.iinfo(x.dtype).min
        y = lax.reduce_window(x, low, lax.max, window, steps, full_pads)
    return y.reshape(lead + y.shape[1:])


def max_pool1d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 1, "max_pool1d", False)


def max_pool2d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 2, "max_pool2d", False)


def max_pool3d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 3, "max_pool3d", False)


def avg_pool1d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 1, "avg_pool1d", True)


def avg_pool2d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 2, "avg_pool2d", True)


def avg_pool3d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 3, "avg_pool3d", True)
