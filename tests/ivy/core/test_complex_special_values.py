"""Special values of complex elementwise functions, on every backend.

Inputs: every pair of real and imaginary parts from a table of signed zeros, finite numbers,
infinities and NaN. The reference is Python's ``cmath``, which implements C99 Annex G (the
standard's source) for ``exp``, ``log``, ``sqrt``, the hyperbolic functions and their inverses;
where ``cmath`` raises instead of answering (C99's invalid and divide-by-zero cases) and where the
standard departs from C99, the standard's value is written here. ``expm1``, ``log1p`` and ``sign``
have references written from the standard's rules. NaN compares as NaN; zeros and infinities
compare with their sign, except where the standard leaves the sign unspecified.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

import ivy
from tests.helpers import TOLERANCES, api, native, native_value_and_grads, numpy_of

INF, NAN, PI = math.inf, math.nan, math.pi
PARTS = [0.0, -0.0, 0.5, -1.0, 2.5, -2.5, INF, -INF, NAN]
PAIRS = [(a, b) for a in PARTS for b in PARTS]
CMATH = "exp cosh sinh tanh log sqrt acos acosh asinh atanh".split()
FUNCTIONS = CMATH + ["expm1", "log1p", "sign"]
COMPLEX = ["complex64", "complex128"]


def _neg(v: float) -> bool:
    return math.copysign(1.0, v) < 0


def _when_cmath_raises(name: str, a: float, b: float) -> complex:
    """C99's value where ``cmath`` raises ValueError (an invalid or divide-by-zero case)."""
    finite_a = math.isfinite(a)
    if name == "exp":  # finite + inf j; +inf + inf j
        return complex(NAN, NAN) if finite_a else complex(INF, NAN)
    if name == "cosh":  # finite + inf j; inf + inf j
        if a == 0:
            return complex(NAN, 0.0)
        return complex(NAN, NAN) if finite_a else complex(INF, NAN)
    if name == "sinh":
        if a == 0:
            return complex(0.0, NAN)
        return complex(NAN, NAN) if finite_a else complex(INF, NAN)
    if name == "tanh":  # the standard: +-0 + NaN j at a = +-0 (C99 before TC3 said NaN + NaN j)
        return complex(a, NAN) if a == 0 else complex(NAN, NAN)
    if name == "log":  # log(+-0 +- 0j) = -inf + (0 or pi) j
        return complex(-INF, math.copysign(PI if _neg(a) else 0.0, b))
    if name == "atanh":  # atanh(+-1 +- 0j) = +-inf +- 0j
        return complex(math.copysign(INF, a), b)
    raise AssertionError(f"no C99 value written for {name}({a} + {b}j)")


def _cmath_standard(name: str, a: float, b: float) -> complex:
    if name == "tanh" and a == 0 and math.isnan(b):
        return complex(a, NAN)  # the standard's +0 + NaN j (cmath follows the older C)
    if name == "tanh" and math.isinf(a) and math.isfinite(b):
        # the standard: 1 + 0j for positive b (C99 and cmath: the sign of sin(2b))
        return complex(math.copysign(1.0, a), math.copysign(0.0, b))
    if name == "acosh" and a == 0 and math.isnan(b):
        return complex(NAN, PI / 2)  # the standard's NaN +- pi/2 j (cmath: NaN + NaN j)
    try:
        return getattr(cmath, name)(complex(a, b))
    except ValueError:
        return _when_cmath_raises(name, a, b)


def _expm1(a: float, b: float) -> complex:
    """The standard's expm1: exp's special values minus one in the real part (``+0 cis(b) - 1``,
    ``-1 + 0j`` at ``-inf + inf j``, ``+0 + 0j`` at zero); exp(z) - 1 elsewhere."""
    e = _cmath_standard("exp", a, b)
    if math.isfinite(a) and math.isfinite(b) and (a, b) != (0.0, 0.0):
        return cmath.exp(complex(a, b)) - 1  # finite nonzero: the value, not its last bits
    return complex(e.real - 1.0, e.imag)


