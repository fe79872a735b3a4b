"""A2C: advantage actor-critic (also called vanilla policy gradient), the base of PPO and TRPO.

Each update uses one segment of ``segment_size`` steps of every worker. Its numbers form one
function of arrays, :meth:`A2C._update_fn`, compiled with ``ivy.compile_fn`` as a whole
(``fusion="update"``, what ``"auto"`` chooses where the compiler compiles loops as loops):

1. the critic evaluates the observations and the true next observations;
2. λ-returns and advantages follow by an ``ivy.scan`` backwards in time, with partial-episode
   bootstrapping (bootstrapped at time limits, not at terminations); the advantages are
   standardised and, with ``normalize_returns``, the returns' running moments are updated;
3. the models are optimised: here one actor step on the whole segment, then ``ivy.scan`` over
   the critic's mini-batches (PPO and TRPO change this part). The mini-batch orders are an input
   drawn from the agent's numpy generator, so the compiled function draws nothing.

With ``fusion="steps"`` the same code is compiled piece by piece instead: the critic's values
as one function, each optimisation step as another, the loops (the returns' scan, the
mini-batches) running on the host. Compilers that unroll ``ivy.scan`` (``torch.compile``) take
minutes on a whole update; this level keeps each compiled function one step long. Both levels
give the same numbers, as does ``compile=False`` (everything eager).

An agent is composed of parts, as in Tonic: ``A2C(model=..., replay=..., actor_updater=...,
critic_updater=...)`` (:class:`~ivy_rl.models.ActorCriticModel`,
:class:`~ivy_rl.replays.Segment`, the updaters of :mod:`ivy_rl.updaters`). Flat settings
(``A2C(segment_size=128)``, the command line's ``--agent-kwargs``) build the parts a setting
belongs to, and ``agent.config`` holds the flat settings of every part.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = A2C(segment_size=128).initialize(env.observation_space, env.action_space,
    ...                                         seed=0, f="jax")
    >>> from ivy_rl.replays import Segment
    >>> from ivy_rl.updaters import StochasticPolicyGradient
    >>> agent = A2C(replay=Segment(128, discount=0.98),
    ...             actor_updater=StochasticPolicyGradient(3e-3))
    >>> agent.config["segment_size"], agent.config["discount"], agent.config["actor_lr"]
    (128, 0.98, 0.003)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

from ivy.nest import map_nest, multi_map_nest
from ivy.typing import Array
from ivy_rl.agents.agent import Agent
from ivy_rl.agents.fusion import FUSION, check_fusion, fusion_level
from ivy_rl.models import ActorCriticModel
from ivy_rl.normalizers import MeanStd, ReturnNormalizer, _fold_moments, _standard_deviation
from ivy_rl.replays import Segment
from ivy_rl.returns import _lambda_returns
from ivy_rl.updaters import StochasticPolicyGradient, ValueRegression

__all__ = ["A2C", "Acting"]


class Acting(NamedTuple):
    """What an on-policy agent's acting function returns for a batch of observations.

    Attributes:
        actions: the samples as the policy's distribution stores them (``[batch, ...]``; for
            a squashed Gaussian, before the squashing).
        env_actions: the actions to take, in ``[-1, 1]`` (Box, rescaled to the space's bounds
            by the agent) or indices (Discrete).
        log_probs: ``[batch]`` log-probabilities of the samples.
        distribution: the acting policy's parameters (``{'loc', 'scale'}``, ``{'logits'}``),
            when the actor updater needs them (TRPO's old policy); else None.
    """

    actions: Array
    env_actions: Array
    log_probs: Array
    distribution: dict[str, Array] | None


_TRANSITION_KEYS = ("observations", "next_observations", "rewards", "resets", "terminations")


class A2C(Agent):
    """Advantage actor-critic (Mnih et al., 2016) in Tonic's form: one actor step on the whole
    segment, then ``critic_iterations`` passes of value regression on the λ-returns.

    Args:
        model: the model part (default: an :class:`~ivy_rl.models.ActorCriticModel` built from
            the flat settings).
        replay: the replay part (default: a :class:`~ivy_rl.replays.Segment`).
        actor_updater: default :class:`~ivy_rl.updaters.StochasticPolicyGradient`.
        critic_updater: default :class:`~ivy_rl.updaters.ValueRegression`.
        settings: the flat settings of the parts not given (routed by :attr:`parts`), and the
            agent's own ``fusion`` (:mod:`ivy_rl.agents.fusion`; the same numbers either way).

    Settings: the flat settings (``A2C(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``A2C.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults A2C CartPole-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> A2C(segment_size=64, actor_lr=1e-3).config["segment_size"]
        64
    """

    learns = True
    own_settings = {"fusion": FUSION}
    #: A2C's defaults where they differ from its parts' (see :meth:`Agent.settings`)
    _defaults: dict[str, Any] = dict(segment_size=256, critic_iterations=40, fusion="auto")
    scheduled = ("actor_lr", "critic_lr")
    _MODEL = (
        "hidden_sizes",
        "critic_hidden_sizes",
        "activation",
        "head",
        "log_std_init",
        "normalize_observations",
        "normalize_returns",
    )
    #: the Segment replay's flat settings and its parameters (PPO extends them)
    REPLAY_SETTINGS = {
        "segment_size": "size",
        "batch_size": "batch_size",
        "discount": "discount",
        "trace_decay": "trace_decay",
        "normalize_advantages": "normalize_advantages",
    }
    #: each part: its role, its default class and ``{flat setting: the class's parameter}``
    parts: dict[str, tuple[type, dict[str, str]]] = {
        "model": (ActorCriticModel, {k: k for k in _MODEL}),
        "replay": (Segment, {**REPLAY_SETTINGS, "critic_iterations": "batch_iterations"}),
        "actor_updater": (
            StochasticPolicyGradient,
            {
                "actor_lr": "lr",
                "entropy_coeff": "entropy_coeff",
                "actor_gradient_clip": "gradient_clip",
            },
        ),
        "critic_updater": (
            ValueRegression,
            {"critic_lr": "lr", "critic_gradient_clip": "gradient_clip"},
        ),
    }

    def __init__(
        self,
        *,
        model: Any = None,
        replay: Any = None,
        actor_updater: Any = None,
        critic_updater: Any = None,
        **settings: Any,
    ) -> None:
        given = {
            "model": model,
            "replay": replay,
            "actor_updater": actor_updater,
            "critic_updater": critic_updater,
        }
        config, built = self._composed(
            {**settings, **{role: part for role, part in given.items() if part is not None}}
        )
        self.model, self.replay = built["model"], built["replay"]
        self.actor_updater, self.critic_updater = built["actor_updater"], built["critic_updater"]
        check_fusion(type(self).__name__, config["fusion"])
        super().__init__(**config)

    # ------------------------------------------------------------------------------------------
    # Building
    # ------------------------------------------------------------------------------------------

    def _build(self) -> None:
        xp = self.xp
        self.model.initialize(
            self.observation_space,
            self.action_space,
            rng=self.rng,
            dtype=self.dtype,
            device=self.device,
            f=xp,
        )
        self.v = self._placed(self.model.v)
        self.optimizer_states = {}
        for role, updater in (("actor", self.actor_updater), ("critic", self.critic_updater)):
            updater.initialize(xp)
            if updater.has_optimizer:
                self.optimizer_states[role] = updater.init_state(self.v[role])
        obs_size = int(np.prod(self.observation_space.shape))
        model = self.model
        self.observation_normalizer = MeanStd((obs_size,)) if model.normalize_observations else None
        self.return_normalizer = ReturnNormalizer() if model.normalize_returns else None
        self._noise_shape = (
            (int(self.action_space.n),)
            if self.action_kind == "Discrete"
            else self.action_space.shape
        )
        self._pending: dict[str, Any] | None = None
        self.updates = 0
        self._refresh_stats()
        self._act = self._compile(self._act_fn, "act")
        self._mode = self._compile(self._mode_fn, "mode")
        self.fusion = fusion_level(self.config["fusion"], compiled=self.compiled, f=xp)
        self._fused = self.fusion == "update"
        self._compiled_steps: dict[str, Callable] = {}
        fn = self._update_fn
        self._update = self._compile(fn, "update") if self._fused else fn

    def _refresh_stats(self) -> None:
        """The observation statistics as arrays of the framework, for the models' calls."""
        norm = self.observation_normalizer
        self.stats = {
            "obs": None
            if norm is None
            else {k: self._asarray(a) for k, a in norm.stats(self.dtype).items()}
        }

    def _return_moments(self) -> dict[str, Any] | None:
        norm = self.return_normalizer
        if norm is None:
            return None
        return {k: self._asarray(a) for k, a in norm.moments(self.dtype).items()}

    # ------------------------------------------------------------------------------------------
    # Pure functions (compiled)
    # ------------------------------------------------------------------------------------------

    def _act_fn(self, actor_v, obs_stats, observations, noise) -> Acting:
        dist = self.model.actor(observations, obs_stats, v=actor_v)
        raw = dist.sample_raw(noise)
        keep = self.actor_updater.needs_distribution
        return Acting(
            actions=raw,
            env_actions=dist.raw_to_action(raw),
            log_probs=dist.log_prob_raw(raw),
            distribution=dist.params() if keep else None,
        )

    def _mode_fn(self, actor_v, obs_stats, observations):
        return self.model.actor(observations, obs_stats, v=actor_v).mode()

    def _update_fn(self, v, states, obs_stats, return_moments, segment, orders, scheduled):
        """The whole update: ``(v, states, return_moments, logs)`` after learning from the
        segment (arrays ``[time, workers, ...]``) with the mini-batches ``orders``; the
        scheduled settings' values ``scheduled`` (scalar arrays) ride along in ``stats``."""
        batch, return_moments, return_stats = self._prepare(
            v["critic"], obs_stats, return_moments, segment
        )
        stats = {"obs": obs_stats, "ret": return_stats, "scheduled": scheduled}
        v, states, logs = self._optimize(v, states, stats, batch, orders)
        return v, states, return_moments, logs

    def _prepare(self, critic_v, obs_stats, return_moments, segment):
        """Values, λ-returns and advantages of a segment, flattened to ``[time * workers]``
        (index ``t * workers + w``), and the return statistics updated with the new returns.

        Returns:
            ``(batch, return_moments, return_stats)``; the batch holds constants: on tensorflow
            ``execute_with_gradients`` differentiates every tensor computed from the watched
            variables (by identity, even one captured in a closure), so values computed from the
            critic's variables pass through ``stop_gradient`` to stay targets, as they are on
            torch and jax.
        """
        xp, replay = self.xp, self.replay
        rewards = segment["rewards"]
        steps, workers = tuple(rewards.shape)
        size = steps * workers
        observations = xp.reshape(segment["observations"], (size, -1))
        following = xp.reshape(segment["next_observations"], (size, -1))
        return_stats = self._moment_stats(return_moments)
        values = self._run_once(
            "critic_values",
            self._critic_values,
            critic_v,
            obs_stats,
            return_stats,
            xp.concat([observations, following], axis=0),
        )
        current = xp.reshape(values[:size], (steps, workers))
        next_values = xp.reshape(values[size:], (steps, workers))
        returns = _lambda_returns(
            xp,
            rewards,
            next_values,
            segment["resets"],
            segment["terminations"],
            replay.discount,
            replay.trace_decay,
        )
        advantages = xp.reshape(returns - current, (size,))
        returns = xp.reshape(returns, (size,))
        if replay.normalize_advantages:
            centred = advantages - xp.mean(advantages)
            advantages = xp.safe_divide(centred, xp.std(advantages))
        if return_moments is not None:
            count, mean, mean_sq = _fold_moments(
                return_moments["count"],
                return_moments["mean"],
                return_moments["mean_sq"],
                float(size),
                xp.sum(returns),
                xp.sum(xp.square(returns)),
            )
            return_moments = {"count": count, "mean": mean, "mean_sq": mean_sq}
            return_stats = self._moment_stats(return_moments)
        batch = {"observations": observations, "returns": returns, "advantages": advantages}
        for key, value in segment.items():
            if key not in _TRANSITION_KEYS:
                batch[key] = map_nest(lambda a: xp.reshape(a, (size, *tuple(a.shape)[2:])), value)
        return batch, return_moments, return_stats

    def _critic_values(self, critic_v, obs_stats, return_stats, observations):
        values = self.model.critic(observations, obs_stats, return_stats, v=critic_v)
        return self.xp.stop_gradient(values)

    def _moment_stats(self, moments):
        if moments is None:
            return None
        eps = self.return_normalizer.epsilon
        std = _standard_deviation(self.xp, moments["mean"], moments["mean_sq"], eps)
        return {"mean": moments["mean"], "std": std}

    def _optimize(self, v, states, stats, batch, orders):
        """A2C: one actor step on the whole segment, then the critic's mini-batches."""
        (actor_v, actor_state), actor_logs = self._run_once(
            "actor_step", self._actor_step, (v["actor"], states["actor"]), stats, batch
        )
        (critic_v, critic_state), critic_logs = self._run_critic(v, states, stats, batch, orders)
        logs = {f"actor/{k}": x for k, x in actor_logs.items()}
        logs.update(critic_logs)
        new_v = {"actor": actor_v, "critic": critic_v}
        return new_v, {"actor": actor_state, "critic": critic_state}, logs

    def _run_critic(self, v, states, stats, batch, orders):
        carry, ys = self._run_loop(
            "critic_step",
            self._critic_step,
            (v["critic"], states["critic"]),
            orders,
            stats,
            batch,
        )
        return carry, {"critic/loss": self.xp.mean(ys["loss"])}

    def _actor_step(self, carry, stats, batch):
        actor_v, state = carry
        actor_v, state, infos = self.actor_updater.minimize(
            lambda w: self._actor_loss(w, stats, batch),
            actor_v,
            state,
            stats["scheduled"].get("actor_lr"),
        )
        return (actor_v, state), infos

    def _critic_step(self, carry, indices, stats, batch):
        critic_v, state = carry
        part = self._select(batch, indices, ("observations", "returns"))
        critic_v, state, infos = self.critic_updater.minimize(
            lambda w: self._critic_loss(w, stats, part),
            critic_v,
            state,
            stats["scheduled"].get("critic_lr"),
        )
        return (critic_v, state), {"loss": infos["loss"]}

    def _masked(self, keep, new, old):
        """``new`` where the scalar ``keep`` is true, else ``old``, leaf by leaf."""
        return multi_map_nest(lambda a, b: self.xp.where(keep, a, b), new, old)

    def _critic_loss(self, critic_v, stats, batch):
        targets = batch["returns"]
        if stats["ret"] is not None:
            targets = (targets - stats["ret"]["mean"]) / stats["ret"]["std"]
        predictions = self.model.critic.normalized(critic_v, batch["observations"], stats["obs"])
        return self.critic_updater.loss(predictions, targets)

    def _actor_loss(self, actor_v, stats, batch):
        dist = self.model.actor(batch["observations"], stats["obs"], v=actor_v)
        return self.actor_updater.loss(dist, batch)

    def _select(self, batch, indices, keys):
        return {k: map_nest(lambda a: self.xp.take(a, indices, axis=0), batch[k]) for k in keys}

    # ------------------------------------------------------------------------------------------
    # The fusion levels: inside the one compiled update, or step by step from the host
    # ------------------------------------------------------------------------------------------

    def _step_function(self, name: str, fn: Callable) -> Callable:
        if name not in self._compiled_steps:
            self._compiled_steps[name] = self._compile(fn)
        return self._compiled_steps[name]

    def _run_once(self, name, fn, carry, *consts):
        """``fn(carry, *consts)``: inline in the fused update, else its own compiled function."""
        if self._fused:
            return fn(carry, *consts)
        return self._step_function(name, fn)(carry, *consts)

    def _run_loop(self, name, body, carry, xs, *consts):
        """``ivy.scan`` of ``body(carry, x, *consts)`` over the rows of ``xs``: inside the fused
        update (or eagerly), else through ``ivy.compiled_scan`` (``fusion='steps'``), which puts
        the compile boundary where the framework's compiler wants it: around the whole scan
        where it keeps loops, around ``body`` with a host loop where it unrolls them."""
        xp = self.xp
        steps = int(xs.shape[0])
        if self._fused or steps == 0 or not self.compiled:
            return xp.scan(lambda c, x: body(c, x, *consts), carry, xs)
        run = self._compiled_steps.get(name)
        if run is None:

            def scan_body(state, x):
                inner, fixed = state
                inner, y = body(inner, x, *fixed)
                return (inner, fixed), y

            run = self._counted(xp.compiled_scan(scan_body), name)
            self._compiled_steps[name] = run
        (carry, _), ys = run((carry, consts), xs)
        return carry, ys

    # ------------------------------------------------------------------------------------------
    # Acting
    # ------------------------------------------------------------------------------------------

    def _noise(self, count: int) -> np.ndarray:
        shape = (count,) + tuple(self._noise_shape)
        if self.action_kind == "Discrete":
            return self.rng.gumbel(size=shape).astype(self.np_dtype)
        return self.rng.standard_normal(shape).astype(self.np_dtype)

    def step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        xp = self.xp
        obs = self._observations(observations)
        noise = self._noise(obs.shape[0])
        acting = self._act(
            self.v["actor"], self.stats["obs"], self._asarray(obs), self._asarray(noise)
        )
        acting = Acting(*map_nest(lambda a: np.asarray(xp.to_numpy(a)), tuple(acting)))
        self._pending = {
            "observations": obs,
            "actions": acting.actions,
            "log_probs": acting.log_probs,
        }
        if acting.distribution is not None:
            self._pending["distribution"] = acting.distribution
        return self._env_actions(acting.env_actions)

    def test_step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        xp = self.xp
        obs = self._observations(observations)
        mode = self._mode(self.v["actor"], self.stats["obs"], self._asarray(obs))
        return self._env_actions(np.asarray(xp.to_numpy(mode)))

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def update(self, observations, rewards, resets, terminations) -> dict[str, float]:
        self._check_initialized()
        if self._pending is None:
            raise RuntimeError(f"{type(self).__name__}.update called before step")
        next_obs = self._observations(observations)
        self.replay.store(
            **self._pending,
            next_observations=next_obs,
            rewards=np.asarray(rewards, np.float64),
            resets=np.asarray(resets, bool),
            terminations=np.asarray(terminations, bool),
        )
        if self.observation_normalizer is not None:
            self.observation_normalizer.record(self._pending["observations"])
        self._pending = None
        if not self.replay.ready():
            return {}
        logs = self._learn()
        self.replay.clear()
        self.updates += 1
        return logs

    def _segment(self) -> dict[str, Any]:
        """The segment's buffers as arrays of the framework on the agent's device (one copy
        per update): floats in the model's dtype, integers as int32 (jax without 64-bit types
        has no int64)."""

        def placed(value):
            if value.dtype.kind == "f":
                value = value.astype(self.np_dtype)
            elif value.dtype.kind in "iu":
                value = value.astype(np.int32)
            return self._asarray(value)

        return map_nest(placed, self.replay.buffers)

    def _learn(self) -> dict[str, float]:
        xp = self.xp
        orders = self.replay.batch_orders(self.rng)
        v, states, moments, logs = self._update(
            self.v,
            self.optimizer_states,
            self.stats["obs"],
            self._return_moments(),
            self._segment(),
            self._asarray(orders),
            self._scheduled_arrays(),
        )
        self.v, self.optimizer_states = v, states
        if moments is not None:
            self.return_normalizer.set_moments(
                **{k: np.asarray(xp.to_numpy(a)) for k, a in moments.items()}
            )
        out = {k: float(np.asarray(xp.to_numpy(x))) for k, x in logs.items()}
        out.update(self._iteration_counts(len(orders)))
        if self.observation_normalizer is not None:
            self.observation_normalizer.update()
        self._refresh_stats()
        return out

    def _iteration_counts(self, batches: int) -> dict[str, float]:
        """Optimisation steps of an update known on the host (logged with the losses)."""
        return {"actor/iterations": 1.0, "critic/iterations": float(batches)}

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def _arrays(self) -> dict[str, Any]:
        arrays: dict[str, Any] = {"v": self.v, "optimizer": self.optimizer_states}
        if self.observation_normalizer is not None:
            arrays["observation_normalizer"] = self.observation_normalizer.state_dict()
        if self.return_normalizer is not None:
            arrays["return_normalizer"] = self.return_normalizer.state_dict()
        arrays["replay"] = self.replay.state_dict()
        if self._pending is not None:
            arrays["pending"] = dict(self._pending)
        return arrays

    def _load_arrays(self, arrays: dict[str, Any]) -> None:
        self.v = self._to_backend(arrays["v"], self.v)
        self.optimizer_states = self._to_backend(arrays["optimizer"], self.optimizer_states)
        for name in ("observation_normalizer", "return_normalizer"):
            norm = getattr(self, name)
            if norm is not None:
                norm.load_state_dict(arrays[name])
        self.replay.load_state_dict(arrays["replay"])
        self._pending = dict(arrays["pending"]) if "pending" in arrays else None
        self._refresh_stats()

    def _meta(self) -> dict[str, Any]:
        return {"updates": self.updates}

    def _load_meta(self, meta: dict[str, Any]) -> None:
        self.updates = int(meta.get("updates", 0))
