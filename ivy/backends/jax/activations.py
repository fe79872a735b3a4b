"""jax backend: the activations with a kernel of their own (the rest are compositions)."""

from __future__ import annotations

import jax

from ivy.backends.jax._helpers import as_inexact

relu = jax.nn.relu


def sigmoid(x, /):
    return jax.nn.sigmoid(as_inexact(x))


def gelu(x, /, approximate=False):
    return jax.nn.gelu(as_inexact(x), approximate=approximate)


def softmax(x, /, axis=-1):
    x = as_inexact(x)
    if len(x.shape) == 0 and axis in (0, -1):  # a 0-d array: one class (as numpy and torch)
        return jax.nn.softmax(x[None], axis=0)[0]
    return jax.nn.softmax(x, axis=axis)


def log_softmax(x, /, axis=-1):
    x = as_inexact(x)
    if len(x.shape) == 0 and axis in (0, -1):  # a 0-d array: one class (as numpy and torch)
        return jax.nn.log_softmax(x[None], axis=0)[0]
    return jax.nn.log_softmax(x, axis=axis)
