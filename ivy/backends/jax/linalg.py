"""jax backend: linear algebra, the Array API ``linalg`` extension.

``jax.numpy.linalg`` has the Array API signatures and returns namedtuples; it is exported as is
where it agrees with ivy. The shims compute bool and integer inputs of the floating-point
functions in float32, the default float dtype (jax would use float64 with 64-bit types enabled).
"""

from __future__ import annotations

import jax.numpy as jnp

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


def _floating(x):
    """``x`` as an array of a floating dtype: bool and integers become float32."""
    x = jnp.asarray(x)
    return x if jnp.issubdtype(x.dtype, jnp.inexact) else x.astype(jnp.float32)


def cholesky(x, /, *, upper=False):
    return jnp.linalg.cholesky(_floating(x), upper=upper)


def det(x, /):
    return jnp.linalg.det(_floating(x))


def eigh(x, /):
    return jnp.linalg.eigh(_floating(x))


def eigvalsh(x, /):
    return jnp.linalg.eigvalsh(_floating(x))


def inv(x, /):
    return jnp.linalg.inv(_floating(x))


def matrix_norm(x, /, *, keepdims=False, ord="fro"):
    return jnp.linalg.matrix_norm(_floating(x), keepdims=keepdims, ord=ord)


def matrix_power(x, n, /):
    """Integer matrices stay integer for ``n >= 0``; a negative ``n`` inverts in float32."""
    return jnp.linalg.matrix_power(x if n >= 0 else _floating(x), n)


def matrix_rank(x, /, *, rtol=None):
    """jnp.linalg.matrix_rank reads ``rtol`` as an absolute tolerance; here it is relative to
    the largest singular value, as the Array API says."""
    x = _floating(x)
    s = jnp.linalg.svdvals(x)
    if rtol is None:
        rtol = max(x.shape[-2:]) * jnp.finfo(s.dtype).eps
    tol = jnp.asarray(rtol, s.dtype)[..., None] * jnp.max(s, axis=-1, keepdims=True)
    return jnp.sum(s > tol, axis=-1)


def pinv(x, /, *, rtol=None):
    return jnp.linalg.pinv(_floating(x), rtol=rtol)


def qr(x, /, *, mode="reduced"):
    return jnp.linalg.qr(_floating(x), mode=mode)


def slogdet(x, /):
    return jnp.linalg.slogdet(_floating(x))


def solve(x1, x2, /):
    return jnp.linalg.solve(_floating(x1), _floating(x2))


def svd(x, /, *, full_matrices=True):
    return jnp.linalg.svd(_floating(x), full_matrices=full_matrices)


def svdvals(x, /):
    return jnp.linalg.svdvals(_floating(x))


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    return jnp.linalg.vector_norm(_floating(x), axis=axis, keepdims=keepdims, ord=ord)
