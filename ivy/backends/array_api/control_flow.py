"""Control flow for backends without a compiler of their own: Python loops and a Python ``if``
(see ``ivy/core/control_flow.py``), stacking with ``xp.stack``."""

from __future__ import annotations

from ivy.backends.array_api._unbound import array_types, backend_ns, xp
from ivy.core.control_flow import (
    LoopOps,
    python_cond,
    python_fori_loop,
    python_scan,
    python_while_loop,
)


def _ops():
    return LoopOps(
        unstack=lambda a: [a[i, ...] for i in range(a.shape[0])],
        stack=xp.stack,
        zeros=xp.zeros,
        asarray=backend_ns.asarray,
        native=array_types,
    )


def scan(fn, init, xs=None, length=None, unroll=1, *, pure=False):
    return python_scan(_ops(), fn, init, xs, length, unroll)


def fori_loop(lower, upper, body_fun, init_val, *, pure=False):
    return python_fori_loop(_ops(), lower, upper, body_fun, init_val)


def while_loop(cond_fun, body_fun, init_val, *, maximum_iterations=None, pure=False):
    return python_while_loop(_ops(), cond_fun, body_fun, init_val, maximum_iterations)


def cond(pred, true_fun, false_fun, *operands):
    return python_cond(pred, true_fun, false_fun, *operands)
