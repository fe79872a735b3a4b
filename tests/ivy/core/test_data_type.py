"""Tests of the core group ``data_type`` (``ivy/core/data_type.py``), on every backend.

astype and its paper spelling cast, and the handling of dtype names, on every backend.

The Array API's data type functions (can_cast, finfo, iinfo, isdtype, result_type) and
astype's device, on every backend and without any framework (dtype names).

References: numpy's finfo/iinfo read in Python numbers, the Array API's promotion table written
out below, and what each backend's own arithmetic actually produces.
"""

from __future__ import annotations

import itertools
import subprocess
import sys

import numpy as np
import pytest

import ivy
from ivy.core._dtype_rules import FInfo, IInfo
from tests.conftest import require
from tests.helpers import api, api_f, check, dtype_name, native, numpy_of

SIGNED = [-2.7, -1.0, -0.0, 0.0, 0.4, 1.5, 2.7, 100.25]


UNSIGNED = [0.0, 0.4, 1.5, 2.7, 100.25]


TARGETS = [
    "float16",
    "float32",
    "float64",
    "int8",
    "int16",
    "int32",
    "int64",
    "uint8",
    "bool",
]


def _source(source_dtype, target):
    values = UNSIGNED if target.startswith("uint") else SIGNED
    return np.array(values, dtype=source_dtype)


def _expected(a, target):
    """Floats to integers truncate toward zero; nonzero is True."""
    a64 = a.astype(np.float64)
    if target == "bool":
        return a64 != 0
    if target.startswith(("int", "uint")):
        return np.trunc(a64).astype(target)
    return a64.astype(target)


@pytest.mark.parametrize("name", ["astype", "cast"])
@pytest.mark.parametrize("source", ["float32", "float64"])
@pytest.mark.parametrize("target", TARGETS)
def test_astype_from_floats(backend, name, source, target):
    a = _source(source, target)
    expected = _expected(a, target)
    native_target = getattr(getattr(ivy, backend), target)
    for fn in api(backend, name):
        check(fn(native(a, backend), target), expected, backend, dtype=target)
        check(fn(native(a, backend), native_target), expected, backend, dtype=target)


@pytest.mark.parametrize("name", ["astype", "cast"])
@pytest.mark.parametrize("source", ["int32", "int64", "bool", "uint8"])
@pytest.mark.parametrize("target", ["float32", "float64", "int64", "int32", "bool"])
def test_astype_from_integers_and_bools(backend, name, source, target):
    a = np.array([0, 1, 7, 100], dtype=source)
    expected = (a != 0) if target == "bool" else a.astype(target)
    for fn in api(backend, name):
        check(fn(native(a, backend), target), expected, backend)


def test_astype_keeps_the_shape_of_0d_and_empty_arrays(backend):
    for a in (np.float32(2.5), np.zeros((0, 3), np.float32)):
        for fn in api(backend, "astype"):
            check(fn(native(a, backend), "float64"), np.asarray(a, np.float64), backend)


def test_astype_with_copy_false(backend):
    a = np.array([1.0, 2.0], np.float32)
    for fn in api(backend, "astype"):
        check(fn(native(a, backend), "float32", copy=False), a, backend)
        check(fn(native(a, backend), "float64", copy=False), a.astype(np.float64), backend)


def test_cast_is_the_same_function_as_astype(backend):
    assert ivy.cast is ivy.astype
    xp = getattr(ivy, backend)
    assert xp.cast is xp.astype


