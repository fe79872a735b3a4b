"""Tests of the core group ``control_flow`` (``ivy/core/control_flow.py``), on every backend.

Control flow (``ivy.scan``, ``fori_loop``, ``while_loop``, ``cond``) against plain Python loops
in numpy float64, eagerly on every backend and compiled (jax, tensorflow; torch.compile once,
cached), with gradients against central finite differences on the differentiable backends.

Each loop body is written once against an Array API namespace ``xp``: the reference runs it with
numpy itself in a plain Python loop written here; the test runs it with ``ivy.<backend>`` inside
ivy's control flow.
"""

from __future__ import annotations

import functools
import inspect
import warnings

import numpy as np
import pytest

import ivy
from ivy import nest
from ivy.framework_handler import capabilities
from tests.conftest import capable, require
from tests.helpers import check_gradients, is_native, native, numpy_of

TOL = dict(rtol=1e-12, atol=1e-12)


COMPILED_TOL = dict(rtol=1e-10, atol=1e-12)  # XLA and graph mode may fuse differently


_data = np.random.default_rng(12)  # constants only; tests: the rng fixture


def _on(backend, tree):
    return nest.map_nest(lambda a: native(np.asarray(a), backend), tree)


def _numpy(tree):
    return nest.map_nest(numpy_of, tree)


def _assert_same(actual, expected, backend, tol=TOL):
    assert nest.nest_structure(actual) == nest.nest_structure(expected), (actual, expected)
    for a, e in zip(nest.nest_leaves(actual), nest.nest_leaves(expected)):
        assert is_native(a, backend), type(a)
        np.testing.assert_allclose(numpy_of(a), e, **tol)


W_IN, W_REC = _data.normal(size=(4, 3)) * 0.5, _data.normal(size=(3, 3)) * 0.5


def cumulative(xp, consts):
    def step(c, x):
        return c + x, c * x

    return step


def rnn(xp, consts):
    w_in, w_rec = consts

    def step(h, x):
        h = xp.tanh(xp.matmul(x, w_in) + xp.matmul(h, w_rec))
        return h, {"h": h, "energy": xp.sum(h * h, axis=-1)}

    return step


def particle(xp, consts):
    """Semi-implicit Euler of a damped particle: a dict carry, a tuple of inputs, no outputs."""

    def step(state, inputs):
        force, dt = inputs
        vel = state["vel"] + dt * (force - 0.3 * state["vel"])
        return {"pos": state["pos"] + dt * vel, "vel": vel}, None

    return step


def fibonacci(xp, consts):
    """No inputs (``xs=None``, ``length=``): a tuple carry."""

    def step(c, x):
        a, b = c
        return (b, a + b), a

    return step


SCAN_CASES = {
    "cumulative": (cumulative, (), np.float64(0.5), _data.normal(size=6), None),
    "rnn": (rnn, (W_IN, W_REC), _data.normal(size=(2, 3)), _data.normal(size=(5, 2, 4)), None),
    "particle": (
        particle,
        (),
        {"pos": _data.normal(size=3), "vel": _data.normal(size=3)},
        (_data.normal(size=(7, 3)), np.abs(_data.normal(size=(7, 1))) * 0.1),
        None,
    ),
    "fibonacci": (fibonacci, (), (np.float64(0.0), np.float64(1.0)), None, 9),
}


def reference_scan(name):
    """The case run with numpy in a plain Python loop."""
    make, consts, init, xs, length = SCAN_CASES[name]
    step = make(np, consts)
    steps = length if xs is None else len(nest.nest_leaves(xs)[0])
    carry, ys = init, []
    for t in range(steps):
        x = None if xs is None else nest.map_nest(lambda a, t=t: a[t], xs)
        carry, y = step(carry, x)
        ys.append(y)
    stacked = nest.multi_map_nest(lambda *v: np.stack(v), ys[0], *ys[1:])
    return carry, stacked


def run_scan(name, backend, unroll=1):
    make, consts, init, xs, length = SCAN_CASES[name]
    xp = getattr(ivy, backend)
    step = make(xp, _on(backend, consts))
    return ivy.scan(step, _on(backend, init), _on(backend, xs), length, unroll)


