"""Tests of the core group ``compilation`` (``ivy/core/compilation.py``), on every backend.

ivy.compile_fn: compiled results equal eager results, on every backend, including a whole
training step (loss, gradients, SGD update). torch.compile is slow to start, so torch compiles
two functions here: the training step, cached for the module and reused, and a writer of rows
given ``donate_argnums`` (donation: jax reuses the donated buffers; elsewhere it changes nothing).
"""

from __future__ import annotations

import functools
import warnings

import numpy as np
import pytest

import ivy
from ivy import nest
from tests.conftest import capable, require
from tests.helpers import is_native, native, numpy_of

COMPILED_TOL = dict(rtol=1e-10, atol=1e-12)  # float64; XLA and graph mode may fuse differently


_data = np.random.default_rng(3)  # constants only; tests: the rng fixture


PARAMS = {"w": _data.normal(size=(3, 2)), "b": _data.normal(size=2) * 0.1}


BATCH = (_data.normal(size=(8, 3)), _data.normal(size=(8, 2)))


def loss_fn(v, x, y):
    pred = ivy.tanh(ivy.matmul(x, v["w"]) + v["b"])
    return ivy.mean((pred - y) ** 2), pred


def train_step(v, x, y, lr=0.1):
    """One SGD step, written by hand with ivy.nest (the optimizers live in ivy.stateful)."""
    loss, grads, pred = ivy.execute_with_gradients(lambda v: loss_fn(v, x, y), v)
    v = nest.multi_map_nest(lambda p, g: p - lr * g, v, grads)
    return loss, v


@functools.cache
def compiled_train_step(backend):
    return ivy.compile_fn(train_step)


def _on(backend, n):
    return nest.map_nest(lambda a: native(np.asarray(a, dtype=np.float64), backend), n)


def _check_same(compiled, eager, backend):
    assert nest.nest_structure(compiled) == nest.nest_structure(eager)
    for c, e in zip(nest.nest_leaves(compiled), nest.nest_leaves(eager)):
        assert is_native(c, backend)
        np.testing.assert_allclose(numpy_of(c), numpy_of(e), **COMPILED_TOL)


def test_compiled_training_step_equals_eager(backend):
    require(backend, "compilation")
    require(backend, "autodiff")
    step = compiled_train_step(backend)
    x, y = _on(backend, BATCH)
    v_compiled = v_eager = _on(backend, PARAMS)
    losses = []
    for _ in range(3):
        loss_c, v_compiled = step(v_compiled, x, y)
        loss_e, v_eager = train_step(v_eager, x, y)
        _check_same((loss_c, v_compiled), (loss_e, v_eager), backend)
        losses.append(float(numpy_of(loss_c)))
    assert losses[2] < losses[0]  # it trains


def model(v, x, *, scale):
    h = ivy.tanh(ivy.matmul(x, v["w"]) + v["b"])
    return {
        "out": h * scale,
        "norm": ivy.sum(ivy.sin(x) ** 2, axis=-1),
        "parts": (h[0], ivy.permute_dims(x, (1, 0))),
    }


def test_compiled_equals_eager(backend):
    if capable(backend, "compilation") and not capable(backend, "fast_graph"):
        # a slow compiler (torch.compile): one case, reused: the training step
        step = compiled_train_step(backend)
        args = (_on(backend, PARAMS), *_on(backend, BATCH))
        _check_same(step(*args), train_step(*args), backend)
        return
    v, (x, _) = _on(backend, PARAMS), _on(backend, BATCH)
    compiled = ivy.compile_fn(model)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # numpy, at the first call: "no compiler"
        for scale in (2.0, 3.0):
            _check_same(compiled(v, x, scale=scale), model(v, x, scale=scale), backend)


