"""MPO: maximum a posteriori policy optimisation (Abdolmaleki et al., 2018).

A Gaussian actor and a critic ``Q(s, a)`` with targets. The critic regresses on expected-SARSA
n-step targets ``R + γ^k mean_j Q'(s', a'_j)`` with ``a'_j`` sampled from the target policy.
The actor: for each state, ``num_samples`` actions of the target policy are weighted by
``softmax(Q'(s, a_j) / η)`` (the E-step, with the temperature η found by its dual under a KL
bound ``epsilon``); the policy then fits those weighted actions by maximum likelihood (the
M-step) with its mean and its scale fitted separately, each under a per-dimension KL bound to
the target policy (``epsilon_mean``, ``epsilon_std``) enforced by Lagrange multipliers learned
alongside. Every sample's noise is drawn by the agent's numpy generator and passed in.

Example:
    >>> agent = MPO(num_samples=20, epsilon=0.1).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="tensorflow")
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ivy_rl.agents.ddpg import DDPG, ExploresItself
from ivy_rl.models import GaussianHead

__all__ = ["MPO"]


class MPO(ExploresItself, DDPG):
    """Maximum a posteriori policy optimisation with decoupled KL constraints.

    Args:
        num_samples: actions sampled per state (E-step and critic targets).
        epsilon: KL bound of the E-step (the temperature's dual).
        epsilon_mean, epsilon_std: per-dimension KL bounds of the policy's mean and scale.
        initial_log_temperature, initial_log_alpha_mean, initial_log_alpha_std: initial dual
            variables (before a softplus).
        min_log_dual: lower bound of the dual variables.
        dual_lr: Adam learning rate of the dual variables.
        Others: as for :class:`~ivy_rl.agents.off_policy.OffPolicyAgent` (MPO explores by
        sampling its policy).

    Example:
        >>> MPO(hidden_sizes=(256, 256), num_samples=20)
    """

    _unused = ("exploration", "exploration_scale")
    scheduled = ("actor_lr", "critic_lr", "dual_lr")
    _defaults: dict[str, Any] = dict(
        num_samples=20,
        epsilon=0.1,
        epsilon_mean=1e-3,
        epsilon_std=1e-6,
        initial_log_temperature=1.0,
        initial_log_alpha_mean=1.0,
        initial_log_alpha_std=10.0,
        min_log_dual=-18.0,
        dual_lr=1e-2,
        actor_lr=3e-4,
        critic_lr=3e-4,
    )

    def _policy_head(self, in_size, action_size, init):
        return GaussianHead(
            in_size,
            action_size,
            loc_activation="tanh",
            state_dependent_scale=True,
            scale_min=1e-4,
            scale_max=1.0,
            weight_init=init,
            **self._build_args(),
        )

    def _build_parts(self):
        c = self.config
        model = self._actor_critic()
        self.model = model
        self.action_size = int(np.prod(self.action_space.shape))
        xp, build = self.xp, {"dtype": self.dtype, "device": self.device}
        dual = {
            "log_temperature": xp.asarray(c["initial_log_temperature"], **build),
            "log_alpha_mean": xp.full((self.action_size,), c["initial_log_alpha_mean"], **build),
            "log_alpha_std": xp.full((self.action_size,), c["initial_log_alpha_std"], **build),
        }
        self.optimizers = {
            "actor": self._adam(c["actor_lr"]),
            "critic": self._adam(c["critic_lr"]),
            "dual": self._adam(c["dual_lr"]),
        }
        return {**model.v, "dual": dual}, dict(model.target_v)

    def _build_exploration(self):
        pass  # the policy samples

    # ------------------------------------------------------------------------------------------
    # Acting
    # ------------------------------------------------------------------------------------------

    def _act_noise(self, count):
        return self.rng.standard_normal((count, self.action_size)).astype(self.np_dtype)

    def _act_fn(self, v, obs_stats, observations, noise):
        dist = self.model.actor(observations, obs_stats, v=v["actor"])
        return self.xp.clip(dist.sample(noise), -1.0, 1.0)

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def _draw(self, iterations):
        c = self.config
        shape = (iterations, c["num_samples"], c["batch_size"], self.action_size)
        return {
            "indices": self.replay.windows(self.rng, iterations, c["batch_size"]),
            "next_noise": self.rng.standard_normal(shape).astype(self.np_dtype),
            "noise": self.rng.standard_normal(shape).astype(self.np_dtype),
        }

    def _sampled_values(self, actor_v, critic_v, observations, noise, obs_stats):
        """Actions sampled from the policy of ``actor_v`` ``[samples, batch, actions]``, their
        values under ``critic_v`` ``[samples, batch]``, and the policy."""
        xp = self.xp
        dist = self.model.actor(observations, obs_stats, v=actor_v)
        actions = xp.clip(dist.loc[None] + dist.scale[None] * noise, -1.0, 1.0)
        samples = int(noise.shape[0])
        tiled = xp.broadcast_to(observations[None], (samples, *tuple(observations.shape)))
        return actions, self._q(critic_v, tiled, actions, obs_stats), dist

    def _target_values(self, v, targets, batch, obs_stats, x):
        _, values, _ = self._sampled_values(
            targets["actor"],
            targets["critic"],
            batch["next_observations"],
            x["next_noise"],
            obs_stats,
        )
        return self.xp.mean(values, axis=0)

    def _policy_and_dual_loss(self, w, target_dist, actions, weights_logits, batch, obs_stats):
        xp, c = self.xp, self.config
        samples = int(actions.shape[0])
        dual = w["dual"]
        temperature = xp.softplus(dual["log_temperature"]) + 1e-8
        alpha_mean = xp.softplus(dual["log_alpha_mean"]) + 1e-8
        alpha_std = xp.softplus(dual["log_alpha_std"]) + 1e-8
        # E-step: the temperature's dual and the weights of the sampled actions
        scaled = weights_logits / temperature
        weights = xp.stop_gradient(xp.softmax(scaled, axis=0))
        log_mean_exp = xp.logsumexp(scaled, axis=0) - math.log(samples)
        temperature_loss = temperature * (c["epsilon"] + xp.mean(log_mean_exp))
        # M-step: the mean and the scale fitted separately (the other one from the target)
        dist = self.model.actor(batch["observations"], obs_stats, v=w["actor"])
        loc, scale = dist.loc, dist.scale
        target_loc, target_scale = target_dist.loc, target_dist.scale
        fixed_scale = _gaussian_log_prob(xp, actions, loc[None], target_scale[None])
        fixed_loc = _gaussian_log_prob(xp, actions, target_loc[None], scale[None])
        loss_mean = -xp.mean(xp.sum(weights * fixed_scale, axis=0))
        loss_std = -xp.mean(xp.sum(weights * fixed_loc, axis=0))
        # per-dimension KL(target || fitted), averaged over the batch: [actions]
        kl_mean = xp.mean(xp.square(target_loc - loc) / (2.0 * xp.square(target_scale)), axis=0)
        ratio = xp.square(target_scale / scale)
        kl_std = xp.mean(0.5 * (ratio - 1.0 - xp.log(ratio)), axis=0)
        alpha_mean_loss = xp.sum(alpha_mean * (c["epsilon_mean"] - xp.stop_gradient(kl_mean)))
        alpha_std_loss = xp.sum(alpha_std * (c["epsilon_std"] - xp.stop_gradient(kl_std)))
        policy_loss = (
            loss_mean
            + loss_std
            + xp.sum(xp.stop_gradient(alpha_mean) * kl_mean)
            + xp.sum(xp.stop_gradient(alpha_std) * kl_std)
        )
        total = policy_loss + temperature_loss + alpha_mean_loss + alpha_std_loss
        infos = {
            "loss": policy_loss,
            "temperature": temperature,
            "kl_mean": xp.sum(kl_mean),
            "kl_std": xp.sum(kl_std),
        }
        return total, infos

    def _learn_step(self, carry, x, arrays, obs_stats):
        xp, c = self.xp, self.config
        v, targets, states = carry["v"], carry["targets"], carry["states"]
        v, states, critic_loss, batch = self._critic_step(
            v, targets, states, x["indices"], arrays, obs_stats, x
        )
        actions, values, target_dist = self._sampled_values(
            targets["actor"], targets["critic"], batch["observations"], x["noise"], obs_stats
        )
        actions, values = xp.stop_gradient(actions), xp.stop_gradient(values)
        parts = {"actor": v["actor"], "dual": v["dual"]}
        _, grads, infos = xp.execute_with_gradients(
            lambda w: self._policy_and_dual_loss(w, target_dist, actions, values, batch, obs_stats),
            parts,
        )
        clip = c["gradient_clip"]
        actor_grads = xp.clip_by_global_norm(grads["actor"], clip)[0] if clip else grads["actor"]
        actor_v, actor_state = self.optimizers["actor"].step(
            v["actor"], actor_grads, states["actor"]
        )
        dual_v, dual_state = self.optimizers["dual"].step(v["dual"], grads["dual"], states["dual"])
        dual_v = {k: xp.maximum(a, c["min_log_dual"]) for k, a in dual_v.items()}
        v = {**v, "actor": actor_v, "dual": dual_v}
        states = {**states, "actor": actor_state, "dual": dual_state}
        targets = self._soft_update(targets, v, ("actor", "critic"))
        logs = {"critic/loss": critic_loss, **{f"actor/{k}": a for k, a in infos.items()}}
        return {"v": v, "targets": targets, "states": states}, logs


def _gaussian_log_prob(xp, actions, loc, scale):
    """Log-density of a diagonal Gaussian, summed over the last axis."""
    z = (actions - loc) / scale
    per_dim = -0.5 * xp.square(z) - xp.log(scale) - 0.5 * math.log(2.0 * math.pi)
    return xp.sum(per_dim, axis=-1)