def _log1p(a: float, b: float) -> complex:
    """The standard's log1p: log's special values at 1 + z (its table is log's, shifted)."""
    return _cmath_standard("log", a + 1.0, b)


def _sign(a: float, b: float) -> complex:
    """The standard's sign: 0 at zero, NaN + NaN j with a NaN part, z / |z| where finite; with an
    infinite part, the standard's rules of complex division: infinite / infinite is NaN + NaN j
    (C99 Annex G recovers infinite / finite and finite / infinite only)."""
    if not (math.isfinite(a) and math.isfinite(b)):
        return complex(NAN, NAN)
    if a == 0 and b == 0:
        return complex(0.0, 0.0)
    r = abs(complex(a, b))
    return complex(a / r, b / r)  # part by part: -0.0 / r keeps its sign


def expected(name: str, a: float, b: float) -> complex:
    if name == "expm1":
        return _expm1(a, b)
    if name == "log1p":
        return _log1p(a, b)
    if name == "sign":
        return _sign(a, b)
    return _cmath_standard(name, a, b)


def unspecified_signs(name: str, a: float, b: float) -> tuple[bool, bool]:
    """(real, imaginary): whether the standard leaves the sign of that part unspecified."""
    inf_a, inf_b, nan_a, nan_b = math.isinf(a), math.isinf(b), math.isnan(a), math.isnan(b)
    bad_b = inf_b or nan_b
    if name == "exp":
        return (inf_a and bad_b, inf_a and a < 0 and bad_b)
    if name == "expm1":
        return (inf_a and a > 0 and bad_b, inf_a and a < 0 and bad_b)
    if name == "cosh":
        return (inf_a and inf_b, (a == 0 and bad_b) or (nan_a and b == 0))
    if name == "sinh":
        return ((a == 0 or inf_a) and bad_b, False)
    if name == "tanh":
        return (False, inf_a and bad_b)
    if name == "acos":
        return (False, inf_a and nan_b)
    if name == "acosh":
        return (False, a == 0 and nan_b)  # NaN +- pi/2 j
    if name in ("asinh", "atanh"):
        return (nan_a and inf_b, False)
    if name == "sqrt":
        return (False, inf_a and a < 0 and nan_b)
    return (False, False)


def complex_array(pairs, dtype: str) -> np.ndarray:
    """Complex numbers of parts ``pairs`` (``a + 1j * b`` would turn ``0 * inf`` into NaN)."""
    out = np.empty(len(pairs), dtype)
    out.real = [a for a, _ in pairs]
    out.imag = [b for _, b in pairs]
    return out


def _zero_sign_variants(a: float, b: float) -> list[tuple[float, float]]:
    """``(a, b)`` and the same with the sign of a zero part changed."""
    return [(x, y) for x in ([a, -a] if a == 0 else [a]) for y in ([b, -b] if b == 0 else [b])]


def _wrong_parts(name, value, a, b, want, tol) -> list[str]:
    free = unspecified_signs(name, a, b)
    # the standard fixes signs for its special inputs (a part infinite or NaN, z = 0); finite
    # nonzero inputs are the framework's own computation, whose zeros' signs are not compared
    finite_nonzero = math.isfinite(a) and math.isfinite(b) and (a != 0 or b != 0)
    bad = []
    for part, g, w, sign_free in (
        ("real", value.real, want.real, free[0]),
        ("imag", value.imag, want.imag, free[1]),
    ):
        if math.isnan(w):
            ok = math.isnan(g)
        elif w == 0 or math.isinf(w):
            ok = abs(g) == abs(w) and (sign_free or finite_nonzero or _neg(g) == _neg(w))
        elif sign_free:
            ok = math.isclose(abs(g), abs(w), rel_tol=tol["rtol"], abs_tol=tol["atol"])
        else:
            ok = math.isclose(g, w, rel_tol=tol["rtol"], abs_tol=tol["atol"])
        if not ok:
            bad.append(f"{name}({a!r} + {b!r}j).{part} = {g!r}, expected {w!r}")
    return bad


