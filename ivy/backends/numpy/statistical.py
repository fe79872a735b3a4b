"""numpy backend: reductions."""

from __future__ import annotations

import numpy as np

from ivy._args.axes import cumulative_axis
from ivy.backends.numpy._helpers import native_dtype


def sum(x, /, *, axis=None, dtype=None, keepdims=False):
    return np.sum(x, axis=axis, dtype=native_dtype(dtype), keepdims=keepdims)


def prod(x, /, *, axis=None, dtype=None, keepdims=False):
    return np.prod(x, axis=axis, dtype=native_dtype(dtype), keepdims=keepdims)


def min(x, /, *, axis=None, keepdims=False):
    return np.min(x, axis=axis, keepdims=keepdims)


def max(x, /, *, axis=None, keepdims=False):
    return np.max(x, axis=axis, keepdims=keepdims)


def cumulative_sum(x, /, *, axis=None, dtype=None, include_initial=False):
    return np.cumulative_sum(
        x,
        axis=cumulative_axis(axis, np.ndim(x), "cumulative_sum"),
        dtype=native_dtype(dtype),
        include_initial=include_initial,
    )


def cumulative_prod(x, /, *, axis=None, dtype=None, include_initial=False):
    return np.cumulative_prod(
        x,
        axis=cumulative_axis(axis, np.ndim(x), "cumulative_prod"),
        dtype=native_dtype(dtype),
        include_initial=include_initial,
    )


def logsumexp(x, /, *, axis=None, keepdims=False):
    """Shifted by the maximum (0 where that is infinite, so that -inf and inf give themselves)."""
    x = np.asarray(x)
    if x.dtype.kind not in "fc":
        x = x.astype(np.float32)
    shift = np.max(x, axis=axis, keepdims=True, initial=-np.inf)
    shift = np.where(np.isfinite(shift), shift, np.zeros((), x.dtype))
    with np.errstate(divide="ignore"):  # log(0) = -inf: no element, or all -inf
        out = np.log(np.sum(np.exp(x - shift), axis=axis, keepdims=keepdims))
    return out + (shift if keepdims else np.squeeze(shift, axis=axis))
