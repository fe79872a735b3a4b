"""SHAC: short-horizon actor-critic (Xu et al., 2022), learning through ivy_gym's gradients.

A batch of ``batch_size`` simulated environments is carried from update to update. Each update
runs the deterministic policy for ``horizon`` (K) steps from their current states through the
ivy_gym core, and

1. the actor takes one Adam step on the negative mean of ``sum_t γ^t r_t + γ^K V(s_K)``
   (divided by K), differentiated through the K steps of dynamics and through the critic's
   value of the last state (the critic's weights are constants here);
2. the critic regresses on TD(λ) targets of the same rollout (values of the target critic,
   bootstrapped at the end of the window, not after terminations), in ``critic_iterations``
   passes of ``critic_batches`` mini-batches;
3. the target critic moves towards the critic by ``target_update``.

Environments whose episode reached its time limit (or terminated) restart from fresh initial
states, drawn by the agent's numpy generator. The rollouts are truncated to K steps, so the
gradient never runs through a long, chaotic horizon; the critic stands for what follows.

Example:
    >>> import gymnasium as gym, ivy_gym                 # ivy_gym registers its ids
    >>> env = gym.make("ivy_gym/Pendulum-v1")
    >>> agent = SHAC(horizon=32, batch_size=64)
    >>> agent.bind_environment("ivy_gym/Pendulum-v1", {})
    >>> agent = agent.initialize(env.observation_space, env.action_space, seed=0, f="jax")
    >>> sorted(agent.v)                                 # the critic's target network too
    ['actor', 'critic', 'target']
"""

from __future__ import annotations

from functools import partial
from typing import Any

import numpy as np

from ivy_rl.agents.through_gym import DifferentiableAgent
from ivy_rl.differentiable_parts import ActorValueModel, TargetValueRegression
from ivy_rl.normalizers import _fold_moments
from ivy_rl.returns import _lambda_returns

__all__ = ["SHAC"]


