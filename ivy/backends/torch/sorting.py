"""torch backend: sorting (torch's own: NaN is the largest value, last ascending and first
descending; a stable descending sort keeps equal elements in their order)."""

from __future__ import annotations

import torch

from ivy._args.axes import normalize_axis
from ivy.backends._sample_args import top_k_axis
from ivy.backends.torch._unsigned import SIGNED_OF, WIDE_UNSIGNED, order_key
from ivy.core._results import TopKResult


def argsort(x, /, *, axis=-1, descending=False, stable=True):
    if x.ndim == 0:  # (torch sorts a 0-d tensor along axis -1; the other backends raise)
        normalize_axis(axis, 0, "argsort", "torch")
    return torch.argsort(x, dim=axis, descending=descending, stable=stable)


def sort(x, /, *, axis=-1, descending=False, stable=True):
    if x.ndim == 0:
        normalize_axis(axis, 0, "sort", "torch")
    return torch.sort(x, dim=axis, descending=descending, stable=stable).values


def top_k(x, k, /, *, axis=-1, largest=True, sorted=True):
    """torch.topk finds the k best values, but among equal ones it picks any, in any order. So
    only its k-th value is kept: a second topk, of integer keys, takes every element better than
    that value and then the first ones equal to it, in index order; a stable sort of those k
    orders them."""
    dim = top_k_axis(x.shape, k, axis)
    if x.dtype is torch.bool:  # torch has no topk of bools
        key = x.to(torch.uint8)
    elif x.dtype in WIDE_UNSIGNED:  # nor of uint16, uint32, uint64: their order keys
        key = order_key(x)
    else:
        key = x
    n = x.shape[dim]
    if k == 0:
        values = x.narrow(dim, 0, 0)
        return TopKResult(values, torch.zeros(values.shape, dtype=torch.int64, device=x.device))
    kth = torch.topk(key, k, dim, largest=largest, sorted=True).values.narrow(dim, k - 1, 1)
    if key.is_floating_point():  # NaN is the largest value
        nan, nan_kth = key.isnan(), kth.isnan()
        if largest:
            better = (key > kth) | (nan & ~nan_kth)
        else:
            better = (key < kth) | (~nan & nan_kth)
        tied = (key == kth) | (nan & nan_kth)
    else:
        better = key > kth if largest else key < kth
        tied = key == kth
    shape = [1] * x.ndim
    shape[dim] = n
    small = torch.int32 if 2 * n < 2**31 else torch.int64  # int32 keys: faster wheres
    rank = torch.arange(n, 0, -1, dtype=small, device=x.device).reshape(shape)  # earlier: larger
    # every better element (fewer than k) outranks every tied one, which outranks the rest
    ranking = torch.where(better, rank + n, torch.where(tied, rank, 0))
    indices = torch.topk(ranking, k, dim).indices
    if sorted:  # by value; equal values stay in index order
        by_value = torch.sort(key.gather(dim, indices), dim=dim, descending=largest, stable=True)
        indices = indices.gather(dim, by_value[1])
    if x.dtype in WIDE_UNSIGNED:  # gather the same bits, seen as signed
        return TopKResult(x.view(SIGNED_OF[x.dtype]).gather(dim, indices).view(x.dtype), indices)
    return TopKResult(x.gather(dim, indices), indices)
