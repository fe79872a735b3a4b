"""Rendering: point rendering with and without a depth buffer, triangle rasterization (exact
depth of a projected plane), smoothing, signed distances and implicit rendering, against
references written here in numpy."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_vision as vis
from tests.helpers import check, native, numpy_of
from tests.ivy_vision import _reference as R
from tests.ivy_vision._scene import cameras

# ----------------------------------------------------------------------------------------------
# quantize_to_image
# ----------------------------------------------------------------------------------------------


def _quantize_reference(
    coords, feat, dims, with_db, coords_var, feat_var, prior_feat, prior_var, low, high
):
    h, w = dims
    d = feat.shape[-1]
    mean = np.concatenate([R.pixel_grid(h, w)[..., :2], np.broadcast_to(prior_feat, (h, w, d))], -1)
    var = np.broadcast_to(prior_var, (h, w, 2 + d)).copy()
    count = np.zeros((h, w, 1))
    groups = {}
    for i in range(len(coords)):
        col, row = np.floor(coords[i] + 0.5)
        v = np.concatenate([coords_var[i], feat_var[i]])
        if not (0 <= col < w and 0 <= row < h) or np.any(v >= high):
            continue
        groups.setdefault((int(row), int(col)), []).append(
            (np.concatenate([coords[i], feat[i]]), v)
        )
    for (r, c), items in groups.items():
        m = np.array([x for x, _ in items])
        v = np.array([y for _, y in items])
        count[r, c] = len(items)
        if with_db:
            keep = m[:, 2] == m[:, 2].min()
            mean[r, c] = m[keep].mean(0)
            var[r, c] = np.maximum(v[keep].mean(0), low)
        else:
            mean[r, c] = np.sum(m / v, 0) / np.sum(1 / v, 0)
            var[r, c] = np.maximum(len(items) / np.sum(1 / v, 0), low)
    return mean, var, count


@pytest.mark.parametrize("with_db", [False, True])
def test_quantize_to_image(rng, with_db, backend):
    n, dims = 60, (4, 5)
    coords = rng.uniform(-1, 5.2, (2, n, 2))
    coords[:, :20] = np.round(coords[:, :20])  # duplicates on pixel centres
    feat = np.concatenate([rng.uniform(1, 3, (2, n, 1)), rng.standard_normal((2, n, 2))], -1)
    feat[:, 5, 0] = feat[:, 6, 0]  # a tie of depths
    coords[:, 6] = coords[:, 5]
    coords_var = rng.uniform(1e-4, 1.0, (2, n, 2))
    feat_var = rng.uniform(1e-4, 1.0, (2, n, 3))
    feat_var[:, 7, 1] = 2e12  # left out
    prior = rng.standard_normal((2, 4, 5, 3))
    out = vis.quantize_to_image(
        native(coords, backend),
        dims,
        native(feat, backend),
        native(prior, backend),
        with_db,
        native(coords_var, backend),
        native(feat_var, backend),
        5.0,
        7.0,
        (1e-3, 1e12),
    )
    for b in range(2):
        expected = _quantize_reference(
            coords[b],
            feat[b],
            dims,
            with_db,
            coords_var[b],
            feat_var[b],
            prior[b],
            np.array([5.0, 5, 7, 7, 7]),
            1e-3,
            1e12,
        )
        for got, want in zip(out, expected):
            np.testing.assert_allclose(numpy_of(got)[b], want, rtol=1e-12, atol=1e-12)


def test_quantize_to_image_defaults(rng, backend):
    """Scalar variances and no prior, points all inside: every point is counted once."""
    coords = rng.uniform(0, [3.4, 2.4], (30, 2))
    feat = rng.uniform(1, 2, (30, 2))
    mean, var, count = vis.quantize_to_image(native(coords, backend), (3, 4), native(feat, backend))
    expected, _, _ = _quantize_reference(
        coords,
        feat,
        (3, 4),
        False,
        np.full((30, 2), 1e-3),
        np.full((30, 2), 1e-3),
        0.0,
        1e12,
        1e-3,
        1e12,
    )
    check(mean, expected, backend, atol=1e-12)
    assert numpy_of(count).sum() == 30
    assert numpy_of(mean).dtype == np.float64


# ----------------------------------------------------------------------------------------------
# rasterize_triangles
# ----------------------------------------------------------------------------------------------


def _rasterize_reference(tris, dims):
    h, w = dims
    depth = np.full((h, w), np.inf)
    ids = np.full((h, w), -1)
    bary = np.zeros((h, w, 3))
    for t, tri in enumerate(tris):
        a = np.array(
            [
                [tri[1, 0] - tri[0, 0], tri[2, 0] - tri[0, 0]],
                [tri[1, 1] - tri[0, 1], tri[2, 1] - tri[0, 1]],
            ]
        )
        if abs(np.linalg.det(a)) < 1e-12 or np.any(tri[:, 2] <= 0):
            continue
        for i, j in np.ndindex(h, w):
            l1, l2 = np.linalg.solve(a, np.array([j, i]) - tri[0, :2])
            lam = np.array([1 - l1 - l2, l1, l2])
            if np.any(lam < -1e-12):
                continue
            z = 1 / np.sum(lam / tri[:, 2])
            if z < depth[i, j]:
                depth[i, j], ids[i, j], bary[i, j] = z, t, lam / tri[:, 2] * z
    return np.where(ids >= 0, depth, 0)[..., None], ids[..., None], bary


def test_rasterize_triangles_against_loops(rng, backend):
    tris = np.concatenate([rng.uniform(-2, 9, (2, 7, 3, 2)), rng.uniform(1, 4, (2, 7, 3, 1))], -1)
    tris[0, 3, 1, 2] = -1.0  # behind the camera: skipped
    tris[1, 4, 2, :2] = tris[1, 4, 0, :2]  # no area: skipped
    out = vis.rasterize_triangles(native(tris, backend), (6, 8), chunk_size=3)
    for b in range(2):
        depth, ids, bary = _rasterize_reference(tris[b], (6, 8))
        np.testing.assert_array_equal(numpy_of(out[1])[b], ids)
        np.testing.assert_allclose(numpy_of(out[0])[b], depth, rtol=1e-12)
        np.testing.assert_allclose(numpy_of(out[2])[b], bary, atol=1e-12)
    assert (numpy_of(out[1]) >= 0).mean() > 0.3


def test_rasterized_depth_of_a_projected_plane_is_exact(backend):
    """Two triangles of the floor square, projected into a MuJoCo test camera: the rasterized
    (perspective-correct) depth equals the depth of the floor along every covered pixel's ray."""
    cam, _ = cameras((24, 32))
    corners = np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]])
    ds = R.apply(cam.P, corners)
    vertices = np.concatenate([ds[:, :2] / ds[:, 2:], ds[:, 2:]], -1)
    tris = vertices[[[0, 1, 2], [0, 2, 3]]]
    depth, ids, _ = vis.rasterize_triangles(native(tris, backend), (cam.h, cam.w))
    depth, covered = numpy_of(depth)[..., 0], numpy_of(ids)[..., 0] >= 0
    rays = cam.pixel_rays(cam.grid()).reshape(cam.h, cam.w, 3)
    floor_depth = -cam.C[2] / rays[..., 2]  # rays have unit camera z: t is the planar depth
    assert covered.mean() > 0.1
    np.testing.assert_allclose(depth[covered], floor_depth[covered], rtol=1e-12)