class SHAC(DifferentiableAgent):
    """Short-horizon actor-critic through an ivy_gym environment.

    Args:
        settings: as for :class:`~ivy_rl.agents.APG`, with those of its critic (an
            :class:`~ivy_rl.models.ActorValueModel` with a critic and its target, regressed on
            TD(λ) targets, optionally normalised by their running mean and standard deviation).

    Settings: the flat settings (``SHAC(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``SHAC.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults SHAC ivy_gym/Pendulum-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> SHAC(horizon=32, critic_iterations=16).config["critic_iterations"]
        16
    """

    scheduled: tuple[str, ...] = ("actor_lr", "critic_lr")
    _defaults: dict[str, Any] = dict(actor_lr=2e-3)

    parts = {
        **DifferentiableAgent.parts,
        "model": (
            partial(ActorValueModel, critic=True),
            {
                "hidden_sizes": "hidden_sizes",
                "activation": "activation",
                "critic_hidden_sizes": "critic_hidden_sizes",
                "normalize_returns": "normalize_returns",
                "normalize_observations": "normalize_observations",
            },
        ),
        "critic_updater": (
            TargetValueRegression,
            {
                "critic_lr": "lr",
                "critic_gradient_clip": "gradient_clip",
                "trace_decay": "trace_decay",
                "critic_iterations": "iterations",
                "critic_batches": "batches",
                "target_update": "target_update",
                "adam_beta1": "beta1",
                "adam_beta2": "beta2",
            },
        ),
    }

    def _build_learner(self) -> None:
        c = self.config
        self.critic_updater.initialize(self.xp)
        self.critic_optimizer = self.critic_updater.optimizer
        v = self.model.v
        self.v = {k: self._placed(v[k]) for k in ("actor", "critic", "target")}
        self.optimizer_states = {
            "actor": self.actor_optimizer.init(self.v["actor"]),
            "critic": self.critic_optimizer.init(self.v["critic"]),
        }
        size = c["batch_size"] * c["horizon"]
        if c["critic_batches"] < 1 or size % c["critic_batches"]:
            raise ValueError(
                f"SHAC: critic_batches must divide batch_size * horizon = {size}, got "
                f"{c['critic_batches']!r}"
            )
        self.moments = self._moments()
        # the simulated environments (an agent that only acts, as in play, has no environment
        # bound: then they are drawn at the first update)
        bound = self.core is not None
        self._states = self._initial_states(c["batch_size"]) if bound else None
        self._times = np.zeros(c["batch_size"], np.int64)

    # ------------------------------------------------------------------------------------------
    # Pure functions
    # ------------------------------------------------------------------------------------------

    def _update_fn(self, v, states, moments, obs_moments, start, orders, scheduled):
        """The whole update from the states ``start`` with the critic's mini-batches
        ``orders``, at the scheduled learning rates: ``(v, states, moments, obs_moments,
        final_states, restart, logs)``. The rollout, the critic's values and its regression
        see the observations normalised by the moments before this update's rollout."""
        stats = self._return_stats(moments)
        obs_stats = self._stats(obs_moments)
        actor_v, actor_state, data, logs = self._actor_step(
            v["actor"], states["actor"], v["critic"], stats, obs_stats, start, scheduled["actor_lr"]
        )
        batch, moments = self._critic_batch(v["target"], stats, obs_stats, moments, start, data)
        obs_moments = self._fold_observations(obs_moments, data["observations"])
        (critic_v, critic_state), ys = self._run_loop(
            "critic_step",
            self._critic_step,
            (v["critic"], states["critic"]),
            orders,
            batch,
            scheduled["critic_lr"],
        )
        logs["critic/loss"] = self.xp.mean(ys["loss"])
        target_v = self.critic_updater.update_target(v["target"], critic_v)
        new_v = {"actor": actor_v, "critic": critic_v, "target": target_v}
        new_states = {"actor": actor_state, "critic": critic_state}
        return new_v, new_states, moments, obs_moments, data["final_state"], data["ended"], logs

    def _return_stats(self, moments):
        """``{'mean', 'std'}`` of the critic's targets (None without ``normalize_returns``)."""
        return self._stats(moments) if self.config["normalize_returns"] else None

    def _actor_step(self, actor_v, actor_state, critic_v, stats, obs_stats, start, lr):
        xp = self.xp
        horizon = self.config["horizon"]
        gamma = self.config["discount"]

        def loss_fn(w):
            traj = self._rollout(w, start, horizon, obs_stats=obs_stats)
            rewards = traj.rewards
            discounted = xp.sum(rewards * self._discounts(horizon, rewards.dtype), axis=0)
            last = traj.observations[horizon - 1]
            alive = xp.logical_and(traj.valid[horizon - 1], xp.logical_not(traj.terminated[-1]))
            values = self.critic(last, obs_stats, stats, v=critic_v)
            bootstrap = xp.where(alive, values, xp.zeros_like(values))
            loss = -xp.mean(discounted + gamma**horizon * bootstrap) / horizon
            ended = xp.logical_not(alive)
            data = {
                "observations": xp.stop_gradient(traj.observations),
                "rewards": xp.stop_gradient(rewards),
                "terminated": xp.logical_and(traj.terminated, traj.valid),
                "valid": traj.valid,
                "final_state": xp.stop_gradient(traj.final_state),
                "ended": ended,
                "rollout_reward": xp.stop_gradient(xp.mean(rewards)),
            }
            return loss, data

        actor_v, actor_state, infos = self._actor_minimize(loss_fn, actor_v, actor_state, lr)
        logs = {
            "actor/loss": infos.pop("loss"),
            "actor/gradient_norm": infos.pop("gradient_norm"),
            "actor/rollout_reward": infos.pop("rollout_reward"),
            "actor/skipped": infos.pop("skipped"),
        }
        return actor_v, actor_state, infos, logs

    def _critic_batch(self, target_v, stats, obs_stats, moments, start, data):
        """The critic's regression data, flattened to ``[horizon * batch]``: the observation
        before each step (normalised by ``obs_stats``), its TD(λ) target (normalised with the
        moments updated by this rollout's targets) and its weight (0 after a termination); and
        the new moments."""
        xp, c = self.xp, self.config
        observations = data["observations"]
        steps, batch = tuple(data["rewards"].shape)
        first = xp.expand_dims(self.core.observe(start, f=xp), axis=0)
        before = xp.concat([first, observations[: steps - 1]], axis=0)
        next_values = xp.stop_gradient(self.critic(observations, obs_stats, stats, v=target_v))
        no_resets = xp.zeros_like(data["rewards"])
        terminations = xp.astype(data["terminated"], data["rewards"].dtype)
        targets = _lambda_returns(
            xp,
            data["rewards"],
            next_values,
            no_resets,
            terminations,
            c["discount"],
            c["trace_decay"],
        )
        size = steps * batch
        targets = xp.stop_gradient(xp.reshape(targets, (size,)))
        if c["normalize_returns"]:
            count, mean, mean_sq = _fold_moments(
                moments["count"],
                moments["mean"],
                moments["mean_sq"],
                float(size),
                xp.sum(targets),
                xp.sum(targets * targets),
            )
            moments = {"count": count, "mean": mean, "mean_sq": mean_sq}
            new_stats = self._return_stats(moments)
            targets = (targets - new_stats["mean"]) / new_stats["std"]
        batch = {
            "observations": self.critic.encoder(xp.reshape(before, (size, -1)), obs_stats),
            "targets": targets,
            "weights": xp.reshape(xp.astype(data["valid"], targets.dtype), (size,)),
        }
        return batch, moments

    def _critic_step(self, carry, indices, batch, lr):
        return self.critic_updater.step(self.critic, carry, indices, batch, lr)

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def _orders(self) -> np.ndarray:
        """``[critic_iterations * critic_batches, size]`` indices of the critic's mini-batches."""
        c = self.config
        return self.critic_updater.orders(self.rng, c["batch_size"] * c["horizon"])

    def _learn(self) -> dict[str, float]:
        c, xp = self.config, self.xp
        if self._states is None:
            self._states = self._initial_states(c["batch_size"])
        v, states, self.moments, self.obs_moments, final, ended, logs = self._update(
            self.v,
            self.optimizer_states,
            self.moments,
            self.obs_moments,
            self._asarray(self._states),
            self._asarray(self._orders()),
            self._scheduled_arrays(),
        )
        self.v, self.optimizer_states = v, states
        self.simulated_steps += c["batch_size"] * c["horizon"]
        self._times += c["horizon"]
        restart = (self._times >= self.episode_steps) | np.asarray(xp.to_numpy(ended), bool)
        self._states = np.asarray(xp.to_numpy(final), self.np_dtype)
        if restart.any():
            self._states[restart] = self._initial_states(int(restart.sum()))
            self._times[restart] = 0
        out = self._logs(logs)
        out["critic/iterations"] = float(c["critic_iterations"] * c["critic_batches"])
        return out

    # ------------------------------------------------------------------------------------------
    # Checkpoints: the simulated environments too
    # ------------------------------------------------------------------------------------------

    def _arrays(self) -> dict[str, Any]:
        arrays = super()._arrays()
        if self._states is not None:
            arrays["simulation"] = {"states": self._states, "times": self._times}
        arrays["moments"] = self.moments
        return arrays

    def _load_arrays(self, arrays: dict[str, Any]) -> None:
        super()._load_arrays(arrays)
        if "simulation" in arrays:
            self._states = np.asarray(arrays["simulation"]["states"], self.np_dtype)
            self._times = np.asarray(arrays["simulation"]["times"], np.int64)
        self.moments = self._to_backend(arrays["moments"], self.moments)
