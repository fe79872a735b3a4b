"""Gymnasium facades over the batched cores: a Gymnasium ``Env`` and a native ``VectorEnv``.

The facades own what the cores leave out: numpy conversion, seeding (Gymnasium's
``np_random``), validation of the actions, time limits (the vector environment's) and autoreset.
The core owns the physics, run on any backend:

    env = gymnasium.make("ivy_gym/Pendulum-v1", framework="torch", dtype="float64")
    envs = gymnasium.make_vec("ivy_gym/CartPole-v1", num_envs=1024,
                              vectorization_mode="vector_entry_point", framework="jax")

The core computes in the chosen dtype, and observations are numpy arrays of it. By default both
are Gymnasium's, so that a facade made with its defaults passes Gymnasium's own
``check_environments_match`` against Gymnasium's environment: the core's ``gymnasium_dtype``
(float64 for the MuJoCo tasks and for Gymnasium's classic-control tasks, which Gymnasium
computes in float64; float32 for ivy_gym's own tasks) and ``gymnasium_observation_dtype``
(float32 observations of the classic-control tasks' float64 states); the action space's dtype
is the core's ``gymnasium_action_dtype`` (float32 for the MuJoCo tasks, Pendulum and
MountainCarContinuous); where the backend cannot hold float64 (jax without 64-bit types), float32;
``env.unwrapped.state`` reads and writes the state as a float64 numpy array in the core's layout
(Gymnasium's, for the faithful tasks). Actions are checked against the action space; float32 and
float64 actions keep their dtype (the faithful tasks compute with them as Gymnasium does).
Rewards and ``info`` (the core's ``kernel_step_info``) have the types Gymnasium's own task
returns (the core's ``reward_type`` and ``info_types``); the vector facade stacks ``info`` as
Gymnasium's vector environments do (``info[key]`` an array, ``info["_" + key]`` its mask).
``set_state(qpos, qvel)`` is Gymnasium's ``MujocoEnv.set_state`` for the MuJoCo tasks.
``device=`` places the core's arrays; ``compile=`` runs the step (and the reset's kernels)
through ``ivy.compile_fn``.
"""

from __future__ import annotations

import functools
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

import ivy
from ivy.typing import Dtype, Framework
from ivy_gym.base import Env

__all__ = ["GymnasiumEnv", "GymnasiumVectorEnv"]

_FLOATS = ("float32", "float64")
_KEPT_ACTION_DTYPES = (np.dtype("float32"), np.dtype("float64"))


def _default_dtype(core: Env, xp) -> str:
    """The core's ``gymnasium_dtype``, or float32 where the backend cannot hold float64 now
    (jax without x64): with a warning where the observations then differ from Gymnasium's."""
    name = core.gymnasium_dtype
    if name == "float64" and not hasattr(xp, "float64"):  # (jax without x64: no such dtype)
        if (core.gymnasium_observation_dtype or name) == "float64":
            gymnasium.logger.warn(
                f"ivy_gym: {type(core).__name__}'s observations are float64 in Gymnasium, but "
                f"{xp.backend} cannot hold float64 now (for jax: jax.config.update("
                "'jax_enable_x64', True)); using float32."
            )
        return "float32"
    return name


def _dtype_name(dtype: Dtype) -> str:
    try:
        name = np.dtype(dtype).name  # names, numpy and jax dtypes
    except TypeError:  # another framework's dtype object: its name (tf) or its last word (torch)
        name = getattr(dtype, "name", None) or str(dtype).rpartition(".")[2]
    if name not in _FLOATS:
        raise ValueError(f"ivy_gym: dtype must be 'float32' or 'float64', got {dtype!r}.")
    return name


def _box(low: np.ndarray, high: np.ndarray, dtype: str) -> spaces.Box:
    return spaces.Box(low.astype(dtype), high.astype(dtype), dtype=np.dtype(dtype))


