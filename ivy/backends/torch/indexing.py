"""torch backend: gathering and scattering."""

from __future__ import annotations

import math

import torch

from ivy._args.axes import normalize_axis
from ivy.backends._index_checks import check_bounds, check_rows
from ivy.backends.torch._helpers import native_dtype
from ivy.backends.torch._unsigned import SIGNED_OF, WIDE_UNSIGNED, from_order_key, order_key

indices_where = torch.argwhere

_REDUCE = {"min": "amin", "max": "amax"}


def _compiling() -> bool:
    return torch.compiler.is_compiling()


def _signed_view(x):
    """``x``, or for uint16, uint32 and uint64 (few torch kernels) the same bits as the signed
    type of the same width, and the dtype to view the result back as (None: as it is)."""
    signed = SIGNED_OF.get(x.dtype)
    return (x, None) if signed is None else (x.view(signed), x.dtype)


def _back(out, dtype):
    return out if dtype is None else out.view(dtype)


def take(x, indices, /, *, axis=None):
    """``index_select`` for 1-D indices (3-5x faster than advanced indexing on the CPU), with
    negative indices counted from the end; advanced indexing for the others."""
    indices = torch.as_tensor(indices, device=x.device)
    x, dtype = _signed_view(x)
    if axis is None:
        return _back(torch.take(x, indices.long()), dtype)
    axis = normalize_axis(axis, x.ndim, "take", "torch")
    if indices.ndim == 1:
        if indices.dtype is not torch.int64 and indices.dtype is not torch.int32:
            indices = indices.long()
        size = x.shape[axis]
        wrapped = torch.where(indices < 0, indices + size, indices)  # index_select: no negatives
        return _back(torch.index_select(x, axis, wrapped), dtype)
    return _back(x[(slice(None),) * axis + (indices,)], dtype)


def _index_tuple(indices, device):
    return torch.as_tensor(indices, device=device).unbind(-1)


def gather_nd(params, indices, /):
    params, dtype = _signed_view(params)
    return _back(params[_index_tuple(indices, params.device)], dtype)


def scatter_nd(indices, updates, /, shape, *, reduction="sum"):
    updates = torch.as_tensor(updates)
    if updates.dtype in WIDE_UNSIGNED:  # no torch kernels: sums in int64 (the same bits),
        # minima and maxima by order keys
        final = updates.dtype
        if reduction in ("min", "max"):
            out = scatter_nd(indices, order_key(updates), shape, reduction=reduction)
            touched = scatter_nd(indices, torch.ones_like(updates, dtype=torch.int64), shape)
            return torch.where(
                touched > 0, from_order_key(out, final).view(SIGNED_OF[final]), 0
            ).view(final)
        return scatter_nd(indices, updates.to(torch.int64), shape, reduction=reduction).to(final)
    idx = _index_tuple(indices, updates.device)
    shape = tuple(int(s) for s in shape)
    out = torch.zeros(shape, dtype=updates.dtype, device=updates.device)
    if reduction in ("sum", "replace"):
        return out.index_put_(idx, updates, accumulate=reduction == "sum")
    if reduction not in _REDUCE:
        raise ValueError(
            f"scatter_nd: unknown reduction {reduction!r}; use 'sum', 'replace', 'min' or 'max'."
        )
    # min/max: number the indexed places (indexing checks the bounds and counts negative
    # indices from the end), then reduce the updates of each place; untouched places stay 0.
    lead, rest = shape[: len(idx)], shape[len(idx) :]
    places = torch.arange(math.prod(lead), device=out.device).reshape(lead)[idx]
    updates = torch.broadcast_to(updates, (*places.shape, *rest)).reshape(-1, *rest)
    places = places.reshape(-1, *(1,) * len(rest)).expand_as(updates)
    out.view(-1, *rest).scatter_reduce_(0, places, updates, _REDUCE[reduction], include_self=False)
    return out


def one_hot(indices, depth, /, *, dtype=None):
    indices = torch.as_tensor(indices)
    if not _compiling():
        check_bounds(
            indices.cpu().numpy(), depth, function="one_hot", backend="torch", negative=False
        )
    hot = indices[..., None] == torch.arange(depth, device=indices.device)
    return hot.to(native_dtype(dtype) or torch.float32)


def gather_flat(params, indices, /):
    indices = torch.as_tensor(indices, device=params.device)
    params, dtype = _signed_view(params)
    return _back(torch.take(params, indices.long()), dtype)  # torch.take wants int64 indices


def scatter_flat(indices, updates, /, size, *, reduction="sum"):
    indices = torch.as_tensor(indices)[..., None]
    return scatter_nd(indices, updates, (size,), reduction=reduction)


def take_along_axis(x, indices, /, *, axis=-1):
    indices = torch.as_tensor(indices, device=x.device).long()  # torch wants int64 indices
    size = x.shape[axis]
    if not _compiling():  # (torch's take_along_dim does not check the bounds)
        check_bounds(indices.cpu().numpy(), size, function="take_along_axis", backend="torch")
    indices = torch.where(indices < 0, indices + size, indices)  # negatives from the end
    x, dtype = _signed_view(x)
    return _back(torch.take_along_dim(x, indices, dim=axis), dtype)


def put_rows(x, indices, updates, /):
    """Out-of-place ``index_copy`` along axis 0 (differentiable in ``x`` and ``updates``), with
    negative indices counted from the end."""
    indices = torch.as_tensor(indices, device=x.device)
    updates = torch.as_tensor(updates, device=x.device)
    integer = not indices.dtype.is_floating_point and not indices.dtype.is_complex
    integer = integer and indices.dtype is not torch.bool
    check_rows(x.shape, indices.shape, updates.shape, integer=integer, backend="torch")
    size = x.shape[0]
    if not _compiling():  # (index_copy checks bounds only on the CPU)
        check_bounds(indices.cpu().numpy(), size, function="put_rows", backend="torch")
    indices = indices.long()
    indices = torch.where(indices < 0, indices + size, indices)
    x, dtype = _signed_view(x)
    updates = updates.to(dtype or x.dtype)
    if dtype is not None:
        updates = updates.view(x.dtype)
    return _back(x.index_copy(0, indices, updates), dtype)
