"""numpy backend: searching."""

from __future__ import annotations

import numpy as np

__all__ = ["argmax", "argmin", "where"]


def argmax(x, /, *, axis=None, keepdims=False):
    return np.asarray(np.argmax(x, axis=axis, keepdims=keepdims), dtype=np.int64)


def argmin(x, /, *, axis=None, keepdims=False):
    return np.asarray(np.argmin(x, axis=axis, keepdims=keepdims), dtype=np.int64)


where = np.where