class _Facade:
    """What the single and the vector facades share: the core, its backend and the spaces."""

    def _setup(
        self,
        core: Env,
        framework: Framework,
        dtype: Dtype | None,
        discrete: bool,
        device: str | None,
        compile: bool | None,
    ) -> None:
        if not isinstance(core, Env):
            raise TypeError(f"ivy_gym facade: expected an ivy_gym.Env, got {type(core)!r}.")
        self.core = core
        self.xp = ivy.get_framework(f=framework)
        #: Where the core's arrays live (None: the backend's default device).
        self.device = device
        # The arrays the facade makes are placed on a named device: jax compiles a function
        # once per pattern of committed (placed) inputs and commits its outputs, so a state
        # drawn without a device would compile the step a second time at the second step.
        self._device = device if device is not None else self.xp.dev(self.xp.zeros((1,)))
        self._to_numpy = self.xp.to_numpy  # the backend's own: no dispatch at every step
        self.framework = self.xp.backend
        self.dtype = _dtype_name(_default_dtype(core, self.xp) if dtype is None else dtype)
        #: The observations' dtype: ``dtype``'s; by default Gymnasium's (float32 observations
        #: of a state that Gymnasium computes in float64, as Pendulum's).
        self.observation_dtype = _dtype_name(
            (dtype is None and core.gymnasium_observation_dtype) or self.dtype
        )
        self.action_dtype = _dtype_name(core.gymnasium_action_dtype or self.dtype)
        self.discrete = bool(discrete)
        low, high = core.action_bounds()
        if self.discrete:
            if core.action_dim != 1:
                raise ValueError("ivy_gym facade: discrete=True needs a 1-D action.")
            # Gymnasium's discrete actions index this table of core actions: the core's
            # ``discrete_actions``, else CartPole's (0: push left, 1: push right); in the
            # facade's dtype: one ``take`` per step.
            table = core.discrete_actions
            if table is None:
                table, self._discrete_names = ((-1.0,), (1.0,)), "0 (push left) or 1 (push right)"
            else:
                self._discrete_names = f"in {{0, ..., {len(table) - 1}}}"
            self._discrete_actions = np.array(table, self.dtype)
            self._single_action_space = spaces.Discrete(len(table))
        else:
            self._single_action_space = _box(low, high, self.action_dtype)
        self._single_observation_space = _box(*core.observation_bounds(), self.observation_dtype)
        self._action_low = low.astype(self.action_dtype)
        self._action_high = high.astype(self.action_dtype)
        # The step and the reset's kernels, resolved once: the core's kernels on the facade's
        # namespace (the facade checks and converts the actions, so ``Env.step``'s look-up of
        # the backend and its checks are not needed at every step).
        if compile is None:
            # compilers that keep loops (jax, tensorflow) also start in about a second;
            # torch.compile takes ~20 s, more than most runs of an environment gain
            caps = self.xp.capabilities
            compile = caps.compilation and caps.compiled_loops
        self.compiled = bool(compile)
        if self.compiled:
            self._step, self._fresh = _compiled_kernels(core, self.xp)
        else:
            self._step, self._fresh = _kernels(core, self.xp)

    def _to_backend(self, states: np.ndarray):
        """Draws of the reset box as initial states: ``(state, observation, reset info)``."""
        x = self.xp.asarray(np.asarray(states, np.float64), dtype=self.dtype, device=self._device)
        return self._fresh(x)

    def _numpy(self, x) -> np.ndarray:
        return np.asarray(self._to_numpy(x), dtype=self.dtype)

    def _observation(self, x) -> np.ndarray:
        return np.asarray(self._to_numpy(x), dtype=self.observation_dtype)

    def _reward(self, value) -> Any:
        """A reward as the type of Gymnasium's own task."""
        return self.core.reward_type(value)

    def _info(self, info: dict, action_dtype) -> dict:
        """The core's info arrays (of one environment) as Gymnasium's own task's values."""
        types = self.core.info_types
        out = {}
        for key, value in info.items():
            value = np.asarray(self._to_numpy(value))
            if value.ndim:
                out[key] = np.array(value, dtype=np.float64)
                continue
            kind = types.get(key, np.float64)
            out[key] = np.dtype(action_dtype).type(value) if kind == "action" else kind(value)
        return out

    def _vector_info(self, info: dict, action_dtype, masks=None) -> dict:
        """The core's info arrays (``(num_envs, ...)``) as Gymnasium's vector environments
        stack the ``info`` of their environments: each value's array in the dtype of the
        single environment's value, and its mask under ``"_" + key`` (``masks[key]``; all True
        by default)."""
        types = self.core.info_types
        out = {}
        for key, value in info.items():
            value = np.asarray(self._to_numpy(value))
            kind = types.get(key, np.float64)
            if value.ndim > 1:
                dtype = np.float64
            elif kind == "action":
                dtype = np.dtype(action_dtype)
            else:
                dtype = np.dtype(kind)  # float -> float64, int -> int64
            out[key] = np.array(value, dtype=dtype)
            mask = None if masks is None else masks.get(key)
            out["_" + key] = np.ones(len(value), bool) if mask is None else mask
        return out

    def set_state(self, qpos, qvel) -> None:
        """Gymnasium's ``MujocoEnv.set_state``: set ``qpos`` and ``qvel`` (of every copy, for
        the vector facade: ``(num_envs, nq)``); what MuJoCo keeps (the solver's warm start)
        is kept, what ``mj_forward`` recomputes (the tracked position) is recomputed."""
        setter = getattr(self.core, "kernel_set_state", None)
        if setter is None:
            raise TypeError(f"{self._name}: set_state is for the MuJoCo tasks; set .state instead.")
        if self._state is None:
            raise RuntimeError(f"{self._name}: call reset() before set_state().")
        batch = tuple(self._state.shape[:-1])
        nq, nv = self.core.model.nq, self.core.model.nv
        qpos, qvel = np.asarray(qpos, np.float64), np.asarray(qvel, np.float64)
        if qpos.shape != (*batch, nq) or qvel.shape != (*batch, nv):
            raise ValueError(
                f"{self._name}: set_state expects qpos {(*batch, nq)} and qvel {(*batch, nv)}, "
                f"got {qpos.shape} and {qvel.shape}."
            )

        def backend(x):
            return self.xp.asarray(x, dtype=self.dtype, device=self._device)

        self._state = setter(self.xp, self._state, backend(qpos), backend(qvel))

    def state_vector(self) -> np.ndarray:
        """``[qpos, qvel]`` (Gymnasium's ``MujocoEnv.state_vector``) of the MuJoCo tasks."""
        if self._state is None:
            raise RuntimeError(f"{self._name}: call reset() before state_vector().")
        nq, nv = self.core.model.nq, self.core.model.nv
        return np.asarray(ivy.to_numpy(self._state), np.float64)[..., : nq + nv]

    @property
    def dt(self) -> float:
        """Seconds per step (the MuJoCo tasks': ``timestep * frame_skip``)."""
        return self.core.dt

    def _checked_actions(self, action, batch: tuple[int, ...]):
        """The action(s) as core actions ``(*batch, action_dim)`` of the backend and the
        facade's dtype, or a clear error."""
        a = np.asarray(action)
        if self.discrete:
            n = len(self._discrete_actions)
            if a.shape != batch or a.dtype.kind not in "iu":
                raise ValueError(
                    f"{self._name}: expected integer action(s) of shape {batch} in "
                    f"{{0, ..., {n - 1}}}, got {action!r} (shape {a.shape}, dtype {a.dtype})."
                )
            if ((a < 0) | (a >= n)).any():
                raise ValueError(
                    f"{self._name}: actions must be {self._discrete_names}, got {action!r}."
                )
            core_action = self._discrete_actions.take(a, 0)
            return self.xp.asarray(core_action, device=self._device)
        want = (*batch, self.core.action_dim)
        if a.shape != want:
            raise ValueError(
                f"{self._name}: expected action(s) of shape {want}, got shape {a.shape}."
            )
        inside = (a >= self._action_low) & (a <= self._action_high)  # NaN is outside
        if not inside.all():
            raise ValueError(
                f"{self._name}: action(s) outside the action space [{self._action_low}, "
                f"{self._action_high}]: {a[~inside]}. Clip or rescale the action (e.g. tanh)."
            )
        # float32 and float64 actions keep their dtype: the faithful tasks compute with them as
        # Gymnasium does (its action spaces sample float32); a dtype that the backend cannot
        # hold now (float64 on jax without 64-bit types) is cast to the environment's
        kept = a.dtype in _KEPT_ACTION_DTYPES and hasattr(self.xp, a.dtype.name)
        dtype = a.dtype if kept else self.dtype
        return self.xp.asarray(a, dtype=dtype, device=self._device)

    @property
    def backend_state(self):
        """The core's state as an array of the facade's backend, on its device (None before
        ``reset``): what the physics steps, without a copy to the host."""
        return self._state

    def _frame(self, state_row) -> np.ndarray:
        return self.core.render(state_row)

    @property
    def _name(self) -> str:
        return f"ivy_gym {type(self.core).__name__} ({self.framework})"


