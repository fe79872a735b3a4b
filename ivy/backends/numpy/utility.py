"""numpy backend: truth tests and differences."""

from __future__ import annotations

import numpy as np

__all__ = ["all", "any", "diff"]

all = np.all  # noqa: A001 - the Array API names
any = np.any  # noqa: A001


def diff(x, /, *, axis=-1, n=1, prepend=None, append=None):
    extra = {}
    if prepend is not None:
        extra["prepend"] = prepend
    if append is not None:
        extra["append"] = append
    return np.diff(x, n=n, axis=axis, **extra)