# Every function that takes a dtype refuses a name it does not know (clearly bogus names: whether
# aliases such as 'double' are accepted is left to the backends).
UNKNOWN_DTYPE_CALLS = {
    "astype": lambda b: ivy.astype(native(np.ones(2, np.float32), b), "float31"),
    "cast": lambda b: ivy.cast(native(np.ones(2, np.float32), b), "flaot32"),
    "asarray": lambda b: ivy.asarray([1.0, 2.0], dtype="int65", f=b),
    "zeros": lambda b: ivy.zeros((2,), dtype="float32x", f=b),
    "ones": lambda b: ivy.ones(3, dtype="doubble", f=b),
    "full": lambda b: ivy.full((2,), 1.0, dtype="float33", f=b),
    "arange": lambda b: ivy.arange(4, dtype="int63", f=b),
    "linspace": lambda b: ivy.linspace(0.0, 1.0, 3, dtype="floatt", f=b),
    "eye": lambda b: ivy.eye(2, dtype="float31", f=b),
    "zeros_like": lambda b: ivy.zeros_like(native(np.ones(2), b), dtype="zeros32"),
    "one_hot": lambda b: ivy.one_hot(native(np.array([0, 1]), b), 2, dtype="onehot"),
    "sum": lambda b: ivy.sum(native(np.ones(2), b), dtype="float65"),
    "random_uniform": lambda b: ivy.random_uniform(shape=(2,), dtype="uniform", f=b),
    "randint": lambda b: ivy.randint(0, 3, (2,), dtype="int63", f=b),
}


@pytest.mark.parametrize("name", sorted(UNKNOWN_DTYPE_CALLS))
def test_unknown_dtype_name_raises_type_error(backend, name):
    with pytest.raises(TypeError):
        UNKNOWN_DTYPE_CALLS[name](backend)


def test_unknown_dtype_name_raises_type_error_in_namespace(backend):
    xp = getattr(ivy, backend)
    with pytest.raises(TypeError):
        xp.astype(native(np.ones(2, np.float32), backend), "float31")
    for fn in api_f(backend, "zeros"):
        with pytest.raises(TypeError):
            fn((2,), dtype="float31")


ALL = ivy.dtypes.DTYPE_NAMES


FLOATS = ("float16", "float32", "float64")


COMPLEX = ("complex64", "complex128")


INTS = ("int8", "int16", "int32", "int64", "uint8", "uint16", "uint32", "uint64")


# The Array API's promotion table (2023.12), within each kind; every pair listed once.
_TABLE_ROWS = {
    ("int8", "int16"): "int16",
    ("int8", "int32"): "int32",
    ("int8", "int64"): "int64",
    ("int16", "int32"): "int32",
    ("int16", "int64"): "int64",
    ("int32", "int64"): "int64",
    ("uint8", "uint16"): "uint16",
    ("uint8", "uint32"): "uint32",
    ("uint8", "uint64"): "uint64",
    ("uint16", "uint32"): "uint32",
    ("uint16", "uint64"): "uint64",
    ("uint32", "uint64"): "uint64",
    ("int8", "uint8"): "int16",
    ("int8", "uint16"): "int32",
    ("int8", "uint32"): "int64",
    ("int16", "uint8"): "int16",
    ("int16", "uint16"): "int32",
    ("int16", "uint32"): "int64",
    ("int32", "uint8"): "int32",
    ("int32", "uint16"): "int32",
    ("int32", "uint32"): "int64",
    ("int64", "uint8"): "int64",
    ("int64", "uint16"): "int64",
    ("int64", "uint32"): "int64",
    ("float16", "float32"): "float32",
    ("float16", "float64"): "float64",
    ("float32", "float64"): "float64",
    ("float32", "complex64"): "complex64",
    ("float32", "complex128"): "complex128",
    ("float64", "complex64"): "complex128",
    ("float64", "complex128"): "complex128",
    ("complex64", "complex128"): "complex128",
}


TABLE = {**_TABLE_ROWS, **{(b, a): r for (a, b), r in _TABLE_ROWS.items()}}
TABLE.update({(d, d): d for d in ALL})


def _name(dtype) -> str:
    """Name of a dtype object of any backend (or of a name)."""
    if isinstance(dtype, str):
        return dtype
    name = str(dtype).removeprefix("torch.")
    if name.startswith("<dtype: "):  # tf.DType
        return dtype.name
    return np.dtype(name).name if name != "bool" else "bool"


def _as(backend, name):
    return getattr(getattr(ivy, backend), name)


