"""Tests of the core group ``gradients`` (``ivy/core/gradients.py``), on every backend.

Automatic differentiation: gradients of composite functions in float64, checked against
central finite differences computed with numpy and across torch, jax and tensorflow.

Gradients of the nn functions against central finite differences in float64, and compiled runs
against eager ones, on the differentiable backends.

Gradients are taken with each framework's own autodiff (``torch.autograd.grad``, ``jax.grad``,
``tf.GradientTape``) of ``sum(fn(*inputs) * weights)``, and compared along random directions
``v`` with ``(L(inputs + h v) - L(inputs - h v)) / 2h``.
"""

from __future__ import annotations

import types
import zlib

import numpy as np
import pytest

import ivy
from ivy import nest
from tests.compilers import native_compile
from tests.conftest import capable
from tests.helpers import (
    TOLERANCES,
    check,
    check_gradients,
    is_native,
    native,
    numpy_of,
)

# The composite functions are written once against an array namespace: an ivy backend
# namespace under test, or plain numpy (the reference, independent of ivy's numpy backend).
NP = types.SimpleNamespace(
    **{n: getattr(np, n) for n in dir(np) if not n.startswith("_")},
    inv=np.linalg.inv,
    vector_norm=np.linalg.vector_norm,
)


X_DATA = np.random.default_rng(7).normal(size=(5, 3))


FD = dict(rtol=1e-6, atol=1e-8)  # central differences with h ~ 1e-6 in float64


F64 = TOLERANCES["float64"]


def mlp(v, xp):
    h = xp.tanh(xp.matmul(xp.asarray(X_DATA), v["w1"]) + v["b1"])
    out = xp.matmul(h, v["w2"])
    return xp.mean(out**2) + 0.1 * xp.sum(v["w1"] ** 2)


def logsumexp_softplus(v, xp):
    a, b = v
    return xp.log(xp.sum(xp.exp(a))) + xp.sum(xp.log1p(xp.exp(b)))


def rational_sqrt(v, xp):
    x, y = v
    return xp.sum(xp.sqrt(x**2 + y**2 + 1.0) / (1.0 + x * x)) * xp.prod(xp.cos(y))


def nested_broadcast(v, xp):
    p, (q, s) = v["a"]["p"], v["q"]
    m = xp.mean(xp.sin(p) * xp.cos(q), axis=0)
    return xp.sum(m**2) * xp.exp(s) + xp.var(p)


def linalg(v, xp):
    a, b = v["A"], v["b"]
    m = xp.matmul(a, xp.permute_dims(a, (1, 0))) + 3.0 * xp.eye(3, dtype=xp.float64)
    return xp.sum(xp.matmul(xp.inv(m), b)) + xp.vector_norm(a)


def _inputs(name):
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    n = rng.normal
    return {
        "mlp": lambda: {"w1": n(size=(3, 4)), "b1": n(size=4), "w2": n(size=(4, 2))},
        "logsumexp_softplus": lambda: [n(size=4), n(size=(2, 3))],
        "rational_sqrt": lambda: (n(size=3), n(size=3)),
        "nested_broadcast": lambda: {"a": {"p": n(size=(2, 3))}, "q": [n(size=3), n(size=())]},
        "linalg": lambda: {"A": n(size=(3, 3)), "b": n(size=3)},
    }[name]()


COMPOSITES = {
    f.__name__: f for f in (mlp, logsumexp_softplus, rational_sqrt, nested_broadcast, linalg)
}


def finite_differences(fn, v, h=1e-6):
    """Central differences of the numpy function ``fn`` at the nest ``v`` of float64 arrays."""
    leaves, spec = nest.flatten_nest(v)
    leaves = [np.array(x, dtype=np.float64) for x in leaves]
    grads = []
    for leaf in leaves:
        g = np.zeros_like(leaf)
        for i in np.ndindex(leaf.shape):
            old = leaf[i]
            step = h * max(1.0, abs(old))
            leaf[i] = old + step
            up = fn(nest.unflatten_nest(spec, leaves))
            leaf[i] = old - step
            down = fn(nest.unflatten_nest(spec, leaves))
            leaf[i] = old
            g[i] = (up - down) / (2 * step)
        grads.append(g)
    return nest.unflatten_nest(spec, grads)