@pytest.mark.parametrize("name", sorted(SCAN_CASES))
def test_scan_equals_a_python_loop(name, backend):
    _assert_same(run_scan(name, backend), reference_scan(name), backend)


@pytest.mark.parametrize("unroll", [1, 3, True])
@pytest.mark.parametrize("name", sorted(SCAN_CASES))
def test_compiled_scan_equals_a_python_loop(name, unroll, graph_backend):
    make, consts, init, xs, length = SCAN_CASES[name]
    xp = getattr(ivy, graph_backend)
    step = make(xp, _on(graph_backend, consts))
    compiled = ivy.compile_fn(lambda init, xs: ivy.scan(step, init, xs, length, unroll))
    out = compiled(_on(graph_backend, init), _on(graph_backend, xs))
    _assert_same(out, reference_scan(name), graph_backend, COMPILED_TOL)


def test_scan_in_the_backend_namespace_and_with_f(backend):
    xp = getattr(ivy, backend)
    expected = reference_scan("fibonacci")
    step = fibonacci(xp, ())
    init = (0.0, 1.0)  # Python floats: the framework comes from f
    for out in (xp.scan(step, _on(backend, init), None, 9), ivy.scan(step, init, length=9, f=xp)):
        carry, ys = out
        np.testing.assert_allclose(float(numpy_of(carry[1])), expected[0][1])
        np.testing.assert_allclose(numpy_of(ys), expected[1], rtol=1e-6)


def test_inputs_of_another_framework_are_converted_with_f(backend):
    step = cumulative(np, ())
    carry, ys = ivy.scan(step, native(np.float64(0.5), backend), np.arange(3.0), f=backend)
    assert is_native(carry, backend) and is_native(ys, backend)
    np.testing.assert_allclose(numpy_of(ys), [0.0, 0.5, 3.0])  # c * x, c += x


def test_scan_of_no_steps_returns_empty_outputs(backend):
    make, consts, init, xs, _ = SCAN_CASES["rnn"]
    xp = getattr(ivy, backend)
    carry, ys = ivy.scan(make(xp, _on(backend, consts)), _on(backend, init), _on(backend, xs[:0]))
    np.testing.assert_array_equal(numpy_of(carry), init)
    assert numpy_of(ys["h"]).shape == (0, 2, 3) and numpy_of(ys["energy"]).shape == (0, 2)


def counted(step, traces):
    """``step``, appending to ``traces`` each time it runs (in Python: eagerly, or tracing)."""

    def counting(c, x):
        traces.append(None)
        return step(c, x)

    return counting


def rnn_outputs(backend, traces=None):
    """The rnn case as a function of (init, xs, w_in, w_rec) -> all outputs, one array; its body
    counts its runs in ``traces`` (a list) if given."""
    xp = getattr(ivy, backend)

    def fn(h0, xs, w_in, w_rec):
        step = rnn(xp, (w_in, w_rec))
        h, ys = ivy.scan(step if traces is None else counted(step, traces), h0, xs)
        return xp.concat([xp.reshape(h, (-1,)), xp.reshape(ys["h"], (-1,)), ys["energy"][-1]])

    return fn


def test_scan_gradients_equal_finite_differences(diff_backend):
    _, consts, init, xs, _ = SCAN_CASES["rnn"]
    check_gradients(diff_backend, rnn_outputs(diff_backend), [init, xs, *consts], n_directions=2)


def _loss_and_grads(backend, args, traces=None):
    fn = rnn_outputs(backend, traces)

    def loss(v):
        return ivy.sum(fn(*v) ** 2)

    loss_value, grads = ivy.execute_with_gradients(loss, list(args))
    return loss_value, grads


@functools.cache
def compiled_loss_and_grads(backend):
    """The compiled rnn loss and gradients, and the list of its body's traces."""
    traces = []
    return ivy.compile_fn(lambda *args: _loss_and_grads(backend, args, traces)), traces


def test_compiled_scan_gradients_equal_eager(backend):
    require(backend, "compilation")  # torch.compile: once, here (cached)
    _, consts, init, xs, _ = SCAN_CASES["rnn"]
    args = _on(backend, [init, xs, *consts])
    eager = _loss_and_grads(backend, args)
    compiled, traces = compiled_loss_and_grads(backend)
    _assert_same(compiled(*args), _numpy(eager), backend, COMPILED_TOL)
    # the capability says whether the compiler keeps the loop (its body traced once or twice)
    # or unrolls it (traced once per step, 5 here, or more)
    assert (len(traces) < len(xs)) == capabilities(backend).compiled_loops, len(traces)


