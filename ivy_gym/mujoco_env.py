"""The base of ivy_gym's MuJoCo tasks: Gymnasium's MuJoCo environments on ``ivy_robot.physics``.

A task is Gymnasium's model (an asset of ``gymnasium/envs/mujoco/assets``, read once into
:mod:`ivy_robot.physics`), its observation and its reward; :class:`MuJoCoEnv` does the rest as
Gymnasium's ``MujocoEnv`` does:

- **frame skip**: an environment step holds the action as MuJoCo's ``ctrl`` over ``frame_skip``
  calls of :func:`ivy_robot.physics.step` (``mj_step``), as ``do_simulation``: one ``xp.scan``
  over the frames, so that compilers trace the physics once; what the task reads after the step
  (:attr:`MuJoCoEnv.data_fields`) is the last frame's, as MuJoCo leaves it (for RK4 models, the
  position-dependent fields of its last stage, and ``cfrc_ext`` of ``mj_rnePostConstraint``);
- **resets**: Gymnasium's ``reset_model``, draw for draw (:meth:`MuJoCoEnv.draw_initial`):
  ``init_qpos + uniform(-s, s, nq)``, then ``init_qvel + uniform(-s, s, nv)`` or ``init_qvel +
  s * standard_normal(nv)`` (:attr:`MuJoCoEnv.velocity_noise`);
- **what MuJoCo keeps between steps**, carried in the state after ``[qpos, qvel]`` where it
  changes the result: ``qacc_warmstart`` (the solver's warm start; PGS models only, see
  :attr:`MuJoCoEnv.carries_warmstart`) and the tracked position that Gymnasium reads *before*
  ``do_simulation`` from the data the previous step left (Ant's torso ``xpos``, Humanoid's
  centre of mass from ``xipos``: stale by a RK4 stage), see :attr:`MuJoCoEnv.position_stale`;
- **info**: :meth:`MuJoCoEnv.kernel_step_info` returns Gymnasium's ``info`` (its keys, the reward
  components) as arrays beside the step's outputs; :attr:`MuJoCoEnv.info_types` tells the
  Gymnasium facades which Python or numpy type each value has in Gymnasium's own environment;
- **rendering**: the model's spheres, capsules, cylinders and boxes projected onto a side or top
  view, drawn with :class:`ivy_gym.Canvas` (no OpenGL).

A task defines ``Params`` (a frozen dataclass of Gymnasium's constructor arguments, with
``xml_file``, ``frame_skip`` and ``reset_noise_scale``), :meth:`~MuJoCoEnv.observation` of a
:class:`~ivy_robot.physics.Data` and :meth:`~MuJoCoEnv.reward` of a :class:`Transition`, plus,
where Gymnasium has them, :meth:`~MuJoCoEnv.position` (what ``x_velocity`` differentiates) and
:meth:`~MuJoCoEnv.reset_info`. Example (Gymnasium's HalfCheetah-v5, in full)::

    class HalfCheetah(MuJoCoEnv):
        Params = HalfCheetahParams          # xml_file, frame_skip, the weights...
        velocity_noise = "normal"
        position_dim = 1

        def position(self, xp, data):
            return data.qpos[..., :1]

        def observation(self, xp, data):
            skip = 1 if self.params.exclude_current_positions_from_observation else 0
            return xp.concat([data.qpos[..., skip:], data.qvel], axis=-1)

        def reward(self, xp, t):
            p = self.params
            forward = p.forward_reward_weight * t.velocity[..., 0]
            ctrl = control_cost(xp, t.action, p.ctrl_cost_weight, forward)
            info = {"x_position": t.data.qpos[..., 0], "x_velocity": t.velocity[..., 0],
                    "reward_forward": forward, "reward_ctrl": -ctrl}
            return forward - ctrl, never(xp, forward), info
"""

from __future__ import annotations

import functools
import importlib.util
import math
import os
from typing import Any, ClassVar, NamedTuple

import numpy as np

import ivy
from ivy.typing import Array, Dtype, Framework, Shape
from ivy_gym.base import Env, _is_number, _shape, cast_like

__all__ = [
    "MuJoCoEnv",
    "Transition",
    "control_cost",
    "gymnasium_asset",
    "mujoco_tree",
    "never",
]

#: MuJoCo's geom types (``mjtGeom``) that the renderer draws.
_PLANE, _SPHERE, _CAPSULE, _ELLIPSOID, _CYLINDER, _BOX = 0, 2, 3, 4, 5, 6


