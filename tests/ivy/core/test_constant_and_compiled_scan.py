"""``ivy.constant`` and ``ivy.compiled_scan``: what applied code uses to bring model constants
into compiled code and to put the compile boundary of a loop, on every backend.

Inside a trace (``jax.jit``, ``tf.function``, ``torch.compile``) a constant neither breaks the
graph nor recompiles; a compiled scan traces its body once, whatever the number of steps.
torch.compile is slow to start: one case each here.
"""

from __future__ import annotations

import gc
import weakref

import numpy as np
import pytest

import ivy
from tests.compilers import GRAPH_COUNTERS, native_compile
from tests.conftest import capable, device_for, require
from tests.helpers import check, native, numpy_of

_data = np.random.default_rng(23)  # constants only; tests: the rng fixture
K = _data.normal(size=(2, 3))  # a model constant, float64


# ----------------------------------------------------------------------------------------------
# ivy.constant
# ----------------------------------------------------------------------------------------------


def test_constant_converts_numpy_arrays_scalars_and_lists(backend, xp):
    device = device_for(backend)
    out = xp.constant(K, dtype="float32", device=device)
    check(out, K.astype(np.float32), backend)
    assert xp.dev(out) == device
    check(xp.constant(K), K, backend)  # a numpy array keeps its dtype
    check(xp.constant(1.5), np.float32(1.5), backend)  # a Python float is float32
    check(xp.constant([[1, 2]], dtype="float64"), np.array([[1.0, 2.0]]), backend)
    check(xp.constant(np.int8(3)), np.int8(3), backend)
    check(ivy.constant(K, dtype="float32", f=backend), K.astype(np.float32), backend)
    check(ivy.constant(K), K, "numpy")  # a numpy value without f: numpy


def test_constant_is_converted_once_while_the_array_lives(xp):
    value = K.copy()
    first = xp.constant(value, dtype="float32")
    assert xp.constant(value, dtype="float32") is first
    assert xp.constant(value, dtype="float64") is not first  # one per dtype
    kept = weakref.ref(first)
    del value, first
    gc.collect()
    assert kept() is None  # forgotten with its numpy array: nothing leaks


def test_constant_inside_fast_graph_compilers(graph_backend):
    xp = getattr(ivy, graph_backend)
    traces = []

    def scaled(x):
        traces.append(1)  # runs once per trace
        return x * xp.constant(K, dtype=x.dtype)

    for compiled in (native_compile(graph_backend, scaled), ivy.compile_fn(scaled)):
        traces.clear()
        for seed in range(3):
            x = np.random.default_rng(seed).normal(size=(2, 3))
            check(compiled(native(x, graph_backend)), x * K, graph_backend)
        assert len(traces) == 1


def test_constant_inside_torch_compile_one_graph(rng, backend):
    """A compiler that reports graph breaks (``torch.compile``): constants of two objects and
    repeated calls make one graph and no break."""
    if backend not in GRAPH_COUNTERS:
        pytest.skip(f"{backend}'s compiler has no graph report (counted in the test above)")
    xp = getattr(ivy, backend)
    device = device_for(backend)

    class Model:
        def __init__(self, k):
            self.k = k  # one numpy copy

    def apply(x, model):
        return x * xp.constant(model.k, dtype=x.dtype, device=xp.dev(x))

    compiled = ivy.compile_fn(apply)
    report = GRAPH_COUNTERS[backend]()
    models = [Model(K), Model(2.0 * K)]
    for model in models + models:
        x = xp.asarray(rng.normal(size=(2, 3)), dtype="float32", device=device)
        out = compiled(x, model)
        check(out, numpy_of(x) * model.k.astype(np.float32), backend)
        assert xp.dev(out) == device
    assert report() == (1, {})


# ----------------------------------------------------------------------------------------------
# ivy.compiled_scan
# ----------------------------------------------------------------------------------------------


def _decay(carry, x):
    """carry {'h': (3,), 'n': ()} -> (carry, y) with y a nest."""
    h = carry["h"] * 0.5 + x
    return {"h": h, "n": carry["n"] + 1.0}, {"h": h, "norm": ivy.sum(h * h)}


def _decay_reference(h0, xs):
    h, hs = h0.copy(), []
    for x in xs:
        h = h * 0.5 + x
        hs.append(h)
    hs = np.array(hs)
    return h, float(len(xs)), hs, (hs * hs).sum(axis=1)


def _check_decay(result, h0, xs, backend):
    (carry, ys) = result
    h, n, hs, norms = _decay_reference(h0, xs)
    check(carry["h"], h, backend)
    check(carry["n"], np.float64(n), backend)
    check(ys["h"], hs, backend)
    check(ys["norm"], norms, backend)


def test_compiled_scan_equals_the_scan(rng, backend, xp):
    """Each backend where its compiler puts the boundary (torch: a host loop over the compiled
    body, its one compiled case here; jax, tensorflow: one compiled loop; numpy: eagerly)."""
    h0, xs = rng.normal(size=3), rng.normal(size=(5, 3))
    run = ivy.compiled_scan(_decay)
    init = {"h": native(h0, backend), "n": native(np.float64(0.0), backend)}
    report = GRAPH_COUNTERS[backend]() if backend in GRAPH_COUNTERS else None
    _check_decay(run(init, native(xs, backend)), h0, xs, backend)
    _check_decay(run(init, native(xs[:3], backend)), h0, xs[:3], backend)  # another length
    if report is not None and xp.capabilities.compilation:
        assert report() == (1, {})  # the body, compiled once, whatever the length
    # the bound form, without xs
    carry, ys = xp.compiled_scan(lambda c, x: (c + 1.0, c), length=4)(
        native(np.float64(0), backend)
    )
    check(carry, np.float64(4.0), backend)
    check(ys, np.arange(4.0), backend)


def test_compiled_scan_traces_a_kept_loop_once(rng, graph_backend):
    """Where the compiler keeps loops, the whole scan is one compiled function: its body is
    traced a fixed number of times, whatever the number of steps, and not again."""
    xp = getattr(ivy, graph_backend)
    assert xp.capabilities.compiled_loops
    traces = []

    def body(carry, x):
        traces.append(1)
        return _decay(carry, x)

    run = xp.compiled_scan(body)
    h0, xs = rng.normal(size=3), rng.normal(size=(50, 3))
    init = {"h": native(h0, graph_backend), "n": native(np.float64(0.0), graph_backend)}
    _check_decay(run(init, native(xs, graph_backend)), h0, xs, graph_backend)
    first = len(traces)
    assert 1 <= first <= 2
    _check_decay(run(init, native(xs[::-1].copy(), graph_backend)), h0, xs[::-1], graph_backend)
    assert len(traces) == first


def test_compiled_scan_checks_its_length(backend, xp):
    run = xp.compiled_scan(lambda c, x: (c, c))
    with pytest.raises((ValueError, TypeError), match="length"):
        run(native(np.float64(0.0), backend))  # no xs and no length
    if not capable(backend, "compilation"):
        return
    require(backend, "fast_graph")  # (torch's one compiled case is above)
    other = xp.compiled_scan(lambda c, x: (c + x, c), length=3)
    with pytest.raises(Exception, match="length"):
        other(native(np.float64(0.0), backend), native(np.ones(4), backend))


del _data  # no test draws from a generator shared by the module
