"""Environments for the trainer: Gymnasium vector environments (sync or async workers, or Ray
actors) that keep resets and terminations apart, a time-awareness wrapper, and the record that
lets a checkpoint restore the environments exactly.

:class:`Workers` steps a vector environment built by ``gymnasium.make_vec`` with automatic
resets disabled and resets finished episodes itself, each with a seed drawn from its own
generator. For every step it returns the observations to act on next (the first observation of
a new episode where one ended) and the true next observations, rewards, ``resets``
(terminated or truncated) and ``terminations`` (terminated only): a time limit is a reset, not
a termination. It remembers each episode's seed and actions, so a checkpoint can bring every
worker back to the same state by replaying them (Gymnasium's environments are deterministic
given the seed and the actions). With the time feature (the remaining time as an input), a time
limit is reported as a termination too: the time-limits paper's time-aware setting, where the
limit is part of the task.

Environments are Gymnasium ids, also ``"module:EnvId"`` for one registered by the user's own
module, with Gymnasium wrappers by name (:func:`resolve_wrappers`).

Example:
    >>> import numpy as np
    >>> workers = Workers("CartPole-v1", 8, seed=0)
    >>> obs = workers.start(); obs.shape                # [workers, *observation_shape]
    (8, 4)
    >>> obs, infos = workers.step(np.zeros(8, int))     # each worker pushes left
    >>> sorted(infos)
    ['observations', 'resets', 'rewards', 'terminations']
    >>> infos["rewards"]
    array([1., 1., 1., 1., 1., 1., 1., 1.])
    >>> workers.close()
"""

from __future__ import annotations

import difflib
import importlib
from collections.abc import Callable, Sequence
from typing import Any

import gymnasium as gym
import numpy as np

import ivy

__all__ = [
    "TimeFeature",
    "make_env",
    "make_vector_env",
    "run_env_kwargs",
    "Workers",
    "check_environment_id",
    "closest_ids",
    "resolve_wrappers",
]

VECTORIZATION_MODES = ("sync", "async", "ray", "batched")
ASYNC_START_METHOD = "forkserver"  # how async workers start (multiprocessing's start method)


class TimeFeature(gym.ObservationWrapper):
    """Time awareness (Pardo et al., 2018): the remaining time of the episode, as a fraction
    from 1 at the start to 0 at the time limit, appended to the observations.

    Args:
        env: an environment with a Box observation space of one dimension.
        max_steps: the time limit (default: the environment's ``max_episode_steps``).

    Example:
        >>> import gymnasium
        >>> env = TimeFeature(gymnasium.make("Pendulum-v1"))
        >>> env.observation_space.shape
        (4,)
    """

    def __init__(self, env: gym.Env, max_steps: int | None = None) -> None:
        super().__init__(env)
        space = env.observation_space
        if not isinstance(space, gym.spaces.Box) or len(space.shape) != 1:
            raise TypeError(
                f"TimeFeature needs a Box observation space of one dimension, got {space}"
            )
        if max_steps is None:
            spec = env.spec
            max_steps = spec.max_episode_steps if spec is not None else None
        if not max_steps:
            raise ValueError(
                "TimeFeature needs the time limit: pass max_steps=..., or use an environment "
                "registered with max_episode_steps"
            )
        self.max_steps = int(max_steps)
        self.observation_space = gym.spaces.Box(
            np.append(space.low, 0.0).astype(space.dtype),
            np.append(space.high, 1.0).astype(space.dtype),
            dtype=space.dtype,
        )
        self._steps = 0

    def reset(self, **kwargs):
        self._steps = 0
        return super().reset(**kwargs)

    def step(self, action):
        self._steps += 1
        return super().step(action)

    def observation(self, observation):
        remaining = max(self.max_steps - self._steps, 0) / self.max_steps
        return np.append(observation, remaining).astype(self.observation_space.dtype)