RATES = _data.uniform(0.5, 1.5, size=6)


def growth(xp, rates):
    """``val`` grows by ``rates[i]`` at step ``i``: the body indexes with ``i``."""

    def body(i, val):
        return {"x": val["x"] * rates[i] + 0.1, "sum": val["sum"] + val["x"]}

    return body


def reference_fori(lower, upper, x0):
    body, val = growth(np, RATES), {"x": x0, "sum": np.zeros_like(x0)}
    for i in range(lower, upper):
        val = body(i, val)
    return val


@pytest.mark.parametrize("lower,upper", [(0, 6), (2, 5), (3, 3)])
def test_fori_loop_equals_a_python_loop(rng, lower, upper, backend):
    x0 = rng.normal(size=3)
    init = _on(backend, {"x": x0, "sum": np.zeros(3)})
    out = ivy.fori_loop(lower, upper, growth(getattr(ivy, backend), _on(backend, RATES)), init)
    _assert_same(out, reference_fori(lower, upper, x0), backend)


def test_compiled_fori_loop_and_its_gradients(rng, graph_backend):
    x0 = rng.normal(size=3)
    rates = _on(graph_backend, RATES)
    body = growth(getattr(ivy, graph_backend), rates)

    def run(x):
        return ivy.fori_loop(1, 5, body, {"x": x, "sum": ivy.zeros_like(x)})

    out = ivy.compile_fn(run)(_on(graph_backend, x0))
    _assert_same(out, reference_fori(1, 5, x0), graph_backend, COMPILED_TOL)
    check_gradients(graph_backend, lambda x: run(x)["sum"], [x0])


def test_fori_loop_gradients_equal_finite_differences(rng, diff_backend):
    xp = getattr(ivy, diff_backend)

    def fn(x0, rates):
        val = ivy.fori_loop(0, 6, growth(xp, rates), {"x": x0, "sum": xp.zeros_like(x0)})
        return xp.concat([val["x"], val["sum"]])

    check_gradients(diff_backend, fn, [rng.normal(size=3), RATES])


def newton(xp, a):
    """Newton's iteration for sqrt(a), with a step counter in the carry."""

    def keep_going(val):
        return val[1] < 4

    def body(val):
        x, n = val
        return 0.5 * (x + a / x), n + 1

    return keep_going, body


def reference_newton(a, x0, limit=None):
    keep_going, body = newton(np, a)
    val, steps = (x0, np.int64(0)), 0
    while keep_going(val) and (limit is None or steps < limit):
        val, steps = body(val), steps + 1
    return val


@pytest.mark.parametrize("limit", [None, 2, 10])
def test_while_loop_equals_a_python_loop(rng, limit, backend):
    a, x0 = rng.uniform(1, 4, size=3), np.ones(3)
    keep_going, body = newton(getattr(ivy, backend), native(a, backend))
    init = (native(x0, backend), native(np.int64(0), backend))
    out = ivy.while_loop(keep_going, body, init, maximum_iterations=limit)
    _assert_same(out, reference_newton(a, x0, limit), backend)


@pytest.mark.parametrize("limit", [None, 2, 10])
def test_compiled_while_loop_equals_a_python_loop(rng, limit, graph_backend):
    a, x0 = rng.uniform(1, 4, size=3), np.ones(3)
    keep_going, body = newton(getattr(ivy, graph_backend), native(a, graph_backend))

    def run(x, n):
        return ivy.while_loop(keep_going, body, (x, n), maximum_iterations=limit)

    out = ivy.compile_fn(run)(native(x0, graph_backend), native(np.int64(0), graph_backend))
    _assert_same(out, reference_newton(a, x0, limit), graph_backend, COMPILED_TOL)


def test_while_loop_with_maximum_iterations_is_differentiable(rng, diff_backend):
    xp = getattr(ivy, diff_backend)

    def fn(a, x0):
        keep_going, body = newton(xp, a)
        zero = ivy.asarray(np.int64(0), f=xp)
        return ivy.while_loop(keep_going, body, (x0, zero), maximum_iterations=10)[0]

    check_gradients(diff_backend, fn, [rng.uniform(1, 4, size=3), np.ones(3) * 1.5])


