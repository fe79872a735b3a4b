"""numpy backend: linear algebra, the Array API ``linalg`` extension.

numpy 2's ``np.linalg`` has the Array API signatures and returns namedtuples (``EighResult``,
``QRResult``, ``SlogdetResult``, ``SVDResult``); it is exported as is where it agrees with ivy.
The shims only compute bool and integer inputs of the floating-point functions in float32, the
default float dtype (numpy would use float64).
"""

from __future__ import annotations

import numpy as np

from ivy.backends.numpy._helpers import as_inexact

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

matmul = np.matmul
diagonal = np.linalg.diagonal
matrix_transpose = np.linalg.matrix_transpose
outer = np.linalg.outer
tensordot = np.linalg.tensordot
trace = np.linalg.trace  # bool and small integers accumulate in int64 (unsigned: uint64)
vecdot = np.linalg.vecdot


def cholesky(x, /, *, upper=False):
    return np.linalg.cholesky(as_inexact(x), upper=upper)


def cross(x1, x2, /, *, axis=-1):
    return np.cross(x1, x2, axis=axis)


def det(x, /):
    return np.linalg.det(as_inexact(x))


def eigh(x, /):
    return np.linalg.eigh(as_inexact(x))


def eigvalsh(x, /):
    return np.linalg.eigvalsh(as_inexact(x))


def inv(x, /):
    return np.linalg.inv(as_inexact(x))


def matrix_norm(x, /, *, keepdims=False, ord="fro"):
    return np.linalg.matrix_norm(as_inexact(x), keepdims=keepdims, ord=ord)


def matrix_power(x, n, /):
    """Integer matrices stay integer for ``n >= 0``; a negative ``n`` inverts in float32."""
    return np.linalg.matrix_power(x if n >= 0 else as_inexact(x), n)


def matrix_rank(x, /, *, rtol=None):
    return np.linalg.matrix_rank(as_inexact(x), rtol=rtol)


def pinv(x, /, *, rtol=None):
    return np.linalg.pinv(as_inexact(x), rtol=rtol)


def qr(x, /, *, mode="reduced"):
    return np.linalg.qr(as_inexact(x), mode=mode)


def slogdet(x, /):
    return np.linalg.slogdet(as_inexact(x))


def solve(x1, x2, /):
    return np.linalg.solve(as_inexact(x1), as_inexact(x2))


def svd(x, /, *, full_matrices=True):
    return np.linalg.svd(as_inexact(x), full_matrices=full_matrices)


def svdvals(x, /):
    return np.linalg.svdvals(as_inexact(x))


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    return np.linalg.vector_norm(as_inexact(x), axis=axis, keepdims=keepdims, ord=ord)
