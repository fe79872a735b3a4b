"""tensorflow backend: gathering and scattering."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends._index_checks import check_bounds, check_bounds_per_column, check_rows
from ivy.backends.tensorflow._helpers import native_dtype, tensor


def gather_nd(params, indices, /):
    """tf's, with negative indices counted from the end (tf refuses them) and, in eager calls,
    indices out of range raising IndexOutOfBoundsError."""
    params, indices = tensor(params), tf.convert_to_tensor(indices)
    if tf.executing_eagerly():
        check_bounds_per_column(
            indices.numpy(), params.shape, function="gather_nd", backend="tensorflow"
        )
    depth = indices.shape[-1]
    lead = tf.shape(params, out_type=indices.dtype)[:depth]
    return tf.gather_nd(params, tf.where(indices < 0, indices + lead, indices))


_SCATTERS = {
    "replace": tf.tensor_scatter_nd_update,
    "min": tf.tensor_scatter_nd_min,
    "max": tf.tensor_scatter_nd_max,
}


def take(x, indices, /, *, axis=None):
    x = tensor(x)
    if axis is None:
        x, axis = tf.reshape(x, [-1]), 0
    indices = tf.convert_to_tensor(indices)
    size = tf.shape(x, out_type=indices.dtype)[axis]
    return tf.gather(x, tf.where(indices < 0, indices + size, indices), axis=axis)


def scatter_nd(indices, updates, /, shape, *, reduction="sum"):
    updates = tensor(updates)
    shape = (shape,) if isinstance(shape, int) else shape
    if reduction == "sum":
        return tf.scatter_nd(indices, updates, shape)
    if reduction not in _SCATTERS:
        raise ValueError(
            f"scatter_nd: unknown reduction {reduction!r}; use 'sum', 'replace', 'min' or 'max'."
        )
    zeros = tf.zeros(shape, updates.dtype)
    if reduction == "replace":
        return tf.tensor_scatter_nd_update(zeros, indices, updates)
    # Reduce into the dtype's extreme, then put 0 back where no update landed.
    dt = updates.dtype
    if dt.is_floating:
        extreme = float("inf") if reduction == "min" else float("-inf")
    else:
        extreme = dt.max if reduction == "min" else dt.min
    out = _SCATTERS[reduction](tf.fill(tf.shape(zeros), tf.constant(extreme, dt)), indices, updates)
    touched = tf.scatter_nd(indices, tf.ones_like(updates, tf.int32), shape)
    return tf.where(touched > 0, out, zeros)


def one_hot(indices, depth, /, *, dtype=None):
    dt = native_dtype(dtype) or tf.float32
    indices = tensor(indices)
    if tf.executing_eagerly():  # (inside tf.function indices have no values yet)
        check_bounds(
            indices.numpy(), depth, function="one_hot", backend="tensorflow", negative=False
        )
    if dt is tf.bool:  # tf's default on and off values are the numbers 1 and 0
        return tf.one_hot(indices, depth, on_value=True, off_value=False, dtype=dt)
    return tf.one_hot(indices, depth, dtype=dt)


def gather_flat(params, indices, /):
    return take(params, indices)  # take with axis=None: the flattened params, any index shape


def scatter_flat(indices, updates, /, size, *, reduction="sum"):
    indices = tf.convert_to_tensor(indices)[..., None]
    return scatter_nd(indices, updates, (size,), reduction=reduction)


def indices_where(x, /):
    x = tensor(x)
    if x.shape.rank == 0:  # tf.where refuses 0-d input: one row of no coordinates, or none
        return tf.where(tf.reshape(x, [1]))[:, :0]
    return tf.where(x)


def take_along_axis(x, indices, /, *, axis=-1):
    return tf.experimental.numpy.take_along_axis(tensor(x), tf.convert_to_tensor(indices), axis)


def put_rows(x, indices, updates, /):
    """``tf.tensor_scatter_nd_update`` of the rows (differentiable in ``x`` and ``updates``),
    with negative indices counted from the end (tf refuses them)."""
    x, indices = tensor(x), tf.convert_to_tensor(indices)
    updates = tensor(updates)
    check_rows(
        *(None if t.shape.rank is None else t.shape.as_list() for t in (x, indices, updates)),
        integer=indices.dtype.is_integer,
        backend="tensorflow",
    )
    if tf.executing_eagerly():
        check_bounds(indices.numpy(), x.shape[0], function="put_rows", backend="tensorflow")
    if indices.dtype not in (tf.int32, tf.int64):
        indices = tf.cast(indices, tf.int64)
    size = tf.shape(x, out_type=indices.dtype)[0]
    indices = tf.where(indices < 0, indices + size, indices)
    if updates.dtype != x.dtype:
        updates = tf.cast(updates, x.dtype)
    return tf.tensor_scatter_nd_update(x, indices[:, None], updates)