@pytest.mark.parametrize("pair", sorted(TABLE), ids=lambda p: "-".join(p))
def test_result_type_follows_the_table_without_a_framework(pair):
    assert ivy.result_type(*pair) == TABLE[pair]


def test_result_type_follows_the_table_on_every_backend(backend):
    xp = getattr(ivy, backend)
    pairs = sorted(TABLE)
    if backend == "jax":  # jax without x64 has no 64-bit types; the tests enable them
        import jax

        assert jax.config.jax_enable_x64
    for a, b in pairs:
        want = TABLE[(a, b)]
        for fn in api(backend, "result_type")[1:]:
            assert _name(fn(_as(backend, a), _as(backend, b))) == want, (a, b)
            assert _name(fn(a, _as(backend, b))) == want, (a, b)
        assert _name(ivy.result_type(_as(backend, a), b)) == want, (a, b)
        assert _name(ivy.result_type(a, b, f=xp)) == want, (a, b)


@pytest.mark.parametrize(
    "a, b",
    [("int8", "int16"), ("uint8", "int8"), ("float32", "float64"), ("int32", "float32")],
)
def test_result_type_is_the_dtype_the_backend_computes(backend, a, b):
    """For arrays: the dtype that ``ivy.add`` of such arrays has (mixed kinds included, whose
    promotion the standard leaves to each backend)."""
    x, y = native(np.ones(2, a), backend), native(np.ones(2, b), backend)
    for fn in api(backend, "result_type"):
        assert _name(fn(x, y)) == dtype_name(ivy.add(x, y))
        assert _name(fn(x, y, x)) == dtype_name(ivy.add(x, y))


def test_result_type_with_python_scalars(backend):
    """Scalars of the array's kind or lower keep the array's dtype."""
    x = native(np.ones(2, "float32"), backend)
    i = native(np.ones(2, "int16"), backend)
    for fn in api(backend, "result_type"):
        assert _name(fn(x, 1.0)) == "float32"
        assert _name(fn(x, 1)) == "float32"
        assert _name(fn(i, 1)) == "int16"
        assert _name(fn(i, True)) == "int16"
        assert _name(fn(x, 1j)) == "complex64"
    assert ivy.result_type("float64", 1j) == "complex128"
    assert ivy.result_type("int8", 1.0) == "float32"
    assert ivy.result_type("bool", 1) == "int64"


def test_result_type_needs_an_array_or_dtype():
    with pytest.raises(TypeError):
        ivy.result_type(1.0, 2)


def _can_cast_expected(a, b):
    """By the table: a casts to b if promoting them gives b (pairs of one kind)."""
    return TABLE[(a, b)] == b


def test_can_cast_within_kinds_without_a_framework():
    for a, b in TABLE:
        assert ivy.can_cast(a, b) is _can_cast_expected(a, b), (a, b)


def test_can_cast_within_kinds_on_every_backend(backend):
    for a, b in TABLE:
        want = _can_cast_expected(a, b)
        for fn in api(backend, "can_cast")[1:]:
            assert bool(fn(_as(backend, a), _as(backend, b))) is want, (a, b)
            assert bool(fn(a, b)) is want, (a, b)
        assert bool(ivy.can_cast(_as(backend, a), b)) is want, (a, b)


def test_can_cast_from_an_array(backend):
    x = native(np.ones(2, "float32"), backend)
    for fn in api(backend, "can_cast"):
        assert fn(x, "float64")
        assert not fn(x, "float16")
        assert not fn(x, "int64")


def test_can_cast_never_crosses_kinds(backend):
    """The Array API's table has no bool-to-integer nor integer-to-floating promotion (numpy's
    own can_cast allows both)."""
    for a, b in [("bool", "int8"), ("int64", "float64"), ("uint8", "float32"), ("bool", "float32")]:
        for fn in api(backend, "can_cast")[1:]:
            assert not fn(a, b), (a, b)
        assert not ivy.can_cast(a, b)
        assert not ivy.can_cast(_as(backend, a), b)
    assert ivy.can_cast("float32", "complex64") and ivy.can_cast("float32", "complex128")