def _on(backend, v):
    return nest.map_nest(lambda a: native(np.asarray(a, dtype=np.float64), backend), v)


def _to_numpy(v):
    return nest.map_nest(numpy_of, v)


def _assert_nests_close(actual, expected, **tol):
    assert nest.nest_structure(actual) == nest.nest_structure(expected)
    for a, e in zip(nest.nest_leaves(actual), nest.nest_leaves(expected)):
        np.testing.assert_allclose(a, e, **tol)


def _gradients(backend, name):
    xp = getattr(ivy, backend)
    v = _on(backend, _inputs(name))
    loss, grads = ivy.execute_with_gradients(lambda v: COMPOSITES[name](v, xp), v)
    assert is_native(loss, backend) and numpy_of(loss).shape == ()
    for g in nest.nest_leaves(grads):
        assert is_native(g, backend) and numpy_of(g).dtype == np.float64
    return numpy_of(loss), _to_numpy(grads)


@pytest.mark.parametrize("name", COMPOSITES)
def test_gradients_match_finite_differences(diff_backend, name):
    loss, grads = _gradients(diff_backend, name)
    v = _inputs(name)
    reference = COMPOSITES[name]
    np.testing.assert_allclose(loss, reference(v, NP), **F64)
    _assert_nests_close(grads, finite_differences(lambda w: reference(w, NP), v), **FD)


@pytest.mark.parametrize("name", COMPOSITES)
def test_gradients_agree_across_backends(request, name):
    backends = [b for b in request.config.ivy_backends if capable(b, "autodiff")]
    if len(backends) < 2:
        pytest.skip("needs two differentiable backends")
    results = {b: _gradients(b, name) for b in backends}
    first = backends[0]
    for b in backends[1:]:
        np.testing.assert_allclose(results[b][0], results[first][0], rtol=1e-12, atol=1e-12)
        _assert_nests_close(results[b][1], results[first][1], rtol=1e-11, atol=1e-12)


def test_single_array_and_dict_key_order(diff_backend):
    xp = getattr(ivy, diff_backend)
    x = native(np.array([1.0, 2.0, 3.0]), diff_backend)
    loss, g = ivy.execute_with_gradients(lambda x: xp.sum(x**3), x)
    np.testing.assert_allclose(numpy_of(loss), 36.0, **F64)
    np.testing.assert_allclose(numpy_of(g), [3.0, 12.0, 27.0], **F64)
    v = {"z": x, "a": x}
    _, grads = ivy.execute_with_gradients(lambda v: xp.sum(v["z"] * v["a"]), v)
    assert list(grads) == ["z", "a"]


def test_aux_outputs_follow_the_gradients(diff_backend):
    xp = getattr(ivy, diff_backend)
    v = {"w": native(np.array([1.0, -2.0]), diff_backend)}

    def func(v):
        y = v["w"] * 3.0
        return xp.sum(y**2), y, {"mean": xp.mean(y)}

    loss, grads, y, extra = ivy.execute_with_gradients(func, v)
    np.testing.assert_allclose(numpy_of(loss), 45.0, **F64)
    np.testing.assert_allclose(numpy_of(grads["w"]), [18.0, -36.0], **F64)
    np.testing.assert_allclose(numpy_of(y), [3.0, -6.0], **F64)
    np.testing.assert_allclose(numpy_of(extra["mean"]), -1.5, **F64)


def test_unused_leaves_get_zero_gradients(diff_backend):
    xp = getattr(ivy, diff_backend)
    v = {"used": native(np.ones(2), diff_backend), "unused": native(np.ones((2, 3)), diff_backend)}
    _, grads = ivy.execute_with_gradients(lambda v: xp.sum(v["used"] * 2.0), v)
    np.testing.assert_array_equal(numpy_of(grads["unused"]), np.zeros((2, 3)))
    _, grads = ivy.execute_with_gradients(lambda v: xp.sum(xp.ones(3, dtype=xp.float64)), v)
    np.testing.assert_array_equal(numpy_of(grads["used"]), np.zeros(2))


