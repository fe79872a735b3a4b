"""What the agents that learn through ivy_gym's gradients share (:class:`~ivy_rl.agents.APG`,
:class:`~ivy_rl.agents.SHAC`).

Such an agent acts in the trainer's environments like any other (``step``, ``test_step``), but
learns inside ``update`` from differentiable rollouts of the environment's core, an
:class:`ivy_gym.Env`: the trainer first calls ``agent.bind_environment(environment,
env_kwargs)``, which resolves the Gymnasium id to its core (and refuses, in one line, an
environment that has none), and the agent counts the environment steps its rollouts consume in
``agent.simulated_steps``, which the trainer adds to its own count of steps.

The policy is deterministic, ``tanh`` of an MLP (:class:`~ivy_rl.models.DeterministicHead`),
rescaled to the action space; in the trainer's environments it acts with Gaussian exploration
noise of scale ``exploration_noise``. Initial states of the rollouts are drawn from the core's
reset box by the agent's numpy generator, so that compiled functions draw nothing.

Compilation follows the rule of the other agents, by capability: where ``ivy.compile_fn``
compiles ``ivy.scan`` as a loop (``compiled_loops``), the whole update (rollout, gradient
through it, every optimisation step) is one compiled function (``fusion='update'``); where it
unrolls loops (``torch.compile``, which takes minutes on a rollout and its backward pass), the
rollout and its gradient run eagerly and each critic step is compiled on its own
(``fusion='steps'``). Same numbers either way.

Example:
    >>> import gymnasium as gym, numpy as np, ivy_gym    # ivy_gym registers its ids
    >>> env = gym.make("ivy_gym/Pendulum-v1")
    >>> agent = ivy_rl.agents.APG()
    >>> agent.bind_environment("ivy_gym/Pendulum-v1", {})
    >>> agent = agent.initialize(env.observation_space, env.action_space, seed=0, f="jax")
    >>> agent.test_step(np.zeros((2, 3), np.float32)).shape   # acts like any agent
    (2, 1)
    >>> agent.bind_environment("CartPole-v1", {})
    Traceback (most recent call last):
    ValueError: APG: 'CartPole-v1' is not a differentiable ivy_gym environment ...
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Any

import numpy as np

import ivy
from ivy_rl.agents.agent import Agent
from ivy_rl.agents.fusion import FUSION, check_fusion, fusion_level
from ivy_rl.differentiable_parts import ActorValueModel, AnalyticPolicyGradient
from ivy_rl.explorations import NormalNoise
from ivy_rl.normalizers import _fold_moments, _standard_deviation
from ivy_rl.replays import Rollouts

__all__ = ["DifferentiableAgent", "environment_core"]

#: Keyword arguments of the ivy_gym facades that are not the core's.
_FACADE_KWARGS = ("task", "framework", "dtype", "render_mode", "max_episode_steps", "compile")


def environment_core(environment: str, env_kwargs: dict[str, Any] | None = None, *, who: str = ""):
    """The :class:`ivy_gym.Env` behind a Gymnasium id of ivy_gym, and its time limit.

    Args:
        environment: a Gymnasium id such as ``'ivy_gym/Pendulum-v1'`` (``'module:id'`` imports
            the module first).
        env_kwargs: the keyword arguments given to ``gymnasium.make`` (the core's parameters,
            e.g. ``{'g': 9.81}``; the facade's own are ignored).
        who: the agent's name, for the error messages.

    Returns:
        ``(core, max_episode_steps)``.

    Raises:
        ValueError: in one line, when the id is unknown or not a differentiable ivy_gym task.

    Example:
        >>> core, limit = environment_core("ivy_gym/Pendulum-v1")
        >>> type(core).__name__, limit
        ('Pendulum', 200)
    """
    import gymnasium

    import ivy_gym
    from ivy_gym.gymnasium.registration import make_env  # registers ivy_gym's ids

    prefix = f"{who}: " if who else ""
    env_id = str(environment)
    if ":" in env_id:
        module, env_id = env_id.split(":", 1)
        importlib.import_module(module)
    try:
        spec = gymnasium.spec(env_id)
    except gymnasium.error.Error:
        raise ValueError(
            f"{prefix}unknown environment {environment!r}; give an ivy_gym id such as "
            f"'ivy_gym/Pendulum-v1'"
        ) from None
    task = spec.kwargs.get("task")
    ivy_entry_points = (make_env, f"{make_env.__module__}:{make_env.__name__}")
    if spec.entry_point not in ivy_entry_points or task not in ivy_gym.TASKS:
        choices = ", ".join(f"ivy_gym/{t}" for t, (_, d, _) in ivy_gym.TASKS.items() if not d)
        raise ValueError(
            f"{prefix}{environment!r} is not a differentiable ivy_gym environment (its entry "
            f"point is {spec.entry_point!r}); this agent learns through the gradients of one of: "
            f"{choices}"
        )
    cls, discrete, _ = ivy_gym.TASKS[task]
    if discrete:
        raise ValueError(
            f"{prefix}{environment!r} has discrete actions, which have no gradient; use its "
            f"continuous version or another ivy_gym task"
        )
    merged = {**spec.kwargs, **(env_kwargs or {})}
    core = cls(**{k: v for k, v in merged.items() if k not in _FACADE_KWARGS})
    limit = merged.get("max_episode_steps") or spec.max_episode_steps or cls.max_episode_steps
    return core, int(limit)


class DifferentiableAgent(Agent):
    """Base class of the agents that learn through the gradients of an ivy_gym core.

    Subclasses define ``_defaults`` and the pure update ``_update_fn``; see the module's
    docstring for the contract with the trainer.
    """

    learns = True
    differentiable = True
    scheduled: tuple[str, ...] = ("actor_lr",)
    supported_action_spaces = ("Box",)
    own_settings = {"fusion": FUSION}
    _defaults: dict[str, Any] = dict(fusion="auto")

    #: the flat settings of the parts (SHAC adds its critic's)
    parts = {
        "model": (
            ActorValueModel,
            {
                "hidden_sizes": "hidden_sizes",
                "activation": "activation",
                "normalize_observations": "normalize_observations",
            },
        ),
        "replay": (
            Rollouts,
            {
                "batch_size": "batch_size",
                "horizon": "horizon",
                "update_every": "update_every",
                "discount": "discount",
            },
        ),
        "exploration": (NormalNoise, {"exploration_noise": "scale"}),
        "actor_updater": (
            AnalyticPolicyGradient,
            {
                "actor_lr": "lr",
                "actor_gradient_clip": "gradient_clip",
                "adam_beta1": "beta1",
                "adam_beta2": "beta2",
            },
        ),
    }

    def __init__(self, **settings: Any) -> None:
        config, parts = self._composed(settings)
        check_fusion(type(self).__name__, config["fusion"])
        for role, part in parts.items():
            setattr(self, role, part)
        super().__init__(**config)
        self.core = None
        self.simulated_steps = 0

    # ------------------------------------------------------------------------------------------
    # The trainer's hook
    # ------------------------------------------------------------------------------------------

    def bind_environment(self, environment: str, env_kwargs: dict[str, Any] | None = None) -> None:
        """Resolve the Gymnasium id of the environment to its ivy_gym core, through whose
        gradients the agent learns (called by the trainer before :meth:`initialize`).

        Raises:
            ValueError: in one line, if the environment is not a differentiable ivy_gym task
                (e.g. Gymnasium's ``'CartPole-v1'``).

        Example:
            >>> APG().bind_environment("ivy_gym/Reacher-v0", {"num_joints": 3})
        """
        self.core, self.episode_steps = environment_core(
            environment, env_kwargs, who=type(self).__name__
        )
        self.environment = str(environment)

    # ------------------------------------------------------------------------------------------
    # Building
    # ------------------------------------------------------------------------------------------

    def _build(self) -> None:
        core, c, xp = self.core, self.config, self.xp
        obs_shape = tuple(self.observation_space.shape)
        if len(obs_shape) != 1 or len(self.action_space.shape) != 1:
            raise ValueError(
                f"{type(self).__name__}: expected flat observations and actions, got spaces of "
                f"shapes {obs_shape} and {self.action_space.shape}"
            )
        if core is not None:
            self._check_core_spaces(obs_shape)
        self._obs_dim, action_dim = obs_shape[0], self.action_space.shape[0]
        self.model.initialize(
            self._obs_dim,
            action_dim,
            rng=self.rng,
            dtype=self.dtype,
            device=self.device,
            f=xp,
        )
        self.actor, self.critic = self.model.actor, self.model.critic
        # running moments of the rollouts' observations (None: not normalised)
        normalized = self.model.normalize_observations
        self.obs_moments = self._moments((self._obs_dim,)) if normalized else None
        low, high = (
            self.action_space.low.astype(np.float64),
            self.action_space.high.astype(np.float64),
        )
        self._action_low = tuple(float(x) for x in low)
        self._action_half = tuple(float(x) for x in (high - low) / 2)
        self.actor_updater.initialize(xp)
        self.actor_optimizer = self.actor_updater.optimizer
        self._build_learner()
        self.fusion = fusion_level(c["fusion"], compiled=self.compiled, f=xp)
        # 'steps': the rollout and its gradient run eagerly (a compiler that unrolls loops
        # would unroll the whole rollout and its backward pass); the critic's steps compile
        self._fused = self.fusion == "update"
        self._compiled_steps: dict[str, Callable] = {}
        self._update = self._compile(self._update_fn) if self._fused else self._update_fn
        self._mode = self._compile(self._mode_fn)
        self.updates, self._calls = 0, 0

    def _check_core_spaces(self, obs_shape) -> None:
        core = self.core
        if obs_shape != (core.observation_dim,) or self.action_space.shape != (core.action_dim,):
            raise ValueError(
                f"{type(self).__name__}: the environment's spaces (observations {obs_shape}, "
                f"actions {self.action_space.shape}) are not those of its ivy_gym core "
                f"({core.observation_dim},), ({core.action_dim},); wrappers that change them "
                "(e.g. time_feature) cannot be differentiated through"
            )

    def _build_learner(self) -> None:
        """Create ``self.v`` (``{'actor': ...}`` and more) and ``self.optimizer_states``."""
        raise NotImplementedError

    def _moments(self, shape: tuple[int, ...] = ()) -> dict[str, Any]:
        """Running moments before any value: count 0, mean 0, mean of squares 1."""
        return {
            k: self._asarray(np.full(s, x, self.np_dtype))
            for k, s, x in (("count", (), 0.0), ("mean", shape, 0.0), ("mean_sq", shape, 1.0))
        }

    # ------------------------------------------------------------------------------------------
    # Pure functions
    # ------------------------------------------------------------------------------------------

    def _stats(self, moments):
        """``{'mean', 'std'}`` from running moments (None: None)."""
        if moments is None:
            return None
        std = _standard_deviation(self.xp, moments["mean"], moments["mean_sq"], 1e-2)
        return {"mean": moments["mean"], "std": std}

    def _fold_observations(self, moments, observations):
        """The moments with a rollout's observations ``[..., obs_dim]`` added (None: None)."""
        if moments is None:
            return None
        xp = self.xp
        flat = xp.reshape(xp.stop_gradient(observations), (-1, self._obs_dim))
        count, mean, mean_sq = _fold_moments(
            moments["count"],
            moments["mean"],
            moments["mean_sq"],
            float(flat.shape[0]),
            xp.sum(flat, axis=0),
            xp.sum(flat * flat, axis=0),
        )
        return {"count": count, "mean": mean, "mean_sq": mean_sq}

    def _policy(self, obs_stats=None) -> Callable:
        """``policy(obs, v)`` in the action space, for ``ivy_gym.rollout``, on observations
        normalised by ``obs_stats``."""
        xp = self.xp

        def policy(obs, v):
            unit = self.actor(obs, obs_stats, v=v).mode()
            low = xp.asarray(self._action_low, dtype=obs.dtype)
            half = xp.asarray(self._action_half, dtype=obs.dtype)
            return low + (unit + 1.0) * half

        return policy

    def _rollout(self, actor_v, states, horizon, window=None, obs_stats=None):
        import ivy_gym

        return ivy_gym.rollout(
            self.core,
            states,
            policy=self._policy(obs_stats),
            v=actor_v,
            horizon=horizon,
            window=window,
            f=self.xp,
        )

    def _discounts(self, steps, dtype):
        """``(steps, 1)``: ``discount ** t``."""
        gamma = self.config["discount"]
        return self.xp.asarray([[gamma**t] for t in range(steps)], dtype=dtype)

    def _actor_minimize(self, loss_fn, actor_v, actor_state, lr):
        """A step of the actor updater on ``loss_fn`` at the learning rate ``lr`` (the
        scheduled value, a scalar array)."""
        return self.actor_updater.minimize(loss_fn, actor_v, actor_state, lr)

    def _mode_fn(self, actor_v, obs_moments, observations):
        return self.actor(observations, self._stats(obs_moments), v=actor_v).mode()

    def _update_fn(self, v, states, *args):
        """The whole update (pure, compiled with ``fusion='update'``); its last argument is
        :meth:`Agent._scheduled_arrays`, the scheduled learning rates at the run's progress."""
        raise NotImplementedError

    # ------------------------------------------------------------------------------------------
    # The fusion levels
    # ------------------------------------------------------------------------------------------

    def _run_loop(self, name, body, carry, xs, *consts):
        """``ivy.scan`` of ``body(carry, x, *consts)`` over the rows of ``xs``: inside the fused
        update, or as a host loop over ``body`` compiled on its own (``fusion='steps'``)."""
        xp = self.xp
        steps = int(xs.shape[0])
        if self._fused or steps == 0:
            return xp.scan(lambda c, x: body(c, x, *consts), carry, xs)
        if name not in self._compiled_steps:
            self._compiled_steps[name] = self._compile(body)
        step = self._compiled_steps[name]
        ys = []
        for i in range(steps):
            carry, y = step(carry, xs[i], *consts)
            ys.append(y)
        return carry, {k: xp.stack([y[k] for y in ys]) for k in ys[0]}

    # ------------------------------------------------------------------------------------------
    # Acting and learning
    # ------------------------------------------------------------------------------------------

    def _unit_actions(self, observations: Any) -> np.ndarray:
        obs = self._observations(observations)
        mode = self._mode(self.v["actor"], self.obs_moments, self._asarray(obs))
        return np.asarray(self.xp.to_numpy(mode), np.float64)

    def step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        return self._env_actions(self.exploration(self._unit_actions(observations), self.rng))

    def test_step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        return self._env_actions(self._unit_actions(observations))

    def _initial_states(self, count: int) -> np.ndarray:
        """``count`` initial states of the core, drawn by the agent's generator as the core's
        Gymnasium reset draws them (:meth:`ivy_gym.Env.draw_initial`; the parts a MuJoCo task
        carries, its warm start and tracked position, filled in as its reset does)."""
        draws = self.core.draw_initial(self.rng, count)
        states = self.core.kernel_initial(ivy.get_framework(f="numpy"), draws)
        return np.asarray(states, self.np_dtype)

    def update(self, observations, rewards, resets, terminations) -> dict[str, float]:
        """Learn from ``batch_size`` differentiable rollouts every ``update_every`` calls (the
        transitions of the trainer's environments are not used: the rollouts are the data).

        Returns:
            The logged scalars of the update (``actor/loss``, ``actor/gradient_norm``, the
            return of the rollouts ``actor/rollout_return`` ...), or an empty dict.
        """
        self._check_initialized()
        if self.core is None:
            raise RuntimeError(
                f"{type(self).__name__} learns through an ivy_gym environment: call "
                "agent.bind_environment('ivy_gym/<Task>', env_kwargs) before learning (the "
                "trainer does; acting, e.g. in play, needs no environment)"
            )
        self._calls += 1
        if self._calls % self.config["update_every"]:
            return {}
        return self._learn()

    def _learn(self) -> dict[str, float]:
        raise NotImplementedError

    def _logs(self, logs: dict[str, Any]) -> dict[str, float]:
        self.updates += 1
        return {k: float(np.asarray(self.xp.to_numpy(x))) for k, x in logs.items()}

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def _arrays(self) -> dict[str, Any]:
        arrays = {"v": self.v, "optimizer": self.optimizer_states}
        if self.obs_moments is not None:
            arrays["observation_moments"] = self.obs_moments
        return arrays

    def _load_arrays(self, arrays: dict[str, Any]) -> None:
        self.v = self._to_backend(arrays["v"], self.v)
        self.optimizer_states = self._to_backend(arrays["optimizer"], self.optimizer_states)
        if self.obs_moments is not None and "observation_moments" in arrays:
            moments = arrays["observation_moments"]
            self.obs_moments = self._to_backend(moments, self.obs_moments)

    def _meta(self) -> dict[str, Any]:
        return {
            "updates": self.updates,
            "calls": self._calls,
            "simulated_steps": self.simulated_steps,
        }

    def _load_meta(self, meta: dict[str, Any]) -> None:
        self.updates = int(meta.get("updates", 0))
        self._calls = int(meta.get("calls", 0))
        self.simulated_steps = int(meta.get("simulated_steps", 0))
