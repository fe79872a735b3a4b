"""Tests of the core group ``layers`` (``ivy/core/layers.py``), on every backend.

Gradients of the nn functions against central finite differences in float64, and compiled runs
against eager ones, on the differentiable backends.

Gradients are taken with each framework's own autodiff (``torch.autograd.grad``, ``jax.grad``,
``tf.GradientTape``) of ``sum(fn(*inputs) * weights)``, and compared along random directions
``v`` with ``(L(inputs + h v) - L(inputs - h v)) / 2h``.

linear, layer_norm, scaled_dot_product_attention, lstm_update and dropout against numpy
float64 references, on every backend, in float32 and float64.
"""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import (
    api,
    check,
    check_gradients,
    check_meta,
    dtype_name,
    native,
    numpy_of,
    tolerance,
)


def _random(shape, seed, scale=1.0):
    return scale * np.random.default_rng(60 + seed).standard_normal(shape)


def _lstm_outputs(x, h, c, kernel, recurrent, bias, recurrent_bias):
    hs, (_, c_last) = ivy.lstm_update(x, h, c, kernel, recurrent, bias, recurrent_bias)
    return ivy.concat([ivy.reshape(hs, (-1,)), ivy.reshape(c_last, (-1,))])


def test_lstm_update_gradients(diff_backend):
    shapes = [(2, 3, 3), (2, 4), (2, 4), (3, 16), (4, 16), (16,), (16,)]
    arrays = [_random(s, i, 0.7) for i, s in enumerate(shapes)]
    check_gradients(diff_backend, _lstm_outputs, arrays, n_directions=2)


def test_layer_norm_gradients(diff_backend):
    def fn(x, scale, offset):
        return ivy.layer_norm(x, (1, 2), scale=scale, offset=offset)

    check_gradients(
        diff_backend, fn, [_random((3, 2, 4), 1, 2.0), _random((2, 4), 2), _random((4,), 3)]
    )


def test_linear_gradients(diff_backend):
    check_gradients(
        diff_backend, ivy.linear, [_random((2, 3), 1), _random((4, 3), 2), _random((4,), 3)]
    )


FLOATS = ("float32", "float64")


def _random_nn_layers(shape, dtype, seed, scale=1.0):
    return (scale * np.random.default_rng(40 + seed).standard_normal(shape)).astype(dtype)


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize("x_shape", [(3,), (2, 3), (4, 2, 3)], ids=str)
@pytest.mark.parametrize("with_bias", [True, False])
def test_linear(backend, dtype, x_shape, with_bias):
    x, w, b = (
        _random_nn_layers(x_shape, dtype, 1),
        _random_nn_layers((5, 3), dtype, 2),
        _random_nn_layers((5,), dtype, 3),
    )
    expected = x.astype(np.float64) @ w.T.astype(np.float64) + (b if with_bias else 0)
    args = (native(b, backend),) if with_bias else ()
    for fn in api(backend, "linear"):
        out = fn(native(x, backend), native(w, backend), *args)
        check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


def test_linear_errors(backend):
    with pytest.raises(ValueError, match=r"weight must be \[out, in\]"):
        ivy.linear(native(np.ones((2, 3)), backend), native(np.ones((3, 5)), backend))
    with pytest.raises(ValueError, match=r"weight must be \[out, in\]"):
        ivy.linear(native(np.ones((2, 3)), backend), native(np.ones((3,)), backend))


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize(
    ("axes", "affine_shape"), [(-1, (6,)), ((1, 2), (4, 6)), (0, None)], ids=str
)
def test_layer_norm(backend, dtype, axes, affine_shape):
    x = _random_nn_layers((3, 4, 6), dtype, 4, scale=3.0) + 5
    x64 = x.astype(np.float64)
    mean = x64.mean(axis=axes, keepdims=True)
    var = ((x64 - mean) ** 2).mean(axis=axes, keepdims=True)
    expected = (x64 - mean) / np.sqrt(var + 1e-5)
    kwargs = {}
    if affine_shape is not None:
        scale, offset = (
            _random_nn_layers(affine_shape, dtype, 5),
            _random_nn_layers(affine_shape, dtype, 6),
        )
        expected = expected * scale + offset
        kwargs = dict(scale=native(scale, backend), offset=native(offset, backend))
    for fn in api(backend, "layer_norm"):
        out = fn(native(x, backend), axes, **kwargs)
        check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


