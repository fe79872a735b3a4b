"""Gradient-safe numerics (``ivy/core/numerics.py``) on every backend: values against numpy
float64 references, gradients at the singular points against each function's documented rule,
and gradients elsewhere against central finite differences.

Each case is a row of ``CASES``: the function, its inputs (singular points included), a float64
numpy reference of the value, and the gradients the docstring promises (written here by hand).
"""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import check, check_gradients, native, native_value_and_grads, numpy_of

SINC_SERIES = (1.0, -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0)


def _sinc_of_sq(xp, x_sq):
    return xp.taylor_switch(x_sq, SINC_SERIES, lambda x: xp.sin(x) / x)


def _sinc_of_sq_ref(x_sq):
    x = np.sqrt(x_sq)
    with np.errstate(invalid="ignore"):
        return np.where(x_sq == 0, 1.0, np.sin(x) / np.where(x == 0, 1.0, x))


def _sinc_of_sq_grad(x_sq):
    """d/d(x_sq) of sin(x)/x = (x cos x - sin x) / (2 x**3), which cancels catastrophically for
    small x: there, the derivative of the series (-1/6 + x_sq/60 - x_sq**2/1680 + ...)."""
    x = np.sqrt(np.where(x_sq == 0, 1.0, x_sq))
    series = -1.0 / 6.0 + x_sq / 60.0 - x_sq**2 / 1680.0 + x_sq**3 / 90720.0
    return np.where(x_sq < 1e-2, series, (x * np.cos(x) - np.sin(x)) / (2 * x**3))


def _hypot_grads(a, b):
    r = np.hypot(a, b)
    safe = np.where(r == 0, 1.0, r)
    return [np.where(r == 0, 0.0, a / safe), np.where(r == 0, 0.0, b / safe)]


def _atan2_grads(y, x):
    origin = (x == 0) & (y == 0)
    r2 = np.where(origin, 1.0, x * x + y * y)
    return [np.where(origin, 1.0, x / r2), np.where(origin, 0.0, -y / r2)]


def _divide_grads(a, b):
    zero = b == 0
    safe = np.where(zero, 1.0, b)
    return [np.where(zero, 0.0, 1.0 / safe), np.where(zero, 0.0, -a / safe**2)]


SQRT_IN = np.array([4.0, 0.0, -1e-18, 2.5, 1e-300])
NORM_IN = np.array([[3.0, 4.0, 0.0], [0.0, 0.0, 0.0], [1e-200, 0.0, 0.0], [-1.0, 2.0, -2.0]])
PAIRS_A = np.array([3.0, 0.0, 0.0, -1.0, 0.0, 2.0])
PAIRS_B = np.array([4.0, 0.0, 2.0, 0.0, -3.0, -2.0])
# x**2 at 0, inside the series, on both sides of the switch (1e-4), and far out.
X_SQ_IN = np.array([0.0, 1e-12, 0.99e-4, 1.01e-4, 0.5, np.pi**2, 30.0])

