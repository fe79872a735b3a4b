"""jax backend: the one pool, channel-last, with ``jax.lax.reduce_window``.

Average pools divide each window's sum by its number of real (unpadded) entries, as tf does for
'SAME'.
"""

from __future__ import annotations

import math

import jax.numpy as jnp
from jax import lax

from ivy._args import nn as A


def pool_general(x, kernel, strides, padding, /, *, reduction="max"):
    x = jnp.asarray(x)
    window, steps = (1, *kernel, 1), (1, *strides, 1)
    full_pads = ((0, 0), *padding, (0, 0))
    if A.averages(reduction):
        total = lax.reduce_window(x, 0.0, lax.add, window, steps, full_pads)
        if any(p != (0, 0) for p in padding):
            counts = A.window_counts(x.shape[1:-1], kernel, strides, padding)[None, ..., None]
            return total / jnp.asarray(counts, total.dtype)
        return total / math.prod(kernel)
    if jnp.issubdtype(x.dtype, jnp.floating):  # (a Python -inf: jax's gradient of max pools)
        return lax.reduce_window(x, -jnp.inf, lax.max, window, steps, full_pads)
    low = jnp.asarray(jnp.iinfo(x.dtype).min, x.dtype)  # (of the input's dtype, not weak)
    return lax.reduce_window(x, low, lax.max, window, steps, full_pads)
