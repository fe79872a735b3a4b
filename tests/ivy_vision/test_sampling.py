"""Sampling and warping: bilinear and nearest sampling equal scipy's ``map_coordinates`` and
torch's ``grid_sample`` (1e-12 in float64); identity warps return the image; inverse and
forward warping between the MuJoCo cameras equal pixel-by-pixel references."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import ivy_vision as vis
from tests.helpers import check, native, numpy_of
from tests.ivy_vision import _reference as R
from tests.ivy_vision._scene import cameras, texture

_data = np.random.default_rng(7)  # constants only; tests: the rng fixture
IMAGE = _data.standard_normal((2, 5, 7, 3))
# points inside, on the border, half a pixel out and far out (never exactly on .5 for nearest)
COORDS = np.concatenate(
    [
        _data.uniform(-3, 10, (2, 60, 2)),
        np.array([[[0.0, 0.0], [6.0, 4.0], [-0.4, 2.2], [6.3, -0.7]]] * 2),
    ],
    1,
)


@pytest.mark.parametrize("dtype", ["float64", "float32"])
@pytest.mark.parametrize("method", ["bilinear", "nearest"])
@pytest.mark.parametrize("padding", ["border", "zeros"])
def test_sample_image_equals_scipy(padding, method, dtype, backend):
    expected = R.sample(IMAGE, COORDS, method, padding)
    out = vis.sample_image(
        native(IMAGE.astype(dtype), backend),
        native(COORDS.astype(dtype), backend),
        method=method,
        padding=padding,
    )
    check(out, expected, backend, dtype=dtype, **({"atol": 1e-5} if dtype == "float32" else {}))


@pytest.mark.parametrize("padding", ["border", "zeros"])
def test_sample_image_equals_torch_grid_sample(padding, backend):
    torch = pytest.importorskip("torch")
    image = torch.from_numpy(IMAGE).permute(0, 3, 1, 2)
    h, w = IMAGE.shape[1:3]
    grid = COORDS / np.array([w - 1, h - 1]) * 2 - 1
    expected = (
        torch.nn.functional.grid_sample(
            image,
            torch.from_numpy(grid)[:, None],
            mode="bilinear",
            padding_mode=padding,
            align_corners=True,
        )[:, :, 0]
        .permute(0, 2, 1)
        .numpy()
    )
    out = vis.sample_image(native(IMAGE, backend), native(COORDS, backend), padding=padding)
    check(out, expected, backend)


def test_sample_image_batch_and_sample_shapes(backend):
    """Any sample shape after the batch; an unbatched image sampled at unbatched points; an
    integer image is sampled in the coordinates' dtype."""
    coords = COORDS[:, :60].reshape(2, 3, 4, 5, 2)
    out = vis.sample_image(native(IMAGE, backend), native(coords, backend))
    check(out, R.sample(IMAGE, coords), backend)
    out = vis.bilinearly_interpolate_image(native(IMAGE[0], backend), native(COORDS[0], backend))
    check(out, R.sample(IMAGE[:1], COORDS[:1])[0], backend)
    ints = (IMAGE * 10).astype(np.int32)
    out = vis.sample_image(native(ints, backend), native(COORDS.astype(np.float32), backend))
    check(out, R.sample(ints.astype(np.float64), COORDS), backend, dtype="float32", atol=1e-4)


def test_identity_warps_return_the_image(rng, backend):
    image = native(IMAGE, backend)
    depth = native(rng.uniform(1, 2, (2, 5, 7, 1)), backend)
    identity = native(np.eye(3, 4), backend)
    for padding in ("zeros", "border"):
        for method in ("bilinear", "nearest"):
            out = vis.inverse_warp(image, depth, identity, method=method, padding=padding)
            check(out, IMAGE, backend)
    warped, valid = vis.inverse_warp(image, depth, identity, with_validity=True)
    assert np.all(numpy_of(valid))
    out, out_depth, valid = vis.forward_warp(image, depth, identity)
    check(out, IMAGE, backend)
    check(out_depth, numpy_of(depth), backend)
    assert np.all(numpy_of(valid))


