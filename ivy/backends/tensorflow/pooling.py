"""tensorflow backend: max and average pools, channel-last, with ``tf.nn`` kernels.

'SAME' average pools exclude the padding from the count (tf's own rule). Explicit padding is
added with ``tf.pad`` (``-inf`` for max pools; zeros for average pools, whose sums are then divided
by the number of real entries in each window). tf has no float64 3-D pool on the CPU; a 3-D pool
of float64 runs as a 2-D pool over (H, W) followed by a 1-D pool over D (max and average over a
box are separable, the count of real entries too).
"""

from __future__ import annotations

import math

import tensorflow as tf

from ivy.backends import _nn_args as A
from ivy.backends.tensorflow.convolutions import flatten_batch, pad_spatial


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


def _pool(x, kernel, strides, padding, nd, fn, average):
    x = tf.convert_to_tensor(x)
    A.check_pool_input(tuple(x.shape), nd, fn)
    k = A.as_tuple(kernel, nd, "kernel", fn)
    s = A.as_tuple(strides, nd, "strides", fn)
    x, unflatten = flatten_batch(x, nd)
    sizes = tuple(x.shape[1:-1])
    parsed = A.parse_padding(padding, nd, fn)
    if None in sizes and isinstance(parsed, str):
        return unflatten(_native(x, k, s, parsed, average))
    pads = A.pool_pads(padding, sizes, k, s, fn)
    if isinstance(parsed, str):
        y = _native(x, k, s, parsed, average)
    elif average:
        counts = A.window_counts(sizes, k, s, pads)[None, ..., None] / math.prod(k)
        mean = _native(pad_spatial(x, pads), k, s, "VALID", True)  # padding counted
        y = mean / tf.constant(counts, x.dtype)
    else:
        y = _native(pad_spatial(x, pads, float("-inf")), k, s, "VALID", False)
    return unflatten(y)


def max_pool1d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 1, "max_pool1d", False)


def max_pool2d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 2, "max_pool2d", False)


def max_pool3d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 3, "max_pool3d", False)


def avg_pool1d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 1, "avg_pool1d", True)


def avg_pool2d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 2, "avg_pool2d", True)


def avg_pool3d(x, kernel, strides, padding, /):
    return _pool(x, kernel, strides, padding, 3, "avg_pool3d", True)
