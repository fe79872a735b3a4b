"""Special values of complex elementwise functions, written once for every backend.

The Array API standard (after C99 Annex G) lists what ``exp``, ``log``, ``sqrt``, ``acos``... give
for complex input with an infinite or NaN part, and for signed zeros. Frameworks compute complex
functions with formulas that are right for finite numbers but give NaN, or the wrong sign of a
zero, on many of those inputs (jax's ``exp(-inf + inf j)`` is NaN, not ``0 + 0j``).

:func:`fixer` gives, for one function and one backend, ``fix(z, out)``: the native result ``out``
of a complex ``z`` with the special inputs' elements replaced by the standard's values: a part
infinite or NaN, ``z = +-0 +-0j`` (only where the native's value or a zero's sign differs), and
the poles the standard lists (``log1p(-1 + 0j)``, ``atanh(+-1 + 0j)``). Other finite inputs keep
the native's values, and its gradients: the replacement is a ``where`` whose other branch only
ever sees finite, harmless operands. Everything is elementwise array
code (no Python branching on values), so it traces under ``jax.jit`` and ``tf.function``.

The backend calls the fixer only for complex results: numpy and jax through the check their
``reals`` wrappers already make on the result's dtype (``ivy/backends/_reals.py``), torch and
tensorflow through :func:`wrap`, which it applies only to the functions its framework gets wrong.

``xp`` is a namespace of the backend's native functions under the Array API's names: ``where``,
``isnan``, ``isinf``, ``isfinite``, ``real``, ``imag``, ``abs``, ``copysign``, ``cos``, ``sin``,
``full_like``, and ``complex(re, im)``, which builds a complex array from two real ones
(``re + 1j * im`` would turn ``0 * inf`` into NaN).
"""

from __future__ import annotations

import math
import types
from collections.abc import Callable
from typing import Any

__all__ = ["FUNCTIONS", "NEEDS", "fixer", "namespace", "wrap"]

_PI = math.pi
_INF = math.inf
_NAN = math.nan
NEEDS = "where isnan isinf isfinite real imag abs copysign cos sin full_like complex".split()


def namespace(module: Any = None, /, **functions: Callable) -> types.SimpleNamespace:
    """The namespace the rules use: ``module``'s functions of the names in :data:`NEEDS`, with
    ``functions`` in their place (tf's ``isnan`` is ``tf.math.is_nan``...).

    Example:
        >>> xp = namespace(jax.numpy, complex=jax.lax.complex)  # doctest: +SKIP
    """
    found = {name: getattr(module, name) for name in NEEDS if hasattr(module, name)}
    found.update(functions)
    missing = [name for name in NEEDS if name not in found]
    if missing:
        raise TypeError(f"complex special values need {missing} from the backend")
    return types.SimpleNamespace(**found)


class _Parts:
    """The real part ``a`` and imaginary part ``b`` of ``z`` (or their magnitudes) and the
    masks the rules test."""

    def __init__(self, xp: Any, a: Any, b: Any) -> None:
        self.xp, self.a, self.b = xp, a, b
        self.nan_a, self.nan_b = xp.isnan(a), xp.isnan(b)
        self.inf_a, self.inf_b = xp.isinf(a), xp.isinf(b)
        self.fin_a, self.fin_b = xp.isfinite(a), xp.isfinite(b)
        self.pinf_a = self.inf_a & (a > 0)
        self.ninf_a = self.inf_a & (a < 0)
        self.zero_a, self.zero_b = a == 0, b == 0
        self.bad_b = ~self.fin_b  # infinite or NaN

    def const(self, value: float) -> Any:
        return self.xp.full_like(self.a, value)

    def pick(self, default: float, cases: list[tuple[Any, Any]]) -> Any:
        """The value of the first case whose mask holds, else ``default``, elementwise."""
        out = self.const(default)
        for mask, value in reversed(cases):
            out = self.xp.where(mask, self.const(value) if isinstance(value, float) else value, out)
        return out

    def cis_signs(self, magnitude: float) -> tuple[Any, Any]:
        """``magnitude * cis(b)`` for an infinite or zero ``magnitude``: the signs of
        ``cos(b)`` and ``sin(b)`` on it (``b`` made finite where it is not, for safe gradients)."""
        xp = self.xp
        safe_b = xp.where(self.fin_b, self.b, self.const(0.0))
        m = self.const(magnitude)
        return xp.copysign(m, xp.cos(safe_b)), xp.copysign(m, xp.sin(safe_b))