CASES = {
    "safe_sqrt": dict(
        fn=lambda xp, x: xp.safe_sqrt(x),
        inputs=[SQRT_IN],
        ref=lambda x: np.sqrt(np.maximum(x, 0.0)),
        grads=lambda x: [np.where(x > 0, 0.5 / np.sqrt(np.where(x > 0, x, 1.0)), 0.0)],
    ),
    "safe_norm": dict(
        fn=lambda xp, x: xp.safe_norm(x),
        inputs=[NORM_IN],
        ref=lambda x: np.linalg.norm(x, axis=-1),
        grads=lambda x: [
            np.where(
                np.linalg.norm(x, axis=-1, keepdims=True) > 0,
                x / np.maximum(np.linalg.norm(x, axis=-1, keepdims=True), 1e-300),
                0.0,
            )
        ],
    ),
    "safe_norm axis 0 keepdims": dict(
        fn=lambda xp, x: xp.safe_norm(x, axis=0, keepdims=True),
        inputs=[NORM_IN.T.copy()],
        ref=lambda x: np.linalg.norm(x, axis=0, keepdims=True),
        grads=None,
    ),
    "safe_hypot": dict(
        fn=lambda xp, a, b: xp.safe_hypot(a, b),
        inputs=[PAIRS_A, PAIRS_B],
        ref=np.hypot,
        grads=_hypot_grads,
    ),
    "safe_atan2": dict(
        fn=lambda xp, y, x: xp.safe_atan2(y, x),
        inputs=[PAIRS_A, PAIRS_B],
        ref=np.arctan2,
        grads=_atan2_grads,
    ),
    "safe_divide": dict(
        fn=lambda xp, a, b: xp.safe_divide(a, b),
        inputs=[PAIRS_A, PAIRS_B],
        ref=lambda a, b: np.divide(a, np.where(b == 0, 1.0, b)) * (b != 0),
        grads=_divide_grads,
    ),
    "safe_divide fill": dict(
        fn=lambda xp, a, b: xp.safe_divide(a, b, fill=-7.0),
        inputs=[PAIRS_A, PAIRS_B],
        ref=lambda a, b: np.where(b == 0, -7.0, a / np.where(b == 0, 1.0, b)),
        grads=_divide_grads,
    ),
    "taylor_switch sinc": dict(
        fn=_sinc_of_sq,
        inputs=[X_SQ_IN],
        ref=_sinc_of_sq_ref,
        grads=lambda x_sq: [_sinc_of_sq_grad(x_sq)],
    ),
    "taylor_switch two outputs": dict(
        fn=lambda xp, x_sq: xp.stack_vector(
            xp.taylor_switch(
                x_sq,
                (SINC_SERIES, (1.0, -0.5, 1.0 / 24.0, -1.0 / 720.0)),
                lambda x: (xp.sin(x) / x, xp.cos(x)),
            )
        ),
        inputs=[X_SQ_IN],
        ref=lambda x_sq: np.stack([_sinc_of_sq_ref(x_sq), np.cos(np.sqrt(x_sq))], axis=-1),
        grads=None,
    ),
    "horner": dict(
        fn=lambda xp, x: xp.horner(x, (1.0, -2.0, 0.5, 3.0)),
        inputs=[np.array([0.0, 1.0, -2.0, 0.3])],
        ref=lambda x: np.polynomial.polynomial.polyval(x, [1.0, -2.0, 0.5, 3.0]),
        grads=lambda x: [np.polynomial.polynomial.polyval(x, [-2.0, 1.0, 9.0])],
    ),
    "horner one coefficient": dict(
        fn=lambda xp, x: xp.horner(x, (2.5,)),
        inputs=[np.array([0.0, 1.0, -2.0])],
        ref=lambda x: np.full_like(x, 2.5),
        grads=lambda x: [np.zeros_like(x)],
    ),
    "matvec": dict(
        fn=lambda xp, m, v: xp.matvec(m, v),
        inputs=[
            np.random.default_rng(0).standard_normal((2, 1, 3, 4)),
            np.random.default_rng(1).standard_normal((5, 4)),
        ],
        ref=lambda m, v: np.einsum("...ij,...j->...i", m, v),
        grads=None,
    ),
    "stack_vector": dict(
        fn=lambda xp, a, b: xp.stack_vector([a, b, a * b]),
        inputs=[PAIRS_A, PAIRS_B],
        ref=lambda a, b: np.stack([a, b, a * b], axis=-1),
        grads=None,
    ),
    "stack_matrix": dict(
        fn=lambda xp, c, s: xp.stack_matrix([[c, -s], [s, c]]),
        inputs=[np.cos(PAIRS_A), np.sin(PAIRS_A)],
        ref=lambda c, s: np.stack([np.stack([c, -s], -1), np.stack([s, c], -1)], -2),
        grads=None,
    ),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_values(backend, name):
    case = CASES[name]
    xp = getattr(ivy, backend)
    for dtype in ("float64", "float32"):
        inputs = [native(a.astype(dtype), backend) for a in case["inputs"]]
        expected = case["ref"](*case["inputs"])
        check(case["fn"](xp, *inputs), expected.astype(dtype), backend)


@pytest.mark.parametrize("name", sorted(c for c in CASES if CASES[c]["grads"]))
def test_gradients_follow_the_rule_at_singular_points(diff_backend, name):
    """The gradient of ``sum(fn)`` with respect to each input, singular points included, equals
    the documented rule (finite everywhere; the exact gradient away from the singular point)."""
    case = CASES[name]
    xp = getattr(ivy, diff_backend)
    inputs = case["inputs"]
    out_shape = np.shape(case["ref"](*inputs))
    _, grads = native_value_and_grads(
        diff_backend, lambda *a: case["fn"](xp, *a), inputs, np.ones(out_shape)
    )
    for got, want in zip(grads, case["grads"](*inputs)):
        assert np.all(np.isfinite(got)), f"{name}: gradient not finite: {got}"
        np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-12, err_msg=name)