def _kernels(core: Env, xp) -> tuple:
    """The step and the reset's kernels of ``core`` on the namespace ``xp``."""
    return functools.partial(core.kernel_step_info, xp), functools.partial(_fresh, core, xp)


#: Compiled kernels shared by the facades of equal cores (same class, parameters and reset
#: box, on one backend): the copies of a vector environment and a trainer's test environment
#: compile the step once, not once each (4 s each for Hopper on jax). The most recent kept.
_SHARED: dict = {}
_SHARED_SIZE = 16


def _compiled_kernels(core: Env, xp) -> tuple:
    """The compiled step and reset kernels of ``core``, shared with equal cores."""
    key = (type(core), core.params, core.reset_scale, xp.__name__)
    try:
        hash(key)
    except TypeError:  # parameters that are arrays: kernels of its own
        return tuple(ivy.compile_fn(k, f=xp) for k in _kernels(core, xp))
    if key not in _SHARED:
        if len(_SHARED) >= _SHARED_SIZE:
            del _SHARED[next(iter(_SHARED))]
        _SHARED[key] = tuple(ivy.compile_fn(k, f=xp) for k in _kernels(core, xp))
    return _SHARED[key]


def _fresh(core: Env, xp, draws) -> tuple:
    """Initial states from draws of the reset box, their observations and reset infos."""
    state = core.kernel_initial(xp, draws)
    return state, core.kernel_observe(xp, state), core.kernel_reset_info(xp, state)