# Each rule takes the parts of z in the upper half plane (b >= 0; for the odd functions also
# a >= 0) and returns (re, im) for the elements with an infinite or NaN part. The other half
# planes follow from the symmetry the standard states (the second entry of ``_RULES``).


def _exp_like(p: _Parts, shift: float) -> tuple[Any, Any]:
    """exp(z) - shift: exp (shift 0) and expm1 (shift 1)."""
    big_re, big_im = p.cis_signs(_INF)
    small_re, small_im = p.cis_signs(0.0)
    fin_b0 = p.fin_b & p.zero_b
    re = p.pick(
        _NAN,
        [
            (p.pinf_a & p.fin_b, big_re),
            (p.pinf_a, _INF),
            (p.ninf_a & p.fin_b, small_re - shift),
            (p.ninf_a, 0.0 - shift),  # +0 for exp
        ],
    )
    im = p.pick(
        _NAN,
        [
            (p.pinf_a & fin_b0, 0.0),
            (p.pinf_a & p.fin_b, big_im),
            (p.ninf_a & p.fin_b, small_im),
            (p.ninf_a, 0.0),
            (p.nan_a & p.zero_b, 0.0),
        ],
    )
    return re, im


def _exp(p: _Parts) -> tuple[Any, Any]:
    return _exp_like(p, 0.0)


def _expm1(p: _Parts) -> tuple[Any, Any]:
    return _exp_like(p, 1.0)


def _cosh(p: _Parts) -> tuple[Any, Any]:  # a >= 0, b >= 0
    big_re, big_im = p.cis_signs(_INF)
    re = p.pick(_NAN, [(p.inf_a & p.zero_b, _INF), (p.inf_a & p.fin_b, big_re), (p.inf_a, _INF)])
    im = p.pick(
        _NAN,
        [
            (p.zero_a & p.bad_b, 0.0),
            (p.inf_a & p.zero_b, 0.0),
            (p.inf_a & p.fin_b, big_im),
            (p.nan_a & p.zero_b, 0.0),
        ],
    )
    return re, im


def _sinh(p: _Parts) -> tuple[Any, Any]:  # a >= 0, b >= 0
    big_re, big_im = p.cis_signs(_INF)
    re = p.pick(
        _NAN,
        [
            (p.zero_a & p.bad_b, 0.0),
            (p.inf_a & p.zero_b, _INF),
            (p.inf_a & p.fin_b, big_re),
            (p.inf_a, _INF),
        ],
    )
    im = p.pick(
        _NAN,
        [(p.inf_a & p.zero_b, 0.0), (p.inf_a & p.fin_b, big_im), (p.nan_a & p.zero_b, 0.0)],
    )
    return re, im


def _tanh(p: _Parts) -> tuple[Any, Any]:  # a >= 0, b >= 0
    re = p.pick(_NAN, [(p.zero_a & p.bad_b, 0.0), (p.inf_a, 1.0)])
    im = p.pick(_NAN, [(p.inf_a, 0.0), (p.nan_a & p.zero_b, 0.0)])
    return re, im


def _angles(p: _Parts, at_zero_nan: bool = False) -> Any:
    """The angle that log's imaginary part, acos' real part and acosh's imaginary part share on
    inputs with an infinite or NaN part (with ``at_zero_nan``: pi/2 at +-0 + NaN j too)."""
    inf_b = p.inf_b
    return p.pick(
        _NAN,
        [(p.zero_a & p.nan_b, _PI / 2 if at_zero_nan else _NAN)]
        + [
            (p.fin_a & inf_b, _PI / 2),
            (p.ninf_a & p.fin_b, _PI),
            (p.pinf_a & p.fin_b, 0.0),
            (p.ninf_a & inf_b, 3 * _PI / 4),
            (p.pinf_a & inf_b, _PI / 4),
        ],
    )


def _log_like(p: _Parts) -> tuple[Any, Any]:
    """log and log1p agree on every input with an infinite or NaN part."""
    return p.pick(_NAN, [(p.inf_b, _INF), (p.inf_a, _INF)]), _angles(p)


def _sqrt(p: _Parts) -> tuple[Any, Any]:
    inf_b = p.inf_b
    re = p.pick(_NAN, [(inf_b, _INF), (p.ninf_a & p.fin_b, 0.0), (p.pinf_a, _INF)])
    im = p.pick(_NAN, [(inf_b, _INF), (p.ninf_a, _INF), (p.pinf_a & p.fin_b, 0.0)])
    return re, im