def test_can_cast_never_narrows_nor_drops_the_imaginary_part(backend):
    for fn in api(backend, "can_cast")[1:]:
        for a, b in [("float64", "float32"), ("complex64", "float32"), ("float32", "int32")]:
            assert not fn(a, b)
            assert not ivy.can_cast(a, b)


def _finfo_reference(name):
    real = {"complex64": "float32", "complex128": "float64"}.get(name, name)
    info = np.finfo(real)
    bits = {"float16": 16, "float32": 32, "float64": 64}[real]
    mant = {"float16": 10, "float32": 23, "float64": 52}[real]
    emax = {"float16": 15, "float32": 127, "float64": 1023}[real]
    # exact values from the IEEE 754 formats (numpy only for the cross-check below)
    expected = dict(
        bits=bits,
        eps=2.0**-mant,
        max=(2 - 2.0**-mant) * 2.0**emax,
        min=-(2 - 2.0**-mant) * 2.0**emax,
        smallest_normal=2.0 ** (1 - emax),
    )
    assert expected["max"] == float(info.max)
    return real, expected


def _check_finfo(info, name, native_dtype):
    real, expected = _finfo_reference(name)
    for field, value in expected.items():
        got = getattr(info, field)
        assert type(got) is (int if field == "bits" else float), field
        assert got == value, (field, got, value)
    assert info.dtype == native_dtype, (info.dtype, native_dtype)


@pytest.mark.parametrize("name", FLOATS + COMPLEX)
def test_finfo_without_a_framework(name):
    info = ivy.finfo(name)
    assert isinstance(info, FInfo)
    real = {"complex64": "float32", "complex128": "float64"}.get(name, name)
    _check_finfo(info, name, real)
    _check_finfo(ivy.finfo(np.dtype(name)), name, _as("numpy", real))  # numpy dtype: numpy


@pytest.mark.parametrize("name", FLOATS + COMPLEX)
def test_finfo_on_every_backend(backend, name):
    if name == "float16":
        require(backend, "float16")
    xp = getattr(ivy, backend)
    real = {"complex64": "float32", "complex128": "float64"}.get(name, name)
    want = _as(backend, real)
    x = native(np.ones(2, name), backend)
    for fn in api(backend, "finfo"):
        _check_finfo(fn(x), name, want)  # an array
    for fn in api(backend, "finfo")[1:]:
        _check_finfo(fn(_as(backend, name)), name, want)
        _check_finfo(fn(name), name, want)
    _check_finfo(ivy.finfo(_as(backend, name)), name, want)  # the native dtype picks the backend
    _check_finfo(ivy.finfo(name, f=xp), name, want)


@pytest.mark.parametrize("name", INTS)
def test_iinfo(backend, name):
    bits = int(name.removeprefix("u").removeprefix("int"))
    signed = not name.startswith("u")
    lo, hi = (-(2 ** (bits - 1)), 2 ** (bits - 1) - 1) if signed else (0, 2**bits - 1)
    infos = [ivy.iinfo(name), ivy.iinfo(name, f=backend), ivy.iinfo(_as(backend, name))]
    infos.append(getattr(ivy, backend).iinfo(name))
    if backend != "torch" or name in ("uint8", "int8", "int16", "int32", "int64"):
        infos.append(ivy.iinfo(native(np.ones(2, name), backend)))
    for k, info in enumerate(infos):
        assert isinstance(info, IInfo)
        assert (info.bits, info.min, info.max) == (bits, lo, hi)
        assert all(type(v) is int for v in (info.bits, info.min, info.max))
        assert info.dtype == (name if k == 0 else _as(backend, name))


def test_finfo_and_iinfo_refuse_the_other_kind(backend):
    with pytest.raises(TypeError):
        ivy.finfo("int32")
    with pytest.raises(TypeError):
        ivy.iinfo("float32")
    xp = getattr(ivy, backend)
    with pytest.raises(TypeError):
        xp.finfo(xp.int32)
    with pytest.raises(TypeError):
        xp.iinfo(xp.float32)


