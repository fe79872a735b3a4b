"""jax backend: linear algebra, the Array API ``linalg`` extension.

``jax.numpy.linalg`` has the Array API signatures and returns namedtuples; it is exported as is
where it agrees with ivy. The shims compute bool and integer inputs of the floating-point
functions in float32, the default float dtype (jax would use float64 with 64-bit types enabled).
"""

from __future__ import annotations

import jax.numpy as jnp

from ivy.backends.jax._helpers import as_inexact

__all__ = [
    "cholesky",
    "cross",
    "det",
    "diagonal",
    "eigh",
    "eigvalsh",
    "inv",
    "matmul",
    "matrix_norm",
    "matrix_power",
    "matrix_rank",
    "matrix_transpose",
    "outer",
    "pinv",
    "qr",
    "slogdet",
    "solve",
    "svd",
    "svdvals",
    "tensordot",
    "trace",
    "vecdot",
    "vector_norm",
]

matmul = jnp.matmul
cross = jnp.linalg.cross
diagonal = jnp.linalg.diagonal
matrix_transpose = jnp.linalg.matrix_transpose
outer = jnp.linalg.outer
tensordot = jnp.linalg.tensordot
trace = jnp.linalg.trace  # bool and small integers accumulate in int64 (unsigned: uint64)
vecdot = jnp.linalg.vecdot


def cholesky(x, /, *, upper=False):
    return jnp.linalg.cholesky(as_inexact(x), upper=upper)


def det(x, /):
    return jnp.linalg.det(as_inexact(x))


def eigh(x, /):
    return jnp.linalg.eigh(as_inexact(x))


def eigvalsh(x, /):
    return jnp.linalg.eigvalsh(as_inexact(x))


def inv(x, /):
    return jnp.linalg.inv(as_inexact(x))


def matrix_norm(x, /, *, keepdims=False, ord="fro"):
    return jnp.linalg.matrix_norm(as_inexact(x), keepdims=keepdims, ord=ord)


def matrix_power(x, n, /):
    """Integer matrices stay integer for ``n >= 0``; a negative ``n`` inverts in float32."""
    return jnp.linalg.matrix_power(x if n >= 0 else as_inexact(x), n)


def matrix_rank(x, /, *, rtol=None):
    """jnp.linalg.matrix_rank reads ``rtol`` as an absolute tolerance; here it is relative to
    the largest singular value, as the Array API says."""
    x = as_inexact(x)
    s = jnp.linalg.svdvals(x)
    if rtol is None:
        rtol = max(x.shape[-2:]) * jnp.finfo(s.dtype).eps
    tol = jnp.asarray(rtol, s.dtype)[..., None] * jnp.max(s, axis=-1, keepdims=True)
    return jnp.sum(s > tol, axis=-1)


def pinv(x, /, *, rtol=None):
    return jnp.linalg.pinv(as_inexact(x), rtol=rtol)


def qr(x, /, *, mode="reduced"):
    return jnp.linalg.qr(as_inexact(x), mode=mode)


def slogdet(x, /):
    return jnp.linalg.slogdet(as_inexact(x))


def solve(x1, x2, /):
    return jnp.linalg.solve(as_inexact(x1), as_inexact(x2))


def svd(x, /, *, full_matrices=True):
    return jnp.linalg.svd(as_inexact(x), full_matrices=full_matrices)


def svdvals(x, /):
    return jnp.linalg.svdvals(as_inexact(x))


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    return jnp.linalg.vector_norm(as_inexact(x), axis=axis, keepdims=keepdims, ord=ord)
