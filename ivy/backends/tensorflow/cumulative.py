"""tensorflow backend: cumulative sums and products (``tf.math.cumsum``/``cumprod``, which have
``exclusive`` and ``reverse``). Bool and small integers accumulate in int64 (unsigned: uint64),
which tf would not widen."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends.tensorflow._helpers import native_dtype, tensor


def _accumulated(x, dtype):
    x = tensor(x)
    dt = native_dtype(dtype)
    if dt is None:
        dt = x.dtype
        if dt == tf.bool or (dt.is_integer and dt.size < 8):
            dt = tf.uint64 if dt.is_unsigned else tf.int64
    return x if dt == x.dtype else tf.cast(x, dt)


def cumsum(x, /, axis=0, *, exclusive=False, reverse=False, dtype=None):
    return tf.math.cumsum(_accumulated(x, dtype), axis, exclusive=exclusive, reverse=reverse)


def cumprod(x, /, axis=0, *, exclusive=False, reverse=False, dtype=None):
    return cumprod_native(_accumulated(x, dtype), axis, exclusive=exclusive, reverse=reverse)


def cumprod_native(x, axis=0, exclusive=False, reverse=False):
    """``tf.math.cumprod`` with a gradient that is right where ``x`` has zeros (tf's divides the
    reverse cumulative sum of ``g * y`` by ``x``: at a zero it gives 0 or NaN, where
    d/dx1 sum(cumprod([2, x1, 3])) at x1 = 0 is 8). Real floating ``x``; other dtypes (and
    complex numbers) are tf's own."""
    if not x.dtype.is_floating:
        return tf.math.cumprod(x, axis, exclusive=exclusive, reverse=reverse)
    axis = axis % x.shape.rank if x.shape.rank is not None and axis < 0 else axis
    if reverse:
        flipped = cumprod_native(tf.reverse(x, [axis]), axis, exclusive)
        return tf.reverse(flipped, [axis])
    if exclusive:  # 1, then the products of all before
        y = _inclusive_cumprod(x, axis)
        ones = tf.ones_like(tf.gather(x, [0], axis=axis))
        return tf.concat([ones, tf.gather(y, tf.range(tf.shape(x)[axis] - 1), axis=axis)], axis)
    return _inclusive_cumprod(x, axis)


def _inclusive_cumprod(x, axis):
    @tf.custom_gradient
    def cumprod(x):
        y = tf.math.cumprod(x, axis)

        def grad(g):
            # d/dx_i = sum_{j >= i} g_j * prod_{l <= j, l != i} x_l. Before the first zero of a
            # line that is the reverse cumulative sum of g * y over x_i; at the first zero, the
            # same sum with that zero taken as 1 in the products; after it, 0.
            zero = tf.math.equal(x, 0)
            count = tf.math.cumsum(tf.cast(zero, tf.int32), axis)
            before = tf.math.equal(count, 0)
            first = zero & tf.math.equal(count, 1)
            ones = tf.ones_like(x)
            at_before = tf.math.cumsum(g * y, axis, reverse=True) / tf.where(before, x, ones)
            skipping_first = tf.math.cumprod(tf.where(first, ones, x), axis)
            at_first = tf.math.cumsum(g * skipping_first, axis, reverse=True)
            return tf.where(before, at_before, tf.where(first, at_first, tf.zeros_like(x)))

        return y, grad

    return cumprod(x)
