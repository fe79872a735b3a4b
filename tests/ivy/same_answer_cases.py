"""The cases of the differential test (``test_same_answer.py``): for every public function of the
core, the calls every backend must answer alike. Inputs are numpy arrays (each backend gets its
own copy, made with the framework's own functions)."""

from __future__ import annotations

import dataclasses
import math
import os

import numpy as np

from ivy.dtypes import DTYPE_NAMES
from tests.ivy.differential import C, Case, PerBackend

# The full grid (every elementwise function on every dtype and dtype pair) runs with
# IVY_SAME_ANSWER_FULL=1; by default a smaller one keeps the test within its time budget (jax
# compiles each operation once per dtype and shape).
FULL = bool(os.environ.get("IVY_SAME_ANSWER_FULL"))

inf, nan = math.inf, math.nan

ALL_DTYPES = DTYPE_NAMES  # every dtype ivy names
INTEGERS = ("int8", "int16", "int32", "int64", "uint8", "uint16", "uint32", "uint64")
FLOATS = ("float16", "float32", "float64")
COMPLEX = ("complex64", "complex128")

# Values of each dtype that exercise its edges: extremes, zero of both signs, halves (rounding
# ties), infinities and NaN.
_FLOAT_VALUES = [0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 1.5, 2.5, -2.5, 3.0, 0.001, 100.0, inf, -inf, nan]
# (none on a branch cut, where the sign of a result is implementation-defined: jax and numpy
# part on asinh(-2j))
_COMPLEX_VALUES = [0j, 1 + 1j, -1.5 + 0.5j, 0.5j, 0.5 - 2j, 2.5 - 1j]


def values(dtype: str) -> np.ndarray:
    """A 1-D array of edge values of ``dtype``."""
    if dtype == "bool":
        return np.array([True, False, True])
    if dtype in INTEGERS:
        info = np.iinfo(dtype)
        picked = [info.min, info.max, 0, 1, 2, 7, -1, -7, info.min + 1, info.max - 1]
        return np.array([v for v in picked if info.min <= v <= info.max], dtype=dtype)
    if dtype in COMPLEX:
        return np.array(_COMPLEX_VALUES, dtype=dtype)
    return np.array(_FLOAT_VALUES, dtype=dtype)


def small(dtype: str, shape=(2, 3), seed: int = 0) -> np.ndarray:
    """Small values of ``dtype`` (no overflow in sums and products), of ``shape``."""
    rng = np.random.default_rng(seed)
    if dtype == "bool":
        return rng.random(shape) > 0.5
    if dtype in INTEGERS:
        low = 0 if dtype.startswith("u") else -3
        return rng.integers(low, 4, shape).astype(dtype)
    out = rng.integers(-8, 9, shape) / 4  # multiples of 1/4: exact in every float dtype
    if dtype in COMPLEX:
        out = out + 1j * rng.integers(-8, 9, shape) / 4
    return np.asarray(out, dtype=dtype)


def a(data, dtype: str) -> np.ndarray:
    return np.asarray(data, dtype=dtype)


# ----------------------------------------------------------------------------------------------
# Elementwise functions
# ----------------------------------------------------------------------------------------------

UNARY = (
    "abs acos acosh asin asinh atan atanh bitwise_invert ceil conj cos cosh exp expm1 floor imag "
    "isfinite isinf isnan log log10 log1p log2 logical_not negative positive real reciprocal "
    "round sign signbit sin sinh sqrt square tan tanh trunc nan_to_num"
).split()
BINARY = (
    "add atan2 bitwise_and bitwise_left_shift bitwise_or bitwise_right_shift bitwise_xor "
    "copysign divide equal floor_divide greater greater_equal hypot less less_equal logaddexp "
    "logical_and logical_or logical_xor maximum minimum multiply nextafter not_equal pow "
    "remainder subtract"
).split()


# The dtype kinds (numpy's letters: b bool, i and u integers, f real floating, c complex) that a
# function refuses: the Array API standard's table, with ivy's one extension (functions of real
# numbers take integers and bools, computed in float32). Every backend raises TypeError (ivy's
# DtypeError) on them.
_NO_COMPLEX = "atan2 copysign hypot nextafter logaddexp signbit ceil floor trunc greater "
_NO_COMPLEX += "greater_equal less less_equal maximum minimum remainder floor_divide"
REFUSED_KINDS = {name: "c" for name in _NO_COMPLEX.split()}
REFUSED_KINDS.update(
    {name: "fc" for name in "bitwise_and bitwise_or bitwise_xor bitwise_invert".split()}
)
REFUSED_KINDS.update({name: "fc" for name in ("bitwise_left_shift", "bitwise_right_shift")})
# Booleans where the standard takes numbers only and the frameworks part (numpy's square of a
# bool is int8, jax's int32, torch's int64; numpy's shift of bools answers, torch refuses):
# not compared; docs/conformance.md lists them.
UNDEFINED_FOR_BOOL = frozenset(
    (
        "bitwise_left_shift bitwise_right_shift ceil floor trunc round conj real negative "
        "positive sign square subtract pow remainder floor_divide"
    ).split()
)
# Complex numbers where the standard leaves them out and the frameworks part: numpy and jax order
# complex numbers lexicographically (less, maximum...), torch and tensorflow refuse them;
# logaddexp of complex numbers answers on torch and jax. Not compared (docs/conformance.md).
UNDEFINED_FOR_COMPLEX = frozenset(
    "greater greater_equal less less_equal maximum minimum logaddexp".split()
)
# torch has no kernel for these on uint64 and computes them through int64: values of 2**63 or
# more raise UnsupportedError there (a NotImplementedError), tested on their own.
THROUGH_INT64_ON_TORCH = frozenset(("bitwise_right_shift", "floor_divide", "remainder"))
# Divisors and exponents whose result the standard leaves to the implementation (integer
# division by zero, integer powers with negative exponents, complex division by zero).
_NONZERO_DIVISOR = frozenset(("floor_divide", "remainder", "divide", "pow"))


def _kinds(args) -> set[str]:
    """The dtype kinds of a call's operands, and of the dtype they promote to (numpy's
    int64 with uint64 is float64)."""
    arrays = [v for v in args if isinstance(v, np.ndarray)]
    kinds = {v.dtype.kind for v in arrays}
    if arrays:
        kinds.add(np.result_type(*arrays).kind)
    for v in args:
        if isinstance(v, (bool, int, float, complex)) and not isinstance(v, np.ndarray):
            scalar_kind = {bool: "b", int: "i", float: "f", complex: "c"}[type(v)]
            if scalar_kind in "fc" and kinds <= set("biu" + scalar_kind):
                kinds.add(scalar_kind)
    return kinds


def _for(name: str, cases: list[Case]) -> list[Case]:
    """``cases`` for function ``name``: those on refused dtypes expect TypeError, those on
    bools where the standard leaves bools out are dropped."""
    refused = REFUSED_KINDS.get(name, "")
    out = []
    for case in cases:
        kinds = _kinds(case.args)
        if name in UNDEFINED_FOR_COMPLEX and "c" in kinds:
            continue
        if kinds & set(refused):  # (a dtype refused is found before shapes that differ)
            case = Case(case.args, case.kwargs, raises=TypeError, label=case.label)
        elif name in UNDEFINED_FOR_BOOL and kinds == {"b"}:
            continue
        out.append(case)
    return out


