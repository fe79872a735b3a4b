"""Randomness inside compiled code: draws are not frozen at trace time, and ``ivy.seed``
reproduces them. torch compiles one noise function for the whole module (torch.compile is slow
to start)."""

from __future__ import annotations

import functools
import warnings

import numpy as np
import pytest

import ivy
from ivy import nest
from tests.helpers import is_native, native, numpy_of

# torch.compile's own internals warn about torch.jit while compiling
pytestmark = pytest.mark.filterwarnings("ignore:`torch.jit.script_method`:DeprecationWarning")


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


@pytest.mark.parametrize("backend_", ["jax", "tensorflow"])
def test_noisy_compiled_training_step(request, backend_):
    """Noise inside a compiled step with gradients (dropout-like): fresh on every call."""
    if backend_ not in request.config.ivy_backends:
        pytest.skip(f"{backend_} not selected")
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
