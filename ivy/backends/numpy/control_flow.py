"""numpy backend: control flow as Python loops and a Python ``if`` (see ``ivy/core/control_flow.py``)."""

from __future__ import annotations

import numpy as np

from ivy.backends.numpy.creation import asarray
from ivy.core.control_flow import (
    LoopOps,
    python_cond,
    python_fori_loop,
    python_scan,
    python_while_loop,
)

__all__ = ["scan", "fori_loop", "while_loop", "cond"]

_OPS = LoopOps(
    unstack=list, stack=np.stack, zeros=np.zeros, asarray=asarray, native=(np.ndarray, np.generic)
)


def scan(fn, init, xs=None, length=None, unroll=1):
    return python_scan(_OPS, fn, init, xs, length, unroll)


def fori_loop(lower, upper, body_fun, init_val):
    return python_fori_loop(_OPS, lower, upper, body_fun, init_val)


def while_loop(cond_fun, body_fun, init_val, *, maximum_iterations=None):
    return python_while_loop(_OPS, cond_fun, body_fun, init_val, maximum_iterations)


def cond(pred, true_fun, false_fun, *operands):
    return python_cond(pred, true_fun, false_fun, *operands)
