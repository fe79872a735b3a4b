"""numpy backend: cumulative sums and products (numpy's own accumulation dtypes are ivy's)."""

from __future__ import annotations

import numpy as np

from ivy.backends.numpy._helpers import native_dtype


def _cumulative(fn, identity, x, axis, exclusive, reverse, dtype):
    x = np.asarray(x)
    if reverse:
        x = np.flip(x, axis)
    out = fn(x, axis=axis, dtype=native_dtype(dtype))
    if exclusive and out.shape[axis]:
        head = np.full_like(np.take(out, [0], axis=axis), identity)
        out = np.concatenate([head, np.delete(out, -1, axis=axis)], axis=axis)
    return np.flip(out, axis) if reverse else out


def cumsum(x, /, axis=0, *, exclusive=False, reverse=False, dtype=None):
    return _cumulative(np.cumsum, 0, x, axis, exclusive, reverse, dtype)


def cumprod(x, /, axis=0, *, exclusive=False, reverse=False, dtype=None):
    return _cumulative(np.cumprod, 1, x, axis, exclusive, reverse, dtype)
