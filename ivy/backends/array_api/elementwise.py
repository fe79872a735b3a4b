"""Elementwise functions, written once: the native ones as they are (``xp.add``), and the few
whose native behaviour differs from ivy's.

Functions of real numbers (``sin``, ``divide``...) are declared on the core's stubs
(``@dispatch(reals=True)``); the assembly wraps them with the backend's ``reals`` wrappers, so
nothing here converts integer inputs.
"""

from __future__ import annotations

from ivy.backends import _signed_zeros
from ivy.backends._clip_args import clip_bounds
from ivy.backends._reals import scalar_operands
from ivy.backends.array_api._unbound import backend_ns, xp

NATIVE = {
    name: name
    for name in (
        "abs acos acosh asin asinh atan atanh bitwise_invert ceil conj copysign cos "
        "cosh divide exp expm1 floor hypot imag isfinite "
        "isinf isnan log log10 log1p log2 logaddexp logical_and logical_not "
        "logical_or logical_xor negative nextafter positive "
        "real round sign signbit sin sinh sqrt square tan tanh trunc"
    ).split()
}
# Natives that promote a Python float next to an integer array to float64 (numpy, and jax with
# 64-bit types), or wrap a Python int beyond the array's dtype around (jax): wrapped so that the
# float is float32 and the int answered as ``ivy/backends/_int_scalars.py`` says
# (``_reals.scalar_operands``).
SCALAR_OPERANDS = {
    name: name
    for name in (
        "add subtract multiply floor_divide remainder pow "
        "bitwise_and bitwise_or bitwise_xor bitwise_left_shift bitwise_right_shift "
        "equal not_equal less less_equal greater greater_equal"
    ).split()
}


def atan2(x1, x2, /):
    """The native's; complex input is refused (jax's would answer)."""
    out = xp.atan2(x1, x2)
    if getattr(out.dtype, "kind", None) == "c":
        from ivy.errors import DtypeError

        raise DtypeError(
            "takes no complex floating input. Cast first (ivy.astype).",
            function="atan2",
            argument="x1, x2",
            backend=backend_ns.backend,
        )
    return out


def reciprocal(x, /):
    return xp.divide(1.0, x)  # a native reciprocal may divide integers as integers (1 // x)


def clip(x, /, min=None, max=None):  # noqa: A002 - the Array API names
    """The result has ``x``'s dtype whatever the bounds' (``ivy/backends/_clip_args.py``)."""
    x = xp.asarray(x)
    if min is None and max is None:
        return xp.asarray(x, copy=True)
    low, high = clip_bounds(backend_ns, x, min, max)
    if x.dtype == xp.bool:
        if low is not None:
            x = xp.logical_or(x, xp.asarray(low))
        return x if high is None else xp.logical_and(x, xp.asarray(high))
    return xp.clip(x, low, high)


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


def _zero_ties(native_name: str, lower: bool):
    """The native ``minimum`` or ``maximum`` with IEEE's signed zeros at a tie of zeros
    (``ivy/backends/_signed_zeros.py``; numpy's, which array libraries on numpy share, returns
    the second operand), Python scalars promoted as ivy's rules say."""
    native = getattr(xp, native_name)

    def arrays(x1, x2):
        out = native(x1, x2)
        if not xp.isdtype(out.dtype, "real floating"):
            return out
        return _signed_zeros.zero_ties(xp.where, x1, x2, out, lower)

    return scalar_operands(arrays, native_name)


def maximum(x1, x2, /):
    """The larger of each pair; ``+0`` above ``-0``."""
    return _zero_ties("maximum", False)(x1, x2)


def minimum(x1, x2, /):
    """The smaller of each pair; ``-0`` below ``+0``."""
    return _zero_ties("minimum", True)(x1, x2)
