"""Elementwise functions, written once: the native ones as they are (``xp.add``), and the few
whose native behaviour differs from ivy's.

Functions of real numbers (``sin``, ``divide``...) are declared on the core's stubs
(``@dispatch(reals=True)``); the assembly wraps them with the backend's ``reals`` wrappers, so
nothing here converts integer inputs.
"""

from __future__ import annotations

from ivy.backends.array_api._unbound import xp

NATIVE = {
    name: name
    for name in (
        "abs acos acosh add asin asinh atan atan2 atanh bitwise_and bitwise_invert "
        "bitwise_left_shift bitwise_or bitwise_right_shift bitwise_xor ceil conj copysign cos "
        "cosh divide equal exp expm1 floor floor_divide greater greater_equal hypot imag isfinite "
        "isinf isnan less less_equal log log10 log1p log2 logaddexp logical_and logical_not "
        "logical_or logical_xor maximum minimum multiply negative nextafter not_equal positive "
        "pow real remainder round sign signbit sin sinh sqrt square subtract tan tanh trunc"
    ).split()
}


def reciprocal(x, /):
    return xp.divide(1.0, x)  # a native reciprocal may divide integers as integers (1 // x)


def clip(x, /, min=None, max=None):  # noqa: A002 - the Array API names
    if min is None and max is None:
        return xp.asarray(x, copy=True)
    return xp.clip(x, min, max)


def nan_to_num(x, /, *, nan=0.0, posinf=None, neginf=None):
    native = getattr(xp, "nan_to_num", None)  # not in the standard; numpy and jax have it
    if native is not None:
        return native(x, nan=nan, posinf=posinf, neginf=neginf)
    if not xp.isdtype(x.dtype, ("real floating", "complex floating")):
        return x
    if xp.isdtype(x.dtype, "complex floating"):
        re = nan_to_num(xp.real(x), nan=nan, posinf=posinf, neginf=neginf)
        im = nan_to_num(xp.imag(x), nan=nan, posinf=posinf, neginf=neginf)
        return re + im * 1j
    info = xp.finfo(x.dtype)
    x = xp.where(xp.isnan(x), xp.asarray(nan, dtype=x.dtype), x)
    x = xp.where(x == xp.inf, xp.asarray(info.max if posinf is None else posinf, dtype=x.dtype), x)
    return xp.where(
        x == -xp.inf, xp.asarray(info.min if neginf is None else neginf, dtype=x.dtype), x
    )
