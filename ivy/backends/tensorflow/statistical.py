"""tensorflow backend: reductions. Integer sums and products accumulate in 64 bits."""

from __future__ import annotations

import math

import tensorflow as tf

from ivy._args.axes import cumulative_axis
from ivy.backends import _signed_zeros
from ivy.backends.tensorflow._helpers import (
    floating,
    native_dtype,
    normalize_axis,
    static_rank,
    tensor,
)
from ivy.backends.tensorflow.cumulative import cumprod_native
from ivy.errors import InvalidValueError


def _extremum(native, name: str):
    """tf's reduce_min or reduce_max: bools as uint8 (no tf kernel), and an empty reduction
    raises (tf would give the dtype's extreme, where the others have no identity)."""

    def fn(x, /, *, axis=None, keepdims=False):
        x = tensor(x)
        shape = x.shape
        if shape.rank is not None and shape.num_elements() == 0:
            axes = (
                range(shape.rank) if axis is None else ((axis,) if isinstance(axis, int) else axis)
            )
            if any(shape[a] == 0 for a in axes):
                raise InvalidValueError(
                    f"zero-size reduction of an array of shape {tuple(shape)}: {name} has no "
                    f"identity, so an empty reduction has no value.",
                    function=name,
                    argument="x",
                    backend="tensorflow",
                )
        if x.dtype is tf.bool:
            return tf.cast(native(tf.cast(x, tf.uint8), axis=axis, keepdims=keepdims), tf.bool)
        out = native(x, axis=axis, keepdims=keepdims)
        if not x.dtype.is_floating:
            return out
        if tf.executing_eagerly() and not (out.numpy() == 0).any():
            return out  # (eager: a test on the host is cheaper than the fix)
        # IEEE's sign of a zero result (``ivy/backends/_signed_zeros.py``): 1 / -0 is -inf
        lower = name == "min"
        signed = tf.math.reciprocal(x) < 0 if lower else tf.math.reciprocal(x) > 0
        found = tf.reduce_any(tf.logical_and(x == 0, signed), axis=axis, keepdims=keepdims)
        negative = found if lower else tf.logical_not(found)
        return _signed_zeros.reduced_zero(tf.where, tf.stop_gradient, out, negative)

    fn.__name__ = fn.__qualname__ = name
    return fn


min = _extremum(tf.math.reduce_min, "min")
max = _extremum(tf.math.reduce_max, "max")


def _accumulator(x, dtype):
    """``x`` cast to ``dtype``, or bool and small integers widened to int64 (uint64)."""
    x = tensor(x)
    if dtype is not None:
        return tf.cast(x, native_dtype(dtype))
    dt = x.dtype  # (dtypes are interned: `is` is much faster than ==)
    if dt is tf.float32 or dt is tf.float64 or not (dt is tf.bool or dt.is_integer):
        return x
    if dt.size == 8:
        return x
    return tf.cast(x, tf.uint64 if dt.is_unsigned else tf.int64)


def sum(x, /, *, axis=None, dtype=None, keepdims=False):
    return tf.math.reduce_sum(_accumulator(x, dtype), axis=axis, keepdims=keepdims)


def prod(x, /, *, axis=None, dtype=None, keepdims=False):
    return tf.math.reduce_prod(_accumulator(x, dtype), axis=axis, keepdims=keepdims)


def mean(x, /, *, axis=None, keepdims=False):
    """Integers are averaged as float32 (tf would truncate the mean to an integer)."""
    return tf.math.reduce_mean(floating(x), axis=axis, keepdims=keepdims)


def var(x, /, *, axis=None, correction=0.0, keepdims=False):
    x = floating(x)
    out = tf.math.reduce_variance(x, axis=axis, keepdims=keepdims)
    if not correction:
        return out
    n = x.shape.num_elements(), out.shape.num_elements()
    if None in n:  # shapes unknown inside tf.function
        n = tf.size(x), tf.size(out)
    count = tf.cast(n[0], out.dtype) / tf.cast(n[1], out.dtype)  # elements per result
    out = out * count / (count - correction)
    # NaN where N - correction <= 0, as the standard says (the formula gives inf or below 0)
    return tf.where(count - correction > 0, out, tf.constant(math.nan, out.dtype))


def std(x, /, *, axis=None, correction=0.0, keepdims=False):
    return tf.math.sqrt(var(x, axis=axis, correction=correction, keepdims=keepdims))


def _cumulative(native, initial, x, axis, dtype, include_initial, name):
    """``native`` (cumsum, cumprod) along ``axis``, accumulating as :func:`sum` does."""
    x = _accumulator(x, dtype)
    rank = static_rank(x, name)
    axis = normalize_axis(cumulative_axis(axis, rank, name), rank)
    out = native(x, axis=axis)
    if include_initial:
        shape = tf.tensor_scatter_nd_update(tf.shape(out), [[axis]], [1])
        out = tf.concat([tf.fill(shape, tf.constant(initial, out.dtype)), out], axis)
    return out


def cumulative_sum(x, /, *, axis=None, dtype=None, include_initial=False):
    return _cumulative(tf.math.cumsum, 0, x, axis, dtype, include_initial, "cumulative_sum")


def cumulative_prod(x, /, *, axis=None, dtype=None, include_initial=False):
    return _cumulative(cumprod_native, 1, x, axis, dtype, include_initial, "cumulative_prod")


def logsumexp(x, /, *, axis=None, keepdims=False):
    return tf.math.reduce_logsumexp(floating(x), axis=axis, keepdims=keepdims)