def gymnasium_asset(name: str) -> str:
    """The path of Gymnasium's MuJoCo model ``name`` (``"hopper.xml"``); a path that exists
    (absolute, or relative to the working directory) is returned as it is.

    Example:
        >>> gymnasium_asset("hopper.xml")
        '.../gymnasium/envs/mujoco/assets/hopper.xml'
    """
    name = os.fspath(name)
    if os.path.sep in name and os.path.exists(os.path.expanduser(name)):
        return os.path.expanduser(name)
    spec = importlib.util.find_spec("gymnasium")
    if spec is None or spec.origin is None:
        raise ImportError(
            f"ivy_gym's MuJoCo tasks read Gymnasium's model {name!r}: install gymnasium "
            "(pip install 'ivy[gym]')."
        )
    return os.path.join(os.path.dirname(spec.origin), "envs", "mujoco", "assets", name)


@functools.cache
def mujoco_tree(xml_file: str):
    """The :class:`ivy_robot.KinematicTree` of Gymnasium's model ``xml_file`` (an asset's name
    or a path), read once through MuJoCo; ``tree.physics`` is the pipeline's model.

    Example:
        >>> mujoco_tree("hopper.xml").physics.nq
        6
    """
    from ivy_robot import KinematicTree

    return KinematicTree.from_mjcf(gymnasium_asset(xml_file))


@functools.cache
def _mujoco_extras(xml_file: str) -> dict:
    """What the tasks read of a MuJoCo model beyond ``ivy_robot.physics``' model: the geoms'
    colours (for rendering) and the fixed tendons' coefficients (Humanoid's ``info``)."""
    import mujoco

    m = mujoco.MjModel.from_xml_path(gymnasium_asset(xml_file))
    rgba = np.array(m.geom_rgba, dtype=np.float64).reshape(-1, 4)
    tendon_qpos = np.zeros((m.ntendon, m.nq))
    tendon_dof = np.zeros((m.ntendon, m.nv))
    tendon_joints = [[] for _ in range(m.ntendon)]
    fixed = True
    for t in range(m.ntendon):
        for w in range(m.tendon_adr[t], m.tendon_adr[t] + m.tendon_num[t]):
            if int(m.wrap_type[w]) != int(mujoco.mjtWrap.mjWRAP_JOINT):
                fixed = False
                continue
            j = int(m.wrap_objid[w])
            tendon_qpos[t, m.jnt_qposadr[j]] += m.wrap_prm[w]
            tendon_dof[t, m.jnt_dofadr[j]] += m.wrap_prm[w]
            tendon_joints[t].append(j)
    return {
        "geom_rgba": rgba,
        "tendon_qpos": tendon_qpos,
        "tendon_dof": tendon_dof,
        "tendon_joints": tuple(tuple(j) for j in tendon_joints),
        "tendons_fixed": fixed,
    }


class Transition(NamedTuple):
    """What a task's reward reads of an environment step.

    ``data``: the :class:`ivy_robot.physics.Data` after ``do_simulation``: ``qpos``, ``qvel`` and
    ``qacc_warmstart`` new, ``ctrl`` the controls, and the task's :attr:`MuJoCoEnv.data_fields`
    as the last frame left them. ``action``: the action as given, in its dtype (Gymnasium's
    control costs compute in it: float32 for its sampled actions). ``velocity``: ``(position
    after - position before) / dt`` of the task's :meth:`MuJoCoEnv.position`, ``(*B, k)``
    (None for tasks that track none).
    """

    data: Any
    action: Array
    velocity: Array | None


def never(xp, like: Array) -> Array:
    """``False`` of ``like``'s shape: the termination of a task that never terminates."""
    return xp.zeros_like(like) > 1.0


def control_cost(xp, action: Array, weight, like: Array) -> Array:
    """``weight * sum(action ** 2)`` as Gymnasium's numpy computes it, in ``like``'s dtype.

    In the action's dtype: a float32 action (Gymnasium's samples) with a float64 ``like`` is
    squared, summed and weighted in float32 arithmetic as numpy does it, numpy's own summation
    order included (pairwise: one by one below 8 terms, else 8 running sums combined as a
    tree), each float32 rounding written as exact float64 arithmetic (:func:`_round32`, which
    compilers keep, where they may drop casts). A float64 action, or float32 throughout, is
    computed directly.

    Args:
        xp: the backend namespace.
        action: ``(*B, nu)``.
        weight: a Python number or an array of ``like``'s framework.
        like: the dtype of the result (its shape is ``(*B,)``).

    Returns:
        ``(*B,)``.
    """
    if xp.dtype_name(action.dtype) == "float32" and xp.dtype_name(like.dtype) == "float64":
        wide = xp.astype(action, "float64")
        total = _numpy_float32_sum(xp, xp.unstack(_round32(wide * wide), axis=-1))
        if _is_number(weight):
            return _round32(total * float(np.float32(weight)))
        return _round32(total * _round32(xp.astype(weight, "float64")))
    cost = xp.sum(action * action, axis=-1) * weight
    return cost if cost.dtype == like.dtype else xp.astype(cost, like.dtype)