def _defined_operands(name: str, cases: list[Case]) -> list[Case]:
    """``cases`` without the operands whose result the standard leaves to the implementation:
    zero divisors of integers and complex numbers (ones instead), negative integer exponents
    (their magnitude instead), complex powers of zero, float floor division by or of
    infinities (numpy, torch and jax give NaN where the standard, and tensorflow, give an
    infinity)."""
    if name not in _NONZERO_DIVISOR:
        return cases
    out = []
    for case in cases:
        args = list(case.args)
        x1, x2 = args[0], args[1]
        if isinstance(x2, np.ndarray) and x2.dtype.kind in "iuc":
            x2 = np.where(x2 == 0, np.ones((), x2.dtype), x2)
        if name == "pow" and isinstance(x2, np.ndarray) and x2.dtype.kind == "i":
            x2 = np.abs(x2) % 8
        if name == "pow" and "c" in _kinds(case.args):
            if isinstance(x1, np.ndarray):
                x1 = np.where(x1 == 0, np.ones((), x1.dtype), x1)
        if name == "floor_divide":
            x1, x2 = (
                np.where(np.isinf(v), 2, v).astype(v.dtype)
                if isinstance(v, np.ndarray) and v.dtype.kind == "f"
                else v
                for v in (x1, x2)
            )
        args[0], args[1] = x1, x2
        out.append(dataclasses.replace(case, args=tuple(args)))
    return out


def _uint64_through_int64(name: str) -> list[Case]:
    """torch's uint64 beyond int64: UnsupportedError there; below 2**63 every backend
    answers alike."""
    if name not in THROUGH_INT64_ON_TORCH:
        return []
    big = a([2**64 - 1, 2**63], "uint64")
    return [
        C(big, a([3, 5], "uint64"), _backends=("torch",), _raises=NotImplementedError),
        C(a([2**63 - 1, 9], "uint64"), a([3, 5], "uint64")),
    ]


def _unary_cases() -> list[Case]:
    dtypes = (
        ALL_DTYPES
        if FULL
        else ("bool", "int8", "uint8", "uint64", "float32", "float64", "complex64")
    )
    cases = [C(values(dt)) for dt in dtypes]
    cases += [C(a(-2.5, "float32")), C(np.zeros((2, 0), "int16"))]  # 0-d, empty
    return cases


# Mixed dtypes: within a kind (the Array API's table), across kinds (ivy's rule: the floating or
# complex operand's dtype), and 0-d arrays, which promote as arrays, not as Python scalars.
_MIXED = [
    ("int8", "uint8"),
    ("uint16", "int32"),
    ("int64", "uint64"),
    ("float16", "float32"),
    ("complex64", "float64"),
    ("bool", "int8"),
    ("bool", "float32"),
    ("uint8", "float16"),
]
# numpy promotes an int32 or int64 array with a float32 one to float64 (and int16 with float16 to
# float32, int32 with complex64 to complex128), where the others give the floating operand's
# dtype: ivy's dispatch calls numpy's own functions on two numpy arrays, at no cost, and does
# not look at their dtypes (docs/conformance.md). Python scalars promote alike everywhere.
NUMPY_PROMOTES_MIXED_KINDS = [
    ("int32", "float32"),
    ("int64", "float32"),
    ("int16", "float16"),
    ("int32", "complex64"),
]


def _binary_cases(name: str) -> list[Case]:
    dtypes = (
        ALL_DTYPES
        if FULL
        else ("bool", "int8", "uint8", "uint64", "float32", "float64", "complex64")
    )
    cases = []
    for dt in dtypes:  # each dtype with itself, edge values against each other
        v = w = values(dt)
        if dt == "uint64" and name in THROUGH_INT64_ON_TORCH:
            v = w = v[v < 2**63]
        if name in _NONZERO_DIVISOR and dt in INTEGERS + COMPLEX:
            w = v[v != 0]
            if name == "pow" and dt in INTEGERS:
                w = a([0, 1, 2, 7], dt)  # no negative exponents, no overflowing ones
            if name == "pow" and dt in COMPLEX:
                v = w  # (0j ** 0j: 1 in numpy, NaN in torch)
        cases.append(C(v[:, None], w[None, :]))
    for d1, d2 in _MIXED if FULL else _MIXED[::2]:
        cases.append(C(small(d1, (2, 3), 1), small(d2, (3,), 2)))
    for d1, d2 in NUMPY_PROMOTES_MIXED_KINDS:
        cases.append(
            C(small(d1, (3,), 1), small(d2, (3,), 2), _backends=("torch", "jax", "tensorflow"))
        )
    cases += [
        C(a(100, "int64"), a([100, -100], "int8")),  # a 0-d int64 array is an array: int64
        C(a([1.0, 2.0], "float32"), a(3.0, "float64")),  # 0-d float64: float64
        C(a([100, 27], "int8"), a([100, 100], "int8")),  # overflow wraps
        C(np.ones((2, 1, 3), "float32"), np.ones((4, 1), "float32")),
        C(small("int8", (4,), 5), 2.5),  # Python scalars: of a higher kind, the default dtype
        C(3, small("uint8", (4,), 6)),
        C(small("float32", (4,), 7), -2),
        C(small("bool", (4,), 8), True),
        C(np.ones((2, 3), "float32"), np.ones((4, 3), "float32"), _raises=ValueError),
    ]
    return cases


CASES: dict[str, list[Case]] = {}
CASES.update({name: _for(name, _unary_cases()) for name in UNARY})
CASES.update(
    {
        name: _for(name, _defined_operands(name, _binary_cases(name))) + _uint64_through_int64(name)
        for name in BINARY
    }
)

F32 = small("float32", (2, 3))
F64 = small("float64", (2, 3), 1)
I64 = small("int64", (2, 3), 2)
NAN_TIES = a([[3.0, nan, 1.0, 3.0], [-0.0, 0.0, 2.0, 2.0]], "float32")
INT_TIES = a([[3, 1, 3, -2], [0, 5, 5, 0]], "int8")
VECTOR = a([0.5, -1.0, 2.0], "float64")
MATRIX = a([[4.0, 1.0, 0.5], [1.0, 3.0, -1.0], [0.5, -1.0, 2.0]], "float64")  # symmetric, PD
SINGULAR = a([[1.0, 2.0], [2.0, 4.0]], "float64")
IMAGES = small("float32", (1, 4, 5, 2), 3)


def _elementwise_extra() -> None:
    clip = [
        C(F32, 0.0, 1.0),
        C(F32, -0.5),
        C(F32, None, 0.25),
        C(F32, a([[0.0], [-1.0]], "float32"), 1.0),  # array and scalar bounds, broadcasting
        C(F32, -1.0, a([0.0, 0.5, 1.0], "float32")),
        C(a([1, 200, 50], "uint8"), -1, 100),  # a bound outside the dtype's range
        C(a([1, 100, -100], "int8"), a(0, "int64"), a(50, "int64")),  # keeps int8
        C(a([1, 100, -100], "int8"), 0.5, 50.5),  # float bounds round inward
        C(a([True, False], "bool"), True),
        C(a([], "float64")),
    ]
    CASES["clip"] = clip
    # half precision computed as in float32 (jax's own rounds the quotient: 2496, not 2498)
    halves = a([[2.5], [-2.5], [100.0]], "float16"), a([[0.001, 0.003, 0.5]], "float16")
    CASES["floor_divide"] = CASES["floor_divide"] + [C(*halves)]
    CASES["nan_to_num"] = _unary_cases() + [C(NAN_TIES, nan=-1.0, posinf=9.0, neginf=-9.0)]


