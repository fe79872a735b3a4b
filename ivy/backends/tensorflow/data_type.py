"""tensorflow backend: dtype conversion."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends.tensorflow._helpers import native_dtype

__all__ = ["astype"]


def astype(x, dtype, /, *, copy=True):
    """tf tensors are immutable, so ``copy`` changes nothing."""
    return tf.cast(x, native_dtype(dtype))
