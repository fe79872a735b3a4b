"""Settings that cannot be right raise on every backend instead of a plausible wrong answer
(issue 40, class 4). Each case was answered by some backends and refused by others."""

from __future__ import annotations

import pytest

import ivy
from ivy.errors import DtypeError, InvalidValueError


@pytest.mark.parametrize("draw", ["random_uniform", "random_normal"])
def test_real_draws_refuse_integer_dtypes(backend, draw):
    """numpy, torch and tensorflow rounded the draws (mostly zeros from U[0, 1)); jax refused."""
    with pytest.raises(DtypeError, match="draws real numbers.*ivy.randint"):
        getattr(ivy, draw)(shape=(3,), dtype="int32", f=backend)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda f: ivy.random_uniform(1.0, 0.0, (3,), f=f), r"low \(1.0\) must not exceed high"),
        (lambda f: ivy.random_normal(0.0, -1.0, (3,), f=f), r"std \(-1.0\) must not be negative"),
        (lambda f: ivy.randint(3, 3, (3,), f=f), r"low \(3\) must be less than high \(3\)"),
        (lambda f: ivy.arange(0, 5, 0, f=f), "step must not be 0"),
    ],
    ids=["uniform low > high", "normal std < 0", "randint low == high", "arange step 0"],
)
def test_bounds_that_describe_nothing_are_refused(backend, call, message):
    with pytest.raises(InvalidValueError, match=message):
        call(backend)
