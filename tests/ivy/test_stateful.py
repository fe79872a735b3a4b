"""The stateful layer: modules and their variable nests, layers against numpy float64
references, initializers, and portable checkpoints across every pair of backends."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import ivy
from ivy import nest
from ivy.stateful import initializers
from ivy.stateful.module import default_fans
from tests.helpers import check, native, numpy_of, tolerance

# ----------------------------------------------------------------------------------------------
# References in numpy float64
# ----------------------------------------------------------------------------------------------


def _sigmoid(x):
    return 1.0 / (1.0 + np.exp(-x))


def np_linear(x, w, b=None):
    return x @ w.T + (0.0 if b is None else b)


def np_conv(x, w, strides, padding, dilations):
    """Channel-last N-D convolution: x [N, *S, Cin], w [*K, Cin, Cout]."""
    dims = w.ndim - 2
    s = (strides,) * dims if np.isscalar(strides) else tuple(strides)
    d = (dilations,) * dims if np.isscalar(dilations) else tuple(dilations)
    span = [(w.shape[i] - 1) * d[i] + 1 for i in range(dims)]
    if padding == "SAME":
        pads = []
        for i in range(dims):
            n = x.shape[1 + i]
            total = max((-(-n // s[i]) - 1) * s[i] + span[i] - n, 0)
            pads.append((total // 2, total - total // 2))
        x = np.pad(x, [(0, 0), *pads, (0, 0)])
    out = [(x.shape[1 + i] - span[i]) // s[i] + 1 for i in range(dims)]
    y = np.zeros((x.shape[0], *out, w.shape[-1]))
    for k in np.ndindex(*w.shape[:dims]):
        window = tuple(
            slice(k[i] * d[i], k[i] * d[i] + (out[i] - 1) * s[i] + 1, s[i]) for i in range(dims)
        )
        y += x[(slice(None), *window)] @ w[k]
    return y


def np_lstm(x, h, c, kernel, recurrent, bias):
    """One LSTM layer, gates i, f, g, o; x [B, T, in]."""
    hs = []
    for t in range(x.shape[-2]):
        z = x[..., t, :] @ kernel + h @ recurrent + bias
        i, f, g, o = np.split(z, 4, axis=-1)
        c = _sigmoid(f) * c + _sigmoid(i) * np.tanh(g)
        h = _sigmoid(o) * np.tanh(c)
        hs.append(h)
    return np.stack(hs, axis=-2), h, c


def randomize(module, backend, seed=0):
    """Give ``module`` float64 N(0, 0.5) variables; return them as a numpy nest."""
    rng = np.random.default_rng(seed)
    ref = nest.map_nest(lambda a: 0.5 * rng.standard_normal(numpy_of(a).shape), module.v)
    module.v = nest.map_nest(lambda a: native(a, backend), ref)
    return ref


# ----------------------------------------------------------------------------------------------
# Module: framework, variables, purity
# ----------------------------------------------------------------------------------------------


def test_module_needs_a_framework():
    with pytest.raises(ivy.NoFrameworkError, match="set_framework"):
        ivy.Linear(2, 3)


def test_module_framework_from_f_global_or_dtype(backend, xp):
    assert ivy.Linear(2, 3, f=backend).f is xp
    with ivy.set_framework(backend):
        assert ivy.MLP(2, (4,), 1).f is xp
    layer = ivy.Linear(2, 3, dtype=xp.float64)
    assert layer.f is xp
    check(layer.v["w"], numpy_of(layer.v["w"]), backend, dtype="float64")


def test_variables_nest_structure(backend):
    mlp = ivy.MLP(3, (8, 5), 2, f=backend)
    shapes = nest.map_nest(lambda a: tuple(numpy_of(a).shape), mlp.v)
    assert shapes == {
        "layers": {
            "0": {"w": (8, 3), "b": (8,)},
            "1": {"w": (5, 8), "b": (5,)},
            "2": {"w": (2, 5), "b": (2,)},
        }
    }
    assert mlp.num_parameters == 8 * 4 + 5 * 9 + 2 * 6
    net = ivy.Sequential(
        ivy.Linear(3, 4, f=backend), "relu", ivy.Linear(4, 1, bias=False, f=backend)
    )
    assert sorted(net.v["layers"]) == ["0", "2"] and sorted(net.v["layers"]["2"]) == ["w"]
    lstm = ivy.LSTM(3, 4, num_layers=2, f=backend)
    assert nest.map_nest(lambda a: tuple(numpy_of(a).shape), lstm.v["layers"]["1"]) == {
        "kernel": (4, 16),
        "recurrent_kernel": (4, 16),
        "bias": (16,),
    }


def test_assigning_v_checks_keys(backend):
    mlp = ivy.MLP(3, (4,), 1, f=backend)
    v = mlp.v
    del v["layers"]["1"]["b"]
    with pytest.raises(KeyError, match="expects"):
        mlp.v = v
    with pytest.raises(KeyError, match="expects"):
        mlp.v = {"layers": {}}


def test_seed_makes_variables_reproducible(backend):
    def weights(seed):
        ivy.seed(seed)
        return [numpy_of(a) for a in nest.nest_leaves(ivy.LSTM(3, 4, f=backend).v)]

    for a, b in zip(weights(5), weights(5)):
        np.testing.assert_array_equal(a, b)
    assert not all(np.array_equal(a, b) for a, b in zip(weights(5), weights(6)))


def test_call_with_explicit_v_is_pure(backend):
    mlp = ivy.MLP(3, (4,), 2, dtype="float64", f=backend)
    own = nest.map_nest(numpy_of, mlp.v)
    other = randomize(ivy.MLP(3, (4,), 2, dtype="float64", f=backend), backend, seed=1)
    x = np.random.default_rng(2).standard_normal((5, 3))
    y = mlp(native(x, backend), v=nest.map_nest(lambda a: native(a, backend), other))
    layers = other["layers"]
    expected = np_linear(np.maximum(np_linear(x, **layers["0"]), 0), **layers["1"])
    check(y, expected, backend)
    # the module's own variables are untouched and still used without v
    nest.multi_map_nest(lambda a, b: np.testing.assert_array_equal(numpy_of(a), b), mlp.v, own)
    layers = own["layers"]
    expected = np_linear(np.maximum(np_linear(x, **layers["0"]), 0), **layers["1"])
    check(mlp(native(x, backend)), expected, backend)


def test_submodules_must_share_the_framework(request, backend):
    others = [b for b in request.config.ivy_backends if b != backend]
    if not others:
        pytest.skip("needs two backends under test")
    other = others[0]

    class Pair(ivy.Module):
        def __init__(self):
            super().__init__(f=backend)
            self.a = ivy.Linear(2, 2, f=other)

    with pytest.raises(ivy.MixedFrameworksError, match="same f="):
        Pair()


def test_custom_module(backend):
    class Affine(ivy.Module):
        def __init__(self, n, *, f=None):
            super().__init__(dtype="float64", f=f)
            self.add_variable("scale", initializers.constant(2.0), (n,))
            self.add_variable("shift", initializers.zeros, (n,))
            self.inner = ivy.Linear(n, n, bias=False, **self.build_args)

        def _forward(self, v, x):
            return self.inner(x * v["scale"] + v["shift"], v=v["inner"])

    m = Affine(3, f=backend)
    assert sorted(m.v) == ["inner", "scale", "shift"]
    x = np.arange(6.0).reshape(2, 3)
    check(m(native(x, backend)), np_linear(2 * x, numpy_of(m.v["inner"]["w"])), backend)
    assert "Affine(f=" in repr(m)


# ----------------------------------------------------------------------------------------------
# Layers against numpy float64
# ----------------------------------------------------------------------------------------------


def test_linear_forward(backend):
    layer = ivy.Linear(4, 3, dtype="float64", f=backend)
    ref = randomize(layer, backend)
    x = np.random.default_rng(1).standard_normal((2, 5, 4))
    check(layer(native(x, backend)), np_linear(x, ref["w"], ref["b"]), backend)
    no_bias = ivy.Linear(4, 3, bias=False, dtype="float64", f=backend)
    ref = randomize(no_bias, backend)
    check(no_bias(native(x, backend)), np_linear(x, ref["w"]), backend)


def test_mlp_forward(backend):
    mlp = ivy.MLP(
        3, (6, 5), 2, activation="tanh", output_activation="sigmoid", dtype="float64", f=backend
    )
    ref = randomize(mlp, backend)["layers"]
    x = np.random.default_rng(1).standard_normal((7, 3))
    h = np.tanh(np_linear(x, **ref["0"]))
    h = np.tanh(np_linear(h, **ref["1"]))
    check(mlp(native(x, backend)), _sigmoid(np_linear(h, **ref["2"])), backend)


def test_sequential_forward(backend, xp):
    net = ivy.Sequential(
        ivy.Linear(3, 4, dtype="float64", f=backend),
        ivy.tanh,
        ivy.Linear(4, 2, dtype="float64", f=backend),
        "relu",
    )
    ref = randomize(net, backend)["layers"]
    x = np.random.default_rng(1).standard_normal((5, 3))
    expected = np.maximum(np_linear(np.tanh(np_linear(x, **ref["0"])), **ref["2"]), 0)
    check(net(native(x, backend)), expected, backend)


@pytest.mark.parametrize(
    "dims, kernel, strides, padding, dilations",
    [
        (1, 3, 1, "SAME", 2),
        (2, (3, 2), (2, 1), "VALID", 1),
        (3, 2, 1, "SAME", 1),
    ],
)
def test_conv_forward(backend, dims, kernel, strides, padding, dilations):
    conv = ivy.Conv(
        dims,
        2,
        3,
        kernel,
        strides=strides,
        padding=padding,
        dilations=dilations,
        dtype="float64",
        f=backend,
    )
    ref = randomize(conv, backend)
    x = np.random.default_rng(1).standard_normal((2, *(7,) * dims, 2))
    expected = np_conv(x, ref["w"], strides, padding, dilations) + ref["b"]
    check(conv(native(x, backend)), expected, backend, **tolerance("float64", 10))


def test_conv_aliases(backend):
    for cls, dims in ((ivy.Conv1D, 1), (ivy.Conv2D, 2), (ivy.Conv3D, 3)):
        conv = cls(2, 4, 3, f=backend)
        assert conv.dims == dims
        assert tuple(numpy_of(conv.v["w"]).shape) == (3,) * dims + (2, 4)


def test_lstm_forward(backend):
    lstm = ivy.LSTM(3, 4, num_layers=2, dtype="float64", f=backend)
    ref = randomize(lstm, backend)["layers"]
    rng = np.random.default_rng(1)
    x = rng.standard_normal((2, 5, 3))
    hs, states = lstm(native(x, backend))
    zeros = np.zeros((2, 4))
    hs0, h0, c0 = np_lstm(x, zeros, zeros, **_lstm_args(ref["0"]))
    hs1, h1, c1 = np_lstm(hs0, zeros, zeros, **_lstm_args(ref["1"]))
    tol = tolerance("float64", 10)
    check(hs, hs1, backend, **tol)
    for (h, c), (eh, ec) in zip(states, [(h0, c0), (h1, c1)]):
        check(h, eh, backend, **tol)
        check(c, ec, backend, **tol)
    # with an initial state
    init = [(rng.standard_normal((2, 4)), rng.standard_normal((2, 4))) for _ in range(2)]
    hs, _ = lstm(native(x, backend), [tuple(native(a, backend) for a in s) for s in init])
    hs0, _, _ = np_lstm(x, *init[0], **_lstm_args(ref["0"]))
    check(hs, np_lstm(hs0, *init[1], **_lstm_args(ref["1"]))[0], backend, **tol)


def _lstm_args(v):
    return {"kernel": v["kernel"], "recurrent": v["recurrent_kernel"], "bias": v["bias"]}


def test_unknown_activation(backend):
    with pytest.raises(ValueError, match="unknown activation"):
        ivy.MLP(2, (3,), 1, activation="no_such_function", f=backend)


# ----------------------------------------------------------------------------------------------
# Initializers
# ----------------------------------------------------------------------------------------------


def test_default_fans():
    assert default_fans((8, 3)) == (3, 8)
    assert default_fans((3, 3, 16, 32)) == (144, 288)
    assert default_fans((5,)) == (5, 5)


@pytest.mark.parametrize(
    "name, std",
    [
        ("glorot_uniform", np.sqrt(2.0 / 500)),
        ("glorot_normal", np.sqrt(2.0 / 500)),
        ("he_uniform", np.sqrt(2.0 / 200)),
        ("he_normal", np.sqrt(2.0 / 200)),
    ],
)
def test_variance_scaling_initializers(backend, name, std):
    ivy.seed(0)
    w = getattr(initializers, name)((300, 200), f=backend)
    check(w, numpy_of(w), backend, dtype="float32")
    w = numpy_of(w).astype(np.float64)
    assert w.shape == (300, 200)
    assert abs(w.mean()) < 5 * std / np.sqrt(w.size)
    assert abs(w.std() / std - 1) < 0.02
    if name.endswith("uniform"):
        assert np.abs(w).max() <= std * np.sqrt(3) * (1 + 1e-6)


@pytest.mark.parametrize("shape", [(4, 10), (10, 4), (3, 2, 5)])
def test_orthogonal(backend, shape):
    ivy.seed(0)
    q = initializers.orthogonal(shape, gain=2.0, dtype="float64", f=backend)
    q = numpy_of(q)
    assert q.shape == shape
    m = q.reshape(-1, shape[-1]) / 2.0
    gram = m @ m.T if m.shape[0] <= m.shape[1] else m.T @ m
    np.testing.assert_allclose(gram, np.eye(len(gram)), atol=1e-12)


def test_constant_ones_zeros(backend):
    check(initializers.constant(0.5)((2, 3), f=backend), np.full((2, 3), 0.5, np.float32), backend)
    check(initializers.ones((2,), dtype="float64", f=backend), np.ones(2), backend)
    check(initializers.zeros((2,), f=backend), np.zeros(2, np.float32), backend)


def test_initializer_choice_in_layers(backend):
    layer = ivy.Linear(
        3, 2, weight_init=initializers.ones, bias_init=initializers.constant(1.5), f=backend
    )
    check(layer.v["w"], np.ones((2, 3), np.float32), backend)
    check(layer.v["b"], np.full(2, 1.5, np.float32), backend)
    init = functools.partial(initializers.orthogonal, gain=3.0)
    w = numpy_of(ivy.Linear(4, 4, weight_init=init, dtype="float64", f=backend).v["w"])
    np.testing.assert_allclose(w @ w.T, 9 * np.eye(4), atol=1e-12)


# ----------------------------------------------------------------------------------------------
# Checkpoints
# ----------------------------------------------------------------------------------------------


def test_checkpoint_round_trip_across_backends(backend, tmp_path, request):
    """A checkpoint written on ``backend`` loads on every installed backend."""
    ivy.seed(1)
    src = ivy.MLP(3, (8, 8), 2, f=backend)
    path = tmp_path / "mlp.ckpt"
    src.save(path)
    assert path.exists()
    x = np.random.default_rng(0).standard_normal((4, 3)).astype(np.float32)
    expected = numpy_of(src(native(x, backend)))
    src_weights = nest.map_nest(numpy_of, src.v)
    for target in request.config.ivy_backends:
        ivy.seed(2)
        dst = ivy.MLP(3, (8, 8), 2, f=target).load(path)
        nest.multi_map_nest(
            lambda a, b, t=target: check(a, b, t, rtol=0, atol=0), dst.v, src_weights
        )
        check(dst(native(x, target)), expected, target)


def test_checkpoint_converts_dtype_and_checks_structure(backend, tmp_path):
    path = tmp_path / "w.npz"
    src = ivy.Linear(3, 2, dtype="float64", f=backend)
    ivy.save_weights(path, src.v)
    dst = ivy.Linear(3, 2, f=backend).load(path)  # float32 module
    check(dst.v["w"], numpy_of(src.v["w"]).astype(np.float32), backend)
    with pytest.raises(KeyError, match="missing"):
        ivy.Linear(3, 2, bias=False, f=backend).load(path)
    with pytest.raises(ValueError, match="shape"):
        ivy.Linear(4, 2, f=backend).load(path)


def test_load_weights_without_like(backend, tmp_path):
    path = tmp_path / "w.npz"
    mlp = ivy.MLP(2, (3,), 1, f=backend)
    ivy.save_weights(path, mlp.v)
    v = ivy.load_weights(path, f=backend)
    nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), backend, rtol=0, atol=0), v, mlp.v)
    with pytest.raises(ivy.NoFrameworkError):
        ivy.load_weights(path)
    with ivy.set_framework(backend):
        assert sorted(ivy.load_weights(path)["layers"]) == ["0", "1"]
