"""Signed zeros, the same on every backend (written once, against any array library's
operators and a ``where``).

The Array API leaves the sign of a zero open where ``minimum``, ``maximum``, ``min`` and ``max``
choose between ``-0`` and ``+0``; numpy's answer depends on the order of the arguments
(``minimum`` returns its second at a tie) and, for the reductions, on the array's length (its
SIMD loops). ivy takes IEEE 754-2019's ``minimum`` and ``maximum``, which order ``-0`` below
``+0`` whatever the order of the arguments (jax's answer): ``minimum(+0, -0)`` is ``-0``,
``maximum(-0, +0)`` is ``+0``, and so are the reductions (``min`` of zeros is ``-0`` when one of
them is). ``relu(-0)`` is ``+0`` (``maximum(x, 0)``), and a singular matrix's ``det`` is ``+0``
and ``slogdet``'s sign ``0`` (numpy's answer, the standard's "the sign should be 0").

Each fix keeps the gradient of the value it replaces, so that the derivatives of the backends
are unchanged; none is needed on jax.
"""

from __future__ import annotations


def zero_ties(where, x1, x2, out, lower: bool):
    """``out`` (a native ``minimum`` or ``maximum`` of ``x1`` and ``x2``) with IEEE's sign where
    both operands are zeros: ``-0`` if either is (``lower``, the minimum), ``+0`` if either is
    (the maximum). There the value is half the sum of the two (``x1 + x2`` has the maximum's
    sign, ``-(-x1 - x2)`` the minimum's), which splits the gradient between them as torch and
    jax do at a tie."""
    both = (x1 == 0) & (x2 == 0)
    tie = -(-x1 - x2) * 0.5 if lower else (x1 + x2) * 0.5
    return where(both, tie, out)


def reduced_zero(where, stop_gradient, out, negative):
    """``out`` (a native ``min`` or ``max``) with the sign of a zero result set by the boolean
    ``negative`` (reduced like ``out``), keeping the gradient: ``out - stop_gradient(out)`` is
    ``+0`` and ``-(stop_gradient(out) - out)`` is ``-0``, each with derivative 1."""
    positive_zero = out - stop_gradient(out)
    negative_zero = -(stop_gradient(out) - out)
    return where(out == 0, where(negative, negative_zero, positive_zero), out)


def positive_zero(where, stop_gradient, x):
    """``x`` with ``-0`` made ``+0``, keeping the gradient (``x - stop_gradient(x)`` is ``+0``;
    ``x + 0.0`` would be simplified away by XLA and tensorflow's graph optimiser)."""
    return where(x == 0, x - stop_gradient(x), x)
