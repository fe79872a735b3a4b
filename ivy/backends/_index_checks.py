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

from ivy.errors import IndexOutOfBoundsError


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
