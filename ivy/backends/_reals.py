"""Functions of real numbers given integer or boolean arrays, for backends whose arrays carry
numpy dtypes (numpy, jax).

ivy's rule, the same on every backend: a function defined on floating-point numbers (``sin``,
``divide``, ``mean``, ``softmax``...) computes integer and boolean inputs in the default float
dtype, float32, as it would a float32 array of the same values. Next to a floating array an
integer one takes the floating dtype, as type promotion says.

numpy's own ufuncs compute integers in float64 and booleans in float16; jax computes int64 in
float64 when 64-bit types are on. The wrappers here call the framework's function and look at
the result's dtype: float32 (the common case) is returned at once; only a float16, float64 or
complex128 result, which such inputs produce, leads to a look at the inputs, and to a second
call with converted inputs when they were not floating. A float32 call costs one function call
and a dtype comparison more than the framework's own.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable

import numpy as np

from ivy.backends import _int_scalars

_INEXACT = "fc"  # numpy dtype kinds: floating, complex
_PYTHON_SCALARS = frozenset({bool, int, float, complex})
# The result dtypes that integer or boolean inputs can produce (float32 ones cannot).
_F16, _F64, _C128 = np.dtype(np.float16), np.dtype(np.float64), np.dtype(np.complex128)
_C64 = np.dtype(np.complex64)


def _suspect(out) -> bool:
    dtype = out.dtype
    return dtype is _F64 or dtype is _F16 or dtype is _C128


def _float32(x):
    return x.astype("float32")  # numpy and jax arrays alike


def _kind(x):
    """``x``'s dtype kind; None for a Python scalar (and for array-likes without a dtype)."""
    return None if type(x) in _PYTHON_SCALARS else getattr(getattr(x, "dtype", None), "kind", None)


def unary(native: Callable, name: str, complex_fix: Callable | None = None) -> Callable:
    """``native(x)`` with an integer or boolean ``x`` converted to float32 first; with
    ``complex_fix``, a complex result ``out`` of ``x`` is ``complex_fix(x, out)`` (the standard's
    special values, ``ivy/backends/_complex_special.py``)."""
    if complex_fix is not None:
        return _unary_fixing_complex(native, name, complex_fix)

    def fn(x, /):
        out = native(x)
        dtype = out.dtype  # inlined _suspect: this is the hot path of small arrays
        if dtype is not _F64 and dtype is not _F16 and dtype is not _C128:
            return out
        kind = _kind(x)
        return out if kind is None or kind in _INEXACT else native(_float32(x))

    return _named(fn, name, "inputs")


def _unary_fixing_complex(native: Callable, name: str, fix: Callable) -> Callable:
    """:func:`unary` whose complex results go through ``fix``: a real result pays one more
    identity test of its dtype than :func:`unary`'s."""

    def fn(x, /):
        out = native(x)
        dtype = out.dtype
        if dtype is not _F64 and dtype is not _F16 and dtype is not _C128 and dtype is not _C64:
            return out
        if dtype is _C64 or dtype is _C128:
            return fix(x, out)
        kind = _kind(x)
        return out if kind is None or kind in _INEXACT else native(_float32(x))

    return _named(fn, name, "inputs")


def with_options(native: Callable, name: str) -> Callable:
    """``native(x, *args, **kwargs)`` (a reduction...) with an integer or boolean ``x``
    converted to float32 first."""

    def fn(x, /, *args, **kwargs):
        out = native(x, *args, **kwargs)
        if not _suspect(out):
            return out
        kind = _kind(x)
        if kind is None or kind in _INEXACT:
            return out
        return native(_float32(x), *args, **kwargs)

    return _named(fn, name, "inputs", native)


def binary(native: Callable, name: str) -> Callable:
    """``native(x1, x2)`` with integer or boolean operands converted first: to float32 when
    neither operand is floating, else to the floating operand's dtype."""

    def fn(x1, x2, /):
        if type(x1) is int or type(x2) is int:  # beyond the array's dtype: as a float
            x1, x2 = _int_scalars.operands(native, name, x1, x2)
        out = native(x1, x2)
        dtype = out.dtype  # inlined _suspect, as in unary
        if dtype is not _F64 and dtype is not _F16 and dtype is not _C128:
            return out
        k1, k2 = _kind(x1), _kind(x2)
        if (k1 is None or k1 in _INEXACT) and (k2 is None or k2 in _INEXACT):
            return out
        if k1 is not None and k1 in _INEXACT:  # x2 exact: it takes x1's dtype
            return native(x1, x2.astype(x1.dtype))
        if k2 is not None and k2 in _INEXACT:
            return native(x1.astype(x2.dtype), x2)
        # no floating array: exact arrays become float32, Python scalars stay as they are
        return native(x1 if k1 is None else _float32(x1), x2 if k2 is None else _float32(x2))

    return _named(fn, name, "operands")


def _named(fn: Callable, name: str, what: str, native: Callable | None = None) -> Callable:
    fn.__name__ = fn.__qualname__ = name
    fn.__ivy_reals__ = True
    fn.__doc__ = f"{name}, with integer and boolean {what} computed in float32."
    if native is not None:
        try:  # the native's parameters, not ``*args, **kwargs``
            fn.__signature__ = inspect.signature(native)
        except (TypeError, ValueError):
            pass
    return fn


# ivy's rule for the functions of real numbers that the core declares (@dispatch(reals=True)),
# applied by the assembly of the backends whose arrays carry numpy dtypes.
WRAPPERS = {"unary": unary, "binary": binary, "options": with_options}


def scalar_operands(native: Callable, name: str) -> Callable:
    """``native(x1, x2)`` with a Python float (or complex) next to an integer or boolean array
    computed as ivy says: in float32 (complex64), the default dtype, where numpy and jax (with
    64-bit types) give float64 (complex128); a Python int beyond the array's dtype as
    ``_int_scalars`` says (jax would wrap it around). Two arrays are the native's business: the function
    carries it as ``__ivy_native__``, which ivy's dispatchers call when no Python scalar is
    involved."""

    def fn(x1, x2, /):
        if type(x1) is int or type(x2) is int:  # beyond the array's dtype?
            x1, x2 = _int_scalars.operands(native, name, x1, x2)
            if x2 is None:
                return x1  # a comparison's answer
        out = native(x1, x2)
        if type(x1) not in _PYTHON_SCALARS and type(x2) not in _PYTHON_SCALARS:
            return out
        dtype = getattr(out, "dtype", None)
        if dtype is not _F64 and dtype is not _C128:
            return out
        if type(x1) in _PYTHON_SCALARS:
            kind = _kind(x2)
            return out if kind is None or kind in _INEXACT else native(x1, _float32(x2))
        kind = _kind(x1)
        return out if kind is None or kind in _INEXACT else native(_float32(x1), x2)

    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = f"{name}, with Python scalars promoted as ivy's rules say."
    fn.__ivy_native__ = native
    fn.__ivy_scalar_shim__ = True
    return fn
