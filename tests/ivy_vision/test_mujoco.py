"""Ground truth from MuJoCo ray casts (float64, every backend): unprojected depth pixels lie on
the analytic surfaces of the scene, and reprojected into a second camera they land where that
camera's own ray cast says, wherever they are visible."""

from __future__ import annotations

import functools

import numpy as np

import ivy_vision as vis
from tests.helpers import native, numpy_of
from tests.ivy_vision._scene import cameras, scene_sdf

SURFACE_TOL = 1e-9


@functools.lru_cache(maxsize=1)
def _views():
    cam1, cam2 = cameras()
    return cam1, cam2, cam1.depth_image(), cam2.depth_image()


def _hit(depth):
    return depth[..., 0] > 0


def test_unprojected_points_lie_on_the_scene(backend):
    cam1, cam2, depth1, depth2 = _views()
    for cam, depth in ((cam1, depth1), (cam2, depth2)):
        world = vis.depth_to_world_coords(native(depth, backend), native(cam.P_inv, backend))
        points = numpy_of(world)[..., :3][_hit(depth)]
        assert len(points) > 0.8 * depth[..., 0].size
        assert np.max(np.abs(scene_sdf(points))) < SURFACE_TOL
        # the same points through the camera frame, with a calibration made by ivy_vision
        calib = vis.focal_lengths_and_pp_offsets_to_calib_mat(
            native(cam.K[[0, 1], [0, 1]], backend), native(cam.K[:2, 2], backend)
        )
        cam_coords = vis.depth_to_cam_coords(native(depth, backend), vis.invert_calib_mat(calib))
        ext = vis.rot_mat_and_cam_center_to_ext_mat(native(cam.R, backend), native(cam.C, backend))
        inv_ext = vis.projection_matrix_inverse(ext)
        points = numpy_of(vis.cam_to_world_coords(cam_coords, inv_ext))[..., :3][_hit(depth)]
        assert np.max(np.abs(scene_sdf(points))) < SURFACE_TOL


def test_radial_depth_and_sphere_radius_match_unit_ray_casts(backend):
    cam1, _, depth1, _ = _views()
    radial_cast = cam1.depth_image(normalize=True)
    hit = _hit(depth1)
    k_inv = native(cam1.K_inv, backend)
    radial = numpy_of(vis.depth_to_radial_depth(native(depth1, backend), k_inv))
    np.testing.assert_allclose(radial[hit], radial_cast[hit], rtol=1e-12)
    ds = vis.depth_to_ds_pixel_coords(native(depth1, backend))
    np.testing.assert_allclose(
        numpy_of(vis.ds_pixel_coords_to_radial_depth(ds, k_inv))[hit], radial_cast[hit], rtol=1e-12
    )
    sphere = numpy_of(vis.ds_pixel_to_sphere_coords(ds, k_inv))
    np.testing.assert_allclose(sphere[..., 2:3][hit], radial_cast[hit], rtol=1e-12)
    # the world rays of the pixels, scaled by the radial depth, reach the surface
    rays = numpy_of(
        vis.pixel_coords_to_world_ray_vectors(
            native(cam1.P_inv, backend), image_dims=depth1.shape[:2]
        )
    )
    points = cam1.C + rays * radial_cast
    assert np.max(np.abs(scene_sdf(points[hit]))) < SURFACE_TOL


