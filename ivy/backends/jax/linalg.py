"""jax backend: what differs from the shared layer's linear algebra
(``ivy/backends/array_api/linalg.py``)."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends import _signed_zeros
from ivy.backends.jax._helpers import as_inexact


def det(x, /):
    """A singular matrix's determinant is ``+0`` (``ivy/backends/_signed_zeros.py``)."""
    out = jnp.linalg.det(as_inexact(x))
    if jnp.iscomplexobj(out):
        return out
    return _signed_zeros.positive_zero(jnp.where, jax.lax.stop_gradient, out)


def slogdet(x, /):
    """The sign of a singular matrix's determinant is ``0``, not ``-0``."""
    out = jnp.linalg.slogdet(as_inexact(x))
    if jnp.iscomplexobj(out.sign):
        return out
    return out._replace(sign=jnp.where(out.sign == 0, jnp.zeros_like(out.sign), out.sign))


def matrix_rank(x, /, *, rtol=None):
    """jnp.linalg.matrix_rank reads ``rtol`` as an absolute tolerance; here it is relative to
    the largest singular value, as the Array API says."""
    x = as_inexact(x)
    s = jnp.linalg.svdvals(x)
    if rtol is None:
        rtol = max(x.shape[-2:]) * jnp.finfo(s.dtype).eps
    tol = jnp.asarray(rtol, s.dtype)[..., None] * jnp.max(s, axis=-1, keepdims=True)
    return jnp.sum(s > tol, axis=-1)