def _torch_trainable(w):
    return w.requires_grad and w.is_leaf


def _jax_trainable(w):
    import jax

    return isinstance(w, jax.Array)  # jax differentiates values: a variable is an array


def _tensorflow_trainable(w):
    import tensorflow as tf

    return isinstance(w, tf.Variable) and w.trainable


# What ivy.variable gives on each differentiable backend (a new one adds its row).
TRAINABLE = {
    "torch": _torch_trainable,
    "jax": _jax_trainable,
    "tensorflow": _tensorflow_trainable,
}


def test_repeated_calls_do_not_accumulate(diff_backend):
    xp = getattr(ivy, diff_backend)
    v = {"w": ivy.variable(native(np.array([1.0, 2.0]), diff_backend))}
    first = ivy.execute_with_gradients(lambda v: xp.sum(v["w"] ** 2), v)[1]
    second = ivy.execute_with_gradients(lambda v: xp.sum(v["w"] ** 2), v)[1]
    np.testing.assert_array_equal(numpy_of(first["w"]), [2.0, 4.0])
    np.testing.assert_array_equal(numpy_of(second["w"]), [2.0, 4.0])
    assert getattr(v["w"], "grad", None) is None  # torch: autograd.grad, never .backward()


def test_variables_are_differentiable_leaves(diff_backend):
    xp = getattr(ivy, diff_backend)
    w = ivy.variable(native(np.array([0.5, 1.5]), diff_backend))
    assert TRAINABLE[diff_backend](w)
    _, grads = ivy.execute_with_gradients(lambda v: xp.sum(xp.sin(v[0])), [w])
    np.testing.assert_allclose(numpy_of(grads[0]), np.cos([0.5, 1.5]), **F64)


def test_results_are_cut_from_the_graph_by_default(diff_backend):
    xp = getattr(ivy, diff_backend)
    x = native(np.array([1.0, 2.0]), diff_backend)

    def outer(x):
        loss, g = ivy.execute_with_gradients(lambda x: xp.sum(x**3), x)
        return xp.sum(g) + loss  # constants for the outer differentiation

    _, g_outer = ivy.execute_with_gradients(outer, x)
    np.testing.assert_array_equal(numpy_of(g_outer), [0.0, 0.0])
    loss, g = ivy.execute_with_gradients(lambda x: xp.sum(x**3), x)
    assert not getattr(loss, "requires_grad", False) and not getattr(g, "requires_grad", False)


def test_retain_grads_gives_second_order_gradients(diff_backend):
    xp = getattr(ivy, diff_backend)
    x = native(np.array([1.0, 2.0, -0.5]), diff_backend)

    def outer(x):
        inner = ivy.execute_with_gradients(lambda x: xp.sum(x**3), x, retain_grads=True)
        return xp.sum(inner[1])  # sum of 3 x^2

    loss, g = ivy.execute_with_gradients(outer, x)
    np.testing.assert_allclose(numpy_of(loss), 3 * (1 + 4 + 0.25), **F64)
    np.testing.assert_allclose(numpy_of(g), [6.0, 12.0, -3.0], **F64)


@pytest.mark.parametrize("retain_grads", [False, True])
def test_captured_arrays_are_constants(diff_backend, retain_grads):
    """``func`` is differentiated only through its argument: an array it captures is a constant,
    also where it is the very object passed as a leaf (a variable too)."""
    xp = getattr(ivy, diff_backend)
    w = ivy.variable(native(np.array([0.5, -1.0]), diff_backend))
    _, g = ivy.execute_with_gradients(
        lambda v: xp.sum(v["w"] * w), {"w": w}, retain_grads=retain_grads
    )
    np.testing.assert_allclose(numpy_of(g["w"]), [0.5, -1.0], **F64)
    _, jac = ivy.execute_with_jacobian(lambda q: q * w, w, batch_dims=0, retain_grads=retain_grads)
    np.testing.assert_allclose(numpy_of(jac), np.diag([0.5, -1.0]), **F64)


