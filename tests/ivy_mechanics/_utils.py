"""Calling ivy_mechanics on a backend from numpy inputs, and each framework's own autodiff."""

from __future__ import annotations

import numpy as np

import ivy_mechanics as mech
from tests.helpers import native, native_value_and_grads, numpy_of


def call(backend, name, args, kwargs=None):
    """``mech.<name>`` on ``backend`` arrays made from the numpy ``args``; result as numpy."""
    out = getattr(mech, name)(*[native(a, backend) for a in args], **(kwargs or {}))
    return numpy_of(out)


def gradients(backend, fn, args, weights):
    """Gradients of ``sum(weights * fn(*args))`` with respect to each of ``args``, by the
    framework's own autodiff (``tests/helpers.py``), eagerly (each function is small and called
    once per input set: a jitted program per function and shape took five times as long on
    jax); float64 numpy in and out."""
    return native_value_and_grads(backend, fn, args, weights, jit=False)[1]


def finite_difference(fn, args, weights, wrt=0, h=1e-7):
    """Central differences of ``sum(weights * fn(*args))`` (numpy float64), perturbing one
    component of every batch item at once (items are independent)."""
    x = args[wrt]
    g = np.zeros_like(x)
    for index in np.ndindex(x.shape[1:]):
        step = np.zeros_like(x)
        step[(slice(None), *index)] = h
        plus = fn(*args[:wrt], x + step, *args[wrt + 1 :])
        minus = fn(*args[:wrt], x - step, *args[wrt + 1 :])
        diff = (plus - minus) * weights
        g[(slice(None), *index)] = diff.reshape(len(x), -1).sum(-1) / (2 * h)
    return g