class GymnasiumEnv(_Facade, gymnasium.Env):
    """A Gymnasium ``Env`` over one state of an ivy_gym core, on any backend.

    Args:
        core: the environment's core (an :class:`ivy_gym.Env`).
        framework: the backend that runs the physics.
        dtype: ``'float32'`` or ``'float64'``: the core's dtype and the observations' (None:
            the core's ``gymnasium_dtype``, Gymnasium's: float64 for the MuJoCo tasks).
        render_mode: None or ``'rgb_array'``.
        discrete: Gymnasium's discrete actions instead of the core's continuous one: indices
            into the core's ``discrete_actions`` table (MountainCar's and Acrobot's {0, 1, 2}),
            else CartPole's {0, 1} (push left/right).
        device: where the core's arrays live (``'gpu:0'``; None: the backend's default).
        compile: run the step and the reset's kernels through ``ivy.compile_fn``; by default
            where the compiler keeps loops (jax, tensorflow).

    Example:
        >>> env = GymnasiumEnv(ivy_gym.Pendulum(), framework="jax", dtype="float64")
        >>> obs, info = env.reset(seed=0)
        >>> obs, reward, terminated, truncated, info = env.step(np.array([0.5]))
    """

    def __init__(
        self,
        core: Env,
        *,
        framework: Framework = "numpy",
        dtype: Dtype | None = None,
        render_mode: str | None = None,
        discrete: bool = False,
        device: str | None = None,
        compile: bool | None = None,
    ) -> None:
        self._setup(core, framework, dtype, discrete, device, compile)
        self.metadata = {"render_modes": ["rgb_array"], "render_fps": core.render_fps}
        if render_mode not in (None, "rgb_array"):
            raise ValueError(
                f"ivy_gym: render_mode must be None or 'rgb_array', got {render_mode!r}."
            )
        self.render_mode = render_mode
        self.action_space = self._single_action_space
        self.observation_space = self._single_observation_space
        self._state = None

    @property
    def state(self) -> np.ndarray | None:
        """The core's state as a float64 numpy array ``(state_dim,)`` (None before reset)."""
        return None if self._state is None else np.asarray(ivy.to_numpy(self._state), np.float64)

    @state.setter
    def state(self, value) -> None:
        value = np.asarray(value, dtype=np.float64)
        if value.shape != (self.core.state_dim,):
            raise ValueError(
                f"{self._name}: the state has shape ({self.core.state_dim},) "
                f"{self.core.state_names}; got shape {value.shape}."
            )
        self._state = self.xp.asarray(value, dtype=self.dtype, device=self._device)

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        super().reset(seed=seed)
        self._state, obs, info = self._to_backend(self.core.draw_initial(self.np_random))
        return self._observation(obs), self._info(info, self.action_dtype)

    def step(self, action):
        if self._state is None:
            raise RuntimeError(f"{self._name}: call reset() before step().")
        a = self._checked_actions(action, ())
        state, obs, reward, terminated, info = self._step(self._state, a)
        self._state = state
        return (
            self._observation(obs),
            self._reward(self._to_numpy(reward)),
            bool(self._to_numpy(terminated)),
            False,
            self._info(info, _numpy_dtype(a)),
        )

    def render(self):
        if self.render_mode != "rgb_array":
            gymnasium.logger.warn(
                "ivy_gym: render() needs render_mode='rgb_array' (e.g. gymnasium.make(id, "
                "render_mode='rgb_array')); returning None."
            )
            return None
        if self._state is None:
            raise RuntimeError(f"{self._name}: call reset() before render().")
        return self._frame(self._state)


