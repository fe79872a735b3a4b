"""Automatic differentiation, functional and the same on every differentiable backend.

``loss, grads, *aux = ivy.execute_with_gradients(func, xs)`` evaluates ``func(xs)`` once and
returns its loss, the gradients of the loss with respect to every leaf of the nest ``xs`` (same
structure), and any further outputs of ``func``. ``func`` is differentiated only through its
argument: an array it captures from outside is a constant, even where it is the very object
passed in ``xs``.

The family is written once here, over two primitives that each backend implements:
:func:`value_and_grad_native` (a function of a flat list of arrays returning ``(loss, aux)``) and
:func:`jacobian_native`. The nests, the loss/aux split, the checks and the batch layout of
Jacobians live here. Per backend: torch ``torch.autograd.grad`` on fresh leaf tensors (nothing
accumulates in ``.grad`` across calls), tensorflow a ``GradientTape`` watching fresh tensors
(``tf.identity`` of each leaf), jax ``jax.value_and_grad(..., has_aux=True)`` and
``jax.jacrev``. numpy has no autodiff and raises :class:`ivy.errors.UnsupportedError`.

Leaves must be floating-point arrays; gradients of leaves the loss does not use are zeros.
``value_and_grad``, ``grad`` and ``jacobian`` return functions, whose framework is resolved from
their call arguments (or from ``f`` / the global framework).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from typing import Any

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition, dispatch
from ivy.nest import flatten_nest, unflatten_nest
from ivy.typing import Array, Framework, Nest

__all__ = [
    "value_and_grad_native",
    "jacobian_native",
    "execute_with_gradients",
    "execute_with_jacobian",
    "value_and_grad",
    "grad",
    "jacobian",
    "stop_gradient",
    "with_gradient_of",
    "variable",
]


@dispatch("xs")
def value_and_grad_native(
    fn: Callable[[list[Array]], tuple[Array, Any]],
    xs: Sequence[Array],
    /,
    *,
    retain_grads: bool = False,
    f: Framework = None,
) -> tuple[Array, Any, list[Array]]:
    """The backends' one gradient primitive, under :func:`execute_with_gradients`,
    :func:`value_and_grad` and :func:`grad` (prefer those).

    ``fn`` is differentiated only through its argument: arrays that ``fn`` captures from outside
    are constants, also where they are the very objects given in ``xs`` (each backend hands
    ``fn`` fresh arrays of the same values).

    Args:
        fn: ``fn(leaves) -> (loss, aux)``, with ``loss`` a scalar array.
        xs: the arrays (a flat list) to differentiate with respect to.
        retain_grads: as in :func:`execute_with_gradients`; with False the results are cut from
            the graph.
        f: framework name or namespace; by default inferred from ``xs``.

    Returns:
        ``(loss, aux, grads)``, ``grads`` a list like ``xs`` (zeros where ``loss`` does not
        depend on an array).

    Example:
        >>> ivy.value_and_grad_native(lambda v: (ivy.sum(v[0] ** 2), ()), [jnp.ones(2)])[2]
        [Array([2., 2.], dtype=float32)]
    """


@dispatch("x")
def jacobian_native(
    fn: Callable[[Array], tuple[Array, Any]],
    x: Array,
    /,
    *,
    retain_grads: bool = False,
    f: Framework = None,
) -> tuple[Array, Any]:
    """The backends' Jacobian primitive, under :func:`execute_with_jacobian` and
    :func:`jacobian` (prefer those). Like :func:`value_and_grad_native`, ``fn`` is differentiated
    only through its argument.

    Args:
        fn: ``fn(x) -> (out, aux)``.
        x: the array to differentiate with respect to.
        retain_grads: keep the results differentiable.
        f: framework name or namespace; by default inferred from ``x``.

    Returns:
        ``(jac, aux)``, ``jac`` of shape ``(*out.shape, *x.shape)``.

    Example:
        >>> ivy.jacobian_native(lambda x: (x**2, ()), jnp.arange(2.0))[0]
        Array([[0., 0.],
               [0., 2.]], dtype=float32)
    """


def _loss_and_aux(out: Any, name: str) -> tuple[Any, tuple]:
    """(loss, aux) of a differentiated function's output: a tuple's first element is the loss,
    which must be a scalar."""
    if isinstance(out, tuple):
        if not out:
            raise ValueError(f"{name}: the function returned an empty tuple; return the loss.")
        loss, aux = out[0], out[1:]
    else:
        loss, aux = out, ()
    shape = tuple(getattr(loss, "shape", ()))
    if shape:
        raise ValueError(
            f"{name}: the loss must be a scalar (shape ()), got shape {shape}; reduce it "
            f"first, e.g. with ivy.mean or ivy.sum."
        )
    return loss, aux


@composition
def execute_with_gradients(
    func: Callable[[Nest], Any], xs: Nest, *, retain_grads: bool = False, f: Framework = None
) -> tuple[Any, ...]:
    """Evaluate ``func(xs)`` and differentiate its loss with respect to every leaf of ``xs``.

    ``func`` is differentiated only through its argument: arrays it captures from outside are
    constants, even where they are the very arrays passed in ``xs``.

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
    xp = _fh.get_framework(xs, f=f)
    leaves, spec = flatten_nest(xs)

    def loss_and_aux(leaves):
        return _loss_and_aux(func(unflatten_nest(spec, leaves)), "execute_with_gradients")

    loss, aux, grads = xp.value_and_grad_native(loss_and_aux, leaves, retain_grads=retain_grads)
    # the structure of xs found again, not ``spec``: where the loss breaks a torch.compile
    # graph, dynamo resumes this frame with a ``spec`` that its optree polyfill cannot unflatten
    # (torch 2.13: "unhashable type: 'list'", "length mismatch")
    return (loss, unflatten_nest(flatten_nest(xs)[1], grads), *aux)