def test_static_arguments(graph_backend):
    def tiled(x, n, *, axis=0):
        return ivy.concat([x] * n, axis=axis)  # n decides the shape: a compile-time constant

    x = native(np.arange(3.0), graph_backend)
    by_num = ivy.compile_fn(tiled, static_argnums=1, static_argnames="axis")
    by_name = ivy.compile_fn(tiled, static_argnames=("n", "axis"))
    for fn in (by_num, by_name):
        for n in (2, 3):
            np.testing.assert_array_equal(numpy_of(fn(x, n)), np.tile(np.arange(3.0), n))
        np.testing.assert_array_equal(numpy_of(fn(x, n=2, axis=0)), np.tile(np.arange(3.0), 2))


def test_framework_is_resolved_at_the_first_call(graph_backend):
    traced = []

    def double(x):
        traced.append(type(x))
        return x * 2

    compiled = ivy.compile_fn(double)
    assert traced == []  # nothing happens before the first call
    x = native(np.arange(3.0), graph_backend)
    out = compiled(x)
    assert is_native(out, graph_backend)
    assert traced[0] is not type(x)  # traced: a symbolic array, not the concrete input
    compiled(native(np.arange(3.0), graph_backend))
    assert len(traced) == 1  # compiled once, called twice
    # an explicit framework compiles at once; numpy inputs are then converted
    eager = ivy.compile_fn(double, f=graph_backend)(np.arange(3.0))
    assert is_native(eager, graph_backend)
    assert tuple(getattr(ivy, graph_backend).compile_fn(double)(np.arange(3.0)).shape) == (3,)


def test_compiled_function_without_arrays_needs_a_framework():
    compiled = ivy.compile_fn(lambda n: n + 1)
    with pytest.raises(ivy.NoFrameworkError):
        compiled(1)


def test_without_a_compiler_warns_and_returns_the_function(backend):
    if capable(backend, "compilation"):
        pytest.skip(f"{backend} has a compiler")

    def fn(x):
        return x + 1

    with pytest.warns(UserWarning, match=f"{backend} has no compiler"):
        assert ivy.compile_fn(fn, f=backend) is fn
    lazy = ivy.compile_fn(fn)
    with pytest.warns(UserWarning, match=f"{backend} has no compiler"):
        np.testing.assert_array_equal(numpy_of(lazy(native(np.zeros(2), backend))), [1.0, 1.0])


def test_torch_falls_back_to_eager_when_compile_cannot_run(request, monkeypatch):
    if "torch" not in request.config.ivy_backends:
        pytest.skip("torch not selected")
    import torch

    def broken_compile(fn, **kwargs):
        def run(*args, **kw):
            raise torch._dynamo.exc.BackendCompilerFailed(
                run, RuntimeError("no C++ compiler found"), None
            )

        return run

    monkeypatch.setattr(torch, "compile", broken_compile)
    compiled = ivy.compile_fn(lambda x: x * 3, f="torch")
    with pytest.warns(RuntimeWarning, match="runs the function eagerly"):
        out = compiled(torch.ones(2))
    assert torch.equal(out, torch.full((2,), 3.0))
    assert torch.equal(compiled(torch.ones(2)), torch.full((2,), 3.0))  # stays eager, silently

    monkeypatch.setattr(torch._dynamo, "is_dynamo_supported", lambda: False)
    with pytest.warns(RuntimeWarning, match="does not support"):
        fn = ivy.torch.compile_fn(torch.sin)
    assert fn is torch.sin


