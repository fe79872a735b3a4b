"""Reductions. ``axis`` is None (all axes), an int or a tuple; ``keepdims`` keeps reduced axes.

Integer sums and products accumulate in int64 on every backend.
"""

from __future__ import annotations

from ivy.core._dispatch import dispatch

__all__ = [
    "sum",
    "prod",
    "mean",
    "min",
    "max",
    "var",
    "std",
    "cumulative_sum",
    "cumulative_prod",
]


@dispatch
def sum(x, /, *, axis=None, dtype=None, keepdims=False, f=None):
    """Sum of ``x`` over ``axis``. Example: ``ivy.sum(np.ones((2, 3)), axis=1)`` -> [3., 3.]."""


@dispatch
def prod(x, /, *, axis=None, dtype=None, keepdims=False, f=None):
    """Product of ``x`` over ``axis``."""


@dispatch
def mean(x, /, *, axis=None, keepdims=False, f=None):
    """Arithmetic mean of a floating ``x`` over ``axis``."""


@dispatch
def min(x, /, *, axis=None, keepdims=False, f=None):
    """Minimum of ``x`` over ``axis`` (nan propagates)."""


@dispatch
def max(x, /, *, axis=None, keepdims=False, f=None):
    """Maximum of ``x`` over ``axis`` (nan propagates)."""


@dispatch
def var(x, /, *, axis=None, correction=0.0, keepdims=False, f=None):
    """Variance over ``axis``, dividing by ``N - correction`` (1 gives the sample variance)."""


@dispatch
def std(x, /, *, axis=None, correction=0.0, keepdims=False, f=None):
    """Standard deviation over ``axis``, dividing by ``N - correction``."""


@dispatch
def cumulative_sum(x, /, *, axis=None, dtype=None, include_initial=False, f=None):
    """Running sums along ``axis`` (None only for 1-D ``x``), starting with 0 when
    ``include_initial``. Bools and signed integers accumulate in int64, unsigned ones in uint64.

    Example: ``ivy.cumulative_sum(np.array([1, 2, 3]))`` -> ``[1, 3, 6]``.
    """


@dispatch
def cumulative_prod(x, /, *, axis=None, dtype=None, include_initial=False, f=None):
    """Running products along ``axis`` (None only for 1-D ``x``), starting with 1 when
    ``include_initial``; dtypes as :func:`cumulative_sum` (Array API 2024.12)."""