class GymnasiumVectorEnv(_Facade, VectorEnv):
    """A native Gymnasium ``VectorEnv``: ``num_envs`` copies of an ivy_gym core stepped by one
    batched array call, with Gymnasium's next-step autoreset (or none) and a time limit.

    At the step after an environment terminated or was truncated it restarts instead: its
    action is ignored, the observation is a fresh initial one, the reward 0 and both flags
    False (``metadata["autoreset_mode"]`` is ``AutoresetMode.NEXT_STEP``, as Gymnasium's own
    vectorised CartPole).

    With ``autoreset_mode=AutoresetMode.DISABLED`` nothing restarts by itself: the caller resets
    the environments it chooses, ``reset(seed=seeds, options={"reset_mask": mask})``, as
    Gymnasium's ``SyncVectorEnv`` with that mode allows (ivy_rl's trainer drives its workers so).
    Each copy then has its own generator, as each environment of a ``SyncVectorEnv`` has: a seed
    ``s`` for copy ``i`` (a list of seeds, or ``seed + i`` for a number) draws its state as
    ``gymnasium.make(...).reset(seed=s)`` draws it; a copy reset without a seed continues its
    own generator.

    Args:
        core: the environment's core.
        num_envs: number of copies.
        framework, dtype, render_mode, discrete, device: as for :class:`GymnasiumEnv`.
        max_episode_steps: time limit per episode (None: none).
        compile: run the batched step (and the reset's kernels) through ``ivy.compile_fn``; by
            default where the compiler keeps loops (jax, tensorflow: they also start in a
            second; torch.compile takes ~20 s).
        autoreset_mode: ``AutoresetMode.NEXT_STEP`` (default) or ``AutoresetMode.DISABLED``
            (or their names).

    Example:
        >>> envs = GymnasiumVectorEnv(ivy_gym.CartPole(), 1024, framework="jax", discrete=True)
        >>> obs, info = envs.reset(seed=0)
        >>> obs, rewards, terminated, truncated, info = envs.step(envs.action_space.sample())
    """

    def __init__(
        self,
        core: Env,
        num_envs: int = 1,
        *,
        framework: Framework = "numpy",
        dtype: Dtype | None = None,
        max_episode_steps: int | None = None,
        render_mode: str | None = None,
        discrete: bool = False,
        compile: bool | None = None,
        device: str | None = None,
        autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP,
    ) -> None:
        self._setup(core, framework, dtype, discrete, device, compile)
        modes = (AutoresetMode.NEXT_STEP, AutoresetMode.DISABLED)
        mode = AutoresetMode(autoreset_mode) if isinstance(autoreset_mode, str) else autoreset_mode
        if mode not in modes:
            raise ValueError(
                f"ivy_gym: autoreset_mode must be one of {[m.value for m in modes]}, got "
                f"{autoreset_mode!r}."
            )
        self._autoreset = mode is AutoresetMode.NEXT_STEP
        if int(num_envs) < 1:
            raise ValueError(f"ivy_gym: num_envs must be at least 1, got {num_envs}.")
        if render_mode not in (None, "rgb_array"):
            raise ValueError(
                f"ivy_gym: render_mode must be None or 'rgb_array', got {render_mode!r}."
            )
        self.metadata = {
            "render_modes": ["rgb_array"],
            "render_fps": core.render_fps,
            "autoreset_mode": mode,
        }
        self.num_envs = int(num_envs)
        self.render_mode = render_mode
        self.max_episode_steps = max_episode_steps
        self.single_action_space = self._single_action_space
        self.single_observation_space = self._single_observation_space
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self._state = None
        self._steps = np.zeros(self.num_envs, np.int64)
        self._prev_done = np.zeros(self.num_envs, bool)
        self._rngs: list | None = None  # the copies' own generators (without autoreset)

    @property
    def state(self) -> np.ndarray | None:
        """The cores' states as a float64 numpy array ``(num_envs, state_dim)``."""
        return None if self._state is None else np.asarray(ivy.to_numpy(self._state), np.float64)

    def reset(self, *, seed: int | list | None = None, options: dict[str, Any] | None = None):
        if not self._autoreset:
            return self._masked_reset(seed, options)
        super().reset(seed=seed)
        draws = self.core.draw_initial(self.np_random, self.num_envs)
        self._state, obs, info = self._to_backend(draws)
        self._steps[:] = 0
        self._prev_done[:] = False
        return self._observation(obs), self._vector_info(info, self.action_dtype)

    def _masked_reset(self, seed, options):
        """A reset without autoreset: the copies of ``options['reset_mask']`` (all by default)
        draw from their own generators, seeded by ``seed``; the others keep their state."""
        n = self.num_envs
        mask = np.ones(n, bool) if not options else options.get("reset_mask", np.ones(n, bool))
        mask = np.asarray(mask, bool)
        if mask.shape != (n,):
            raise ValueError(f"{self._name}: reset_mask must have shape ({n},), got {mask.shape}.")
        if self._state is None and not mask.all():
            raise RuntimeError(f"{self._name}: the first reset() must reset every copy.")
        if seed is None or isinstance(seed, (list, tuple, np.ndarray)):
            seeds = [None] * n if seed is None else list(seed)
            if len(seeds) != n:
                raise ValueError(f"{self._name}: {len(seeds)} seeds for {n} environments.")
        else:
            seeds = [int(seed) + i for i in range(n)]
        if self._rngs is None:
            self._rngs = [gymnasium.utils.seeding.np_random(s)[0] for s in seeds]
        else:
            for i in np.flatnonzero(mask):
                if seeds[i] is not None:
                    self._rngs[i] = gymnasium.utils.seeding.np_random(seeds[i])[0]
        draws = np.zeros((n, self.core.state_dim)) if self._state is None else self.state
        for i in np.flatnonzero(mask):
            draws[i] = self.core.draw_initial(self._rngs[i])
        # the whole batch through the reset's kernels (one compiled shape); kept copies after
        fresh, obs, info = self._to_backend(draws)
        state_np, obs = self._numpy(fresh), self._observation(obs)
        if not mask.all():  # the others keep their state and last observation
            state_np = np.where(mask[:, None], state_np, self._numpy(self._state))
            obs = np.where(mask[:, None], obs, self._last_obs)
        self._state = self.xp.asarray(state_np, device=self._device)
        self._steps[mask] = 0
        self._last_obs = obs
        return obs, self._vector_info(info, self.action_dtype)

    def step(self, actions):
        if self._state is None:
            raise RuntimeError(f"{self._name}: call reset() before step().")
        a = self._checked_actions(actions, (self.num_envs,))
        state, obs, reward, terminated, info = self._step(self._state, a)
        state_np, obs, reward = self._numpy(state), self._observation(obs), self._numpy(reward)
        terminated = np.asarray(self._to_numpy(terminated), bool)
        info = self._vector_info(info, _numpy_dtype(a))
        steps = self._steps
        steps += 1
        if self.max_episode_steps is None:
            truncated = np.zeros(self.num_envs, bool)
        else:
            truncated = steps >= self.max_episode_steps
        restart = self._prev_done if self._autoreset else np.zeros(self.num_envs, bool)
        restarts = np.count_nonzero(restart)
        if restarts:
            # Gymnasium's next-step autoreset, in place on numpy copies of this step's outputs;
            # the fresh draws (only the restarting copies draw) go through the reset's kernels
            # with the whole batch, so that a compiled reset keeps one shape
            if not state_np.flags.writeable or state_np is self._to_numpy(self._state):
                state_np = state_np.copy()
            draws = state_np.astype(np.float64)
            draws[restart] = self.core.draw_initial(self.np_random, restarts)
            fresh, fresh_obs, fresh_info = self._to_backend(draws)
            state_np[restart] = self._numpy(fresh)[restart]
            state = self.xp.asarray(state_np, device=self._device)
            if not obs.flags.writeable:
                obs = obs.copy()
            obs[restart] = self._observation(fresh_obs)[restart]
            reward[restart] = 0.0
            terminated[restart] = False
            truncated[restart] = False
            steps[restart] = 0
            info = self._restart_info(info, fresh_info, restart)
        if np.may_share_memory(obs, state_np):
            obs = obs.copy()  # the caller's to change: not a view of the state
        self._state = state
        self._prev_done = terminated | truncated
        self._last_obs = obs
        return obs, reward, terminated, truncated, info

    def _restart_info(self, info: dict, fresh_info: dict, restart: np.ndarray) -> dict:
        """The step's info with the restarting copies' entries replaced by their reset info
        (as Gymnasium's vector environments give it), masked out where a key has none."""
        fresh = self._vector_info(fresh_info, self.action_dtype)
        for key in [k for k in info if not k.startswith("_")]:
            if key in fresh:
                info[key][restart] = fresh[key][restart]
            else:
                info[key][restart] = 0
                info["_" + key] = ~restart
        return info

    def render(self):
        if self.render_mode != "rgb_array":
            gymnasium.logger.warn(
                "ivy_gym: render() needs render_mode='rgb_array'; returning None."
            )
            return None
        if self._state is None:
            raise RuntimeError(f"{self._name}: call reset() before render().")
        return [self._frame(row) for row in self.state]


def _numpy_dtype(action) -> np.dtype:
    """The numpy dtype of an action array of any backend."""
    name = getattr(action.dtype, "name", None) or str(action.dtype).rpartition(".")[2]
    return np.dtype(name)
