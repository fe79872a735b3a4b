"""torch backend: control flow (see ``ivy/core/control_flow.py``).

Eagerly: Python loops and a Python ``if``; inside ``torch.compile`` the Python loops unroll (the
body is traced once per step; a condition on values splits the graph at every test).

Loops declared ``pure=True`` are kept inside ``torch.compile`` as torch's higher-order operators
(``torch._higher_order_ops.scan``; ``while_loop``): the compiled graph holds the loop and traces
its body once, whatever the number of steps, as jax's and tensorflow's compilers do (measured:
a physics step of the Hopper, four stages each holding a solver's loop of data-dependent length,
313 s to compile unrolled). Random draws inside their bodies give fresh numbers at every call;
``scan`` differentiates. torch accepts no Python side effects in such bodies and no two of their
captured tensors sharing memory, hence the opt-in. The Python loop still runs where an operator
cannot serve: ``scan(..., unroll=True)``, a ``while_loop`` whose carry requires gradients
(torch's ``while_loop`` operator has no backward pass), loops of no steps. Outputs of a body are
copied before they leave it (the operators refuse outputs that alias their inputs); inductor
removes the copies it can.
"""

from __future__ import annotations

import torch
from torch._higher_order_ops.scan import scan as _scan_op
from torch._higher_order_ops.while_loop import while_loop as _while_op

from ivy.backends.torch.creation import asarray
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


def _unstack(a):
    return torch.unbind(a, 0)


def _zeros(shape, dtype):
    return torch.zeros(shape, dtype=dtype)


_OPS = LoopOps(
    unstack=_unstack, stack=torch.stack, zeros=_zeros, asarray=asarray, native=torch.Tensor
)


def _compiling() -> bool:
    return torch.compiler.is_compiling()


def _copies(leaves):
    return [leaf.clone() for leaf in leaves]


def scan(fn, init, xs=None, length=None, unroll=1, *, pure=False):
    if not pure or not _compiling() or unroll is True:
        return python_scan(_OPS, fn, init, xs, length, unroll)
    init = _OPS.arrays(init)
    init_leaves, _ = flatten_nest(init)
    xs_leaves, _ = flatten_nest(xs)
    n = scan_length(_OPS.leaves(xs_leaves), length)
    if n == 0 or not init_leaves:
        return python_scan(_OPS, fn, init, xs, length, unroll)
    # without inputs, the steps' indices stand in for them (the operator needs one)
    inputs = xs if xs_leaves else torch.arange(n, device=init_leaves[0].device)

    def combine(carry, x):
        new_carry, y = fn(carry, x if xs_leaves else xs)
        check_carry("scan", init, new_carry)
        return _copied(_OPS.arrays(new_carry)), _copied(y)

    return _scan_op(combine, _copied(init), inputs)


def _copied(nest):
    return torch.utils._pytree.tree_map(
        lambda a: a.clone() if isinstance(a, torch.Tensor) else a, nest
    )


def fori_loop(lower, upper, body_fun, init_val, *, pure=False):
    kept = pure and _compiling() and isinstance(lower, int) and isinstance(upper, int)
    if not kept:
        return python_fori_loop(_OPS, lower, upper, body_fun, init_val)

    def step(val, i):
        return body_fun(i, val), None

    if upper <= lower:
        return _OPS.arrays(init_val)
    first = flatten_nest(_OPS.arrays(init_val))[0]
    device = first[0].device if first else None
    val, _ = scan(step, init_val, torch.arange(lower, upper, device=device), pure=True)
    return val


def while_loop(cond_fun, body_fun, init_val, *, maximum_iterations=None, pure=False):
    init = _OPS.arrays(init_val)
    leaves, spec = flatten_nest(init)
    if not pure or not _compiling() or not leaves or any(leaf.requires_grad for leaf in leaves):
        return python_while_loop(_OPS, cond_fun, body_fun, init_val, maximum_iterations)
    counted = maximum_iterations is not None
    count = [torch.zeros((), dtype=torch.int64, device=leaves[0].device)] if counted else []

    def condition(*carry):
        go = cond_fun(unflatten_nest(spec, list(carry[: len(leaves)])))
        go = torch.as_tensor(go, device=leaves[0].device).reshape(())
        if counted:
            go = torch.logical_and(go, carry[-1] < maximum_iterations)
        return go

    def body(*carry):
        new = body_fun(unflatten_nest(spec, list(carry[: len(leaves)])))
        check_carry("while_loop", init_val, new)
        new_leaves, _ = flatten_nest(_OPS.arrays(new))
        return tuple(_copies(new_leaves) + ([carry[-1] + 1] if counted else []))

    out = _while_op(condition, body, tuple(_copies(leaves) + count))
    return unflatten_nest(spec, list(out[: len(leaves)]))


def cond(pred, true_fun, false_fun, *operands):
    return python_cond(pred, true_fun, false_fun, *operands)