def test_jax_while_loop_without_maximum_iterations_refuses_reverse_mode(request):
    if "jax" not in request.config.ivy_backends:
        pytest.skip("jax not selected")
    keep_going, body = newton(ivy.jax, 2.0)

    def value_and_grads(x0):
        def fn(x0):
            return ivy.sum(ivy.while_loop(keep_going, body, (x0, ivy.asarray(0, f="jax")))[0])

        return ivy.execute_with_gradients(fn, x0)

    x0 = native(np.ones(2), "jax")
    for run in (value_and_grads, ivy.compile_fn(value_and_grads)):  # eager (traced x0), compiled
        with pytest.raises(ValueError, match="Reverse-mode differentiation does not work"):
            run(x0)


def branches(xp):
    def grow(x, scale):
        return {"y": x * scale["k"], "norm": xp.sum(x * x)}

    def shrink(x, scale):
        return {"y": x / scale["k"], "norm": -xp.sum(xp.abs(x))}

    return grow, shrink


@pytest.mark.parametrize("take", [True, False])
def test_cond_takes_the_selected_branch(rng, take, backend):
    x, k = rng.normal(size=3), 1.7
    grow, shrink = branches(getattr(ivy, backend))
    expected = (branches(np)[0] if take else branches(np)[1])(x, {"k": k})
    pred = native(np.asarray(take), backend)
    out = ivy.cond(pred, grow, shrink, native(x, backend), {"k": native(np.float64(k), backend)})
    _assert_same(out, expected, backend)
    # a Python bool selects in Python
    out = ivy.cond(take, grow, shrink, native(x, backend), {"k": native(np.float64(k), backend)})
    _assert_same(out, expected, backend)


def test_compiled_cond_and_its_gradients(rng, graph_backend):
    grow, shrink = branches(getattr(ivy, graph_backend))
    x, k = rng.normal(size=3), np.float64(1.7)

    def fn(x, k):
        out = ivy.cond(ivy.sum(x) > 0, grow, shrink, x, {"k": k})
        return ivy.concat([out["y"], ivy.reshape(out["norm"], (1,))])

    compiled = ivy.compile_fn(fn)
    for sign in (1.0, -1.0):
        xs = sign * np.abs(x)
        expected = (branches(np)[0] if sign > 0 else branches(np)[1])(xs, {"k": k})
        out = compiled(native(xs, graph_backend), native(k, graph_backend))
        np.testing.assert_allclose(numpy_of(out), [*expected["y"], expected["norm"]], **TOL)
        check_gradients(graph_backend, fn, [xs, k])


def test_cond_gradients_equal_finite_differences(diff_backend):
    grow, shrink = branches(getattr(ivy, diff_backend))

    def fn(x, k):
        return ivy.cond(ivy.sum(x) > 0, grow, shrink, x, {"k": k})["y"]

    check_gradients(diff_backend, fn, [np.array([0.3, -0.1, 0.5]), np.float64(2.0)])
    check_gradients(diff_backend, fn, [np.array([-0.3, -0.1, 0.5]), np.float64(2.0)])


def noisy_scan(backend, init=None):
    def step(c, x):
        noise = ivy.random_uniform(shape=(2,), dtype="float64", f=backend)
        return c + noise, noise

    return ivy.scan(step, native(np.zeros(2), backend) if init is None else init, None, 4)


def test_random_draws_in_a_scan_body_differ_per_step_and_repeat_after_seed(backend):
    ivy.seed(3)
    first = _numpy(noisy_scan(backend))
    second = _numpy(noisy_scan(backend))
    ivy.seed(3)
    again = _numpy(noisy_scan(backend))
    draws = first[1]
    assert len({tuple(row) for row in draws}) == 4  # a fresh draw at every step
    assert not np.array_equal(draws, second[1])  # and at every call
    np.testing.assert_array_equal(draws, again[1])
    np.testing.assert_allclose(first[0], draws.sum(0), **TOL)


