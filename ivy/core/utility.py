"""Truth tests and differences. ``axis`` is None (all axes), an int or a tuple."""

from __future__ import annotations

from ivy.core._dispatch import dispatch

__all__ = ["all", "any", "diff"]


@dispatch
def all(x, /, *, axis=None, keepdims=False, f=None):  # noqa: A001 - the Array API name
    """True where every element over ``axis`` is nonzero (NaN counts as nonzero); True for an
    empty reduction."""


@dispatch
def any(x, /, *, axis=None, keepdims=False, f=None):  # noqa: A001 - the Array API name
    """True where some element over ``axis`` is nonzero (NaN counts as nonzero); False for an
    empty reduction."""


@dispatch
def diff(x, /, *, axis=-1, n=1, prepend=None, append=None, f=None):
    """The ``n``-th forward difference along ``axis`` (``x[i+1] - x[i]``; for bools, ``!=``),
    after joining ``prepend`` before and ``append`` after ``x`` along that axis.

    Example: ``ivy.diff(np.array([1, 4, 9, 16]))`` -> ``[3, 5, 7]``.
    """