@functools.lru_cache(maxsize=1)
def _views():
    cam1, cam2 = cameras((12, 16))
    depth1, depth2 = cam1.depth_image(), cam2.depth_image()
    depth1 = np.where(depth1 > 0, depth1, 0.0)
    depth2 = np.where(depth2 > 0, depth2, 0.0)
    depth1[::5, ::3] = 0.0  # pixels without a measurement

    def colours(cam, depth):
        points = (cam.P_inv[:, :3] @ (R.pixel_grid(cam.h, cam.w) * depth)[..., None])[..., 0]
        return texture(points + cam.P_inv[:, 3])

    return cam1, cam2, depth1, depth2, colours(cam1, depth1), colours(cam2, depth2)


@pytest.mark.parametrize("padding", ["zeros", "border"])
def test_inverse_warp_between_cameras(padding, backend):
    cam1, cam2, depth1, _, _, colour2 = _views()
    full12 = (
        np.concatenate([cam2.P, [[0, 0, 0, 1.0]]])
        @ np.linalg.inv(np.concatenate([cam1.P, [[0, 0, 0, 1.0]]]))
    )[:3]
    expected = R.inverse_warp(colour2, depth1, full12, padding)
    out, valid = vis.inverse_warp(
        native(colour2, backend),
        native(depth1, backend),
        native(full12, backend),
        padding=padding,
        with_validity=True,
    )
    check(out, expected, backend)
    projected = R.apply(full12, R.pixel_grid(cam1.h, cam1.w) * depth1)
    px = projected[..., :2] / projected[..., 2:3]
    inside = np.all((px >= -0.5) & (px <= [cam2.w - 0.5, cam2.h - 0.5]), -1, keepdims=True)
    np.testing.assert_array_equal(
        numpy_of(valid), inside & (projected[..., 2:3] > 0) & (depth1 > 0)
    )
    assert 0.2 < inside.mean() < 1.0


@pytest.mark.parametrize("with_db", [True, False])
def test_forward_warp_between_cameras(with_db, backend):
    cam1, cam2, depth1, _, colour1, _ = _views()
    full12 = (
        np.concatenate([cam2.P, [[0, 0, 0, 1.0]]])
        @ np.linalg.inv(np.concatenate([cam1.P, [[0, 0, 0, 1.0]]]))
    )[:3]
    image, depth, valid = R.splat(colour1, depth1, full12, (10, 14), with_db)
    out = vis.forward_warp(
        native(colour1, backend),
        native(depth1, backend),
        native(full12, backend),
        (10, 14),
        with_db=with_db,
    )
    check(out[0], image, backend)
    check(out[1], depth, backend)
    np.testing.assert_array_equal(numpy_of(out[2]), valid)
    assert 0.2 < valid.mean()


def test_forward_warp_depth_buffer_keeps_the_nearest(backend):
    """Two source pixels landing on one target pixel: the nearer wins."""
    image = np.array([[[1.0], [2.0]]])
    depth = np.array([[[2.0], [1.0]]])
    # both pixels move to x = 0: shift the far one by -x_c ... use a matrix that drops x
    full = np.array([[0.0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]])
    out, out_depth, valid = vis.forward_warp(
        native(image, backend), native(depth, backend), native(full, backend)
    )
    check(out[..., 0], np.array([[2.0, 0.0]]), backend)
    check(out_depth[..., 0], np.array([[1.0, 0.0]]), backend)
    out, _, _ = vis.forward_warp(
        native(image, backend), native(depth, backend), native(full, backend), with_db=False
    )
    check(out[..., 0], np.array([[1.5, 0.0]]), backend)


del _data  # no test draws from a generator shared by the module
