"""tensorflow backend: padding (``tf.pad``, with the fill value cast to the array's dtype)."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends._pad_args import pad_pairs
from ivy.backends.tensorflow._helpers import static_rank, tensor


def constant_pad(x, /, pad_width, *, value=0):
    x = tensor(x)
    pairs = pad_pairs(pad_width, static_rank(x, "constant_pad"))
    if not pairs:  # 0-d: nothing to pad
        return x
    return tf.pad(x, pairs, constant_values=tf.cast(value, x.dtype))
