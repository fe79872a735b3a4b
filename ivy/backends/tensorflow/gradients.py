"""tensorflow backend: gradients with a ``tf.GradientTape`` that watches the leaves of ``xs``
explicitly, so plain tensors work as well as ``tf.Variable`` s. Gradients of leaves the loss does
not depend on are zeros, and sparse gradients (``IndexedSlices``, from gathers) are made dense.

With ``retain_grads=False`` the results are wrapped in ``tf.stop_gradient``; with ``True`` an
enclosing tape can differentiate them again (second order)."""

from __future__ import annotations

import tensorflow as tf

from ivy.nest import flatten_nest, map_nest, unflatten_nest

_ZERO = tf.UnconnectedGradients.ZERO


def _input(x):
    return x if isinstance(x, (tf.Tensor, tf.Variable)) else tf.convert_to_tensor(x)


def _stop(nest):
    return map_nest(lambda a: tf.stop_gradient(a) if isinstance(a, tf.Tensor) else a, nest)


def execute_with_gradients(func, xs, *, retain_grads=False):
    leaves, spec = flatten_nest(xs)
    inputs = [_input(x) for x in leaves]
    with tf.GradientTape(watch_accessed_variables=False) as tape:
        tape.watch(inputs)
        out = func(unflatten_nest(spec, inputs))
    if isinstance(out, tuple):
        if not out:
            raise ValueError(
                "execute_with_gradients: the function returned an empty tuple; return the loss."
            )
        loss, aux = out[0], out[1:]
    else:
        loss, aux = out, ()
    loss = _input(loss)
    if loss.shape.rank != 0:
        raise ValueError(
            f"execute_with_gradients: the loss must be a scalar (shape ()), got shape "
            f"{tuple(loss.shape)}; reduce it first, e.g. with ivy.mean or ivy.sum."
        )
    grads = tape.gradient(loss, inputs, unconnected_gradients=_ZERO)
    grads = unflatten_nest(spec, [tf.convert_to_tensor(g) for g in grads])
    if not retain_grads:
        loss, grads, aux = _stop((loss, grads, aux))
    return (loss, grads, *aux)


def execute_with_jacobian(func, x, *, batch_dims=None, retain_grads=False):
    x = _input(x)
    nb = max(x.shape.rank - 1 if batch_dims is None else batch_dims, 0)
    with tf.GradientTape(watch_accessed_variables=False) as tape:
        tape.watch(x)
        y = func(x)
        if y.shape[:nb] != x.shape[:nb]:
            raise ValueError(
                f"execute_with_jacobian: with {nb} batch dims the output's leading shape "
                f"{tuple(y.shape[:nb])} must equal the input's {tuple(x.shape[:nb])}."
            )
        # Batch elements are independent: the Jacobian of the sum over the batch holds the
        # per-element Jacobians.
        summed = tf.reduce_sum(y, axis=list(range(nb))) if nb else y
    jac = tape.jacobian(summed, x, unconnected_gradients=_ZERO)
    n_out = y.shape.rank - nb
    perm = [*range(n_out, n_out + nb), *range(n_out), *range(n_out + nb, jac.shape.rank)]
    jac = tf.transpose(jac, perm)
    if not retain_grads:
        y, jac = tf.stop_gradient(y), tf.stop_gradient(jac)
    return y, jac


def stop_gradient(x, /):
    return tf.stop_gradient(x)


def variable(x, /):
    return tf.Variable(x, trainable=True)
