"""numpy backend: sorting. NaN sorts as the largest value: last ascending, first descending (as on
every backend); -0.0 and 0.0 are equal. A stable descending sort keeps equal elements in their
order, so it sorts the reversed array and reverses the result."""

from __future__ import annotations

import numpy as np

__all__ = ["argsort", "sort"]


def argsort(x, /, *, axis=-1, descending=False, stable=True):
    kind = "stable" if stable else None
    if not descending:
        return np.argsort(x, axis=axis, kind=kind)
    flipped = np.flip(np.argsort(np.flip(x, axis), axis=axis, kind=kind), axis)
    return np.shape(x)[axis] - 1 - flipped


def sort(x, /, *, axis=-1, descending=False, stable=True):
    kind = "stable" if stable else None
    if not descending:
        return np.sort(x, axis=axis, kind=kind)
    return np.flip(np.sort(np.flip(x, axis), axis=axis, kind=kind), axis)
