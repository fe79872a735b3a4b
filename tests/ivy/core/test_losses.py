"""Tests of the core group ``losses`` (``ivy/core/losses.py``), on every backend.

Gradients of the nn functions against central finite differences in float64, and compiled runs
against eager ones, on the differentiable backends.

Gradients are taken with each framework's own autodiff (``torch.autograd.grad``, ``jax.grad``,
``tf.GradientTape``) of ``sum(fn(*inputs) * weights)``, and compared along random directions
``v`` with ``(L(inputs + h v) - L(inputs - h v)) / 2h``.

Losses against numpy float64 references, on every backend, in float32 and float64.
"""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import (
    api,
    check,
    check_gradients,
    native,
    native_value_and_grads,
    tolerance,
)


def _random(shape, seed, scale=1.0):
    return scale * np.random.default_rng(60 + seed).standard_normal(shape)


LOSS_CASES = {
    "mse": lambda p, t: ivy.mse(p, t),
    "huber": lambda p, t: ivy.huber(p, t, delta=0.7, reduction="sum"),
    "bce-probabilities": lambda p, t: ivy.binary_cross_entropy(
        ivy.sigmoid(p), ivy.sigmoid(t), reduction="none"
    ),
    "bce-logits": lambda p, t: ivy.binary_cross_entropy(p, ivy.sigmoid(t), from_logits=True),
    "cce-logits": lambda p, t: ivy.categorical_cross_entropy(p, ivy.softmax(t), from_logits=True),
    "cce-probabilities": lambda p, t: ivy.categorical_cross_entropy(
        ivy.softmax(p, axis=0), ivy.softmax(t, axis=0), axis=0, reduction="none"
    ),
}


@pytest.mark.parametrize("case", sorted(LOSS_CASES))
def test_loss_gradients(diff_backend, case):
    check_gradients(
        diff_backend, LOSS_CASES[case], [_random((3, 4), 1, 2.0), _random((3, 4), 2, 2.0)]
    )


def test_cross_entropy_gradients_from_extreme_logits(diff_backend):
    z = np.array([[-1000.0, 0.0, 1000.0]])
    t = np.array([[1.0, 0.0, 0.0]])

    def bce(z):
        return ivy.binary_cross_entropy(
            z, native(t, diff_backend), from_logits=True, reduction="sum"
        )

    def cce(z):
        return ivy.categorical_cross_entropy(z, native(t, diff_backend), from_logits=True)

    _, (g,) = native_value_and_grads(diff_backend, bce, [z], np.ones(()))
    np.testing.assert_allclose(g, [[-1.0, 0.5, 1.0]], atol=1e-12)
    _, (g,) = native_value_and_grads(diff_backend, cce, [z], np.ones(()))
    np.testing.assert_allclose(g, [[-1.0, 0.0, 1.0]], atol=1e-12)


FLOATS = ("float32", "float64")


REDUCTIONS = ("mean", "sum", "none")


def _reduce(loss, reduction):
    return {"mean": np.mean, "sum": np.sum, "none": lambda a: a}[reduction](loss)


def _pair(dtype, seed=0, shape=(4, 5)):
    rng = np.random.default_rng(20 + seed)
    return rng.normal(0, 2, shape).astype(dtype), rng.normal(0, 2, shape).astype(dtype)


def _expected(value, dtype):
    return np.asarray(value).astype(dtype)


@pytest.mark.parametrize("reduction", REDUCTIONS)
@pytest.mark.parametrize("dtype", FLOATS)
def test_mse(backend, dtype, reduction):
    pred, target = _pair(dtype)
    d = pred.astype(np.float64) - target
    for fn in api(backend, "mse"):
        out = fn(native(pred, backend), native(target, backend), reduction=reduction)
        check(out, _expected(_reduce(d**2, reduction), dtype), backend, **tolerance(dtype, 10))


@pytest.mark.parametrize("reduction", REDUCTIONS)
@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize("delta", [1.0, 0.5])
def test_huber(backend, dtype, reduction, delta):
    pred, target = _pair(dtype, 1)
    d = pred.astype(np.float64) - target
    loss = np.where(np.abs(d) <= delta, 0.5 * d**2, delta * (np.abs(d) - 0.5 * delta))
    out = ivy.huber(
        native(pred, backend), native(target, backend), delta=delta, reduction=reduction
    )
    check(out, _expected(_reduce(loss, reduction), dtype), backend, **tolerance(dtype, 10))


