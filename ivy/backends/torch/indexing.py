"""torch backend: gathering and scattering."""

from __future__ import annotations

import math

import torch

from ivy.backends.torch._helpers import native_dtype

indices_where = torch.argwhere

_REDUCE = {"min": "amin", "max": "amax"}


def take(x, indices, /, *, axis=None):
    indices = torch.as_tensor(indices, device=x.device)
    if axis is None:
        return torch.take(x, indices)
    axis = axis + x.ndim if axis < 0 else axis
    return x[(slice(None),) * axis + (indices,)]  # negative indices count from the end


def _index_tuple(indices, device):
    return torch.as_tensor(indices, device=device).unbind(-1)


def gather_nd(params, indices, /):
    return params[_index_tuple(indices, params.device)]


def scatter_nd(indices, updates, /, shape, *, reduction="sum"):
    updates = torch.as_tensor(updates)
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
    hot = indices[..., None] == torch.arange(depth, device=indices.device)
    return hot.to(native_dtype(dtype) or torch.float32)


def gather_flat(params, indices, /):
    indices = torch.as_tensor(indices, device=params.device)
    return torch.take(params, indices.long())  # torch.take wants int64 indices


def scatter_flat(indices, updates, /, size, *, reduction="sum"):
    indices = torch.as_tensor(indices)[..., None]
    return scatter_nd(indices, updates, (size,), reduction=reduction)


def take_along_axis(x, indices, /, *, axis=-1):
    indices = torch.as_tensor(indices, device=x.device)
    return torch.take_along_dim(x, indices.long(), dim=axis)  # torch wants int64 indices
