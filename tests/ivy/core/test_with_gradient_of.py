"""``ivy.with_gradient_of(value, fn, args)``: ``value`` in value, ``fn(*args)``'s derivatives,
``fn`` called only where a derivative is taken (jax, torch) -- on every backend, against numpy
float64 written here and central finite differences."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import check_gradients, native, numpy_of

A = np.array([2.0, 5.0, 0.5])


def _sqrt(xp, a, calls=None):
    """sqrt(a) by Newton's method without derivatives, then one Newton step from its result
    given as its derivative; ``calls`` counts the step's evaluations."""
    x = a * 0.0 + 1.0
    for _ in range(40):
        x = xp.stop_gradient(0.5 * (x + a / x))

    def step(a):
        if calls is not None:
            calls.append(1)
        return 0.5 * (x + a / x)

    return xp.with_gradient_of(x, step, (a,))


def test_value_is_the_values(backend):
    xp = getattr(ivy, backend)
    calls = []
    out = _sqrt(xp, native(A, backend), calls)
    np.testing.assert_allclose(numpy_of(out), np.sqrt(A), rtol=1e-15)
    # eagerly, without a derivative, fn runs only where the backend cannot tell (tensorflow)
    assert len(calls) == (1 if backend == "tensorflow" else 0)


def test_derivatives_are_fns(diff_backend):
    xp = getattr(ivy, diff_backend)
    _, grad = ivy.execute_with_gradients(lambda a: xp.sum(_sqrt(xp, a)), native(A, diff_backend))
    np.testing.assert_allclose(numpy_of(grad), 0.5 / np.sqrt(A), rtol=1e-12)
    check_gradients(diff_backend, lambda a: _sqrt(xp, a), [A])


def test_value_keeps_none_of_its_own_derivative(diff_backend):
    """``value`` depends on ``a`` here too: only ``fn``'s derivative (3) counts, not value's (2)."""
    xp = getattr(ivy, diff_backend)

    def f(a):
        return xp.sum(xp.with_gradient_of(2.0 * a, lambda a: 3.0 * a, (a,)))

    loss, grad = ivy.execute_with_gradients(f, native(A, diff_backend))
    np.testing.assert_allclose(numpy_of(loss), 2.0 * A.sum())
    np.testing.assert_allclose(numpy_of(grad), [3.0, 3.0, 3.0])


def test_nests_of_values_and_arguments(diff_backend):
    xp = getattr(ivy, diff_backend)
    b = native(np.array([1.5, -0.5]), diff_backend)

    def f(inputs):
        a, b = inputs["a"], inputs["b"]
        value = {"p": a * 0.0, "q": (b * 0.0, b * 0.0 + 1.0)}
        out = xp.with_gradient_of(
            value, lambda a, bs: {"p": a**2, "q": (bs[0] * bs[1], bs[0] + a[0])}, (a, (b, b))
        )
        return xp.sum(out["p"]) + xp.sum(out["q"][0]) + xp.sum(out["q"][1] * b)

    inputs = {"a": native(A, diff_backend), "b": b}
    loss, grads = ivy.execute_with_gradients(f, inputs)
    bn = np.array([1.5, -0.5])
    # value: 0 + 0 + sum(1 * b); derivative: p -> 2a; q0 = b*b -> 2b; q1 = b + a0, weighted by b
    # (whose own derivative adds the value q1 = 1)
    np.testing.assert_allclose(numpy_of(loss), bn.sum())
    np.testing.assert_allclose(numpy_of(grads["a"]), 2 * A + np.array([bn.sum(), 0, 0]))
    np.testing.assert_allclose(numpy_of(grads["b"]), 2 * bn + bn + 1.0)


def test_jax_compiled_without_a_derivative_never_runs_fn(request):
    if "jax" not in request.config.ivy_backends:
        pytest.skip("jax not selected")
    import jax

    calls = []
    a = native(A, "jax")
    np.testing.assert_allclose(
        np.asarray(jax.jit(lambda a: _sqrt(ivy.jax, a, calls))(a)), np.sqrt(A)
    )
    assert not calls
    grad = jax.jit(jax.grad(lambda a: ivy.jax.sum(_sqrt(ivy.jax, a, calls))))(a)
    np.testing.assert_allclose(np.asarray(grad), 0.5 / np.sqrt(A), rtol=1e-12)
    assert calls


def test_forward_mode(request):
    """jax's jvp and torch's torch.func.jvp and forward-mode AD give fn's tangents too."""
    got = {}
    if "jax" in request.config.ivy_backends:
        import jax

        a = native(A, "jax")
        got["jax"] = jax.jvp(lambda a: _sqrt(ivy.jax, a), (a,), (a * 0 + 1.0,))[1]
    if "torch" in request.config.ivy_backends:
        import torch
        import torch.autograd.forward_ad as fwAD

        a = native(A, "torch")
        got["torch.func"] = torch.func.jvp(lambda a: _sqrt(ivy.torch, a), (a,), (a * 0 + 1.0,))[1]
        with fwAD.dual_level():
            dual = fwAD.make_dual(a, torch.ones_like(a))
            got["forward_ad"] = fwAD.unpack_dual(_sqrt(ivy.torch, dual)).tangent
    if not got:
        pytest.skip("neither jax nor torch selected")
    for name, tangent in got.items():
        np.testing.assert_allclose(numpy_of(tangent), 0.5 / np.sqrt(A), rtol=1e-12, err_msg=name)


def test_torch_runs_fn_only_for_a_derivative(request):
    if "torch" not in request.config.ivy_backends:
        pytest.skip("torch not selected")
    import torch

    calls = []
    a = native(A, "torch")
    _sqrt(ivy.torch, a, calls)
    with torch.no_grad():
        _sqrt(ivy.torch, a.requires_grad_(), calls)
    assert not calls
    out = _sqrt(ivy.torch, a, calls)
    assert calls and out.requires_grad
