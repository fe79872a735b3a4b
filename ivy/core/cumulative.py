"""Cumulative sums and products along an axis, with tensorflow's ``exclusive`` and ``reverse``.

With ``dtype=None``, floating inputs keep their dtype, bool and integers narrower than 64 bits
accumulate in int64 (unsigned ones in uint64), on every backend.
"""

from __future__ import annotations

from ivy.core._dispatch import dispatch
from ivy.typing import Array, Dtype, Framework

__all__ = ["cumsum", "cumprod"]


@dispatch
def cumsum(
    x: Array,
    /,
    axis: int = 0,
    *,
    exclusive: bool = False,
    reverse: bool = False,
    dtype: Dtype | None = None,
    f: Framework = None,
) -> Array:
    """Cumulative sum of ``x`` along ``axis``.

    Args:
        x: array with at least one axis.
        axis: the axis summed along.
        exclusive: leave each element out of its own sum (the first result is 0).
        reverse: sum from the end of the axis towards its start.
        dtype: dtype to accumulate in (and of the result).

    Returns:
        An array of ``x``'s shape: ``out[i] = x[0] + ... + x[i]`` (``exclusive``: up to
        ``x[i - 1]``; ``reverse``: ``x[i] + ... + x[-1]``).

    Example: ``ivy.cumsum(np.array([1, 2, 3]), exclusive=True)`` -> ``[0, 1, 3]``.
    """


@dispatch
def cumprod(
    x: Array,
    /,
    axis: int = 0,
    *,
    exclusive: bool = False,
    reverse: bool = False,
    dtype: Dtype | None = None,
    f: Framework = None,
) -> Array:
    """Cumulative product of ``x`` along ``axis`` (arguments as :func:`cumsum`; the first result
    of an exclusive product is 1).

    Example: ``ivy.cumprod(np.array([1, 2, 3]), reverse=True)`` -> ``[6, 6, 3]``.
    """
