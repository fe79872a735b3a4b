"""numpy backend: elementwise functions that differ from the shared layer's.

numpy's ``expm1`` of complex numbers misses the Array API's special values (``expm1(0j)``,
``expm1(inf + 0j)``...), and its ``tanh(inf + bj)`` gives ``1 - 0j`` for some positive ``b``
where the standard says ``1 + 0j``: the two are numpy's own with those values put back for
complex results (``ivy/backends/_complex_special.py``); so is its ``sign`` of a complex number
with an infinite part (numpy gives the direction, ``sign(inf + 1j) = 1``; the standard's rules of
complex division, and every other backend, NaN + NaN j). Every other function stays numpy's.
"""

from __future__ import annotations

import numpy as np

from ivy.backends import _complex_special, _reals, _signed_zeros


def _complex(re, im):
    """A complex array of parts ``re`` and ``im`` (``re + 1j * im`` makes ``0 * inf`` NaN)."""
    re, im = np.broadcast_arrays(re, im)
    out = np.empty(re.shape, np.result_type(re.dtype, np.complex64))
    out.real, out.imag = re, im
    return out if out.ndim else out[()]


_XP = _complex_special.namespace(np, complex=_complex)


def _fixed(name: str):
    return _reals.unary(getattr(np, name), name, _complex_special.fixer(name, _XP))


expm1 = _fixed("expm1")
sign = _fixed("sign")
tanh = _fixed("tanh")


def _with_zero_ties(native, lower: bool):
    """numpy's ``minimum`` or ``maximum`` with IEEE's signed zeros at a tie of zeros (numpy
    returns the second operand; ``ivy/backends/_signed_zeros.py``)."""

    def fn(x1, x2, /):
        out = native(x1, x2)
        if getattr(out, "dtype", None) is None or out.dtype.kind != "f":
            return out
        both = np.logical_and(np.equal(x1, 0), np.equal(x2, 0))
        if not both.any():  # (numpy is eager: a test is cheaper than the fix)
            return out
        fixed = _signed_zeros.zero_ties(np.where, x1, x2, out, lower).astype(out.dtype)
        return fixed if np.ndim(out) else fixed[()]

    fn.__name__ = fn.__qualname__ = native.__name__
    return fn


maximum = _reals.scalar_operands(_with_zero_ties(np.maximum, lower=False), "maximum")
minimum = _reals.scalar_operands(_with_zero_ties(np.minimum, lower=True), "minimum")
