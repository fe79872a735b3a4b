"""tensorflow backend: searching."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends.tensorflow._helpers import FAST_TYPES, REFUSED, fast, promote, static_rank, tensor

__all__ = ["argmax", "argmin", "where"]


def _arg_reduce(native, x, axis, keepdims, name):
    x = tensor(x)
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
