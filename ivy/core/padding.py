"""Padding an array with a constant along each axis."""

from __future__ import annotations

from collections.abc import Sequence

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition, dispatch
from ivy.typing import Array, Framework, Scalar

__all__ = ["constant_pad", "zero_pad"]


@dispatch
def constant_pad(
    x: Array, /, pad_width: Sequence[tuple[int, int]], *, value: Scalar = 0, f: Framework = None
) -> Array:
    """Pad ``x`` with ``value`` at both ends of each axis.

    Args:
        x: array.
        pad_width: one ``(before, after)`` pair of non-negative ints per axis of ``x``.
        value: the fill value (cast to ``x``'s dtype).

    Returns:
        ``x`` with ``before + after`` more elements along each axis.

    Example: ``ivy.constant_pad(np.array([1, 2]), [(1, 2)], value=9)`` -> ``[9, 1, 2, 9, 9]``.
    """


@composition
def zero_pad(x: Array, /, pad_width: Sequence[tuple[int, int]], *, f: Framework = None) -> Array:
    """Pad ``x`` with zeros: :func:`constant_pad` with ``value=0``.

    Example: ``ivy.zero_pad(np.ones((1, 1)), [(0, 1), (1, 0)])`` -> ``[[0., 1.], [0., 0.]]``.
    """
    return _fh.get_framework(x, f=f).constant_pad(x, pad_width, value=0)
