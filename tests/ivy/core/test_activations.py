"""Tests of the core group ``activations`` (``ivy/core/activations.py``), on every backend.

Activations against numpy float64 references, on every backend, in float32 and float64.

Inputs include values far in the tails (+-30, +-1000) where the naive formulas overflow, and NaN.

Gradients of the nn functions against central finite differences in float64, and compiled runs
against eager ones, on the differentiable backends.

Gradients are taken with each framework's own autodiff (``torch.autograd.grad``, ``jax.grad``,
``tf.GradientTape``) of ``sum(fn(*inputs) * weights)``, and compared along random directions
``v`` with ``(L(inputs + h v) - L(inputs - h v)) / 2h``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import ivy
from tests.conftest import require
from tests.helpers import (
    api,
    check,
    check_gradients,
    native,
    native_value_and_grads,
    numpy_of,
    reference,
)

FLOATS = ("float32", "float64")


TAILS = [-1000.0, -30.0, -3.0, -1.0, -0.5, -1e-3, 0.0, 1e-3, 0.5, 1.0, 3.0, 30.0, 1000.0]


def _inputs(dtype):
    rng = np.random.default_rng(7)
    return np.concatenate([TAILS, rng.uniform(-6, 6, 11)]).reshape(4, 6).astype(dtype)


_erf = np.vectorize(math.erf)


def _ref_sigmoid(x):
    return 1 / (1 + np.exp(-x))


def _ref_log_softmax(x, axis):
    m = x.max(axis=axis, keepdims=True)
    return x - m - np.log(np.exp(x - m).sum(axis=axis, keepdims=True))


REFERENCES = {
    "relu": (lambda x: np.maximum(x, 0), {}),
    "leaky_relu": (lambda x: np.where(x > 0, x, 0.2 * x), {}),
    "leaky_relu_alpha": (lambda x: np.where(x > 0, x, 0.01 * x), {"alpha": 0.01}),
    "gelu": (lambda x: 0.5 * x * (1 + _erf(x / math.sqrt(2))), {}),
    "gelu_tanh": (
        lambda x: 0.5 * x * (1 + np.tanh(math.sqrt(2 / math.pi) * (x + 0.044715 * x**3))),
        {"approximate": True},
    ),
    "sigmoid": (_ref_sigmoid, {}),
    "softplus": (lambda x: np.logaddexp(0, x), {}),
    "silu": (lambda x: x * _ref_sigmoid(x), {}),
    "elu": (lambda x: np.where(x > 0, x, np.expm1(x)), {}),
    "elu_alpha": (lambda x: np.where(x > 0, x, 0.5 * np.expm1(x)), {"alpha": 0.5}),
    "softmax": (lambda x: np.exp(_ref_log_softmax(x, -1)), {}),
    "softmax_axis0": (lambda x: np.exp(_ref_log_softmax(x, 0)), {"axis": 0}),
    "log_softmax": (lambda x: _ref_log_softmax(x, -1), {}),
    "log_softmax_axis0": (lambda x: _ref_log_softmax(x, 0), {"axis": 0}),
}


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize("case", sorted(REFERENCES))
def test_activation(backend, dtype, case):
    name = case.removesuffix("_alpha").removesuffix("_tanh").removesuffix("_axis0")
    ref, kwargs = REFERENCES[case]
    x = _inputs(dtype)
    expected = reference(ref, x.astype(np.float64)).astype(dtype)
    for fn in api(backend, name):
        check(fn(native(x, backend), **kwargs), expected, backend)


@pytest.mark.parametrize("case", sorted(REFERENCES))
def test_activation_keeps_float16(backend, case):
    """float16 in, float16 out (numpy's sigmoid and silu were float64: scipy's expit)."""
    require(backend, "float16")
    name = case.removesuffix("_alpha").removesuffix("_tanh").removesuffix("_axis0")
    ref, kwargs = REFERENCES[case]
    x = np.linspace(-6, 6, 12).reshape(3, 4).astype("float16")
    expected = reference(ref, x.astype(np.float64)).astype("float16")
    for fn in api(backend, name):
        check(fn(native(x, backend), **kwargs), expected, backend, rtol=4e-3, atol=4e-3)


@pytest.mark.parametrize("name", ["softmax", "log_softmax"])
@pytest.mark.parametrize("shape, axis", [((0,), -1), ((2, 0), -1), ((0, 3), 0), ((0, 3), -1)])
def test_softmax_of_an_empty_axis_is_empty(backend, name, shape, axis):
    """(numpy raised: the max of an empty row)"""
    for fn in api(backend, name):
        check(
            fn(native(np.zeros(shape, "float32"), backend), axis=axis),
            np.zeros(shape, "float32"),
            backend,
        )


@pytest.mark.parametrize(
    "name", ["relu", "leaky_relu", "gelu", "sigmoid", "softplus", "silu", "elu", "softmax"]
)
def test_activation_keeps_nan(backend, name):
    x = native(np.array([np.nan, 1.0], np.float32), backend)
    out = numpy_of(getattr(ivy, name)(x))
    assert np.isnan(out[0]) and (name == "softmax" or np.isfinite(out[1]))


def test_positional_parameters(backend):
    """``alpha``, ``approximate`` and ``axis`` may be given by position."""
    x = np.array([[-1.0, 2.0], [0.5, -3.0]])
    nx = native(x, backend)
    check(ivy.leaky_relu(nx, 0.1), np.where(x > 0, x, 0.1 * x), backend)
    check(ivy.elu(nx, 2.0), np.where(x > 0, x, 2 * np.expm1(x)), backend)
    check(ivy.softmax(nx, 0), np.exp(_ref_log_softmax(x, 0)), backend)
    check(ivy.gelu(nx, True), REFERENCES["gelu_tanh"][0](x), backend)


def test_softmax_of_a_masked_slice(backend):
    """-inf logits get probability 0 (as long as one logit in the slice is finite)."""
    x = native(np.array([[-np.inf, 0.0, 0.0], [1.0, -np.inf, 1.0]]), backend)
    check(ivy.softmax(x), np.array([[0, 0.5, 0.5], [0.5, 0, 0.5]]), backend)
    check(
        ivy.log_softmax(x),
        np.array([[-np.inf, -math.log(2), -math.log(2)], [-math.log(2), -np.inf, -math.log(2)]]),
        backend,
    )


def _random(shape, seed, scale=1.0):
    return scale * np.random.default_rng(60 + seed).standard_normal(shape)


@pytest.mark.parametrize(
    "name", ["sigmoid", "softplus", "silu", "elu", "gelu", "leaky_relu", "softmax", "log_softmax"]
)
def test_activation_gradients(diff_backend, name):
    check_gradients(diff_backend, getattr(ivy, name), [_random((3, 5), 1, 3.0)])


# Exact derivatives at 0 and in the tails, where naive forms give NaN (0 * inf).
TAIL_DERIVATIVES = {
    "relu": [0.0, 0.0, 1.0],
    "sigmoid": [0.0, 0.25, 0.0],
    "softplus": [0.0, 0.5, 1.0],
    "silu": [0.0, 0.5, 1.0],
    "elu": [0.0, 1.0, 1.0],
}


@pytest.mark.parametrize("name", sorted(TAIL_DERIVATIVES))
def test_activation_derivatives_at_zero_and_in_the_tails(diff_backend, name):
    x = np.array([-1000.0, 0.0, 1000.0])
    fn = getattr(ivy, name)
    value, (grad,) = native_value_and_grads(diff_backend, fn, [x], np.ones(3))
    assert np.isfinite(value)
    np.testing.assert_allclose(grad, TAIL_DERIVATIVES[name], atol=1e-12)


def test_softmax_of_rows_with_nan_or_infinities(backend, xp):
    """``exp(x - max)`` in IEEE arithmetic, on every backend: a row holding NaN or +inf is NaN
    throughout (inf - inf is NaN), a row of -inf only is NaN, -inf among numbers gives 0."""
    inf, nan = math.inf, math.nan
    rows = [[inf, 1.0, 2.0], [-inf, 1.0, 2.0], [inf, inf, 0.0], [-inf, -inf, -inf], [nan, 1.0, 0.0]]
    x = np.array(rows, np.float64)
    with np.errstate(invalid="ignore"):
        shifted = x - x.max(axis=1, keepdims=True)
        e = np.exp(shifted)
        expected = e / e.sum(axis=1, keepdims=True)
    assert np.isnan(expected[[0, 2, 3, 4]]).all() and not np.isnan(expected[1]).any()
    for dtype in ("float32", "float64"):
        out = xp.softmax(native(x.astype(dtype), backend), axis=-1)
        check(out, expected.astype(dtype), backend)
        out = ivy.softmax(native(x.T.astype(dtype), backend), axis=0)
        check(out, expected.T.astype(dtype), backend)
