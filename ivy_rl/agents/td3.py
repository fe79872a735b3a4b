"""TD3: twin delayed deep deterministic policy gradient (Fujimoto et al., 2018).

DDPG with twin critics (the target takes the smaller of the two target critics' values),
target policy smoothing (clipped Gaussian noise on the target actions, drawn by the agent's
numpy generator and passed in) and delayed actor updates: each step of the compiled scan makes
``policy_delay`` critic steps, then one actor step and the targets' soft update.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = TD3(policy_delay=2, target_noise=0.2).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
    >>> agent.step(np.zeros((2, 3), np.float32)).shape
    (2, 1)
"""

from __future__ import annotations

from functools import partial
from typing import Any

from ivy_rl.agents.ddpg import DDPG, MODEL, UPDATER
from ivy_rl.off_policy_models import ActorQModel
from ivy_rl.off_policy_updaters import (
    TwinCriticDeterministicPolicyGradient,
    TwinCriticDeterministicQLearning,
)
from ivy_rl.settings import Setting

__all__ = ["TD3"]


class TD3(DDPG):
    """Twin delayed DDPG.

    Parts: as DDPG's, with twin critics, a
    :class:`~ivy_rl.off_policy_updaters.TwinCriticDeterministicPolicyGradient` and a
    :class:`~ivy_rl.off_policy_updaters.TwinCriticDeterministicQLearning`.

    Args:
        As for :class:`~ivy_rl.agents.DDPG`, and the agent's own ``policy_delay`` (critic steps
        per actor step; ``batch_iterations`` must be a multiple of it).

    Settings: the flat settings (``TD3(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``TD3.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults TD3 Pendulum-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> TD3(hidden_sizes=(64, 64), policy_delay=2).config["policy_delay"]
        2
    """

    own_settings = {
        "policy_delay": Setting("int", 1, meaning="critic steps per actor step"),
    }
    _defaults: dict[str, Any] = dict(policy_delay=2)
    parts = {
        **DDPG.parts,
        "model": (partial(ActorQModel, policy="deterministic", critics=2), MODEL),
        "actor_updater": (TwinCriticDeterministicPolicyGradient, {"actor_lr": "lr", **UPDATER}),
        "critic_updater": (
            TwinCriticDeterministicQLearning,
            {
                "critic_lr": "lr",
                "target_noise": "target_noise",
                "target_noise_clip": "target_noise_clip",
                **UPDATER,
            },
        ),
    }

    def _check_config(self, config):
        if config["batch_iterations"] % config["policy_delay"]:
            raise ValueError(
                f"TD3: batch_iterations ({config['batch_iterations']}) must be a multiple of "
                f"policy_delay ({config['policy_delay']})"
            )

    def _draw(self, iterations):
        # grouped by actor step: [groups, policy_delay, ...]
        delay = self.config["policy_delay"]
        xs = super()._draw(iterations)
        return {k: a.reshape(iterations // delay, delay, *a.shape[1:]) for k, a in xs.items()}

    def _learn_step(self, carry, x, arrays, obs_stats, rates):
        xp = self.xp
        v, targets, states = carry["v"], carry["targets"], carry["states"]
        losses = []
        for i in range(self.config["policy_delay"]):
            batch = self._batch(arrays, x["indices"][i])
            noise = {k: a[i] for k, a in x.items() if k != "indices"}
            v, states, infos = self.critic_updater.step(
                v, targets, states, batch, obs_stats, noise, rates["critic_updater"]
            )
            losses.append(infos["loss"])
        v, states, actor_infos = self.actor_updater.step(
            v, targets, states, batch, obs_stats, {}, rates["actor_updater"]
        )
        targets = self._soft_update(targets, v)
        logs = {"critic/loss": xp.mean(xp.stack(losses)), "actor/loss": actor_infos["loss"]}
        return {"v": v, "targets": targets, "states": states}, logs
