"""numpy backend: sorting. NaN sorts as the largest value: last ascending, first descending (as on
every backend); -0.0 and 0.0 are equal. A stable descending sort keeps equal elements in their
order, so it sorts the reversed array and reverses the result."""

from __future__ import annotations

import numpy as np

from ivy._args.axes import normalize_axis
from ivy.backends._sample_args import top_k_axis
from ivy.core._results import TopKResult


def argsort(x, /, *, axis=-1, descending=False, stable=True):
    if np.ndim(x) == 0:  # (numpy's argsort of a 0-d array is [0], its sort raises)
        normalize_axis(axis, 0, "argsort", "numpy")
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


def top_k(x, k, /, *, axis=-1, largest=True, sorted=True):
    """The first ``k`` of a stable sort (descending for the largest): ties in index order."""
    x = np.asarray(x)
    axis = top_k_axis(x.shape, k, axis)
    order = argsort(x, axis=axis, descending=largest, stable=True)
    indices = np.take(order, np.arange(k), axis=axis)
    return TopKResult(np.take_along_axis(x, indices, axis=axis), indices)
