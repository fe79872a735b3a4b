"""tensorflow backend: linear algebra."""

from __future__ import annotations

import math

import numpy as np
import tensorflow as tf

from ivy.backends.tensorflow._helpers import FAST_TYPES, REFUSED, floating, promote

__all__ = ["matmul", "cross", "svd", "inv", "pinv", "vector_norm"]

inv = tf.linalg.inv


def matmul(x1, x2, /):
    """``tf.linalg.matmul``, plus 1-D operands and dtype promotion as in numpy."""
    if type(x1) in FAST_TYPES and type(x2) in FAST_TYPES:
        try:
            return tf.linalg.matmul(x1, x2)
        except REFUSED:
            pass
    x1, x2 = promote(x1, x2)
    vec1, vec2 = x1.shape.rank == 1, x2.shape.rank == 1
    out = tf.linalg.matmul(x1[None] if vec1 else x1, x2[:, None] if vec2 else x2)
    if vec2:
        out = out[..., 0]  # drop the column of the vector made a matrix
    if vec1:
        out = out[..., 0] if vec2 else out[..., 0, :]
    return out


def cross(x1, x2, /, *, axis=-1):
    x1, x2 = promote(x1, x2)
    a0, a1, a2 = tf.unstack(x1, 3, axis=axis)
    b0, b1, b2 = tf.unstack(x2, 3, axis=axis)
    return tf.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=axis)


def svd(x, /, *, full_matrices=True):
    s, u, v = tf.linalg.svd(x, full_matrices=full_matrices)
    return u, s, tf.linalg.adjoint(v)


def pinv(x, /, *, rtol=None):
    x = floating(x)
    if rtol is None:  # numpy 2's default
        rows, cols = x.shape[-2:]
        if rows is None or cols is None:
            size = tf.cast(tf.reduce_max(tf.shape(x)[-2:]), x.dtype.real_dtype)
        else:
            size = max(rows, cols)
        rtol = size * np.finfo(x.dtype.real_dtype.as_numpy_dtype).eps
    return tf.linalg.pinv(x, rcond=rtol)


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    x = tf.math.abs(floating(x))
    if ord == 2:
        return tf.math.sqrt(tf.math.reduce_sum(tf.math.square(x), axis=axis, keepdims=keepdims))
    if ord == 1:
        return tf.math.reduce_sum(x, axis=axis, keepdims=keepdims)
    if ord == math.inf:
        return tf.math.reduce_max(x, axis=axis, keepdims=keepdims)
    if ord == -math.inf:
        return tf.math.reduce_min(x, axis=axis, keepdims=keepdims)
    if ord == 0:
        return tf.math.reduce_sum(tf.cast(x != 0, x.dtype), axis=axis, keepdims=keepdims)
    return tf.math.reduce_sum(x**ord, axis=axis, keepdims=keepdims) ** (1.0 / ord)