def test_trimesh_of_images(rng, backend):
    expected = np.array(
        [[0, 1, 3], [1, 2, 4], [3, 4, 6], [4, 5, 7], [4, 1, 3], [5, 2, 4], [7, 4, 6], [8, 5, 7]]
    )
    out = vis.create_trimesh_indices_for_image((3, 3), f=backend)
    np.testing.assert_array_equal(numpy_of(out), expected)
    coords = rng.standard_normal((3, 3, 3))
    mask = np.ones((3, 3, 1), bool)
    mask[0, 0] = False
    vertices, triangles = vis.coord_image_to_trimesh(native(coords, backend), native(mask, backend))
    check(vertices, coords.reshape(9, 3), backend)
    np.testing.assert_array_equal(numpy_of(triangles), expected[1:])
    _, batched = vis.coord_image_to_trimesh(native(np.stack([coords] * 2), backend))
    assert numpy_of(batched).shape == (2, 8, 3)


# ----------------------------------------------------------------------------------------------
# smoothing
# ----------------------------------------------------------------------------------------------


def test_weighted_and_variance_smoothing(rng, backend):
    mean = rng.standard_normal((2, 5, 6, 2))
    weights = rng.uniform(0.1, 2, (2, 5, 6, 2))
    k = 3
    out_mean, out_weights = vis.weighted_image_smooth(
        native(mean, backend), native(weights, backend), k
    )
    expected_mean = np.zeros((2, 3, 4, 2))
    expected_weights = np.zeros((2, 3, 4, 2))
    for b, i, j in np.ndindex(2, 3, 4):
        m, w = mean[b, i : i + k, j : j + k], weights[b, i : i + k, j : j + k]
        expected_mean[b, i, j] = np.sum(m * w, (0, 1)) / np.sum(w, (0, 1))
        expected_weights[b, i, j] = np.mean(w, (0, 1))
    check(out_mean, expected_mean, backend)
    check(out_weights, expected_weights, backend)

    scale = np.array([0.5, 2.0])
    out_mean, out_var = vis.smooth_image_from_var_image(
        native(mean, backend), native(weights, backend), k, scale
    )
    expected_mean, expected_var = np.zeros((2, 3, 4, 2)), np.zeros((2, 3, 4, 2))
    for b, i, j in np.ndindex(2, 3, 4):
        dist = np.hypot(*np.mgrid[-1:2, -1:2])[..., None]
        v = weights[b, i : i + k, j : j + k] * (1 + dist * scale)
        expected_mean[b, i, j] = np.sum(mean[b, i : i + k, j : j + k] / v, (0, 1)) / np.sum(
            1 / v, (0, 1)
        )
        expected_var[b, i, j] = k * k / np.sum(1 / v, (0, 1))
    check(out_mean, expected_mean, backend)
    check(out_var, expected_var, backend)
    alias = vis.smooth_image_fom_var_image(
        native(mean, backend), native(weights, backend), k, scale
    )
    check(alias[1], expected_var, backend)