def _acos(p: _Parts) -> tuple[Any, Any]:
    im = p.pick(_NAN, [(p.inf_b, -_INF), (p.inf_a & p.fin_b, -_INF), (p.inf_a, _INF)])
    return _angles(p, at_zero_nan=True), im


def _acosh(p: _Parts) -> tuple[Any, Any]:
    return p.pick(_NAN, [(p.inf_b, _INF), (p.inf_a, _INF)]), _angles(p, at_zero_nan=True)


def _asinh(p: _Parts) -> tuple[Any, Any]:  # a >= 0, b >= 0
    inf_b = p.inf_b
    re = p.pick(_NAN, [(p.fin_a & inf_b, _INF), (p.inf_a, _INF), (p.nan_a & inf_b, _INF)])
    im = p.pick(
        _NAN,
        [
            (p.fin_a & inf_b, _PI / 2),
            (p.inf_a & p.fin_b, 0.0),
            (p.inf_a & inf_b, _PI / 4),
            (p.nan_a & p.zero_b, 0.0),
        ],
    )
    return re, im


def _atanh(p: _Parts) -> tuple[Any, Any]:  # a >= 0, b >= 0
    inf_b = p.inf_b
    re = p.pick(
        _NAN,
        [(p.zero_a & p.nan_b, 0.0), (p.fin_a & inf_b, 0.0), (p.inf_a, 0.0), (p.nan_a & inf_b, 0.0)],
    )
    im = p.pick(_NAN, [(inf_b, _PI / 2), (p.inf_a & p.fin_b, _PI / 2)])
    return re, im


def _sign(p: _Parts) -> tuple[Any, Any]:
    # inputs with a NaN or an infinite part: z / |z| is NaN + NaN j by the standard's rules of
    # complex division (infinite / infinite has no recovery case in C99 Annex G)
    return p.const(_NAN), p.const(_NAN)


# The value at z = +-0 +-0j, from (xp, a, b) there, built from constants and the parts
# themselves: compilers fold ``a + 0.0`` into ``a`` (XLA, grappler), which would keep a -0.


def _exp_zero(xp, a, b):  # 1 +- 0j
    return xp.full_like(a, 1.0), b


def _plus_zero_real(xp, a, b):  # +0 +- 0j: expm1, log1p, sqrt
    return xp.full_like(a, 0.0), b


def _cosh_zero(xp, a, b):  # 1 + (sign(a) sign(b)) 0j
    zero = xp.full_like(a, 0.0)
    return xp.full_like(a, 1.0), xp.where(_negative(xp, a) ^ _negative(xp, b), -zero, zero)


def _log_zero(xp, a, b):  # -inf + (0 or pi) j, with b's sign
    im = xp.where(_negative(xp, a), xp.full_like(a, _PI), xp.full_like(a, 0.0))
    return xp.full_like(a, -_INF), xp.where(_negative(xp, b), -im, im)


def _acos_zero(xp, a, b):  # pi/2 -+ 0j
    return xp.full_like(a, _PI / 2), -b


def _acosh_zero(xp, a, b):  # +0 +- pi/2 j, with b's sign
    half_pi = xp.full_like(a, _PI / 2)
    return xp.full_like(a, 0.0), xp.where(_negative(xp, b), -half_pi, half_pi)


def _sign_zero(xp, a, b):  # 0 + 0j
    return xp.full_like(a, 0.0), xp.full_like(b, 0.0)


def _odd_zero(xp, a, b):  # z itself
    return a, b


def _log1p_pole(xp, a, b):  # log1p(-1 +- 0j) = -inf +- 0j
    return (a == -1) & (b == 0), xp.full_like(a, -_INF), b


def _atanh_poles(xp, a, b):  # atanh(+-1 +- 0j) = +-inf +- 0j
    return ((a == 1) | (a == -1)) & (b == 0), xp.copysign(xp.full_like(a, _INF), a), b