def _creation() -> None:
    CASES["asarray"] = [
        C([1.0, 2.0]),
        C([[1, 2], [3, 4]]),
        C(True),
        C(1 + 2j),
        C(F64),
        C(I64, dtype="int8"),
        C([1.5, -2.5], dtype="float64"),
        C([np.float32(1.0), np.float32(2.0)]),
    ]
    for name in ("zeros", "ones"):
        CASES[name] = [
            C((2, 3)),
            C(3, dtype="int8"),
            C((), dtype="bool"),
            C((0, 2), dtype="complex64"),
        ]
    CASES["empty"] = [C((2, 3), _post=_shape_dtype), C(0, dtype="int64", _post=_shape_dtype)]
    CASES["full"] = [
        C((2, 2), 1.5),
        C(3, 7),
        C((2,), True),
        C((1, 2), 2, dtype="float16"),
        C((2,), 1j),
        C((), -1, dtype="uint8", _raises=OverflowError),
    ]
    CASES["arange"] = [
        C(5),
        C(1, 0),  # empty
        C(2, 11, 3),
        C(5, 0, -2),
        C(0.0, 1.0, 0.25),
        C(3, dtype="uint8"),
        C(-3, 3, dtype="int16"),
        C(0, 1, 0.1, dtype="float64"),
    ]
    CASES["linspace"] = [
        C(0.0, 1.0, 5),
        C(-1, 1, 4, endpoint=False),
        C(0, 10, 4, dtype="int64"),
        C(2.0, 2.0, 1),
        C(0.0, 1.0, 0),
        C(0j, 1 + 1j, 3),  # complex bounds (the Array API allows them)
        C(0.0, 1.0, 3, dtype="float64"),
    ]
    CASES["logspace"] = [
        C(0.0, 2.0, 3),
        C(0, 1, 4, base=2.0, endpoint=False),
        C(1, 2, 2, dtype="float64"),
    ]
    CASES["eye"] = [C(3), C(2, 4, k=1), C(3, 2, k=-1, dtype="int32"), C(0), C(2, k=5)]
    CASES["eye"] += [C(0, k=2**63), C(3, 4, k=-(2**63)), C(3, 4, k=10**20)]  # far diagonals
    for name in ("zeros_like", "ones_like"):
        CASES[name] = [
            C(F32),
            C(I64, dtype="bool"),
            C(a(2.0, "float64")),
            C(np.zeros((0, 3), "uint8")),
        ]
    CASES["empty_like"] = [C(F32, _post=_shape_dtype), C(I64, dtype="float16", _post=_shape_dtype)]
    CASES["full_like"] = [
        C(F32, 2.5),
        C(I64, -3),
        C(F32, 7, dtype="int16"),
        C(a([True], "bool"), False),
    ]
    CASES["from_dlpack"] = [C(F32), C(I64), C(a(True, "bool"))]
    CASES["meshgrid"] = [
        C(a([1, 2, 3], "int64"), a([4.0, 5.0], "float32")),
        C(a([1, 2, 3], "int64"), a([4.0, 5.0], "float32"), indexing="ij"),
        C(a([1.0], "float64")),
        C(),
    ]
    CASES["tril"] = [C(F32), C(I64, k=1), C(small("float64", (2, 3, 3)), k=-1)]
    CASES["triu"] = [C(F32), C(I64, k=-1), C(small("bool", (2, 3, 3)), k=2)]


def _shape_dtype(answer, xp):
    """The dtype and shape of an answer whose values are not defined (empty, random)."""
    return (xp.dtype(answer, as_str=True), tuple(answer.shape))


def _data_type() -> None:
    CASES["astype"] = [
        C(F32, "int32"),
        C(a([1.7, -1.7, 0.0], "float64"), "int8"),
        C(I64, "bool"),
        C(a([True, False], "bool"), "float16"),
        C(F32, "complex64"),
        C(a([300, -1], "int64"), "uint8"),  # wraps around
    ]
    pairs = [
        ("bool", "int8"),
        ("int64", "float64"),
        ("int8", "int16"),
        ("float64", "float32"),
        ("uint8", "int16"),
        ("float32", "complex64"),
        ("int64", "uint64"),
        ("float16", "float32"),
    ]
    CASES["can_cast"] = [C(d1, d2) for d1, d2 in pairs] + [C(I64, "float64"), C(F32, "float64")]
    CASES["result_type"] = [
        C("int8", "uint8"),
        C("float32", "float64"),
        C("int64", "uint64"),
        C("float16", "int8"),
        C(F32, "float64"),
        C(I64, 1.5),
        C(a([1], "int8"), 3),
        C(small("complex64"), F64),
    ]
    CASES["finfo"] = [C(dt) for dt in ("float16", "float32", "float64", "complex64")] + [C(F64)]
    CASES["iinfo"] = [C(dt) for dt in INTEGERS] + [C(I64)]
    CASES["isdtype"] = [
        C("float32", "real floating"),
        C("int8", ("integral", "bool")),
        C("complex64", "numeric"),
        C("uint8", "signed integer"),
        C("bool", "bool"),
        C("float64", "float64"),
    ]


def _manipulation() -> None:
    x3 = small("float32", (2, 3, 4))
    CASES["reshape"] = [
        C(F32, (3, 2)),
        C(F32, (-1,)),
        C(a(1.0, "float64"), (1, 1)),
        C(F32, (4, 2), _raises=ValueError),
    ]
    CASES["permute_dims"] = [
        C(x3, (2, 0, 1)),
        C(x3, axes=(1, 0, 2)),
        C(x3, (-1, 0, -2)),  # negative axes, as the conformance suite passes them
        C(F32, (0, 0), _raises=ValueError),
    ]
    CASES["transpose"] = [C(x3), C(x3, (1, 2, 0)), C(a(2.0, "float32"))]
    CASES["concat"] = [
        C([F32, F32]),
        C([F32, F64], axis=-1),
        C([I64, F32], axis=None),
        C([a([1], "int8"), a([2], "uint8")]),
        C([F32, small("float32", (3, 3))], axis=1, _raises=ValueError),
    ]
    CASES["stack"] = [
        C([F32, F32]),
        C([a([1], "int8"), a([1.5], "float32")], axis=1),  # mixed dtypes promote
        C([a(1.0, "float64"), a(2.0, "float64")], axis=-1),
        C([F32, F32], axis=3, _raises=IndexError),
    ]
    CASES["unstack"] = [C(x3), C(x3, axis=-1), C(x3, axis=3, _raises=IndexError)]
    CASES["split"] = [
        C(small("float32", (6, 2))),
        C(small("float32", (6, 2)), 3),
        C(small("float32", (6, 2)), [1, 5]),
        C(small("float32", (2, 6)), 2, axis=-1),
        C(small("float32", (5, 2)), 2, _raises=ValueError),
    ]
    CASES["squeeze"] = [
        C(small("float32", (1, 3, 1))),
        C(small("float32", (1, 3, 1)), axis=-1),
        C(small("float32", (1, 3, 1)), axis=()),
        C(small("float32", (1, 3, 1)), axis=(0, 2)),
        C(small("float32", (1, 3, 1)), axis=1, _raises=ValueError),
        C(small("float32", (1, 3, 1)), axis=3, _raises=IndexError),
    ]
    CASES["expand_dims"] = [
        C(F32),
        C(F32, 1),  # by position, as the 2024.12 standard
        C(F32, axis=-1),
        C(F32, axis=(0, 3)),
        C(a(5, "int8"), axis=0),
        C(F32, axis=3, _raises=IndexError),
        C(F32, axis=(0, 0), _raises=IndexError),
    ]
    CASES["flip"] = [C(x3), C(x3, axis=1), C(x3, axis=(0, -1)), C(a(1.0, "float32"))]
    CASES["tile"] = [C(F32, (2, 1)), C(a([1, 2], "int8"), (3,)), C(F32, (2, 1, 2))]
    CASES["repeat"] = [
        C(a([1.0, 2.0], "float32"), 2),
        C(a([1.0, 2.0], "float32"), a([1, 2], "int8")),  # int8 counts
        C(F32, 2, axis=1),
        C(F32, a([0, 2], "int64"), axis=0),
    ]
    CASES["roll"] = [C(x3, 1), C(x3, -2, axis=1), C(x3, (1, 2), axis=(0, 2)), C(x3, 5, axis=-1)]
    CASES["swapaxes"] = [C(x3, 0, 2), C(x3, -1, 0), C(x3, 0, 3, _raises=IndexError)]
    CASES["broadcast_to"] = [
        C(a([1.0, 2.0], "float32"), (3, 2)),
        C(a(1, "int8"), (2, 2)),
        C(F32, (3, 3), _raises=ValueError),
    ]
    CASES["moveaxis"] = [C(x3, 0, -1), C(x3, (0, 1), (2, 0)), C(x3, 0, 3, _raises=IndexError)]
    CASES["broadcast_arrays"] = [
        C(a([1.0], "float32"), small("float32", (2, 1)), a(1, "int8")),
        C(F32),
        C(F32, small("float32", (3, 3)), _raises=ValueError),
    ]


