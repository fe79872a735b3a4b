"""TD3: twin delayed deep deterministic policy gradient (Fujimoto et al., 2018).

DDPG with twin critics (the target takes the smaller of the two target critics' values),
target policy smoothing (clipped Gaussian noise on the target actions, drawn by the agent's
numpy generator and passed in) and delayed actor updates: each step of the compiled scan makes
``policy_delay`` critic steps, then one actor step and the targets' soft update.

Example:
    >>> agent = TD3(policy_delay=2, target_noise=0.2).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="torch")
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ivy_rl.agents.ddpg import DDPG

__all__ = ["TD3"]


class TD3(DDPG):
    """Twin delayed DDPG.

    Args:
        policy_delay: critic steps per actor step (``batch_iterations`` is a multiple of it).
        target_noise: scale of the target policy's smoothing noise.
        target_noise_clip: bound of that noise.
        Others: as for :class:`~ivy_rl.agents.DDPG`.

    Example:
        >>> TD3(hidden_sizes=(64, 64), policy_delay=2)
    """

    _defaults: dict[str, Any] = dict(policy_delay=2, target_noise=0.2, target_noise_clip=0.5)
    _critics = 2

    def _check_config(self, config):
        if config["batch_iterations"] % config["policy_delay"]:
            raise ValueError(
                f"TD3: batch_iterations ({config['batch_iterations']}) must be a multiple of "
                f"policy_delay ({config['policy_delay']})"
            )

    def _draw(self, iterations):
        c = self.config
        delay = c["policy_delay"]
        groups = iterations // delay
        indices = self.replay.windows(self.rng, iterations, c["batch_size"])
        action_size = int(np.prod(self.action_space.shape))
        noise = self.rng.standard_normal((groups, delay, c["batch_size"], action_size))
        return {
            "indices": indices.reshape(groups, delay, *indices.shape[1:]),
            "noise": noise.astype(self.np_dtype),
        }

    def _target_values(self, v, targets, batch, obs_stats, x):
        xp, c = self.xp, self.config
        following = batch["next_observations"]
        actions = self.model.actor(following, obs_stats, v=targets["actor"]).mode()
        smoothing = xp.clip(
            c["target_noise"] * x["noise"], -c["target_noise_clip"], c["target_noise_clip"]
        )
        actions = xp.clip(actions + smoothing, -1.0, 1.0)
        return xp.min(self._q(targets["critic"], following, actions, obs_stats), axis=0)

    def _actor_loss(self, actor_v, critic_v, batch, obs_stats, x):
        observations = batch["observations"]
        actions = self.model.actor(observations, obs_stats, v=actor_v).mode()
        return -self.xp.mean(self._q(critic_v, observations, actions, obs_stats)[0])

    def _learn_step(self, carry, x, arrays, obs_stats):
        xp = self.xp
        v, targets, states = carry["v"], carry["targets"], carry["states"]
        losses = []
        for i in range(self.config["policy_delay"]):
            v, states, loss, batch = self._critic_step(
                v, targets, states, x["indices"][i], arrays, obs_stats, {"noise": x["noise"][i]}
            )
            losses.append(loss)
        v, states, actor_infos = self._actor_step(v, states, batch, obs_stats, x)
        targets = self._soft_update(targets, v, tuple(targets))
        logs = {"critic/loss": xp.mean(xp.stack(losses)), "actor/loss": actor_infos["loss"]}
        return {"v": v, "targets": targets, "states": states}, logs
