"""Axes as the Array API reads them, for the backends whose frameworks read them otherwise:
negative axes count from the end, and an axis out of range or repeated raises
:class:`ivy.errors.AxisError` naming the function, the argument and the backend."""

from __future__ import annotations

import math
from collections.abc import Sequence

from ivy.errors import AxisError, ShapeError


def normalize_axis(
    axis: int, ndim: int, function: str, backend: str, argument: str = "axis"
) -> int:
    """``axis`` as a non-negative position among ``ndim`` axes."""
    if not -ndim <= axis < ndim:
        raise AxisError(
            AxisError.out_of_range(axis, ndim),
            function=function,
            argument=argument,
            backend=backend,
        )
    return axis % ndim


def normalize_axes(
    axes: int | Sequence[int], ndim: int, function: str, backend: str, argument: str = "axis"
) -> tuple[int, ...]:
    """``axes`` (an int or a sequence of them) as distinct non-negative positions."""
    items = (axes,) if isinstance(axes, int) else tuple(axes)
    out = tuple(normalize_axis(a, ndim, function, backend, argument) for a in items)
    if len(set(out)) != len(out):
        raise AxisError(
            f"repeated axis in {items}.", function=function, argument=argument, backend=backend
        )
    return out


def new_axis_positions(
    axis: int | Sequence[int], ndim: int, function: str, backend: str
) -> tuple[int, ...]:
    """The positions, in the result, of the new axes of ``expand_dims(x, axis)`` for an ``x`` of
    ``ndim`` dimensions (negative positions count from the end of the result), sorted."""
    count = 1 if isinstance(axis, int) else len(axis)
    return tuple(sorted(normalize_axes(axis, ndim + count, function, backend)))


def check_squeezable(
    shape: Sequence[int | None], axes: Sequence[int], axis: object, backend: str
) -> None:
    """Raise :class:`ivy.errors.ShapeError` if an axis of ``axes`` (normalized) has a size other
    than 1 (``axis`` as given, for the message)."""
    if any(shape[a] not in (1, None) for a in axes):
        raise ShapeError(
            f"cannot remove axis {axis} of an array of shape {tuple(shape)}: only axes of size 1 "
            f"can be removed.",
            function="squeeze",
            argument="axis",
            backend=backend,
        )


def too_few_for_correction(
    shape: Sequence[int | None], axis: int | Sequence[int] | None, correction: float
) -> bool | None:
    """True where ``var``/``std`` over ``axis`` of an array of ``shape`` has ``N - correction <= 0``
    (N: the elements per result), whose result the standard says is NaN (numpy and torch give
    inf, tensorflow a negative number); None where a size is unknown (inside ``tf.function``).
    Axes out of range are left to the framework's own error."""
    ndim = len(shape)
    if axis is None:
        sizes = list(shape)
    else:
        items = (axis,) if isinstance(axis, int) else tuple(axis)
        if any(not -ndim <= a < ndim for a in items):
            return False
        sizes = [shape[a] for a in items]
    if any(s is None for s in sizes):
        return None
    return math.prod(sizes) - correction <= 0


def cumulative_axis(axis: int | None, ndim: int, name: str) -> int:
    """The axis of ``cumulative_sum``/``cumulative_prod``: ``None`` is allowed for
    one-dimensional arrays only (numpy would accumulate a 0-d array into shape (1,))."""
    if axis is not None:
        return axis
    if ndim != 1:
        raise ValueError(
            f"{name}: axis is required for arrays of {ndim} dimensions (None is allowed for "
            "one-dimensional arrays only)."
        )
    return 0