def test_hessian_vector_product_of_a_kl_with_a_captured_side(diff_backend):
    """The case that found the quirk: KL(N(v, 1) || N(w, 1)) = sum((v - w)^2) / 2 with ``v``
    captured and ``w`` the argument has Hessian I in ``w``, also at ``w = v``."""
    xp = getattr(ivy, diff_backend)
    v = {"loc": native(np.array([0.5, -1.0]), diff_backend)}
    u = native(np.array([2.0, 3.0]), diff_backend)

    def kl(w):
        return xp.sum((v["loc"] - w["loc"]) ** 2) / 2.0

    def directional_gradient(w):
        g = ivy.execute_with_gradients(kl, w, retain_grads=True)[1]
        return xp.sum(g["loc"] * u)

    value, hvp = ivy.execute_with_gradients(directional_gradient, v)
    np.testing.assert_allclose(numpy_of(value), 0.0, **F64)
    np.testing.assert_allclose(numpy_of(hvp["loc"]), [2.0, 3.0], **F64)


def test_loss_must_be_a_scalar(diff_backend):
    x = native(np.ones(3), diff_backend)
    with pytest.raises(ValueError, match="scalar"):
        ivy.execute_with_gradients(lambda x: x * 2.0, x)


def test_stop_gradient(diff_backend):
    xp = getattr(ivy, diff_backend)
    x = native(np.array([1.0, 3.0]), diff_backend)
    _, g = ivy.execute_with_gradients(lambda x: xp.sum(ivy.stop_gradient(x) * x), x)
    np.testing.assert_allclose(numpy_of(g), [1.0, 3.0], **F64)


def test_value_and_grad_and_grad(diff_backend):
    xp = getattr(ivy, diff_backend)
    v = {"a": native(np.array([1.0, 2.0]), diff_backend)}

    def func(v):
        return xp.sum(v["a"] ** 2)

    loss, grads = ivy.value_and_grad(func)(v)
    np.testing.assert_allclose(numpy_of(loss), 5.0, **F64)
    np.testing.assert_allclose(numpy_of(grads["a"]), [2.0, 4.0], **F64)
    grads = ivy.grad(lambda v: (func(v), "aux dropped"))(v)
    np.testing.assert_allclose(numpy_of(grads["a"]), [2.0, 4.0], **F64)
    # the framework from f=, from the namespace, or from the global framework
    grads = ivy.grad(func, f=diff_backend)(_to_numpy(v))
    assert is_native(grads["a"], diff_backend)
    assert is_native(xp.grad(func)(_to_numpy(v))["a"], diff_backend)
    with ivy.set_framework(diff_backend):
        assert is_native(ivy.grad(func)(_to_numpy(v))["a"], diff_backend)


def planar_arm(q, xp):
    """End point and orientation of a planar 3-link arm: (..., 3) joint angles -> (..., 3)."""
    lengths = (1.0, 0.7, 0.4)
    a1 = q[..., 0]
    a2 = a1 + q[..., 1]
    a3 = a2 + q[..., 2]
    px = lengths[0] * xp.cos(a1) + lengths[1] * xp.cos(a2) + lengths[2] * xp.cos(a3)
    py = lengths[0] * xp.sin(a1) + lengths[1] * xp.sin(a2) + lengths[2] * xp.sin(a3)
    return xp.stack([px, py, a3], axis=-1)


def rotation(theta, xp):
    """(..., 1) angle -> (..., 2, 2) rotation matrix scaled by the angle."""
    c, s = xp.cos(theta[..., 0]), xp.sin(theta[..., 0])
    r = xp.stack([xp.stack([c, -s], axis=-1), xp.stack([s, c], axis=-1)], axis=-2)
    return r * theta[..., :1, None]


def jacobian_fd(fn, x, batch_dims, h=1e-6):
    """Per-batch-element Jacobian of the numpy function ``fn`` by central differences."""
    x = np.asarray(x, dtype=np.float64)
    event = x.shape[batch_dims:]
    y = fn(x)
    jac = np.zeros(y.shape + event)
    for i in np.ndindex(event):
        dx = np.zeros(event)
        dx[i] = h
        d = (fn(x + dx) - fn(x - dx)) / (2 * h)
        jac[(..., *i)] = d
    return y, jac


