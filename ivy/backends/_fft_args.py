"""Argument resolution shared by every backend's ``fft`` module.

Pure Python (no framework): ``s``, ``axes`` and ``norm`` are read here with the Array API's rules
so that the four backends accept the same arguments and raise the same errors. The frameworks then
receive explicit sizes and non-negative axes.
"""

from __future__ import annotations

import operator
from collections.abc import Sequence

NORMS = ("backward", "ortho", "forward")
# hfft is irfft of the conjugate, and ihfft the conjugate of rfft, with the scalings swapped.
SWAPPED_NORM = {"backward": "forward", "forward": "backward", "ortho": "ortho"}


def check_norm(norm: str, fn: str) -> str:
    if norm not in NORMS:
        raise ValueError(f"{fn}: unknown norm {norm!r}; use 'backward', 'ortho' or 'forward'.")
    return norm


def axis_of(axis: int, ndim: int, fn: str) -> int:
    """``axis`` as a non-negative axis of an array of ``ndim`` axes."""
    axis = operator.index(axis)
    if not -ndim <= axis < ndim:
        raise ValueError(f"{fn}: axis {axis} is out of bounds for an array of {ndim} dimensions.")
    return axis % ndim


def size_of(n, default: int, fn: str) -> int:
    """The transform length: ``n``, or ``default`` when ``n`` is None; at least 1."""
    n = default if n is None else operator.index(n)
    if n < 1:
        raise ValueError(f"{fn}: the transform length must be at least 1; got {n}.")
    return n


def sizes_and_axes(
    shape: Sequence[int], s, axes, fn: str, *, real_inverse: bool = False
) -> tuple[list[int], list[int]]:
    """Explicit ``(sizes, axes)`` for the n-dimensional transforms.

    ``axes=None`` means every axis, or the last ``len(s)`` axes when ``s`` is given; ``s=None`` or
    an entry ``-1`` means the input's size along that axis, except for the last axis of an inverse
    real transform (``irfftn``), where it means ``2 * (m - 1)``.
    """
    ndim = len(shape)
    if axes is None:
        axes = list(range(ndim)) if s is None else list(range(ndim - len(s), ndim))
    axes = [axis_of(a, ndim, fn) for a in axes]
    if len(set(axes)) != len(axes):
        raise ValueError(f"{fn}: axes {tuple(axes)} repeat an axis.")
    s = [-1] * len(axes) if s is None else list(s)
    if len(s) != len(axes):
        raise ValueError(f"{fn}: s and axes must have the same length; got {s} and {axes}.")
    sizes = []
    for i, (n, a) in enumerate(zip(s, axes)):
        if n == -1:
            last = real_inverse and i == len(axes) - 1
            n = 2 * (shape[a] - 1) if last else shape[a]
        sizes.append(size_of(n, n, fn))
    return sizes, axes
