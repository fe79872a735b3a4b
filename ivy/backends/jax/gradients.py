"""jax backend: gradients with ``jax.value_and_grad(..., has_aux=True)``, so the function is
evaluated once; Jacobians with ``jax.jacrev`` (one vectorised backward pass per output
component). jax differentiates values, so arrays the function captures are constants."""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.nest import map_nest


def _stop(nest):
    return map_nest(lambda a: jax.lax.stop_gradient(a) if isinstance(a, jax.Array) else a, nest)


def value_and_grad_native(fn, xs, /, *, retain_grads=False):
    (loss, aux), grads = jax.value_and_grad(fn, has_aux=True)(list(xs))
    if not retain_grads:
        loss, aux, grads = _stop((loss, aux, grads))
    return loss, aux, grads


def jacobian_native(fn, x, /, *, retain_grads=False):
    jac, aux = jax.jacrev(fn, has_aux=True)(jnp.asarray(x))
    if not retain_grads:
        jac, aux = _stop((jac, aux))
    return jac, aux


def stop_gradient(x, /):
    return jax.lax.stop_gradient(x)


def with_gradient_of(value, fn, args, /):
    """A ``custom_jvp`` whose primal is ``value``: ``fn`` enters only the tangent rule, so a
    function that takes no derivative never evaluates it (reverse mode transposes the rule)."""

    @jax.custom_jvp
    def carried(value, args):
        return _stop(value)

    @carried.defjvp
    def _tangents(primals, tangents):
        value, args = primals
        _, tangent = jax.jvp(fn, tuple(args), tuple(tangents[1]))
        return _stop(value), tangent

    return carried(value, tuple(args))


def variable(x, /):
    return jnp.asarray(x)
