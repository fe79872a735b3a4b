"""Geometry functions (single view, omnidirectional, projective, two view) against independent
numpy references, on every backend, in float64 and float32, plus round trips and batching."""

from __future__ import annotations

import numpy as np
import pytest

import ivy_vision as vis
from tests.conftest import capable
from tests.helpers import TOLERANCES, check, native, numpy_of
from tests.ivy_vision import _cases as K
from tests.ivy_vision import _reference as R
from tests.ivy_vision._cases import CASES


def _native_args(args, backend, dtype):
    return [R.to_backend(a, backend, dtype) for a in args]


@pytest.mark.parametrize("dtype", ["float64", "float32"])
@pytest.mark.parametrize("name", sorted(CASES))
def test_against_reference(name, dtype, backend):
    args, kwargs, reference = CASES[name]
    expected = reference(*args)
    out = getattr(vis, name)(*_native_args(args, backend, dtype), **kwargs)
    outs = out if isinstance(out, tuple) else (out,)
    wants = expected if isinstance(expected, tuple) else (expected,)
    assert len(outs) == len(wants)
    scale = K.scale_of(expected)
    for got, want in zip(outs, wants):
        if dtype == "float32":
            tol = TOLERANCES["float32"]
            check(got, want, backend, dtype=dtype, rtol=5 * tol["rtol"], atol=2e-5 * max(scale, 1))
        else:
            check(got, want, backend, dtype=dtype, atol=1e-12 * max(scale, 1))


def test_uniform_pixel_coords(backend):
    out = vis.create_uniform_pixel_coords_image((3, 4), (2,), f=backend)
    check(out, np.broadcast_to(R.pixel_grid(3, 4), (2, 3, 4, 3)), backend, dtype="float32")
    dtype = "float64" if capable(backend, "float64") else "float32"
    out = vis.create_uniform_pixel_coords_image(
        (3, 4), normalized=True, homogeneous=False, dtype=dtype, f=backend
    )
    check(out, R.pixel_grid(3, 4)[..., :2] / [4.0, 3.0], backend, dtype=dtype)


def test_ray_vectors_of_every_pixel(backend):
    out = vis.pixel_coords_to_world_ray_vectors(native(K.FULL_INV, backend), image_dims=(K.H, K.W))
    expected = R.apply(K.FULL_INV[:, None, None, :, :3], K.GRID[None])
    check(out, expected / np.linalg.norm(expected, axis=-1, keepdims=True), backend)
    # with the camera centre given, and depth-scaled coordinates: the same unit vectors
    centers = native(K.CENTER, backend)
    out = vis.pixel_coords_to_world_ray_vectors(
        native(K.FULL_INV, backend), native(K.DS, backend), centers
    )
    check(out, expected / np.linalg.norm(expected, axis=-1, keepdims=True), backend)


def test_round_trips(backend):
    """unproject(project(p)) == p for points, depth, sphere and angular coordinates."""
    world = native(K.WORLD, backend)
    ds = vis.world_to_ds_pixel_coords(world, native(K.FULL, backend))
    back = vis.ds_pixel_to_world_coords(ds, native(K.FULL_INV, backend))
    check(back[..., :3], K.WORLD, backend)
    cam = vis.world_to_cam_coords(world, native(K.EXT, backend))
    check(vis.cam_to_world_coords(cam, native(K.EXT_INV, backend))[..., :3], K.WORLD, backend)
    depth = native(K.DEPTH, backend)
    radial = vis.depth_to_radial_depth(depth, native(K.K_INV, backend))
    check(vis.radial_depth_to_depth(radial, native(K.K_INV, backend)), K.DEPTH, backend)
    inv = vis.invert_calib_mat(native(K.K_SKEW, backend))
    check(numpy_of(inv) @ K.K_SKEW, np.broadcast_to(np.eye(3), (2, 3, 3)), "numpy")
    sphere = vis.cam_to_sphere_coords(native(K.CAM, backend))
    check(vis.sphere_to_cam_coords(sphere)[..., :3], K.CAM, backend)
    angular = vis.sphere_to_angular_pixel_coords(sphere, K.PPD)
    check(vis.angular_pixel_to_sphere_coords(angular, K.PPD), numpy_of(sphere), backend)
    fl = vis.persp_angles_to_focal_lengths(native(K.ANGLES, backend), (24, 32))
    check(vis.focal_lengths_to_persp_angles(fl, (24, 32)), K.ANGLES, backend)
    ext = vis.rot_mat_and_cam_center_to_ext_mat(native(K.ROT, backend), native(K.CENTER, backend))
    rot, center = vis.ext_mat_to_rot_mat_and_cam_center(ext)
    check(center, K.CENTER, backend)