JACOBIAN_METHODS = ("native", "replicate")


@pytest.mark.parametrize("method", JACOBIAN_METHODS)
@pytest.mark.parametrize("batch_shape", [(), (4,), (2, 3)])
def test_jacobian_of_batched_kinematics(diff_backend, batch_shape, method):
    xp = getattr(ivy, diff_backend)
    q = np.random.default_rng(1).uniform(-2, 2, size=(*batch_shape, 3))
    y, jac = ivy.execute_with_jacobian(
        lambda q: planar_arm(q, xp), native(q, diff_backend), method=method
    )
    y_ref, jac_ref = jacobian_fd(lambda q: planar_arm(q, NP), q, len(batch_shape))
    assert numpy_of(jac).shape == (*batch_shape, 3, 3)
    np.testing.assert_allclose(numpy_of(y), y_ref, **F64)
    np.testing.assert_allclose(numpy_of(jac), jac_ref, **FD)
    jac2 = ivy.jacobian(lambda q: planar_arm(q, xp), method=method)(native(q, diff_backend))
    np.testing.assert_allclose(numpy_of(jac2), numpy_of(jac), **F64)


@pytest.mark.parametrize("method", JACOBIAN_METHODS)
def test_jacobian_with_matrix_outputs_and_full_jacobian(diff_backend, method):
    xp = getattr(ivy, diff_backend)
    theta = np.array([[0.3], [-1.2], [2.0]])
    jac = ivy.jacobian(lambda t: rotation(t, xp), method=method)(native(theta, diff_backend))
    assert numpy_of(jac).shape == (3, 2, 2, 1)
    np.testing.assert_allclose(
        numpy_of(jac), jacobian_fd(lambda t: rotation(t, NP), theta, 1)[1], **FD
    )
    # batch_dims=0: the full Jacobian, also across batch elements
    m = np.array([[1.0, 2.0], [3.0, 4.0]])
    full = ivy.jacobian(lambda a: xp.matmul(a, a), batch_dims=0, method=method)(
        native(m, diff_backend)
    )
    assert numpy_of(full).shape == (2, 2, 2, 2)
    np.testing.assert_allclose(numpy_of(full), jacobian_fd(lambda a: a @ a, m, 0)[1], **FD)


def test_replicated_jacobian_is_differentiable(diff_backend):
    """retain_grads=True: the Jacobian's own gradient (second order) equals the native
    method's."""
    xp = getattr(ivy, diff_backend)
    q = native(np.random.default_rng(2).uniform(-2, 2, size=(4, 3)), diff_backend)

    def jac_sum(method):
        def loss(q):
            jac = ivy.jacobian(lambda q: planar_arm(q, xp), method=method, retain_grads=True)(q)
            return xp.sum(jac * jac)

        return loss

    grads = [numpy_of(ivy.grad(jac_sum(m))(q)) for m in JACOBIAN_METHODS]
    np.testing.assert_allclose(grads[1], grads[0], **F64)


def test_replicated_jacobian_compiles(graph_backend):
    xp = getattr(ivy, graph_backend)
    q = native(np.random.default_rng(2).uniform(-2, 2, size=(4, 3)), graph_backend)
    jac = ivy.jacobian(lambda q: planar_arm(q, xp), method="replicate")
    np.testing.assert_allclose(numpy_of(ivy.compile_fn(jac)(q)), numpy_of(jac(q)), **F64)


def test_replicated_jacobian_needs_a_func_of_any_batch(diff_backend):
    xp = getattr(ivy, diff_backend)
    x = native(np.ones((4, 3)), diff_backend)
    with pytest.raises(ValueError, match="new leading batch axis.*method='native'"):
        ivy.jacobian(lambda q: 2.0 * xp.reshape(q, (-1, 3))[-4:], method="replicate")(x)
    with pytest.raises(ValueError, match="'native' or 'replicate'"):
        ivy.jacobian(lambda q: q, method="forward")(x)


