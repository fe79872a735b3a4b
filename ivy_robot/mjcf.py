"""Loading MJCF models through MuJoCo, once, into plain float64 numpy arrays.

MuJoCo is the parser: it resolves defaults, ``<frame>`` elements, ``<include>`` files, angle units
(``<compiler angle="degree">``), Euler sequences and every orientation attribute (``quat``,
``euler``, ``axisangle``, ``xyaxes``, ``zaxis``) into positions and unit quaternions. ivy_robot
reads the compiled model once and never calls MuJoCo inside differentiable code.

Quaternions: MuJoCo stores them scalar-first ``[w, x, y, z]``; ivy_mechanics uses scalar-last
``[x, y, z, w]``. :func:`mujoco_quaternion_to_rot_mat` converts MuJoCo's order to matrices in numpy
(for constants); array code converts with :func:`wxyz_to_xyzw` before calling ivy_mechanics.
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ET
from typing import Any

import numpy as np

import ivy
from ivy.typing import Array, Framework

__all__ = [
    "load_mjcf",
    "mujoco_quaternion_to_rot_mat",
    "wxyz_to_xyzw",
    "xyzw_to_wxyz",
    "SUPPORTED_JOINT_TYPES",
]

#: MuJoCo's joint types, by their ``mjtJoint`` value.
SUPPORTED_JOINT_TYPES = {0: "free", 1: "ball", 2: "slide", 3: "hinge"}


def _import_mujoco():
    try:
        import mujoco
    except ImportError as err:  # pragma: no cover - mujoco is in the [robot] extra
        raise ImportError(
            "ivy_robot reads MJCF through MuJoCo, which is not installed: "
            "pip install 'ivy[robot]' (or pip install mujoco)"
        ) from err
    return mujoco


def _check_joint_types(xml_text: str) -> None:
    """Raise a clear error for a ``<joint type=...>`` that MuJoCo (and ivy_robot) lacks, before
    MuJoCo's own, terser, parse error."""
    try:
        root = ET.fromstring(xml_text)
    except ET.ParseError:
        return  # MuJoCo reports malformed XML itself
    supported = set(SUPPORTED_JOINT_TYPES.values())
    for element in root.iter("joint"):
        kind = element.get("type")
        if kind is not None and kind not in supported:
            name = element.get("name", "<unnamed>")
            raise ValueError(
                f"MJCF joint {name!r} has type {kind!r}; ivy_robot supports the joint types "
                f"{sorted(supported)} (MuJoCo's). Model a universal or spherical-like joint as "
                "hinges in one body, or a ball joint."
            )


def load_mjcf(source: Any):
    """Compile an MJCF model with MuJoCo.

    Args:
        source: a path to an ``.xml`` file, an MJCF XML string, or a compiled ``mujoco.MjModel``
            (returned as it is).

    Returns:
        The compiled ``mujoco.MjModel``.

    Raises:
        ValueError: the source is neither a file nor XML, uses an unsupported joint type, or
            MuJoCo cannot compile it (MuJoCo's message is included).

    Example:
        >>> model = load_mjcf('<mujoco><worldbody><geom size=".1"/></worldbody></mujoco>')
        >>> model.ngeom
        1
    """
    mujoco = _import_mujoco()
    if isinstance(source, mujoco.MjModel):
        return source
    if isinstance(source, os.PathLike):
        source = os.fspath(source)
    if not isinstance(source, str):
        raise TypeError(
            f"load_mjcf: expected a path, an MJCF XML string or a mujoco.MjModel, got "
            f"{type(source).__name__}"
        )
    is_xml = source.lstrip().startswith("<")
    if not is_xml and not os.path.isfile(source):
        raise ValueError(
            f"load_mjcf: {source[:80]!r} is neither an existing file nor an MJCF XML string "
            "(XML must start with '<')"
        )
    if is_xml:
        _check_joint_types(source)
    else:
        with open(source, encoding="utf-8") as handle:
            _check_joint_types(handle.read())
    try:
        if is_xml:
            return mujoco.MjModel.from_xml_string(source)
        return mujoco.MjModel.from_xml_path(source)
    except ValueError as err:
        message = re.sub(r"\s+", " ", str(err)).strip()
        raise ValueError(f"MuJoCo could not compile the MJCF model: {message}") from err


def mujoco_quaternion_to_rot_mat(quat_wxyz: np.ndarray) -> np.ndarray:
    """Rotation matrices of MuJoCo quaternions ``[w, x, y, z]`` (normalised first), in numpy
    float64, for the constants of a model.

    Args:
        quat_wxyz: quaternions *[batch_shape, 4]*, scalar first.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> mujoco_quaternion_to_rot_mat(np.array([1.0, 0.0, 0.0, 0.0]))
        array([[1., 0., 0.],
               [0., 1., 0.],
               [0., 0., 1.]])
    """
    q = np.asarray(quat_wxyz, dtype=np.float64)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    rows = [
        [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z],
    ]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def wxyz_to_xyzw(quaternion: Array, *, f: Framework = None) -> Array:
    """Reorder MuJoCo quaternions ``[w, x, y, z]`` to ivy_mechanics' ``[x, y, z, w]``.

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar first.
        f: framework name or namespace; inferred from the input if None.

    Returns:
        The same quaternions, scalar last *[batch_shape, 4]*.

    Example:
        >>> wxyz_to_xyzw(np.array([1.0, 0.0, 0.0, 0.0]))
        array([0., 0., 0., 1.])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return xp.concat([quaternion[..., 1:4], quaternion[..., 0:1]], axis=-1)


def xyzw_to_wxyz(quaternion: Array, *, f: Framework = None) -> Array:
    """Reorder ivy_mechanics quaternions ``[x, y, z, w]`` to MuJoCo's ``[w, x, y, z]``.

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar last.
        f: framework name or namespace; inferred from the input if None.

    Returns:
        The same quaternions, scalar first *[batch_shape, 4]*.

    Example:
        >>> xyzw_to_wxyz(np.array([0.0, 0.0, 0.0, 1.0]))
        array([1., 0., 0., 0.])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return xp.concat([quaternion[..., 3:4], quaternion[..., 0:3]], axis=-1)
