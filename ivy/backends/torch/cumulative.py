"""torch backend: cumulative sums and products.

torch accumulates every integer dtype in int64; unsigned inputs give uint64 here (computed in
int64: the bits are the same modulo 2**64), as on the other backends.
"""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import native_dtype

_UNSIGNED = (torch.uint8, torch.uint16, torch.uint32, torch.uint64)


def _cumulative(fn, identity, x, axis, exclusive, reverse, dtype):
    dtype = native_dtype(dtype)
    if dtype is None:
        dtype = torch.uint64 if x.dtype in _UNSIGNED else None  # None: torch's own choice
    final = dtype
    if dtype in _UNSIGNED:  # torch lacks most kernels for uint64: work in int64
        x, dtype = x.to(torch.int64), torch.int64
    if reverse:
        x = torch.flip(x, (axis,))
    out = fn(x, axis, dtype=dtype)
    if exclusive and out.shape[axis]:
        head = torch.full_like(out.narrow(axis, 0, 1), identity)
        out = torch.cat([head, out.narrow(axis, 0, out.shape[axis] - 1)], axis)
    if reverse:
        out = torch.flip(out, (axis,))
    return out if final is None or out.dtype == final else out.to(final)


def cumsum(x, /, axis=0, *, exclusive=False, reverse=False, dtype=None):
    return _cumulative(torch.cumsum, 0, x, axis, exclusive, reverse, dtype)


def cumprod(x, /, axis=0, *, exclusive=False, reverse=False, dtype=None):
    return _cumulative(torch.cumprod, 1, x, axis, exclusive, reverse, dtype)
