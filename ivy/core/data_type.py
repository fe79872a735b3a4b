"""Data types. Dtypes may be given as strings ('float32') or as the framework's objects."""

from __future__ import annotations

from ivy.core._dispatch import alias, dispatch

__all__ = ["astype", "cast"]


@dispatch
def astype(x, dtype, /, *, copy=True, f=None):
    """``x`` converted to ``dtype``. Example: ``ivy.astype(x, 'float64')``."""


cast = alias("cast", astype)