def mismatches(name: str, got: np.ndarray, pairs, dtype: str) -> list[str]:
    """The inputs where ``got`` is not the standard's value, described.

    A finite nonzero input with a zero part (``sqrt(-1 - 0j)``, on a branch cut) is the
    framework's own computation, which may read that zero's sign or not (jax does not): either
    answer is accepted there."""
    tol = TOLERANCES[dtype]
    bad = []
    for (a, b), value in zip(pairs, got.tolist()):
        finite_nonzero = math.isfinite(a) and math.isfinite(b) and (a != 0 or b != 0)
        variants = _zero_sign_variants(a, b) if finite_nonzero else [(a, b)]
        failures = [_wrong_parts(name, value, a, b, expected(name, x, y), tol) for x, y in variants]
        if all(failures):
            bad.extend(failures[0])
    return bad


def _native_numpy(x) -> np.ndarray:
    return np.asarray(numpy_of(x)).reshape(-1)


# What a backend still answers otherwise than the standard (strict: a fix shows as XPASS).
KNOWN_GAPS = {
    ("array_api_strict", "expm1"): "array_api_strict computes with numpy's expm1 (expm1(0j)...)",
    ("array_api_strict", "tanh"): "array_api_strict computes with numpy's tanh: tanh(inf + 2.5j) "
    "is 1 - 0j",
    ("array_api_strict", "sign"): "array_api_strict's own sign gives sign(0 - 0j) = 0 - 0j",
}


@pytest.mark.parametrize("dtype", COMPLEX)
@pytest.mark.parametrize("name", FUNCTIONS)
def test_special_values(backend, name, dtype, request):
    gap = KNOWN_GAPS.get((backend, name))
    if gap is not None:
        request.applymarker(pytest.mark.xfail(strict=True, reason=gap))
    z = native(complex_array(PAIRS, dtype), backend)
    for fn in api(backend, name):  # ivy.<name> and ivy.<backend>.<name>
        with np.errstate(all="ignore"):
            got = _native_numpy(fn(z))
        assert got.dtype == np.dtype(dtype)
        assert mismatches(name, got, PAIRS, dtype) == []


def test_reference_raises_where_c99_is_written():
    """The fallbacks above are used: cmath does raise on these inputs (so the table matters)."""
    for name, a, b in (("exp", 1.0, INF), ("cosh", 0.0, INF), ("log", -0.0, 0.0)):
        with pytest.raises(ValueError):
            getattr(cmath, name)(complex(a, b))
    assert cmath.isnan(expected("exp", 1.0, INF).real)
    assert expected("log", -0.0, 0.0) == complex(-INF, PI)


_NATIVE_MODULES = {
    "numpy": lambda: np,
    "torch": lambda: __import__("torch"),
    "jax": lambda: __import__("jax.numpy").numpy,
    "tensorflow": lambda: __import__("tensorflow").math,
    "array_api_strict": lambda: __import__("array_api_strict"),
}


_NATIVE_NAMES = {("torch", "sign"): "sgn"}  # torch.sign refuses complex numbers


def _native_function(backend: str, name: str):
    return getattr(_NATIVE_MODULES[backend](), _NATIVE_NAMES.get((backend, name), name))


# finite inputs where the standard lists a value (a pole), not the framework's computation
_POLES = {"log1p": {(-1.0, 0.0)}, "atanh": {(1.0, 0.0), (-1.0, 0.0)}}


