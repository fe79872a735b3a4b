"""torch backend: reductions (integer sums and products accumulate in int64, as torch does)."""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import native_dtype, reduction_args

__all__ = ["sum", "prod", "mean", "min", "max", "var", "std"]


def sum(x, /, *, axis=None, dtype=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.sum(x, dim=dim, keepdim=keepdim, dtype=native_dtype(dtype))


def prod(x, /, *, axis=None, dtype=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    dtype = native_dtype(dtype)
    if dim is None:
        out = torch.prod(x, dtype=dtype)
        return out.reshape((1,) * x.ndim) if keepdim else out
    if isinstance(dim, int):
        return torch.prod(x, dim, keepdim=keepdim, dtype=dtype)
    for d in sorted({d % x.ndim for d in dim}, reverse=True):  # torch.prod takes one dim
        x = torch.prod(x, d, keepdim=keepdim, dtype=dtype)
    return x


def mean(x, /, *, axis=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.mean(x, dim=dim, keepdim=keepdim)


def min(x, /, *, axis=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.amin(x, dim=dim, keepdim=keepdim)


def max(x, /, *, axis=None, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.amax(x, dim=dim, keepdim=keepdim)


def var(x, /, *, axis=None, correction=0.0, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.var(x, dim=dim, correction=correction, keepdim=keepdim)


def std(x, /, *, axis=None, correction=0.0, keepdims=False):
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.std(x, dim=dim, correction=correction, keepdim=keepdim)