def check_environment_id(env_id: str) -> None:
    """Raise a ValueError naming the three closest registered ids when ``env_id`` is not
    registered.

    ``env_id`` may name the module that registers it, as Gymnasium's ``gymnasium.make`` allows:
    ``"my_package.envs:MyTask-v0"`` imports ``my_package.envs`` first.

    Example:
        >>> check_environment_id("CartPol-v1")
        Traceback (most recent call last):
        ...
        ValueError: unknown environment 'CartPol-v1'; did you mean: CartPole-v1, CartPole-v0, ...
    """
    if not isinstance(env_id, str) or not env_id:
        raise TypeError(f"environment must be a Gymnasium id (a string), got {env_id!r}")
    name = env_id
    if ":" in env_id:
        module, name = env_id.split(":", 1)
        try:
            importlib.import_module(module)
        except ImportError as error:
            raise ValueError(
                f"environment {env_id!r}: cannot import the module {module!r} that should "
                f"register {name!r} ({error}); check that it is installed or on PYTHONPATH"
            ) from None
    if name in gym.registry:
        return
    if name.startswith("ivy_gym/"):
        try:  # ivy_gym's Gymnasium facades register its environments when imported
            import ivy_gym.gymnasium  # noqa: F401
        except ImportError:
            pass
        if name in gym.registry:
            return
    if not name.startswith("ivy_gym/"):
        try:  # ivy_gym's ids are candidates too
            import ivy_gym.gymnasium  # noqa: F401
        except ImportError:
            pass
    close = closest_ids(name, sorted(gym.registry))
    raise ValueError(
        f"unknown environment {env_id!r}; did you mean: {', '.join(close)}? (gymnasium."
        "pprint_registry() lists every registered id)"
    )


def closest_ids(name: str, ids: Sequence[str], n: int = 3) -> list[str]:
    """The ``n`` ids most like ``name`` (ignoring case; difflib's ratio), best first.

    Example:
        >>> closest_ids("cartpole", ["CartPole-v1", "Pendulum-v1", "Acrobot-v1"], 2)
        ['CartPole-v1', 'Acrobot-v1']
    """
    lowered = name.lower()

    def likeness(candidate: str) -> float:
        other = candidate.lower()
        ratio = difflib.SequenceMatcher(None, lowered, other).ratio()
        # an id the name is part of (a version left out, a namespace added) comes first
        return ratio + (1.0 if lowered and lowered in other else 0.0)

    # ties: the later id first (the newest version)
    return sorted(sorted(ids, reverse=True), key=lambda candidate: -likeness(candidate))[:n]


def resolve_wrappers(
    wrappers: Sequence[str | type] | None,
) -> list[Callable[[gym.Env], gym.Env]]:
    """Gymnasium wrappers by name: a name of ``gymnasium.wrappers`` (``"FlattenObservation"``),
    or ``"package.module:ClassName"`` for a wrapper of your own; classes pass through. Each
    wrapper is applied with its default arguments, in the order given.

    Raises:
        ValueError: a name that is not a wrapper, with the names that exist.

    Example:
        >>> resolve_wrappers(["FlattenObservation", "ClipAction"])
        [<class 'gymnasium.wrappers...FlattenObservation'>, <class '...ClipAction'>]
    """
    resolved = []
    for wrapper in wrappers or ():
        if not isinstance(wrapper, str):
            resolved.append(wrapper)
            continue
        if ":" in wrapper:
            module_name, name = wrapper.split(":", 1)
            try:
                module = importlib.import_module(module_name)
            except ImportError as error:
                raise ValueError(
                    f"wrapper {wrapper!r}: cannot import {module_name!r} ({error})"
                ) from None
        else:
            module, name = gym.wrappers, wrapper
        try:
            cls = getattr(module, name, None)
        except ImportError as error:
            raise ValueError(f"wrapper {wrapper!r} needs a package: {error}") from None
        if not (isinstance(cls, type) and issubclass(cls, gym.Wrapper)):
            names = _gymnasium_wrapper_names()
            close = difflib.get_close_matches(wrapper, names, n=3)
            hint = f" did you mean: {', '.join(close)}?" if close else ""
            raise ValueError(
                f"unknown wrapper {wrapper!r};{hint} give a name of gymnasium.wrappers "
                f"({', '.join(names)}) or 'package.module:ClassName'"
            )
        resolved.append(cls)
    return resolved


def _gymnasium_wrapper_names() -> list[str]:
    names = []
    for name in getattr(gym.wrappers, "__all__", ()):
        try:  # some wrappers load optional packages when first touched
            value = getattr(gym.wrappers, name)
        except ImportError:
            continue
        if isinstance(value, type) and issubclass(value, gym.Wrapper):
            names.append(name)
    return sorted(names)


def _wrappers(
    wrappers: Sequence[str | type] | None, time_feature: bool
) -> list[Callable[[gym.Env], gym.Env]]:
    """The user's wrappers, then the time feature (which needs a flat Box observation)."""
    return resolve_wrappers(wrappers) + ([TimeFeature] if time_feature else [])


