"""tensorflow backend: gradients with a ``tf.GradientTape`` that watches fresh tensors, one per
leaf (``tf.identity`` of a tensor or variable): the tape records only what the function computes
from its argument, so a tensor that the function captures from outside is a constant, as on
torch and jax, even where it is the very object passed as a leaf (a tape watching that object
would differentiate every use of it). Gradients of leaves the loss does not depend on are zeros,
and sparse gradients (``IndexedSlices``, from gathers) are made dense.

With ``retain_grads=False`` the results are wrapped in ``tf.stop_gradient``; with ``True`` an
enclosing tape can differentiate them again (second order): the fresh tensors are connected to
the leaves."""

from __future__ import annotations

import tensorflow as tf

from ivy.nest import map_nest, multi_map_nest

_ZERO = tf.UnconnectedGradients.ZERO


def _input(x):
    """A fresh tensor of the leaf ``x``'s value, connected to ``x``."""
    if isinstance(x, (tf.Tensor, tf.Variable)):
        return tf.identity(x)
    return tf.convert_to_tensor(x)


def _stop(nest):
    return map_nest(lambda a: tf.stop_gradient(a) if isinstance(a, tf.Tensor) else a, nest)


def value_and_grad_native(fn, xs, /, *, retain_grads=False):
    inputs = [_input(x) for x in xs]
    with tf.GradientTape(watch_accessed_variables=False) as tape:
        tape.watch(inputs)
        loss, aux = fn(inputs)
    if not isinstance(loss, (tf.Tensor, tf.Variable)):
        loss = tf.convert_to_tensor(loss)
    grads = tape.gradient(loss, inputs, unconnected_gradients=_ZERO)
    grads = [tf.convert_to_tensor(g) for g in grads]
    if not retain_grads:
        loss, aux, grads = _stop((loss, aux, grads))
    return loss, aux, grads


def jacobian_native(fn, x, /, *, retain_grads=False):
    x = _input(x)
    with tf.GradientTape(watch_accessed_variables=False) as tape:
        tape.watch(x)
        out, aux = fn(x)
    jac = tape.jacobian(out, x, unconnected_gradients=_ZERO)
    if not retain_grads:
        jac, aux = _stop((jac, aux))
    return jac, aux


def stop_gradient(x, /):
    return tf.stop_gradient(x)


def with_gradient_of(value, fn, args, /):
    # whether a tape or a forward accumulator watches args is not known: fn always runs
    out = fn(*args)
    return multi_map_nest(lambda v, o: tf.stop_gradient(v) + (o - tf.stop_gradient(o)), value, out)


def variable(x, /):
    return tf.Variable(x, trainable=True)