def _numpy_float32_sum(xp, terms: tuple) -> Array:
    """The sum of float32 numbers (held as float64) in numpy's pairwise order, rounded to
    float32 after each addition."""
    n = len(terms)
    if n < 8:
        total = terms[0]
        for term in terms[1:]:
            total = _round32(total + term)
        return total
    sums = list(terms[:8])
    whole = n - n % 8
    for i in range(8, whole, 8):
        sums = [_round32(s + terms[i + j]) for j, s in enumerate(sums)]
    pairs = [_round32(sums[2 * j] + sums[2 * j + 1]) for j in range(4)]
    total = _round32(_round32(pairs[0] + pairs[1]) + _round32(pairs[2] + pairs[3]))
    for term in terms[whole:]:
        total = _round32(total + term)
    return total


_SPLITTER = 2.0**29 + 1.0  # Veltkamp's constant: 53 - 29 = 24 significant bits remain


def _round32(x):
    """A float64 ``x`` rounded to float32's 24 significant bits (to nearest), as float64, by
    Veltkamp's splitting ``c - (c - x)``, ``c = x (2^29 + 1)``: exact arithmetic that compilers
    keep, with gradient 1 (the cast's straight-through). Valid for ``|x| < 1e300``."""
    c = x * _SPLITTER
    return c - (c - x)


@functools.cache
def _state_names(xml_file: str, warmstart: bool, stale: bool, position_dim: int) -> tuple:
    m = mujoco_tree(xml_file).physics
    names = _joint_names(m, False) + _joint_names(m, True)
    if warmstart:
        names += [f"qacc_warmstart_{i}" for i in range(m.nv)]
    if stale:
        names += [f"position_before_{c}" for c in "xyz"[:position_dim]]
    return tuple(names)


def _joint_names(model, velocity: bool) -> list[str]:
    """Names of the components of ``qpos`` (or ``qvel``) by joint, in MuJoCo's order."""
    from ivy_robot.physics import JOINT_KINDS

    parts_of = {
        "free": ("vx", "vy", "vz", "wx", "wy", "wz") if velocity else "x y z qw qx qy qz".split(),
        "ball": ("wx", "wy", "wz") if velocity else ("qw", "qx", "qy", "qz"),
    }
    names = []
    for j in np.argsort(model.jnt_qposadr, kind="stable"):
        name, kind = model.joint_names[j] or f"joint{j}", JOINT_KINDS[int(model.jnt_type[j])].name
        parts = parts_of.get(kind, ("vel",) if velocity else ("",))
        names += [f"{name}_{p}" if p else name for p in parts]
    return names