def run_env_kwargs(env_id: str, env_kwargs: dict[str, Any] | None, framework: Any) -> dict:
    """``env_kwargs`` with the backend of an ivy_gym MuJoCo task chosen for a run on
    ``framework``: that framework where its compiler keeps loops (jax, tensorflow), since such a
    task's facade is then compiled (a Hopper step: 2.5 ms on jax, 28 ms on tensorflow, 44 ms on
    numpy, 118 ms on eager torch); else the facade's own default, numpy. A ``framework`` the
    user gives is kept, and other environments are left alone (the classic tasks are fastest on
    numpy). The trainer records the result, so a resumed run steps the same physics.

    Example:
        >>> run_env_kwargs("ivy_gym/Hopper-v5", {}, "jax")
        {'framework': 'jax'}
        >>> run_env_kwargs("ivy_gym/Hopper-v5", {}, "torch"), run_env_kwargs("Hopper-v5", {}, "jax")
        ({}, {})
    """
    kwargs = dict(env_kwargs or {})
    name = env_id.split(":", 1)[-1]
    if "framework" in kwargs or not name.startswith("ivy_gym/"):
        return kwargs
    import ivy_gym
    from ivy_gym.mujoco_env import MuJoCoEnv

    check_environment_id(env_id)
    task = gym.spec(name).kwargs.get("task")
    core = ivy_gym.TASKS.get(task, (None,))[0]
    xp = ivy.get_framework(f=framework)
    caps = xp.capabilities
    if isinstance(core, type) and issubclass(core, MuJoCoEnv):
        if caps.compilation and caps.compiled_loops:
            kwargs["framework"] = xp.backend
    return kwargs


def make_env(
    env_id: str,
    *,
    env_kwargs: dict[str, Any] | None = None,
    time_feature: bool = False,
    render_mode: str | None = None,
    wrappers: Sequence[str | type] | None = None,
) -> gym.Env:
    """One environment (for tests and play), with the trainer's wrappers.

    Args:
        env_id: a Gymnasium id, optionally ``"module:EnvId"``.
        env_kwargs: keyword arguments of ``gymnasium.make``.
        time_feature: append the remaining time to the observations.
        render_mode: Gymnasium's render mode.
        wrappers: wrappers applied first (names, see :func:`resolve_wrappers`).

    Example:
        >>> env = make_env("Pendulum-v1", time_feature=True)
    """
    check_environment_id(env_id)
    kwargs = dict(env_kwargs or {})
    if render_mode is not None:
        kwargs["render_mode"] = render_mode
    env = gym.make(env_id, **kwargs)
    for wrap in _wrappers(wrappers, time_feature):
        env = wrap(env)
    return env


