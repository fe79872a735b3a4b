"""torch backend: reductions (integer sums and products accumulate in int64, as torch does)."""

from __future__ import annotations

import math

import torch

from ivy._args.axes import cumulative_axis, too_few_for_correction
from ivy.backends import _signed_zeros
from ivy.backends.torch._helpers import as_inexact, native_dtype, reduction_args
from ivy.backends.torch._unsigned import WIDE_UNSIGNED, unsigned_safe, work_dtype

_UNSIGNED = (torch.uint8, torch.uint16, torch.uint32, torch.uint64)


def _accumulator(x, dtype):
    """``(work, final)``: the dtype to accumulate in and the result's. Unsigned integers give
    uint64 (the default unsigned integer), accumulated in int64, whose wrap-around is the same
    (torch would give int64, and has no uint64 kernels)."""
    dtype = native_dtype(dtype)
    if dtype is None and x.dtype in _UNSIGNED:
        dtype = torch.uint64
    return work_dtype(dtype), dtype


def sum(x, /, *, axis=None, dtype=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    work, final = _accumulator(x, dtype)
    if work is not final and x.dtype in WIDE_UNSIGNED:
        x = x.to(torch.int64)
    out = torch.sum(x, dim=dim, keepdim=keepdim, dtype=work)
    return out if final is None or out.dtype is final else out.to(final)


def prod(x, /, *, axis=None, dtype=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    dtype, final = _accumulator(x, dtype)
    if dtype is not final and x.dtype in WIDE_UNSIGNED:
        x = x.to(torch.int64)
    out = _prod(x, dim, keepdim, dtype)
    return out if final is None or out.dtype is final else out.to(final)


def _prod(x, dim, keepdim, dtype):
    if dim is None:
        out = torch.prod(x, dtype=dtype)
        return out.reshape((1,) * x.ndim) if keepdim else out
    if isinstance(dim, int):
        return torch.prod(x, dim, keepdim=keepdim, dtype=dtype)
    for d in sorted({d % x.ndim for d in dim}, reverse=True):  # torch.prod takes one dim
        x = torch.prod(x, d, keepdim=keepdim, dtype=dtype)
    return x


def mean(x, /, *, axis=None, keepdims=False):
    x, dim, keepdim = reduction_args(as_inexact(x), axis, keepdims)
    return torch.mean(x, dim=dim, keepdim=keepdim)


_amin = unsigned_safe(torch.amin, "min", "order", (0,))
_amax = unsigned_safe(torch.amax, "max", "order", (0,))


def _signed_zero(x, out, dim, keepdim, lower: bool):
    """``out``, torch's ``amin`` or ``amax`` of ``x``, with IEEE's sign of a zero result
    (``ivy/backends/_signed_zeros.py``)."""
    if not out.is_floating_point():
        return out
    if out.device.type == "cpu" and not torch.compiler.is_compiling():
        # (eager on the CPU: a test is cheaper than the fix)
        if (out.item() != 0) if out.numel() == 1 else not (out.detach().numpy() == 0).any():
            return out
    signed = torch.signbit(x) if lower else torch.logical_not(torch.signbit(x))
    hits = torch.logical_and(x == 0, signed)
    found = torch.any(hits) if dim is None else torch.any(hits, dim=dim, keepdim=keepdim)
    if dim is None and keepdim:
        found = found.reshape((1,) * x.ndim)
    negative = found if lower else torch.logical_not(found)
    return _signed_zeros.reduced_zero(torch.where, torch.Tensor.detach, out, negative)


def min(x, /, *, axis=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return _signed_zero(x, _amin(x, dim=dim, keepdim=keepdim), dim, keepdim, True)


def max(x, /, *, axis=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return _signed_zero(x, _amax(x, dim=dim, keepdim=keepdim), dim, keepdim, False)


def var(x, /, *, axis=None, correction=0.0, keepdims=False):
    return _spread(torch.var, x, axis, correction, keepdims)


def std(x, /, *, axis=None, correction=0.0, keepdims=False):
    return _spread(torch.std, x, axis, correction, keepdims)


def _spread(native, x, axis, correction, keepdims):
    """torch's var or std; NaN where ``N - correction <= 0``, as the standard says (torch: inf)."""
    x = as_inexact(x)
    too_few = too_few_for_correction(x.shape, axis, correction)
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    if too_few:  # (the shape of the result, without torch's warning)
        return torch.full_like(native(x, dim=dim, correction=0, keepdim=keepdim), math.nan)
    return native(x, dim=dim, correction=correction, keepdim=keepdim)


def _cumulative(native, initial, x, axis, dtype, include_initial, name):
    """``native`` (cumsum, cumprod) along ``axis``. Bools and signed integers accumulate in int64,
    unsigned integers in uint64 (computed in int64, whose wrap-around is the same, since torch
    has no uint64 kernels)."""
    axis = cumulative_axis(axis, x.ndim, name)
    out_dtype = native_dtype(dtype)
    if out_dtype is None:
        if x.dtype in _UNSIGNED:
            out_dtype = torch.uint64
        elif x.dtype is torch.bool or not (x.is_floating_point() or x.is_complex()):
            out_dtype = torch.int64
        else:
            out_dtype = x.dtype
    work = torch.int64 if out_dtype in _UNSIGNED else out_dtype
    if x.dtype in _UNSIGNED[1:]:
        x = x.to(torch.int64)  # torch casts from uint16+ but computes nothing else with them
    out = native(x, axis, dtype=work)
    if include_initial:
        shape = list(out.shape)
        shape[axis] = 1
        out = torch.cat([torch.full(shape, initial, dtype=work, device=out.device), out], axis)
    return out if work is out_dtype else out.to(out_dtype)


def cumulative_sum(x, /, *, axis=None, dtype=None, include_initial=False):
    return _cumulative(torch.cumsum, 0, x, axis, dtype, include_initial, "cumulative_sum")


def cumulative_prod(x, /, *, axis=None, dtype=None, include_initial=False):
    return _cumulative(torch.cumprod, 1, x, axis, dtype, include_initial, "cumulative_prod")


def logsumexp(x, /, *, axis=None, keepdims=False):
    if not (x.is_floating_point() or x.is_complex()):
        x = x.to(torch.float32)
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    if dim is None:
        dim = tuple(range(x.ndim)) if x.ndim else 0  # torch.logsumexp needs the dims
    return torch.logsumexp(x, dim, keepdim=keepdim)