def _generic(inputs, rng):
    """Points away from every singular point (nonzero, off the switch threshold)."""
    return [np.abs(a) + 0.5 + 0.3 * rng.random(a.shape) for a in inputs]


@pytest.mark.parametrize("name", sorted(CASES))
def test_gradients_against_finite_differences(diff_backend, name):
    case = CASES[name]
    xp = getattr(ivy, diff_backend)
    inputs = _generic(case["inputs"], np.random.default_rng(3))
    check_gradients(diff_backend, lambda *a: case["fn"](xp, *a), inputs, n_directions=2)


def test_taylor_switch_is_continuous_at_the_threshold(backend):
    """Both branches agree at the switch to float64 precision (the series is exact there)."""
    xp = getattr(ivy, backend)
    edge = np.array([1e-4 * (1 - 1e-12), 1e-4])
    got = numpy_of(_sinc_of_sq(xp, native(edge, backend)))
    assert abs(got[0] - got[1]) < 1e-15
    np.testing.assert_allclose(got, _sinc_of_sq_ref(edge), rtol=1e-15)


def test_taylor_switch_checks_the_number_of_series(backend):
    xp = getattr(ivy, backend)
    x_sq = native(np.array([0.0, 1.0]), backend)
    with pytest.raises(ValueError, match="one tuple of coefficients per output"):
        xp.taylor_switch(x_sq, SINC_SERIES, lambda x: (xp.sin(x), xp.cos(x)))


def test_horner_needs_a_coefficient(backend):
    with pytest.raises(ValueError, match="at least one coefficient"):
        getattr(ivy, backend).horner(native(np.ones(2), backend), ())


def test_compiled_equals_eager(graph_backend):
    """Inside ``ivy.compile_fn`` (jax.jit, tf.function) the helpers give the eager values."""
    xp = getattr(ivy, graph_backend)

    def fn(x, y):
        return xp.stack_vector(
            [xp.safe_atan2(y, x), xp.safe_hypot(x, y), xp.safe_divide(y, x), _sinc_of_sq(xp, x)]
        )

    x, y = native(np.abs(PAIRS_B) * 1e-3, graph_backend), native(PAIRS_A, graph_backend)
    np.testing.assert_array_equal(numpy_of(ivy.compile_fn(fn)(x, y)), numpy_of(fn(x, y)))


def test_agnostic_and_namespace_calls_agree(backend):
    """``ivy.safe_norm(x)`` infers the backend; ``ivy.<backend>.safe_norm`` has it bound."""
    x = native(NORM_IN, backend)
    np.testing.assert_array_equal(
        numpy_of(ivy.safe_norm(x)), numpy_of(getattr(ivy, backend).safe_norm(x))
    )