@pytest.mark.parametrize("reduction", REDUCTIONS)
@pytest.mark.parametrize("dtype", FLOATS)
def test_binary_cross_entropy_from_probabilities(backend, dtype, reduction):
    rng = np.random.default_rng(3)
    p = rng.uniform(0.01, 0.99, (4, 5))
    p[0, :2] = [0.0, 1.0]  # clipped to [eps, 1 - eps]
    t = rng.uniform(0, 1, (4, 5))
    t[1] = rng.integers(0, 2, 5)  # hard labels too
    p, t = p.astype(dtype), t.astype(dtype)
    pc = np.clip(p.astype(np.float64), 1e-7, 1 - 1e-7)
    if dtype == "float32":  # the bounds as float32 represents them
        pc = np.clip(p.astype(np.float64), np.float32(1e-7), np.float32(1 - 1e-7))
    loss = -(t * np.log(pc) + (1 - t.astype(np.float64)) * np.log1p(-pc))
    for fn in api(backend, "binary_cross_entropy"):
        out = fn(native(p, backend), native(t, backend), reduction=reduction)
        check(out, _expected(_reduce(loss, reduction), dtype), backend, **tolerance(dtype, 10))


@pytest.mark.parametrize("reduction", REDUCTIONS)
@pytest.mark.parametrize("dtype", FLOATS)
def test_binary_cross_entropy_from_logits(backend, dtype, reduction):
    z, _ = _pair(dtype, 2)
    z[0, :4] = [-1000, -40, 40, 1000]  # the naive form overflows here
    t = np.random.default_rng(4).uniform(0, 1, z.shape).astype(dtype)
    t[0, :4] = [0, 1, 0, 1]
    z64 = z.astype(np.float64)
    loss = np.logaddexp(0, z64) - z64 * t
    out = ivy.binary_cross_entropy(
        native(z, backend), native(t, backend), from_logits=True, reduction=reduction
    )
    check(out, _expected(_reduce(loss, reduction), dtype), backend, **tolerance(dtype, 100))


def _one_hot(labels, n, dtype):
    return np.eye(n, dtype=dtype)[labels]


@pytest.mark.parametrize("reduction", REDUCTIONS)
@pytest.mark.parametrize("dtype", FLOATS)
def test_categorical_cross_entropy(backend, dtype, reduction):
    rng = np.random.default_rng(5)
    logits = rng.normal(0, 3, (2, 3, 4)).astype(dtype)
    logits[0, 0] = [1000, -1000, 0, 3]  # extreme logits
    t = _one_hot(rng.integers(0, 4, (2, 3)), 4, dtype)
    t[1, 2] = [0.1, 0.2, 0.3, 0.4]  # a probability target
    z = logits.astype(np.float64)
    m = z.max(-1, keepdims=True)
    log_p = z - m - np.log(np.exp(z - m).sum(-1, keepdims=True))
    expected = _reduce(-(t * log_p).sum(-1), reduction)
    for fn in api(backend, "categorical_cross_entropy"):
        out = fn(native(logits, backend), native(t, backend), from_logits=True, reduction=reduction)
        check(out, _expected(expected, dtype), backend, **tolerance(dtype, 100))
    # from probabilities, over another axis
    p = np.exp(log_p).astype(dtype)
    p_axis0 = np.moveaxis(p, -1, 0)
    t_axis0 = np.moveaxis(t, -1, 0)
    pc = np.clip(p.astype(np.float64), np.float64(np.asarray(1e-7, dtype)), 1)
    expected = _reduce(-(t * np.log(pc)).sum(-1), reduction)
    out = ivy.categorical_cross_entropy(
        native(p_axis0, backend), native(t_axis0, backend), axis=0, reduction=reduction
    )
    check(out, _expected(expected, dtype), backend, **tolerance(dtype, 100))


def test_bad_reduction(backend):
    x = native(np.ones(3), backend)
    for name in ("mse", "huber", "binary_cross_entropy", "categorical_cross_entropy"):
        with pytest.raises(
            ValueError, match="unknown reduction 'avg'; use 'mean', 'sum' or 'none'"
        ):
            getattr(ivy, name)(x, x, reduction="avg")
    with pytest.raises(ValueError, match="delta must be positive"):
        ivy.huber(x, x, delta=0.0)
