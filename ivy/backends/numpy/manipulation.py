"""numpy backend: shape manipulation."""

from __future__ import annotations

import numpy as np

from ivy.core import _dtype_rules as rules


def reshape(x, /, shape, *, copy=None):
    out = np.reshape(x, shape)
    return out.copy() if copy else out


def permute_dims(x, /, axes):
    return np.transpose(x, axes)


def transpose(x, /, axes=None):
    return np.transpose(x, axes)


def concat(arrays, /, *, axis=0):
    dtypes = {getattr(a, "dtype", None) for a in arrays}
    if len(dtypes) > 1 and None not in dtypes:  # by ivy's rules: int64 with float32 is float32
        dtype = rules.result_type([d.name for d in dtypes])
        return np.concatenate(arrays, axis=axis, dtype=dtype, casting="unsafe")
    return np.concatenate(arrays, axis=axis)


def stack(arrays, /, *, axis=0):
    return np.stack(arrays, axis=axis)


def unstack(x, /, *, axis=0):
    if axis == 0 and x.ndim:  # slices: several times cheaper than np.moveaxis
        return tuple([x[i, ...] for i in range(x.shape[0])])
    return tuple(np.moveaxis(x, axis, 0))


def split(x, /, num_or_size_splits=None, *, axis=0):
    if num_or_size_splits is None:
        num_or_size_splits = x.shape[axis]
    if isinstance(num_or_size_splits, (int, np.integer)):
        if x.shape[axis] % num_or_size_splits:
            raise ValueError(
                f"split: axis {axis} of size {x.shape[axis]} does not divide into "
                f"{num_or_size_splits} equal pieces; pass a list of piece sizes instead."
            )
        return list(np.split(x, num_or_size_splits, axis=axis))
    sizes = list(num_or_size_splits)
    if sum(sizes) != x.shape[axis]:
        raise ValueError(
            f"split: piece sizes {sizes} add up to {sum(sizes)}, not to the size "
            f"{x.shape[axis]} of axis {axis}."
        )
    return list(np.split(x, np.cumsum(sizes)[:-1], axis=axis))


def squeeze(x, /, axis=None):
    return np.squeeze(x, axis=axis)


def expand_dims(x, /, axis=0):
    return np.expand_dims(x, axis)


def flip(x, /, *, axis=None):
    return np.flip(x, axis=axis)


def tile(x, repetitions, /):
    return np.tile(x, repetitions)


def repeat(x, repeats, /, *, axis=None):
    return np.repeat(x, repeats, axis=axis)


def roll(x, /, shift, *, axis=None):
    return np.roll(x, shift, axis=axis)


def swapaxes(x, axis0, axis1, /):
    return np.swapaxes(x, axis0, axis1)


def broadcast_to(x, /, shape):
    return np.broadcast_to(x, shape)


moveaxis = np.moveaxis


def broadcast_arrays(*arrays):
    return list(np.broadcast_arrays(*arrays))
