"""Tests of the core group ``random`` (``ivy/core/random.py``), on every backend.

Random numbers on every backend: reproducibility under ``ivy.seed``, bounds, shapes, dtypes,
and statistical checks (seeded, so deterministic; bounds are many standard errors wide, or a
chi-square quantile that a correct sampler exceeds with probability 1e-6).

Randomness inside compiled code: draws are not frozen at trace time, and ``ivy.seed``
reproduces them. torch compiles one noise function for the whole module (torch.compile is slow
to start).
"""

from __future__ import annotations

import functools
import warnings

import numpy as np
import pytest
from scipy import stats

import ivy
from ivy import nest
from tests.helpers import api, api_f, check_meta, is_native, native, numpy_of

DRAWS = {
    "random_uniform": lambda fn: fn(shape=(4, 5)),
    "random_normal": lambda fn: fn(shape=(4, 5)),
    "randint": lambda fn: fn(0, 1000, (4, 5)),
}


def _draw(backend, name, which=0):
    """One draw of ``name`` on ``backend`` through ivy (``which=0``) or the namespace (1)."""
    if name == "shuffle":
        fn = api(backend, "shuffle")[which]
        return numpy_of(fn(native(np.arange(50, dtype=np.float32), backend)))
    return numpy_of(DRAWS[name](api_f(backend, name)[which]))


@pytest.mark.parametrize("name", [*DRAWS, "shuffle"])
def test_seed_makes_draws_reproducible(backend, name):
    for which in (0, 1):
        ivy.seed(3)
        first = _draw(backend, name, which)
        second = _draw(backend, name, which)
        ivy.seed(3)
        again = _draw(backend, name, which)
        np.testing.assert_array_equal(first, again)
        assert not np.array_equal(first, second), "consecutive draws are equal"
        ivy.seed(4)
        assert not np.array_equal(first, _draw(backend, name, which)), "seeds 3 and 4 agree"


@pytest.mark.parametrize("name", [*DRAWS, "shuffle"])
def test_seed_of_one_framework(backend, name):
    ivy.seed(11, f=backend)
    first = _draw(backend, name)
    ivy.seed(11, f=backend)
    np.testing.assert_array_equal(first, _draw(backend, name))


def test_random_uniform_defaults(backend):
    ivy.seed(0)
    for fn in api_f(backend, "random_uniform"):
        x = fn(shape=(2000,))
        check_meta(x, backend, "float32", (2000,))
        v = numpy_of(x)
        assert v.min() >= 0.0 and v.max() < 1.0
        assert abs(v.mean() - 0.5) < 0.05 and abs(v.std() - 12**-0.5) < 0.03
        check_meta(fn(), backend, "float32", ())


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_random_uniform_bounds_shape_and_dtype(backend, dtype):
    ivy.seed(1)
    for fn in api_f(backend, "random_uniform"):
        x = fn(-2.0, 3.0, (50, 40), dtype=dtype)
        check_meta(x, backend, dtype, (50, 40))
        v = numpy_of(x)
        assert v.min() >= -2.0 and v.max() < 3.0
        assert abs(v.mean() - 0.5) < 0.25
        assert v.min() < -1.9 and v.max() > 2.9  # the whole interval is covered
        x = fn(low=1.0, high=1.5, shape=(3,), dtype=dtype, device="cpu")
        assert np.all((numpy_of(x) >= 1.0) & (numpy_of(x) < 1.5))


