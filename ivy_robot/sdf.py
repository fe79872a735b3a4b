"""Signed distance functions of primitives and of MuJoCo scenes, batched and differentiable.

Signed distances are negative inside, zero on the surface, positive outside, exact (not
bounds) for every primitive, with MuJoCo's shape conventions so that a scene's geoms map one to
one: a shape's frame is given by a world-from-shape ``pose`` (*[..., 4, 4]*, identity when None);

- sphere: ``radius`` about ``centre``;
- box: ``half_sizes`` (MuJoCo's box ``size``);
- capsule: the points within ``radius`` of the segment from ``-half_length`` to ``half_length``
  on the shape's z axis (MuJoCo's capsule ``size = (radius, half_length)``);
- cylinder: radius about the z axis, ``|z| <= half_length``;
- plane: the half-space ``z <= 0`` of the shape frame (MuJoCo's infinite plane, normal +z).

Gradients: the norms are ``safe_norm`` (finite at the centre of a sphere and on a capsule's
axis), and the kinks of the box and cylinder (edges, the medial surfaces inside) take one side's
gradient.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

import ivy
from ivy.typing import Array, Framework
from ivy_robot import _arrays as A
from ivy_robot.mjcf import load_mjcf

__all__ = [
    "sphere_sdf",
    "box_sdf",
    "capsule_sdf",
    "cylinder_sdf",
    "plane_sdf",
    "SceneSDF",
]

_PLANE, _SPHERE, _CAPSULE, _CYLINDER, _BOX = 0, 2, 3, 5, 6
_TYPE_NAMES = {_PLANE: "plane", _SPHERE: "sphere", _CAPSULE: "capsule", _CYLINDER: "cylinder",
               _BOX: "box"}  # fmt: skip


def _param(xp, value, like):
    return A.to_backend(xp, value, like)


def _to_local(xp, points, pose):
    """Points in the shape frame: ``R^T (p - t)``."""
    if pose is None:
        return points
    pose = _param(xp, pose, points)
    rot_t = xp.swapaxes(pose[..., 0:3, 0:3], -1, -2)
    return xp.matvec(rot_t, points - pose[..., 0:3, 3])


def _check_points(xp, points, owner):
    if len(points.shape) == 0 or points.shape[-1] != 3:
        raise ValueError(f"{owner}: points must have shape [..., 3], got {tuple(points.shape)}")
    A.check_floating(xp, points, "points", owner)


# ----------------------------------------------------------------------------------------------
# Kernels on points in the shape frame
# ----------------------------------------------------------------------------------------------


def _box_kernel(xp, p, half_sizes):
    q = xp.abs(p) - half_sizes
    outside = xp.safe_norm(xp.maximum(q, xp.zeros_like(q)), axis=-1)
    inside = xp.minimum(xp.max(q, axis=-1), xp.zeros_like(q[..., 0]))
    return outside + inside


def _rect_kernel(xp, u, v):
    """The 2-D box distance of ``(u, v)`` (each already ``|coord| - half_size``)."""
    zero = xp.zeros_like(u)
    outside = xp.safe_hypot(xp.maximum(u, zero), xp.maximum(v, zero))
    return outside + xp.minimum(xp.maximum(u, v), zero)


def _cylinder_kernel(xp, p, radius, half_length):
    radial = xp.safe_norm(p[..., 0:2], axis=-1)
    return _rect_kernel(xp, radial - radius, xp.abs(p[..., 2]) - half_length)


def _capsule_kernel(xp, p, radius, half_length):
    z = xp.minimum(xp.maximum(p[..., 2], -half_length), half_length)
    offset = xp.stack([p[..., 0], p[..., 1], p[..., 2] - z], axis=-1)
    return xp.safe_norm(offset, axis=-1) - radius


def _axial_sdf(kernel, owner, points, radius, half_length, pose, f):
    """A shape about the z axis of its frame (capsule, cylinder), from its public function."""
    xp = ivy.get_framework(points, f=f)
    _check_points(xp, points, owner)
    local = _to_local(xp, points, pose)
    return kernel(xp, local, _param(xp, radius, points), _param(xp, half_length, points))


# ----------------------------------------------------------------------------------------------
# Public primitives
# ----------------------------------------------------------------------------------------------


def sphere_sdf(
    points: Array, centre: Array, radius: Array | float, *, f: Framework = None
) -> Array:
    """Signed distance to a sphere.

    Args:
        points: query points *[batch_shape, 3]*.
        centre: the centre *[3]* (or broadcastable *[batch_shape, 3]*).
        radius: the radius, a number or an array broadcastable with *[batch_shape]*.
        f: framework name or namespace; inferred from ``points`` if None.

    Returns:
        Signed distances *[batch_shape]*.

    Example:
        >>> sphere_sdf(np.array([[2.0, 0.0, 0.0]]), np.zeros(3), 0.5)
        array([1.5])
    """
    xp = ivy.get_framework(points, f=f)
    _check_points(xp, points, "sphere_sdf")
    return xp.safe_norm(points - _param(xp, centre, points), axis=-1) - _param(xp, radius, points)


def box_sdf(
    points: Array, half_sizes: Array, pose: Array | None = None, *, f: Framework = None
) -> Array:
    """Signed distance to a box (exact inside and outside).

    Args:
        points: query points *[batch_shape, 3]*.
        half_sizes: half the side lengths *[3]* (MuJoCo's box ``size``).
        pose: world from box *[4, 4]* (or broadcastable *[batch_shape, 4, 4]*); identity if None.
        f: framework name or namespace; inferred from ``points`` if None.

    Returns:
        Signed distances *[batch_shape]*.

    Example:
        >>> box_sdf(np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]), np.ones(3))
        array([-1.,  1.])
    """
    xp = ivy.get_framework(points, f=f)
    _check_points(xp, points, "box_sdf")
    return _box_kernel(xp, _to_local(xp, points, pose), _param(xp, half_sizes, points))


def capsule_sdf(
    points: Array,
    radius: Array | float,
    half_length: Array | float,
    pose: Array | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Signed distance to a capsule along the shape frame's z axis.

    Args:
        points: query points *[batch_shape, 3]*.
        radius: the radius.
        half_length: half the length of the axis segment (MuJoCo's capsule ``size[1]``).
        pose: world from capsule *[4, 4]*; identity if None.
        f: framework name or namespace; inferred from ``points`` if None.

    Returns:
        Signed distances *[batch_shape]*.

    Example:
        >>> capsule_sdf(np.array([[0.0, 0.0, 2.0]]), 0.5, 1.0)
        array([0.5])
    """
    return _axial_sdf(_capsule_kernel, "capsule_sdf", points, radius, half_length, pose, f)


