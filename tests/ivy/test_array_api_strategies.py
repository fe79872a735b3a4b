"""Functions on arrays drawn by ``hypothesis.extra.array_api`` strategies built from each backend
namespace itself, which also shows that every ``ivy.<backend>`` serves as an Array API namespace.

References are numpy float64 computations written here; edge values (0, -0, +-inf, nan, empty
and 0-d arrays) come from the strategies.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra.array_api import make_strategies_namespace

import ivy
from tests.helpers import assert_close

SETTINGS = settings(
    max_examples=20,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
_STRATEGIES: dict[str, object] = {}


def strategies_for(backend):
    """Array API strategies for ``ivy.<backend>`` (cached: building them inspects the namespace)."""
    if backend not in _STRATEGIES:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # hypothesis notes the namespace is not one it knows
            _STRATEGIES[backend] = make_strategies_namespace(
                getattr(ivy, backend), api_version="2023.12"
            )
    return _STRATEGIES[backend]


def float_arrays(xps, *, bounded=False, min_dims=0):
    elements = {"min_value": -50, "max_value": 50} if bounded else None
    return xps.arrays(
        dtype=xps.floating_dtypes(),
        shape=xps.array_shapes(min_dims=min_dims, max_dims=3, min_side=0, max_side=4),
        elements=elements,
    )


def as_float64(x):
    return np.asarray(ivy.to_numpy(x), dtype=np.float64)


EXACT_UNARY = {
    "abs": np.abs,
    "negative": np.negative,
    "floor": np.floor,
    "ceil": np.ceil,
    "trunc": np.trunc,
    "sign": np.sign,
}
TRANSCENDENTAL = {"sin": np.sin, "cos": np.cos, "tanh": np.tanh, "exp": np.exp, "atan": np.arctan}


def test_backend_namespace_is_an_array_api_namespace(xp):
    assert xp.__array_api_version__ == "2023.12"
    assert xp.pi == np.pi and xp.newaxis is None
    strategies_for(xp.backend)  # raises if hypothesis finds the namespace incomplete


@pytest.mark.parametrize("name", sorted(EXACT_UNARY))
def test_exact_elementwise_on_edge_values(backend, xp, name):
    @SETTINGS
    @given(x=float_arrays(strategies_for(backend)))
    def check(x):
        out = getattr(ivy, name)(x)
        assert ivy.dtype(out, as_str=True) == ivy.dtype(x, as_str=True)
        expected = EXACT_UNARY[name](as_float64(x))
        np.testing.assert_array_equal(as_float64(out), expected)

    check()


@pytest.mark.parametrize("name", sorted(TRANSCENDENTAL))
def test_transcendental_elementwise(backend, xp, name):
    @SETTINGS
    @given(x=float_arrays(strategies_for(backend), bounded=True))
    def check(x):
        out = getattr(xp, name)(x)
        dtype = ivy.dtype(x, as_str=True)
        expected = TRANSCENDENTAL[name](as_float64(x)).astype(dtype)
        assert_close(out, expected, dtype=dtype, atol=1e-5 if dtype == "float32" else 1e-12)

    check()


@pytest.mark.parametrize("name", ["max", "min", "sum"])
def test_reductions_over_drawn_axes(backend, name):
    xps = strategies_for(backend)

    @SETTINGS
    @given(x=float_arrays(xps, bounded=True, min_dims=1), data=st.data())
    def check(x, data):
        ndim = len(ivy.shape(x))
        axis = data.draw(st.integers(-ndim, ndim - 1))
        keepdims = data.draw(st.booleans())
        if name != "sum" and ivy.shape(x)[axis] == 0:
            return  # max/min of an empty axis is undefined
        out = getattr(ivy, name)(x, axis=axis, keepdims=keepdims)
        expected = getattr(np, name)(as_float64(x), axis=axis, keepdims=keepdims)
        dtype = ivy.dtype(x, as_str=True)
        assert ivy.dtype(out, as_str=True) == dtype
        assert_close(out, expected.astype(dtype), dtype=dtype, atol=1e-4)

    check()


def test_manipulation_round_trips(backend):
    xps = strategies_for(backend)

    @SETTINGS
    @given(x=float_arrays(xps, min_dims=1))
    def check(x):
        ref = as_float64(x)
        np.testing.assert_array_equal(as_float64(ivy.flip(x, axis=0)), ref[::-1])
        reversed_axes = tuple(range(ref.ndim))[::-1]
        np.testing.assert_array_equal(
            as_float64(ivy.permute_dims(x, reversed_axes)), ref.transpose(reversed_axes)
        )
        np.testing.assert_array_equal(as_float64(ivy.reshape(x, (-1,))), ref.reshape(-1))
        np.testing.assert_array_equal(
            as_float64(ivy.concat([x, x], axis=0)), np.concatenate([ref, ref])
        )
        np.testing.assert_array_equal(as_float64(ivy.expand_dims(x, axis=0)), ref[None])

    check()