def _indexing() -> None:
    x = small("float32", (3, 4))
    CASES["take"] = [
        C(x, a([0, 2, -1], "int64"), axis=1),  # negative indices count from the end
        C(x, a([[1, 0]], "int32"), axis=0),
        C(x, a([5, 11], "int64")),  # flattened
        C(x, a([], "int64"), axis=1),
        C(x, a([4], "int64"), axis=1, _raises=IndexError),  # out of range: raises eagerly
        C(x, a([-5], "int64"), axis=1, _raises=IndexError),
        C(x, a([12], "int64"), _raises=IndexError),
    ]
    CASES["take_along_axis"] = [
        C(x, a([[0, 3], [1, 1], [2, 0]], "int64"), axis=1),
        C(x, a([[2, 0, 1, -1]], "int64"), axis=0),
        C(x, a([[4], [0], [0]], "int64"), axis=1, _raises=IndexError),
    ]
    CASES["gather_nd"] = [
        C(x, a([[0, 1], [2, 3], [-1, 0]], "int64")),
        C(x, a([[1], [0]], "int64")),
        C(x, a([[3, 0]], "int64"), _raises=IndexError),
        C(x, a([[0, 4]], "int64"), _raises=IndexError),
    ]
    CASES["gather_flat"] = [
        C(x, a([0, 11, 5], "int64")),
        C(x, a([[1, 2]], "int32")),
        C(x, a([12], "int64"), _raises=IndexError),
    ]
    CASES["scatter_nd"] = [
        C(a([[0], [2], [0]], "int64"), a([1.0, 2.0, 3.0], "float32"), (4,)),  # sums duplicates
        C(a([[0, 1], [1, 0]], "int64"), a([5, 7], "int32"), (2, 2), reduction="replace"),
        C(a([[0], [0], [1]], "int64"), a([3.0, -1.0, 2.0], "float64"), (3,), reduction="min"),
        C(a([[0], [0], [1]], "int64"), a([3, -1, 2], "int8"), (3,), reduction="max"),
        C(a([[1]], "int64"), a([[1.0, 2.0]], "float32"), (2, 2)),
        C(a([[4]], "int64"), a([1.0], "float32"), (4,), _raises=IndexError),
    ]
    CASES["scatter_flat"] = [
        C(a([0, 2, 0], "int64"), a([1.0, 2.0, 3.0], "float32"), 4),
        C(a([1, 1], "int64"), a([4, 5], "int64"), 3, reduction="max"),
        C(a([3], "int64"), a([1.0], "float32"), 3, _raises=IndexError),
    ]
    CASES["put_rows"] = [
        C(x, a([2, -3], "int64"), small("float32", (2, 4), seed=1)),  # negative from the end
        C(small("int8", (4,)), a([3, 0], "int32"), a([7, -7], "int8")),
        C(small("float64", (2, 2, 3)), a([1], "int64"), small("float64", (1, 2, 3), seed=2)),
        C(x, a([], "int64"), small("float32", (0, 4))),
        C(x, a([1], "int64"), small("float32", (1, 4)).astype("float64")),  # to x's dtype
        C(x, a([3], "int64"), small("float32", (1, 4)), _raises=IndexError),
        C(x, a([-4], "int64"), small("float32", (1, 4)), _raises=IndexError),
        C(x, a([0, 1], "int64"), small("float32", (1, 4)), _raises=ValueError),  # rows differ
        C(x, a([[0]], "int64"), small("float32", (1, 4)), _raises=ValueError),  # not 1-D
        C(x, a([0.0], "float32"), small("float32", (1, 4)), _raises=TypeError),  # not integers
    ]
    CASES["one_hot"] = [
        C(a([0, 2, 1], "int64"), 3),
        C(a([[1], [0]], "int32"), 2, dtype="int8"),
        C(a([1], "int64"), 3, dtype="bool"),
        C(a([3], "int64"), 3, _raises=IndexError),
        C(a([-1], "int64"), 3, _raises=IndexError),
    ]
    CASES["indices_where"] = [
        C(a([[True, False], [False, True]], "bool")),
        C(x > 0),
        C(a(True, "bool")),
        C(a([0, 0], "int8")),
    ]


def _searching_sorting_sets() -> None:
    for name in ("argmax", "argmin"):
        CASES[name] = [
            C(NAN_TIES),  # NaN wins; ties: the first
            C(NAN_TIES, axis=1),
            C(INT_TIES, axis=0, keepdims=True),
            C(a([False, True, True], "bool")),
            C(a([2, 65535, 7], "uint16")),
            C(a([], "float32"), _raises=ValueError),
        ]
    CASES["count_nonzero"] = [
        C(NAN_TIES),
        C(INT_TIES, axis=1),
        C(INT_TIES, axis=(0, 1), keepdims=True),
        C(a([True, False], "bool")),
    ]
    CASES["nonzero"] = [
        C(INT_TIES),
        C(a([0.0, -0.0, nan], "float32")),
        C(a(1.0, "float32"), _raises=ValueError),
    ]
    CASES["searchsorted"] = [
        C(a([1.0, 2.0, 2.0, 3.0], "float32"), a([2.0, 0.0, 5.0, nan], "float32")),
        C(a([1.0, 2.0, 2.0, 3.0], "float32"), a([2.0], "float32"), side="right"),
        C(a([1.0, inf, nan, nan], "float32"), a([2.0, inf, nan, -inf], "float32")),
        C(a([1.0, inf, nan, nan], "float64"), a([2.0, inf, nan, -inf], "float64"), side="right"),
        C(a([3, 1, 2], "int64"), a([2, 3], "int64"), sorter=a([1, 2, 0], "int64")),
        C(a([1, 5], "int8"), a([2, 9], "int16")),
    ]
    CASES["where"] = [
        C(a([True, False, True], "bool"), F32[0], F32[1]),
        C(
            a([[True], [False]], "bool"), a([1, 2, 3], "int8"), a(0, "int64")
        ),  # broadcasting, promotion
        C(a([True, False], "bool"), 1.5, a([1, 2], "int32")),
        C(a([1, 0], "int8"), a([1.0, 2.0], "float32"), a([3.0, 4.0], "float32")),
        C(a([True, False], "bool"), F32, F32, _raises=ValueError),
    ]
    for name in ("sort", "argsort"):
        CASES[name] = [
            C(NAN_TIES),  # NaN last; -0.0 equal to 0.0; stable
            C(NAN_TIES, descending=True),
            C(INT_TIES, axis=0),
            C(a([True, False, True], "bool")),
            C(a([3, 65535, 0], "uint16"), descending=True),
            C(a([], "float64")),
        ]
    CASES["top_k"] = [
        C(NAN_TIES, 2),
        C(NAN_TIES, 3, largest=False),
        C(INT_TIES, 1, axis=0),
        C(a([2, 18446744073709551615, 7], "uint64"), 2),
        C(NAN_TIES, 5, _raises=ValueError),
    ]
    for name in ("unique_values", "unique_counts", "unique_inverse", "unique_all"):
        CASES[name] = [
            C(a([3, 1, 3, 2, 1], "int64")),
            C(NAN_TIES),
            C(a([True, False, True], "bool")),
            C(a([], "float32")),
        ]
    CASES["isin"] = [
        C(INT_TIES, a([3, 5], "int8")),
        C(INT_TIES, a([3, 5], "int64"), invert=True),
        C(NAN_TIES, a([nan, 0.0], "float32")),  # NaN is never found; -0.0 is 0.0
    ]


