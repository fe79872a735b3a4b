"""Optical flow against numpy references written here: flow from depth and pose, epipolar
projection, cost volumes, object motion, and velocities."""

from __future__ import annotations

import numpy as np

import ivy_vision as vis
from tests.helpers import check, native, numpy_of
from tests.ivy_vision import _cases as K
from tests.ivy_vision import _reference as R


def _pixels(ds):
    return ds[..., :2] / ds[..., 2:3]


def test_flow_from_depth_and_cam_mats(backend):
    expected = _pixels(R.apply(K.FULL12, K.DS)) - _pixels(K.DS)
    out = vis.flow_from_depth_and_cam_mats(native(K.DS, backend), native(K.FULL12, backend))
    check(out, expected, backend, atol=1e-10)


def test_depth_from_flow_and_cam_mats(backend):
    """Depth triangulated from exact flow is the depth (both methods, given inverses too)."""
    flow = _pixels(R.apply(K.FULL12, K.DS)) - _pixels(K.DS)
    full_mats = np.stack([K.FULL, K.FULL2], 1)
    for method in ("cmp", "dlt"):
        out = vis.depth_from_flow_and_cam_mats(
            native(flow, backend), native(full_mats, backend), triangulation_method=method
        )
        check(out, K.DEPTH, backend, rtol=1e-8, atol=1e-8)
    inverses = np.linalg.inv(K.homo44(full_mats))[..., :3, :]
    out = vis.depth_from_flow_and_cam_mats(
        native(flow, backend), native(full_mats, backend), native(inverses, backend)
    )
    check(out, K.DEPTH, backend, rtol=1e-8, atol=1e-8)


def test_project_flow_to_epipolar_line(backend):
    """The projected flow ends on the epipolar line, at its point nearest the flow's end, and
    exact flow does not move."""
    f = numpy_of(vis.get_fundamental_matrix(native(K.FULL, "numpy"), native(K.FULL2, "numpy")))
    exact = _pixels(R.apply(K.FULL12, K.DS)) - _pixels(K.DS)
    noisy = exact + np.random.default_rng(3).normal(0, 2.0, exact.shape)
    out = numpy_of(vis.project_flow_to_epipolar_line(native(noisy, backend), native(f, backend)))
    grid = K.GRID[None]
    lines = np.einsum("bij,bhwj->bhwi", f, np.broadcast_to(grid, (2, K.H, K.W, 3)))
    end = grid[..., :2] + out
    residual = np.sum(lines[..., :2] * end, -1) + lines[..., 2]
    np.testing.assert_allclose(residual / np.linalg.norm(lines[..., :2], axis=-1), 0, atol=1e-9)
    # the move is perpendicular to the line: along its normal (a, b)
    move = out - noisy
    cross = move[..., 0] * lines[..., 1] - move[..., 1] * lines[..., 0]
    np.testing.assert_allclose(cross / np.linalg.norm(lines[..., :2], axis=-1), 0, atol=1e-9)
    check(
        vis.project_flow_to_epipolar_line(native(exact, backend), native(f, backend)),
        exact,
        backend,
        atol=1e-8,
    )


def test_pixel_cost_volume(backend):
    rng = np.random.default_rng(4)
    a, b = rng.standard_normal((2, 2, 5, 6, 3))
    r = 2
    padded = np.pad(b, ((0, 0), (r, r), (r, r), (0, 0)))
    expected = np.zeros((2, 5, 6, (2 * r + 1) ** 2))
    for k, (dy, dx) in enumerate(np.ndindex(2 * r + 1, 2 * r + 1)):
        expected[..., k] = np.mean(a * padded[:, dy : dy + 5, dx : dx + 6], -1)
    check(vis.pixel_cost_volume(native(a, backend), native(b, backend), r), expected, backend)


def _object_scene():
    rng = np.random.default_rng(9)
    cam = np.concatenate([rng.uniform(-1, 1, (2, 3, 4, 2)), rng.uniform(2, 4, (2, 3, 4, 1))], -1)
    ids = rng.integers(0, 3, (2, 3, 4, 1)).astype(np.float64)  # 0: static, 1 and 2: moving
    obj_ids = np.array([[[1.0], [2.0]]] * 2)
    trans = np.stack(
        [
            np.stack(
                [
                    np.concatenate([R.random_rotation(rng), rng.normal(0, 0.3, (3, 1))], -1)
                    for _ in range(2)
                ]
            )
            for _ in range(2)
        ]
    )
    cam12 = np.concatenate(
        [
            np.stack([R.random_rotation(rng) for _ in range(2)]) * 0 + np.eye(3),
            rng.normal(0, 0.2, (2, 3, 1)),
        ],
        -1,
    )
    return cam, ids, obj_ids, trans, cam12


def _moved(cam, ids, trans, cam12):
    out = np.zeros_like(cam)
    for b, i, j in np.ndindex(*cam.shape[:3]):
        k = int(ids[b, i, j, 0])
        m = cam12[b] if k == 0 else trans[b, k - 1]
        out[b, i, j] = m[:, :3] @ cam[b, i, j] + m[:, 3]
    return out


def test_object_motion_projection_and_flow(backend):
    cam, ids, obj_ids, trans, cam12 = _object_scene()
    moved = _moved(cam, ids, trans, cam12)
    args = [native(a, backend) for a in (cam, ids, obj_ids, trans, cam12)]
    coords, mask = vis.project_cam_coords_with_object_transformations(*args)
    check(coords, R.homogeneous(moved), backend, atol=1e-12)
    np.testing.assert_array_equal(numpy_of(mask), ids > 0)
    calib = native(K.K, backend)
    flow = vis.flow_from_cam_coords_id_image_and_object_trans(*args[:4], calib, args[4])
    expected = _pixels(R.apply(K.K, moved)) - _pixels(R.apply(K.K, cam))
    check(flow, expected, backend, atol=1e-9)


def test_velocities(backend):
    cam, ids, obj_ids, trans, _ = _object_scene()
    dt = np.array([[0.5], [0.25]])
    previous = _moved(cam, ids, trans, np.broadcast_to(np.eye(3, 4), (2, 3, 4)))
    expected = np.where(ids > 0, (cam - previous) / dt[:, None, None], 0.0)
    out = vis.velocity_from_cam_coords_id_image_and_object_trans(
        *[native(a, backend) for a in (cam, ids, obj_ids, trans, dt)]
    )
    check(out, expected, backend, atol=1e-12)
    # from flow: frame t-1 is frame t moved by a camera motion; zero flow, identity motion
    shift = np.concatenate([np.broadcast_to(np.eye(3), (2, 3, 3)), np.full((2, 3, 1), 0.1)], -1)
    cam_tm1 = cam - 0.1
    velocity, valid = vis.velocity_from_flow_cam_coords_and_cam_mats(
        native(np.zeros((2, 3, 4, 2)), backend),
        native(cam, backend),
        native(cam_tm1, backend),
        native(shift, backend),
        native(dt, backend),
    )
    check(velocity, np.zeros_like(cam), backend, atol=1e-12)
    assert np.all(numpy_of(valid))
