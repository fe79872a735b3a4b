"""jax backend: the activations with a kernel of their own (the rest are compositions)."""

from __future__ import annotations

import jax

__all__ = ["relu", "gelu", "sigmoid", "softmax", "log_softmax"]

relu = jax.nn.relu
sigmoid = jax.nn.sigmoid


def gelu(x, /, approximate=False):
    return jax.nn.gelu(x, approximate=approximate)


def softmax(x, /, axis=-1):
    return jax.nn.softmax(x, axis=axis)


def log_softmax(x, /, axis=-1):
    return jax.nn.log_softmax(x, axis=axis)