def _statistical() -> None:
    x3 = small("float32", (2, 3, 4))
    reductions = [
        C(F32),
        C(x3, axis=1),
        C(x3, axis=(0, 2), keepdims=True),
        C(x3, axis=()),
        C(x3, axis=-1),
        C(a(2.5, "float64")),
        C(x3, axis=3, _raises=IndexError),
    ]
    for name in ("sum", "prod"):
        CASES[name] = reductions + [
            C(a([200, 100], "uint8")),  # unsigned: uint64
            C(a([100, 100], "int8")),  # signed: int64
            C(a([True, True], "bool")),
            C(F32, dtype="float64"),
            C(a([], "int16")),
        ]
    for name in ("min", "max"):
        CASES[name] = reductions + [
            C(NAN_TIES, axis=1),
            C(a([True, False], "bool")),
            C(a([3, 65535], "uint16")),
            C(a([], "float32"), _raises=ValueError),  # no identity
            C(np.zeros((0, 2), "float32"), axis=0, _raises=ValueError),
        ]
    for name in ("mean", "var", "std"):
        extra = [C(a([1, 2, 4], "int8")), C(a([], "float32"), _tol={})]
        if name != "mean":
            extra += [C(x3, axis=1, correction=1), C(F64, correction=0.5)]
        CASES[name] = reductions + extra
    CASES["logsumexp"] = reductions + [
        C(a([-inf, -inf], "float32")),
        C(a([inf, 1.0], "float32")),
        C(a([1, 2], "int32")),
    ]
    CASES["median"] = reductions[:-2] + [
        C(NAN_TIES, axis=1),
        C(a([1, 4, 2, 3], "int64")),
        C(a([], "float32")),
    ]
    CASES["quantile"] = [
        C(F32, 0.5),
        C(x3, [0.1, 0.9], axis=1),
        C(x3, a([0.25], "float64"), axis=-1, keepdims=True),
        C(F32, 0.3, method="nearest"),
        C(F32, 0.3, method="lower"),
        C(F32, 0.3, method="midpoint"),
        C(F32, 1.5, _raises=ValueError),
    ]
    for name in ("cumulative_sum", "cumulative_prod"):
        CASES[name] = [
            C(a([1.0, 2.0, 3.0], "float32")),
            C(F32, axis=1),
            C(F32, axis=0, include_initial=True),
            C(a([200, 100], "uint8")),
            C(a([100, 100], "int8")),
            C(a([True, True], "bool")),
            C(F32, _raises=ValueError),  # axis required for 2-D
        ]
    for name in ("cumsum", "cumprod"):
        CASES[name] = [
            C(F32),
            C(F32, -1, exclusive=True),
            C(F32, 1, reverse=True),
            C(F32, 0, exclusive=True, reverse=True),
            C(a([200, 100], "uint8")),
            C(a([True, True], "bool"), dtype="int32"),
        ]


def _utility() -> None:
    for name in ("all", "any"):
        CASES[name] = [
            C(a([0, 2], "uint8")),  # a bool, whatever the dtype
            C(NAN_TIES),  # NaN is true
            C(NAN_TIES, axis=1, keepdims=True),
            C(a([], "bool")),
            C(a([[True, False]], "bool"), axis=()),
            C(a([0, 5], "uint16")),
        ]
    CASES["diff"] = [
        C(a([1, 4, 9, 16], "int64")),
        C(F32, axis=0),
        C(F32, n=2),
        C(a([1.0, 2.0], "float32"), prepend=0.0, append=a([5.0], "float32")),
        C(a([True, False, False], "bool")),
        C(a([3, 1], "uint8")),  # wraps around
    ]
    CASES["isclose"] = [
        C(a([1.0, nan, inf], "float32"), a([1.0 + 1e-7, nan, inf], "float32")),
        C(a([1.0, nan], "float64"), a([1.1, nan], "float64"), rtol=0.2, equal_nan=True),
        C(F32, 0.0, atol=0.5),
        C(I64, a(1, "int8")),
    ]
    CASES["allclose"] = [
        C(F32, F32),
        C(a([1.0, nan], "float32"), a([1.0, nan], "float32"), equal_nan=True),
        C(I64, 1.0),
    ]
    CASES["to_numpy"] = [C(F32), C(I64), C(a(True, "bool"))]
    CASES["to_list"] = [C(F32), C(a([1, 2], "uint8")), C(a(1.5, "float64"))]
    CASES["shape"] = [C(F32), C(a(1, "int8")), C(np.zeros((0, 3), "float32"))]
    CASES["dtype"] = [C(F32, as_str=True), C(I64, as_str=True), C(a([True], "bool"), as_str=True)]
    CASES["dev"] = [C(F32)]
    CASES["to_framework"] = [C(F32, "numpy"), C(I64, "torch", _post=lambda r, xp: r.numpy())]


