"""Functions of real numbers given integer or boolean arrays, for backends whose arrays carry
numpy dtypes (numpy, jax).

ivy's rule, the same on every backend: a function defined on floating-point numbers (``sin``,
``divide``, ``mean``, ``softmax``...) computes integer and boolean inputs in the default float
dtype, float32, as it would a float32 array of the same values. Next to a floating array an
integer one takes the floating dtype, as type promotion says.

numpy's own ufuncs compute integers in float64 and booleans in float16; jax computes int64 in
float64 when 64-bit types are on. The wrappers here convert such inputs first, and cost one
dtype check when the inputs are already floating.
"""

from __future__ import annotations

from collections.abc import Callable

_INEXACT = "fc"  # numpy dtype kinds: floating, complex


def unary(native: Callable, name: str, to_float32: Callable) -> Callable:
    """``native(x, ...)`` with an integer or boolean ``x`` converted by ``to_float32`` first."""

    def fn(x, /, *args, **kwargs):
        try:
            exact = x.dtype.kind not in _INEXACT
        except AttributeError:  # a Python scalar: the framework's own rules
            exact = False
        return native(to_float32(x) if exact else x, *args, **kwargs)

    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = f"{name}, with integer and boolean inputs computed in float32."
    return fn


def binary(native: Callable, name: str, to_float32: Callable, astype: Callable) -> Callable:
    """``native(x1, x2)`` with integer or boolean operands converted first: to float32 when
    neither operand is floating, else to the floating operand's dtype."""

    def fn(x1, x2, /):
        k1 = getattr(getattr(x1, "dtype", None), "kind", None)
        k2 = getattr(getattr(x2, "dtype", None), "kind", None)
        if (k1 is None or k1 in _INEXACT) and (k2 is None or k2 in _INEXACT):
            return native(x1, x2)
        if k1 is not None and k1 in _INEXACT:  # x2 exact: it takes x1's dtype
            return native(x1, astype(x2, x1.dtype))
        if k2 is not None and k2 in _INEXACT:
            return native(astype(x1, x2.dtype), x2)
        # no floating array: exact arrays become float32, Python scalars stay as they are
        return native(x1 if k1 is None else to_float32(x1), x2 if k2 is None else to_float32(x2))

    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = f"{name}, with integer and boolean operands computed in float32."
    return fn
