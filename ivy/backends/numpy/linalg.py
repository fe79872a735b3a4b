"""numpy backend: linear algebra."""

from __future__ import annotations

import numpy as np

__all__ = ["matmul", "cross", "svd", "inv", "pinv", "vector_norm"]

matmul = np.matmul
inv = np.linalg.inv


def cross(x1, x2, /, *, axis=-1):
    return np.cross(x1, x2, axis=axis)


def svd(x, /, *, full_matrices=True):
    return np.linalg.svd(x, full_matrices=full_matrices)


def pinv(x, /, *, rtol=None):
    return np.linalg.pinv(x, rtol=rtol)


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    return np.linalg.vector_norm(x, axis=axis, keepdims=keepdims, ord=ord)