def _linalg() -> None:
    batch = np.stack([MATRIX, MATRIX * 2 + np.eye(3)])
    CASES["matmul"] = [
        C(MATRIX, VECTOR),
        C(VECTOR, MATRIX),
        C(VECTOR, VECTOR),
        C(batch, MATRIX),
        C(a([[1, 2]], "int8"), a([[3], [4]], "int8")),  # int8: no tensorflow kernel
        C(a([[1.0]], "float32"), a([[2.0]], "float64")),  # promotes
        C(MATRIX, a([1.0, 2.0], "float64"), _raises=ValueError),
    ]
    CASES["tensordot"] = [
        C(MATRIX, MATRIX),
        C(batch, MATRIX, axes=1),
        C(batch, VECTOR, axes=([-1], [0])),
        C(a([[1, 2], [3, 4]], "int8"), a([[1, 0], [0, 1]], "int8"), axes=1),
        C(MATRIX, a([1.0, 2.0], "float32"), axes=1, _raises=ValueError),
    ]
    CASES["vecdot"] = [
        C(MATRIX, VECTOR),
        C(batch, MATRIX, axis=-2),
        C(small("complex64", (2, 3)), small("complex64", (2, 3), 4)),
        C(a([1, 2], "int32"), a([3, 4], "int32")),
        C(a([1.0, 2.0], "float32"), a([1.0, 2.0, 3.0], "float32"), _raises=ValueError),
    ]
    CASES["outer"] = [C(VECTOR, a([1.0, 2.0], "float32")), C(a([1, 2], "int8"), a([3], "uint8"))]
    CASES["cross"] = [
        C(MATRIX, MATRIX[::-1]),
        C(VECTOR, MATRIX, axis=-1),
        C(MATRIX, MATRIX, axis=0),
        C(a([1, 0, 0], "int64"), a([0, 1, 0], "int64")),
    ]
    CASES["diagonal"] = [C(MATRIX), C(batch, offset=1), C(batch, offset=-2), C(MATRIX, offset=5)]
    CASES["trace"] = [
        C(MATRIX),
        C(batch, offset=1),
        C(a([[1, 2], [3, 4]], "int8")),
        C(a([[1, 2], [3, 4]], "uint8")),
        C(MATRIX, dtype="float32"),
    ]
    CASES["matrix_transpose"] = [C(batch), C(F32)]
    CASES["det"] = [C(MATRIX), C(batch), C(SINGULAR), C(a([[2, 1], [1, 3]], "int32"))]
    CASES["slogdet"] = [C(MATRIX), C(batch), C(SINGULAR), C(a([[1 + 1j, 0], [0, 2]], "complex64"))]
    CASES["inv"] = [
        C(MATRIX),
        C(batch),
        C(a([[2, 1], [1, 3]], "int64")),
        C(SINGULAR, _raises=ValueError),
    ]
    CASES["solve"] = [
        C(MATRIX, VECTOR),
        C(MATRIX, MATRIX),
        C(batch, VECTOR[:, None]),
        C(SINGULAR, a([1.0, 1.0], "float64"), _raises=ValueError),
    ]
    CASES["cholesky"] = [
        C(MATRIX),
        C(batch, upper=True),
        C(a([[1.0, 2.0], [2.0, 1.0]], "float64"), _raises=ValueError),
    ]
    CASES["eigvalsh"] = [C(MATRIX), C(batch)]
    CASES["eigh"] = [C(MATRIX, _post=_eigh_parts), C(batch, _post=_eigh_parts)]
    CASES["svdvals"] = [C(MATRIX), C(small("float64", (2, 3, 2)))]
    CASES["svd"] = [
        C(MATRIX, _post=_svd_parts),
        C(small("float64", (3, 2)), full_matrices=False, _post=_svd_parts),
    ]
    CASES["qr"] = [
        C(MATRIX, _post=_qr_parts),
        C(small("float64", (3, 2)), mode="complete", _post=_qr_parts),
    ]
    CASES["pinv"] = [
        C(MATRIX),
        C(small("float64", (3, 2))),
        C(SINGULAR),
        C(a([[1 + 1j, 0], [0, 2]], "complex64")),
        C(a(batch, "float32"), rtol=a([0.1, 0.9], "float64")),  # an rtol per matrix, as float64
        C(a(np.zeros((2, 0)), "float32")),  # empty matrices and stacks
        C(a(np.zeros((2, 2, 0)), "float32"), rtol=a([0.5, 0.5], "float64")),
        C(a(np.zeros((0, 2, 1)), "float32"), rtol=0.5),
    ]
    CASES["matrix_rank"] = [C(MATRIX), C(SINGULAR), C(batch), C(SINGULAR, rtol=0.1)]
    CASES["matrix_power"] = [
        C(MATRIX, 3),
        C(MATRIX, 0),
        C(MATRIX, -1),
        C(a([[1, 2], [0, 1]], "int8"), 2),
    ]
    CASES["matrix_norm"] = [
        C(MATRIX),
        C(batch, ord="nuc"),
        C(MATRIX, ord=1),
        C(MATRIX, ord=-inf),
        C(MATRIX, ord=2, keepdims=True),
    ]
    CASES["vector_norm"] = [
        C(VECTOR),
        C(MATRIX, axis=0, ord=1),
        C(MATRIX, ord=inf),
        C(MATRIX, axis=(0, 1), ord=3, keepdims=True),
        C(a([3, 4], "int8")),
        C(VECTOR, ord=0),
    ]
    CASES["einsum"] = [
        C("ij,jk->ik", MATRIX, MATRIX),
        C("ii->i", MATRIX),
        C("i,j->ij", VECTOR, a([1.0, 2.0], "float32")),
        C("...ij->...ji", small("float32", (2, 2, 3))),
    ]
    CASES["vector_to_skew_symmetric_matrix"] = [C(VECTOR), C(small("float32", (2, 3)))]
    CASES["cosine_similarity"] = [
        C(MATRIX, MATRIX[::-1]),
        C(F32, small("float32", (2, 3), 5), axis=0),
        C(a([0.0, 0.0], "float32"), a([1.0, 0.0], "float32")),
    ]
    CASES["clip_vector_norm"] = [C(MATRIX, 1.0), C(MATRIX, 2.0, axis=-1), C(F32, 0.5, p=1.0)]
    CASES["clip_by_global_norm"] = [C({"a": MATRIX, "b": VECTOR}, 1.0), C([F32, F32], 100.0)]


def _eigh_parts(answer, xp):
    """Eigenvalues, and the projector of each eigenvector (vectors are defined up to a sign)."""
    w, v = answer
    return w, xp.multiply(xp.expand_dims(v, -2), xp.expand_dims(v, -1))


def _svd_parts(answer, xp):
    u, s, vh = answer
    return s, xp.matmul(
        xp.multiply(u[..., :, : s.shape[-1]], xp.expand_dims(s, -2)), vh[..., : s.shape[-1], :]
    )


def _qr_parts(answer, xp):
    q, r = answer
    return tuple(q.shape), tuple(r.shape), xp.matmul(q, r), xp.abs(xp.linalg.diagonal(r))


def _fft() -> None:
    sig = small("float32", (2, 8))
    csig = small("complex64", (2, 8), 4)
    for name in ("fft", "ifft"):
        CASES[name] = [
            C(csig),
            C(sig, n=6),
            C(csig, axis=0, norm="ortho"),
            C(a([1, 2, 3], "int8"), norm="forward"),
        ]
    for name in ("rfft", "ihfft"):
        CASES[name] = [C(sig), C(sig, n=5, axis=0), C(a([1, 2, 3, 4], "int32"), norm="ortho")]
    for name in ("irfft", "hfft"):
        CASES[name] = [C(csig), C(csig, n=10), C(csig, axis=0, norm="forward")]
    for name in ("fftn", "ifftn"):
        CASES[name] = [C(csig), C(csig, s=(2, 4)), C(sig, axes=(1,), norm="ortho")]
    CASES["rfftn"] = [C(sig), C(sig, s=(2, 6)), C(sig, axes=(0,))]
    CASES["irfftn"] = [C(csig), C(csig, s=(2, 10)), C(csig, axes=(1,))]
    for name in ("fftfreq", "rfftfreq"):
        CASES[name] = [C(8), C(5, d=0.5), C(4, dtype="float64")]
    for name in ("fftshift", "ifftshift"):
        CASES[name] = [C(sig), C(sig, axes=1), C(sig, axes=(0, 1)), C(a(1.0, "float32"))]


