"""tensorflow backend: utilities (truth tests, differences, conversion to numpy and lists, shape,
dtype, device)."""

from __future__ import annotations

import numpy as np
import tensorflow as tf

from ivy.backends.tensorflow._helpers import (
    ivy_device,
    normalize_axis,
    promote,
    static_rank,
    tensor,
)


def _truth(x):
    x = tensor(x)
    return x if x.dtype is tf.bool else tf.not_equal(x, tf.zeros((), x.dtype))  # NaN is true


def all(x, /, *, axis=None, keepdims=False):  # noqa: A001 - the Array API name
    return tf.math.reduce_all(_truth(x), axis=axis, keepdims=keepdims)


def any(x, /, *, axis=None, keepdims=False):  # noqa: A001
    return tf.math.reduce_any(_truth(x), axis=axis, keepdims=keepdims)


def diff(x, /, *, axis=-1, n=1, prepend=None, append=None):
    x = tensor(x)
    rank = static_rank(x, "diff")
    axis = normalize_axis(axis, rank)
    if prepend is not None or append is not None:
        parts = promote(*(v for v in (prepend, x, append) if v is not None))
        shape = tf.tensor_scatter_nd_update(tf.shape(x), [[axis]], [1])
        parts = [tf.broadcast_to(p, shape) if p.shape.rank == 0 else p for p in parts]
        x = tf.concat(parts, axis)
    head = tuple(slice(None) for _ in range(axis))
    for _ in range(n):
        a, b = x[head + (slice(1, None),)], x[head + (slice(None, -1),)]
        x = tf.not_equal(a, b) if x.dtype is tf.bool else a - b
    return x


def to_numpy(x, /):
    try:
        return np.asarray(x.numpy() if hasattr(x, "numpy") else x)  # (0-d: an array too)
    except NotImplementedError as err:  # a graph tensor has no value yet
        raise TypeError(
            "to_numpy needs a value, but inside tf.function tensors are symbolic. Call it "
            "outside the compiled function, or wrap the numpy code in tf.numpy_function."
        ) from err


def to_list(x, /):
    return np.asarray(to_numpy(x)).tolist()


def shape(x, /):
    """The static shape; inside tf.function an unknown size is None (use tf.shape for it)."""
    return tuple(x.shape)


def dtype(x, /, *, as_str=False):
    return x.dtype.name if as_str else x.dtype


def dev(x, /):
    return ivy_device(x.device)
