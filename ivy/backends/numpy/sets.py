"""numpy backend: unique values, sorted, as the Array API's named tuples. Each NaN is a distinct
value; -0.0 and 0.0 are one value.

``np.unique`` (which sorts), not numpy's ``unique_*`` functions: since numpy 2.3 those may return
the values unsorted (``unique_values`` already does), and ivy's are sorted on every backend."""

from __future__ import annotations

import numpy as np

from ivy.core._results import UniqueAllResult, UniqueCountsResult, UniqueInverseResult


def unique_all(x, /):
    values, indices, inverse, counts = np.unique(
        x, return_index=True, return_inverse=True, return_counts=True, equal_nan=False
    )
    return UniqueAllResult(values, indices, inverse.reshape(np.shape(x)), counts)


def unique_counts(x, /):
    return UniqueCountsResult(*np.unique(x, return_counts=True, equal_nan=False))


def unique_inverse(x, /):
    values, inverse = np.unique(x, return_inverse=True, equal_nan=False)
    return UniqueInverseResult(values, inverse.reshape(np.shape(x)))


def unique_values(x, /):
    return np.unique(x, equal_nan=False)