def _numerics_image_interpolation_padding() -> None:
    CASES["safe_sqrt"] = [C(a([0.0, 4.0, -1.0], "float64")), C(F32)]
    CASES["safe_norm"] = [
        C(MATRIX),
        C(a([[0.0, 0.0], [3.0, 4.0]], "float32"), axis=-1, keepdims=True),
    ]
    CASES["safe_hypot"] = [C(a([0.0, 3.0], "float64"), a([0.0, 4.0], "float64"))]
    CASES["safe_atan2"] = [C(a([0.0, 1.0, -1.0], "float64"), a([0.0, 0.0, -1.0], "float64"))]
    CASES["safe_divide"] = [
        C(a([1.0, 2.0], "float32"), a([0.0, 4.0], "float32")),
        C(a([1.0], "float64"), a([0.0], "float64"), fill=7.0),
    ]
    CASES["horner"] = [C(VECTOR, [1.0, -2.0, 0.5]), C(F32, [3.0])]
    CASES["taylor_switch"] = [
        C(
            a([0.0, 1e-6, 0.25], "float64"),
            [1.0, -1 / 6, 1 / 120],
            PerBackend(lambda xp: lambda x_sq: xp.sin(xp.sqrt(x_sq)) / xp.sqrt(x_sq), "sinc"),
        ),
    ]
    CASES["matvec"] = [C(MATRIX, VECTOR), C(np.stack([MATRIX, MATRIX]), VECTOR)]
    CASES["stack_vector"] = [
        C([VECTOR, VECTOR * 2, VECTOR]),
        C([a(1.0, "float32"), a(2.0, "float32")]),
    ]
    CASES["stack_matrix"] = [C([[VECTOR, VECTOR], [VECTOR * 2, VECTOR]])]
    CASES["bilinear_resample"] = [C(IMAGES, a([[[0.0, 0.0], [1.5, 2.5], [4.0, 3.0]]], "float32"))]
    CASES["gradient_image"] = [C(IMAGES), C(small("int16", (2, 3, 3, 1)))]
    CASES["stack_images"] = [
        C([IMAGES[0], IMAGES[0], IMAGES[0]]),
        C([IMAGES[0]] * 2, desired_aspect_ratio=(2, 1)),
    ]
    CASES["linear_resample"] = [C(VECTOR, 5), C(F32, 2, axis=0), C(a([1, 3], "int32"), 3)]
    CASES["interp"] = [
        C(
            a([0.5, -1.0, 3.0], "float64"),
            a([0.0, 1.0, 2.0], "float64"),
            a([0.0, 10.0, 5.0], "float64"),
        ),
        C(
            1.5,
            a([0.0, 1.0, 2.0], "float32"),
            a([0.0, 10.0, 5.0], "float32"),
            left=-1.0,
            right=-2.0,
        ),
    ]
    CASES["constant_pad"] = [
        C(F32, [(1, 0), (0, 2)]),
        C(a([1, 2], "int8"), [(2, 1)], value=7),
        C(a(1.0, "float32"), []),
    ]
    CASES["zero_pad"] = [C(F32, [(1, 1), (0, 0)]), C(a([True], "bool"), [(1, 0)])]


def _nn() -> None:
    x1 = small("float32", (1, 6, 2))
    x2 = small("float32", (1, 5, 4, 2))
    x3 = small("float32", (1, 3, 4, 3, 1))
    CASES["conv1d"] = [
        C(x1, small("float32", (3, 2, 4), 1), 1, "SAME"),
        C(x1, small("float32", (2, 2, 3), 1), 2, "VALID", dilations=1),
    ]
    CASES["conv1d_transpose"] = [C(x1, small("float32", (3, 4, 2), 1), 2, "SAME")]
    CASES["conv2d"] = [
        C(x2, small("float32", (3, 3, 2, 3), 1), 1, "SAME"),
        C(x2, small("float32", (2, 2, 2, 1), 1), (2, 1), "VALID"),
    ]
    CASES["conv2d_transpose"] = [C(x2, small("float32", (3, 3, 4, 2), 1), 2, "SAME")]
    CASES["conv3d"] = [C(x3, small("float32", (2, 2, 2, 1, 2), 1), 1, "VALID")]
    CASES["conv3d_transpose"] = [C(x3, small("float32", (2, 2, 2, 2, 1), 1), 1, "VALID")]
    CASES["depthwise_conv2d"] = [C(x2, small("float32", (3, 3, 2), 1), 1, "SAME")]
    for name, x, k in (("1d", x1, 2), ("2d", x2, (2, 2)), ("3d", x3, 2)):
        CASES[f"max_pool{name}"] = [C(x, k, 1, "VALID"), C(x, k, 2, "SAME")]
        CASES[f"avg_pool{name}"] = [C(x, k, 1, "VALID"), C(x, k, 2, "SAME")]
    CASES["conv_general"] = [
        C(x1, small("float32", (3, 2, 4), 1), (1,), ((1, 1),), (1,)),
        C(x2, small("float32", (2, 2, 1, 4), 1), (1, 2), ((0, 1), (1, 0)), (1, 1), groups=2),
        C(x1, small("float32", (3, 4, 2), 1), (2,), ((1, 1),), (1,), transpose=True),
    ]
    CASES["pool_general"] = [
        C(x1, (2,), (2,), ((0, 1),)),
        C(x2, (2, 2), (1, 1), ((1, 0), (0, 1)), reduction="mean"),
    ]
    logits = small("float32", (2, 4))
    CASES["relu"] = [C(logits), C(a([-1, 2], "int8"))]
    CASES["sigmoid"] = [C(logits), C(a([-100.0, 0.0, 100.0], "float64"))]
    CASES["silu"] = [C(logits)]
    CASES["softplus"] = [C(logits), C(a([-100.0, 100.0], "float64"))]
    CASES["gelu"] = [C(logits), C(logits, approximate=True)]
    CASES["elu"] = [C(logits), C(logits, 0.5)]
    CASES["leaky_relu"] = [C(logits), C(logits, 0.1)]
    for name in ("softmax", "log_softmax"):
        CASES[name] = [
            C(logits),
            C(logits, axis=0),
            C(a(2.0, "float32")),
            C(a([-inf, 0.0], "float64")),
            C(a([[inf, 1.0, 2.0], [nan, 0.0, 1.0], [-inf, -inf, -inf]], "float32")),
        ]
    CASES["linear"] = [
        C(logits, small("float32", (3, 4), 1)),
        C(logits, small("float32", (3, 4), 1), a([1.0, 2.0, 3.0], "float32")),
    ]
    CASES["layer_norm"] = [
        C(logits),
        C(
            small("float32", (2, 3, 4)),
            (1, 2),
            scale=small("float32", (3, 4)),
            offset=small("float32", (3, 4)),
        ),
    ]
    CASES["dropout"] = [
        C(logits, 0.5, training=False),
        C(logits, 0.0),
        C(logits, 0.5, _post=_shape_dtype),
    ]
    CASES["scaled_dot_product_attention"] = [
        C(
            small("float32", (1, 3, 4)),
            small("float32", (1, 5, 4), 1),
            small("float32", (1, 5, 2), 2),
        )
    ]
    h = small("float32", (2, 3), 4)
    CASES["lstm_update"] = [
        C(
            small("float32", (2, 4, 5)),
            h,
            h,
            small("float32", (5, 12), 5),
            small("float32", (3, 12), 6),
            _tol={"rtol": 1e-4, "atol": 1e-5},
        )
    ]
    CASES["binary_cross_entropy"] = [
        C(a([0.1, 0.9, 0.5], "float32"), a([0.0, 1.0, 1.0], "float32")),
        C(logits, (logits > 0).astype("float32"), from_logits=True, reduction="none"),
    ]
    CASES["categorical_cross_entropy"] = [
        C(logits, a([[0, 1, 0, 0], [0, 0, 0, 1]], "float32"), from_logits=True),
        C(logits, logits, reduction="sum", from_logits=True),
    ]
    CASES["huber"] = [C(logits, logits * 2, delta=0.5), C(logits, logits, reduction="none")]
    CASES["mse"] = [C(logits, logits * 2), C(logits, 0.5 * logits, reduction="sum")]