def test_random_uniform_with_array_bounds_broadcasts(backend):
    """The framework comes from the bounds; the shape defaults to their broadcast shape."""
    low = np.array([[0.0], [10.0], [-5.0]], np.float32)
    high = np.array([10.5, 12.0], np.float32)  # broadcast: (3, 2)
    ivy.seed(2)
    for fn in api(backend, "random_uniform"):
        x = fn(native(low, backend), native(high, backend))
        check_meta(x, backend, "float32", (3, 2))
        v = numpy_of(x)
        lo, hi = np.broadcast_arrays(low, high)
        assert np.all((v >= lo) & (v < hi)), v
        x = fn(native(low, backend), 20.0, (4, 3, 1))
        check_meta(x, backend, "float32", (4, 3, 1))
        assert np.all((numpy_of(x) >= low) & (numpy_of(x) < 20.0))


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_random_normal_moments(backend, dtype):
    ivy.seed(5)
    n = 20000
    for fn in api_f(backend, "random_normal"):
        x = fn(shape=(n,)) if dtype == "float32" else fn(shape=(n,), dtype=dtype)
        check_meta(x, backend, dtype, (n,))
        v = numpy_of(x).astype(np.float64)
        assert abs(v.mean()) < 5 / n**0.5 and abs(v.std() - 1) < 0.05
        x = fn(3.0, 0.5, (n,), dtype=dtype)
        v = numpy_of(x).astype(np.float64)
        assert abs(v.mean() - 3) < 5 * 0.5 / n**0.5 and abs(v.std() - 0.5) < 0.025
        assert not np.array_equal(v[: n // 2], v[n // 2 :])


def test_random_normal_with_array_parameters(backend):
    mean = np.array([0.0, 100.0, -50.0], np.float32)
    std = np.array([[1.0], [0.01]], np.float32)  # broadcast: (2, 3)
    ivy.seed(6)
    for fn in api(backend, "random_normal"):
        x = fn(native(mean, backend), native(std, backend))
        check_meta(x, backend, "float32", (2, 3))
        assert np.all(np.abs(numpy_of(x) - mean) < 6 * std)
        x = fn(native(mean, backend), 1.0, (1000, 3))
        check_meta(x, backend, "float32", (1000, 3))
        assert np.all(np.abs(numpy_of(x).mean(axis=0) - mean) < 0.2)


@pytest.mark.parametrize("low, high", [(0, 5), (-3, 4), (10, 11)])
def test_randint_bounds_and_default_int64(backend, low, high):
    ivy.seed(7)
    for fn in api_f(backend, "randint"):
        x = fn(low, high, (500,))
        check_meta(x, backend, "int64", (500,))
        assert set(np.unique(numpy_of(x)).tolist()) == set(range(low, high))


@pytest.mark.parametrize("dtype", ["int32", "int64"])
def test_randint_dtype_and_shape(backend, dtype):
    ivy.seed(8)
    for fn in api_f(backend, "randint"):
        x = fn(low=-100, high=100, shape=(3, 4, 2), dtype=dtype, device="cpu")
        check_meta(x, backend, dtype, (3, 4, 2))
        assert numpy_of(x).min() >= -100 and numpy_of(x).max() < 100


def test_randint_with_array_bounds(backend):
    low = np.array([0, 100, -10], np.int64)
    high = np.array([2, 105, -9], np.int64)
    ivy.seed(9)
    for fn in api(backend, "randint"):
        x = fn(native(low, backend), native(high, backend), (200, 3))
        check_meta(x, backend, "int64", (200, 3))
        v = numpy_of(x)
        assert np.all((v >= low) & (v < high))


@pytest.mark.parametrize("dtype", ["float32", "float64", "int64"])
def test_shuffle_permutes_the_first_axis(backend, dtype):
    ivy.seed(10)
    a = np.arange(40).reshape(20, 2).astype(dtype)
    for fn in api(backend, "shuffle"):
        x = fn(native(a, backend))
        check_meta(x, backend, dtype, (20, 2))
        v = numpy_of(x)
        assert not np.array_equal(v, a), "shuffle returned the rows in their order"
        order = np.argsort(v[:, 0])
        np.testing.assert_array_equal(v[order], a)  # rows are intact, each exactly once
        v1 = numpy_of(fn(native(a[:, 0], backend)))
        np.testing.assert_array_equal(np.sort(v1), a[:, 0])


def test_shuffle_of_tiny_arrays(backend):
    for fn in api(backend, "shuffle"):
        for a in (np.zeros((0, 3), np.float32), np.array([4.5], np.float32)):
            x = fn(native(a, backend))
            check_meta(x, backend, "float32", a.shape)
            np.testing.assert_array_equal(numpy_of(x), a)


# Two distributions of 5 classes; class 3 of the first has probability 0.
LOGITS = np.array([[0.0, 1.0, 2.0, -np.inf, 0.5], [3.0, 0.0, 0.0, -1.0, 0.0]])


def _softmax(logits):
    e = np.exp(logits - logits.max(axis=-1, keepdims=True))
    return e / e.sum(axis=-1, keepdims=True)


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_random_categorical_frequencies_match_softmax(backend, dtype):
    """Pearson's chi-square statistic of the counts of 20000 draws per distribution, against its
    quantile of probability 1 - 1e-6 (seeded: the test cannot flake); the impossible class is
    never drawn."""
    n = 20_000
    ivy.seed(21)
    draws = numpy_of(ivy.random_categorical(native(LOGITS.astype(dtype), backend), num_samples=n))
    assert draws.shape == (2, n)
    for row, probs in zip(draws, _softmax(LOGITS)):
        counts = np.bincount(row, minlength=5)
        possible = probs > 0
        assert counts[~possible].sum() == 0
        expected = n * probs[possible]
        chi2 = np.sum((counts[possible] - expected) ** 2 / expected)
        assert chi2 < stats.chi2.isf(1e-6, df=possible.sum() - 1), (counts, expected)


def test_random_categorical_shapes_and_dtypes(backend):
    ivy.seed(22)
    for fn in api(backend, "random_categorical"):
        batched = native(np.zeros((2, 3, 4), np.float32), backend)
        out = fn(batched, num_samples=5)
        check_meta(out, backend, "int64", (2, 3, 5))
        assert np.all((numpy_of(out) >= 0) & (numpy_of(out) < 4))
        check_meta(fn(native(np.zeros(4), backend)), backend, "int64", (1,))  # one sample
        check_meta(fn(batched, num_samples=3, dtype="int32"), backend, "int32", (2, 3, 3))
        check_meta(fn(batched, num_samples=0), backend, "int64", (2, 3, 0))
        check_meta(fn(native(np.zeros((0, 4)), backend), num_samples=2), backend, "int64", (0, 2))
        certain = fn(native(np.array([-np.inf, 0.0, -np.inf]), backend), num_samples=50)
        np.testing.assert_array_equal(numpy_of(certain), np.ones(50))
        with pytest.raises(ValueError, match="at least one class"):
            fn(native(np.zeros((2, 0)), backend))


def test_random_categorical_is_reproducible(backend):
    logits = native(np.zeros((3, 10)), backend)
    for fn in api(backend, "random_categorical"):
        ivy.seed(23)
        first, second = numpy_of(fn(logits, num_samples=20)), numpy_of(fn(logits, num_samples=20))
        ivy.seed(23)
        np.testing.assert_array_equal(numpy_of(fn(logits, num_samples=20)), first)
        assert not np.array_equal(first, second), "consecutive draws are equal"


def noise(x):
    xp = ivy.get_framework(x)
    return x + xp.random_normal(shape=(4,), dtype="float64"), xp.random_uniform(shape=(2,))


@functools.cache
def compiled_noise(backend):
    return ivy.compile_fn(noise)


def _draws(backend, n=2):
    x = native(np.zeros(4), backend)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # numpy: "no compiler"
        return [tuple(numpy_of(a) for a in compiled_noise(backend)(x)) for _ in range(n)]


def test_compiled_noise_differs_between_calls(backend):
    (a1, u1), (a2, u2) = _draws(backend)
    assert a1.shape == (4,) and u1.shape == (2,)
    assert np.all(a1 != a2) and np.all(u1 != u2)
    assert np.all((0 <= u1) & (u1 < 1))


def test_seed_reproduces_compiled_draws(backend):
    ivy.seed(1234)
    first = _draws(backend, 3)
    ivy.seed(1234)
    again = _draws(backend, 3)
    ivy.seed(99)
    other = _draws(backend, 1)
    for (a, u), (b, w) in zip(first, again):
        np.testing.assert_array_equal(a, b)
        np.testing.assert_array_equal(u, w)
    assert np.all(other[0][0] != first[0][0])


def test_seed_reproduces_mixed_eager_and_compiled_draws(backend):
    def run():
        eager = numpy_of(ivy.random_uniform(shape=(3,), f=backend))
        compiled = _draws(backend, 1)[0][0]
        return eager, compiled, numpy_of(ivy.random_uniform(shape=(3,), f=backend))

    ivy.seed(5)
    first = run()
    ivy.seed(5)
    for a, b in zip(first, run()):
        np.testing.assert_array_equal(a, b)


def categorical(logits):
    return ivy.random_categorical(logits, num_samples=64)


@functools.cache
def compiled_categorical(backend):
    return ivy.compile_fn(categorical)


def test_compiled_categorical_draws_differ_between_calls_and_repeat_after_seed(backend):
    logits = native(np.zeros((2, 10)), backend)

    def draws(n):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # numpy: "no compiler"
            return [numpy_of(compiled_categorical(backend)(logits)) for _ in range(n)]

    ivy.seed(31)
    first = draws(2)
    assert first[0].shape == (2, 64) and np.all((first[0] >= 0) & (first[0] < 10))
    assert not np.array_equal(first[0], first[1]), "compiled draws are frozen"
    ivy.seed(31)
    for a, b in zip(first, draws(2)):
        np.testing.assert_array_equal(a, b)


def test_noisy_compiled_training_step(graph_backend):
    """Noise inside a compiled step with gradients (dropout-like): fresh on every call."""
    backend_ = graph_backend
    xp = getattr(ivy, backend_)

    def step(v):
        def loss(v):
            mask = xp.random_uniform(shape=(5,), dtype="float64")
            return xp.sum((v["w"] * mask) ** 2)

        _, grads = ivy.execute_with_gradients(loss, v)
        return nest.multi_map_nest(lambda p, g: p - 0.1 * g, v, grads)

    compiled = ivy.compile_fn(step)
    v = {"w": native(np.ones(5), backend_)}
    ivy.seed(0)
    a, b = numpy_of(compiled(v)["w"]), numpy_of(compiled(v)["w"])
    assert np.all(a != b) and np.all(a < 1)
    ivy.seed(0)
    np.testing.assert_array_equal(numpy_of(compiled(v)["w"]), a)


@pytest.fixture
def jax_only(request):
    if "jax" not in request.config.ivy_backends:
        pytest.skip("jax not selected")
    import jax

    return jax


def test_jax_compiled_functions_calling_each_other(jax_only):
    inner = ivy.compile_fn(lambda x: x + ivy.random_normal(shape=(3,), dtype="float64", f="jax"))
    outer = ivy.compile_fn(lambda x: (inner(x), inner(x)))
    x = native(np.zeros(3), "jax")
    ivy.seed(3)
    (a, b), (c, d) = outer(x), outer(x)
    draws = [numpy_of(t) for t in (a, b, c, d)]
    for i in range(4):
        for j in range(i):
            assert np.all(draws[i] != draws[j])
    ivy.seed(3)
    np.testing.assert_array_equal(numpy_of(outer(x)[1]), draws[1])


def test_jax_draws_under_plain_jit_are_frozen_with_a_warning(jax_only):
    """Documented: a plain jax.jit cannot thread ivy's key; ivy.compile_fn can."""
    jitted = jax_only.jit(lambda x: x + ivy.random_normal(shape=(3,), dtype="float64", f="jax"))
    x = native(np.zeros(3), "jax")
    with pytest.warns(UserWarning, match="ivy.compile_fn"):
        first = numpy_of(jitted(x))
    np.testing.assert_array_equal(numpy_of(jitted(x)), first)  # the same numbers every call
    after = numpy_of(ivy.random_normal(shape=(3,), dtype="float64", f="jax"))
    assert np.all(after != first)  # the key still advanced, eagerly


def test_jax_gradients_of_a_compiled_noisy_function(jax_only):
    noisy = ivy.compile_fn(
        lambda x: ivy.sum(x * ivy.random_uniform(shape=(3,), dtype="float64", f="jax"))
    )
    x = native(np.ones(3), "jax")
    g1 = numpy_of(ivy.grad(noisy)(x))
    g2 = numpy_of(ivy.grad(noisy)(x))
    assert is_native(ivy.grad(noisy)(x), "jax")
    assert np.all(g1 != g2) and np.all((0 <= g1) & (g1 < 1))
