"""tensorflow backend: sorting.

tf sorts NaNs anywhere and refuses bools, so floats are sorted by an integer key of their bits
that orders them as numbers, -0.0 equal to 0.0 and NaN the largest value (last ascending, first
descending, as on every backend). A stable descending sort keeps equal elements in their order:
it sorts the reversed array and reverses the result.
"""

from __future__ import annotations

import tensorflow as tf

from ivy.backends._sample_args import top_k_axis
from ivy.backends.tensorflow._helpers import normalize_axis, static_rank, tensor
from ivy.core._results import TopKResult

_BITS = {tf.float16: tf.int16, tf.bfloat16: tf.int16, tf.float32: tf.int32, tf.float64: tf.int64}


def _key(x):
    """An integer or float tensor that tf sorts in the order of ``x``'s values."""
    bits = _BITS.get(x.dtype)
    if bits is None:
        return tf.cast(x, tf.int8) if x.dtype is tf.bool else x
    nan = tf.constant(float("nan"), x.dtype)
    x = tf.where(tf.math.is_nan(x), nan, x + tf.zeros((), x.dtype))  # one NaN; -0.0 + 0.0 = 0.0
    b = tf.bitcast(x, bits)
    # Negative floats: larger bits mean smaller numbers. Flipping all bits but the sign fixes that.
    magnitude = tf.constant(bits.max, bits)
    return tf.where(b < 0, tf.bitwise.bitwise_xor(b, magnitude), b)


def _ascending(x, axis, stable):
    return tf.argsort(_key(x), axis=axis, stable=stable)


def argsort(x, /, *, axis=-1, descending=False, stable=True):
    x = tensor(x)
    axis = normalize_axis(axis, static_rank(x, "argsort"))
    if not descending:
        return tf.cast(_ascending(x, axis, stable), tf.int64)
    flipped = tf.reverse(_ascending(tf.reverse(x, [axis]), axis, stable), [axis])
    return tf.cast(tf.shape(x)[axis] - 1 - flipped, tf.int64)


def sort(x, /, *, axis=-1, descending=False, stable=True):
    x = tensor(x)
    rank = static_rank(x, "sort")
    axis = normalize_axis(axis, rank)
    order = argsort(x, axis=axis, descending=descending, stable=stable)
    if axis == rank - 1:
        return tf.gather(x, order, batch_dims=axis)
    perm = [a for a in range(rank) if a != axis] + [axis]  # the sorted axis last
    back = [perm.index(a) for a in range(rank)]
    taken = tf.gather(tf.transpose(x, perm), tf.transpose(order, perm), batch_dims=rank - 1)
    return tf.transpose(taken, back)


def top_k(x, k, /, *, axis=-1, largest=True, sorted=True):
    """``tf.math.top_k`` (last axis; equal elements in index order) of the integer key that
    ``argsort`` sorts by; the values are gathered from ``x``, so that gradients flow to them."""
    x = tensor(x)
    rank = static_rank(x, "top_k")
    axis = top_k_axis(x.shape.as_list(), k, axis)
    if axis != rank - 1:
        perm = [a for a in range(rank) if a != axis] + [axis]
        back = [perm.index(a) for a in range(rank)]
        values, indices = top_k(tf.transpose(x, perm), k, axis=-1, largest=largest)
        return TopKResult(tf.transpose(values, back), tf.transpose(indices, back))
    key = _key(x)
    if not largest:
        key = tf.bitwise.invert(key)  # reverses the order of integers, without overflow
    indices = tf.math.top_k(key, k, sorted=True).indices
    values = tf.gather(x, indices, batch_dims=rank - 1)
    return TopKResult(values, tf.cast(indices, tf.int64))