def test_torch_compiles_a_scan_around_a_while_loop(request):
    """A loop kept as torch's ``scan`` operator around a ``while_loop`` (a physics step's RK4
    stages around its solver) compiles: inductor reads the scan's step with ``.item()``, which
    dynamo captures only with ``capture_scalar_outputs``. Without it the whole function ran
    eagerly, with the fallback's warning. The user's dynamo settings are left as they were."""
    if "torch" not in request.config.ivy_backends:
        pytest.skip("torch not selected")
    import torch

    xp = ivy.torch

    def fn(x):
        def stage(carry, w):
            def halve(state):
                return state[0] * 0.5 + w, state[1] + 1

            out, _ = xp.while_loop(
                lambda s: s[1] < 3, halve, (carry, xp.zeros((), dtype=xp.int32)), pure=True
            )
            return out, out

        carry, ys = xp.scan(stage, x, xp.asarray([1.0, 2.0, 3.0, 4.0]), pure=True)
        return carry + xp.sum(ys, axis=0)

    config = torch._dynamo.config
    before = (config.capture_scalar_outputs, config.trace_autograd_ops)
    x = torch.linspace(0.0, 1.0, 3)
    with warnings.catch_warnings():
        warnings.filterwarnings("error", message="torch.compile cannot run")
        compiled = ivy.compile_fn(fn)(x)
    torch.testing.assert_close(compiled, fn(x), rtol=1e-6, atol=1e-6)
    assert (config.capture_scalar_outputs, config.trace_autograd_ops) == before


def test_tensorflow_calls_after_the_first_skip_argument_matching_and_stay_correct(rng, request):
    """tensorflow's compile_fn calls a known trace's flat entry point directly from the second
    call of a signature on (see ivy/backends/tensorflow/compilation.py). Every kind of call
    must still give tf.function's results: new shapes and dtypes, changed static values,
    variables, a gradient tape outside, and a call from inside another graph."""
    if "tensorflow" not in request.config.ivy_backends:
        pytest.skip("tensorflow not selected")
    import tensorflow as tf

    traces = []

    def affine(v, x, *, scale):
        traces.append(1)
        return {"y": ivy.matmul(x, v["w"]) * scale + v["b"], "n": ivy.sum(x)}, scale

    compiled = ivy.compile_fn(affine, f="tensorflow")
    w, b = rng.normal(size=(3, 2)), rng.normal(size=2)

    def expected(x, scale):
        return {"y": x @ w * scale + b, "n": x.sum()}, scale

    def check(out, x, scale):
        exp = expected(x, scale)
        assert out[1] == exp[1]
        for key in ("y", "n"):
            np.testing.assert_allclose(numpy_of(out[0][key]), exp[0][key], **COMPILED_TOL)

    v = _on("tensorflow", {"w": w, "b": b})
    for x_np in (rng.normal(size=(4, 3)), rng.normal(size=(4, 3)), rng.normal(size=(6, 3))):
        for scale in (2.0, 2.0, 3.0):
            check(compiled(v, _on("tensorflow", x_np), scale=scale), x_np, scale)
    assert len(traces) == 4  # one per (batch size, scale): repeated signatures reuse a trace
    assert len(compiled._traces) == 4  # and take the fast path

    x_np = rng.normal(size=(4, 3))
    x = _on("tensorflow", x_np)
    variables = {"w": tf.Variable(w), "b": tf.Variable(b)}  # variables: tf.function's path
    for _ in range(2):
        check(compiled(variables, x, scale=2.0), x_np, 2.0)
    with tf.GradientTape() as tape:  # a tape outside records through the fast path
        tape.watch(v["w"])
        loss = tf.reduce_sum(compiled(v, x, scale=2.0)[0]["y"])
    np.testing.assert_allclose(
        numpy_of(tape.gradient(loss, v["w"])), 2.0 * x_np.sum(0)[:, None].repeat(2, 1), 1e-12
    )
    inside = tf.function(lambda v, x: compiled(v, x, scale=2.0)[0]["y"], autograph=False)
    np.testing.assert_allclose(numpy_of(inside(v, x)), expected(x_np, 2.0)[0]["y"], 1e-12)
    x32 = tf.cast(x, tf.float32)
    v32 = nest.map_nest(lambda a: tf.cast(a, tf.float32), v)
    for _ in range(2):
        out = compiled(v32, x32, scale=2.0)[0]["y"]
        assert out.dtype == tf.float32
        np.testing.assert_allclose(numpy_of(out), expected(x_np, 2.0)[0]["y"], rtol=1e-5)


