"""jax backend: gradients with ``jax.value_and_grad(..., has_aux=True)``, so the function is
evaluated once; Jacobians with ``jax.jacrev`` (one vectorised backward pass per output
component). ``xs`` is flattened with :mod:`ivy.nest`, so gradients come back in the structure
of ``xs`` (dict key order included), as on the other backends."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.nest import flatten_nest, map_nest, unflatten_nest


def _stop(nest):
    return map_nest(lambda a: jax.lax.stop_gradient(a) if isinstance(a, jax.Array) else a, nest)


def execute_with_gradients(func, xs, *, retain_grads=False):
    leaves, spec = flatten_nest(xs)

    def split(leaves):
        out = func(unflatten_nest(spec, leaves))
        if isinstance(out, tuple):
            if not out:
                raise ValueError(
                    "execute_with_gradients: the function returned an empty tuple; return the loss."
                )
            loss, aux = out[0], out[1:]
        else:
            loss, aux = out, ()
        if jnp.ndim(loss) != 0:
            raise ValueError(
                f"execute_with_gradients: the loss must be a scalar (shape ()), got shape "
                f"{jnp.shape(loss)}; reduce it first, e.g. with ivy.mean or ivy.sum."
            )
        return loss, aux

    (loss, aux), grads = jax.value_and_grad(split, has_aux=True)(leaves)
    grads = unflatten_nest(spec, grads)
    if not retain_grads:
        loss, grads, aux = _stop((loss, grads, aux))
    return (loss, grads, *aux)


def execute_with_jacobian(func, x, *, batch_dims=None, retain_grads=False):
    x = jnp.asarray(x)
    nb = max(x.ndim - 1 if batch_dims is None else batch_dims, 0)
    batch_axes = tuple(range(nb))

    def summed(x):
        y = func(x)
        if tuple(y.shape[:nb]) != tuple(x.shape[:nb]):
            raise ValueError(
                f"execute_with_jacobian: with {nb} batch dims the output's leading shape "
                f"{tuple(y.shape[:nb])} must equal the input's {tuple(x.shape[:nb])}."
            )
        # Batch elements are independent: the Jacobian of the sum over the batch holds the
        # per-element Jacobians.
        return (jnp.sum(y, axis=batch_axes) if nb else y), y

    jac, y = jax.jacrev(summed, has_aux=True)(x)
    n_out = y.ndim - nb
    perm = (*range(n_out, n_out + nb), *range(n_out), *range(n_out + nb, jac.ndim))
    jac = jnp.transpose(jac, perm)
    if not retain_grads:
        y, jac = jax.lax.stop_gradient(y), jax.lax.stop_gradient(jac)
    return y, jac


def stop_gradient(x, /):
    return jax.lax.stop_gradient(x)


def variable(x, /):
    return jnp.asarray(x)
