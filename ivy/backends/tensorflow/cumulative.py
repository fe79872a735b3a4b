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
    return tf.math.cumprod(_accumulated(x, dtype), axis, exclusive=exclusive, reverse=reverse)
