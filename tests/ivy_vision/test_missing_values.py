"""Missing values at the gathers: NaN or infinite depth and NaN sampling coordinates give an
invalid pixel (the padding value, ``False`` in the validity mask) on every backend, with the
same answer everywhere and no error; other pixels are untouched. Before the fix a NaN depth
pixel made numpy and tensorflow raise and torch read out of bounds (the NaN was cast to an
index), and jax returned NaN."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import ivy_vision as vis
from tests.helpers import check, native, numpy_of
from tests.ivy_vision import _reference as R

MISSING = (np.nan, np.inf, -np.inf)


def _image(h=5, w=6, c=2, seed=0):
    return np.random.default_rng(seed).uniform(1.0, 2.0, size=(h, w, c))


@pytest.mark.parametrize("padding", ["zeros", "border"])
@pytest.mark.parametrize("method", ["bilinear", "nearest"])
def test_nan_sampling_coordinates_give_zero(method, padding, backend):
    image = _image()
    coords = np.array(
        [[1.5, 2.25], [np.nan, 1.0], [2.0, np.nan], [np.nan, np.nan], [np.inf, 1.0], [0.2, -np.inf]]
    )
    out = vis.sample_image(
        native(image, backend), native(coords, backend), method=method, padding=padding
    )
    finite = np.all(np.isfinite(coords), -1)
    # infinite coordinates are far outside the image: scipy's answer at a far coordinate
    far = np.where(np.isposinf(coords), 1e6, np.where(np.isneginf(coords), -1e6, coords))
    expected = R.sample(image, far, method, padding)
    expected[np.any(np.isnan(coords), -1)] = 0.0
    check(out, expected, backend)
    assert finite.sum() == 1


@pytest.mark.parametrize("padding", ["zeros", "border"])
def test_missing_depth_gives_invalid_pixels(padding, backend):
    rng = np.random.default_rng(1)
    image = _image(seed=2)
    depth = rng.uniform(2.0, 3.0, size=(4, 5, 1))
    depth[0, 1], depth[2, 3], depth[3, 0] = MISSING
    full = np.concatenate([np.eye(3), [[0.1], [-0.05], [0.0]]], axis=1)  # a small shift
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # not even a warning about an invalid cast
        out, valid = vis.inverse_warp(
            native(image, backend),
            native(depth, backend),
            native(full, backend),
            padding=padding,
            with_validity=True,
        )
    missing = ~np.isfinite(depth)
    known = np.where(missing, 2.5, depth)
    expected = R.inverse_warp(image, known, full, padding)
    expected[np.broadcast_to(missing, expected.shape)] = 0.0
    check(out, expected, backend)
    valid = numpy_of(valid)
    assert not valid[missing].any() and valid[~missing].all()


def test_missing_depth_in_forward_warp_is_left_out(backend):
    image = _image(4, 5, 1, seed=3)
    depth = np.random.default_rng(4).uniform(2.0, 3.0, size=(4, 5, 1))
    depth[1, 1], depth[2, 4], depth[0, 0] = MISSING
    full = np.concatenate([np.eye(3), [[0.2], [0.0], [0.0]]], axis=1)
    out = vis.forward_warp(native(image, backend), native(depth, backend), native(full, backend))
    expected = R.splat(image, np.where(np.isfinite(depth), depth, 0.0), full, (4, 5))
    for got, want in zip(out, expected):
        check(got, want, backend)


def test_non_finite_points_are_left_out_of_voxel_grids(backend):
    points = np.random.default_rng(5).uniform(size=(9, 3))
    points[2, 0], points[5, 1], points[7] = np.nan, np.inf, -np.inf
    finite = np.all(np.isfinite(points), -1)
    grid = vis.coords_to_voxel_grid(native(points, backend), (2, 3, 2))[0]
    lower, upper = points[finite].min(0), points[finite].max(0)
    counts, _ = np.histogramdd(points[finite], bins=(2, 3, 2), range=list(zip(lower, upper)))
    check(grid[..., -1], counts, backend)
    bounded = vis.coords_to_voxel_grid(
        native(points, backend), (2, 3, 2), coord_bounds=(0,) * 3 + (1,) * 3
    )[0]
    counts, _ = np.histogramdd(points[finite], bins=(2, 3, 2), range=[(0, 1)] * 3)
    check(bounded[..., -1], counts, backend)