def test_unbatched_matrix_broadcasts_over_batched_images(backend):
    """A matrix without batch dimensions applies to every image of a batch."""
    out = vis.depth_to_cam_coords(native(K.DEPTH, backend), native(K.K_INV[0], backend))
    check(out, R.homogeneous(R.apply(K.K_INV[0], K.DS)), backend)
    out = vis.ds_pixel_to_ds_pixel_coords(native(K.DS, backend), native(K.FULL12[1], backend))
    check(out, R.apply(K.FULL12[1], K.DS), backend)


def test_pseudo_inverse_and_dlt(backend):
    p = native(K.FULL, backend)
    pinv = numpy_of(vis.projection_matrix_pseudo_inverse(p))
    np.testing.assert_allclose(K.FULL @ pinv, np.broadcast_to(np.eye(3), (2, 3, 3)), atol=1e-12)
    # DLT: the null vector of a rank-3 system, up to sign
    a = np.random.default_rng(5).standard_normal((3, 4, 4))
    x_true = np.random.default_rng(6).standard_normal((3, 4))
    a = a - (a @ x_true[..., None]) * x_true[:, None, :] / np.sum(x_true**2, -1)[:, None, None]
    x = numpy_of(vis.solve_homogeneous_dlt(native(a, backend)))
    x_true = x_true / np.linalg.norm(x_true, axis=-1, keepdims=True)
    np.testing.assert_allclose(np.abs(np.sum(x * x_true, -1)), 1.0, atol=1e-12)


def test_fundamental_matrix(backend):
    """x2^T F x1 = 0 for corresponding pixels, and F = K2^-T E K1^-1 up to scale."""
    f = numpy_of(vis.get_fundamental_matrix(native(K.FULL, backend), native(K.FULL2, backend)))
    x1 = R.apply(K.FULL, K.WORLD)
    x2 = R.apply(K.FULL2, K.WORLD)
    residual = np.einsum("bni,bij,bnj->bn", x2, f, x1)
    scale = (
        np.linalg.norm(f, axis=(-2, -1))[:, None]
        * np.linalg.norm(x1, axis=-1)
        * np.linalg.norm(x2, axis=-1)
    )
    np.testing.assert_allclose(residual / scale, 0.0, atol=1e-13)
    ess = K._skew(K.EXT12[:, :, 3]) @ K.EXT12[:, :, :3]
    expected = np.swapaxes(np.linalg.inv(K.K), -1, -2) @ ess @ np.linalg.inv(K.K)
    normed = f / np.linalg.norm(f, axis=(-2, -1), keepdims=True)
    expected = expected / np.linalg.norm(expected, axis=(-2, -1), keepdims=True)
    sign = np.sign(np.sum(normed * expected, axis=(-2, -1)))[:, None, None]
    np.testing.assert_allclose(normed * sign, expected, atol=1e-10)
    # with the camera centre and pseudo-inverse given
    f2 = vis.get_fundamental_matrix(
        native(K.FULL, backend),
        native(K.FULL2, backend),
        native(K.CENTER, backend),
        native(np.linalg.pinv(K.FULL), backend),
    )
    check(f2, f, backend, rtol=1e-9)


def test_closest_mutual_points(backend):
    """Against the 2x2 normal equations of min |c1 + t1 d1 - c2 - t2 d2|."""
    rng = np.random.default_rng(11)
    centers = rng.standard_normal((2, 2, 3))
    rays = rng.standard_normal((2, 2, 3, 4, 3))
    out = numpy_of(
        vis.closest_mutual_points_along_two_skew_rays(
            native(centers, backend), native(rays, backend)
        )
    )
    for b in range(2):
        for i, j in np.ndindex(3, 4):
            d1, d2 = rays[b, 0, i, j], rays[b, 1, i, j]
            a = np.array([[d1 @ d1, -d1 @ d2], [d1 @ d2, -d2 @ d2]])
            rhs = np.array(
                [(centers[b, 1] - centers[b, 0]) @ d1, (centers[b, 1] - centers[b, 0]) @ d2]
            )
            t1, t2 = np.linalg.solve(a, rhs)
            np.testing.assert_allclose(out[b, 0, i, j, :3], centers[b, 0] + t1 * d1, atol=1e-10)
            np.testing.assert_allclose(out[b, 1, i, j, :3], centers[b, 1] + t2 * d2, atol=1e-10)
    assert np.all(out[..., 3] == 1)


@pytest.mark.parametrize("method", ["cmp", "dlt"])
def test_triangulate_depth(method, backend):
    """Pixels of world points seen by two cameras triangulate back to their depth."""
    ds1 = R.apply(K.FULL, K.WORLD)
    ds2 = R.apply(K.FULL2, K.WORLD)
    pixels = np.stack([ds1 / ds1[..., 2:3], ds2 / ds2[..., 2:3]], axis=1)
    full_mats = np.stack([K.FULL, K.FULL2], axis=1)
    out = vis.triangulate_depth(native(pixels, backend), native(full_mats, backend), method=method)
    check(out, ds1, backend, rtol=1e-9, atol=1e-9)
