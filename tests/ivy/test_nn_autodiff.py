"""Gradients of the nn functions against central finite differences in float64, and compiled runs
against eager ones, on the differentiable backends.

Gradients are taken with each framework's own autodiff (``torch.autograd.grad``, ``jax.grad``,
``tf.GradientTape``) of ``sum(fn(*inputs) * weights)``, and compared along random directions
``v`` with ``(L(inputs + h v) - L(inputs - h v)) / 2h``.
"""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import check, check_gradients, native, native_value_and_grads, numpy_of


def _random(shape, seed, scale=1.0):
    return scale * np.random.default_rng(60 + seed).standard_normal(shape)


# ----------------------------------------------------------------------------------------------
# Convolutions and pools
# ----------------------------------------------------------------------------------------------

CONV_CASES = {
    "conv2d-same-stride": (
        lambda x, w: ivy.conv2d(x, w, 2, "SAME"),
        [(2, 5, 6, 3), (3, 3, 3, 2)],
    ),
    "conv2d-dilated-explicit": (
        lambda x, w: ivy.conv2d(x, w, 1, [(1, 0), (2, 1)], dilations=2),
        [(1, 5, 6, 2), (2, 3, 2, 3)],
    ),
    "conv1d-stride-dilation": (
        lambda x, w: ivy.conv1d(x, w, 2, "SAME", dilations=2),
        [(2, 9, 2), (3, 2, 3)],
    ),
    "conv3d-dilated": (
        lambda x, w: ivy.conv3d(x, w, 1, "VALID", dilations=(2, 1, 1)),
        [(1, 4, 3, 3, 2), (2, 2, 2, 2, 2)],
    ),
    "conv2d_transpose": (
        lambda x, w: ivy.conv2d_transpose(x, w, 2, "SAME", dilations=(1, 2)),
        [(1, 3, 3, 2), (3, 2, 3, 2)],
    ),
    "conv3d_transpose": (
        lambda x, w: ivy.conv3d_transpose(x, w, (1, 2, 1), "SAME"),
        [(1, 2, 2, 3, 2), (2, 2, 2, 3, 2)],
    ),
    "conv1d_transpose-output_shape": (
        lambda x, w: ivy.conv1d_transpose(x, w, 2, "VALID", output_shape=(10,)),
        [(2, 4, 3), (3, 2, 3)],
    ),
    "depthwise_conv2d": (
        lambda x, w: ivy.depthwise_conv2d(x, w, (1, 2), "SAME"),
        [(2, 5, 5, 3), (3, 3, 3)],
    ),
    "max_pool2d": (lambda x: ivy.max_pool2d(x, 2, 2, "SAME"), [(2, 5, 5, 3)]),
    "avg_pool2d-explicit": (lambda x: ivy.avg_pool2d(x, 3, 2, [(1, 2), 1]), [(2, 5, 5, 3)]),
    "avg_pool3d": (lambda x: ivy.avg_pool3d(x, 2, 2, "SAME"), [(1, 3, 4, 3, 2)]),
    "max_pool3d": (lambda x: ivy.max_pool3d(x, 2, 1, "VALID"), [(1, 3, 3, 3, 2)]),
}


@pytest.mark.parametrize("case", sorted(CONV_CASES))
def test_conv_and_pool_gradients(diff_backend, case):
    fn, shapes = CONV_CASES[case]
    check_gradients(diff_backend, fn, [_random(s, i) for i, s in enumerate(shapes)])


# ----------------------------------------------------------------------------------------------
# Layers
# ----------------------------------------------------------------------------------------------


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


def test_attention_gradients(diff_backend):
    mask = np.tril(np.ones((3, 4), bool), k=1)

    def fn(q, k, v):
        return ivy.scaled_dot_product_attention(q, k, v, mask=native(mask, diff_backend))

    check_gradients(
        diff_backend, fn, [_random((2, 3, 5), 1), _random((2, 4, 5), 2), _random((2, 4, 2), 3)]
    )


def test_linear_gradients(diff_backend):
    check_gradients(
        diff_backend, ivy.linear, [_random((2, 3), 1), _random((4, 3), 2), _random((4,), 3)]
    )


# ----------------------------------------------------------------------------------------------
# Losses and activations
# ----------------------------------------------------------------------------------------------

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


# ----------------------------------------------------------------------------------------------
# Compiled (jax.jit, tf.function) against eager
# ----------------------------------------------------------------------------------------------


def _network(x, w_conv, w_up, kernel, recurrent, q):
    y = ivy.relu(ivy.conv2d(x, w_conv, 2, "SAME"))
    y = ivy.max_pool2d(y, 2, 1, "SAME")
    up = ivy.conv2d_transpose(y, w_up, 2, "SAME", output_shape=(3, 4))
    seq = ivy.reshape(y, (2, 4, 4))
    hs, _ = ivy.lstm_update(seq, ivy.zeros_like(q), ivy.zeros_like(q), kernel, recurrent)
    att = ivy.scaled_dot_product_attention(hs, hs, hs)
    norm = ivy.layer_norm(att, scale=q[0], offset=q[1])
    return ivy.sum(up) + ivy.sum(ivy.log_softmax(norm)) + ivy.avg_pool1d(hs, 2, 2, "SAME")[0, 0, 0]


@pytest.mark.parametrize("compiler", ["jax", "tensorflow"])
def test_compiled_matches_eager(request, compiler):
    backend = compiler
    if backend not in request.config.ivy_backends:
        pytest.skip(f"{backend} is not selected")
    shapes = [(2, 3, 4, 3), (3, 3, 3, 4), (3, 3, 2, 4), (4, 16), (4, 16), (2, 4)]
    arrays = [native(_random(s, i), backend) for i, s in enumerate(shapes)]
    eager = _network(*arrays)
    if backend == "jax":
        import jax

        compiled = jax.jit(_network)(*arrays)
    else:
        import tensorflow as tf

        compiled = tf.function(_network)(*arrays)
    check(compiled, numpy_of(eager), backend, rtol=1e-10, atol=1e-10)