def test_layer_norm_eps(backend):
    x = np.array([[1.0, 1.0, 1.0], [0.0, 1.0, 2.0]])
    var = np.array([[0.0], [2 / 3]])
    expected = (x - x.mean(-1, keepdims=True)) / np.sqrt(var + 0.1)
    check(ivy.layer_norm(native(x, backend), eps=0.1), expected, backend)


def _ref_attention(q, k, v, mask=None, scale=None):
    q, k, v = (a.astype(np.float64) for a in (q, k, v))
    scale = 1 / np.sqrt(q.shape[-1]) if scale is None else scale
    s = q @ np.swapaxes(k, -1, -2) * scale
    if mask is not None:
        s = np.where(mask, s, -np.inf) if mask.dtype == bool else s + mask
    e = np.exp(s - s.max(-1, keepdims=True))
    return (e / e.sum(-1, keepdims=True)) @ v


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize("mask_kind", [None, "bool", "float"])
def test_attention(backend, dtype, mask_kind):
    q, k, v = (
        _random_nn_layers((2, 3, 4, 5), dtype, 7),
        _random_nn_layers((2, 3, 6, 5), dtype, 8),
        _random_nn_layers((2, 3, 6, 2), dtype, 9),
    )
    mask = None
    if mask_kind == "bool":  # causal-like, broadcast over batch and heads; every row attends
        mask = np.tril(np.ones((4, 6), bool), k=1)
    elif mask_kind == "float":
        mask = _random_nn_layers((3, 4, 6), dtype, 10)
    expected = _ref_attention(q, k, v, mask)
    kwargs = {} if mask is None else {"mask": native(mask, backend)}
    for fn in api(backend, "scaled_dot_product_attention"):
        out = fn(native(q, backend), native(k, backend), native(v, backend), **kwargs)
        check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


def test_attention_scale_and_errors(backend):
    q, k, v = (
        _random_nn_layers((3, 4), "float64", 11),
        _random_nn_layers((5, 4), "float64", 12),
        _random_nn_layers((5, 2), "float64", 13),
    )
    out = ivy.scaled_dot_product_attention(
        native(q, backend), native(k, backend), native(v, backend), scale=0.3
    )
    check(out, _ref_attention(q, k, v, scale=0.3), backend)
    with pytest.raises(ValueError, match=r"q \[\.\.\., Lq, d\], k \[\.\.\., Lk, d\]"):
        ivy.scaled_dot_product_attention(native(q, backend), native(v, backend), native(v, backend))


