"""jax backend: what differs from the shared layer's linear algebra
(``ivy/backends/array_api/linalg.py``)."""

from __future__ import annotations

import jax.numpy as jnp

from ivy.backends.jax._helpers import as_inexact


def matrix_rank(x, /, *, rtol=None):
    """jnp.linalg.matrix_rank reads ``rtol`` as an absolute tolerance; here it is relative to
    the largest singular value, as the Array API says."""
    x = as_inexact(x)
    s = jnp.linalg.svdvals(x)
    if rtol is None:
        rtol = max(x.shape[-2:]) * jnp.finfo(s.dtype).eps
    tol = jnp.asarray(rtol, s.dtype)[..., None] * jnp.max(s, axis=-1, keepdims=True)
    return jnp.sum(s > tol, axis=-1)
