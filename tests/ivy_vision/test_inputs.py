"""What users pass behaves the same on every backend: integer images and depths, and float32
arrays next to float64 ones, promote by ivy's rule (integers compute in float32; float32 with
float64 is float64) where tensorflow raised ``InvalidArgumentError``; and the gradient of
``inverse_warp`` with respect to depth is the same on every backend where the projections land
on whole pixels (jax's clip halved it there)."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_vision as vis
from tests.helpers import assert_close, native, numpy_of

K = np.array([[40.0, 0.0, 15.5], [0.0, 40.0, 11.5], [0.0, 0.0, 1.0]])
SHIFT = 0.1  # camera 2 is 10 cm right of camera 1: at depth 2, 2 pixels of disparity


def _tgt_to_src(depth_shift: float = SHIFT) -> np.ndarray:
    """``P_src P_tgt^-1`` for two cameras ``K`` apart by ``depth_shift`` along x."""
    ext_src = np.eye(3, 4)
    ext_src[0, 3] = -depth_shift
    p_tgt = np.vstack([K @ np.eye(3, 4), [0.0, 0.0, 0.0, 1.0]])
    return K @ ext_src @ np.linalg.inv(p_tgt)


def _image(dtype=np.float64, seed=0) -> np.ndarray:
    return np.random.default_rng(seed).random((6, 8, 3)).astype(dtype)


def _reference_warp(image: np.ndarray, disparity: int) -> np.ndarray:
    """Independent answer for whole-pixel disparity: target column u reads source column
    ``u - disparity``; outside the source image, 0 (``padding='zeros'``)."""
    out = np.zeros_like(image, dtype=np.float64)
    out[:, disparity:] = image[:, : image.shape[1] - disparity]
    return out


def test_float32_image_and_float64_depth_promote_on_every_backend(backend):
    image = _image(np.float32)
    depth = np.full((6, 8, 1), 2.0)  # float64
    out = vis.inverse_warp(native(image, backend), native(depth, backend),
                           native(_tgt_to_src(), backend))  # fmt: skip
    assert numpy_of(out).dtype == np.float64
    assert_close(out, _reference_warp(image.astype(np.float64), 2), "float64")


def test_integer_depth_and_integer_image_compute_in_float32(backend):
    image = (_image() * 10).astype(np.int32)
    depth = np.full((6, 8, 1), 2, np.int64)
    out = vis.inverse_warp(native(image, backend), native(depth, backend),
                           native(_tgt_to_src().astype(np.float32), backend))  # fmt: skip
    assert numpy_of(out).dtype == np.float32
    assert_close(out, _reference_warp(image.astype(np.float64), 2), "float32")
    coords = vis.depth_to_ds_pixel_coords(native(depth, backend))
    assert numpy_of(coords).dtype == np.float32
    assert_close(coords[2, 3], np.array([6.0, 4.0, 2.0]), "float32")


def test_mixed_precisions_in_projections_promote(backend):
    calib = native(K.astype(np.float32), backend)
    points = native(np.array([[0.5, 0.0, 2.0], [1.0, -1.0, 4.0]]), backend)  # float64
    out = vis.cam_to_ds_pixel_coords(points, calib)
    assert numpy_of(out).dtype == np.float64
    assert_close(out, (K @ np.array([[0.5, 0.0, 2.0], [1.0, -1.0, 4.0]]).T).T, "float64")
    ids = native(np.array([[[1], [0]]]), backend)  # integer ids stay ids
    moved, mask = vis.project_cam_coords_with_object_transformations(
        native(np.ones((1, 2, 3), np.float32), backend),
        ids,
        native(np.array([[1]]), backend),
        native((np.eye(3, 4) + np.eye(3, 4, 3))[None], backend),
        native(np.eye(3, 4, dtype=np.float32), backend),
    )
    assert numpy_of(moved).dtype == np.float64
    np.testing.assert_array_equal(numpy_of(mask)[..., 0], [[True, False]])
    assert_close(moved[..., 0], np.array([[2.0, 1.0]]), "float64")


def test_inverse_warp_gradient_at_whole_pixel_projections_agrees(diff_backend):
    """At depth 2 every target pixel projects exactly onto a source pixel; the first columns
    project onto the padded border's edge (x = -1), where the clamp of the coordinates used to
    halve jax's gradient. The gradient is the one-sided one from above (the module's
    convention), checked against a finite difference from above, the same everywhere."""
    image = _image()
    full = _tgt_to_src()

    def warped_sum(depth):
        return ivy.sum(vis.inverse_warp(native(image, diff_backend), depth,
                                        native(full, diff_backend)))  # fmt: skip

    depth0 = np.full((6, 8, 1), 2.0)
    _, grad = ivy.execute_with_gradients(warped_sum, native(depth0, diff_backend))
    grad = numpy_of(grad)[..., 0]

    def numpy_warp_sum(depth):  # an independent bilinear warp with zero padding, in numpy
        u = np.arange(8.0)[None, :] - 40.0 * SHIFT / depth[..., 0]
        x0 = np.floor(u).astype(int)
        w = u - x0
        padded = np.pad(image, ((0, 0), (1, 1), (0, 0)))
        rows = np.arange(6)[:, None]
        left = padded[rows, np.clip(x0 + 1, 0, 9)]
        right = padded[rows, np.clip(x0 + 2, 0, 9)]
        return float(np.sum(left * (1 - w[..., None]) + right * w[..., None]))

    eps = 1e-7
    expected = np.zeros((6, 8))
    for r in range(6):
        for c in range(8):
            bumped = depth0.copy()
            bumped[r, c, 0] += eps  # a larger depth moves the projection right: from above
            expected[r, c] = (numpy_warp_sum(bumped) - numpy_warp_sum(depth0)) / eps
    np.testing.assert_allclose(grad, expected, rtol=1e-5, atol=1e-6)
    assert np.abs(grad[:, 1]).max() > 0.1  # the border's edge column has a gradient


def test_settings_that_would_round_to_a_plausible_answer_are_refused(backend):
    """An integer dtype for pixel coordinates (normalised, they rounded to zeros) and an image
    size that is not a whole number of pixels (int() rounded it down)."""
    from ivy.checks import InputError

    with pytest.raises(InputError, match="dtype must be a floating dtype"):
        vis.create_uniform_pixel_coords_image((2, 3), normalized=True, dtype="int32", f=backend)
    with pytest.raises(InputError, match="dtype must be a floating dtype"):
        vis.create_sampled_pixel_coords_image((4, 4), (2, 2), dtype="int64", f=backend)
    with pytest.raises(InputError, match="whole numbers of pixels"):
        vis.create_uniform_pixel_coords_image((2.5, 3), f=backend)
    assert numpy_of(vis.create_uniform_pixel_coords_image((2.0, 3), f=backend)).shape == (2, 3, 3)
