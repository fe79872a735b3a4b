"""tensorflow backend: unique values, sorted, as the Array API's named tuples.

``tf.unique`` keeps the order of first occurrence and tells -0.0 from 0.0 by their bits, so the
values are sorted here (by the sorting module's key: -0.0 equal to 0.0, NaNs last) and grouped by
``!=``, which makes each NaN a distinct value. Works inside ``tf.function`` (results of unknown
size)."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends.tensorflow._helpers import promote, tensor
from ivy.backends.tensorflow.sorting import argsort
from ivy.core._results import UniqueAllResult, UniqueCountsResult, UniqueInverseResult


def _groups(x):
    """``(flat, order, ordered, starts, group)``: the flattened ``x``, its stable sorting order,
    the sorted elements, whether each starts a new unique value, and the number of its unique
    value."""
    flat = tf.reshape(x, [-1])
    order = argsort(flat)
    ordered = tf.gather(flat, order)
    starts = tf.concat([tf.ones([1], tf.bool)[: tf.size(flat)], ordered[1:] != ordered[:-1]], 0)
    group = tf.cumsum(tf.cast(starts, tf.int64)) - 1
    return flat, order, ordered, starts, group


def unique_values(x, /):
    _, _, ordered, starts, _ = _groups(tensor(x))
    return tf.boolean_mask(ordered, starts)


def unique_counts(x, /):
    flat, _, ordered, starts, group = _groups(tensor(x))
    n = tf.reduce_sum(tf.cast(starts, tf.int64))
    counts = tf.math.unsorted_segment_sum(tf.ones_like(group), group, n)
    return UniqueCountsResult(tf.boolean_mask(ordered, starts), counts)


def unique_inverse(x, /):
    x = tensor(x)
    _, order, ordered, starts, group = _groups(x)
    inverse = tf.scatter_nd(order[:, None], group, tf.shape(order, out_type=tf.int64))
    return UniqueInverseResult(tf.boolean_mask(ordered, starts), tf.reshape(inverse, tf.shape(x)))


def unique_all(x, /):
    x = tensor(x)
    _, order, ordered, starts, group = _groups(x)
    n = tf.reduce_sum(tf.cast(starts, tf.int64))
    inverse = tf.scatter_nd(order[:, None], group, tf.shape(order, out_type=tf.int64))
    counts = tf.math.unsorted_segment_sum(tf.ones_like(group), group, n)
    first = tf.math.unsorted_segment_min(order, group, n)  # the stable sort puts it first anyway
    return UniqueAllResult(
        tf.boolean_mask(ordered, starts), first, tf.reshape(inverse, tf.shape(x)), counts
    )


def isin(x1, x2, /, *, invert=False):
    x1, x2 = promote(x1, x2)
    found = tf.reduce_any(tf.equal(x1[..., None], tf.reshape(x2, [-1])), axis=-1)
    return tf.logical_not(found) if invert else found
