"""Linear algebra."""

from __future__ import annotations

from ivy.core._dispatch import alias, dispatch

__all__ = ["matmul", "cross", "svd", "inv", "pinv", "vector_norm", "norm"]


@dispatch("x1", "x2")
def matmul(x1, x2, /, *, f=None):
    """Matrix product with batch broadcasting (1-D operands as in numpy)."""


@dispatch("x1", "x2")
def cross(x1, x2, /, *, axis=-1, f=None):
    """Cross product of 3-vectors along ``axis``."""


@dispatch
def svd(x, /, *, full_matrices=True, f=None):
    """Singular value decomposition ``(U, S, Vh)`` with ``x = U @ diag(S) @ Vh``; S descending."""


@dispatch
def inv(x, /, *, f=None):
    """Inverse of square matrices (batched)."""


@dispatch
def pinv(x, /, *, rtol=None, f=None):
    """Moore-Penrose pseudo-inverse; singular values below ``rtol * max(S)`` are dropped."""


@dispatch
def vector_norm(x, /, *, axis=None, keepdims=False, ord=2, f=None):
    """Vector p-norm over ``axis`` (None: all elements; a tuple: those axes together).

    ``ord`` is any real p, ``inf`` or ``-inf``.
    """


norm = alias("norm", vector_norm)
