"""SAC: soft actor-critic (Haarnoja et al., 2018) with automatic entropy tuning.

A ``tanh``-squashed Gaussian actor, twin critics regressing on the soft n-step targets
``R + γ^k (min_i Q'_i(s', a') - α log π(a'|s'))`` with ``a' ~ π(s')``, the actor minimising
``α log π(a|s) - min_i Q_i(s, a)``, and the temperature ``α = exp(log_alpha)`` adjusted so that
the policy's entropy tracks ``target_entropy`` (default: minus the number of action
dimensions). The sampling noise is drawn by the agent's numpy generator and passed in, so the
compiled update draws nothing.

Example:
    >>> agent = SAC(hidden_sizes=(256, 256)).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ivy_rl.agents.ddpg import DDPG, ExploresItself
from ivy_rl.models import SquashedGaussianHead

__all__ = ["SAC"]


class SAC(ExploresItself, DDPG):
    """Soft actor-critic with twin critics and a learned temperature.

    Args:
        initial_temperature: α at the start.
        temperature_lr: Adam learning rate of ``log_alpha`` (0: α stays fixed).
        target_entropy: the entropy α steers towards (None: ``-action dimensions``).
        Others: as for :class:`~ivy_rl.agents.off_policy.OffPolicyAgent` (SAC explores by
        sampling its policy: it has no exploration noise).

    Example:
        >>> SAC(initial_temperature=0.1, temperature_lr=3e-4)
    """

    _unused = ("exploration", "exploration_scale")
    scheduled = ("actor_lr", "critic_lr", "temperature_lr")
    _defaults: dict[str, Any] = dict(
        initial_temperature=1.0, temperature_lr=1e-3, target_entropy=None
    )
    _critics = 2

    def _policy_head(self, in_size, action_size, init):
        return SquashedGaussianHead(in_size, action_size, weight_init=init, **self._build_args())

    def _build_parts(self):
        c = self.config
        model = self._actor_critic()
        self.model = model
        self.action_size = int(np.prod(self.action_space.shape))
        log_alpha = self.xp.asarray(
            math.log(c["initial_temperature"]), dtype=self.dtype, device=self.device
        )
        v = {**model.v, "temperature": {"log_alpha": log_alpha}}
        self.optimizers = {
            "actor": self._adam(c["actor_lr"]),
            "critic": self._adam(c["critic_lr"]),
            "temperature": self._adam(c["temperature_lr"]),
        }
        entropy = c["target_entropy"]
        self.target_entropy = -float(self.action_size) if entropy is None else float(entropy)
        return v, {"critic": model.target_v["critic"]}

    def _check_config(self, config):
        if config["initial_temperature"] <= 0:
            raise ValueError(
                f"SAC: initial_temperature must be > 0, got {config['initial_temperature']}"
            )

    def _build_exploration(self):
        pass  # the policy samples

    # ------------------------------------------------------------------------------------------
    # Acting
    # ------------------------------------------------------------------------------------------

    def _act_noise(self, count):
        return self.rng.standard_normal((count, self.action_size)).astype(self.np_dtype)

    def _act_fn(self, v, obs_stats, observations, noise):
        return self.model.actor(observations, obs_stats, v=v["actor"]).sample(noise)

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def _draw(self, iterations):
        c = self.config
        shape = (iterations, c["batch_size"], self.action_size)
        return {
            "indices": self.replay.windows(self.rng, iterations, c["batch_size"]),
            "next_noise": self.rng.standard_normal(shape).astype(self.np_dtype),
            "noise": self.rng.standard_normal(shape).astype(self.np_dtype),
        }

    def _alpha(self, v):
        return self.xp.stop_gradient(self.xp.exp(v["temperature"]["log_alpha"]))

    def _target_values(self, v, targets, batch, obs_stats, x):
        xp = self.xp
        following = batch["next_observations"]
        dist = self.model.actor(following, obs_stats, v=v["actor"])
        raw = dist.sample_raw(x["next_noise"])
        log_probs = dist.log_prob_raw(raw)
        values = self._q(targets["critic"], following, dist.squash(raw), obs_stats)
        return xp.min(values, axis=0) - self._alpha(v) * log_probs

    def _actor_loss(self, actor_v, critic_v, batch, obs_stats, x):
        xp = self.xp
        observations = batch["observations"]
        dist = self.model.actor(observations, obs_stats, v=actor_v)
        raw = dist.sample_raw(x["noise"])
        log_probs = dist.log_prob_raw(raw)
        values = xp.min(self._q(critic_v, observations, dist.squash(raw), obs_stats), axis=0)
        loss = xp.mean(x["alpha"] * log_probs - values)
        return loss, {"entropy": xp.stop_gradient(-xp.mean(log_probs))}

    def _learn_step(self, carry, x, arrays, obs_stats):
        xp = self.xp
        v, targets, states = carry["v"], carry["targets"], carry["states"]
        v, states, critic_loss, batch = self._critic_step(
            v, targets, states, x["indices"], arrays, obs_stats, x
        )
        x = {**x, "alpha": self._alpha(v)}
        v, states, actor_infos = self._actor_step(v, states, batch, obs_stats, x)
        gap = xp.stop_gradient(self.target_entropy - actor_infos["entropy"])

        def temperature_loss(w):
            return -w["log_alpha"] * gap

        temperature_v, temperature_state, temperature_infos = self._minimize(
            "temperature", temperature_loss, v["temperature"], states["temperature"]
        )
        v = {**v, "temperature": temperature_v}
        states = {**states, "temperature": temperature_state}
        targets = self._soft_update(targets, v, ("critic",))
        logs = {
            "critic/loss": critic_loss,
            "actor/loss": actor_infos["loss"],
            "actor/entropy": actor_infos["entropy"],
            "actor/temperature": xp.exp(temperature_v["log_alpha"]),
        }
        return {"v": v, "targets": targets, "states": states}, logs
