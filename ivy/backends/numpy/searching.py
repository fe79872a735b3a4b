"""numpy backend: searching."""

from __future__ import annotations

import numpy as np


def argmax(x, /, *, axis=None, keepdims=False):
    return np.asarray(np.argmax(x, axis=axis, keepdims=keepdims), dtype=np.int64)


def argmin(x, /, *, axis=None, keepdims=False):
    return np.asarray(np.argmin(x, axis=axis, keepdims=keepdims), dtype=np.int64)


where = np.where
count_nonzero = np.count_nonzero  # int64 (numpy's intp)
nonzero = np.nonzero  # a tuple of int64 index arrays; 0-d input raises
searchsorted = np.searchsorted