class MuJoCoEnv(Env):
    """Base class of the MuJoCo tasks (see the module docstring).

    **State** ``[qpos (nq), qvel (nv)]``, then ``qacc_warmstart (nv)`` where
    :attr:`carries_warmstart`, then the tracked position ``(position_dim)`` where
    :attr:`position_stale` (:attr:`state_names` lists them). :meth:`kernel_initial` fills the
    carried parts of a draw as Gymnasium's reset leaves them (a cold warm start, the position
    after ``mj_forward``).

    **Observation**: :meth:`observation` of the data after the step. :meth:`kernel_observe` of
    a state is what Gymnasium's ``_get_obs`` returns after its reset's ``set_state`` (an
    ``mj_forward`` of the state with zero controls; ``cfrc_ext`` zero, as ``mj_forward`` leaves
    it).

    Class attributes a task sets: ``Params``; :attr:`data_fields`, :attr:`reset_stage`,
    :attr:`velocity_noise`, :attr:`position_dim`, :attr:`position_stale`,
    :attr:`carries_warmstart`, :attr:`info_types`, :attr:`reward_type`, :attr:`camera`,
    :attr:`view_width`.
    """

    #: The Data fields (beyond ``qpos``, ``qvel``, ``ctrl``) that the observation, reward and
    #: position read after a step: the scan over the frames returns the last frame's.
    data_fields: ClassVar[tuple[str, ...]] = ()
    #: What the observation of a state needs (:meth:`kernel_observe`): ``"state"`` (``qpos``
    #: and ``qvel`` only), ``"kinematics"`` (frames), ``"forward"`` (``mj_forward``).
    reset_stage: ClassVar[str] = "state"
    #: How Gymnasium draws the initial velocities: ``"uniform"`` in ``[-s, s]`` or
    #: ``"normal"`` with standard deviation ``s`` (``s = reset_noise_scale``).
    velocity_noise: ClassVar[str] = "uniform"
    #: Components of the position Gymnasium differentiates for ``x_velocity`` (0: none).
    position_dim: ClassVar[int] = 0
    #: Whether that position reads data that Gymnasium finds stale before a step (then the
    #: state carries it: what the previous step, or the reset's ``mj_forward``, left).
    position_stale: ClassVar[bool] = False
    #: Whether the state carries ``qacc_warmstart`` (MuJoCo keeps ``qacc`` of a step as the next
    #: one's warm start; PGS stops at a tolerance, so its result depends on it).
    carries_warmstart: ClassVar[bool] = False
    #: Gymnasium's type of an ``info`` value where it is not ``np.float64`` (or a float64
    #: array for vectors): ``float``, ``int``, or ``"action"`` (a numpy scalar of the action's
    #: dtype: Gymnasium's control costs of float32 actions are ``np.float32``).
    info_types: ClassVar[dict[str, Any]] = {}
    #: Gymnasium's type of the reward.
    reward_type: ClassVar[Any] = np.float64
    #: The facades' default dtype of the core and observations (Gymnasium's: float64), and of
    #: the action space (Gymnasium's MuJoCo action spaces are float32).
    gymnasium_dtype: ClassVar[str] = "float64"
    gymnasium_action_dtype: ClassVar[str] = "float32"
    #: The rendering's projection: ``"side"`` (x right, z up) or ``"top"`` (x right, y up).
    camera: ClassVar[str] = "side"
    #: Width of the world that a rendering shows, in metres.
    view_width: ClassVar[float] = 4.0

    def __init__(self, **params: Any) -> None:
        if not hasattr(type(self), "Params"):
            raise TypeError(
                f"{type(self).__name__} is the base of the MuJoCo tasks, not a task: use one of "
                "them (ivy_gym.Hopper(), ivy_gym.Ant(), ...) or subclass it with a Params "
                "dataclass, an observation and a reward (see ivy_gym.mujoco_env's docstring)."
            )
        super().__init__(**params)
        p = self.params
        if int(p.frame_skip) != p.frame_skip or int(p.frame_skip) < 1:
            raise ValueError(
                f"{type(self).__name__}: frame_skip must be an integer >= 1, got {p.frame_skip!r}."
            )
        self.model.check_dynamics()

    # ------------------------------------------------------------------------------------------
    # The model and the layout
    # ------------------------------------------------------------------------------------------

    @property
    def tree(self):
        """The :class:`ivy_robot.KinematicTree` of ``params.xml_file``."""
        return mujoco_tree(self.params.xml_file)

    @property
    def model(self):
        """The pipeline's model (:class:`ivy_robot.physics.Model`)."""
        return self.tree.physics

    @property
    def dt(self) -> float:
        """Seconds per environment step: ``timestep * frame_skip`` (Gymnasium's ``dt``)."""
        return self.model.timestep * int(self.params.frame_skip)

    @property
    def render_fps(self) -> int:  # type: ignore[override]
        """Gymnasium's ``render_fps``: ``round(1 / dt)``."""
        return int(np.round(1.0 / self.dt))

    @property
    def init_qpos(self) -> np.ndarray:
        """The model's ``qpos0`` (Gymnasium's ``init_qpos``)."""
        return np.array(self.model.qpos0, dtype=np.float64)

    @property
    def state_names(self) -> tuple[str, ...]:  # type: ignore[override]
        return _state_names(
            self.params.xml_file, self.carries_warmstart, self.position_stale, self.position_dim
        )

    @property
    def observation_names(self) -> tuple[str, ...]:  # type: ignore[override]
        return self._observation_names()

    def _observation_names(self) -> tuple[str, ...]:
        """Names of the observation's components (a task's layout)."""
        raise NotImplementedError

    def qpos_names(self) -> list[str]:
        """Names of ``qpos``' components, by joint (free joints: ``_x .. _qz``)."""
        return list(_state_names(self.params.xml_file, False, False, 0)[: self.model.nq])

    def qvel_names(self) -> list[str]:
        """Names of ``qvel``' components, by joint (``_vel``; free joints: ``_vx .. _wz``)."""
        return list(_state_names(self.params.xml_file, False, False, 0)[self.model.nq :])

    def _qpos_qvel_dims(self) -> tuple[int, int]:
        return self.model.nq, self.model.nv

    def split_state(self, xp, state: Array) -> tuple:
        """``(qpos, qvel, qacc_warmstart or None, position or None)`` of a state (a kernel)."""
        nq, nv = self._qpos_qvel_dims()
        qpos, qvel = state[..., :nq], state[..., nq : nq + nv]
        at = nq + nv
        warm = position = None
        if self.carries_warmstart:
            warm, at = state[..., at : at + nv], at + nv
        if self.position_stale:
            position = state[..., at : at + self.position_dim]
        return qpos, qvel, warm, position

    # ------------------------------------------------------------------------------------------
    # What a task defines
    # ------------------------------------------------------------------------------------------

    def observation(self, xp, data) -> Array:
        """The observation of ``data`` (after a step, or a reset's ``mj_forward``)."""
        raise NotImplementedError

    def reward(self, xp, t: Transition) -> tuple[Array, Array, dict]:
        """``(reward, terminated, info)`` of a step (see :class:`Transition`); ``info`` holds
        Gymnasium's ``info`` of the step as arrays ``(*B,)`` (or ``(*B, k)``)."""
        raise NotImplementedError

    def position(self, xp, data) -> Array:
        """The position ``(*B, position_dim)`` whose change over a step, divided by ``dt``, is
        Gymnasium's ``x_velocity`` (and ``y_velocity``)."""
        raise NotImplementedError

    def reset_info(self, xp, data) -> dict:
        """Gymnasium's ``info`` of a reset (``_get_reset_info``), of the data of the state."""
        return {}

    # ------------------------------------------------------------------------------------------
    # Boxes and resets
    # ------------------------------------------------------------------------------------------

    def _centre(self) -> np.ndarray:
        """``[init_qpos, init_qvel]`` and zeros for the carried parts."""
        m = self.model
        centre = np.zeros(len(self.state_names))
        centre[: m.nq] = self.init_qpos
        return centre

    def reset_bounds(self):
        """``qpos``: the box Gymnasium draws it in; ``qvel``: that box, or for normal draws
        the mean plus and minus one standard deviation; the carried parts: zero (filled by
        :meth:`kernel_initial`)."""
        m, s = self.model, float(self.params.reset_noise_scale)
        centre = self._centre()
        half = np.zeros_like(centre)
        half[: m.nq + m.nv] = s
        return centre - half, centre + half

    def action_bounds(self):
        ranges = np.array(self.model.actuator_ctrlrange, dtype=np.float64)
        if not np.isfinite(ranges).all():
            raise ValueError(
                f"{type(self).__name__}: every actuator of the model needs a ctrlrange "
                "(Gymnasium's action space is the control range)."
            )
        return ranges[:, 0], ranges[:, 1]

    def draw_initial(self, rng: np.random.Generator, batch_shape: Shape | int = ()) -> np.ndarray:
        """Gymnasium's ``reset_model``, draw for draw with ``rng``, state by state:
        ``init_qpos + uniform(-s, s, nq)``, then ``init_qvel + uniform(-s, s, nv)`` or
        ``init_qvel + s * standard_normal(nv)`` (``s = reset_noise_scale``, scaled by
        :meth:`Env.narrowed`); the carried parts zero (see :meth:`kernel_initial`)."""
        m = self.model
        batch = _shape(batch_shape)
        s = float(self.params.reset_noise_scale) * self.reset_scale
        centre = self._centre()
        init_qpos, init_qvel = centre[: m.nq], centre[m.nq : m.nq + m.nv]
        out = np.zeros((*batch, self.state_dim))
        for index in np.ndindex(batch):
            qpos = init_qpos + rng.uniform(low=-s, high=s, size=m.nq)
            if self.velocity_noise == "normal":
                qvel = init_qvel + s * rng.standard_normal(m.nv)
            else:
                qvel = init_qvel + rng.uniform(low=-s, high=s, size=m.nv)
            out[index][: m.nq] = qpos
            out[index][m.nq : m.nq + m.nv] = qvel
        return out

    def reset(
        self,
        batch_shape: Shape | int = (),
        *,
        dtype: Dtype = "float32",
        device: str | None = None,
        f: Framework = None,
    ) -> Array:
        """A batch of initial states drawn with ivy's random functions, distributed as
        Gymnasium's (:meth:`draw_initial`), mapped by :meth:`kernel_initial`.

        Example:
            >>> ivy.seed(0)
            >>> ivy_gym.Hopper().reset((64,), dtype="float64", f="torch").shape
            torch.Size([64, 12])
        """
        xp = ivy.get_framework(f=f)
        batch = _shape(batch_shape)
        low, high = self.initial_bounds()

        def constant(values):
            return xp.constant(values, dtype=dtype, device=device)

        u = xp.random_uniform(shape=(*batch, self.state_dim), dtype=dtype, device=device)
        state = constant(low) + constant(high - low) * u
        if self.velocity_noise == "normal":
            m = self.model
            nq, nv = m.nq, m.nv
            half = (high - low)[nq : nq + nv] / 2
            n = xp.random_normal(shape=(*batch, nv), dtype=dtype, device=device)
            qvel = constant(low[nq : nq + nv] + half) + constant(half) * n
            state = xp.concat([state[..., :nq], qvel, state[..., nq + nv :]], axis=-1)
        return self.kernel_initial(xp, state)

    # ------------------------------------------------------------------------------------------
    # Kernels
    # ------------------------------------------------------------------------------------------

    def _data_at(self, xp, qpos, qvel, warm, stage: str):
        """The data of a state as Gymnasium's ``set_state`` leaves it (``mj_forward``, zero
        controls and ``cfrc_ext`` after a reset), computed as far as ``stage`` needs."""
        from ivy_robot.physics import Data, forward, make_data

        m = self.model
        if stage == "forward":
            data = forward(xp, m, make_data(xp, m, qpos, qvel, qacc_warmstart=warm))
        elif stage == "kinematics":
            from ivy_robot.physics import kinematics

            fields = {k: v for k, v in kinematics(xp, m, qpos).items() if k in Data.names()}
            data = Data(qpos=qpos, qvel=qvel, **fields)
        else:
            data = Data(qpos=qpos, qvel=qvel)
        zero = qpos[..., :1, None] * 0.0
        cfrc_ext = zero + xp.constant(np.zeros((m.nbody, 6)), dtype=qpos.dtype, device=xp.dev(qpos))
        return data.replace(cfrc_ext=cfrc_ext)

    def _position_stage(self) -> str:
        return "kinematics" if self.position_stale else "state"

    def _kernel(self, xp, name: str, fn):
        """``fn`` itself, or, where eager mode compiles each operation on first use
        (``xp.capabilities.eager_compiles_ops``: jax), ``ivy.compile_fn(fn)`` made once per
        kernel and parameters: a first eager call then compiles one program instead of each
        operation and loop of the physics (inside a user's compiled function it is inlined).
        ``fn`` must depend only on ``self.params`` and the model."""
        capabilities = getattr(xp, "capabilities", None)
        if not getattr(capabilities, "eager_compiles_ops", False):
            return fn
        cache = self.__dict__.get("_compiled_kernels")
        if cache is None or cache[0] is not self.params:  # new parameters: new kernels
            cache = self._compiled_kernels = (self.params, {})
        key = (xp.__name__, name)
        if key not in cache[1]:
            cache[1][key] = xp.compile_fn(fn)
        return cache[1][key]

    def kernel_initial(self, xp, state):
        """The carried parts of a draw as Gymnasium's reset leaves them: a cold warm start
        (``mj_resetData``) and the position of the state (``mj_forward``)."""
        if not (self.carries_warmstart or self.position_stale):
            return state
        qpos, qvel, _, _ = self.split_state(xp, state)
        return self.kernel_set_state(xp, state, qpos, qvel, keep_warmstart=False)

    def kernel_set_state(self, xp, state, qpos, qvel, *, keep_warmstart: bool = True):
        """Gymnasium's ``set_state(qpos, qvel)`` on ``state``: the new ``qpos`` and ``qvel``,
        the warm start kept (``keep_warmstart``; else zero), the tracked position recomputed
        by ``mj_forward``."""
        name = f"set_state_{keep_warmstart}"
        fn = self._kernel(xp, name, lambda *a: self._set_state(xp, *a, keep_warmstart))
        return fn(state, qpos, qvel)

    def _set_state(self, xp, state, qpos, qvel, keep_warmstart):
        parts = [qpos, qvel]
        if self.carries_warmstart:
            _, _, warm, _ = self.split_state(xp, state)
            parts.append(warm if keep_warmstart else qvel * 0.0)
        if self.position_stale:
            data = self._data_at(xp, qpos, qvel, None, self._position_stage())
            parts.append(self.position(xp, data))
        return xp.concat(parts, axis=-1)

    def kernel_observe(self, xp, state):
        return self._kernel(xp, "observe", lambda s: self._observe(xp, s))(state)

    def _observe(self, xp, state):
        qpos, qvel, warm, _ = self.split_state(xp, state)
        return self.observation(xp, self._data_at(xp, qpos, qvel, warm, self.reset_stage))

    def kernel_reset_info(self, xp, state) -> dict:
        """Gymnasium's ``info`` of a reset to ``state`` (a dict of arrays)."""
        qpos, qvel, _, _ = self.split_state(xp, state)
        return self.reset_info(xp, self._data_at(xp, qpos, qvel, None, "state"))

    def simulate(self, xp, qpos, qvel, warm, ctrl):
        """``do_simulation``: ``frame_skip`` calls of ``mj_step`` with ``ctrl`` held, as one
        ``xp.scan``. Returns the :class:`ivy_robot.physics.Data` with the new ``qpos``,
        ``qvel`` and ``qacc_warmstart`` and the last frame's :attr:`data_fields` (``warm``:
        the warm start, or None for a cold one; ``ctrl`` in the state's dtype)."""
        fn = self._kernel(xp, "simulate", lambda *a: self._simulate(xp, *a))
        return fn(qpos, qvel, qvel * 0.0 if warm is None else warm, ctrl)

    def _simulate(self, xp, qpos, qvel, warm, ctrl):
        from ivy_robot.physics import Data, make_data, step

        m, fields = self.model, self.data_fields

        def frame(carry, _):
            data = make_data(xp, m, carry[0], carry[1], ctrl, qacc_warmstart=carry[2])
            data = step(xp, m, data)
            return (data.qpos, data.qvel, data.qacc_warmstart), {
                k: getattr(data, k) for k in fields
            }

        length = int(self.params.frame_skip)
        (qpos, qvel, warm), frames = xp.scan(frame, (qpos, qvel, warm), None, length=length)
        last = {k: v[-1] for k, v in frames.items()}
        return Data(qpos=qpos, qvel=qvel, ctrl=ctrl, qacc_warmstart=warm, **last)

    def kernel_step_info(self, xp, state, action):
        """One step: ``(state, observation, reward, terminated, info)``, ``info`` Gymnasium's
        (a dict of arrays)."""
        return self._kernel(xp, "step", lambda s, a: self._step_info(xp, s, a))(state, action)

    def _step_info(self, xp, state, action):
        ctrl = cast_like(xp, action, state)
        batch = np.broadcast_shapes(tuple(state.shape[:-1]), tuple(ctrl.shape[:-1]))
        if tuple(state.shape[:-1]) != batch:  # the loop's carry keeps one shape
            state = xp.broadcast_to(state, (*batch, self.state_dim))
        if tuple(ctrl.shape[:-1]) != batch:
            ctrl = xp.broadcast_to(ctrl, (*batch, ctrl.shape[-1]))
        qpos, qvel, warm, before = self.split_state(xp, state)
        if self.position_dim and not self.position_stale:
            before = self.position(xp, self._data_at(xp, qpos, qvel, None, "state"))
        data = self.simulate(xp, qpos, qvel, warm, ctrl)
        parts = [data.qpos, data.qvel]
        if self.carries_warmstart:
            parts.append(data.qacc_warmstart)
        velocity = None
        if self.position_dim:
            after = self.position(xp, data)
            velocity = (after - before) / self.dt
            if self.position_stale:
                parts.append(after)
        reward, terminated, info = self.reward(xp, Transition(data, action, velocity))
        obs = self.observation(xp, data)
        return xp.concat(parts, axis=-1), obs, reward, terminated, info

    def kernel_step(self, xp, state, action):
        return self.kernel_step_info(xp, state, action)[:4]

    # ------------------------------------------------------------------------------------------
    # Rendering: the geoms projected, drawn with numpy
    # ------------------------------------------------------------------------------------------

    def _geoms(self, s: np.ndarray):
        """World positions and orientations of the geoms at the state ``s`` (numpy)."""
        from ivy_robot.physics import kinematics

        qpos = s[: self.model.nq]
        kin = kinematics(ivy.numpy, self.model, np.asarray(qpos, np.float64))
        return np.asarray(kin["geom_xpos"]), np.asarray(kin["geom_xmat"]), np.asarray(kin["xpos"])

    def _axes(self) -> tuple[int, int, int]:
        """The world axes drawn right and up, and the depth axis (towards the viewer)."""
        return (0, 2, 1) if self.camera == "side" else (0, 1, 2)

    def _view(self, s):
        """A square of ``view_width`` about the robot (its geoms' mean position), the floor
        along the bottom of a side view."""
        pos, _, _ = self._geoms(s)
        right, up, _ = self._axes()
        body = pos[np.asarray(self.model.geom_type) != _PLANE]
        centre = body.mean(axis=0) if len(body) else np.zeros(3)
        half = self.view_width / 2
        x = float(centre[right])
        if self.camera == "side":
            return (x - half, x + half, -0.4, 2 * half - 0.4)
        y = float(centre[up])
        return (x - half, x + half, y - half, y + half)

    def _draw(self, canvas, s):
        m = self.model
        pos, mat, _ = self._geoms(s)
        right, up, depth = self._axes()
        rgba = _mujoco_extras(self.params.xml_file)["geom_rgba"]
        # the viewer looks along -y (side) or -z (top): the far geoms first
        order = np.argsort(pos[:, depth] * (1.0 if self.camera == "top" else -1.0))
        sign = 1.0 if self.camera == "top" else -1.0
        depths = sign * pos[:, depth]
        spread = max(float(np.ptp(depths)), 1e-9)
        for g in order:
            kind, size = int(m.geom_type[g]), m.geom_size[g]
            near = 1.0 if kind == _PLANE else (depths[g] - depths.min()) / spread
            color = tuple(int(255 * min(1.0, c * (0.7 + 0.3 * near))) for c in rgba[g, :3])
            p, r = pos[g][[right, up]], mat[g][[right, up]]  # rows: the drawn axes
            if kind == _PLANE:
                _draw_ground(canvas, float(pos[g][up]), self.camera, color)
            elif kind in (_SPHERE, _ELLIPSOID):
                canvas.disc(p, float(size[:3].max() if kind == _ELLIPSOID else size[0]), color)
            elif kind in (_CAPSULE, _CYLINDER):
                half = r[:, 2] * float(size[1])  # the geom's z axis, projected
                radius = float(size[0])
                canvas.line(p - half, p + half, 2 * radius, color)
                if kind == _CAPSULE:
                    canvas.disc(p - half, radius, color)
                    canvas.disc(p + half, radius, color)
            elif kind == _BOX:
                corners = np.array(
                    [[a, b, c] for a in (-1, 1) for b in (-1, 1) for c in (-1, 1)], np.float64
                )
                points = p + (corners * size) @ r.T
                canvas.polygon(_convex_hull(points), color)


