"""Indices out of range raise :class:`ivy.errors.IndexOutOfBoundsError` in eager calls, on
every backend, naming the function, the argument and the backend.

numpy and torch check bounds themselves; jax returns a fill value (``take``, ``gather_nd``) or
drops the update (scatters), and every framework's ``one_hot`` gives a row of zeros, without a
word. Those backends call :func:`check_bounds` on values they can read (eager arrays); inside
``jax.jit`` or ``tf.function`` indices have no values yet, and the frameworks' own behaviour
applies (``docs/conformance.md``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ivy.errors import DtypeError, IndexOutOfBoundsError, ShapeError


def problem(indices: np.ndarray, size: int, *, negative: bool = True) -> str | None:
    """What is out of range among integer ``indices`` for an axis of ``size`` (negative ones
    count from the end when ``negative``), or None."""
    low = -size if negative else 0
    bad = indices[(indices < low) | (indices >= size)]
    if not bad.size:
        return None
    valid = f"{low} to {size - 1}" if size else "none: the axis is empty"
    return f"index {bad.flat[0]} is out of bounds for size {size} (valid: {valid})."


def check_bounds(
    indices: Any,
    size: int,
    *,
    function: str,
    backend: str,
    argument: str = "indices",
    negative: bool = True,
) -> None:
    """Raise if ``indices`` (a numpy array or anything ``np.asarray`` reads) holds an index out of
    range for an axis of ``size``."""
    found = problem(np.asarray(indices), size, negative=negative)
    if found:
        raise IndexOutOfBoundsError(found, function=function, argument=argument, backend=backend)


def check_bounds_per_column(
    indices: Any, shape: Sequence[int], *, function: str, backend: str, argument: str = "indices"
) -> None:
    """Raise if a row of ``indices[..., k]`` (coordinates into the leading axes of ``shape``)
    is out of range for axis ``k``."""
    idx = np.asarray(indices)
    if idx.ndim == 0:
        return
    for k in range(min(idx.shape[-1], len(shape))):
        found = problem(idx[..., k], shape[k])
        if found:
            raise IndexOutOfBoundsError(
                f"column {k}: {found}", function=function, argument=argument, backend=backend
            )


def check_rows(
    x_shape: Sequence[Any] | None,
    indices_shape: Sequence[Any] | None,
    updates_shape: Sequence[Any] | None,
    *,
    integer: bool,
    backend: str,
    function: str = "put_rows",
) -> None:
    """Raise unless ``indices`` is a 1-D integer array ``[k]`` of rows of ``x`` (at least one
    axis) and ``updates`` is ``[k, *x.shape[1:]]``. What is not known yet in a graph being traced
    (a size None, or a shape None: its rank) passes. Shapes are known inside ``jax.jit``, so
    this holds there."""

    def fail(argument: str, message: str, kind: type = ShapeError) -> None:
        raise kind(message, function=function, argument=argument, backend=backend)

    if not integer:
        fail("indices", "indices must be an integer array (row numbers).", DtypeError)
    if x_shape is not None and len(x_shape) == 0:
        fail("x", "x must have at least one axis (its rows), got a 0-d array.")
    if indices_shape is not None and len(indices_shape) != 1:
        fail("indices", f"indices must be 1-D (row numbers), got shape {tuple(indices_shape)}.")
    if x_shape is None or indices_shape is None or updates_shape is None:
        return
    expected = (indices_shape[0], *x_shape[1:])
    same = len(updates_shape) == len(expected) and all(
        a is None or b is None or a == b for a, b in zip(updates_shape, expected)
    )
    if not same:
        fail(
            "updates",
            f"updates must have shape {tuple(expected)} (one row of x's shape {tuple(x_shape)} "
            f"per index), got {tuple(updates_shape)}.",
        )
