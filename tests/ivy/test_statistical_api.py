"""cumulative_sum and cumulative_prod on every backend, against running sums and products
written as Python loops in float64 (or exact Python integers)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.helpers import HYPOTHESIS, api, cast, check, native, tolerance
from tests.ivy.strategies import arrays, reals

pytestmark = pytest.mark.filterwarnings("ignore::RuntimeWarning")  # inf - inf in references

FEW = settings(HYPOTHESIS, max_examples=20)
NAMES = {"cumulative_sum": (0, lambda acc, v: acc + v), "cumulative_prod": (1, lambda a, v: a * v)}


def _running(a, axis, name, include_initial, out_dtype):
    """Running sums or products along ``axis``, element by element in Python numbers."""
    initial, op = NAMES[name]
    moved = np.moveaxis(a, axis, -1)
    n = moved.shape[-1] + include_initial
    out = np.zeros(moved.shape[:-1] + (n,), dtype=object)
    for index in np.ndindex(moved.shape[:-1]):
        acc = initial
        values = [acc] if include_initial else []
        for v in moved[index]:
            acc = op(acc, float(v) if out_dtype.startswith("float") else int(v))
            values.append(acc)
        out[index] = values
    if out_dtype.startswith("float"):
        return cast(np.moveaxis(out, -1, axis).astype(np.float64), out_dtype)
    info = np.iinfo(out_dtype)  # integers wrap around as fixed-width integers do
    wrapped = np.vectorize(lambda v: (v - info.min) % (1 << info.bits) + info.min, otypes=[object])
    return np.moveaxis(wrapped(out), -1, axis).astype(out_dtype)


@pytest.mark.parametrize("name", sorted(NAMES))
@FEW
@given(data=st.data())
def test_cumulative_floats(backend, name, data):
    dtype = data.draw(st.sampled_from(["float32", "float64"]), label="dtype")
    bound = 100 if name == "cumulative_sum" else 2
    a = data.draw(
        arrays(
            dtype,
            reals(dtype, -bound, bound, specials=False),
            st.sampled_from([(6,), (0,), (2, 4), (3, 1, 2), (2, 0)]),
        ),
        label="x",
    )
    axis = data.draw(st.integers(-a.ndim, a.ndim - 1), label="axis")
    include_initial = data.draw(st.booleans(), label="include_initial")
    expected = _running(a, axis, name, include_initial, dtype)
    tol = tolerance(
        dtype, float(np.abs(a.astype(np.float64)).sum()) if name == "cumulative_sum" else 64.0
    )
    for fn in api(backend, name):
        check(
            fn(native(a, backend), axis=axis, include_initial=include_initial),
            expected,
            backend,
            **tol,
        )
        if a.ndim == 1:  # axis may be left out for 1-D arrays only
            check(fn(native(a, backend), include_initial=include_initial), expected, backend, **tol)


@pytest.mark.parametrize("name", sorted(NAMES))
@pytest.mark.parametrize(
    "dtype, out_dtype",
    [
        ("int8", "int64"),
        ("int32", "int64"),
        ("int64", "int64"),
        ("bool", "int64"),
        ("uint8", "uint64"),
    ],
)
def test_cumulative_integers_accumulate_in_64_bits(backend, name, dtype, out_dtype):
    """Signed integers and bools accumulate in int64, unsigned ones in uint64 (the standard's
    default integer, and the unsigned one of its size)."""
    if dtype == "bool":
        a = np.array([[True, False, True], [True, True, False]])
    elif name == "cumulative_sum":
        a = np.array([[100, 100, 100], [120, 7, 1]], dtype)  # int8 running sums overflow int8
    else:
        a = np.array([[3, 5, 7], [11, 13, 2]], dtype)
    for fn in api(backend, name):
        for include_initial in (False, True):
            check(
                fn(native(a, backend), axis=1, include_initial=include_initial),
                _running(a, 1, name, include_initial, out_dtype),
                backend,
            )


@pytest.mark.parametrize("name", sorted(NAMES))
def test_cumulative_with_dtype(backend, name):
    a = np.array([1, 2, 3, 4], np.int32)
    for fn in api(backend, name):
        check(
            fn(native(a, backend), dtype="float64"), _running(a, 0, name, False, "float64"), backend
        )


@pytest.mark.parametrize("name", sorted(NAMES))
def test_cumulative_needs_an_axis_beyond_one_dimension(backend, name):
    for fn in api(backend, name):
        with pytest.raises(ValueError):
            fn(native(np.ones((2, 2)), backend))