def cylinder_sdf(
    points: Array,
    radius: Array | float,
    half_length: Array | float,
    pose: Array | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Signed distance to a solid cylinder along the shape frame's z axis.

    Args:
        points: query points *[batch_shape, 3]*.
        radius: the radius.
        half_length: half the height (MuJoCo's cylinder ``size[1]``).
        pose: world from cylinder *[4, 4]*; identity if None.
        f: framework name or namespace; inferred from ``points`` if None.

    Returns:
        Signed distances *[batch_shape]*.

    Example:
        >>> cylinder_sdf(np.array([[3.0, 4.0, 0.0]]), 1.0, 1.0)
        array([4.])
    """
    return _axial_sdf(_cylinder_kernel, "cylinder_sdf", points, radius, half_length, pose, f)


def plane_sdf(points: Array, pose: Array | None = None, *, f: Framework = None) -> Array:
    """Signed distance to the plane ``z = 0`` of the shape frame (positive on the +z side).

    Args:
        points: query points *[batch_shape, 3]*.
        pose: world from plane *[4, 4]*; identity (the world's ground plane) if None.
        f: framework name or namespace; inferred from ``points`` if None.

    Returns:
        Signed distances *[batch_shape]*.

    Example:
        >>> plane_sdf(np.array([[1.0, 2.0, 3.0]]))
        array([3.])
    """
    xp = ivy.get_framework(points, f=f)
    _check_points(xp, points, "plane_sdf")
    return _to_local(xp, points, pose)[..., 2]


# ----------------------------------------------------------------------------------------------
# Scenes
# ----------------------------------------------------------------------------------------------


class SceneSDF:
    """The signed distance to a set of primitives with constant poses: the static geoms of a
    MuJoCo scene (:meth:`from_mjcf`), or shapes given directly.

    Args:
        names: a name per shape.
        types: ``"plane"``, ``"sphere"``, ``"capsule"``, ``"cylinder"`` or ``"box"`` per shape.
        sizes: MuJoCo ``size`` per shape *[num_shapes, 3]* (sphere: radius; capsule and
            cylinder: radius, half length; box: half sizes; plane: unused).
        poses: world-from-shape poses *[num_shapes, 4, 4]* (numpy).

    Example:
        >>> scene = SceneSDF(["ball", "floor"], ["sphere", "plane"], [[0.5, 0, 0], [0, 0, 0]],
        ...                  [np.eye(4), np.eye(4)])
        >>> scene(np.array([[0.0, 0.0, 2.0], [0.0, 0.0, 0.1]]))     # min over the shapes
        array([ 1.5, -0.4])
    """

    def __init__(
        self,
        names: Sequence[str],
        types: Sequence[str],
        sizes: np.ndarray,
        poses: np.ndarray,
    ) -> None:
        known = {v: k for k, v in _TYPE_NAMES.items()}
        bad = [(n, t) for n, t in zip(names, types) if t not in known]
        if bad:
            raise ValueError(f"SceneSDF: unsupported shape types {bad}; supported: {sorted(known)}")
        if not names:
            raise ValueError("SceneSDF: the scene has no shapes")
        sizes = np.asarray(sizes, dtype=np.float64).reshape(len(names), 3)
        poses = np.asarray(poses, dtype=np.float64).reshape(len(names), 4, 4)
        codes = np.asarray([known[t] for t in types])
        # group the shapes by type: the distances come out grouped, in this order
        order = np.argsort(codes, kind="stable")
        self.names = tuple(names[i] for i in order)
        self.types = tuple(types[i] for i in order)
        self.sizes, self.poses = sizes[order], poses[order]
        self._groups = []
        for code in sorted(set(codes.tolist())):
            index = np.flatnonzero(codes[order] == code)
            self._groups.append((code, int(index[0]), int(index[-1]) + 1))
        self._consts = {
            "rot_t": np.ascontiguousarray(np.swapaxes(self.poses[:, 0:3, 0:3], -1, -2)),
            "pos": np.ascontiguousarray(self.poses[:, 0:3, 3]),
            "sizes": self.sizes,
        }

    @classmethod
    def from_mjcf(cls, source: Any, *, exclude: Sequence[str] = ()) -> SceneSDF:
        """The static geoms of an MJCF model (those of bodies welded to the world, not mocap).

        Args:
            source: a path, an MJCF XML string or a ``mujoco.MjModel``.
            exclude: names of geoms, or of bodies whose geoms, to leave out (a robot's own base,
                a mesh the SDF cannot represent).

        Returns:
            The scene.

        Raises:
            ValueError: a static geom of an unsupported type (ellipsoid, mesh, height field,
                SDF), unless excluded; or no static geom at all.

        Example:
            >>> post = '<geom name="post" type="box" pos="0.6 0 0.2" size="0.06 0.06 0.2"/>'
            >>> SceneSDF.from_mjcf(panda_mjcf(post), exclude=["link0"])   # not the arm's base
            SceneSDF(1 box)
        """
        import mujoco

        model = load_mjcf(source)
        data = mujoco.MjData(model)
        mujoco.mj_kinematics(model, data)
        excluded = set(exclude)
        body_names = [model.body(i).name for i in range(model.nbody)]
        known = set(body_names) | {model.geom(g).name for g in range(model.ngeom)}
        unknown = sorted(excluded - known)
        if unknown:
            raise ValueError(f"SceneSDF.from_mjcf: exclude names no geom or body: {unknown}")
        moving = set()
        for b in range(1, model.nbody):
            parent = int(model.body_parentid[b])
            if parent in moving or model.body_jntnum[b] > 0 or model.body_mocapid[b] >= 0:
                moving.add(b)
        names, types, sizes, poses, unsupported = [], [], [], [], []
        for g in range(model.ngeom):
            body = int(model.geom_bodyid[g])
            name = model.geom(g).name or f"geom{g}"
            if body in moving or name in excluded or body_names[body] in excluded:
                continue
            code = int(model.geom_type[g])
            if code not in _TYPE_NAMES:
                unsupported.append(f"{name} ({mujoco.mjtGeom(code).name})")
                continue
            pose = np.eye(4)
            pose[0:3, 0:3] = data.geom_xmat[g].reshape(3, 3)
            pose[0:3, 3] = data.geom_xpos[g]
            names.append(name), types.append(_TYPE_NAMES[code])
            sizes.append(model.geom_size[g]), poses.append(pose)
        if unsupported:
            raise ValueError(
                f"SceneSDF.from_mjcf: static geoms of unsupported types: {unsupported}; the "
                "scene SDF supports planes, spheres, capsules, cylinders and boxes; pass their "
                "names (or their bodies') in exclude= to leave them out"
            )
        if not names:
            raise ValueError("SceneSDF.from_mjcf: the model has no static geom")
        return cls(names, types, np.asarray(sizes), np.asarray(poses))

    @property
    def num_shapes(self) -> int:
        """The number of shapes."""
        return len(self.names)

    def distances(self, points: Array, *, f: Framework = None) -> Array:
        """Signed distances from every point to every shape.

        Args:
            points: query points *[batch_shape, 3]*.
            f: framework name or namespace; inferred from ``points`` if None.

        Returns:
            *[batch_shape, num_shapes]*, shapes in the order of ``self.names``.

        Example:
            >>> scene = SceneSDF(["ball", "floor"], ["sphere", "plane"], [[0.5, 0, 0], [0, 0, 0]],
            ...                  [np.eye(4), np.eye(4)])
            >>> scene.distances(np.array([[0.0, 0.0, 2.0]]))   # shapes in scene.names' order
            array([[2. , 1.5]])
            >>> scene.names
            ('floor', 'ball')
        """
        xp = ivy.get_framework(points, f=f)
        _check_points(xp, points, "SceneSDF")
        c = A.constants(xp, points, self._consts)
        local = xp.matvec(c["rot_t"], points[..., None, :] - c["pos"])
        parts = []
        for code, lo, hi in self._groups:
            p, size = local[..., lo:hi, :], c["sizes"][lo:hi]
            if code == _PLANE:
                parts.append(p[..., 2])
            elif code == _SPHERE:
                parts.append(xp.safe_norm(p, axis=-1) - size[:, 0])
            elif code == _CAPSULE:
                parts.append(_capsule_kernel(xp, p, size[:, 0], size[:, 1]))
            elif code == _CYLINDER:
                parts.append(_cylinder_kernel(xp, p, size[:, 0], size[:, 1]))
            else:
                parts.append(_box_kernel(xp, p, size))
        return parts[0] if len(parts) == 1 else xp.concat(parts, axis=-1)

    def __call__(self, points: Array, *, f: Framework = None) -> Array:
        """The scene's signed distance: the smallest over its shapes.

        Args:
            points: query points *[batch_shape, 3]*.
            f: framework name or namespace; inferred from ``points`` if None.

        Returns:
            *[batch_shape]*.

        Example:
            >>> scene = SceneSDF(["ball"], ["sphere"], [[0.5, 0, 0]], [np.eye(4)])
            >>> scene(np.zeros((5, 3))).shape
            (5,)
        """
        xp = ivy.get_framework(points, f=f)
        return xp.min(self.distances(points, f=xp), axis=-1)

    def __repr__(self) -> str:
        counts = {t: self.types.count(t) for t in dict.fromkeys(self.types)}
        return f"SceneSDF({', '.join(f'{n} {t}' for t, n in counts.items())})"