def test_random_draws_in_a_compiled_scan_body_differ_per_step_and_call(graph_backend):
    compiled = ivy.compile_fn(lambda init: noisy_scan(graph_backend, init))
    init = native(np.zeros(2), graph_backend)  # traced: jax runs lax.scan, threading the key
    ivy.seed(4)
    first, second = _numpy(compiled(init)), _numpy(compiled(init))
    ivy.seed(4)
    again = _numpy(compiled(init))
    assert len({tuple(row) for row in first[1]}) == 4
    assert not np.array_equal(first[1], second[1])
    np.testing.assert_array_equal(first[1], again[1])


def test_a_jitted_scan_before_any_seed_leaves_a_concrete_key(request):
    if "jax" not in request.config.ivy_backends:
        pytest.skip("jax not selected")
    import jax

    from ivy.backends.jax import random as jax_random

    saved = jax_random._state.saved()
    jax_random._state.restore((None, None))  # as in a new process: never seeded
    try:
        step = jax.jit(lambda x: ivy.scan(lambda c, _: (c + 1.0, c), x, None, 3))
        np.testing.assert_array_equal(numpy_of(step(native(np.zeros(2), "jax"))[0]), 3.0)
        assert not isinstance(jax_random._state.data, jax.core.Tracer)
        assert numpy_of(ivy.random_uniform(shape=(2,), f="jax")).shape == (2,)
    finally:
        jax_random._state.restore(saved)


def test_scan_refuses_a_carry_that_changes_shape_or_dtype(backend):
    x = native(np.zeros(3), backend)
    with pytest.raises(TypeError, match="carry"):
        ivy.scan(lambda c, _: (ivy.concat([c, c]), None), x, None, 2)
    with pytest.raises(TypeError, match="carry"):
        ivy.scan(lambda c, _: (ivy.astype(c, "float32"), None), x, None, 2)
    with pytest.raises(TypeError, match="carry"):
        ivy.scan(lambda c, _: ((c, c), None), x, None, 2)


def test_scan_refuses_inconsistent_lengths(backend):
    xs = (native(np.zeros((3, 2)), backend), native(np.zeros((4, 2)), backend))
    init = native(np.zeros(2), backend)
    with pytest.raises(ValueError):
        ivy.scan(lambda c, x: (c, None), init, xs)
    with pytest.raises(ValueError):
        ivy.scan(lambda c, x: (c, None), init, xs[0], length=5)
    with pytest.raises(ValueError):
        ivy.scan(lambda c, x: (c, None), init)


def test_predicates_must_be_scalars(backend):
    x = native(np.ones(3), backend)
    with pytest.raises(ValueError, match="scalar"):
        ivy.while_loop(lambda v: v < 2, lambda v: v * 2, x)
    with pytest.raises(ValueError, match="scalar"):
        ivy.cond(x > 0, lambda v: v, lambda v: -v, x)


def test_compiled_cond_refuses_branches_of_different_structures(graph_backend):
    def fn(x):
        return ivy.cond(ivy.sum(x) > 0, lambda v: (v, v), lambda v: v, x)

    with pytest.raises(TypeError):
        ivy.compile_fn(fn)(native(np.ones(2), graph_backend))


def test_signatures_end_with_keyword_only_f():
    for name in ("scan", "fori_loop", "while_loop", "cond"):
        params = inspect.signature(getattr(ivy, name)).parameters
        f = list(params.values())[-1]
        assert f.name == "f" and f.kind is f.KEYWORD_ONLY and f.default is None
        assert all(p.annotation is not p.empty for p in params.values() if p.name != "f")
    assert str(inspect.signature(ivy.scan)).startswith("(fn:")


def test_compile_without_a_compiler_warns_and_runs_loops_in_python(backend):
    if capable(backend, "compilation"):
        pytest.skip(f"{backend} has a compiler")
    traces = []
    step = counted(cumulative(getattr(ivy, backend), ()), traces)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        compiled = ivy.compile_fn(lambda x: ivy.scan(step, x, _on(backend, np.ones(3))))
        carry, _ = compiled(_on(backend, np.float64(0.0)))
    assert float(carry) == 3.0
    assert any(f"{backend} has no compiler" in str(w.message) for w in caught)
    assert len(traces) == 3 and not capabilities(backend).compiled_loops


del _data  # no test draws from a generator shared by the module
