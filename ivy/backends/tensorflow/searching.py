"""tensorflow backend: searching."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends.tensorflow._helpers import FAST_TYPES, REFUSED, fast, promote, static_rank, tensor
from ivy.errors import InvalidValueError


def _arg_reduce(native, x, axis, keepdims, name):
    x = tensor(x)
    shape = x.shape
    if shape.rank is not None and shape.num_elements() == 0 and (axis is None or shape[axis] == 0):
        raise InvalidValueError(
            f"{name} of an empty array (shape {tuple(shape)}) has no answer.",
            function=name,
            argument="x",
            backend="tensorflow",
        )
    if x.dtype.is_floating:
        # NaN wins, as on every backend (tf's argmax skips NaN): where a NaN is, argmax of the
        # NaN mask (its first NaN) is the answer
        nan = tf.math.is_nan(x)
        found = _arg_plain(tf.math.argmax, tf.cast(nan, tf.uint8), axis, keepdims, name)
        plain = _arg_plain(native, tf.where(nan, tf.zeros((), x.dtype), x), axis, keepdims, name)
        any_nan = tf.reduce_any(nan, axis=axis, keepdims=keepdims)
        if axis is None and keepdims:
            any_nan = tf.reshape(any_nan, tf.shape(found))
        return tf.where(any_nan, found, plain)
    if x.dtype is tf.bool:
        x = tf.cast(x, tf.uint8)
    return _arg_plain(native, x, axis, keepdims, name)


def _arg_plain(native, x, axis, keepdims, name):
    if axis is None:
        out = native(tf.reshape(x, [-1]), axis=0)
        return tf.reshape(out, [1] * static_rank(x, name)) if keepdims else out
    out = native(x, axis=axis)
    return tf.expand_dims(out, axis) if keepdims else out


def argmax(x, /, *, axis=None, keepdims=False):
    return _arg_reduce(tf.math.argmax, x, axis, keepdims, "argmax")


def argmin(x, /, *, axis=None, keepdims=False):
    return _arg_reduce(tf.math.argmin, x, axis, keepdims, "argmin")


def where(condition, x1, x2, /):
    if (
        type(condition) in FAST_TYPES
        and fast(x1)
        and fast(x2)
        and not (type(x1) is type(x2) is int)
    ):
        try:
            return tf.where(condition, x1, x2)
        except REFUSED:
            pass
    condition = tensor(condition)
    if condition.dtype is not tf.bool:
        condition = tf.cast(condition, tf.bool)
    return tf.where(condition, *promote(x1, x2))


def count_nonzero(x, /, *, axis=None, keepdims=False):
    return tf.math.count_nonzero(x, axis=axis, keepdims=keepdims, dtype=tf.int64)


def nonzero(x, /):
    x = tensor(x)
    rank = static_rank(x, "nonzero")
    if rank == 0:
        raise ValueError("nonzero needs an array of one or more dimensions, got a 0-d array.")
    found = tf.where(x if x.dtype is tf.bool else tf.not_equal(x, tf.zeros((), x.dtype)))
    return tuple(found[:, i] for i in range(rank))


def searchsorted(x1, x2, /, *, side="left", sorter=None):
    x1, x2 = promote(x1, x2)
    if sorter is not None:
        x1 = tf.gather(x1, sorter)
    nans = None
    if x1.dtype.is_floating:  # NaN sorts after every number (see ivy.searchsorted)
        nans = tf.math.is_nan(x1)
        x1 = tf.where(nans, tf.constant(float("inf"), x1.dtype), x1)
    out = tf.searchsorted(x1[None], tf.reshape(x2, [1, -1]), side=side, out_type=tf.int64)
    out = tf.reshape(out, tf.shape(x2))
    if nans is not None:
        n = tf.size(x1, out_type=tf.int64)
        numbers = n - tf.math.count_nonzero(nans, dtype=tf.int64)  # the NaNs: x1[numbers:]
        out = tf.minimum(out, numbers)
        out = tf.where(tf.math.is_nan(x2), numbers if side == "left" else n, out)
    return out