@pytest.mark.parametrize("name", FUNCTIONS)
def test_finite_nonzero_inputs_keep_the_native_values(backend, name):
    """Where both parts are finite and z is not zero, the result is the framework's own, bit
    for bit."""
    poles = _POLES.get(name, set())
    pairs = [
        (a, b)
        for a, b in PAIRS
        if math.isfinite(a) and math.isfinite(b) and (a or b) and (a, b) not in poles
    ]
    z = native(complex_array(pairs, "complex128"), backend)
    own = _native_function(backend, name)
    np.testing.assert_array_equal(
        _native_numpy(getattr(getattr(ivy, backend), name)(z)),
        _native_numpy(own(z)),
    )


_ZEROS_AND_SPECIALS = [(a, b) for a, b in PAIRS if not (math.isfinite(a) and math.isfinite(b))]
_ZEROS_AND_SPECIALS += [(0.0, 0.0), (-0.0, 0.0), (0.0, -0.0), (-0.0, -0.0)]


def test_compiled_gives_the_special_values(graph_backend):
    """Under jax.jit and tf.function (ivy.compile_fn) the values are the eager ones."""
    xp = getattr(ivy, graph_backend)
    z = native(complex_array(_ZEROS_AND_SPECIALS, "complex128"), graph_backend)
    for name in FUNCTIONS:
        compiled = ivy.compile_fn(getattr(xp, name))
        got = _native_numpy(compiled(z))
        assert mismatches(name, got, _ZEROS_AND_SPECIALS, "complex128") == []


_GRAD_POINTS = [np.array([0.3, -1.2, 2.0, 0.7]), np.array([0.4, 0.9, -1.5, -0.2])]


@pytest.mark.parametrize("name", FUNCTIONS)
def test_gradients_of_finite_inputs_are_the_natives(diff_backend, name):
    """Through the real and imaginary parts of finite inputs, the gradients are the framework's
    own function's (the special values' ``where`` adds nothing there; jax's gradients are
    jitted, where XLA may fuse the two programs differently in the last bit)."""
    xp = getattr(ivy, diff_backend)

    def parts_of(fn):
        def parts(re, im):
            out = fn(xp.astype(re, xp.complex128) + xp.astype(im, xp.complex128) * 1j)
            return xp.concat([xp.real(out), xp.imag(out)])

        return parts

    weights = np.random.default_rng(3).standard_normal(8)
    ours = native_value_and_grads(diff_backend, parts_of(getattr(xp, name)), _GRAD_POINTS, weights)
    own = native_value_and_grads(
        diff_backend, parts_of(_native_function(diff_backend, name)), _GRAD_POINTS, weights
    )
    np.testing.assert_allclose(ours[0], own[0], rtol=1e-14, atol=0)
    for got, want in zip(ours[1], own[1]):
        np.testing.assert_allclose(got, want, rtol=1e-14, atol=1e-15)


def test_sign_of_a_real_zero_is_positive_zero(backend):
    """The standard's sign(+-0) is 0, read as +0 by the suite; jax's own gives -0.0 for -0.0."""
    for fn in api(backend, "sign"):
        got = _native_numpy(fn(native(np.array([-0.0, 0.0, -2.0], np.float32), backend)))
        np.testing.assert_array_equal(got, [0.0, 0.0, -1.0])
        assert not np.signbit(got[:2]).any()


@pytest.mark.parametrize("dtype", COMPLEX)
def test_abs_is_infinite_wherever_a_part_is(backend, dtype):
    """The standard's abs of a complex number (C99's hypot, as Python's ``abs``): +inf wherever
    a part is infinite, the other part NaN included (jax's was NaN there); NaN where a part is
    NaN and none infinite."""
    z = native(complex_array(PAIRS, dtype), backend)
    want = np.array([abs(complex(a, b)) for a, b in PAIRS])
    real = {"complex64": "float32", "complex128": "float64"}[dtype]
    for fn in api(backend, "abs"):
        got = _native_numpy(fn(z))
        assert got.dtype == np.dtype(real)
        np.testing.assert_allclose(got, want.astype(real), rtol=1e-6, equal_nan=True)
