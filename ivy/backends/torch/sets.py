"""torch backend: unique values from ``torch.unique`` (sorted; each NaN a distinct value, -0.0 and
0.0 one value), as the Array API's named tuples; the indices of first occurrences, which torch
does not return, come from its inverse indices."""

from __future__ import annotations

import torch

from ivy.backends.torch._unsigned import WIDE_UNSIGNED, order_key, promoted
from ivy.core._results import UniqueAllResult, UniqueCountsResult, UniqueInverseResult


def unique_all(x, /):
    values, inverse, counts = torch.unique(x, return_inverse=True, return_counts=True)
    flat = inverse.reshape(-1)
    n = flat.numel()
    positions = torch.arange(n, device=flat.device)
    first = torch.full((values.shape[0],), n, dtype=torch.int64, device=flat.device)
    first = first.scatter_reduce(0, flat, positions, reduce="amin")
    return UniqueAllResult(values, first, inverse.reshape(x.shape), counts)


def unique_counts(x, /):
    values, counts = torch.unique(x, return_counts=True)
    return UniqueCountsResult(values, counts)


def unique_inverse(x, /):
    values, inverse = torch.unique(x, return_inverse=True)
    return UniqueInverseResult(values, inverse.reshape(x.shape))


def unique_values(x, /):
    return torch.unique(x)


def isin(x1, x2, /, *, invert=False):
    if not isinstance(x2, torch.Tensor):
        x2 = torch.as_tensor(x2, device=x1.device)
    if x1.dtype is not x2.dtype:
        dtype = promoted((x1, x2))
        x1, x2 = x1.to(dtype), x2.to(dtype)
    if x1.dtype in WIDE_UNSIGNED:  # no torch kernel: their order keys
        x1, x2 = order_key(x1), order_key(x2)
    return torch.isin(x1, x2, invert=invert)
