"""CHOMP-style trajectory optimisation on spline paths, for an arm (joint space) and for a rigid
mobile body such as a drone (pose space).

A path is a spline (:func:`ivy_robot.sample_spline_path`) through fixed start and goal values and
a few free interior anchors; sampling it at fixed times is one matrix product with constant
weights (:func:`ivy_robot.spline_weights`). The cost of the anchors is

- smoothness: ``sum_t |x_{t+1} - x_t|**2 * (T - 1)``, the finite-difference estimate of
  ``integral |dx/ds|**2 ds`` over the path parameter ``s`` in [0, 1];
- obstacles: CHOMP's smoothed hinge ``c(d)`` (Ratliff et al., 2009) of the clearance ``d`` of
  every collision sphere (scene SDF at its centre minus its radius) at every sample, averaged
  over samples and summed over spheres: ``-d + eps / 2`` inside, ``(d - eps)**2 / (2 eps)``
  within the margin ``eps``, 0 beyond;
- joint limits (arm): the squared distance beyond ``[lower, upper]`` summed over joints and
  averaged over samples;

weighted and summed. The anchors descend its gradient (``ivy.execute_with_gradients`` and an
ivy optimizer, Adam by default), one compiled step (``ivy.compile_fn``) per iteration. Both
planners need a backend with gradients (torch, jax, tensorflow); numpy raises ivy's
``UnsupportedError``.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

import ivy
import ivy_mechanics as mech
from ivy.typing import Array, Framework
from ivy_robot import _arrays as A
from ivy_robot.kinematic_tree import BodySpheres, KinematicTree
from ivy_robot.manipulator import Manipulator
from ivy_robot.rigid_mobile import RigidMobile
from ivy_robot.splines import spline_weights

__all__ = [
    "smoothness_cost",
    "obstacle_cost",
    "joint_limit_cost",
    "TrajectoryResult",
    "ArmPlanner",
    "DronePlanner",
]


def smoothness_cost(path: Array, *, f: Framework = None) -> Array:
    """The squared length of the path's velocity: ``sum_t |x_{t+1} - x_t|**2 * (T - 1)``.

    Args:
        path: samples *[batch_shape, num_samples, dim]*, evenly spaced in the path parameter.
        f: framework name or namespace; inferred from ``path`` if None.

    Returns:
        *[batch_shape]*; for a straight path at constant speed, the squared distance between
        its ends.

    Example:
        >>> float(smoothness_cost(np.linspace(0, 1, 11)[:, None]))
        1.0
    """
    xp = ivy.get_framework(path, f=f)
    steps = path[..., 1:, :] - path[..., :-1, :]
    return xp.sum(steps * steps, axis=(-2, -1)) * float(path.shape[-2] - 1)


def obstacle_cost(clearance: Array, margin: float, *, f: Framework = None) -> Array:
    """CHOMP's smoothed hinge of the clearance, elementwise.

    Args:
        clearance: signed clearances (negative in collision), any shape.
        margin: ``eps > 0``: the cost reaches 0 at clearance ``eps``.
        f: framework name or namespace; inferred from ``clearance`` if None.

    Returns:
        ``-d + eps / 2`` for ``d < 0``, ``(d - eps)**2 / (2 eps)`` for ``0 <= d <= eps``, else 0;
        continuous with a continuous gradient.

    Example:
        >>> obstacle_cost(np.array([-0.1, 0.05, 0.2]), 0.1)
        array([0.15  , 0.0125, 0.    ])
    """
    if margin <= 0:
        raise ValueError(f"obstacle_cost: margin must be positive, got {margin}")
    xp = ivy.get_framework(clearance, f=f)
    inside = -clearance + 0.5 * margin
    near = xp.minimum(clearance - margin, xp.zeros_like(clearance))
    near = near * near * (0.5 / margin)
    return xp.where(clearance < 0, inside, near)


def joint_limit_cost(q: Array, lower: Array, upper: Array, *, f: Framework = None) -> Array:
    """The squared violation of joint limits, summed over the last axis.

    Args:
        q: joint positions *[batch_shape, n]*.
        lower: lower limits *[n]* (``-inf`` where unlimited).
        upper: upper limits *[n]* (``inf`` where unlimited).
        f: framework name or namespace; inferred from ``q`` if None.

    Returns:
        *[batch_shape]*.

    Example:
        >>> float(joint_limit_cost(np.array([0.5, 2.0]), np.zeros(2), np.ones(2)))
        1.0
    """
    xp = ivy.get_framework(q, f=f)
    zero = xp.zeros_like(q)
    below = xp.maximum(_as(xp, lower, q) - q, zero)
    above = xp.maximum(q - _as(xp, upper, q), zero)
    return xp.sum(below * below + above * above, axis=-1)


def _as(xp, value, like):
    return A.to_backend(xp, value, like)


class TrajectoryResult(NamedTuple):
    """The outcome of a planner.

    Attributes:
        anchors: the optimised interior anchors *[num_anchors, dim]* (backend array).
        path: the path at the planner's samples *[num_samples, dim]* (backend array).
        costs: the cost of the anchors each iteration started from (numpy, ``iterations``).
    """

    anchors: Array
    path: Array
    costs: np.ndarray


class _SplinePlanner:
    """Shared machinery: spline weights, cost assembly, the optimisation loop."""

    dim: int

    def __init__(self, scene, *, num_anchors, num_samples, order, method, margin, weights):
        if num_anchors < 1 or num_samples < 2:
            raise ValueError("planner: give num_anchors >= 1 and num_samples >= 2")
        self.scene = scene
        self.num_anchors, self.num_samples = int(num_anchors), int(num_samples)
        self.margin = float(margin)
        self.weights = {"smoothness": 1.0, "obstacle": 100.0, "limits": 100.0, **(weights or {})}
        unknown = set(self.weights) - {"smoothness", "obstacle", "limits"}
        if unknown:
            raise ValueError(f"planner: unknown cost weights {sorted(unknown)}")
        anchor_times = np.linspace(0.0, 1.0, self.num_anchors + 2)[:, None]
        self.sample_times = np.linspace(0.0, 1.0, self.num_samples)
        self.path_weights = np.asarray(
            spline_weights(anchor_times, self.sample_times[:, None], order, method=method)
        )
        self._anchor_times, self._order, self._method = anchor_times, order, method
        self._interior_times = anchor_times[1:-1]

    # -- what a subclass provides -------------------------------------------------------------

    def _sphere_centres(self, xp, path):  # [num_samples, num_spheres, 3]
        raise NotImplementedError

    def _radii(self) -> list:
        raise NotImplementedError

    def _limits_cost(self, xp, path):
        return None

    # -- paths and costs ----------------------------------------------------------------------

    def _check_ends(self, xp, start, goal):
        for name, value in (("start", start), ("goal", goal)):
            if tuple(value.shape) != (self.dim,):
                raise ValueError(
                    f"{type(self).__name__}: {name} must have shape ({self.dim},), got "
                    f"{tuple(value.shape)}"
                )
            A.check_floating(xp, value, name, type(self).__name__)

    def initial_anchors(self, start: Array, goal: Array, *, f: Framework = None) -> Array:
        """Interior anchors on the straight line from start to goal.

        Args:
            start: the start *[dim]*.
            goal: the goal *[dim]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[num_anchors, dim]*.

        Example:
            >>> planner.initial_anchors(start, goal).shape   # planner: the drone of DronePlanner
            (3, 6)
        """
        xp = ivy.get_framework(start, goal, f=f)
        self._check_ends(xp, start, goal)
        t = A.constant(xp, self._interior_times, start)
        return start + t * (goal - start)

    def path(
        self,
        anchors: Array,
        start: Array,
        goal: Array,
        num_samples: int | None = None,
        *,
        f: Framework = None,
    ) -> Array:
        """The path through start, the anchors and goal.

        Args:
            anchors: interior anchors *[num_anchors, dim]*.
            start: the start *[dim]*.
            goal: the goal *[dim]*.
            num_samples: evenly spaced samples; the planner's own when None (a denser
                resampling for collision checks otherwise).
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[num_samples, dim]*.

        Example:
            >>> anchors = planner.initial_anchors(start, goal)
            >>> planner.path(anchors, start, goal).shape, planner.path(anchors, start, goal, 500).shape
            ((48, 6), (500, 6))
        """
        xp = ivy.get_framework(anchors, start, goal, f=f)
        if num_samples is None or num_samples == self.num_samples:
            weights = A.constant(xp, self.path_weights, anchors)
        else:
            times = np.linspace(0.0, 1.0, int(num_samples))[:, None]
            weights = np.asarray(
                spline_weights(self._anchor_times, times, self._order, method=self._method)
            )
        values = xp.concat([start[None], anchors, goal[None]], axis=0)
        return xp.matmul(_as(xp, weights, anchors), values)

    def cost_terms(self, anchors: Array, start: Array, goal: Array, *, f: Framework = None):
        """The weighted cost terms of the anchors.

        Args:
            anchors: interior anchors *[num_anchors, dim]*.
            start: the start *[dim]*.
            goal: the goal *[dim]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            ``{'smoothness': ..., 'obstacle': ..., 'limits': ...}`` of 0-d arrays (weighted).

        Example:
            >>> terms = planner.cost_terms(planner.initial_anchors(start, goal), start, goal)
            >>> sorted(terms)
            ['obstacle', 'smoothness']
        """
        xp = ivy.get_framework(anchors, start, goal, f=f)
        path = self.path(anchors, start, goal, f=xp)
        centres = self._sphere_centres(xp, path)
        clearance = self.scene(centres, f=xp) - A.constant(xp, self._radii(), path)
        obstacle = xp.sum(xp.mean(obstacle_cost(clearance, self.margin, f=xp), axis=0))
        terms = {
            "smoothness": self.weights["smoothness"] * smoothness_cost(path, f=xp),
            "obstacle": self.weights["obstacle"] * obstacle,
        }
        limits = self._limits_cost(xp, path)
        if limits is not None:
            terms["limits"] = self.weights["limits"] * limits
        return terms

    def cost(self, anchors: Array, start: Array, goal: Array, *, f: Framework = None) -> Array:
        """The total cost of the anchors (the sum of :meth:`cost_terms`).

        Args:
            anchors: interior anchors *[num_anchors, dim]*.
            start: the start *[dim]*.
            goal: the goal *[dim]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            A 0-d array.

        Example:
            >>> float(planner.cost(planner.initial_anchors(start, goal), start, goal)) > 0
            True
        """
        xp = ivy.get_framework(anchors, start, goal, f=f)
        terms = self.cost_terms(anchors, start, goal, f=xp)
        total = terms["smoothness"]
        for key in ("obstacle", "limits"):
            if key in terms:
                total = total + terms[key]
        return total

    def step_fn(self, optimizer: Any, *, compile: bool = True):
        """One optimisation step ``(anchors, state, start, goal) -> (cost, anchors, state)``:
        the cost and its gradient by ``ivy.execute_with_gradients``, then ``optimizer.step``.

        Args:
            optimizer: an ivy optimizer (``ivy.Adam``, ``ivy.SGD``, ...).
            compile: wrap the step with ``ivy.compile_fn``.

        Returns:
            The step function (compiled on its first call).

        Example:
            >>> import torch
            >>> optimizer = ivy.Adam(0.05)
            >>> step = planner.step_fn(optimizer, compile=False)
            >>> anchors = planner.initial_anchors(torch.tensor(start), torch.tensor(goal))
            >>> state = optimizer.init({"anchors": anchors})
            >>> cost, anchors, state = step(anchors, state, torch.tensor(start), torch.tensor(goal))
        """

        def step(anchors, state, start, goal):
            cost, grads = ivy.execute_with_gradients(
                lambda v: self.cost(v["anchors"], start, goal), {"anchors": anchors}
            )[:2]
            new, state = optimizer.step({"anchors": anchors}, grads, state)
            return cost, new["anchors"], state

        return ivy.compile_fn(step) if compile else step

    def optimise(
        self,
        start: Array,
        goal: Array,
        iterations: int = 100,
        *,
        optimizer: Any = None,
        lr: float = 0.05,
        anchors: Array | None = None,
        compile: bool = True,
        f: Framework = None,
    ) -> TrajectoryResult:
        """Optimise the interior anchors from the straight line (or ``anchors``).

        Args:
            start: the start *[dim]* (fixed).
            goal: the goal *[dim]* (fixed).
            iterations: gradient steps.
            optimizer: an ivy optimizer; ``ivy.Adam(lr)`` by default.
            lr: the learning rate of the default optimizer.
            anchors: initial interior anchors *[num_anchors, dim]*; the straight line if None.
            compile: compile the step with ``ivy.compile_fn``.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            :class:`TrajectoryResult`: anchors, path and the cost per iteration.

        Example:
            >>> import torch
            >>> result = planner.optimise(torch.tensor(start), torch.tensor(goal), 30, compile=False)
            >>> bool(result.costs[-1] < result.costs[0])
            True
        """
        xp = ivy.get_framework(start, goal, f=f)
        self._check_ends(xp, start, goal)
        if anchors is None:
            anchors = self.initial_anchors(start, goal, f=xp)
        optimizer = ivy.Adam(lr) if optimizer is None else optimizer
        state = optimizer.init({"anchors": anchors})
        step = self.step_fn(optimizer, compile=compile)
        costs = []
        for _ in range(int(iterations)):
            cost, anchors, state = step(anchors, state, start, goal)
            costs.append(cost)
        costs = np.asarray([float(ivy.to_numpy(c)) for c in costs])
        return TrajectoryResult(anchors, self.path(anchors, start, goal, f=xp), costs)


class ArmPlanner(_SplinePlanner):
    """Joint-space trajectory optimisation for an arm.

    The arm is a :class:`KinematicTree` (collision spheres from its own capsule, cylinder and
    sphere geoms, or given) or a DH :class:`Manipulator` (points along its links, each with
    ``link_radius``). The joint path is a spline through the start, ``num_anchors`` interior
    anchors and the goal.

    Args:
        robot: a :class:`KinematicTree` (joint space: its qpos, of hinges and slides) or a
            :class:`Manipulator`.
        scene: a :class:`ivy_robot.SceneSDF` (or any callable ``points [..., 3] -> [...]``
            accepting ``f=``).
        num_anchors: free interior anchors.
        num_samples: samples of the path in the cost.
        order: spline order (see :func:`ivy_robot.sample_spline_path`).
        method: ``"polyharmonic"`` or ``"bspline"``.
        margin: CHOMP's ``eps``: clearance beyond which obstacles cost nothing (metres).
        weights: cost weights ``{'smoothness', 'obstacle', 'limits'}`` (defaults 1, 100, 100).
        spheres: collision spheres of a tree (:meth:`KinematicTree.collision_spheres`).
        sphere_spacing: spacing of the default tree spheres.
        samples_per_metre: link sampling of a manipulator.
        link_radius: the radius around a manipulator's link points.

    Example:
        >>> xml = panda_mjcf('<geom name="post" type="box" pos="0.6 0 0.2" size="0.06 0.06 0.2"/>')
        >>> scene = SceneSDF.from_mjcf(xml, exclude=["link0"])
        >>> planner = ArmPlanner(KinematicTree.from_mjcf(xml), scene)
        >>> len(planner.radii)          # collision spheres from the arm's capsules
        31
    """

    def __init__(
        self,
        robot: KinematicTree | Manipulator,
        scene,
        *,
        num_anchors: int = 5,
        num_samples: int = 48,
        order: int = 3,
        method: str = "polyharmonic",
        margin: float = 0.05,
        weights: dict | None = None,
        spheres: BodySpheres | None = None,
        sphere_spacing: float = 0.05,
        samples_per_metre: float = 20.0,
        link_radius: float = 0.05,
    ) -> None:
        super().__init__(
            scene,
            num_anchors=num_anchors,
            num_samples=num_samples,
            order=order,
            method=method,
            margin=margin,
            weights=weights,
        )
        self.robot = robot
        if not isinstance(robot, (KinematicTree, Manipulator)):
            raise TypeError(
                f"ArmPlanner: robot must be a KinematicTree or a Manipulator, got "
                f"{type(robot).__name__}"
            )
        if isinstance(robot, KinematicTree):
            if any(t in ("ball", "free") for t in robot.joint_types):
                raise ValueError(
                    "ArmPlanner: the tree has ball or free joints; joint-space splines need "
                    "hinges and slides (plan a free body with DronePlanner)"
                )
            self.dim = robot.nq
            self.spheres = robot.collision_spheres(sphere_spacing) if spheres is None else spheres
            self.lower, self.upper = robot.qpos_lower, robot.qpos_upper
            self._radius = np.asarray(self.spheres.radii, dtype=np.float64)
            self._sphere_bodies = [int(b) for b in self.spheres.body_ids]
            self._sphere_offsets = np.asarray(self.spheres.centres, dtype=np.float64)
        else:
            self.dim = robot.num_joints
            self.samples_per_metre = float(samples_per_metre)
            count = robot.num_link_samples(self.samples_per_metre)
            self._radius = np.full(count, float(link_radius))
            self.lower, self.upper = robot.joint_lower, robot.joint_upper
        self._finite_limits = None
        if np.isfinite(self.lower).any() or np.isfinite(self.upper).any():
            self._finite_limits = (
                np.where(np.isfinite(self.lower), self.lower, -1e30),
                np.where(np.isfinite(self.upper), self.upper, 1e30),
            )

    def _radii(self) -> np.ndarray:
        return self._radius

    def _sphere_centres(self, xp, path):
        if isinstance(self.robot, KinematicTree):
            offsets = A.constant(xp, self._sphere_offsets, path)
            return self.robot.transform_points(path, self._sphere_bodies, offsets, f=xp)
        return self.robot.sample_links(path, self.samples_per_metre, f=xp)

    def _limits_cost(self, xp, path):
        if self._finite_limits is None:
            return None
        lower, upper = (A.constant(xp, limit, path) for limit in self._finite_limits)
        return xp.mean(joint_limit_cost(path, lower, upper, f=xp))

    def sphere_centres(self, path: Array, *, f: Framework = None) -> Array:
        """World centres of the collision spheres along a joint path.

        Args:
            path: joint positions *[num_samples, dim]*.
            f: framework name or namespace; inferred from ``path`` if None.

        Returns:
            *[num_samples, num_spheres, 3]*; the radii are ``self.radii``.

        Example:
            >>> scene = SceneSDF(["ball"], ["sphere"], [[0.1, 0, 0]], [np.eye(4)])
            >>> ArmPlanner(tree, scene).sphere_centres(np.zeros((48, 7))).shape
            (48, 31, 3)
        """
        xp = ivy.get_framework(path, f=f)
        return self._sphere_centres(xp, path)

    @property
    def radii(self) -> np.ndarray:
        """The radius of each collision sphere (numpy)."""
        return self._radius


class DronePlanner(_SplinePlanner):
    """Pose-space trajectory optimisation for a rigid mobile body.

    The path is a spline in rotation-vector poses ``[x, y, z, rx, ry, rz]`` (the original
    ivy_robot's drone demo); the body's points (:class:`RigidMobile`), each a sphere of
    ``body_radius``, are placed along it by ``ivy_mechanics.rot_vec_pose_to_mat_pose``.

    Args:
        body: the :class:`RigidMobile`.
        scene: a :class:`ivy_robot.SceneSDF` (or a callable ``points -> distances`` with ``f=``).
        body_radius: the radius around each body point (a number or one per point).
        num_anchors, num_samples, order, method, margin, weights: as :class:`ArmPlanner`
            (no joint limits).

    Example:
        >>> scene = SceneSDF(["ball"], ["sphere"], [[0.3, 0, 0]], [np.eye(4)])
        >>> planner = DronePlanner(RigidMobile([[0.0, 0.0, 0.0]]), scene, body_radius=0.1)
        >>> start, goal = np.array([-1.0, 0.05, 0, 0, 0, 0]), np.array([1.0, 0, 0, 0, 0, 0])
        >>> float(planner.cost(planner.initial_anchors(start, goal), start, goal)) > 4.0
        True
    """

    dim = 6

    def __init__(
        self,
        body: RigidMobile,
        scene,
        *,
        body_radius: float | np.ndarray = 0.05,
        num_anchors: int = 3,
        num_samples: int = 48,
        order: int = 3,
        method: str = "polyharmonic",
        margin: float = 0.1,
        weights: dict | None = None,
    ) -> None:
        super().__init__(
            scene,
            num_anchors=num_anchors,
            num_samples=num_samples,
            order=order,
            method=method,
            margin=margin,
            weights=weights,
        )
        if not isinstance(body, RigidMobile):
            raise TypeError(f"DronePlanner: body must be a RigidMobile, got {type(body).__name__}")
        self.body = body
        self._radius = np.broadcast_to(
            np.asarray(body_radius, dtype=np.float64), (body.num_points,)
        ).copy()

    def _radii(self) -> np.ndarray:
        return self._radius

    def _sphere_centres(self, xp, path):
        return self.body.sample_body(mech.rot_vec_pose_to_mat_pose(path, f=xp), f=xp)

    def sphere_centres(self, path: Array, *, f: Framework = None) -> Array:
        """World positions of the body points along a pose path.

        Args:
            path: rotation-vector poses *[num_samples, 6]*.
            f: framework name or namespace; inferred from ``path`` if None.

        Returns:
            *[num_samples, num_points, 3]*.

        Example:
            >>> planner.sphere_centres(np.zeros((48, 6))).shape
            (48, 1, 3)
        """
        xp = ivy.get_framework(path, f=f)
        return self._sphere_centres(xp, path)

    @property
    def radii(self) -> np.ndarray:
        """The radius of each body point (numpy)."""
        return self._radius