def test_tensorflow_fast_calls_pack_outputs_as_tf_does(rng, request):
    """Eager calls with no tape recording run the trace's flat entry point and pack its outputs
    with optree, once checked against tf's packing; outputs that optree would pack otherwise
    (composite tensors), or a tape that records, keep tf's own path. Results are tf.function's in every case."""
    if "tensorflow" not in request.config.ivy_backends:
        pytest.skip("tensorflow not selected")
    import tensorflow as tf

    def step(v, x):
        h = ivy.matmul(x, v["w"])
        return {"h": h, "parts": [ivy.sum(h), (None, v["b"] * 2.0)]}, ivy.mean(x)

    compiled = ivy.compile_fn(step, f="tensorflow")
    w, b = rng.normal(size=(3, 2)), rng.normal(size=2)
    v = _on("tensorflow", {"w": w, "b": b})
    for _ in range(4):  # traced; the first fast call checks the packing; then optree packs
        x_np = rng.normal(size=(4, 3))
        out, mean = compiled(v, _on("tensorflow", x_np))
        np.testing.assert_allclose(numpy_of(out["h"]), x_np @ w, **COMPILED_TOL)
        np.testing.assert_allclose(numpy_of(out["parts"][0]), (x_np @ w).sum(), **COMPILED_TOL)
        assert out["parts"][1][0] is None
        np.testing.assert_allclose(numpy_of(out["parts"][1][1]), 2.0 * b, **COMPILED_TOL)
        np.testing.assert_allclose(numpy_of(mean), x_np.mean(), **COMPILED_TOL)
    (trace,) = compiled._traces.values()
    assert trace.out_spec is not None  # optree's packing was checked and is used
    with tf.GradientTape() as tape:  # a recording tape: tf's path, which it records
        tape.watch(v["w"])
        loss = compiled(v, _on("tensorflow", x_np))[0]["parts"][0]
    np.testing.assert_allclose(
        numpy_of(tape.gradient(loss, v["w"])), x_np.sum(0)[:, None].repeat(2, 1), 1e-12
    )

    def ragged(x):  # a composite tensor: one output of several flat tensors
        return ivy.sum(x), tf.RaggedTensor.from_row_lengths(x, [1, 2])

    with_composite = ivy.compile_fn(ragged, f="tensorflow")
    for _ in range(3):
        total, rows = with_composite(_on("tensorflow", np.arange(3.0)))
        assert float(numpy_of(total)) == 3.0 and rows.to_list() == [[0.0], [1.0, 2.0]]
    (trace,) = with_composite._traces.values()
    assert trace.out_checked and trace.out_spec is None  # tf packs: optree's leaves differ


def test_jax_compiled_function_inside_jax_jit(request):
    """An ivy-compiled function called inside a user's own ``jax.jit``: one that draws warns
    (its numbers are fixed when traced), one that draws nothing stays silent, and both give the
    eager result."""
    if "jax" not in request.config.ivy_backends:
        pytest.skip("jax not selected")
    import jax

    x = _on("jax", np.arange(3.0))
    quiet = ivy.compile_fn(lambda x: ivy.sin(x) * 2.0, f="jax")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = jax.jit(lambda x: quiet(x) + 1.0)(x)
    np.testing.assert_allclose(numpy_of(out), np.sin(np.arange(3.0)) * 2.0 + 1.0)
    noisy = ivy.compile_fn(lambda x: x + ivy.random_uniform(shape=(3,), f="jax"), f="jax")
    with pytest.warns(UserWarning, match="draw their numbers once"):
        jax.jit(noisy)(x)


