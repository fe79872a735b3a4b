"""Optimizers against hand-computed numpy float64 updates, training to a fixed loss on every
differentiable backend, compiled training steps against eager ones, and the stateful forms."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from ivy import nest
from tests.compilers import native_compile
from tests.conftest import require
from tests.helpers import check, native, numpy_of, tolerance

# ----------------------------------------------------------------------------------------------
# Optimizer updates against numpy float64 (gradients are given: every backend, numpy included)
# ----------------------------------------------------------------------------------------------

SHAPES = {"layer": {"w": (3, 4), "b": (4,)}, "scale": (2,)}
STEPS = 3


def _random_nests(seed):
    rng = np.random.default_rng(seed)
    v = nest.map_nest(
        lambda s: rng.standard_normal(s),
        SHAPES,
    )
    grads = [nest.map_nest(lambda s: rng.standard_normal(s), SHAPES) for _ in range(STEPS)]
    return v, grads


def _is_shape(x):
    return isinstance(x, tuple) and all(isinstance(i, int) for i in x)


def _shapes_map(fn, *nests):
    """Map over nests of numpy arrays laid out like SHAPES (tuples of ints are leaves there)."""
    return nest.multi_map_nest(fn, *nests)


def np_sgd(p, gs, lr, momentum=0.0, nesterov=False, weight_decay=0.0):
    buf = np.zeros_like(p)
    for g in gs:
        g = g + weight_decay * p
        if momentum:
            buf = momentum * buf + g
            g = g + momentum * buf if nesterov else buf
        p = p - lr * g
    return p


def np_adam(p, gs, lr, b1=0.9, b2=0.999, eps=1e-8, weight_decay=0.0, decoupled=False):
    m, n = np.zeros_like(p), np.zeros_like(p)
    for t, g in enumerate(gs, start=1):
        lr_t = lr(t) if callable(lr) else lr
        if decoupled:
            p = p * (1 - lr_t * weight_decay)
        else:
            g = g + weight_decay * p
        m = b1 * m + (1 - b1) * g
        n = b2 * n + (1 - b2) * g**2
        m_hat, n_hat = m / (1 - b1**t), n / (1 - b2**t)
        p = p - lr_t * m_hat / (np.sqrt(n_hat) + eps)
    return p


CASES = {
    "sgd": (lambda: ivy.SGD(0.1), lambda p, gs: np_sgd(p, gs, 0.1)),
    "sgd_momentum_wd": (
        lambda: ivy.SGD(0.05, momentum=0.9, weight_decay=0.1),
        lambda p, gs: np_sgd(p, gs, 0.05, momentum=0.9, weight_decay=0.1),
    ),
    "sgd_nesterov": (
        lambda: ivy.SGD(0.05, momentum=0.8, nesterov=True),
        lambda p, gs: np_sgd(p, gs, 0.05, momentum=0.8, nesterov=True),
    ),
    "adam": (lambda: ivy.Adam(0.01), lambda p, gs: np_adam(p, gs, 0.01)),
    "adam_l2": (
        lambda: ivy.Adam(0.01, beta1=0.8, beta2=0.99, eps=1e-6, weight_decay=0.1),
        lambda p, gs: np_adam(p, gs, 0.01, 0.8, 0.99, 1e-6, weight_decay=0.1),
    ),
    "adamw": (
        lambda: ivy.AdamW(0.01, weight_decay=0.1),
        lambda p, gs: np_adam(p, gs, 0.01, weight_decay=0.1, decoupled=True),
    ),
    "adamw_schedule": (
        lambda: ivy.AdamW(lambda t: 0.02 / t, weight_decay=0.1),
        lambda p, gs: np_adam(p, gs, lambda t: 0.02 / t, weight_decay=0.1, decoupled=True),
    ),
}


@pytest.mark.parametrize("case", list(CASES))
def test_optimizer_step_matches_numpy(backend, case):
    make_opt, reference = CASES[case]
    v_np, grads_np = _random_nests(0)
    opt = make_opt()
    v = nest.map_nest(lambda a: native(a, backend), v_np)
    state = opt.init(v)
    check(state["step"], np.float64(0), backend)
    for g in grads_np:
        v, state = opt.step(v, nest.map_nest(lambda a: native(a, backend), g), state)
    check(state["step"], np.float64(STEPS), backend)
    expected = nest.multi_map_nest(lambda p, *gs: reference(p, gs), v_np, *grads_np)
    nest.multi_map_nest(lambda a, b: check(a, b, backend, **tolerance("float64", 10)), v, expected)


def test_optimizer_state_is_a_nest(backend):
    v = {
        "a": native(np.ones((2, 3), np.float32), backend),
        "b": {"c": native(np.ones(2, np.float32), backend)},
    }
    state = ivy.Adam().init(v)
    assert sorted(state) == ["mu", "nu", "step"]
    check(state["step"], np.float32(0), backend)
    check(state["mu"]["b"]["c"], np.zeros(2, np.float32), backend)
    assert sorted(ivy.SGD(0.1).init(v)) == ["step"]
    assert sorted(ivy.SGD(0.1, momentum=0.9).init(v)) == ["momentum", "step"]


def test_optimizer_checks_grads_structure(backend):
    v = {"a": native(np.ones(2), backend), "b": native(np.ones(2), backend)}
    opt = ivy.SGD(0.1)
    with pytest.raises(ValueError, match="structure of v"):
        opt.step(v, {"a": v["a"]}, opt.init(v))


def test_optimizer_state_round_trips_through_a_checkpoint(backend, tmp_path):
    v_np, grads_np = _random_nests(1)
    opt = ivy.Adam(0.01)
    v = nest.map_nest(lambda a: native(a, backend), v_np)
    v, state = opt.step(v, nest.map_nest(lambda a: native(a, backend), grads_np[0]), opt.init(v))
    ivy.save_weights(tmp_path / "state.npz", state)
    loaded = ivy.load_weights(tmp_path / "state.npz", like=opt.init(v))
    nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), backend, rtol=0, atol=0), loaded, state)


# ----------------------------------------------------------------------------------------------
# Training
# ----------------------------------------------------------------------------------------------


def _regression_data(n=64):
    rng = np.random.default_rng(0)
    x = rng.uniform(-1, 1, (n, 2)).astype(np.float32)
    y = (np.sin(2 * x[:, :1]) * x[:, 1:] + 0.5 * x[:, :1]).astype(np.float32)
    return x, y


def test_mlp_regression_trains_to_a_fixed_loss(diff_backend):
    x_np, y_np = _regression_data()
    x, y = native(x_np, diff_backend), native(y_np, diff_backend)
    ivy.seed(0)
    model = ivy.MLP(2, (16, 16), 1, activation="tanh", device="cpu", f=diff_backend)
    opt = ivy.Adam(0.02)
    losses = [
        float(numpy_of(opt.minimize(model, lambda v: ivy.mse(model(x, v=v), y))))
        for _ in range(200)
    ]
    assert losses[0] > 0.1
    assert max(losses[-10:]) < 5e-3, f"{diff_backend}: loss {losses[0]:.4f} -> {losses[-1]:.5f}"
    final = float(numpy_of(ivy.mse(model(x), y)))  # the module's own, updated variables
    assert final < 2e-3, f"{diff_backend}: final loss {final:.5f}"


def _step_case(backend):
    x_np, y_np = _regression_data(32)
    x, y = native(x_np, backend), native(y_np, backend)
    ivy.seed(0)
    model = ivy.MLP(2, (16, 16), 1, device="cpu", f=backend)
    opt = ivy.AdamW(0.01, weight_decay=0.01)

    def loss_fn(v, x, y):
        return ivy.mse(model(x, v=v), y)

    return model, opt, loss_fn, x, y


def _torch_graph_counter():
    """Clears dynamo's counters; the check then asserts that forward, autograd.grad and the
    update formed one graph, with no break around the gradients."""
    import torch._dynamo

    counters = torch._dynamo.utils.counters
    counters.clear()

    def check_one_graph():
        assert dict(counters["graph_break"]) == {}
        assert counters["stats"]["unique_graphs"] == 1

    return check_one_graph


# Compilers that report their graphs: backend -> a function that starts counting and returns the
# check that the compiled step was one graph (a new backend with such a report adds its row).
ONE_GRAPH = {"torch": _torch_graph_counter}


# A slow compiler's first call (torch.compile) takes many seconds: its single case lives here.
def test_compiled_training_step_equals_eager(request, backend):
    require(backend, "compilation")
    require(backend, "autodiff")
    model, opt, loss_fn, x, y = _step_case(backend)
    eager = opt.training_step(loss_fn)
    compiled = opt.training_step(loss_fn, compile=True)
    v_e = v_c = model.v
    s_e = s_c = opt.init(model.v)
    check_one_graph = ONE_GRAPH[backend]() if backend in ONE_GRAPH else None
    for _ in range(3):
        loss_e, v_e, s_e = eager(v_e, s_e, x, y)
        loss_c, v_c, s_c = compiled(v_c, s_c, x, y)
        check(loss_c, numpy_of(loss_e), backend, rtol=1e-5, atol=1e-6)
    tol = dict(rtol=1e-4, atol=1e-6)
    nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), backend, **tol), v_c, v_e)
    nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), backend, **tol), s_c, s_e)
    instrumented = any(  # scripts/coverage_table.py's wrappers break graphs of their own
        getattr(p, "wraps_backend_functions", False)
        for p in request.config.pluginmanager.get_plugins()
    )
    if check_one_graph is not None and not instrumented:
        check_one_graph()


def test_stateful_forms_equal_the_functional_step(diff_backend):
    model, opt, loss_fn, x, y = _step_case(diff_backend)
    v0 = model.v
    loss_f, v_f, s_f = opt.training_step(loss_fn)(v0, opt.init(v0), x, y)
    # update(): gradients computed by the caller
    loss, grads = ivy.execute_with_gradients(lambda v: loss_fn(v, x, y), model.v)
    opt.update(model, grads)
    nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), diff_backend), model.v, v_f)
    # minimize(): a second step continues from the kept state
    loss_f2, v_f2, _ = opt.training_step(loss_fn)(v_f, s_f, x, y)
    loss2 = opt.minimize(model, lambda v: loss_fn(v, x, y))
    check(loss2, numpy_of(loss_f2), diff_backend)
    nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), diff_backend), model.v, v_f2)
    check(opt.state["step"], np.float32(2), diff_backend)
    # a new module gets a fresh state
    other = ivy.MLP(2, (16, 16), 1, device="cpu", f=diff_backend)
    opt.minimize(other, lambda v: loss_fn(v, x, y))
    check(opt.state["step"], np.float32(1), diff_backend)


def test_module_step_equals_the_functional_step(diff_backend):
    _check_module_step(diff_backend, compile=False)


def test_compiled_module_step_equals_the_functional_step(graph_backend):
    # torch compiles a training step in test_compiled_training_step_equals_eager
    _check_module_step(graph_backend, compile=True)


def _check_module_step(backend, compile):
    model, opt, loss_fn, x, y = _step_case(backend)
    step = opt.training_step(loss_fn)
    v, state = model.v, opt.init(model.v)
    train = opt.module_step(model, loss_fn, compile=compile)
    tol = dict(rtol=1e-4, atol=1e-6) if compile else {}
    for i in range(3):
        loss, v, state = step(v, state, x, y)
        check(train(x, y), numpy_of(loss), backend, **tol)
        nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), backend, **tol), model.v, v)
        if i == 1:  # an eager update in between: the bound step continues from it
            loss, v, state = step(v, state, x, y)
            opt.minimize(model, lambda w: loss_fn(w, x, y))
    nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), backend, **tol), opt.state, state)
    check(opt.state["step"], np.float32(4), backend)
    check(model(x), numpy_of(model(x, v=v)), backend, **tol)


def test_minimize_returns_aux(diff_backend):
    model, opt, loss_fn, x, y = _step_case(diff_backend)

    def with_aux(v):
        pred = model(x, v=v)
        return ivy.mse(pred, y), pred

    loss, pred = opt.minimize(model, with_aux)
    check(pred, numpy_of(pred), diff_backend)
    assert tuple(numpy_of(pred).shape) == (32, 1)


def test_training_inside_the_frameworks_own_compiler(graph_backend):
    """The functional training step compiled by the framework itself (jax.jit, tf.function),
    not by ivy.compile_fn."""
    model, opt, loss_fn, x, y = _step_case(graph_backend)
    step = native_compile(graph_backend, opt.training_step(loss_fn))
    eager = opt.training_step(loss_fn)
    v, s = model.v, opt.init(model.v)
    loss_c, v_c, _ = step(v, s, x, y)
    loss_e, v_e, _ = eager(v, s, x, y)
    tol = dict(rtol=1e-4, atol=1e-6)
    check(loss_c, numpy_of(loss_e), graph_backend, rtol=1e-5, atol=1e-6)
    nest.multi_map_nest(lambda a, b: check(a, numpy_of(b), graph_backend, **tol), v_c, v_e)
