"""tensorflow backend: the activations with a kernel of their own (the rest are compositions).

``gelu`` is written out with ``tf.math.erfc`` / ``tf.math.tanh``: ``tf.nn.gelu`` is only accurate
to about 1e-8 in float64 on the CPU.
"""

from __future__ import annotations

import math

import tensorflow as tf

from ivy.backends.tensorflow._helpers import as_inexact

_SQRT_HALF = math.sqrt(0.5)
_SQRT_2_OVER_PI = math.sqrt(2 / math.pi)


_ZEROS: dict = {}  # dtype -> a 0-d zero, made once


def relu(x, /):
    """``max(0, x)``, with ``relu(-0) = +0`` as on every backend (``tf.nn.relu`` keeps ``-0``;
    ``ivy/backends/_signed_zeros.py``): tf's maximum returns its first operand at a tie, and
    its gradient at 0 is relu's, 0."""
    if not isinstance(x, tf.Tensor):
        x = tf.convert_to_tensor(x)
    zero = _ZEROS.get(x.dtype)
    if zero is None:
        with tf.init_scope():  # (a constant of the program, also when first made in a trace)
            zero = _ZEROS[x.dtype] = tf.zeros((), x.dtype)
    return tf.math.maximum(zero, x)


def sigmoid(x, /):
    return tf.math.sigmoid(as_inexact(x))


def gelu(x, /, approximate=False):
    x = as_inexact(x)
    if approximate:
        inner = _SQRT_2_OVER_PI * (x + 0.044715 * x * x * x)
        return 0.5 * x * (1 + tf.math.tanh(inner))
    return 0.5 * x * tf.math.erfc(-_SQRT_HALF * x)


def softmax(x, /, axis=-1):
    """A row holding NaN or +inf is NaN throughout, as ``exp(x - max(x))`` computes it on every
    other backend (inf - inf is NaN); tf's kernel answers 0 beside it. Adding 0 * the row's
    maximum (NaN for such rows; tf's maximum propagates NaN) costs about 2x tf's own softmax
    (95 against 210 us on a (64, 1000) float32 batch), the least of the ways measured."""
    x = as_inexact(x)
    if len(x.shape) == 0 and axis in (0, -1):  # a 0-d array: one class (as numpy and torch)
        return tf.nn.softmax(x[None], axis=0)[0]
    out = tf.nn.softmax(x, axis=axis)
    if x.dtype.is_floating:
        out = out + 0.0 * tf.math.reduce_max(x, axis=axis, keepdims=True)
    return out


def log_softmax(x, /, axis=-1):
    x = as_inexact(x)
    if len(x.shape) == 0 and axis in (0, -1):  # a 0-d array: one class (as numpy and torch)
        return tf.nn.log_softmax(x[None], axis=0)[0]
    return tf.nn.log_softmax(x, axis=axis)
