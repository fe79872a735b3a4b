"""Spherical polar and cylindrical coordinates, and the paper's example: an omnidirectional
RGB-D image turned into a point cloud with polar_to_cartesian_coords."""

from __future__ import annotations

import numpy as np

import ivy
import ivy_mechanics as mech
from tests.helpers import native, numpy_of
from tests.ivy_mechanics._utils import call

TOL = dict(rtol=0, atol=1e-12)


def _spherical(phi, theta, r):
    """Reference: azimuth phi from +x, inclination theta from +z."""
    return np.stack(
        [r * np.sin(theta) * np.cos(phi), r * np.sin(theta) * np.sin(phi), r * np.cos(theta)], -1
    )


def test_polar_coordinates(backend):
    rng = np.random.default_rng(40)
    phi, theta, r = rng.uniform(-3, 3, 64), rng.uniform(0, np.pi, 64), rng.uniform(0, 5, 64)
    polar = np.stack([phi, theta, r], -1)
    xyz = call(backend, "polar_to_cartesian_coords", [polar])
    np.testing.assert_allclose(xyz, _spherical(phi, theta, r), **TOL)
    np.testing.assert_allclose(call(backend, "cartesian_to_polar_coords", [xyz]), polar, atol=1e-12)
    # the origin and the poles: angles 0, finite
    edge = np.array([[0.0, 0, 0], [0, 0, 2], [0, 0, -2], [-1, 0, 0], [0, -1e-100, 0]])
    got = call(backend, "cartesian_to_polar_coords", [edge])
    expected = [
        [0, 0, 0],
        [0, 0, 2],
        [0, np.pi, 2],
        [np.pi, np.pi / 2, 1],
        [-np.pi / 2, np.pi / 2, 1e-100],
    ]
    np.testing.assert_allclose(got, expected, **TOL)


def test_cylindrical_coordinates(backend):
    rng = np.random.default_rng(41)
    rho, phi, z = rng.uniform(0, 5, 64), rng.uniform(-3, 3, 64), rng.uniform(-2, 2, 64)
    cyl = np.stack([rho, phi, z], -1)
    xyz = call(backend, "cylindrical_to_cartesian_coords", [cyl])
    np.testing.assert_allclose(xyz, np.stack([rho * np.cos(phi), rho * np.sin(phi), z], -1), **TOL)
    np.testing.assert_allclose(call(backend, "cartesian_to_cylindrical_coords", [xyz]), cyl, **TOL)
    got = call(backend, "cartesian_to_cylindrical_coords", [np.array([[0.0, 0, 3]])])
    np.testing.assert_array_equal(got, [[0.0, 0, 3]])


def test_make_coordinates_homogeneous(backend):
    coords = np.random.default_rng(42).standard_normal((2, 3, 5, 2))
    got = call(backend, "make_coordinates_homogeneous", [coords])
    np.testing.assert_array_equal(got, np.concatenate([coords, np.ones((2, 3, 5, 1))], -1))


# ----------------------------------------------------------------------------------------------
# The paper's example
# ----------------------------------------------------------------------------------------------

HALF_EXTENTS = np.array([3.0, 2.0, 1.5])  # a box room around the camera at the origin
SPHERE_CENTRE, SPHERE_RADIUS = np.array([1.5, 0.5, -0.3]), 0.5
FACE_COLOURS = np.array(  # +x, -x, +y, -y, +z, -z walls, then the sphere
    [[1.0, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [1, 0, 1], [0, 1, 1], [0.5, 0.5, 0.5]]
)


def _render_omni_rgbd(height, width):
    """Equirectangular RGB-D image of the scene, ray cast in numpy: pixel (v, u) looks along
    azimuth -pi + (u + 1/2) 2 pi / W and inclination (v + 1/2) pi / H."""
    v, u = np.meshgrid(np.arange(height), np.arange(width), indexing="ij")
    phi = -np.pi + (u + 0.5) * 2 * np.pi / width
    theta = (v + 0.5) * np.pi / height
    d = np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)], -1)
    with np.errstate(divide="ignore"):
        t_walls = HALF_EXTENTS / np.abs(d)  # distance to the wall along each axis
    axis = np.argmin(t_walls, -1)
    depth = np.take_along_axis(t_walls, axis[..., None], -1)[..., 0]
    sign = np.take_along_axis(d, axis[..., None], -1)[..., 0] < 0
    label = 2 * axis + sign
    dc = d @ SPHERE_CENTRE
    disc = dc**2 - SPHERE_CENTRE @ SPHERE_CENTRE + SPHERE_RADIUS**2
    t_sphere = dc - np.sqrt(np.maximum(disc, 0))
    hit = (disc > 0) & (t_sphere > 0) & (t_sphere < depth)
    depth = np.where(hit, t_sphere, depth)
    label = np.where(hit, 6, label)
    return FACE_COLOURS[label], depth[..., None], label


def _colour_of_points(points):
    """Colour of the scene surface each point lies on (sphere, else the wall it touches)."""
    axis = np.argmax(np.abs(points) / HALF_EXTENTS, -1)
    negative = np.take_along_axis(points, axis[..., None], -1)[..., 0] < 0
    on_sphere = np.linalg.norm(points - SPHERE_CENTRE, axis=-1) < SPHERE_RADIUS + 1e-9
    return FACE_COLOURS[np.where(on_sphere, 6, 2 * axis + negative)]


def test_omnidirectional_rgbd_to_point_cloud(backend):
    height, width = 48, 96
    rgb, depth, label = _render_omni_rgbd(height, width)
    assert 0.01 < np.mean(label == 6) < 0.2 and len(np.unique(label)) == 7
    xp = getattr(ivy, backend)
    depth = native(depth, backend)
    # pixel indices -> polar angles, with the backend
    v = xp.arange(height, dtype="float64")[:, None, None] * xp.ones((1, width, 1), dtype="float64")
    u = xp.arange(width, dtype="float64")[None, :, None] * xp.ones((height, 1, 1), dtype="float64")
    phi = (u + 0.5) * (2 * np.pi / width) - np.pi
    theta = (v + 0.5) * (np.pi / height)
    polar = ivy.concat([phi, theta, depth], axis=-1)
    points = numpy_of(mech.polar_to_cartesian_coords(polar))
    assert points.shape == (height, width, 3)
    # every point lies on the surface that coloured its pixel
    np.testing.assert_array_equal(_colour_of_points(points), rgb)
    on_sphere = label == 6
    np.testing.assert_allclose(
        np.linalg.norm(points[on_sphere] - SPHERE_CENTRE, axis=-1), SPHERE_RADIUS, atol=1e-12
    )
    on_wall = ~on_sphere
    np.testing.assert_allclose(
        np.max(np.abs(points[on_wall]) / HALF_EXTENTS, -1), 1.0, rtol=0, atol=1e-12
    )
    # and the cloud converts back to the image's angles and depths
    back = numpy_of(mech.cartesian_to_polar_coords(mech.polar_to_cartesian_coords(polar)))
    np.testing.assert_allclose(back, numpy_of(polar), rtol=0, atol=1e-12)
