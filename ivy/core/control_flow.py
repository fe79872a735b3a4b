"""Structured control flow: ``scan``, ``fori_loop``, ``while_loop`` and ``cond``.

Loops and branches written with these functions run eagerly, differentiate and compile on every
backend, with jax's semantics (``jax.lax.scan`` and friends):

- jax: ``jax.lax.scan``, ``fori_loop``, ``while_loop`` and ``cond`` themselves. The backend's PRNG
  key is threaded through the loop's carry (and the branches' operands), so ivy's random
  functions inside a body draw fresh numbers at every step, eager and under ``ivy.compile_fn``.
- tensorflow: eagerly, a Python loop (what ``tf.while_loop`` does itself in eager mode); inside a
  graph (``ivy.compile_fn``, ``tf.function``), ``tf.while_loop`` (``scan`` stacks its outputs in
  ``TensorArray`` s) and ``tf.cond``.
- torch: a Python loop and a Python ``if``; ``torch.compile`` unrolls the loop into one graph,
  or, for loops declared ``pure=True``, keeps it as torch's own ``scan``/``while_loop``
  operator, tracing the body once (torch requires such bodies to have no Python side effects
  and not to close over two views of one tensor, hence the opt-in).
- numpy: a Python loop and a Python ``if``.

Carries, inputs and outputs are nests (dicts, lists, tuples of arrays; see :mod:`ivy.nest`). As
jax and tensorflow require, a loop's carry must keep its structure, shapes and dtypes from one
step to the next; the Python loops check this at the first step, so code that runs on numpy or
torch also runs on jax and tensorflow.

Example:
    >>> def step(total, x):
    ...     total = total + x
    ...     return total, total * 2
    >>> total, doubled = ivy.scan(step, np.float64(0.0), np.arange(4.0))
    >>> total, doubled
    (np.float64(6.0), array([ 0.,  2.,  6., 12.]))
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Sequence
from typing import Any

from ivy import framework_handler as _fh
from ivy.core._by_hand import by_hand
from ivy.core._dispatch import dispatch
from ivy.nest import flatten_nest, map_nest, unflatten_nest
from ivy.typing import Array, Framework, Nest

__all__ = ["scan", "fori_loop", "while_loop", "cond"]


@dispatch("init", "xs")
def scan(
    fn: Callable[[Nest, Nest], tuple[Nest, Nest]],
    init: Nest,
    xs: Nest | None = None,
    length: int | None = None,
    unroll: int | bool = 1,
    *,
    pure: bool = False,
    f: Framework = None,
) -> tuple[Nest, Nest]:
    """Loop ``carry, y = fn(carry, x)`` over the leading axis of ``xs``, stacking the ``y`` s.

    The semantics of ``jax.lax.scan``, in Python::

        carry, ys = init, []
        for x in xs:              # slices along the leading axis of every leaf of xs
            carry, y = fn(carry, x)
            ys.append(y)
        return carry, stack(ys)   # stacked leaf by leaf along a new leading axis

    Args:
        fn: ``fn(carry, x) -> (carry, y)``; the returned carry has the structure, shapes and
            dtypes of ``init``; ``y`` is any nest (None for no outputs).
        init: the initial carry, a nest of arrays.
        xs: a nest of arrays with a common leading axis, or None (``fn`` then gets ``x=None``).
        length: the number of steps; required when ``xs`` is None, else it must equal the
            leading axis of ``xs``.
        unroll: steps per iteration of the compiled loop (jax, tensorflow graphs), or True for a
            fully unrolled loop; the result is the same.
        pure: ``fn`` has no Python side effects (no appends, no counters outside the loop)
            and closes over no two views of one array: ``torch.compile`` may then keep the loop
            (torch's ``scan`` operator) and trace ``fn`` once instead of once per step. jax and
            tensorflow always trace it once; eager loops are Python loops either way.
        f: framework name or namespace; by default inferred from ``init`` and ``xs``.

    Returns:
        ``(carry, ys)``: the final carry, and the nest of ``y`` s stacked along a new leading
        axis of size ``length``.

    Example:
        >>> carry, ys = ivy.scan(lambda c, x: (c * x, c), torch.tensor(1.0), torch.arange(1., 5.))
        >>> carry, ys
        (tensor(24.), tensor([1., 1., 2., 6.]))
    """


@dispatch("init_val", "lower", "upper")
def fori_loop(
    lower: int | Array,
    upper: int | Array,
    body_fun: Callable[[Any, Nest], Nest],
    init_val: Nest,
    *,
    pure: bool = False,
    f: Framework = None,
) -> Nest:
    """``val = body_fun(i, val)`` for ``i`` from ``lower`` to ``upper - 1``; returns ``val``.

    ``i`` is a Python int on numpy, torch and eager tensorflow, and a scalar integer array under
    jax and inside tensorflow graphs: index with it, or convert it with ``ivy.astype`` before
    mixing it with float arrays. Differentiable (jax: when ``lower`` and ``upper`` are Python
    ints, as ``jax.lax.fori_loop`` then runs as a scan).

    Args:
        lower: first index.
        upper: one past the last index.
        body_fun: ``body_fun(i, val) -> val`` with ``val``'s structure, shapes and dtypes.
        init_val: the initial value, a nest of arrays.
        pure: as for :func:`scan` (torch.compile then keeps the loop as a scan).
        f: framework name or namespace; by default inferred from ``init_val``.

    Returns:
        The final value.

    Example:
        >>> ivy.fori_loop(0, 3, lambda i, x: x * 2.0, np.float32(1.0))
        np.float32(8.0)
    """


@dispatch("init_val")
def while_loop(
    cond_fun: Callable[[Nest], Array],
    body_fun: Callable[[Nest], Nest],
    init_val: Nest,
    *,
    maximum_iterations: int | None = None,
    pure: bool = False,
    f: Framework = None,
) -> Nest:
    """``while cond_fun(val): val = body_fun(val)``; returns ``val``.

    With ``maximum_iterations`` the loop also stops after that many steps (as
    ``tf.while_loop``'s argument of that name), and it is reverse-differentiable on every
    differentiable backend: jax then runs it as a scan of ``maximum_iterations`` steps whose
    steps after the end do nothing. Without it, jax cannot differentiate the loop in reverse mode
    (``jax.lax.while_loop``'s limit; jax raises when asked to).

    Args:
        cond_fun: ``cond_fun(val)`` returns a boolean scalar array; it should not draw random
            numbers.
        body_fun: ``body_fun(val) -> val`` with ``val``'s structure, shapes and dtypes.
        init_val: the initial value, a nest of arrays.
        maximum_iterations: the most steps to run, or None for no limit.
        pure: as for :func:`scan` (torch.compile then keeps the loop as torch's
            ``while_loop`` operator, where no carried array requires gradients).
        f: framework name or namespace; by default inferred from ``init_val``.

    Returns:
        The final value.

    Example:
        >>> ivy.while_loop(lambda x: x < 10, lambda x: x * 2, torch.tensor(1))
        tensor(16)
    """


@by_hand
def cond(
    pred: bool | Array,
    true_fun: Callable[..., Nest],
    false_fun: Callable[..., Nest],
    *operands: Nest,
    f: Framework = None,
) -> Nest:
    """``true_fun(*operands)`` if ``pred`` else ``false_fun(*operands)``, as ``jax.lax.cond``.

    Only the selected branch runs (jax and tensorflow graphs trace both, and need both to return
    the same structure, shapes and dtypes); gradients flow through the selected branch. A Python
    bool ``pred`` selects the branch in Python on every backend.

    Args:
        pred: a boolean (or numeric) scalar array, or a Python bool.
        true_fun: called with ``*operands`` when ``pred`` is true.
        false_fun: called with ``*operands`` when ``pred`` is false.
        *operands: nests of arrays passed to the branch.
        f: framework name or namespace; by default inferred from ``pred`` and ``operands``.

    Returns:
        The selected branch's output.

    Example:
        >>> x = jnp.array(3.0)
        >>> ivy.cond(x > 0, lambda v: v * 2, lambda v: -v, x)  # pred concrete: a Python if
        Array(6., dtype=float32, weak_type=True)
    """
    if isinstance(pred, bool):
        return true_fun(*operands) if pred else false_fun(*operands)
    return _fh.get_framework(pred, operands, f=f).cond(pred, true_fun, false_fun, *operands)


# ----------------------------------------------------------------------------------------------
# Python loops, shared by the backends that run control flow as Python (numpy, torch, eager
# tensorflow). ``ops`` gives the backend's natives: ``unstack(a) -> list of slices``,
# ``stack(list) -> array``, ``zeros(shape, dtype)``, ``asarray(a)`` (the backend's
# ``ivy.<backend>.asarray``: Python scalars become arrays of the default dtypes, as jax makes
# them arrays) and ``native``, the backend's array types.
# ----------------------------------------------------------------------------------------------


class LoopOps:
    """The few native functions the Python loops need from a backend, and its array types."""

    __slots__ = ("unstack", "stack", "zeros", "asarray", "native")

    def __init__(self, unstack, stack, zeros, asarray, native):
        self.unstack, self.stack, self.zeros, self.asarray = unstack, stack, zeros, asarray
        self.native = native

    def arrays(self, nest: Nest) -> Nest:
        """``nest`` with its leaves that are not arrays of the backend (Python scalars, numpy
        arrays next to torch ones) made arrays of the backend."""
        if isinstance(nest, self.native):  # the common case, without a walk of the nest
            return nest
        return map_nest(lambda a: a if isinstance(a, self.native) else self.asarray(a), nest)

    def leaves(self, leaves: list) -> list:
        """A flat list of leaves made arrays of the backend (as :meth:`arrays`, without a walk
        of a nest or a call per leaf)."""
        native, asarray = self.native, self.asarray
        return [a if isinstance(a, native) else asarray(a) for a in leaves]


def scan_length(xs_leaves: Sequence[Any], length: int | None) -> int:
    """The number of steps of a scan: the common leading axis of ``xs_leaves`` and ``length``."""
    leading = set()
    for a in xs_leaves:
        shape = tuple(a.shape)
        if not shape:
            raise ValueError(
                "ivy.scan: every leaf of xs needs a leading axis to scan over; got a 0-d array. "
                "Pass per-step inputs stacked along axis 0, or use length= with xs=None."
            )
        leading.add(shape[0])
    if len(leading) > 1:
        raise ValueError(
            f"ivy.scan: the leaves of xs have different leading axes {sorted(leading, key=str)}; they "
            f"must all have one size, the number of steps."
        )
    if length is not None:
        length = operator.index(length)
        if length < 0:
            raise ValueError(f"ivy.scan: length must be non-negative, got {length}.")
    if leading:
        (n,) = leading
        if length is not None and n is not None and length != n:
            raise ValueError(
                f"ivy.scan: length={length} but the leaves of xs have leading axis {n}; "
                f"give one or make them agree."
            )
        return n
    if length is None:
        raise ValueError("ivy.scan: with xs=None (or an xs without arrays) give length=.")
    return length


def check_carry(name: str, before: Nest, after: Nest) -> None:
    """Raise a TypeError unless ``after`` has the structure, and its arrays the shapes and
    dtypes, of ``before`` (what jax and tensorflow require of a loop's carry)."""
    leaves_before, spec_before = flatten_nest(before)
    leaves_after, spec_after = flatten_nest(after)
    if spec_before != spec_after:
        raise TypeError(
            f"ivy.{name}: the body must return a carry with the structure of the initial one "
            f"(as jax and tensorflow require); initial {spec_before}, returned {spec_after}."
        )
    problems = []
    for i, (a, b) in enumerate(zip(leaves_before, leaves_after)):
        if not (hasattr(a, "shape") and hasattr(a, "dtype")):
            continue  # a Python scalar: its type is the backend's business
        shape_b = tuple(getattr(b, "shape", ()))
        dtype_b = getattr(b, "dtype", type(b).__name__)
        if tuple(a.shape) != shape_b or a.dtype != dtype_b:
            problems.append((i, f"{a.dtype}{tuple(a.shape)} -> {dtype_b}{shape_b}"))
    if problems:  # the leaves' paths only for the message (they cost more than the check)
        paths = spec_before.paths()
        problems = [f"at {paths[i] or 'the root'}: {change}" for i, change in problems]
        raise TypeError(
            f"ivy.{name}: the body must keep the carry's shapes and dtypes (as jax and tensorflow "
            f"require); changed " + "; ".join(problems) + ". Cast or reshape inside the body."
        )


def python_scan(ops: LoopOps, fn, init, xs, length, unroll):
    """:func:`scan` as a Python loop."""
    xs_leaves, xs_spec = flatten_nest(xs)
    xs_leaves = ops.leaves(xs_leaves)
    n = scan_length(xs_leaves, length)
    if n == 0:
        return ops.arrays(init), _empty_outputs(ops, fn, init, xs_leaves, xs_spec)
    if xs_spec.is_leaf():  # one array: its slices are the inputs
        inputs = ops.unstack(xs_leaves[0])
    elif not xs_leaves:  # None, or a nest without arrays
        inputs = [xs] * n
    else:
        slices = [ops.unstack(a) for a in xs_leaves]
        inputs = [unflatten_nest(xs_spec, [s[t] for s in slices]) for t in range(n)]
    carry, ys = ops.arrays(init), []
    for t, x in enumerate(inputs):
        new_carry, y = fn(carry, x)
        if t == 0:
            check_carry("scan", init, new_carry)  # a Python scalar in init may change dtype
        carry = new_carry
        ys.append(y)
    return carry, stack_outputs(ops, ys)


def stack_outputs(ops: LoopOps, ys: list):
    """The per-step output nests ``ys`` stacked leaf by leaf along a new leading axis."""
    first, spec = flatten_nest(ys[0])
    if spec.is_leaf():
        return ops.stack(ops.leaves(ys))
    if not first:
        return ys[0]
    columns = [[] for _ in first]
    for y in ys:
        leaves, spec_y = flatten_nest(y)
        if spec_y != spec:
            raise TypeError(
                f"ivy.scan: every step must output the same structure; got {spec} then {spec_y}."
            )
        for column, leaf in zip(columns, leaves):
            column.append(leaf)
    return unflatten_nest(spec, [ops.stack(ops.leaves(c)) for c in columns])


def _empty_outputs(ops: LoopOps, fn, init, xs_leaves, xs_spec):
    """Outputs of a scan of no steps: ``fn`` runs once on zeros to learn their structure,
    shapes and dtypes (as jax traces it), and every output gets a leading axis of size 0."""
    x = unflatten_nest(xs_spec, [ops.zeros(tuple(a.shape[1:]), a.dtype) for a in xs_leaves])
    _, y = fn(ops.arrays(init), x)
    leaves, spec = flatten_nest(y)
    leaves = ops.leaves(leaves)
    return unflatten_nest(spec, [ops.zeros((0, *tuple(v.shape)), v.dtype) for v in leaves])


def python_fori_loop(ops: LoopOps, lower, upper, body_fun, init_val):
    """:func:`fori_loop` as a Python loop (``i`` a Python int)."""
    val = ops.arrays(init_val)
    lower, upper = operator.index(lower), operator.index(upper)
    for i in range(lower, upper):
        new_val = body_fun(i, val)
        if i == lower:
            check_carry("fori_loop", init_val, new_val)
        val = new_val
    return val


def scalar_truth(name: str, pred) -> bool:
    """``bool(pred)`` for a scalar ``pred``; a clear error for arrays of more elements."""
    shape = tuple(getattr(pred, "shape", ()))
    if shape:
        raise ValueError(
            f"ivy.{name}: the predicate must be a scalar (shape ()), got shape {shape}; reduce "
            f"it with ivy.all or ivy.any."
        )
    return bool(pred)


def python_while_loop(ops: LoopOps, cond_fun, body_fun, init_val, maximum_iterations):
    """:func:`while_loop` as a Python loop."""
    val, steps = ops.arrays(init_val), 0
    limit = None if maximum_iterations is None else operator.index(maximum_iterations)
    while (limit is None or steps < limit) and scalar_truth("while_loop", cond_fun(val)):
        new_val = body_fun(val)
        if steps == 0:
            check_carry("while_loop", init_val, new_val)
        val, steps = new_val, steps + 1
    return val


def python_cond(pred, true_fun, false_fun, *operands):
    """:func:`cond` as a Python ``if``."""
    branch = true_fun if scalar_truth("cond", pred) else false_fun
    return branch(*operands)