def make_vector_env(
    env_id: str,
    workers: int,
    *,
    vectorization: str = "sync",
    env_kwargs: dict[str, Any] | None = None,
    time_feature: bool = False,
    ray_groups: int | None = None,
    wrappers: Sequence[str | type] | None = None,
) -> gym.vector.VectorEnv:
    """``workers`` copies of an environment as one vector environment whose automatic resets
    are disabled (:class:`Workers` resets them).

    Args:
        env_id: a Gymnasium id (classic control, MuJoCo, ``ivy_gym/...``).
        workers: number of environments.
        vectorization: ``'sync'`` (one process), ``'async'`` (one subprocess per environment,
            started by multiprocessing's ``forkserver``, never a fork of this process, which may
            have framework threads running), ``'ray'`` (Ray actors; the ``[distributed]`` extra)
            or ``'batched'`` (ivy_gym's tasks: every copy in one batched, compiled call of the
            physics, :class:`ivy_gym.gymnasium.GymnasiumVectorEnv`; hundreds or thousands of
            copies cost little more than one).
        env_kwargs: keyword arguments of ``gymnasium.make``.
        time_feature: append the remaining time to the observations.
        ray_groups: with ``'ray'``, the number of actors (default: one per environment).
        wrappers: wrappers of each environment (names, see :func:`resolve_wrappers`).

    Example:
        >>> venv = make_vector_env("CartPole-v1", 8, vectorization="async")
    """
    if vectorization not in VECTORIZATION_MODES:
        raise ValueError(
            f"unknown vectorization {vectorization!r}; choose one of {VECTORIZATION_MODES}"
        )
    if workers < 1:
        raise ValueError(f"workers must be >= 1, got {workers}")
    check_environment_id(env_id)
    wrap = _wrappers(wrappers, time_feature)  # unknown wrappers fail here, in this process
    if vectorization == "batched":
        if not env_id.split(":", 1)[-1].startswith("ivy_gym/"):
            raise ValueError(
                f"vectorization 'batched' steps every copy of an ivy_gym task in one call; "
                f"{env_id!r} is not one: use 'sync' or 'async'"
            )
        if wrap:
            raise ValueError(
                "vectorization 'batched' takes no wrappers or time feature (they wrap single "
                "environments): use 'sync' or 'async' with them"
            )
        return gym.make_vec(
            env_id,
            num_envs=workers,
            vectorization_mode="vector_entry_point",
            autoreset_mode=gym.vector.AutoresetMode.DISABLED,
            **(env_kwargs or {}),
        )
    if vectorization == "ray":
        from ivy_rl.distributed import RayVectorEnv

        return RayVectorEnv(
            env_id,
            workers,
            groups=ray_groups,
            env_kwargs=env_kwargs,
            time_feature=time_feature,
            wrappers=wrappers,
        )
    vector_kwargs: dict[str, Any] = {"autoreset_mode": gym.vector.AutoresetMode.DISABLED}
    if vectorization == "async":
        # Subprocesses start from a fresh interpreter (forkserver) rather than a fork of this
        # one: a fork of a process with jax, tensorflow or torch threads running can deadlock.
        vector_kwargs["context"] = ASYNC_START_METHOD
    return gym.make_vec(
        env_id,
        num_envs=workers,
        vectorization_mode=vectorization,
        vector_kwargs=vector_kwargs,
        wrappers=wrap,
        **(env_kwargs or {}),
    )