@composition
def execute_with_jacobian(
    func: Callable[[Array], Array],
    x: Array,
    *,
    batch_dims: int | None = None,
    method: str = "native",
    retain_grads: bool = False,
    f: Framework = None,
) -> tuple[Array, Array]:
    """Evaluate ``y = func(x)`` and its Jacobian, per batch element.

    ``x`` has shape ``(*batch, *in_shape)`` and ``func(x)`` shape ``(*batch, *out_shape)``, where
    ``batch`` is the first ``batch_dims`` axes; ``func`` must treat batch elements independently.

    Two methods give the same Jacobian:

    - ``"native"``: the framework's own (``jax.jacrev``; on torch one backward pass vectorised
      over the output components; tensorflow's ``GradientTape.jacobian``, vectorised by pfor);
    - ``"replicate"``, for a ``func`` that accepts any leading batch shape (as ivy's functions
      and :func:`ivy_gym.rollout` do): ``x`` is stacked once per output component ``m`` along a
      new leading axis, and one backward pass of ``func`` over that ``m`` times bigger batch
      gives every row. No operation is vectorised by the framework (tensorflow's pfor, torch's
      vmap), which is what a long ``tf.while_loop`` needs: there pfor grows to gigabytes. Its
      memory grows with ``m``; ``func`` is also evaluated once on ``x`` for ``y``.

    Args:
        func: the function of one array.
        x: the input array.
        batch_dims: number of leading batch axes; by default all but the last axis of ``x``
            (so a vector function ``(..., n) -> (..., m)`` gives ``(..., m, n)``). ``0`` gives
            the full Jacobian.
        method: ``"native"`` or ``"replicate"`` (above).
        retain_grads: keep the results differentiable.
        f: framework name or namespace; by default inferred from ``x``.

    Returns:
        ``(y, jac)`` with ``jac`` of shape ``(*batch, *out_shape, *in_shape)``.

    Example:
        >>> y, J = ivy.execute_with_jacobian(lambda q: q ** 2, jnp.ones((5, 3)))
        >>> J.shape
        (5, 3, 3)
    """
    xp = _fh.get_framework(x, f=f)
    if not hasattr(x, "shape"):
        x = xp.asarray(x)
    rank = len(x.shape)
    nb = max(rank - 1 if batch_dims is None else batch_dims, 0)
    batch_axes = tuple(range(nb))

    def summed(x):
        y = func(x)
        _check_batch(y, x, nb)
        # Batch elements are independent: the Jacobian of the sum over the batch holds the
        # per-element Jacobians.
        return (xp.sum(y, axis=batch_axes) if nb else y), y

    if method == "replicate":
        return _replicated_jacobian(xp, func, x, nb, retain_grads)
    if method != "native":
        raise ValueError(
            f"execute_with_jacobian: method must be 'native' or 'replicate', got {method!r}."
        )
    jac, y = xp.jacobian_native(summed, x, retain_grads=retain_grads)
    n_out = len(y.shape) - nb  # jac: (*out_shape, *batch, *in_shape) -> batch first
    perm = (*range(n_out, n_out + nb), *range(n_out), *range(n_out + nb, n_out + rank))
    return y, (xp.permute_dims(jac, perm) if perm != tuple(range(n_out + rank)) else jac)


def _check_batch(y, x, nb):
    if tuple(y.shape[:nb]) != tuple(x.shape[:nb]):
        raise ValueError(
            f"execute_with_jacobian: with {nb} batch dims the output's leading shape "
            f"{tuple(y.shape[:nb])} must equal the input's {tuple(x.shape[:nb])}."
        )


