"""tensorflow backend: shape manipulation."""

from __future__ import annotations

import numpy as np
import tensorflow as tf

from ivy._args.axes import check_squeezable, new_axis_positions, normalize_axes
from ivy.backends.tensorflow._helpers import (
    FAST_TYPES,
    REFUSED,
    normalize_axis,
    promote,
    static_rank,
    tensor,
)


def stack(arrays, /, *, axis=0):
    """tf.stack, with mixed dtypes promoted (tf would refuse them)."""
    if not len(arrays):  # (tf stacks nothing into an empty float32 array)
        raise ValueError("stack needs at least one array.")
    if all(type(a) in FAST_TYPES for a in arrays):
        try:
            return tf.stack(arrays, axis)
        except REFUSED:
            pass
    return tf.stack(promote(*arrays), axis)


repeat = tf.repeat
broadcast_to = tf.broadcast_to


def reshape(x, /, shape, *, copy=None):
    """tf tensors are immutable, so ``copy`` changes nothing."""
    return tf.reshape(x, shape)


def permute_dims(x, /, axes):
    return tf.transpose(x, axes)


def transpose(x, /, axes=None):
    return tf.transpose(x, axes)


def concat(arrays, /, *, axis=0):
    if not len(arrays):
        raise ValueError("concat needs at least one array.")
    if axis is None:
        arrays, axis = [tf.reshape(tensor(a), [-1]) for a in arrays], 0
    if all(type(a) in FAST_TYPES for a in arrays):
        try:
            return tf.concat(arrays, axis)
        except REFUSED:
            pass
    return tf.concat(promote(*arrays), axis)


def unstack(x, /, *, axis=0):
    return tuple(tf.unstack(x, axis=axis))


def split(x, /, num_or_size_splits=None, *, axis=0):
    x = tensor(x)
    size = x.shape[axis]
    if num_or_size_splits is None:
        if size is None:
            raise ValueError(
                f"split: the size of axis {axis} is unknown here (inside tf.function); pass "
                f"num_or_size_splits, or give the tf.function an input_signature with that size."
            )
        num_or_size_splits = size
    if isinstance(num_or_size_splits, (int, np.integer)):
        if size is not None and size % num_or_size_splits:
            raise ValueError(
                f"split: axis {axis} of size {size} does not divide into "
                f"{num_or_size_splits} equal pieces; pass a list of piece sizes instead."
            )
        return tf.split(x, num_or_size_splits, axis=axis)
    sizes = [int(s) for s in num_or_size_splits]
    if size is not None and sum(sizes) != size:
        raise ValueError(
            f"split: piece sizes {sizes} add up to {sum(sizes)}, not to the size "
            f"{size} of axis {axis}."
        )
    return tf.split(x, sizes, axis=axis)


def squeeze(x, /, axis=None):
    if axis is None:
        return tf.squeeze(x)
    x = tensor(x)
    shape = x.shape.as_list()
    axes = normalize_axes(axis, len(shape), "squeeze", "tensorflow")
    if not axes:
        return x  # tf.squeeze(x, ()) would remove every size-1 axis
    check_squeezable(shape, axes, axis, "tensorflow")
    return tf.squeeze(x, axes)


def expand_dims(x, /, axis=0):
    x = tensor(x)
    rank = static_rank(x, "expand_dims")
    for position in new_axis_positions(axis, rank, "expand_dims", "tensorflow"):
        x = tf.expand_dims(x, position)
    return x


def flip(x, /, *, axis=None):
    if axis is None:
        x = tensor(x)
        axis = list(range(static_rank(x, "flip")))
    elif isinstance(axis, int):
        axis = [axis]
    return tf.reverse(x, axis)


def tile(x, repetitions, /):
    x = tensor(x)
    reps = [repetitions] if isinstance(repetitions, int) else list(repetitions)
    rank = static_rank(x, "tile")
    if len(reps) < rank:  # numpy: missing leading repetitions are 1
        reps = [1] * (rank - len(reps)) + reps
    for _ in range(len(reps) - rank):  # numpy: more repetitions than axes add leading axes
        x = x[None]
    if x.dtype is tf.uint16:  # no tf kernel: the same bits as int16
        return tf.bitcast(tf.tile(tf.bitcast(x, tf.int16), reps), tf.uint16)
    return tf.tile(x, reps)


def roll(x, /, shift, *, axis=None):
    if axis is None:
        x = tensor(x)
        return tf.reshape(tf.roll(tf.reshape(x, [-1]), shift, 0), tf.shape(x))
    if isinstance(axis, (tuple, list)) and isinstance(shift, int):
        shift = [shift] * len(axis)
    return tf.roll(x, shift, axis)


def swapaxes(x, axis0, axis1, /):
    x = tensor(x)
    rank = static_rank(x, "swapaxes")
    perm = list(range(rank))
    a, b = normalize_axis(axis0, rank), normalize_axis(axis1, rank)
    perm[a], perm[b] = b, a
    return tf.transpose(x, perm)


def broadcast_arrays(*arrays):
    arrays = [tensor(a) for a in arrays]
    if not arrays:
        return []
    shape = arrays[0].shape
    for a in arrays[1:]:
        shape = tf.broadcast_static_shape(shape, a.shape)
    if not shape.is_fully_defined():  # inside tf.function, with sizes known only when run
        shape = tf.shape(arrays[0])
        for a in arrays[1:]:
            shape = tf.broadcast_dynamic_shape(shape, tf.shape(a))
    return [tf.broadcast_to(a, shape) for a in arrays]


def moveaxis(x, source, destination, /):
    x = tensor(x)
    rank = static_rank(x, "moveaxis")
    source = [source] if isinstance(source, int) else list(source)
    destination = [destination] if isinstance(destination, int) else list(destination)
    if len(source) != len(destination):
        raise ValueError(
            f"moveaxis: {len(source)} source axes but {len(destination)} destination axes; "
            f"give as many of each."
        )
    source = [normalize_axis(a, rank) for a in source]
    destination = [normalize_axis(a, rank) for a in destination]
    if len(set(source)) != len(source) or len(set(destination)) != len(destination):
        raise ValueError("moveaxis: repeated axes in source or destination.")
    order = [a for a in range(rank) if a not in source]
    for dest, src in sorted(zip(destination, source)):
        order.insert(dest, src)
    return tf.transpose(x, order)
