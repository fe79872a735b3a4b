"""Voxel grids: counts equal ``numpy.histogramdd``; means of points and features equal numpy
accumulations; bounds, resolution mode and batches."""

from __future__ import annotations

import numpy as np
import pytest

import ivy_vision as vis
from tests.helpers import check, native, numpy_of

_data = np.random.default_rng(17)  # constants only; tests: the rng fixture
POINTS = _data.uniform(-0.5, 1.5, (2, 400, 3))
FEATS = _data.standard_normal((2, 400, 2))
BOUNDS = (0.0, -0.2, 0.1, 1.0, 1.2, 1.3)


def _means(points, feats, index, dims):
    """Per-voxel sums by ``np.add.at`` (points with index -1 left out)."""
    keep = index[:, 0] >= 0
    size = (*dims, 3 + feats.shape[-1] + 1)
    sums = np.zeros(size)
    values = np.concatenate([points, feats, np.ones_like(points[:, :1])], -1)
    np.add.at(sums, tuple(index[keep].T), values[keep])
    counts = sums[..., -1:]
    with np.errstate(all="ignore"):
        means = np.where(counts > 0, sums[..., :-1] / np.where(counts > 0, counts, 1), 0.0)
    return np.concatenate([means, counts], -1)


def _indices(points, lower, upper, dims):
    """histogramdd's bins by searchsorted on its own edges; -1 outside."""
    index = np.zeros(points.shape, int)
    for axis in range(3):
        edges = np.linspace(lower[axis], upper[axis], dims[axis] + 1)
        k = np.searchsorted(edges, points[:, axis], side="right") - 1
        k[points[:, axis] == upper[axis]] = dims[axis] - 1
        outside = (points[:, axis] < lower[axis]) | (points[:, axis] > upper[axis])
        k[outside] = -1
        index[:, axis] = k
    index[np.any(index < 0, -1)] = -1
    return index


@pytest.mark.parametrize("dtype", ["float64", "float32"])
def test_counts_and_means_with_bounds(dtype, backend):
    dims = (4, 5, 6)
    grid, out_dims, res, lower = vis.coords_to_voxel_grid(
        native(POINTS.astype(dtype), backend),
        dims,
        coord_bounds=BOUNDS,
        features=native(FEATS.astype(dtype), backend),
    )
    grid = numpy_of(grid)
    assert grid.shape == (2, 4, 5, 6, 3 + 2 + 1) and grid.dtype == np.dtype(dtype)
    lo, hi = np.array(BOUNDS[:3]), np.array(BOUNDS[3:])
    for b in range(2):
        hist, _ = np.histogramdd(POINTS[b].astype(dtype), bins=dims, range=list(zip(lo, hi)))
        np.testing.assert_array_equal(grid[b, ..., -1], hist)
        expected = _means(POINTS[b], FEATS[b], _indices(POINTS[b], lo, hi, dims), dims)
        tol = 1e-12 if dtype == "float64" else 1e-5
        np.testing.assert_allclose(grid[b], expected, atol=tol)
    check(out_dims, np.broadcast_to(np.array(dims, float), (2, 3)), backend, dtype=dtype)
    check(res, np.broadcast_to((hi - lo) / dims, (2, 3)), backend, dtype=dtype, atol=1e-6)
    check(lower, np.broadcast_to(lo, (2, 3)), backend, dtype=dtype)


def test_bounds_from_the_data_and_homogeneous_points(backend):
    dims = (3, 3, 2)
    homo = np.concatenate([POINTS, np.ones_like(POINTS[..., :1])], -1)
    grid, _, _, lower = vis.coords_to_voxel_grid(native(homo, backend), dims)
    for b in range(2):
        ranges = list(zip(POINTS[b].min(0), POINTS[b].max(0)))
        hist, _ = np.histogramdd(POINTS[b], bins=dims, range=ranges)
        np.testing.assert_array_equal(numpy_of(grid)[b, ..., -1], hist)
    check(lower, POINTS.min(1), backend)


def test_resolution_mode(backend):
    res = (0.3, 0.25, 0.5)
    grid, dims, out_res, lower = vis.coords_to_voxel_grid(native(POINTS, backend), res, mode="RES")
    grid, dims = numpy_of(grid), numpy_of(dims)
    extent = POINTS.max(1) - POINTS.min(1)
    np.testing.assert_array_equal(dims, np.ceil(extent / res))
    check(out_res, extent / dims, backend)
    assert grid.shape[1:4] == tuple(dims.max(0).astype(int))
    for b in range(2):
        d = dims[b].astype(int)
        hist, _ = np.histogramdd(
            POINTS[b], bins=d, range=list(zip(POINTS[b].min(0), POINTS[b].max(0)))
        )
        np.testing.assert_array_equal(grid[b, : d[0], : d[1], : d[2], -1], hist)


def test_batched_bounds_and_unbatched_points(backend):
    bounds = np.array([[0, 0, 0, 1, 1, 1.0], [-0.5, -0.5, -0.5, 1.5, 1.5, 1.5]])
    grid, _, _, _ = vis.coords_to_voxel_grid(
        native(POINTS, backend), (2, 2, 2), coord_bounds=native(bounds, backend)
    )
    for b in range(2):
        hist, _ = np.histogramdd(
            POINTS[b], bins=(2, 2, 2), range=list(zip(bounds[b, :3], bounds[b, 3:]))
        )
        np.testing.assert_array_equal(numpy_of(grid)[b, ..., -1], hist)
    grid, _, _, _ = vis.coords_to_voxel_grid(
        native(POINTS[0], backend), (2, 3, 4), coord_bounds=BOUNDS
    )
    hist, _ = np.histogramdd(POINTS[0], bins=(2, 3, 4), range=list(zip(BOUNDS[:3], BOUNDS[3:])))
    np.testing.assert_array_equal(numpy_of(grid)[..., -1], hist)


del _data  # no test draws from a generator shared by the module