class Workers:
    """Steps a vector environment for the trainer; see the module's docstring.

    Args:
        env_id: a Gymnasium id, or an already built vector environment with automatic resets
            disabled.
        workers: number of environments (with an id).
        seed: seed of the generator of the episodes' seeds.
        vectorization, env_kwargs, time_feature, ray_groups, wrappers: as for
            :func:`make_vector_env`.
        terminal_time_limits: report the end of an episode at its time limit as a termination
            (default: with ``time_feature``, as in the time-limits paper: once the remaining
            time is an input, the time limit is part of the task and terminal). False: a time
            limit is a reset only, and agents bootstrap there (partial-episode bootstrapping).

    Example:
        >>> workers = Workers("Pendulum-v1", 4, seed=1, vectorization="async")
    """

    def __init__(
        self,
        env_id: str | gym.vector.VectorEnv,
        workers: int = 1,
        *,
        seed: int = 0,
        vectorization: str = "sync",
        env_kwargs: dict[str, Any] | None = None,
        time_feature: bool = False,
        ray_groups: int | None = None,
        wrappers: Sequence[str | type] | None = None,
        terminal_time_limits: bool | None = None,
    ) -> None:
        self.terminal_time_limits = (
            bool(time_feature) if terminal_time_limits is None else bool(terminal_time_limits)
        )
        if isinstance(env_id, gym.vector.VectorEnv):
            self.env = env_id
        else:
            self.env = make_vector_env(
                env_id,
                workers,
                vectorization=vectorization,
                env_kwargs=env_kwargs,
                time_feature=time_feature,
                ray_groups=ray_groups,
                wrappers=wrappers,
            )
        self.num_workers = self.env.num_envs
        self.observation_space = self.env.single_observation_space
        self.action_space = self.env.single_action_space
        self.seed_rng = np.random.default_rng([int(seed), 7])
        self.episode_seeds = np.zeros(self.num_workers, np.int64)
        self.histories: list[list[np.ndarray]] = [[] for _ in range(self.num_workers)]
        self.observations: np.ndarray | None = None

    def _draw_seeds(self, mask: np.ndarray) -> list[int | None]:
        seeds: list[int | None] = [None] * self.num_workers
        for i in np.flatnonzero(mask):
            seeds[i] = int(self.seed_rng.integers(2**31 - 1))
            self.episode_seeds[i] = seeds[i]
            self.histories[i] = []
        return seeds

    def start(self) -> np.ndarray:
        """Reset every environment with a fresh seed; return the first observations."""
        seeds = self._draw_seeds(np.ones(self.num_workers, bool))
        obs, _ = self.env.reset(seed=seeds)
        self.observations = np.asarray(obs)
        return self.observations

    def step(self, actions: np.ndarray) -> tuple[np.ndarray, dict[str, np.ndarray]]:
        """Step every environment; reset those whose episode ended.

        Returns:
            ``(observations, infos)``: the observations to act on next, and ``infos`` with the
            true next ``observations``, ``rewards``, ``resets`` and ``terminations`` (time limits
            included with ``terminal_time_limits``).
        """
        actions = np.asarray(actions)
        for i in range(self.num_workers):
            self.histories[i].append(actions[i].copy())
        next_obs, rewards, terminated, truncated, _ = self.env.step(actions)
        next_obs = np.asarray(next_obs)
        terminated = np.asarray(terminated, bool)
        resets = terminated | np.asarray(truncated, bool)
        if self.terminal_time_limits:
            terminated = resets
        observations = next_obs
        if resets.any():
            seeds = self._draw_seeds(resets)
            reset_obs, _ = self.env.reset(seed=seeds, options={"reset_mask": resets})
            observations = np.where(
                resets.reshape((-1,) + (1,) * (next_obs.ndim - 1)), np.asarray(reset_obs), next_obs
            )
        self.observations = observations
        infos = {
            "observations": next_obs,
            "rewards": np.asarray(rewards, np.float64),
            "resets": resets,
            "terminations": terminated,
        }
        return observations, infos

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def state_dict(self) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
        """``(arrays, meta)``: each episode's actions so far, and the seeds and generator."""
        arrays = {}
        for i, history in enumerate(self.histories):
            shape = (0,) + tuple(self.action_space.shape)
            arrays[str(i)] = (
                np.stack(history) if history else np.zeros(shape, self.action_space.dtype)
            )
        meta = {
            "episode_seeds": [int(s) for s in self.episode_seeds],
            "seed_rng": self.seed_rng.bit_generator.state,
        }
        return arrays, meta

    def load_state_dict(self, arrays: dict[str, np.ndarray], meta: dict[str, Any]) -> np.ndarray:
        """Bring every environment to the saved state by resetting it with its episode's seed
        and replaying its actions; returns the observations to act on."""
        if len(meta["episode_seeds"]) != self.num_workers:
            raise ValueError(
                f"the checkpoint has {len(meta['episode_seeds'])} workers, this run "
                f"{self.num_workers}"
            )
        histories = [list(arrays[str(i)]) for i in range(self.num_workers)]
        seeds = [int(s) for s in meta["episode_seeds"]]
        lengths = np.array([len(h) for h in histories])
        longest = int(lengths.max()) if len(lengths) else 0
        starts = longest - lengths  # worker i starts its episode at replay step starts[i]
        obs = None
        for k in range(longest + 1):
            # workers whose episode starts now get their seed; those not started yet are
            # kept fresh with unseeded resets (their state is replaced when they start)
            mask = starts >= k
            if k == 0:
                mask = np.ones(self.num_workers, bool)
            reset_seeds = [seeds[i] if starts[i] == k else None for i in range(self.num_workers)]
            if mask.any():
                options = None if mask.all() else {"reset_mask": mask}
                reset_obs, _ = self.env.reset(seed=reset_seeds, options=options)
                reset_obs = np.asarray(reset_obs)
                if obs is None:
                    obs = reset_obs
                else:
                    obs = np.where(mask.reshape((-1,) + (1,) * (obs.ndim - 1)), reset_obs, obs)
            if k == longest:
                break
            acts = np.stack(
                [
                    histories[i][k - starts[i]] if k >= starts[i] else self.action_space.sample()
                    for i in range(self.num_workers)
                ]
            )
            obs, _, terminated, truncated, _ = self.env.step(acts)
            obs = np.asarray(obs)
            ended = np.asarray(terminated, bool) | np.asarray(truncated, bool)
            if np.any(ended & (starts <= k)):
                raise RuntimeError(
                    "replaying the saved actions ended an episode early: the environment is not "
                    "deterministic given its seed and actions, so it cannot be restored exactly"
                )
        self.episode_seeds = np.array(seeds, np.int64)
        self.histories = histories
        self.seed_rng.bit_generator.state = meta["seed_rng"]
        self.observations = obs
        return obs

    def close(self) -> None:
        self.env.close()


def _stack(values: Sequence[Any]) -> np.ndarray:
    return np.stack([np.asarray(v) for v in values])
