"""torch backend: searching (torch's own functions: ``axis``/``keepdims`` are accepted spellings
of ``dim``/``keepdim``, and ``axis=None`` flattens)."""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import reduction_args
from ivy.backends.torch._unsigned import WIDE_UNSIGNED, order_key, promoted, unsigned_safe


def _arg_extreme(native, name: str):
    """torch's argmax or argmin; bools (no torch kernel) as uint8, uint16+ by order keys."""

    def fn(x, /, *, axis=None, keepdims=False):
        if x.dtype is torch.bool:
            x = x.to(torch.uint8)
        elif x.dtype in WIDE_UNSIGNED:
            x = order_key(x)
        if axis is None and keepdims:
            return native(x).reshape((1,) * x.ndim)
        return native(x, dim=axis, keepdim=keepdims)

    fn.__name__ = fn.__qualname__ = name
    return fn


argmax = _arg_extreme(torch.argmax, "argmax")
argmin = _arg_extreme(torch.argmin, "argmin")
_where = unsigned_safe(torch.where, "where", "move", (1, 2))


def where(condition, x1, x2, /):
    """Array API promotion of ``x1`` and ``x2`` (also of 0-d tensors, which torch promotes as
    Python scalars); a condition of another dtype is read as ``condition != 0``."""
    if isinstance(condition, torch.Tensor) and condition.dtype is not torch.bool:
        condition = condition != 0
    if isinstance(x1, torch.Tensor) and isinstance(x2, torch.Tensor) and x1.dtype is not x2.dtype:
        dtype = promoted((x1, x2))
        x1, x2 = x1.to(dtype), x2.to(dtype)
    return _where(condition, x1, x2)


def count_nonzero(x, /, *, axis=None, keepdims=False):
    """Counts int64 (torch's own count_nonzero has no keepdim and no uint16+ kernels)."""
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.sum(x != 0, dim=dim, keepdim=keepdim)


def nonzero(x, /):
    if x.ndim == 0:
        raise ValueError("nonzero needs an array of one or more dimensions, got a 0-d array.")
    if x.dtype in WIDE_UNSIGNED:
        x = x != 0  # torch has no nonzero kernel for them
    return torch.nonzero(x, as_tuple=True)


def searchsorted(x1, x2, /, *, side="left", sorter=None):
    if not isinstance(x2, torch.Tensor):
        x2 = torch.asarray(x2, device=x1.device)
    if x1.dtype != x2.dtype:  # torch wants one dtype
        dtype = promoted((x1, x2))
        x1, x2 = x1.to(dtype), x2.to(dtype)
    if x1.dtype in WIDE_UNSIGNED:  # no torch kernel: their order keys
        x1, x2 = order_key(x1), order_key(x2)
    if not x1.is_floating_point():
        return torch.searchsorted(x1, x2, side=side, sorter=sorter)
    # NaN sorts after every number (see ivy.searchsorted); torch's search compares with NaN
    if sorter is not None:
        x1 = x1[sorter]
    nans = torch.isnan(x1)
    x1 = torch.where(nans, torch.tensor(float("inf"), dtype=x1.dtype, device=x1.device), x1)
    out = torch.searchsorted(x1, x2, side=side)
    numbers = x1.shape[-1] - nans.sum()  # the NaNs: x1[numbers:]
    out = torch.minimum(out, numbers)
    return torch.where(torch.isnan(x2), numbers if side == "left" else x1.shape[-1], out)