def _random() -> None:
    def in_range(low, high):
        def post(answer, xp):
            values = np.asarray(xp.to_numpy(answer))
            return (
                xp.dtype(answer, as_str=True),
                values.shape,
                bool(np.all((values >= low) & (values < high))),
            )

        return post

    CASES["random_uniform"] = [
        C(0.0, 2.0, (3, 4), _post=in_range(0.0, 2.0)),
        C(shape=5, dtype="float64", _post=in_range(0, 1)),
    ]
    CASES["random_normal"] = [
        C(shape=(2, 3), _post=_shape_dtype),
        C(1.0, 2.0, 4, dtype="float64", _post=_shape_dtype),
    ]
    CASES["randint"] = [
        C(0, 5, (3, 3), _post=in_range(0, 5)),
        C(-2, 2, 10, dtype="int32", _post=in_range(-2, 2)),
    ]
    CASES["random_categorical"] = [C(small("float32", (2, 4)), num_samples=3, _post=in_range(0, 4))]
    CASES["shuffle"] = [C(a([1, 2, 3, 4], "int64"), _post=lambda r, xp: sorted(xp.to_list(r)))]
    CASES["seed"] = [C(0), C(123)]


DIFFERENTIABLE = ("torch", "jax", "tensorflow")


def _gradients_control_flow_compilation() -> None:
    def loss(xp):
        return lambda v: xp.sum(xp.multiply(v["w"], v["w"])) + xp.sum(xp.sin(v["b"]))

    variables = {"w": a([1.0, -2.0], "float64"), "b": a([0.5], "float64")}
    CASES["execute_with_gradients"] = [
        C(PerBackend(loss, "loss"), variables, _backends=DIFFERENTIABLE),
        C(PerBackend(loss, "loss"), variables, _backends=("numpy",), _raises=NotImplementedError),
    ]
    square = PerBackend(lambda xp: lambda x: xp.multiply(x, x), "square")
    CASES["execute_with_jacobian"] = [
        C(square, a([[1.0, 2.0]], "float64"), _backends=DIFFERENTIABLE)
    ]
    CASES["grad"] = [
        C(
            PerBackend(loss, "loss"),
            _backends=DIFFERENTIABLE,
            _post=lambda g, xp: g({"w": xp.asarray([1.0, -2.0]), "b": xp.asarray([0.5])}),
        )
    ]
    CASES["value_and_grad"] = [
        C(
            PerBackend(loss, "loss"),
            _backends=DIFFERENTIABLE,
            _post=lambda g, xp: g({"w": xp.asarray([1.0, -2.0]), "b": xp.asarray([0.5])}),
        )
    ]
    CASES["jacobian"] = [
        C(square, _backends=DIFFERENTIABLE, _post=lambda j, xp: j(xp.asarray([[1.0, 2.0]])))
    ]
    sum_of_squares = PerBackend(
        lambda xp: lambda leaves: (xp.sum(xp.multiply(leaves[0], leaves[0])), ()), "sum_sq"
    )
    CASES["value_and_grad_native"] = [
        C(sum_of_squares, [a([1.0, -2.0], "float64")], _backends=DIFFERENTIABLE)
    ]
    pair = PerBackend(lambda xp: lambda x: (xp.multiply(x, x), ()), "square_aux")
    CASES["jacobian_native"] = [C(pair, a([1.0, 2.0], "float64"), _backends=DIFFERENTIABLE)]
    CASES["stop_gradient"] = [C(F32)]
    triple = PerBackend(lambda xp: lambda x: xp.multiply(x, 3.0), "triple")
    pair = PerBackend(lambda xp: lambda x: (xp.multiply(x, 3.0), xp.add(x, 1.0)), "pair")
    CASES["with_gradient_of"] = [
        C(F32, triple, (F32,)),  # the value, on every backend (fn runs on tensorflow alone)
        C((F32, F32), pair, (F32,)),  # a nest of values
    ]
    CASES["variable"] = [C(F32, _post=lambda v, xp: xp.to_numpy(v))]
    step = PerBackend(lambda xp: lambda c, x: (xp.add(c, x), xp.multiply(c, 2.0)), "step")
    CASES["scan"] = [
        C(step, a(0.0, "float32"), a([1.0, 2.0, 3.0], "float32")),
        C(step, a([0.0, 1.0], "float64"), np.ones((2, 2), "float64")),
    ]
    body = PerBackend(
        lambda xp: lambda i, v: xp.add(v, xp.astype(xp.asarray(i), "float32")), "body"
    )
    CASES["fori_loop"] = [C(0, 4, body, a([0.0, 1.0], "float32")), C(3, 3, body, a(1.0, "float32"))]
    CASES["while_loop"] = [
        C(
            PerBackend(lambda xp: lambda v: xp.less(v, 10.0), "below 10"),
            PerBackend(lambda xp: lambda v: xp.multiply(v, 3.0), "triple"),
            a(1.0, "float32"),
        ),
        C(
            PerBackend(lambda xp: lambda v: xp.less(v, 1e9), "forever"),
            PerBackend(lambda xp: lambda v: xp.add(v, 1.0), "inc"),
            a(0.0, "float32"),
            maximum_iterations=5,
        ),
    ]
    CASES["cond"] = [
        C(
            True,
            PerBackend(lambda xp: lambda v: xp.add(v, 1.0), "inc"),
            PerBackend(lambda xp: lambda v: xp.add(v, -1.0), "dec"),
            F32,
        ),
        C(
            a(False, "bool"),
            PerBackend(lambda xp: lambda v: xp.add(v, 1.0), "inc"),
            PerBackend(lambda xp: lambda v: xp.add(v, -1.0), "dec"),
            F32,
        ),
    ]
    compiled = PerBackend(lambda xp: lambda x: xp.sin(x) * 2.0, "2 sin")
    CASES["compile_fn"] = [
        C(
            compiled,
            _backends=("jax", "tensorflow", "numpy"),
            _post=lambda c, xp: c(xp.asarray([0.5, 1.0])),
        )
    ]
    CASES["compile_native"] = [
        C(
            compiled,
            _backends=("jax", "tensorflow", "numpy"),
            _post=lambda c, xp: c(xp.asarray([0.5, 1.0])),
        )
    ]


def _applied_helpers() -> None:
    """What the applied libraries build on: constants, the compile boundary, dtypes by name."""
    CASES["constant"] = [
        C(np.array([1.5, -2.0, 0.25]), dtype="float32"),
        C(np.arange(6.0).reshape(2, 3)),
        C([[1, 2], [3, 4]], dtype="int64"),
        C(2.5),
    ]
    step = PerBackend(lambda xp: lambda c, x: (xp.add(c, x), xp.multiply(c, 2.0)), "step")
    CASES["compiled_scan"] = [
        C(
            step,
            _backends=("jax", "tensorflow", "numpy"),  # torch.compile takes ~17 s to start
            _post=lambda run, xp: run(xp.asarray(0.0), xp.asarray([1.0, 2.0, 3.0])),
        ),
        C(
            step,
            length=3,
            _backends=("jax", "tensorflow", "numpy"),
            _post=lambda run, xp: run(xp.asarray([0.0, 1.0]), xp.ones((3, 2))),
        ),
    ]
    CASES["dtype_name"] = [C(F32), C(I64), C(a([True], "bool")), C("float64")]
    CASES["enable_float64"] = [C()]


_elementwise_extra()
_creation()
_data_type()
_manipulation()
_indexing()
_searching_sorting_sets()
_statistical()
_utility()
_linalg()
_fft()
_numerics_image_interpolation_padding()
_nn()
_random()
_gradients_control_flow_compilation()
_applied_helpers()
