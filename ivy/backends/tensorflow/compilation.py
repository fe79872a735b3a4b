"""tensorflow backend: compilation with ``tf.function`` (graph mode), without AutoGraph.

AutoGraph is off (``autograph=False``): Python control flow runs once at trace time, as under
``jax.jit``, so a function written with ivy behaves alike on both; branch on array values with
ivy's array functions (``ivy.where``) rather than Python ``if``.

Static arguments: ``tf.function`` treats every non-tensor argument (Python numbers, strings,
tuples of them) as static and retraces when one changes, so ``static_argnums`` and
``static_argnames`` are accepted for a uniform signature and need nothing more.

Randomness: the backend's ``tf.random.Generator`` keeps its state in a ``tf.Variable`` that the
graph reads and advances on every call, so draws differ from call to call and ``ivy.seed``
(which resets that same variable) reproduces them.
"""

from __future__ import annotations

import tensorflow as tf

__all__ = ["compile_native"]


def compile_native(fn, /, *, static_argnums=None, static_argnames=None):
    return tf.function(fn, autograph=False)