def test_jacobian_rejects_outputs_that_lose_the_batch(diff_backend):
    xp = getattr(ivy, diff_backend)
    with pytest.raises(ValueError, match="batch"):
        ivy.jacobian(lambda q: xp.sum(q, axis=0))(native(np.ones((4, 3)), diff_backend))


def test_numpy_raises_a_clear_error():
    v = {"w": np.ones(2)}
    for call in (
        lambda: ivy.execute_with_gradients(lambda v: np.sum(v["w"]), v),
        lambda: ivy.value_and_grad(lambda v: np.sum(v["w"]))(v),
        lambda: ivy.grad(lambda v: np.sum(v["w"]))(v),
        lambda: ivy.jacobian(lambda x: x)(np.ones(2)),
        lambda: ivy.jacobian(lambda x: x, method="replicate")(np.ones(2)),
    ):
        with pytest.raises(ivy.UnsupportedError, match="differentiable backend"):
            call()
    x = np.ones(2)
    assert ivy.stop_gradient(x) is x
    assert ivy.variable(x) is x


def _random(shape, seed, scale=1.0):
    return scale * np.random.default_rng(60 + seed).standard_normal(shape)


def test_attention_gradients(diff_backend):
    mask = np.tril(np.ones((3, 4), bool), k=1)

    def fn(q, k, v):
        return ivy.scaled_dot_product_attention(q, k, v, mask=native(mask, diff_backend))

    check_gradients(
        diff_backend, fn, [_random((2, 3, 5), 1), _random((2, 4, 5), 2), _random((2, 4, 2), 3)]
    )


def _network(x, w_conv, w_up, kernel, recurrent, q):
    y = ivy.relu(ivy.conv2d(x, w_conv, 2, "SAME"))
    y = ivy.max_pool2d(y, 2, 1, "SAME")
    up = ivy.conv2d_transpose(y, w_up, 2, "SAME", output_shape=(3, 4))
    seq = ivy.reshape(y, (2, 4, 4))
    hs, _ = ivy.lstm_update(seq, ivy.zeros_like(q), ivy.zeros_like(q), kernel, recurrent)
    att = ivy.scaled_dot_product_attention(hs, hs, hs)
    norm = ivy.layer_norm(att, scale=q[0], offset=q[1])
    return ivy.sum(up) + ivy.sum(ivy.log_softmax(norm)) + ivy.avg_pool1d(hs, 2, 2, "SAME")[0, 0, 0]


def test_compiled_matches_eager(graph_backend):
    """The nn functions inside the framework's own compiler (jax.jit, tf.function)."""
    shapes = [(2, 3, 4, 3), (3, 3, 3, 4), (3, 3, 2, 4), (4, 16), (4, 16), (2, 4)]
    arrays = [native(_random(s, i), graph_backend) for i, s in enumerate(shapes)]
    eager = _network(*arrays)
    compiled = native_compile(graph_backend, _network)(*arrays)
    check(compiled, numpy_of(eager), graph_backend, rtol=1e-10, atol=1e-10)


def test_gradients_under_torch_compile_with_a_graph_break_in_the_loss(request):
    """A loss that breaks torch.compile's graph (a print, a numpy call, the coverage recorder's
    wrappers): dynamo resumes execute_with_gradients after the break, and the gradients still
    come back with the structure of ``xs``."""
    if "torch" not in request.config.ivy_backends:
        pytest.skip("torch is not among the tested backends")
    import torch
    import torch._dynamo

    def step(v):
        def loss(v):
            torch._dynamo.graph_break()
            return ivy.sum(v["w"] ** 2) + ivy.sum(v["b"][0])

        return ivy.execute_with_gradients(loss, v)

    v = {"w": native(np.array([1.0, -2.0, 3.0]), "torch"), "b": [native(np.ones(2), "torch")]}
    loss, grads = torch.compile(step, backend="eager")(v)  # dynamo only: quick
    np.testing.assert_allclose(numpy_of(loss), 16.0, **F64)
    np.testing.assert_allclose(numpy_of(grads["w"]), [2.0, -4.0, 6.0], **F64)
    np.testing.assert_allclose(numpy_of(grads["b"][0]), [1.0, 1.0], **F64)
