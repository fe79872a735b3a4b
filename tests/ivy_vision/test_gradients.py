"""Gradients with each framework's own autodiff (torch, jax, tensorflow) equal central finite
differences in float64: with respect to depth, pose and intrinsics through projection,
reprojection, flow and warping, and through the rendering functions."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_mechanics as mech
import ivy_vision as vis
from tests.helpers import check_gradients
from tests.ivy_vision import _cases as K

_data = np.random.default_rng(31)  # constants only; tests: the rng fixture
H, W = 4, 5
DEPTH = _data.uniform(2.0, 3.0, (2, H, W, 1))
POSE = np.concatenate([_data.normal(0, 0.05, (2, 3)), _data.normal(0, 0.05, (2, 3))], -1)
INTRINSICS = np.array([[6.0, 6.5, 2.1, 1.4], [5.5, 5.0, 1.9, 1.6]])
IMAGE = _data.standard_normal((2, H, W, 2))
EXT1 = np.broadcast_to(np.eye(3, 4), (2, 3, 4))


def _camera(xp, pose, intrinsics):
    calib = vis.focal_lengths_and_pp_offsets_to_calib_mat(
        intrinsics[..., 0:2], intrinsics[..., 2:4]
    )
    ext = mech.rot_vec_pose_to_mat_pose(pose, f=xp)[..., 0:3, :]
    return calib, ext


def _reprojection(depth, pose, intrinsics):
    """Depth of camera 1 -> pixels of camera 2 (moved by ``pose``), one calibration."""
    xp = ivy.get_framework(depth)
    calib, ext2 = _camera(xp, pose, intrinsics)
    cam1 = vis.depth_to_cam_coords(depth, vis.invert_calib_mat(calib))
    world = vis.cam_to_world_coords(cam1, xp.asarray(EXT1, dtype=xp.dtype(depth)))
    return vis.world_to_ds_pixel_coords(world, vis.calib_and_ext_to_full_mat(calib, ext2))


def _cam1to2(xp, pose, intrinsics):
    calib, ext2 = _camera(xp, pose, intrinsics)
    full1 = vis.calib_and_ext_to_full_mat(calib, xp.asarray(EXT1, dtype=xp.dtype(pose)))
    return vis.full_mats_to_cam1to2_full_mat(full1, vis.calib_and_ext_to_full_mat(calib, ext2))


def _flow(depth, pose, intrinsics):
    xp = ivy.get_framework(depth)
    ds = vis.depth_to_ds_pixel_coords(depth)
    return vis.flow_from_depth_and_cam_mats(ds, _cam1to2(xp, pose, intrinsics))


def _inverse_warp(image, depth, pose, intrinsics):
    xp = ivy.get_framework(depth)
    return vis.inverse_warp(image, depth, _cam1to2(xp, pose, intrinsics), padding="zeros")


def _forward_warp(image, depth, pose, intrinsics):
    xp = ivy.get_framework(depth)
    out, out_depth, _ = vis.forward_warp(image, depth, _cam1to2(xp, pose, intrinsics), with_db=True)
    return xp.concat([out, out_depth], axis=-1)


def _triangulation(pixels2, method):
    def fn(p2):
        xp = ivy.get_framework(p2)
        p1 = xp.asarray(K.R.pixel_grid(H, W)[None].repeat(2, 0), dtype=xp.dtype(p2))
        pixels = xp.stack([p1, p2], axis=1)
        full = xp.asarray(np.stack([K.FULL, K.FULL2], 1), dtype=xp.dtype(p2))
        return vis.triangulate_depth(pixels, full, method=method)

    return fn


PIXELS2 = K.R.apply(K.FULL12, K.R.pixel_grid(H, W) * DEPTH)
PIXELS2 = PIXELS2 / PIXELS2[..., 2:3]

CASES = {
    "reprojection (depth, pose, intrinsics)": (_reprojection, (DEPTH, POSE, INTRINSICS)),
    "flow (depth, pose, intrinsics)": (_flow, (DEPTH, POSE, INTRINSICS)),
    "inverse_warp (image, depth, pose, intrinsics)": (
        _inverse_warp,
        (IMAGE, DEPTH, POSE, INTRINSICS),
    ),
    "forward_warp (image, depth, pose, intrinsics)": (
        _forward_warp,
        (IMAGE, DEPTH, POSE * 0.2, INTRINSICS),
    ),
    "radial depth": (lambda d, k: vis.depth_to_radial_depth(d, k), (DEPTH, K.K_INV)),
    "sphere coords": (lambda ds, k: vis.ds_pixel_to_sphere_coords(ds, k), (K.DS, K.K_INV)),
    "angular pixels": (lambda s: vis.sphere_to_angular_pixel_coords(s, 2.0), (K.SPHERE,)),
    "ray vectors": (
        lambda p, px: vis.pixel_coords_to_world_ray_vectors(p, px),
        (K.FULL_INV, K.PIXELS),
    ),
    "sample_image border": (
        lambda im, c: vis.sample_image(im, c),
        (IMAGE, _data.uniform(-1, 5.5, (2, 9, 2))),
    ),
    "sample_image zeros": (
        lambda im, c: vis.sample_image(im, c, padding="zeros"),
        (IMAGE, _data.uniform(-1, 5.5, (2, 9, 2))),
    ),
    "triangulate cmp": (_triangulation(PIXELS2, "cmp"), (PIXELS2,)),
    "triangulate dlt": (_triangulation(PIXELS2, "dlt"), (PIXELS2,)),
    "fundamental matrix": (lambda a, b: vis.get_fundamental_matrix(a, b), (K.FULL, K.FULL2)),
    "essential matrix": (lambda a, b: vis.get_essential_matrix(a, b), (K.EXT, K.EXT2)),
    "quantize_to_image": (
        lambda c, ft: vis.quantize_to_image(c, (4, 5), ft, None, False, 1e-2, 1e-2)[0],
        (_data.uniform(0, 4, (2, 12, 2)), _data.uniform(1, 2, (2, 12, 2))),
    ),
    "quantize_to_image depth buffer": (
        lambda c, ft: vis.quantize_to_image(c, (4, 5), ft, None, True)[0],
        (_data.uniform(0, 4, (2, 12, 2)), _data.uniform(1, 2, (2, 12, 2))),
    ),
    "coords_to_voxel_grid": (
        lambda p, ft: vis.coords_to_voxel_grid(p, (2, 3, 2), "DIMS", (0, 0, 0, 1, 1, 1), ft)[0],
        (_data.uniform(0.05, 0.95, (2, 30, 3)), _data.standard_normal((2, 30, 2))),
    ),
    "rasterize_triangles": (
        lambda t: xp_concat(vis.rasterize_triangles(t, (6, 7))[0::2]),
        (
            np.concatenate(
                [_data.uniform(0, 6, (1, 3, 3, 2)), _data.uniform(1, 3, (1, 3, 3, 1))], -1
            ),
        ),
    ),
    "sphere sdf": (
        lambda c, r, q: vis.sphere_signed_distances(c, r, q),
        (
            _data.standard_normal((2, 3, 3)),
            _data.uniform(0.2, 1, (2, 3, 1)),
            _data.standard_normal((2, 6, 3)),
        ),
    ),
    "cuboid sdf": (
        lambda e, d, q: vis.cuboid_signed_distances(e, d, q),
        (
            np.concatenate([K.ROT[:, None], _data.standard_normal((2, 1, 3, 1))], -1),
            _data.uniform(0.5, 1, (2, 1, 3)),
            _data.standard_normal((2, 6, 3)) * 2,
        ),
    ),
    "termination probabilities": (
        lambda s, d, ft: vis.render_rays_via_termination_probabilities(
            vis.ray_termination_probabilities(s, d), ft
        ),
        (
            _data.uniform(0, 2, (3, 8)),
            _data.uniform(0.1, 0.3, (3, 8)),
            _data.standard_normal((3, 8, 2)),
        ),
    ),
    "variance smoothing": (
        lambda m, v: xp_concat(vis.smooth_image_from_var_image(m, v, 3, 0.5)),
        (IMAGE, _data.uniform(0.5, 2, IMAGE.shape)),
    ),
    "weighted smoothing": (
        lambda m, w: xp_concat(vis.weighted_image_smooth(m, w, 2)),
        (IMAGE, _data.uniform(0.5, 2, IMAGE.shape)),
    ),
}


def xp_concat(arrays):
    arrays = list(arrays)
    xp = ivy.get_framework(arrays[0])
    return xp.concat([xp.astype(a, xp.dtype(arrays[0])) for a in arrays], axis=-1)


@pytest.mark.parametrize("name", sorted(CASES))
def test_gradients_equal_finite_differences(name, diff_backend):
    fn, arrays = CASES[name]
    check_gradients(diff_backend, fn, arrays, n_directions=2, rtol=1e-6)


del _data  # no test draws from a generator shared by the module
