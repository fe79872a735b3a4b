"""torch backend: control flow as Python loops and a Python ``if`` (see
``ivy/core/control_flow.py``).

Under ``torch.compile`` the loops unroll into one graph (compilation time grows with the number
of steps); a branch on a tensor's value splits the graph there. torch's own ``scan``,
``while_loop`` and ``cond`` operators are prototypes in torch 2.13, so they are not used.
"""

from __future__ import annotations

import torch

from ivy.backends.torch.creation import asarray
from ivy.core.control_flow import (
    LoopOps,
    python_cond,
    python_fori_loop,
    python_scan,
    python_while_loop,
)

__all__ = ["scan", "fori_loop", "while_loop", "cond"]


def _unstack(a):
    return torch.unbind(a, 0)


def _zeros(shape, dtype):
    return torch.zeros(shape, dtype=dtype)


_OPS = LoopOps(
    unstack=_unstack, stack=torch.stack, zeros=_zeros, asarray=asarray, native=torch.Tensor
)


def scan(fn, init, xs=None, length=None, unroll=1):
    return python_scan(_OPS, fn, init, xs, length, unroll)


def fori_loop(lower, upper, body_fun, init_val):
    return python_fori_loop(_OPS, lower, upper, body_fun, init_val)


def while_loop(cond_fun, body_fun, init_val, *, maximum_iterations=None):
    return python_while_loop(_OPS, cond_fun, body_fun, init_val, maximum_iterations)


def cond(pred, true_fun, false_fun, *operands):
    return python_cond(pred, true_fun, false_fun, *operands)