# ----------------------------------------------------------------------------------------------
# signed distances
# ----------------------------------------------------------------------------------------------


def test_signed_distances(rng, backend):
    centres = rng.standard_normal((2, 3, 3))
    radii = rng.uniform(0.2, 1, (2, 3, 1))
    queries = rng.standard_normal((2, 10, 3)) * 2
    out = vis.sphere_signed_distances(
        native(centres, backend), native(radii, backend), native(queries, backend)
    )
    expected = np.min(
        np.linalg.norm(queries[:, None] - centres[:, :, None], axis=-1) - radii, axis=1
    )[..., None]
    check(out, expected, backend)
    rot = np.stack([np.stack([R.random_rotation(rng) for _ in range(2)]) for _ in range(2)])
    pos = rng.standard_normal((2, 2, 3))
    ext = np.concatenate([rot, -(rot @ pos[..., None])], -1)
    dims = rng.uniform(0.5, 2, (2, 2, 3))
    out = vis.cuboid_signed_distances(
        native(ext, backend), native(dims, backend), native(queries, backend)
    )
    expected = np.full((2, 10), np.inf)
    for b, c, p in np.ndindex(2, 2, 10):
        local = rot[b, c] @ (queries[b, p] - pos[b, c])
        q = np.abs(local) - dims[b, c] / 2
        d = np.linalg.norm(np.maximum(q, 0)) + min(q.max(), 0)
        expected[b, p] = min(expected[b, p], d)
    check(out, expected[..., None], backend)


# ----------------------------------------------------------------------------------------------
# implicit rendering
# ----------------------------------------------------------------------------------------------


