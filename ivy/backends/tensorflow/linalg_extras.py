"""tensorflow backend: linear algebra beyond the Array API extension (``einsum`` promotes mixed
dtypes, which tf.einsum refuses)."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends.tensorflow._helpers import promote


def einsum(equation, /, *operands):
    return tf.einsum(equation, *promote(*operands))
