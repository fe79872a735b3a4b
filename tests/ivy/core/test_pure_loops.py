"""Loops declared ``pure=True``: the same results on every backend, and inside torch.compile
torch's loop operators (the body traced once, no graph split at a data-dependent condition),
with gradients through ``scan``."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.conftest import capable
from tests.helpers import native, numpy_of


def _rnn(xp, w):
    def step(h, x):
        h = xp.tanh(xp.matmul(h, w) + x)
        return h, {"h": h, "sq": xp.sum(h * h, axis=-1)}

    return step


def _halve_until_small(xp):
    def keep_going(val):
        return xp.any(xp.abs(val["x"]) > 1e-3)

    def body(val):
        return {"x": val["x"] * 0.5, "n": val["n"] + 1}

    return keep_going, body


def test_pure_loops_equal_python_loops_on_every_backend(backend, rng):
    h0, xs, w = rng.normal(size=(2, 3)), rng.normal(size=(5, 2, 3)), rng.normal(size=(3, 3))
    xp = getattr(ivy, backend)
    step = _rnn(xp, native(w, backend))
    args = native(h0, backend), native(xs, backend)
    got = ivy.scan(step, *args, pure=True)
    want = ivy.scan(step, *args)
    for a, b in zip(ivy.nest.flatten_nest(got)[0], ivy.nest.flatten_nest(want)[0]):
        np.testing.assert_allclose(numpy_of(a), numpy_of(b), rtol=1e-12)
    cond, body = _halve_until_small(xp)
    start = {"x": native(rng.normal(size=4), backend), "n": native(np.int64(0), backend)}
    out = ivy.while_loop(cond, body, start, pure=True, maximum_iterations=40)
    assert int(numpy_of(out["n"])) == int(numpy_of(ivy.while_loop(cond, body, start)["n"]))
    total = ivy.fori_loop(0, 4, lambda i, v: v * 2.0, native(np.float64(1.0), backend), pure=True)
    assert float(numpy_of(total)) == 16.0


def test_torch_compile_keeps_pure_loops(rng):
    torch = pytest.importorskip("torch")
    if not capable("torch", "compilation"):
        pytest.skip("torch has no compiler here")
    h0 = torch.tensor(rng.normal(size=(2, 3)), requires_grad=True)
    xs = torch.tensor(rng.normal(size=(6, 2, 3)))
    w = torch.tensor(rng.normal(size=(3, 3)))
    xp = ivy.torch

    def loss(h0, xs, pure):
        h, ys = ivy.scan(_rnn(xp, w), h0, xs, pure=pure)
        return (h * h).sum() + ys["sq"].sum()

    explain = torch._dynamo.explain
    kept, unrolled = explain(loss)(h0, xs, True), explain(loss)(h0, xs, False)
    assert kept.graph_break_count == 0
    assert kept.op_count < unrolled.op_count / 2  # the body once, not six times
    compiled = ivy.compile_fn(lambda h0, xs: loss(h0, xs, True))
    value = compiled(h0, xs)
    (grad,) = torch.autograd.grad(value, h0)
    value_eager = loss(h0, xs, False)
    (grad_eager,) = torch.autograd.grad(value_eager, h0)
    np.testing.assert_allclose(float(value.detach()), float(value_eager.detach()), rtol=1e-12)
    np.testing.assert_allclose(grad.numpy(), grad_eager.numpy(), rtol=1e-10)

    cond, body = _halve_until_small(xp)

    def halvings(x, pure):
        out = ivy.while_loop(cond, body, {"x": x, "n": torch.zeros((), dtype=torch.int64)},
                             pure=pure)  # fmt: skip
        return out["n"]

    x = torch.tensor(rng.normal(size=5))
    assert explain(lambda x: halvings(x, True))(x).graph_break_count == 0
    assert explain(lambda x: halvings(x, False))(x).graph_break_count > 0  # split per test
    assert int(ivy.compile_fn(lambda x: halvings(x, True))(x)) == int(halvings(x, False))