# name: (rule for inputs with an infinite or NaN part, symmetry, value at z = +-0 +-0j).
# At zero the native's result is replaced only where it differs (its value or a zero's sign),
# so that where it is right its gradient there stays. Symmetry: "conj" f(conj z) = conj f(z);
# "odd" also f(-z) = -f(z); "even" also f(-z) = f(z); "sign" none.
_RULES: dict[str, tuple[Callable, str, Callable]] = {
    "exp": (_exp, "conj", _exp_zero),
    "expm1": (_expm1, "conj", _plus_zero_real),
    "cosh": (_cosh, "even", _cosh_zero),
    "sinh": (_sinh, "odd", _odd_zero),
    "tanh": (_tanh, "odd", _odd_zero),
    "log": (_log_like, "conj", _log_zero),
    "log1p": (_log_like, "conj", _plus_zero_real),
    "sqrt": (_sqrt, "conj", _plus_zero_real),
    "acos": (_acos, "conj", _acos_zero),
    "acosh": (_acosh, "conj", _acosh_zero),
    "asinh": (_asinh, "odd", _odd_zero),
    "atanh": (_atanh, "odd", _odd_zero),
    "sign": (_sign, "sign", _sign_zero),
}
# Finite poles the standard lists: name -> (xp, a, b) -> (where, re, im).
_POLES: dict[str, Callable] = {"log1p": _log1p_pole, "atanh": _atanh_poles}
FUNCTIONS = frozenset(_RULES)


def _negative(xp: Any, v: Any) -> Any:
    """True where ``v``'s sign bit is set (-0.0 included)."""
    return xp.copysign(xp.full_like(v, 1.0), v) < 0


def _differs(xp: Any, x: Any, y: Any) -> Any:
    """True where ``x`` is not ``y`` (NaN differs from everything, -0.0 from +0.0)."""
    return (x != y) | (_negative(xp, x) ^ _negative(xp, y))


def fixer(name: str, xp: Any) -> Callable[[Any, Any], Any]:
    """``fix(z, out)``: the native's complex result ``out`` of ``z`` with the standard's special
    values where ``z`` has an infinite or NaN part, at ``z = +-0 +-0j``, and at the poles the
    standard lists (``log1p(-1 + 0j)``, ``atanh(1 + 0j)``).

    Args:
        name: the function's Array API name (one of :data:`FUNCTIONS`).
        xp: the backend's functions (:func:`namespace`).

    Returns:
        The fixer, elementwise and traceable.

    Example:
        >>> fix = fixer("exp", namespace(**natives))  # doctest: +SKIP
        >>> fix(z, jnp.exp(z))  # doctest: +SKIP
    """
    rule, symmetry, at_zero = _RULES[name]
    pole = _POLES.get(name)

    def fix(z: Any, out: Any) -> Any:
        a, b = xp.real(z), xp.imag(z)
        neg_a, neg_b = _negative(xp, a), _negative(xp, b)
        if symmetry == "sign":
            special = ~(xp.isfinite(a) & xp.isfinite(b))
            re, im = rule(_Parts(xp, a, b))
        else:
            odd_or_even = symmetry != "conj"
            p = _Parts(xp, xp.abs(a) if odd_or_even else a, xp.abs(b))
            special = ~(p.fin_a & p.fin_b)
            re, im = rule(p)
            if symmetry == "odd":
                re = xp.where(neg_a, -re, re)
            im = xp.where(neg_a ^ neg_b if symmetry == "even" else neg_b, -im, im)
        re = xp.where(special, re, xp.real(out))
        im = xp.where(special, im, xp.imag(out))
        zero_re, zero_im = at_zero(xp, a, b)
        zero = (a == 0) & (b == 0) & (_differs(xp, re, zero_re) | _differs(xp, im, zero_im))
        re, im = xp.where(zero, zero_re, re), xp.where(zero, zero_im, im)
        if pole is not None:
            at_pole, pole_re, pole_im = pole(xp, a, b)
            re, im = xp.where(at_pole, pole_re, re), xp.where(at_pole, pole_im, im)
        return xp.complex(re, im)

    fix.__name__ = fix.__qualname__ = f"fix_{name}"
    return fix


def wrap(native: Callable, name: str, xp: Any, complex_dtypes: tuple[Any, Any]) -> Callable:
    """``native(x)`` with the standard's special values for complex results (:func:`fixer`);
    a real result costs two identity tests of its dtype more than the native.

    Args:
        native: the framework's function.
        name: its Array API name (one of :data:`FUNCTIONS`).
        xp: the backend's functions (:func:`namespace`).
        complex_dtypes: the framework's complex64 and complex128 dtype objects.

    Returns:
        The wrapped function.
    """
    fix = fixer(name, xp)
    c64, c128 = complex_dtypes

    def fn(x, /):
        out = native(x)
        dtype = out.dtype
        if dtype is not c64 and dtype is not c128:
            return out
        return fix(x, out)

    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = f"{name}, with the Array API's special values for complex input."
    return fn
