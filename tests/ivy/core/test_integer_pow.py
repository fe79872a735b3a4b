"""Integers to negative integer powers, the same on every backend (``ivy/backends/_int_pow.py``):
refused where the values are known (numpy's answer; torch answered 0 and jax wrapped around to
-2**63), the integer part of the real power inside a compiled program."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import native, numpy_of

BASES = np.array([2, 3, 1, -1, 0, -1, 5])
EXPONENTS = np.array([-1, -2, -3, -3, -1, -2, 2])
REFUSED = "(?i)integers to negative integer powers are not allowed"


def test_refused_where_the_values_are_known(backend):
    x1, x2 = native(BASES, backend), native(EXPONENTS, backend)
    for args in ((x1, x2), (x1, -1), (2, x2)):
        with pytest.raises(ValueError, match=REFUSED):
            ivy.pow(*args)
    np.testing.assert_array_equal(numpy_of(ivy.pow(x1, 2)), BASES**2)
    np.testing.assert_array_equal(numpy_of(ivy.pow(x1, native(np.abs(EXPONENTS), backend))),
                                  BASES ** np.abs(EXPONENTS))  # fmt: skip


def test_inside_a_compiled_program_the_integer_part(graph_backend):
    xp = getattr(ivy, graph_backend)
    power = ivy.compile_fn(xp.pow, f=xp)
    with np.errstate(divide="ignore"):
        want = np.trunc(np.power(BASES.astype(float), EXPONENTS))  # 0 ** -1: inf
    want[BASES == 0] = 0
    got = numpy_of(power(native(BASES, graph_backend), native(EXPONENTS, graph_backend)))
    np.testing.assert_array_equal(got, want.astype(np.int64))