def _replicated_jacobian(xp, func, x, nb, retain_grads):
    """:func:`execute_with_jacobian`'s ``"replicate"`` method: copy ``i`` of ``x`` (a new
    leading axis) carries the gradient of output component ``i`` alone."""
    batch, in_shape = tuple(x.shape[:nb]), tuple(x.shape[nb:])
    y = xp.stop_gradient(func(x)) if not retain_grads else func(x)
    _check_batch(y, x, nb)
    out_shape = tuple(y.shape[nb:])
    m = math.prod(out_shape)
    # selects output component i of copy i: (m, *batch ones, m)
    pick = xp.reshape(xp.eye(m, dtype=y.dtype, device=xp.dev(y)), (m, *(1,) * nb, m))

    def picked(leaves):
        ys = func(leaves[0])
        if tuple(ys.shape) != (m, *batch, *out_shape):
            raise ValueError(
                "execute_with_jacobian: method='replicate' needs a func that accepts a new "
                f"leading batch axis: x of shape {(m, *batch, *in_shape)} gave "
                f"{tuple(ys.shape)}, not {(m, *batch, *out_shape)}. Use method='native'."
            )
        return xp.sum(xp.reshape(ys, (m, *batch, m)) * pick), ()

    copies = xp.broadcast_to(x, (m, *batch, *in_shape))
    _, _, (rows,) = xp.value_and_grad_native(picked, [copies], retain_grads=retain_grads)
    # rows: (m, *batch, *in_shape) -> (*batch, *out_shape, *in_shape)
    rows = xp.permute_dims(rows, (*range(1, nb + 1), 0, *range(nb + 1, nb + 1 + len(in_shape))))
    return y, xp.reshape(rows, (*batch, *out_shape, *in_shape))


@dispatch
def stop_gradient(x: Array, /, *, f: Framework = None) -> Array:
    """``x`` with no gradient flowing back through it (torch ``detach``, jax/tf
    ``stop_gradient``; numpy arrays carry no gradient and are returned as they are).

    Example:
        >>> ivy.stop_gradient(torch.ones(2, requires_grad=True)).requires_grad
        False
    """


@dispatch("value", "args")
def with_gradient_of(value: Nest, fn: Callable, args: Sequence, /, *, f: Framework = None) -> Nest:
    """``value``, differentiated as ``fn(*args)``: its value is ``value``'s and its derivatives
    (reverse and forward mode) are those of ``fn(*args)`` with respect to ``args``.

    The straight-through pattern ``stop_gradient(value) + fn(*args) - stop_gradient(fn(*args))``,
    with one difference: ``fn`` is called only where a derivative is taken. Use it where the
    value comes from a computation that is not differentiated (an iterative solver run to
    convergence) and ``fn`` is a cheap function with the right derivative at that point (one
    Newton step from the solution: the implicit function theorem). Per backend: jax a
    ``custom_jvp`` (a compiled function that takes no derivative never runs ``fn``); torch
    calls ``fn`` only while gradients are recorded for one of ``args`` (``requires_grad`` with
    grad mode on, or ``torch.func``'s and forward-mode AD's transforms); tensorflow, which cannot
    tell whether a tape watches, always calls it; backends without autodiff never do.

    Args:
        value: an array or a nest of arrays.
        fn: a function of ``*args`` returning arrays of ``value``'s structure, shapes and dtypes;
            it is differentiated only through ``args`` (arrays it captures are constants).
        args: the arrays (or nests of arrays) to differentiate ``fn`` by.

    Returns:
        ``value`` (detached from its own derivatives), with ``fn``'s.

    Example:
        The square root by Newton's method, run without derivatives, then given the derivative
        of one Newton step from its result (which is ``1 / (2 sqrt(a))``):

        >>> a = jnp.asarray(2.0)
        >>> def root(a):
        ...     x = jnp.asarray(1.0)
        ...     for _ in range(30):
        ...         x = ivy.stop_gradient(0.5 * (x + a / x))
        ...     return ivy.with_gradient_of(x, lambda a: 0.5 * (x + a / x), (a,))
        >>> round(float(root(a)), 6), round(float(jax.grad(root)(a)), 6)
        (1.414214, 0.353553)
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
    method: str = "native",
    retain_grads: bool = False,
    f: Framework = None,
) -> Callable[[Array], Array]:
    """The function ``x -> jac`` of ``func``; see :func:`execute_with_jacobian` for the shapes.

    Args:
        func: a function of one array, treating its ``batch_dims`` leading axes as batch.
        batch_dims: leading batch axes; by default all but the last axis of ``x``.
        method: ``"native"`` or ``"replicate"``, as for :func:`execute_with_jacobian`.
        retain_grads: keep the Jacobian differentiable.
        f: framework; by default resolved from the arguments of each call.

    Returns:
        A function of ``x`` returning the Jacobian ``(*batch, *out_shape, *in_shape)``.

    Example:
        >>> forward_kinematics = lambda q: jnp.stack([jnp.cos(q).sum(-1), jnp.sin(q).sum(-1)], -1)
        >>> joint_angles = jnp.zeros((5, 3))
        >>> J = ivy.jacobian(forward_kinematics)(joint_angles)  # (batch, n) -> (batch, m, n)
    """

    @functools.wraps(func)
    def jacobian_fn(x):
        xp = _fh.get_framework(x, f=f)
        return xp.execute_with_jacobian(
            func, x, batch_dims=batch_dims, method=method, retain_grads=retain_grads
        )[1]

    return jacobian_fn
