"""The shapes of ivy_mechanics' arguments, declared once (private).

Every public function is decorated with :func:`takes`, naming its array arguments; their shapes
come from :data:`SHAPES` by name (a trailing digit ignored: ``quaternion1`` is a quaternion).
The core's :func:`ivy.checks.checked` then checks them before any framework sees them, with the
same :class:`ivy.checks.InputError` on every backend, checks that their batch dimensions
broadcast, and brings them to one floating dtype (integers compute in float32, float32 with
float64 is float64).
"""

from __future__ import annotations

from ivy.checks import checked

#: argument name -> shape spec (see :func:`ivy.checks.check_shape`).
SHAPES = {
    "quaternion": ("...", 4),
    "rot_mat": ("...", 3, 3),
    "rot_vec": ("...", 3),
    "axis_angle": ("...", 4),
    "polar_axis_angle": ("...", 3),
    "euler_angles": ("...", 3),
    "rot_6d": ("...", 6),
    "points": ("...", 3),
    "body_pos": ("...", 3),
    "target_pos": ("...", 3),
    "up": ("...", 3),
    "quat_pose": ("...", 7),
    "quat_vel": ("...", 7),
    "mat_pose": ("...", (3, 4), 4),
    "matrices": ("...", 3, 4),
    "rot_vec_pose": ("...", 6),
    "euler_pose": ("...", 6),
    "axis_angle_pose": ("...", 7),
    "polar_coords": ("...", 3),
    "cartesian_coords": ("...", 3),
    "cylindrical_coords": ("...", 3),
    "coords": ("...", "n"),
    "vector": ("...", 3),
    "twist": ("...", 6),
}


_QUATERNION = "Quaternions are scalar-last [x, y, z, w]."
_MAT_POSE = "Matrix poses are [R | t] (3 x 4) or homogeneous (4 x 4)."
#: argument name -> how to fix a wrong shape, appended to the error message.
HINTS = {
    "quaternion": _QUATERNION,
    "rot_mat": "For a pose [R | t], give its rotation part, mat_pose[..., :3, :3].",
    "axis_angle": "Axis-angles are [ax, ay, az, angle] (a rotation vector angle * axis is "
    "[..., 3]: use the rot_vec functions).",
    "rot_vec": "Rotation vectors are angle * axis (for [ax, ay, az, angle] use the axis_angle "
    "functions).",
    "quat_pose": "Quaternion poses are [x, y, z, qx, qy, qz, qw].",
    "quat_vel": "Quaternion velocities are [vx, vy, vz, qx, qy, qz, qw].",
    "mat_pose": _MAT_POSE,
    "rot_vec_pose": "Rotation-vector poses are [x, y, z, rx, ry, rz].",
    "euler_pose": "Euler poses are [x, y, z, a, b, c].",
    "axis_angle_pose": "Axis-angle poses are [x, y, z, ax, ay, az, angle].",
    "twist": "Twists are [vx, vy, vz, wx, wy, wz].",
}


def takes(*names: str, **shapes):
    """Decorate a public function whose array arguments are ``names`` (shapes from
    :data:`SHAPES`) and ``shapes`` (given here, for a name whose shape differs by function).

    Example:
        >>> @takes("quaternion")
        ... def w(quaternion, *, f=None):
        ...     return quaternion[..., 3]
        >>> w(np.zeros(3))
        Traceback (most recent call last):
        ...
        ivy.checks.InputError: w: quaternion must be [..., 4]; got shape (3,). Quaternions are
        scalar-last [x, y, z, w].
    """
    bases = {name: name.rstrip("0123456789") for name in names}
    specs = {name: SHAPES[base] for name, base in bases.items()}
    hints = {name: HINTS[base] for name, base in bases.items() if base in HINTS}
    return checked(broadcast=True, hints=hints, **specs, **shapes)