@pytest.mark.parametrize("committed", [False, True])
def test_jax_compiles_once_whether_or_not_arrays_are_placed(request, committed):
    """The PRNG key that compile_fn threads through follows its neighbours' placement, so a
    step whose outputs feed its next call compiles once (not again at the second call)."""
    if "jax" not in request.config.ivy_backends:
        pytest.skip("jax not selected")
    import jax

    ivy.seed(0)
    v = _on("jax", PARAMS)
    if committed:
        v = jax.device_put(v, jax.devices("cpu")[0])
    x, y = _on("jax", BATCH)

    def noisy_step(v, x, y):
        loss, v = train_step(v, x + 0.01 * ivy.random_normal(shape=(8, 3), f="jax"), y)
        return loss, v

    compiled = ivy.compile_fn(noisy_step, f="jax")
    losses = []
    for _ in range(3):
        loss, v = compiled(v, x, y)
        losses.append(float(loss))
    assert compiled.jitted._cache_size() == 1
    assert len(set(losses)) == 3  # the noise is drawn anew on every call
    assert all(leaf.committed == committed for leaf in jax.tree_util.tree_leaves(v))


def _write_rows(buffers, rows, values):
    """A nest of buffers with rows replaced: what a replay's writer does."""
    return {k: ivy.put_rows(b, rows, values[k]) for k, b in buffers.items()}


def _write_rows_reference(buffers, rows, values):
    out = {k: np.array(b, copy=True) for k, b in buffers.items()}
    for k, b in out.items():
        b[rows] = values[k]
    return out


BUFFERS = {"a": _data.normal(size=(6, 2)), "b": _data.normal(size=6)}
ROWS, VALUES = np.array([4, 1]), {"a": np.ones((2, 2)), "b": np.array([7.0, 8.0])}


def test_jax_donated_arguments_are_deleted_and_the_results_right(request):
    """jax: the donated argument (a nest of arrays, by position or by name) is deleted by the
    call, its buffers reused for the results; the other arguments stay valid."""
    if "jax" not in request.config.ivy_backends:
        pytest.skip("jax not selected")
    expected = _write_rows_reference(BUFFERS, ROWS, VALUES)
    for f, donate in ((None, 0), ("jax", (0,)), (None, -3)):
        write = ivy.compile_fn(_write_rows, donate_argnums=donate, f=f)
        for by_name in (False, True):
            (buffers, values), rows = _on("jax", (BUFFERS, VALUES)), native(ROWS, "jax")
            if by_name:
                out = write(buffers=buffers, rows=rows, values=values)
            else:
                out = write(buffers, rows, values)
            assert all(b.is_deleted() for b in buffers.values())
            assert not rows.is_deleted() and not any(v.is_deleted() for v in values.values())
            for k in expected:
                np.testing.assert_array_equal(numpy_of(out[k]), expected[k])
    undonated = ivy.compile_fn(_write_rows, f="jax")
    buffers = _on("jax", BUFFERS)
    undonated(buffers, native(ROWS, "jax"), _on("jax", VALUES))
    assert not any(b.is_deleted() for b in buffers.values())


def test_donation_elsewhere_is_accepted_and_changes_nothing(backend):
    """tensorflow, torch (one torch.compile) and the backends without a compiler take
    ``donate_argnums`` and give the eager results; the donated arrays stay valid."""
    if backend == "jax":
        pytest.skip("jax donates: see the test above")
    expected = _write_rows_reference(BUFFERS, ROWS, VALUES)
    (buffers, values), rows = _on(backend, (BUFFERS, VALUES)), native(ROWS, backend)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # no compiler (numpy): it runs eagerly
        out = ivy.compile_fn(_write_rows, donate_argnums=0)(buffers, rows, values)
    for k in expected:
        assert is_native(out[k], backend)
        np.testing.assert_array_equal(numpy_of(out[k]), expected[k])
        np.testing.assert_array_equal(numpy_of(buffers[k]), BUFFERS[k])  # still valid, unchanged


del _data  # no test draws from a generator shared by the module
