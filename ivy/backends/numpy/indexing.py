"""numpy backend: gathering and scattering (``gather_flat`` and ``indices_where`` are numpy's
``take`` and ``argwhere``)."""

from __future__ import annotations

import numpy as np

from ivy.backends._index_checks import check_bounds, check_rows
from ivy.backends.numpy._helpers import native_dtype

gather_flat = np.take  # (params, indices): flattened, any index shape, negative from the end
indices_where = np.argwhere

_REDUCERS = {"sum": np.add, "min": np.minimum, "max": np.maximum}


def take(x, indices, /, *, axis=None):
    return np.take(x, indices, axis=axis)


def _index_tuple(indices):
    indices = np.asarray(indices)
    return tuple(np.moveaxis(indices, -1, 0))


def gather_nd(params, indices, /):
    return np.asarray(params)[_index_tuple(indices)]


def scatter_nd(indices, updates, /, shape, *, reduction="sum"):
    updates = np.asarray(updates)
    idx = _index_tuple(indices)
    out = np.zeros(shape, dtype=updates.dtype)
    if reduction == "replace":
        out[idx] = updates
        return out
    if reduction not in _REDUCERS:
        raise ValueError(
            f"scatter_nd: unknown reduction {reduction!r}; use 'sum', 'replace', 'min' or 'max'."
        )
    if reduction == "sum":
        np.add.at(out, idx, updates)
        return out
    touched = np.zeros(shape, dtype=bool)
    touched[idx] = True
    fill = _extreme(updates.dtype, largest=reduction == "min")
    out.fill(fill)
    _REDUCERS[reduction].at(out, idx, updates)
    out[~touched] = 0
    return out


def _extreme(dtype, largest):
    if np.issubdtype(dtype, np.floating):
        return np.inf if largest else -np.inf
    info = np.iinfo(dtype)
    return info.max if largest else info.min


def one_hot(indices, depth, /, *, dtype=None):
    indices = np.asarray(indices)
    check_bounds(indices, depth, function="one_hot", backend="numpy", negative=False)
    return (indices[..., None] == np.arange(depth)).astype(native_dtype(dtype) or np.float32)


def scatter_flat(indices, updates, /, size, *, reduction="sum"):
    return scatter_nd(np.asarray(indices)[..., None], updates, (size,), reduction=reduction)


def take_along_axis(x, indices, /, *, axis=-1):
    return np.take_along_axis(np.asarray(x), np.asarray(indices), axis=axis)


def put_rows(x, indices, updates, /):
    """A copy of ``x``, then the assignment ``out[indices] = updates``."""
    x, indices, updates = np.asarray(x), np.asarray(indices), np.asarray(updates)
    integer = indices.dtype.kind in "iu"
    check_rows(x.shape, indices.shape, updates.shape, integer=integer, backend="numpy")
    check_bounds(indices, x.shape[0], function="put_rows", backend="numpy")
    out = x.copy()
    out[indices] = updates
    return out
