"""numpy backend: reductions."""

from __future__ import annotations

import numpy as np

from ivy._args.axes import cumulative_axis
from ivy.backends.numpy._helpers import native_dtype


def sum(x, /, *, axis=None, dtype=None, keepdims=False):
    return np.sum(x, axis=axis, dtype=native_dtype(dtype), keepdims=keepdims)


def prod(x, /, *, axis=None, dtype=None, keepdims=False):
    return np.prod(x, axis=axis, dtype=native_dtype(dtype), keepdims=keepdims)


def _signed_zero(x, out, axis, keepdims, lower: bool):
    """``out``, numpy's ``min`` or ``max`` of ``x``, with IEEE's sign of a zero result (numpy's
    depends on the array's length; ``ivy/backends/_signed_zeros.py``)."""
    if out.dtype.kind != "f" or not np.any(out == 0):  # (eager: a test is cheaper than the fix)
        return out
    x = np.asarray(x)
    zeros = np.equal(x, 0)
    signed = np.signbit(x) if lower else np.logical_not(np.signbit(x))
    found = np.any(np.logical_and(zeros, signed), axis=axis, keepdims=keepdims)
    negative = found if lower else np.logical_not(found)
    fixed = np.where(out == 0, np.where(negative, -0.0, 0.0).astype(out.dtype), out)
    return fixed if np.ndim(out) else fixed[()]


def min(x, /, *, axis=None, keepdims=False):
    return _signed_zero(x, np.min(x, axis=axis, keepdims=keepdims), axis, keepdims, True)


def max(x, /, *, axis=None, keepdims=False):
    return _signed_zero(x, np.max(x, axis=axis, keepdims=keepdims), axis, keepdims, False)


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
