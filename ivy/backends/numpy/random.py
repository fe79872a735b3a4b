"""numpy backend: random numbers from one module-level ``numpy.random.Generator``."""

from __future__ import annotations

import numpy as np

from ivy.backends._sample_args import categorical_args, check_draw_bounds, floating_draw
from ivy.backends.numpy._helpers import check_device, native_dtype

_rng = [np.random.default_rng()]


def _floating_draw(function: str, dtype) -> None:
    if dtype is not None:
        floating_draw(function, "numpy", dtype, np.dtype(native_dtype(dtype)).kind in "fc")


def seed(seed_value=0):
    _rng[0] = np.random.default_rng(seed_value)


def random_uniform(low=0.0, high=1.0, shape=None, *, dtype=None, device=None):
    check_device(device)
    _floating_draw("random_uniform", dtype)
    check_draw_bounds("random_uniform", low, high, "numpy")
    out = _rng[0].uniform(low, high, size=shape)
    return np.asarray(out, dtype=native_dtype(dtype) or np.float32)


def random_normal(mean=0.0, std=1.0, shape=None, *, dtype=None, device=None):
    check_device(device)
    _floating_draw("random_normal", dtype)
    check_draw_bounds("random_normal", mean, std, "numpy")
    out = _rng[0].normal(mean, std, size=shape)
    return np.asarray(out, dtype=native_dtype(dtype) or np.float32)


def randint(low, high, shape=None, *, dtype=None, device=None):
    check_device(device)
    check_draw_bounds("randint", low, high, "numpy")
    out = _rng[0].integers(low, high, size=shape)
    return np.asarray(out, dtype=native_dtype(dtype) or np.int64)


def shuffle(x, /):
    return _rng[0].permutation(x)


def random_categorical(logits, /, *, num_samples=1, dtype=None):
    """The Gumbel-max trick: the index of the largest ``logit + Gumbel noise``."""
    logits = np.asarray(logits)
    n = categorical_args(logits.shape, num_samples)
    noise = _rng[0].gumbel(size=(*logits.shape[:-1], num_samples, n))
    out = np.argmax(logits[..., None, :] + noise, axis=-1)
    return out.astype(native_dtype(dtype) or np.int64)
