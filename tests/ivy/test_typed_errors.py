"""Bad input in eager mode raises ivy's typed errors (``ivy/errors.py``) on every backend: each
names the function, the argument and the backend, and is also the builtin error that such input
raises in Python and numpy, so that existing ``except`` clauses keep working."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from ivy import errors
from tests.helpers import native

F32 = np.arange(6, dtype="float32").reshape(2, 3)

# (error class, builtin classes it must also be, the call, the function and argument named)
CASES = [
    (
        errors.ShapeError,
        (ValueError,),
        lambda b: ivy.add(native(F32, b), native(np.ones((4, 3), "float32"), b)),
        "add",
        "x1, x2",
    ),
    (
        errors.AxisError,
        (ValueError, IndexError),
        lambda b: ivy.sum(native(F32, b), axis=5),
        "sum",
        "axis",
    ),
    (
        errors.IndexOutOfBoundsError,
        (IndexError,),
        lambda b: ivy.take(native(F32[0], b), native(np.array([5]), b)),
        "take",
        "indices",
    ),
    (
        errors.DtypeError,
        (TypeError,),
        lambda b: ivy.bitwise_and(native(F32, b), native(F32, b)),
        "bitwise_and",
        "x1, x2",
    ),
    (
        errors.InvalidValueError,
        (ValueError,),
        lambda b: ivy.argmax(native(np.zeros(0, "float32"), b)),
        "argmax",
        "x",
    ),
    (
        errors.LinAlgError,
        (ValueError,),
        lambda b: ivy.inv(native(np.array([[1.0, 2.0], [2.0, 4.0]], "float32"), b)),
        "inv",
        None,
    ),
]


@pytest.mark.parametrize(
    "error, builtins, call, function, argument", CASES, ids=[c[0].__name__ for c in CASES]
)
def test_typed_error(backend, error, builtins, call, function, argument):
    with pytest.raises(error) as info:
        call(backend)
    err = info.value
    assert isinstance(err, errors.InvalidArgumentError)
    assert all(isinstance(err, b) for b in builtins)
    assert f"ivy.{function} ({backend} backend)" in str(err)
    assert (err.function, err.backend) == (function, backend)
    if argument is not None:
        assert err.argument == argument
        assert f"argument {argument!r}" in str(err)
