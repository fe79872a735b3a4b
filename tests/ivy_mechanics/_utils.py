"""Calling ivy_mechanics on a backend from numpy inputs, and each framework's own autodiff."""

from __future__ import annotations

import numpy as np

import ivy_mechanics as mech
from tests.helpers import native, numpy_of


def call(backend, name, args, kwargs=None):
    """``mech.<name>`` on ``backend`` arrays made from the numpy ``args``; result as numpy."""
    out = getattr(mech, name)(*[native(a, backend) for a in args], **(kwargs or {}))
    return numpy_of(out)


def grad(backend, fn, args, weights, wrt=0):
    """Gradient of ``sum(weights * fn(*args))`` with respect to ``args[wrt]``, by the framework's
    own autodiff (torch.autograd.grad, jax.grad, tf.GradientTape); float64 numpy in and out."""
    if backend == "torch":
        import torch

        ts = [torch.tensor(a, requires_grad=(i == wrt)) for i, a in enumerate(args)]
        loss = (fn(*ts) * torch.from_numpy(weights)).sum()
        (g,) = torch.autograd.grad(loss, ts[wrt])
        return g.numpy()
    if backend == "jax":
        import jax
        import jax.numpy as jnp

        arrays = [jnp.asarray(a) for a in args]

        def loss(x):
            return jnp.sum(fn(*arrays[:wrt], x, *arrays[wrt + 1 :]) * weights)

        return np.asarray(jax.grad(loss)(arrays[wrt]))
    if backend == "tensorflow":
        import tensorflow as tf

        ts = [tf.constant(a) for a in args]
        with tf.GradientTape() as tape:
            tape.watch(ts[wrt])
            loss = tf.reduce_sum(fn(*ts) * tf.constant(weights))
        return tape.gradient(loss, ts[wrt]).numpy()
    raise ValueError(f"{backend} has no autodiff")


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