def _ref_lstm(x, h, c, kernel, recurrent, bias, recurrent_bias):
    x, h, c, kernel, recurrent = (a.astype(np.float64) for a in (x, h, c, kernel, recurrent))
    sig = lambda z: 1 / (1 + np.exp(-z))  # noqa: E731
    hs = []
    for t in range(x.shape[1]):
        z = x[:, t] @ kernel + h @ recurrent
        if bias is not None:
            z = z + bias
        if recurrent_bias is not None:
            z = z + recurrent_bias
        i, f, g, o = np.split(z, 4, axis=-1)
        c = sig(f) * c + sig(i) * np.tanh(g)
        h = sig(o) * np.tanh(c)
        hs.append(h)
    return np.stack(hs, 1), h, c


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize("biases", [True, False])
def test_lstm_update(backend, dtype, biases):
    batch, time, n_in, hidden = 2, 4, 3, 5
    x = _random_nn_layers((batch, time, n_in), dtype, 14)
    h0, c0 = (
        _random_nn_layers((batch, hidden), dtype, 15),
        _random_nn_layers((batch, hidden), dtype, 16),
    )
    kernel = _random_nn_layers((n_in, 4 * hidden), dtype, 17, 0.5)
    recurrent = _random_nn_layers((hidden, 4 * hidden), dtype, 18, 0.5)
    bias = _random_nn_layers((4 * hidden,), dtype, 19) if biases else None
    recurrent_bias = _random_nn_layers((4 * hidden,), dtype, 20) if biases else None
    hs_ref, h_ref, c_ref = _ref_lstm(x, h0, c0, kernel, recurrent, bias, recurrent_bias)
    extra = (native(bias, backend), native(recurrent_bias, backend)) if biases else ()
    for fn in api(backend, "lstm_update"):
        hs, (h, c) = fn(
            native(x, backend),
            native(h0, backend),
            native(c0, backend),
            native(kernel, backend),
            native(recurrent, backend),
            *extra,
        )
        tol = tolerance(dtype, 10)
        check(hs, hs_ref.astype(dtype), backend, **tol)
        check(h, h_ref.astype(dtype), backend, **tol)
        check(c, c_ref.astype(dtype), backend, **tol)


def test_lstm_update_errors(backend):
    x, h = native(np.ones((2, 3, 4)), backend), native(np.zeros((2, 5)), backend)
    good_r = native(np.ones((5, 20)), backend)
    with pytest.raises(ValueError, match=r"kernel must be \[in, 4 \* hidden\] = \[4, 20\]"):
        ivy.lstm_update(x, h, h, native(np.ones((3, 20)), backend), good_r)
    with pytest.raises(ValueError, match=r"recurrent_kernel must be \[hidden, 4 \* hidden\]"):
        ivy.lstm_update(
            x, h, h, native(np.ones((4, 20)), backend), native(np.ones((5, 16)), backend)
        )
    with pytest.raises(ValueError, match="time >= 1"):
        ivy.lstm_update(
            native(np.ones((2, 0, 4)), backend), h, h, native(np.ones((4, 20)), backend), good_r
        )


@pytest.mark.parametrize("dtype", FLOATS)
def test_dropout(backend, dtype):
    ivy.seed(3, f=backend)
    x = np.random.default_rng(0).uniform(1, 2, (100, 100)).astype(dtype)
    for fn in api(backend, "dropout"):
        out = fn(native(x, backend), 0.3)
        check_meta(out, backend, dtype, x.shape)
        got = numpy_of(out)
        kept = got != 0
        assert abs(kept.mean() - 0.7) < 0.03  # 10,000 draws: the std of the fraction is 0.005
        np.testing.assert_allclose(got[kept], (x / np.asarray(0.7, dtype))[kept], rtol=1e-6)
    unscaled = numpy_of(ivy.dropout(native(x, backend), 0.5, scale=False))
    assert set(np.unique(unscaled[unscaled != 0])) <= set(np.unique(x))
    assert 0.45 < (unscaled != 0).mean() < 0.55


def test_dropout_edge_cases(backend):
    x = native(np.ones((4, 5), np.float32), backend)
    assert ivy.dropout(x, 0.5, training=False) is x
    assert ivy.dropout(x, 0.0) is x
    zeros = ivy.dropout(x, 1.0)
    check(zeros, np.zeros((4, 5), np.float32), backend)
    a, b = numpy_of(ivy.dropout(x, 0.5)), numpy_of(ivy.dropout(x, 0.5))
    assert not np.array_equal(a, b)  # a new mask on every call
    assert dtype_name(ivy.dropout(x, 0.5)) == "float32"
    for prob in (-0.1, 1.5):
        with pytest.raises(ValueError, match=r"prob must be in \[0, 1\]"):
            ivy.dropout(x, prob)