def test_reprojection_lands_where_the_second_camera_sees(backend):
    """Pixels of camera 1 moved into camera 2 (``ds_pixel_to_ds_pixel_coords`` and through the
    world): where camera 2 sees the same point, its ray cast through the reprojected pixel has
    exactly the reprojected depth."""
    cam1, cam2, depth1, _ = _views()
    hit = _hit(depth1)
    ds1 = vis.depth_to_ds_pixel_coords(native(depth1, backend))
    full12 = vis.full_mats_to_cam1to2_full_mat(native(cam1.P, backend), native(cam2.P, backend))
    ds2 = numpy_of(vis.ds_pixel_to_ds_pixel_coords(ds1, full12))[hit]
    world = vis.ds_pixel_to_world_coords(ds1, native(cam1.P_inv, backend))
    via_world = numpy_of(vis.world_to_ds_pixel_coords(world, native(cam2.P, backend)))[hit]
    np.testing.assert_allclose(ds2, via_world, rtol=1e-10, atol=1e-10)
    depth2 = ds2[:, 2]
    pixels2 = ds2[:, :2] / depth2[:, None]
    inside = (
        (depth2 > 0)
        & (pixels2[:, 0] >= -0.5)
        & (pixels2[:, 0] <= cam2.w - 0.5)
        & (pixels2[:, 1] >= -0.5)
        & (pixels2[:, 1] <= cam2.h - 0.5)
    )
    cast = cam2.cast(pixels2[inside])
    visible = cast > depth2[inside] - 1e-7  # nothing in front of the point
    assert visible.mean() > 0.3 and visible.sum() > 100
    np.testing.assert_allclose(cast[visible], depth2[inside][visible], rtol=0, atol=SURFACE_TOL)
    # the occluded ones really are hidden behind another surface
    assert np.all(cast[~visible] < depth2[inside][~visible])


def test_triangulation_recovers_ray_cast_depth(backend):
    """Flow from depth and pose, then depth from that flow: the ray-cast depth again."""
    cam1, cam2, depth1, _ = _views()
    hit = _hit(depth1)
    ds1 = vis.depth_to_ds_pixel_coords(native(depth1, backend))
    full12 = vis.full_mats_to_cam1to2_full_mat(native(cam1.P, backend), native(cam2.P, backend))
    flow = vis.flow_from_depth_and_cam_mats(ds1, full12)
    full_mats = native(np.stack([cam1.P, cam2.P]), backend)
    for method in ("cmp", "dlt"):
        depth = numpy_of(
            vis.depth_from_flow_and_cam_mats(flow, full_mats, triangulation_method=method)
        )
        np.testing.assert_allclose(depth[hit], depth1[hit], rtol=1e-8)


def test_sdfs_vanish_on_ray_cast_hits(backend):
    """ivy_vision's sphere and cuboid SDFs are zero where MuJoCo's rays hit the ball and box."""
    from tests.ivy_vision import _scene as S

    cam1, _, depth1, _ = _views()
    points = numpy_of(
        vis.depth_to_world_coords(native(depth1, backend), native(cam1.P_inv, backend))
    )[..., :3]
    points = points[_hit(depth1)]
    ball = numpy_of(
        vis.sphere_signed_distances(
            native(S.BALL[0][None], backend),
            native(np.array([[S.BALL[1]]]), backend),
            native(points, backend),
        )
    )[:, 0]
    c, s = np.cos(S.BOX_YAW), np.sin(S.BOX_YAW)
    rot = np.array([[c, s, 0], [-s, c, 0], [0, 0, 1.0]])  # world to box
    ext = np.concatenate([rot, -rot @ S.BOX[0][:, None]], -1)[None]
    box = numpy_of(
        vis.cuboid_signed_distances(
            native(ext, backend), native(2 * S.BOX[1][None], backend), native(points, backend)
        )
    )[:, 0]
    on_ball = np.abs(ball) < 1e-6
    on_box = np.abs(box) < 1e-6
    assert on_ball.sum() > 20 and on_box.sum() > 20
    assert np.max(np.abs(ball[on_ball])) < SURFACE_TOL
    assert np.max(np.abs(box[on_box])) < SURFACE_TOL
    # elsewhere they agree with the analytic scene's distance where the primitive is nearest
    np.testing.assert_allclose(
        np.minimum(ball, 1e9), np.linalg.norm(points - S.BALL[0], axis=-1) - S.BALL[1], atol=1e-12
    )
