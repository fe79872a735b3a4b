"""Serial manipulators from Denavit-Hartenberg parameters, written once for every backend.

Two conventions, for a revolute joint ``i`` with parameters ``a_i``, ``d_i``, ``alpha_i`` and the
DH angle ``theta_i = joint_scales_i * q_i + joint_offsets_i``:

- ``"standard"`` (Denavit-Hartenberg; Siciliano et al., *Robotics: Modelling, Planning and
  Control*, 2.8.2): ``A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)``;
- ``"modified"`` (Craig, *Introduction to Robotics*, 3.4; the table Franka publishes for the
  Panda): ``A_i = Rx(alpha_i) Tx(a_i) Rz(theta_i) Tz(d_i)``, where ``a_i`` and ``alpha_i`` are
  those of the link *before* joint ``i``.

Frame 0 is the base (``base_pose``, world from base); frame ``i`` is ``base_pose A_1 ... A_i``; the
end effector is frame ``n`` composed with ``tool_pose``.

Each ``A_i`` is linear in ``cos(theta_i)`` and ``sin(theta_i)``: ``A_i = M0_i + cos * Mc_i +
sin * Ms_i`` with constant matrices, so all link transforms of a batch come from five array
operations, and the chain from ``n`` matrix products.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

import ivy
from ivy.typing import Array, Framework
from ivy_robot import _arrays as A

__all__ = ["Manipulator", "PandaModel", "MicoModel"]


def _as_vector(values, n: int | None, name: str) -> np.ndarray:
    v = np.asarray(values, dtype=np.float64).reshape(-1)
    if n is not None and v.shape[0] != n:
        raise ValueError(f"Manipulator: {name} has {v.shape[0]} entries; give one per joint ({n})")
    return v


def _as_pose(pose, name: str) -> np.ndarray:
    if pose is None:
        return np.eye(4)
    pose = np.asarray(pose, dtype=np.float64)
    if pose.shape == (3, 4):
        pose = np.concatenate([pose, [[0.0, 0.0, 0.0, 1.0]]])
    if pose.shape != (4, 4):
        raise ValueError(f"Manipulator: {name} must be a 4x4 (or 3x4) pose, got {pose.shape}")
    return pose


class Manipulator:
    """A serial arm of revolute joints described by DH parameters.

    Args:
        a: link lengths ``a_i`` *[num_joints]* (metres).
        d: link offsets ``d_i`` *[num_joints]*.
        alpha: link twists ``alpha_i`` *[num_joints]* (radians).
        convention: ``"standard"`` or ``"modified"`` DH (see the module docstring).
        joint_offsets: added to the scaled joint angles: ``theta = scales * q + offsets``.
        joint_scales: multiply the joint angles (e.g. -1 for a joint turning the other way).
        base_pose: world from base *[4, 4]* (numpy); identity by default.
        tool_pose: last link frame to end effector *[4, 4]*; identity by default.
        joint_limits: ``(lower, upper)`` per joint (radians), for planners; unlimited by default.

    Example:
        >>> arm = Manipulator([0.0, 0.3], [0.1, 0.0], [math.pi / 2, 0.0])
        >>> arm.end_effector_pose(np.zeros((8, 2))).shape   # or torch, jax, tf arrays
        (8, 4, 4)
    """

    def __init__(
        self,
        a: Sequence[float],
        d: Sequence[float],
        alpha: Sequence[float],
        *,
        convention: str = "standard",
        joint_offsets: Sequence[float] | None = None,
        joint_scales: Sequence[float] | None = None,
        base_pose: np.ndarray | None = None,
        tool_pose: np.ndarray | None = None,
        joint_limits: tuple[Sequence[float], Sequence[float]] | None = None,
    ) -> None:
        if convention not in ("standard", "modified"):
            raise ValueError(
                f"Manipulator: convention must be 'standard' or 'modified', got {convention!r}"
            )
        self.a = _as_vector(a, None, "a")
        n = self.num_joints = int(self.a.shape[0])
        if n == 0:
            raise ValueError("Manipulator: give at least one joint")
        self.d = _as_vector(d, n, "d")
        self.alpha = _as_vector(alpha, n, "alpha")
        self.convention = convention
        self.joint_offsets = _as_vector(
            np.zeros(n) if joint_offsets is None else joint_offsets, n, "joint_offsets"
        )
        self.joint_scales = _as_vector(
            np.ones(n) if joint_scales is None else joint_scales, n, "joint_scales"
        )
        self.base_pose = _as_pose(base_pose, "base_pose")
        self.tool_pose = _as_pose(tool_pose, "tool_pose")
        if joint_limits is None:
            self.joint_lower, self.joint_upper = np.full(n, -np.inf), np.full(n, np.inf)
        else:
            self.joint_lower = _as_vector(joint_limits[0], n, "joint_limits[0]")
            self.joint_upper = _as_vector(joint_limits[1], n, "joint_limits[1]")
        # distance between consecutive frame origins (constant for revolute joints)
        self.link_lengths = np.hypot(self.a, self.d)
        self._consts = self._link_constants()
        self._weights = {}  # sample_links interpolation weights, by samples_per_metre

    def _link_constants(self) -> dict:
        n, a, d = self.num_joints, self.a, self.d
        ca, sa = np.cos(self.alpha), np.sin(self.alpha)
        m0, mc, ms = np.zeros((n, 4, 4)), np.zeros((n, 4, 4)), np.zeros((n, 4, 4))
        m0[:, 3, 3] = 1.0
        if self.convention == "standard":
            mc[:, 0, 0], mc[:, 0, 3], mc[:, 1, 1], mc[:, 1, 2] = 1.0, a, ca, -sa
            ms[:, 0, 1], ms[:, 0, 2], ms[:, 1, 0], ms[:, 1, 3] = -ca, sa, 1.0, a
            m0[:, 2, 1], m0[:, 2, 2], m0[:, 2, 3] = sa, ca, d
        else:
            mc[:, 0, 0], mc[:, 1, 1], mc[:, 2, 1] = 1.0, ca, sa
            ms[:, 0, 1], ms[:, 1, 0], ms[:, 2, 0] = -1.0, ca, sa
            m0[:, 0, 3], m0[:, 1, 2], m0[:, 1, 3] = a, -sa, -sa * d
            m0[:, 2, 2], m0[:, 2, 3] = ca, ca * d
        return {
            "m0": m0,
            "mc": mc,
            "ms": ms,
            "scales": self.joint_scales,
            "offsets": self.joint_offsets,
            "base": self.base_pose,
            "tool": self.tool_pose,
        }

    def _check(self, xp, q) -> None:
        meaning = f"{self.num_joints} joint angles"
        A.check_last_axis(xp, q, self.num_joints, "joint_angles", "Manipulator", meaning)

    def _chain(self, xp, q, c):
        theta = q * c["scales"] + c["offsets"]
        links = (
            c["m0"]
            + xp.cos(theta)[..., None, None] * c["mc"]
            + xp.sin(theta)[..., None, None] * (c["ms"])
        )
        frames = [A.broadcast_leading(xp, c["base"], q, 1)]
        for i in range(self.num_joints):
            frames.append(xp.matmul(frames[-1], links[..., i, :, :]))
        return frames

    def link_matrices(self, joint_angles: Array, *, f: Framework = None) -> Array:
        """World poses of the base and of every link frame.

        Args:
            joint_angles: joint angles *[batch_shape, num_joints]* (radians).
            f: framework name or namespace; inferred from ``joint_angles`` if None.

        Returns:
            *[batch_shape, num_joints + 1, 4, 4]*: the base pose, then frames 1 to n.

        Example:
            >>> PandaModel().link_matrices(np.zeros(7)).shape
            (8, 4, 4)
        """
        xp = ivy.get_framework(joint_angles, f=f)
        self._check(xp, joint_angles)
        c = A.constants(xp, joint_angles, self._consts)
        return xp.stack(self._chain(xp, joint_angles, c), axis=-3)

    def end_effector_pose(self, joint_angles: Array, *, f: Framework = None) -> Array:
        """World pose of the end effector: frame n composed with ``tool_pose``.

        Args:
            joint_angles: joint angles *[batch_shape, num_joints]*.
            f: framework name or namespace; inferred from ``joint_angles`` if None.

        Returns:
            *[batch_shape, 4, 4]*.

        Example:
            >>> PandaModel().end_effector_pose(np.zeros(7))[:3, 3].round(4) + 0.0
            array([0.088, 0.   , 0.926])
        """
        xp = ivy.get_framework(joint_angles, f=f)
        self._check(xp, joint_angles)
        c = A.constants(xp, joint_angles, self._consts)
        return xp.matmul(self._chain(xp, joint_angles, c)[-1], c["tool"])

    def sample_links(
        self, joint_angles: Array, samples_per_metre: float = 25.0, *, f: Framework = None
    ) -> Array:
        """Points along the segments joining consecutive frame origins (base, links 1 to n,
        then the tool), for collision costs.

        Each segment of length ``L`` gets ``ceil(L * samples_per_metre)`` evenly spaced points
        from its start (its end is the next segment's start); the tool point closes the chain.
        Zero-length segments add no point.

        Args:
            joint_angles: joint angles *[batch_shape, num_joints]*.
            samples_per_metre: sampling density.
            f: framework name or namespace; inferred from ``joint_angles`` if None.

        Returns:
            World positions *[batch_shape, num_samples, 3]*, ``num_samples`` as
            :meth:`num_link_samples` says.

        Example:
            >>> PandaModel().sample_links(np.zeros(7), 25).shape
            (37, 3)
        """
        xp = ivy.get_framework(joint_angles, f=f)
        self._check(xp, joint_angles)
        c = A.constants(xp, joint_angles, self._consts)
        frames = self._chain(xp, joint_angles, c)
        tool = xp.matmul(frames[-1], c["tool"])
        origins = xp.stack([m[..., 0:3, 3] for m in frames + [tool]], axis=-2)
        weights = A.constant(xp, self._sample_weights(samples_per_metre), joint_angles)
        return xp.matmul(weights, origins)

    def num_link_samples(self, samples_per_metre: float = 25.0) -> int:
        """The number of points :meth:`sample_links` returns.

        Args:
            samples_per_metre: sampling density.

        Returns:
            The count.

        Example:
            >>> PandaModel().num_link_samples(25)
            37
        """
        return len(self._sample_weights(samples_per_metre))

    def _sample_weights(self, samples_per_metre: float) -> np.ndarray:
        """Interpolation weights *[num_samples, num_joints + 2]* over the frame origins (numpy,
        computed once per density)."""
        if samples_per_metre <= 0:
            raise ValueError(
                f"sample_links: samples_per_metre must be positive, got {samples_per_metre}"
            )
        if samples_per_metre in self._weights:
            return self._weights[samples_per_metre]
        lengths = [float(v) for v in self.link_lengths]
        lengths.append(float(np.linalg.norm(self.tool_pose[0:3, 3])))
        width = len(lengths) + 1
        rows = []
        for i, length in enumerate(lengths):
            count = math.ceil(length * samples_per_metre - 1e-9)
            for k in range(count if length > 0 else 0):
                row = [0.0] * width
                row[i], row[i + 1] = 1.0 - k / count, k / count
                rows.append(row)
        rows.append([0.0] * (width - 1) + [1.0])
        self._weights[samples_per_metre] = np.asarray(rows)
        return self._weights[samples_per_metre]


class PandaModel(Manipulator):
    """The Franka Emika Panda, from the modified DH table Franka publishes (robot and
    interface specifications: a, d, alpha per joint, and the flange ``d = 0.107`` as the
    tool), with its joint limits.

    Args:
        base_pose: world from base *[4, 4]*; identity by default.
        tool_pose: flange to end effector, composed after the flange; identity by default.

    Example:
        >>> PandaModel().end_effector_pose(np.zeros(7))[:3, 3].round(3) + 0.0
        array([0.088, 0.   , 0.926])
    """

    DH_A = (0.0, 0.0, 0.0, 0.0825, -0.0825, 0.0, 0.088)
    DH_D = (0.333, 0.0, 0.316, 0.0, 0.384, 0.0, 0.0)
    DH_ALPHA = (0.0, -math.pi / 2, math.pi / 2, math.pi / 2, -math.pi / 2, math.pi / 2, math.pi / 2)
    LOWER = (-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973)
    UPPER = (2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973)
    FLANGE = 0.107

    def __init__(self, base_pose: np.ndarray | None = None, tool_pose: np.ndarray | None = None):
        flange = np.eye(4)
        flange[2, 3] = self.FLANGE
        super().__init__(
            self.DH_A,
            self.DH_D,
            self.DH_ALPHA,
            convention="modified",
            base_pose=base_pose,
            tool_pose=flange @ _as_pose(tool_pose, "tool_pose"),
            joint_limits=(self.LOWER, self.UPPER),
        )


class MicoModel(Manipulator):
    """The Kinova Mico (6 DOF), from the standard DH parameters of Kinova's user guide, with the
    joint directions and zero positions of its actuators (``theta = scales * q + offsets``).

    Args:
        base_pose: world from base *[4, 4]*; identity by default.
        tool_pose: last link to end effector; identity by default.

    Example:
        >>> MicoModel().link_matrices(np.zeros(6)).shape
        (7, 4, 4)
    """

    def __init__(self, base_pose: np.ndarray | None = None, tool_pose: np.ndarray | None = None):
        d1, d2, d3, d4, d5, d6, e2 = 0.2755, 0.29, 0.1233, 0.0741, 0.0741, 0.16, 0.007
        aa = math.pi / 6  # the wrist's 60 degree bends are 2 * aa
        ratio = math.sin(aa) / math.sin(2 * aa)
        d4b = d3 + ratio * d4
        d5b = ratio * (d4 + d5)
        d6b = ratio * d5 + d6
        super().__init__(
            (0.0, d2, 0.0, 0.0, 0.0, 0.0),
            (d1, 0.0, -e2, -d4b, -d5b, -d6b),
            (math.pi / 2, math.pi, math.pi / 2, 2 * aa, 2 * aa, math.pi),
            convention="standard",
            joint_scales=(-1.0, 1.0, 1.0, 1.0, 1.0, 1.0),
            joint_offsets=(0.0, -math.pi / 2, math.pi / 2, 0.0, -math.pi, math.pi / 2),
            base_pose=base_pose,
            tool_pose=tool_pose,
        )
