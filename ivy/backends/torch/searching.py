"""torch backend: searching (torch's own functions: ``axis``/``keepdims`` are accepted spellings
of ``dim``/``keepdim``, and ``axis=None`` flattens)."""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import reduction_args

argmax = torch.argmax
argmin = torch.argmin
where = torch.where


def count_nonzero(x, /, *, axis=None, keepdims=False):
    """Counts int64 (torch's own count_nonzero has no keepdim and no uint16+ kernels)."""
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.sum(x != 0, dim=dim, keepdim=keepdim)


def nonzero(x, /):
    if x.ndim == 0:
        raise ValueError("nonzero needs an array of one or more dimensions, got a 0-d array.")
    return torch.nonzero(x, as_tuple=True)


def searchsorted(x1, x2, /, *, side="left", sorter=None):
    if not isinstance(x2, torch.Tensor):
        x2 = torch.asarray(x2, device=x1.device)
    if x1.dtype != x2.dtype:  # torch wants one dtype
        dtype = torch.promote_types(x1.dtype, x2.dtype)
        x1, x2 = x1.to(dtype), x2.to(dtype)
    return torch.searchsorted(x1, x2, side=side, sorter=sorter)