def test_termination_probabilities_and_rendering(rng, backend):
    density = rng.uniform(0, 3, (2, 4, 9))
    spacing = rng.uniform(0.01, 0.5, (2, 4, 9))
    alpha = 1 - np.exp(-density * spacing)
    survive = np.cumprod(np.concatenate([np.ones((2, 4, 1)), 1 - alpha[..., :-1]], -1), -1)
    check(
        vis.sampled_volume_density_to_occupancy_probability(
            native(density, backend), native(spacing, backend)
        ),
        alpha,
        backend,
    )
    weights = vis.ray_termination_probabilities(native(density, backend), native(spacing, backend))
    check(weights, alpha * survive, backend)
    feats = rng.standard_normal((2, 4, 9, 3))
    w = alpha * survive
    rendering = np.sum(w[..., None] * feats, -2)
    out, var = vis.render_rays_via_termination_probabilities(weights, native(feats, backend), True)
    check(out, rendering, backend)
    check(var, np.sum(w[..., None] * (feats - rendering[..., None, :]) ** 2, -2), backend)


def test_stratified_samples(backend):
    starts, ends = np.array([0.0, 1.0]), np.array([1.0, 3.0])
    ivy.seed(3)
    a = numpy_of(vis.stratified_sample(native(starts, backend), native(ends, backend), 5))
    b = numpy_of(vis.stratified_sample(native(starts, backend), native(ends, backend), 5))
    ivy.seed(3)
    c = numpy_of(vis.stratified_sample(native(starts, backend), native(ends, backend), 5))
    np.testing.assert_array_equal(a, c)
    assert not np.array_equal(a, b)
    lows = starts[:, None] + (ends - starts)[:, None] * np.arange(5) / 5
    assert np.all(a >= lows) and np.all(a < lows + (ends - starts)[:, None] / 5)


def test_render_implicit_features_and_depth(backend):
    """An opaque wall at z = 2 in front of rays from the origin: the rendered depth is the first
    sample beyond the wall (within one bin), the features those of the wall."""
    xp = getattr(ivy, backend)

    def network(points, features, timestamps, v=None):
        z = points[..., 2]
        feat = xp.stack([xp.ones_like(z) * 0.25, z * 0], axis=-1)
        return feat, xp.where(z > 2, xp.full_like(z, 1e6), xp.zeros_like(z))

    dirs = np.array([[[0.0, 0.0, 1.0], [0.6, 0.0, 0.8]]])
    near, far = np.ones((1, 2)), np.full((1, 2), 4.0)
    feat, var, depth, depth_var = vis.render_implicit_features_and_depth(
        network,
        native(np.zeros((1, 3)), backend),
        native(dirs, backend),
        native(near, backend),
        native(far, backend),
        96,
        render_variance=True,
    )
    wall = np.array([2.0, 2.0 / 0.8])
    assert np.all(np.abs(numpy_of(depth)[0, :, 0] - wall) <= 3 / 96 + 1e-9)
    check(feat, np.broadcast_to([0.25, 0.0], (1, 2, 2)), backend, atol=1e-9)
    assert np.all(numpy_of(var) < 1e-12) and np.all(numpy_of(depth_var) < 1e-3)


def test_sampled_pixels(backend):
    assert vis.downsampled_image_dims_from_desired_num_pixels((480, 640), 1000) == ([27, 37], 999)
    assert vis.downsampled_image_dims_from_desired_num_pixels((480, 640), 1000, True) == (
        [27, 36],
        972,
    )
    coords = numpy_of(vis.create_sampled_pixel_coords_image((12, 16), (3, 4), (2,), f=backend))
    assert coords.shape == (2, 3, 4, 2)
    cells = np.floor(coords / [4, 4])  # every sample in its own 4 x 4 cell
    np.testing.assert_array_equal(cells[..., 0], np.broadcast_to(np.arange(4), (2, 3, 4)))
    np.testing.assert_array_equal(cells[..., 1], np.broadcast_to(np.arange(3)[:, None], (2, 3, 4)))
    image = np.stack(np.meshgrid(np.arange(16.0), np.arange(12.0)), -1)[None]  # (x, y) of pixels
    image = np.concatenate([image, image[..., :1] * 0 + 7], -1)
    xy, seven = vis.sample_images(
        [native(image[..., :2], backend), native(image[..., 2:], backend)], 12
    )
    xy = numpy_of(xy)
    assert xy.shape == (1, 12, 2) and np.all(numpy_of(seven) == 7)
    assert len({tuple(p) for p in np.floor(xy[0] / 4)}) == 12
