"""torch backend: shape manipulation."""

from __future__ import annotations

import torch

from ivy._args.axes import check_squeezable, new_axis_positions, normalize_axes
from ivy.backends.torch._unsigned import promoted, unsigned_safe
from ivy.backends.torch.creation import asarray

# torch accepts ``axis`` for ``dim``: stack(arrays, axis=1), unbind(x, axis=1) (a tuple),
# repeat_interleave(x, 2, axis=None) (flattens first, as numpy's repeat).
unstack = torch.unbind
_tile = unsigned_safe(torch.tile, "tile", "move", (0,))
swapaxes = torch.swapaxes


def permute_dims(x, /, axes):
    return torch.permute(x, axes)  # (torch names the argument dims)


def repeat(x, repeats, /, *, axis=None):
    if isinstance(repeats, torch.Tensor) and repeats.dtype is not torch.int64:
        repeats = repeats.to(torch.int64)  # torch counts in int64 only
    return torch.repeat_interleave(x, repeats, dim=axis)


def reshape(x, /, shape, *, copy=None):
    if copy is False:
        return x.view(shape)  # raises if the new shape needs a copy
    out = x.reshape(shape)
    return out.clone() if copy else out


def transpose(x, /, axes=None):
    return x.permute(tuple(reversed(range(x.ndim))) if axes is None else axes)


def _one_dtype(arrays):
    """``arrays`` in their dtype promoted by ivy's rules (torch promotes none of uint16, uint32
    and uint64, and stacks only one dtype)."""
    arrays = [a if isinstance(a, torch.Tensor) else asarray(a) for a in arrays]
    dtypes = {a.dtype for a in arrays}
    if len(dtypes) <= 1:
        return arrays
    dtype = promoted(arrays)
    return [a.to(dtype) for a in arrays]


def concat(arrays, /, *, axis=0):
    if not len(arrays):
        raise ValueError("concat needs at least one array.")
    arrays = _one_dtype(arrays)
    if axis is None:
        return torch.cat([a.reshape(-1) for a in arrays])
    return torch.cat(arrays, dim=axis)


def stack(arrays, /, *, axis=0):
    if not len(arrays):
        raise ValueError("stack needs at least one array.")
    return torch.stack(_one_dtype(arrays), dim=axis)


def tile(x, repetitions, /):
    return _tile(x, repetitions)


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
    axes = normalize_axes(axis, x.ndim, "squeeze", "torch")
    check_squeezable(x.shape, axes, axis, "torch")  # torch would skip such axes silently
    return torch.squeeze(x, axes) if axes else x


def expand_dims(x, /, axis=0):
    if isinstance(axis, int) and -x.ndim - 1 <= axis <= x.ndim:
        return torch.unsqueeze(x, axis)
    for position in new_axis_positions(axis, x.ndim, "expand_dims", "torch"):
        x = torch.unsqueeze(x, position)
    return x


_flip = unsigned_safe(torch.flip, "flip", "move", (0,))


def flip(x, /, *, axis=None):
    if axis is None:
        return _flip(x, tuple(range(x.ndim)))
    return _flip(x, (axis,) if isinstance(axis, int) else axis)


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
