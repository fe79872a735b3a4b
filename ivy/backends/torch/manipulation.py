"""torch backend: shape manipulation."""

from __future__ import annotations

import torch

from ivy.backends.torch.creation import asarray

# torch accepts ``axis`` for ``dim``: stack(arrays, axis=1), unbind(x, axis=1) (a tuple),
# repeat_interleave(x, 2, axis=None) (flattens first, as numpy's repeat).
permute_dims = torch.permute
stack = torch.stack
unstack = torch.unbind
tile = torch.tile
repeat = torch.repeat_interleave
swapaxes = torch.swapaxes


def reshape(x, /, shape, *, copy=None):
    if copy is False:
        return x.view(shape)  # raises if the new shape needs a copy
    out = x.reshape(shape)
    return out.clone() if copy else out


def transpose(x, /, axes=None):
    return x.permute(tuple(reversed(range(x.ndim))) if axes is None else axes)


def concat(arrays, /, *, axis=0):
    if axis is None:
        return torch.cat([a.reshape(-1) for a in arrays])
    return torch.cat(arrays, dim=axis)


def split(x, /, num_or_size_splits=None, *, axis=0):
    size = x.shape[axis]
    pieces = size if num_or_size_splits is None else num_or_size_splits
    if not isinstance(pieces, (list, tuple)) and not (
        isinstance(pieces, torch.Tensor) and pieces.ndim
    ):
        pieces = int(pieces)
        if size % pieces:
            raise ValueError(
                f"split: axis {axis} of size {size} does not divide into "
                f"{pieces} equal pieces; pass a list of piece sizes instead."
            )
        return list(torch.tensor_split(x, pieces, dim=axis))
    sizes = [int(s) for s in pieces]
    if sum(sizes) != size:
        raise ValueError(
            f"split: piece sizes {sizes} add up to {sum(sizes)}, not to the size "
            f"{size} of axis {axis}."
        )
    return list(torch.split(x, sizes, dim=axis))


def squeeze(x, /, axis=None):
    if axis is None:
        return torch.squeeze(x)
    axes = (axis,) if isinstance(axis, int) else tuple(axis)
    if any(x.shape[a] != 1 for a in axes):  # torch would skip such axes silently
        raise ValueError(
            f"squeeze: cannot remove axis {axis} of shape {tuple(x.shape)}: only axes of size 1 "
            f"can be removed."
        )
    return torch.squeeze(x, axes)


def expand_dims(x, /, *, axis=0):
    return torch.unsqueeze(x, axis)


def flip(x, /, *, axis=None):
    if axis is None:
        return torch.flip(x, tuple(range(x.ndim)))
    return torch.flip(x, (axis,) if isinstance(axis, int) else axis)


def roll(x, /, shift, *, axis=None):
    if isinstance(axis, (tuple, list)) and isinstance(shift, int):
        shift = (shift,) * len(axis)  # numpy shifts every axis by a lone shift
    return torch.roll(x, shift, () if axis is None else axis)


moveaxis = torch.moveaxis


def broadcast_arrays(*arrays):
    arrays = [a if isinstance(a, torch.Tensor) else asarray(a) for a in arrays]
    return list(torch.broadcast_tensors(*arrays))


def broadcast_to(x, /, shape):
    # torch names the shape argument `size`; the Array API names it `shape`.
    return torch.broadcast_to(x, shape)