def _draw_ground(canvas, height: float, camera: str, color) -> None:
    """The floor: a band below ``height`` (side view) or the whole picture (top view), with
    tiles of a darker shade that show the motion."""
    x0, x1, y0, y1 = canvas.x_min, canvas.x_max, canvas.y_min, canvas.y_max
    dark = tuple(int(0.85 * c) for c in color)
    tile = 0.5 if x1 - x0 <= 4.0 else 1.0
    if camera == "side":
        canvas.polygon([(x0, y0), (x1, y0), (x1, height), (x0, height)], color)
        band = max(height - y0, 0.0) / 2
        for i in range(math.floor(x0 / tile), math.ceil(x1 / tile)):
            if i % 2 == 0:
                a, b = i * tile, (i + 1) * tile
                canvas.polygon(
                    [(a, height - band), (b, height - band), (b, height), (a, height)], dark
                )
        return
    canvas.polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], color)
    for i in range(math.floor(x0 / tile), math.ceil(x1 / tile)):
        for j in range(math.floor(y0 / tile), math.ceil(y1 / tile)):
            if (i + j) % 2 == 0:
                a, b, c, d = i * tile, (i + 1) * tile, j * tile, (j + 1) * tile
                canvas.polygon([(a, c), (b, c), (b, d), (a, d)], dark)


def _convex_hull(points: np.ndarray) -> np.ndarray:
    """The convex hull of 2-D points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(map(tuple, np.round(points, 12)))

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2:
                (ax, ay), (bx, by) = out[-2], out[-1]
                if (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax) > 0:
                    break
                out.pop()
            out.append(p)
        return out

    lower, upper = half(pts), half(pts[::-1])
    return np.array(lower[:-1] + upper[:-1])
