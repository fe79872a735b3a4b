"""tensorflow backend: control flow as Python loops eagerly, ``tf.while_loop`` and ``tf.cond``
inside graphs.

Eagerly, ``tf.while_loop`` and ``tf.cond`` run their bodies in Python anyway; the Python loops of
``ivy/core/control_flow.py`` do the same with less overhead. Inside a graph (``ivy.compile_fn``,
``tf.function``, where AutoGraph is off):

- ``scan`` runs its first step in Python, which gives the structure, shapes and dtypes of the
  outputs, then the other steps in a ``tf.while_loop`` that writes them to ``TensorArray`` s
  (``unroll`` steps per iteration);
- ``fori_loop`` and ``while_loop`` are ``tf.while_loop`` s over the flattened carry (``i`` is an
  int64 scalar tensor);
- ``cond`` is ``tf.cond`` over the flattened outputs of the branches.

Gradients flow through all of them (``tf.GradientTape``, eager or in a graph).
"""

from __future__ import annotations

import operator

import tensorflow as tf

from ivy.backends.tensorflow.creation import asarray
from ivy.core.control_flow import (
    LoopOps,
    check_carry,
    python_cond,
    python_fori_loop,
    python_scan,
    python_while_loop,
    scan_length,
)
from ivy.nest import flatten_nest, unflatten_nest


def _zeros(shape, dtype):
    return tf.zeros(shape, dtype=dtype)


def _asarray(a):
    return a if isinstance(a, (tf.Tensor, tf.Variable)) else asarray(a)


_OPS = LoopOps(
    unstack=tf.unstack,
    stack=tf.stack,
    zeros=_zeros,
    asarray=_asarray,
    native=(tf.Tensor, tf.Variable),
)


def _tensors(nest):
    """The leaves of ``nest`` as tensors, and its structure."""
    leaves, spec = flatten_nest(nest)
    return [_asarray(a) for a in leaves], spec


def scan(fn, init, xs=None, length=None, unroll=1, *, pure=False):
    if tf.executing_eagerly():
        return python_scan(_OPS, fn, init, xs, length, unroll)
    xs_leaves, xs_spec = _tensors(xs)
    n = scan_length(xs_leaves, length)
    if n is None:  # an unknown leading axis: read it when the graph runs
        n = length if length is not None else tf.shape(xs_leaves[0])[0]
    if isinstance(n, int) and n == 0:
        return python_scan(_OPS, fn, init, xs, 0, unroll)

    def x_at(t):
        return unflatten_nest(xs_spec, [a[t] for a in xs_leaves])

    # The first step, in Python: it fixes the outputs' structure, shapes and dtypes.
    carry, y = fn(init, x_at(0))
    check_carry("scan", init, carry)
    carry_leaves, carry_spec = _tensors(carry)
    y_leaves, y_spec = _tensors(y)
    arrays = [tf.TensorArray(v.dtype, size=n, element_shape=v.shape).write(0, v) for v in y_leaves]

    def steps(t, carry_leaves, arrays, count):
        """``count`` steps from step ``t``."""
        carry = unflatten_nest(carry_spec, carry_leaves)
        for k in range(count):
            carry, y = fn(carry, x_at(t + k))
            arrays = [ta.write(t + k, v) for ta, v in zip(arrays, _tensors(y)[0])]
        return _tensors(carry)[0], arrays

    # The other n - 1 steps: `per_iteration` steps in each iteration of a tf.while_loop, and
    # the `rest` unrolled after it (all of them unrolled with unroll=True).
    if not isinstance(n, int):
        per_iteration, iterations, rest = 1, n - 1, 0
    elif unroll is True:
        per_iteration, iterations, rest = 1, 0, n - 1
    else:
        per_iteration = max(operator.index(unroll), 1)
        iterations, rest = divmod(n - 1, per_iteration)
    t = tf.constant(1, tf.int32)
    if not (isinstance(iterations, int) and iterations == 0):
        stop = 1 + iterations * per_iteration

        def body(t, carry_leaves, arrays):
            carry_leaves, arrays = steps(t, carry_leaves, arrays, per_iteration)
            return t + per_iteration, carry_leaves, arrays

        t, carry_leaves, arrays = tf.while_loop(
            lambda t, *_: t < stop,
            body,
            (t, carry_leaves, arrays),
            maximum_iterations=iterations,
        )
    if rest:
        carry_leaves, arrays = steps(t, carry_leaves, arrays, rest)
    carry = unflatten_nest(carry_spec, carry_leaves)
    return carry, unflatten_nest(y_spec, [ta.stack() for ta in arrays])


def fori_loop(lower, upper, body_fun, init_val, *, pure=False):
    if tf.executing_eagerly():
        return python_fori_loop(_OPS, lower, upper, body_fun, init_val)
    leaves, spec = _tensors(init_val)
    lower = tf.cast(lower, tf.int64)
    upper = tf.cast(upper, tf.int64)
    checked = []

    def body(i, leaves):
        val = unflatten_nest(spec, leaves)
        new_val = body_fun(i, val)
        if not checked:
            check_carry("fori_loop", val, new_val)
            checked.append(True)
        return i + 1, _tensors(new_val)[0]

    _, leaves = tf.while_loop(
        lambda i, _: i < upper,
        body,
        (lower, leaves),
        maximum_iterations=tf.cast(tf.maximum(upper - lower, 0), tf.int32),
    )
    return unflatten_nest(spec, leaves)


def while_loop(cond_fun, body_fun, init_val, *, maximum_iterations=None, pure=False):
    if tf.executing_eagerly():
        return python_while_loop(_OPS, cond_fun, body_fun, init_val, maximum_iterations)
    leaves, spec = _tensors(init_val)
    checked = []

    def keep_going(*leaves):
        pred = _asarray(cond_fun(unflatten_nest(spec, list(leaves))))
        return _scalar_bool("while_loop", pred)

    def body(*leaves):
        val = unflatten_nest(spec, list(leaves))
        new_val = body_fun(val)
        if not checked:
            check_carry("while_loop", val, new_val)
            checked.append(True)
        return _tensors(new_val)[0]

    if not leaves:
        raise ValueError("ivy.while_loop: init_val must hold at least one array.")
    leaves = tf.while_loop(keep_going, body, leaves, maximum_iterations=maximum_iterations)
    return unflatten_nest(spec, list(leaves))


def _scalar_bool(name, pred):
    if pred.shape.rank != 0:
        raise ValueError(
            f"ivy.{name}: the predicate must be a scalar (shape ()), got shape "
            f"{tuple(pred.shape)}; reduce it with ivy.all or ivy.any."
        )
    return pred if pred.dtype == tf.bool else tf.not_equal(pred, tf.zeros((), pred.dtype))


def cond(pred, true_fun, false_fun, *operands):
    if tf.executing_eagerly() or not isinstance(pred, (tf.Tensor, tf.Variable)):
        return python_cond(pred, true_fun, false_fun, *operands)
    specs = {}

    def branch(name, fn):
        def run():
            leaves, specs[name] = _tensors(fn(*operands))
            if len(specs) == 2 and specs["true"] != specs["false"]:
                raise TypeError(
                    f"ivy.cond: both branches must return the same structure (as jax and "
                    f"tensorflow require); true_fun gave {specs['true']}, false_fun gave "
                    f"{specs['false']}."
                )
            return leaves

        return run

    leaves = tf.cond(
        _scalar_bool("cond", pred), branch("true", true_fun), branch("false", false_fun)
    )
    return unflatten_nest(specs["true"], list(leaves) if leaves is not None else [])