KIND_MEMBERS = {
    "bool": {"bool"},
    "signed integer": {"int8", "int16", "int32", "int64"},
    "unsigned integer": {"uint8", "uint16", "uint32", "uint64"},
    "integral": set(INTS),
    "real floating": set(FLOATS),
    "complex floating": set(COMPLEX),
    "numeric": set(INTS) | set(FLOATS) | set(COMPLEX),
}


def test_isdtype_kinds(backend):
    for dtype, kind in itertools.product(ALL, KIND_MEMBERS):
        want = dtype in KIND_MEMBERS[kind]
        assert ivy.isdtype(dtype, kind) is want, (dtype, kind)
        assert ivy.isdtype(_as(backend, dtype), kind) is want, (dtype, kind)
        assert getattr(ivy, backend).isdtype(dtype, kind) is want, (dtype, kind)


def test_isdtype_tuples_and_dtypes(backend):
    xp = getattr(ivy, backend)
    for fn in (ivy.isdtype, xp.isdtype):
        assert fn(xp.float32, ("integral", "real floating"))
        assert not fn(xp.bool, ("integral", "real floating"))
        assert fn(xp.int16, xp.int16)
        assert not fn(xp.int16, xp.int32)
        assert fn(xp.uint8, (xp.int8, "unsigned integer"))
        assert fn("float64", "float64")
    with pytest.raises(ValueError):
        ivy.isdtype("float32", "floating point")


def test_dtype_names_need_no_framework():
    code = (
        "import ivy, sys\n"
        "assert ivy.finfo('float32').eps == 2.0**-23\n"
        "assert ivy.iinfo('uint8').max == 255\n"
        "assert ivy.result_type('int8', 'uint8') == 'int16'\n"
        "assert ivy.can_cast('int8', 'int64') and ivy.isdtype('bool', 'bool')\n"
        "print(','.join(m for m in ('torch', 'jax', 'tensorflow') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_global_framework_answers_with_its_dtypes(backend):
    with ivy.set_framework(backend):
        assert ivy.finfo("float32").dtype == _as(backend, "float32")
        assert _name(ivy.result_type("int8", "uint8")) == "int16"


@pytest.mark.parametrize("dtype", ["float64", "int32", "bool"])
def test_astype_with_device(backend, dtype):
    a = np.array([0.5, 1.0, 2.0], np.float32)
    for fn in api(backend, "astype"):
        check(fn(native(a, backend), dtype, device="cpu"), a.astype(dtype), backend)


# ----------------------------------------------------------------------------------------------
# dtype_name and enable_float64: what applied code uses instead of a framework's name
# ----------------------------------------------------------------------------------------------

_NAMED = ("bool", "int8", "int32", "int64", "uint8", "float16", "float32", "float64", "complex64")


def test_dtype_name_of_dtype_objects_arrays_and_names(backend, xp):
    for name in _NAMED:
        if not hasattr(xp, name):  # a dtype the library lacks (float16 on array_api_strict)
            continue
        assert ivy.dtype_name(getattr(xp, name)) == name
        assert xp.dtype_name(getattr(xp, name)) == name
        array = native(np.zeros(2, dtype=name), backend)
        assert ivy.dtype_name(array) == xp.dtype_name(array) == name
        assert xp.dtype_name(name) == name
    assert xp.dtype_name(np.float64) == "float64"  # numpy's scalar types
    assert ivy.dtype_name(np.dtype("int16")) == "int16"
    with pytest.raises(TypeError, match="float128"):
        xp.dtype_name("float128")
    with pytest.raises(TypeError, match="float128"):
        ivy.dtype_name("float128")


def test_enable_float64_makes_float64_work(backend, xp):
    assert xp.capabilities.float64
    ivy.enable_float64(f=backend)
    xp.enable_float64()
    x = xp.asarray([0.1], dtype="float64")
    assert ivy.dtype_name(x) == "float64"
    np.testing.assert_array_equal(numpy_of(x * 3.0), np.array([0.1]) * 3.0)
    with pytest.raises(ivy.NoFrameworkError, match="set_framework"):
        ivy.enable_float64()
