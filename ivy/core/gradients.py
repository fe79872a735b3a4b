"""Automatic differentiation, functional and the same on every differentiable backend.

``loss, grads, *aux = ivy.execute_with_gradients(func, xs)`` evaluates ``func(xs)`` once and
returns its loss, the gradients of the loss with respect to every leaf of the nest ``xs`` (same
structure), and any further outputs of ``func``. Per backend: torch uses
``torch.autograd.grad`` (nothing accumulates in ``.grad`` across calls), tensorflow a
``GradientTape`` that watches the leaves (plain tensors or variables), jax
``jax.value_and_grad(..., has_aux=True)``. numpy has no autodiff and raises
:class:`ivy.errors.UnsupportedError`.

Leaves must be floating-point arrays; gradients of leaves the loss does not use are zeros.
``value_and_grad``, ``grad`` and ``jacobian`` return functions, whose framework is resolved from
their call arguments (or from ``f`` / the global framework).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition, dispatch
from ivy.typing import Array, Framework, Nest

__all__ = [
    "execute_with_gradients",
    "execute_with_jacobian",
    "value_and_grad",
    "grad",
    "jacobian",
    "stop_gradient",
    "variable",
]


@dispatch("xs")
def execute_with_gradients(
    func: Callable[[Nest], Any], xs: Nest, *, retain_grads: bool = False, f: Framework = None
) -> tuple[Any, ...]:
    """Evaluate ``func(xs)`` and differentiate its loss with respect to every leaf of ``xs``.

    Args:
        func: ``func(xs)`` returns a scalar loss, or a tuple ``(loss, *aux)``.
        xs: a nest (dicts, lists, tuples) of floating-point arrays, or one array.
        retain_grads: keep the results differentiable (the graph is kept, e.g. for second-order
            gradients); by default the loss, gradients and aux are cut from the graph.
        f: framework name or namespace; by default inferred from ``xs``.

    Returns:
        ``(loss, grads, *aux)``, with ``grads`` of the structure of ``xs``.

    Example:
        >>> v = {"w": torch.ones(3, dtype=torch.float64)}
        >>> loss, grads = ivy.execute_with_gradients(lambda v: ivy.sum(v["w"] ** 2), v)
        >>> grads["w"]
        tensor([2., 2., 2.], dtype=torch.float64)
    """


@dispatch("x")
def execute_with_jacobian(
    func: Callable[[Array], Array],
    x: Array,
    *,
    batch_dims: int | None = None,
    retain_grads: bool = False,
    f: Framework = None,
) -> tuple[Array, Array]:
    """Evaluate ``y = func(x)`` and its Jacobian, per batch element.

    ``x`` has shape ``(*batch, *in_shape)`` and ``func(x)`` shape ``(*batch, *out_shape)``, where
    ``batch`` is the first ``batch_dims`` axes; ``func`` must treat batch elements independently.

    Args:
        func: the function of one array.
        x: the input array.
        batch_dims: number of leading batch axes; by default all but the last axis of ``x``
            (so a vector function ``(..., n) -> (..., m)`` gives ``(..., m, n)``). ``0`` gives
            the full Jacobian.
        retain_grads: keep the results differentiable.
        f: framework name or namespace; by default inferred from ``x``.

    Returns:
        ``(y, jac)`` with ``jac`` of shape ``(*batch, *out_shape, *in_shape)``.

    Example:
        >>> y, J = ivy.execute_with_jacobian(lambda q: q ** 2, jnp.ones((5, 3)))
        >>> J.shape
        (5, 3, 3)
    """


@dispatch
def stop_gradient(x: Array, /, *, f: Framework = None) -> Array:
    """``x`` with no gradient flowing back through it (torch ``detach``, jax/tf
    ``stop_gradient``; numpy arrays carry no gradient and are returned as they are).

    Example:
        >>> ivy.stop_gradient(torch.ones(2, requires_grad=True)).requires_grad
        False
    """


@dispatch
def variable(x: Array, /, *, f: Framework = None) -> Array:
    """``x`` as a trainable variable: a torch tensor that requires grad, a ``tf.Variable``; jax
    and numpy arrays are returned as arrays (jax differentiates values, numpy does not).

    Example:
        >>> ivy.variable(torch.zeros(2)).requires_grad
        True
    """


@composition
def value_and_grad(
    func: Callable[[Nest], Any], /, *, retain_grads: bool = False, f: Framework = None
) -> Callable[[Nest], tuple[Any, ...]]:
    """The function ``xs -> (loss, grads, *aux)`` of ``func``: :func:`execute_with_gradients`
    with ``func`` fixed.

    Args:
        func: ``func(xs)`` returns a scalar loss or ``(loss, *aux)``.
        retain_grads: as in :func:`execute_with_gradients`.
        f: framework; by default resolved from the arguments of each call.

    Returns:
        A function of ``xs``.

    Example:
        >>> loss, grads = ivy.value_and_grad(lambda x: ivy.sum(x ** 2))(jnp.ones(3))
    """

    @functools.wraps(func)
    def value_and_grad_fn(xs):
        xp = _fh.get_framework(xs, f=f)
        return xp.execute_with_gradients(func, xs, retain_grads=retain_grads)

    return value_and_grad_fn


@composition
def grad(
    func: Callable[[Nest], Any], /, *, retain_grads: bool = False, f: Framework = None
) -> Callable[[Nest], Nest]:
    """The function ``xs -> grads`` of ``func`` (its aux outputs, if any, are dropped).

    Args:
        func: ``func(xs)`` returns a scalar loss or ``(loss, *aux)``.
        retain_grads: as in :func:`execute_with_gradients`.
        f: framework; by default resolved from the arguments of each call.

    Returns:
        A function of ``xs`` returning gradients of the structure of ``xs``.

    Example:
        >>> ivy.grad(lambda x: ivy.sum(x ** 2))(jnp.arange(3.0))
        Array([0., 2., 4.], dtype=float32)
    """

    @functools.wraps(func)
    def grad_fn(xs):
        xp = _fh.get_framework(xs, f=f)
        return xp.execute_with_gradients(func, xs, retain_grads=retain_grads)[1]

    return grad_fn


@composition
def jacobian(
    func: Callable[[Array], Array],
    /,
    *,
    batch_dims: int | None = None,
    retain_grads: bool = False,
    f: Framework = None,
) -> Callable[[Array], Array]:
    """The function ``x -> jac`` of ``func``; see :func:`execute_with_jacobian` for the shapes.

    Args:
        func: a function of one array, treating its ``batch_dims`` leading axes as batch.
        batch_dims: leading batch axes; by default all but the last axis of ``x``.
        retain_grads: keep the Jacobian differentiable.
        f: framework; by default resolved from the arguments of each call.

    Returns:
        A function of ``x`` returning the Jacobian ``(*batch, *out_shape, *in_shape)``.

    Example:
        >>> J = ivy.jacobian(forward_kinematics)(joint_angles)  # (batch, n) -> (batch, m, n)
    """

    @functools.wraps(func)
    def jacobian_fn(x):
        xp = _fh.get_framework(x, f=f)
        return xp.execute_with_jacobian(func, x, batch_dims=batch_dims, retain_grads=retain_grads)[
            1
        ]

    return jacobian_fn
