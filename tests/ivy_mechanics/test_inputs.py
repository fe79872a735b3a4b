"""What users pass behaves the same on every backend: shapes are checked before any framework
sees the arrays (one :class:`ivy.checks.InputError` everywhere, never a silent answer from a
slice that happened to fit), and integer arrays and float32/float64 mixes promote by ivy's rule
(integers compute in float32; float32 with float64 is float64), where tensorflow raised."""

from __future__ import annotations

import numpy as np
import pytest

import ivy_mechanics as mech
from ivy.checks import InputError
from tests.helpers import assert_close, native, numpy_of


def _dtype(x) -> str:
    return numpy_of(x).dtype.name


@pytest.mark.parametrize(
    "fn, shape, message",
    [
        (
            mech.rot_mat_to_quaternion,
            (3, 4),
            r"rot_mat must be \[\.\.\., 3, 3\]; got shape \(3, 4\)",
        ),
        (mech.quaternion_to_rot_mat, (3,), r"quaternion must be \[\.\.\., 4\]; got shape \(3,\)"),
        (mech.rot_vec_to_rot_mat, (4,), r"rot_vec must be \[\.\.\., 3\]"),
        (mech.axis_angle_to_quaternion, (3,), r"axis_angle must be \[\.\.\., 4\]"),
        (mech.mat_pose_to_quaternion_pose, (4, 3), r"mat_pose must be \[\.\.\., 3 or 4, 4\]"),
        (mech.quaternion_pose_to_mat_pose, (6,), r"quat_pose must be \[\.\.\., 7\]"),
        (mech.so3_vee, (3, 4), r"matrix must be \[\.\.\., 3, 3\]"),
        (mech.se3_exp, (3,), r"twist must be \[\.\.\., 6\]"),
        (mech.cartesian_to_polar_coords, (2,), r"cartesian_coords must be \[\.\.\., 3\]"),
        (mech.quaternion_to_rot_mat, (), r"quaternion must be \[\.\.\., 4\]; got shape \(\)"),
    ],
)
def test_a_wrong_shape_is_named_on_every_backend(backend, fn, shape, message):
    with pytest.raises(InputError, match=fn.__name__ + ": " + message):
        fn(native(np.ones(shape), backend))


def test_the_shape_error_says_what_to_do(backend):
    with pytest.raises(InputError, match=r"scalar-last \[x, y, z, w\]"):
        mech.quaternion_to_rot_mat(native(np.ones(3), backend))
    with pytest.raises(InputError, match=r"rotation part, mat_pose\[\.\.\., :3, :3\]"):
        mech.rot_mat_to_euler(native(np.eye(3, 4), backend))


def test_batch_dimensions_that_do_not_broadcast_are_named(backend):
    q1, q2 = native(np.ones((2, 4)), backend), native(np.ones((3, 4)), backend)
    with pytest.raises(InputError, match=r"hamilton_product: the batch dimensions of "
                       r"quaternion1 \(2,\), quaternion2 \(3,\) do not broadcast"):  # fmt: skip
        mech.hamilton_product(q1, q2)
    points = native(np.ones((5, 3)), backend)
    with pytest.raises(InputError, match="do not broadcast"):
        mech.rotate_points(native(np.ones((2, 3, 3)), backend), points)


def test_integer_inputs_compute_in_float32_on_every_backend(backend):
    q = native(np.array([0, 0, 1, 1]), backend)  # an integer quaternion: 90 degrees about z
    out = mech.quaternion_to_rot_mat(q)
    assert _dtype(out) == "float32"
    assert_close(out, np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]), "float32")
    rot_vec = mech.rot_vec_to_quaternion(native(np.array([0, 0, 2]), backend))
    assert _dtype(rot_vec) == "float32"
    assert_close(rot_vec, np.array([0.0, 0.0, np.sin(1.0), np.cos(1.0)]), "float32")


def test_float32_and_float64_promote_to_float64_on_every_backend(backend):
    q1 = native(np.array([0.0, 0.0, 1.0, 1.0], np.float32) / np.sqrt(np.float32(2)), backend)
    q2 = native(np.array([1.0, 0.0, 0.0, 0.0]), backend)  # float64
    out = mech.hamilton_product(q1, q2)
    assert _dtype(out) == "float64"
    s = np.float32(1) / np.sqrt(np.float32(2))  # q1's components, as float32 holds them
    assert_close(out, np.array([s, s, 0.0, 0.0], np.float64), "float64")
    moved = mech.transform_points(native(np.eye(3, 4, dtype=np.float32), backend),
                                  native(np.array([1, 2, 3]), backend))  # fmt: skip
    assert _dtype(moved) == "float32"
    assert_close(moved, np.array([1.0, 2.0, 3.0]), "float32")


def test_lists_are_arrays_of_the_chosen_framework(backend):
    out = mech.rot_vec_to_rot_mat([0.0, 0.0, 0.0], f=backend)
    assert_close(out, np.eye(3), "float32")
    with pytest.raises(InputError, match="rot_vec must be"):
        mech.rot_vec_to_rot_mat([0.0, 0.0], f=backend)


@pytest.mark.parametrize(
    "name", ["get_random_quaternion", "get_random_rot_mat", "get_random_euler"]
)
def test_random_rotations_refuse_integer_dtypes(backend, name):
    """Integer draws rounded the normal samples (quaternions of zeros and ones, NaN rotation
    vectors) on three backends and raised on jax."""
    import ivy

    with pytest.raises(ivy.DtypeError, match="draws real numbers"):
        getattr(mech, name)((2,), dtype="int32", f=backend)
