"""numpy backend: random numbers from one module-level ``numpy.random.Generator``."""

from __future__ import annotations

import numpy as np

from ivy.backends.numpy._helpers import check_device, native_dtype

__all__ = ["seed", "random_uniform", "random_normal", "randint", "shuffle"]

_rng = [np.random.default_rng()]


def seed(seed_value=0):
    _rng[0] = np.random.default_rng(seed_value)


def random_uniform(low=0.0, high=1.0, shape=None, *, dtype=None, device=None):
    check_device(device)
    out = _rng[0].uniform(low, high, size=shape)
    return np.asarray(out, dtype=native_dtype(dtype) or np.float32)


def random_normal(mean=0.0, std=1.0, shape=None, *, dtype=None, device=None):
    check_device(device)
    out = _rng[0].normal(mean, std, size=shape)
    return np.asarray(out, dtype=native_dtype(dtype) or np.float32)


def randint(low, high, shape=None, *, dtype=None, device=None):
    check_device(device)
    out = _rng[0].integers(low, high, size=shape)
    return np.asarray(out, dtype=native_dtype(dtype) or np.int64)


def shuffle(x, /):
    return _rng[0].permutation(x)
