"""Quaternion algebra, rotating points, slerp, distances, random rotations and target facing."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation, Slerp

import ivy
import ivy_mechanics as mech
from tests.conftest import capable, require
from tests.helpers import native, numpy_of
from tests.ivy_mechanics._cases import BATCH, BATCH_SHAPE
from tests.ivy_mechanics._reference import edge_axis_angles
from tests.ivy_mechanics._utils import call

TOL = dict(rtol=0, atol=1e-12)


def _up_to_sign(got, expected):
    flip = np.sum(got * expected, axis=-1, keepdims=True) < 0
    return np.where(flip, -got, got)


def _edge_rotations():
    axes, angles = edge_axis_angles(np.random.default_rng(6))
    return Rotation.from_rotvec(axes * angles[:, None])


def test_hamilton_product_composes_like_scipy(backend):
    r1, r2 = Rotation.random(16, random_state=7), Rotation.random(16, random_state=8)
    got = call(backend, "hamilton_product", [r1.as_quat(), r2.as_quat()])
    expected = (r1 * r2).as_quat()
    np.testing.assert_allclose(_up_to_sign(got, expected), expected, **TOL)
    # R(q1 q2) = R(q1) R(q2), and batch dimensions broadcast: [4, 1, 4] x [1, 4, 4]
    q1, q2 = r1.as_quat()[:4, None], r2.as_quat()[None, :4]
    got = call(backend, "hamilton_product", [q1, q2])
    assert got.shape == (4, 4, 4)
    expected = np.stack([(r1[i] * r2[:4]).as_quat() for i in range(4)])
    np.testing.assert_allclose(_up_to_sign(got, expected), expected, **TOL)


def test_conjugate_inverse_normalize(backend):
    q = np.random.default_rng(9).standard_normal((16, 4))
    inv = call(backend, "inverse_quaternion", [q])
    product = call(backend, "hamilton_product", [q, inv])
    np.testing.assert_allclose(product, np.tile([0.0, 0, 0, 1], (16, 1)), **TOL)
    np.testing.assert_array_equal(
        call(backend, "quaternion_conjugate", [q]), q * np.array([-1, -1, -1, 1])
    )
    unit = call(backend, "normalize_quaternion", [q])
    np.testing.assert_allclose(unit, q / np.linalg.norm(q, axis=-1, keepdims=True), **TOL)


def test_scale_quaternion_rotation_angle_is_a_power(backend):
    rot = _edge_rotations()
    for scale in (0.0, 0.3, 1.0, 2.5):
        got = call(backend, "scale_quaternion_rotation_angle", [rot.as_quat(), np.array(scale)])
        expected = (rot**scale).as_quat()
        at_pi = np.abs(rot.magnitude() - np.pi) < 1e-13  # the direction is ambiguous at pi
        np.testing.assert_allclose(_up_to_sign(got, expected)[~at_pi], expected[~at_pi], **TOL)


def test_rotate_points(backend):
    rot = _edge_rotations()
    points = np.random.default_rng(10).standard_normal((len(rot), 3))
    expected = rot.apply(points)
    np.testing.assert_allclose(
        call(backend, "rotate_points", [rot.as_matrix(), points]), expected, **TOL
    )
    got = call(backend, "quaternion_rotate_points", [rot.as_quat(), points])
    np.testing.assert_allclose(got, expected, **TOL)
    # a cloud [B, N, 3] by one rotation per batch item [B, 1, 3, 3]
    cloud = np.random.default_rng(11).standard_normal((3, 5, 3))
    got = call(backend, "rotate_points", [rot.as_matrix()[:3, None], cloud])
    np.testing.assert_allclose(got, np.stack([rot[i].apply(cloud[i]) for i in range(3)]), **TOL)


def test_slerp_matches_scipy(backend):
    r0, r1 = Rotation.random(8, random_state=12), Rotation.random(8, random_state=13)
    ts = np.linspace(0.0, 1.0, 5)
    for i in range(8):
        pair = Rotation.concatenate([r0[i], r1[i]])
        expected = Slerp([0.0, 1.0], pair)(ts).as_quat()
        q0, q1 = np.tile(r0[i].as_quat(), (5, 1)), np.tile(r1[i].as_quat(), (5, 1))
        got = call(backend, "slerp", [q0, q1, ts[:, None]])
        np.testing.assert_allclose(_up_to_sign(got, expected), expected, **TOL)
    # equal and nearly equal rotations, and the shortest arc when q1 has the opposite sign
    q = r0.as_quat()
    near = (Rotation.from_rotvec([1e-9, 0, 0]) * r0).as_quat()
    got = call(backend, "slerp", [q, -near, np.full((8, 1), 0.5)])
    expected = (Rotation.from_rotvec([0.5e-9, 0, 0]) * r0).as_quat()
    np.testing.assert_allclose(_up_to_sign(got, expected), expected, **TOL)
    np.testing.assert_allclose(call(backend, "slerp", [q, q, np.array(0.7)]), q, **TOL)


def test_geodesic_distances(backend):
    rot = _edge_rotations()
    other = Rotation.random(len(rot), random_state=14)
    for r1, r2 in ((other, rot * other), (rot, rot)):
        expected = (r1.inv() * r2).magnitude()
        got = call(backend, "geodesic_distance", [r1.as_matrix(), r2.as_matrix()])
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-11)
        got = call(backend, "quaternion_geodesic_distance", [r1.as_quat(), -r2.as_quat()])
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-11)


def test_target_facing_rotation_matrix(backend):
    rng = np.random.default_rng(15)
    body, target = rng.standard_normal((32, 3)), rng.standard_normal((32, 3))
    m = call(backend, "target_facing_rotation_matrix", [body, target])
    direction = (target - body) / np.linalg.norm(target - body, axis=-1, keepdims=True)
    np.testing.assert_allclose(m[..., :, 2], direction, **TOL)  # +z faces the target
    np.testing.assert_allclose(m[..., 2, 0], 0.0, **TOL)  # +x is horizontal
    np.testing.assert_allclose(
        m @ np.swapaxes(m, -1, -2), np.broadcast_to(np.eye(3), m.shape), **TOL
    )
    np.testing.assert_allclose(np.linalg.det(m), 1.0, **TOL)
    up = np.tile([1.0, 0, 0], (32, 1))
    m = call(backend, "target_facing_rotation_matrix", [body, target, up])
    np.testing.assert_allclose(m[..., 0, 0], 0.0, **TOL)  # +x perpendicular to the given up


@pytest.mark.parametrize(
    "name, width",
    [
        ("get_random_quaternion", 4),
        ("get_random_rot_mat", None),
        ("get_random_rot_vec", 3),
        ("get_random_axis_angle", 4),
        ("get_random_euler", 3),
    ],
)
def test_random_rotations_shape_dtype(backend, name, width):
    shape = BATCH_SHAPE
    if not capable(backend, "float64"):  # jax without 64-bit types says so
        with pytest.raises(ivy.UnsupportedError, match="64-bit types disabled"):
            getattr(mech, name)(shape, dtype="float64", f=backend)
    for dtype in ("float32", "float64") if capable(backend, "float64") else ("float32",):
        out = getattr(mech, name)(shape, dtype=dtype, f=backend)
        got = numpy_of(out)
        assert got.shape == (*shape, *((3, 3) if width is None else (width,)))
        assert got.dtype == dtype
        assert np.all(np.isfinite(got))
    with ivy.set_framework(backend):  # the global framework when f is None
        assert numpy_of(getattr(mech, name)((BATCH,))).shape[0] == BATCH


def test_random_rotations_are_uniform(backend):
    """Haar measure: E[R] = 0 and the angle has density (1 - cos t) / pi (E[cos t] = -1/2)."""
    require(backend, "float64")
    n = 20000
    m = numpy_of(mech.get_random_rot_mat((n,), dtype="float64", f=backend))
    np.testing.assert_allclose(m.mean(0), 0.0, atol=0.03)
    cos_angle = (np.trace(m, axis1=-2, axis2=-1) - 1) / 2
    assert abs(cos_angle.mean() + 0.5) < 0.02
    q = numpy_of(mech.get_random_quaternion((n,), dtype="float64", f=backend))
    np.testing.assert_allclose(np.linalg.norm(q, axis=-1), 1.0, atol=1e-12)


def test_random_rotation_without_framework_raises():
    with pytest.raises(ivy.NoFrameworkError):
        mech.get_random_quaternion((2,))


def test_inputs_of_one_backend_only(backend):
    q = native(np.array([0.0, 0, 0, 1]), backend)
    out = mech.quaternion_to_rot_mat(q)
    assert type(out) is type(mech.quaternion_to_rot_mat(q, f=backend))
