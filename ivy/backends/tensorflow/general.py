"""tensorflow backend: utilities."""

from __future__ import annotations

import numpy as np

from ivy.backends.tensorflow._helpers import ivy_device

__all__ = ["to_numpy", "to_list", "shape", "dtype", "dev"]


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
