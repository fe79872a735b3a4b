"""jax backend: what differs from the shared layer's linear algebra
(``ivy/backends/array_api/linalg.py``)."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends import _nonfinite, _signed_zeros
from ivy.backends.jax._helpers import as_inexact


def _finite_only(compute, x):
    """``compute(x)``, NaN in the results of the matrices that hold NaN or infinity
    (``ivy/backends/_nonfinite.py``)."""
    x = as_inexact(x)
    ok = jnp.all(jnp.isfinite(x), axis=(-2, -1))
    eye = jnp.eye(x.shape[-2], x.shape[-1], dtype=x.dtype)
    return _nonfinite.nan_where_not_finite(
        compute, x, ok, eye, jnp.where, lambda y: jnp.issubdtype(y.dtype, jnp.inexact)
    )


def eigh(x, /):
    """The lower triangle is read, as numpy and torch read it (jnp.linalg.eigh would average
    it with the upper)."""
    return _finite_only(lambda x: jnp.linalg.eigh(x, UPLO="L", symmetrize_input=False), x)


def eigvalsh(x, /):
    """The lower triangle is read, as by :func:`eigh`."""
    return _finite_only(lambda x: jnp.linalg.eigvalsh(x, UPLO="L", symmetrize_input=False), x)


def det(x, /):
    """A singular matrix's determinant is ``+0`` (``ivy/backends/_signed_zeros.py``)."""
    out = jnp.linalg.det(as_inexact(x))
    if jnp.iscomplexobj(out):
        return out
    return _signed_zeros.positive_zero(jnp.where, jax.lax.stop_gradient, out)


def slogdet(x, /):
    """The sign of a singular matrix's determinant is ``0``, not ``-0``."""
    out = _finite_only(jnp.linalg.slogdet, x)
    if jnp.iscomplexobj(out.sign):
        return out
    return out._replace(sign=jnp.where(out.sign == 0, jnp.zeros_like(out.sign), out.sign))


def matrix_rank(x, /, *, rtol=None):
    """jnp.linalg.matrix_rank reads ``rtol`` as an absolute tolerance; here it is relative to
    the largest singular value, as the Array API says."""
    x = as_inexact(x)
    if not isinstance(x, jax.core.Tracer):
        _nonfinite.refuse_not_finite(bool(jnp.all(jnp.isfinite(x))), "jax")
    s = jnp.linalg.svdvals(x)
    if rtol is None:
        rtol = max(x.shape[-2:]) * jnp.finfo(s.dtype).eps
    tol = jnp.asarray(rtol, s.dtype)[..., None] * jnp.max(s, axis=-1, keepdims=True)
    return jnp.sum(s > tol, axis=-1)
