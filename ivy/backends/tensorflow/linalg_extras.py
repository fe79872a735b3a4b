"""tensorflow backend: linear algebra beyond the Array API extension (``einsum`` promotes mixed
dtypes, which tf.einsum refuses)."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends.tensorflow._helpers import promote


def einsum(equation, /, *operands):
    operands = promote(*operands)
    dtype = operands[0].dtype if operands else None
    if dtype is tf.bool:  # no kernel: numpy's product of booleans is any of the ands
        return tf.einsum(equation, *(tf.cast(o, tf.float32) for o in operands)) > 0
    if dtype in _NO_KERNEL:  # small and unsigned integers: through int64, which wraps alike
        out = tf.einsum(equation, *(_int64(o) for o in operands))
        return tf.bitcast(out, tf.uint64) if dtype is tf.uint64 else tf.cast(out, dtype)
    return tf.einsum(equation, *operands)


# tf.einsum's integer kernels are int32 and int64 only (on the CPU).
_NO_KERNEL = frozenset({tf.int8, tf.int16, tf.uint8, tf.uint16, tf.uint32, tf.uint64})


def _int64(x):
    """``x`` as int64: uint64 bit for bit (its wrap-around modulo 2**64 is the same)."""
    return tf.bitcast(x, tf.int64) if x.dtype is tf.uint64 else tf.cast(x, tf.int64)
