"""Environment workers as Ray actors (the ``[distributed]`` extra): a Gymnasium vector
environment whose environments live in Ray actors, on this machine or on a Ray cluster, with
the same agent and trainer code.

Each actor holds a group of environments (a synchronous Gymnasium vector environment with
automatic resets disabled); :class:`RayVectorEnv` splits the actions between the groups, steps
them in parallel and gathers the results. Ray is started on first use with ``ray.init()``
unless it is already running (connect to a cluster first with ``ray.init(address=...)``).

Example:
    Eight CartPole environments in two Ray actors, stepped as the trainer steps its workers.
    (Starting Ray takes seconds and forks the process, so the test suite skips these lines.)

    >>> venv = RayVectorEnv("CartPole-v1", 8, groups=2)            # doctest: +SKIP
    >>> workers = ivy_rl.environments.Workers(venv, seed=0)        # doctest: +SKIP
    >>> workers.start().shape                                       # doctest: +SKIP
    (8, 4)
"""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np

__all__ = ["RayVectorEnv"]


def _ray():
    try:
        import ray
    except ImportError as error:
        raise ImportError(
            "Ray workers need the 'ray' package: pip install 'ivy[distributed]'"
        ) from error
    return ray


class _Group:
    """A group of environments inside one Ray actor."""

    def __init__(self, env_id, count, env_kwargs, time_feature, wrappers):
        from ivy_rl.environments import make_vector_env

        self.env = make_vector_env(
            env_id,
            count,
            vectorization="sync",
            env_kwargs=env_kwargs,
            time_feature=time_feature,
            wrappers=wrappers,
        )

    def spaces(self):
        return self.env.single_observation_space, self.env.single_action_space

    def reset(self, seeds, mask):
        options = None if mask is None else {"reset_mask": mask}
        obs, _ = self.env.reset(seed=seeds, options=options)
        return np.asarray(obs)

    def step(self, actions):
        obs, rewards, terminated, truncated, _ = self.env.step(actions)
        return np.asarray(obs), np.asarray(rewards), np.asarray(terminated), np.asarray(truncated)

    def close(self):
        self.env.close()


class RayVectorEnv(gym.vector.VectorEnv):
    """``num_envs`` environments in ``groups`` Ray actors, as one vector environment with
    automatic resets disabled (the interface :class:`ivy_rl.environments.Workers` uses).

    Args:
        env_id: a Gymnasium id.
        num_envs: number of environments.
        groups: number of Ray actors (default: one per environment); environments are split
            between them as evenly as possible.
        env_kwargs: keyword arguments of ``gymnasium.make``.
        time_feature: append the remaining time to the observations.
        wrappers: wrappers of each environment (names or classes).
        num_cpus: CPUs Ray reserves for each actor.

    Example:
        (Starting Ray takes seconds and forks the process, so the test suite skips these lines.)

        >>> venv = RayVectorEnv("Pendulum-v1", 4, groups=2)        # doctest: +SKIP
        >>> obs, info = venv.reset(seed=[0, 1, 2, 3])              # doctest: +SKIP
        >>> obs.shape                                               # doctest: +SKIP
        (4, 3)
    """

    def __init__(
        self,
        env_id: str,
        num_envs: int,
        *,
        groups: int | None = None,
        env_kwargs: dict[str, Any] | None = None,
        time_feature: bool = False,
        wrappers: Any = None,
        num_cpus: float = 0.5,
    ) -> None:
        ray = _ray()
        if not ray.is_initialized():
            ray.init(include_dashboard=False, log_to_driver=False)
        groups = num_envs if groups is None else int(groups)
        if not 1 <= groups <= num_envs:
            raise ValueError(f"groups must be between 1 and num_envs={num_envs}, got {groups}")
        sizes = [num_envs // groups + (i < num_envs % groups) for i in range(groups)]
        remote = ray.remote(num_cpus=num_cpus)(_Group)
        self._actors = [remote.remote(env_id, n, env_kwargs, time_feature, wrappers) for n in sizes]
        self._slices = []
        start = 0
        for n in sizes:
            self._slices.append(slice(start, start + n))
            start += n
        self.num_envs = num_envs
        obs_space, act_space = ray.get(self._actors[0].spaces.remote())
        self.single_observation_space, self.single_action_space = obs_space, act_space
        self.observation_space = gym.vector.utils.batch_space(obs_space, num_envs)
        self.action_space = gym.vector.utils.batch_space(act_space, num_envs)
        self.metadata = {"autoreset_mode": gym.vector.AutoresetMode.DISABLED}
        self._obs: np.ndarray | None = None

    def reset(self, *, seed=None, options=None):
        ray = _ray()
        seeds = list(seed) if isinstance(seed, (list, tuple)) else [seed] * self.num_envs
        mask = None if options is None else options.get("reset_mask")
        calls = {}
        for g, (actor, part) in enumerate(zip(self._actors, self._slices)):
            part_mask = None if mask is None else np.asarray(mask[part])
            if part_mask is not None and not part_mask.any():
                continue
            if part_mask is not None and part_mask.all():
                part_mask = None
            calls[g] = actor.reset.remote(seeds[part], part_mask)
        results = dict(zip(calls, ray.get(list(calls.values()))))
        parts = []
        for g, part in enumerate(self._slices):
            parts.append(results[g] if g in results else self._obs[part])
        self._obs = np.concatenate(parts)
        return self._obs.copy(), {}

    def step(self, actions):
        ray = _ray()
        actions = np.asarray(actions)
        refs = [a.step.remote(actions[part]) for a, part in zip(self._actors, self._slices)]
        results = ray.get(refs)
        obs, rewards, terminated, truncated = (np.concatenate(x) for x in zip(*results))
        self._obs = obs
        return obs.copy(), rewards, terminated, truncated, {}

    def close_extras(self, **kwargs):
        ray = _ray()
        for actor in self._actors:
            ray.kill(actor)
        self._actors = []
