"""tensorflow backend: the one pool, channel-last, with ``tf.nn`` kernels.

'SAME' average pools exclude the padding from the count (tf's own rule), so padding that equals
tf's 'SAME' (or none) runs in tf's kernels as it is. Other padding is added with ``tf.pad``
(``-inf`` for max pools; zeros for average pools, whose sums are then divided by the number of
real entries in each window). tf has no float64 3-D pool on the CPU; a 3-D pool of float64 runs
as a 2-D pool over (H, W) followed by a 1-D pool over D (max and average over a box are
separable, the count of real entries too).
"""

from __future__ import annotations

import math

import tensorflow as tf

from ivy._args import nn as A
from ivy.backends.tensorflow.convolutions import native_padding


def _native(x, k, s, padding, average):
    op = tf.nn.avg_pool if average else tf.nn.max_pool
    if len(k) == 3 and x.dtype == tf.float64:
        shape = tf.shape(x)
        n, d, c = shape[0], shape[1], shape[4]
        y = op(tf.reshape(x, tf.concat([[-1], shape[2:]], 0)), k[1:], s[1:], padding)
        inner = tf.shape(y)[1:3]
        y = tf.reshape(y, tf.stack([n, d, inner[0] * inner[1], c]))
        y = op(y, (k[0], 1), (s[0], 1), padding)
        return tf.reshape(y, tf.concat([tf.shape(y)[:2], inner, [c]], 0))
    return op(x, k, s, padding)


def _through_int64(x, kernel, strides, padding):
    """The max pool of a uint32, uint64 or bool ``x`` through int64, in the same order: uint64
    with its top bit flipped, read as int64, orders as uint64 does."""
    if x.dtype is tf.uint64:
        flip = tf.constant(-(2**63), tf.int64)
        y = pool_general(tf.bitcast(x, tf.int64) ^ flip, kernel, strides, padding)
        return tf.bitcast(y ^ flip, tf.uint64)
    return tf.cast(pool_general(tf.cast(x, tf.int64), kernel, strides, padding), x.dtype)


def pool_general(x, kernel, strides, padding, /, *, reduction="max"):
    x = tf.convert_to_tensor(x)
    average = A.averages(reduction)
    if not average and x.dtype in (tf.uint32, tf.uint64, tf.bool):  # no max pool kernels
        return _through_int64(x, kernel, strides, padding)
    fill = 0 if average else (x.dtype.min if x.dtype.is_integer else float("-inf"))
    padded, tf_padding = native_padding(x, padding, kernel, strides, fill)
    y = _native(padded, kernel, strides, tf_padding, average)
    if average and padded is not x:  # tf counted the padding: divide by the real entries
        counts = A.window_counts(tuple(x.shape[1:-1]), kernel, strides, padding)
        y = y / tf.constant(counts[None, ..., None] / math.prod(kernel), x.dtype)
    return y
