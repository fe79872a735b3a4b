"""SAC: soft actor-critic (Haarnoja et al., 2018) with automatic entropy tuning.

A ``tanh``-squashed Gaussian actor, twin critics regressing on the soft n-step targets
``R + γ^k (min_i Q'_i(s', a') - α log π(a'|s'))`` with ``a' ~ π(s')``, the actor minimising
``α log π(a|s) - min_i Q_i(s, a)``, and the temperature ``α = exp(log_alpha)`` adjusted so that
the policy's entropy tracks ``target_entropy`` (default: minus the number of action
dimensions). The sampling noise is drawn by the agent's numpy generator and passed in, so the
compiled update draws nothing.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = SAC(hidden_sizes=(256, 256)).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
    >>> agent.step(np.zeros((2, 3), np.float32)).shape
    (2, 1)

    The same agent from its parts:

    >>> from ivy_rl.off_policy_models import ActorQModel
    >>> from ivy_rl.off_policy_updaters import TwinCriticSoftQLearning
    >>> agent = SAC(model=ActorQModel((64, 64), policy="squashed_gaussian", critics=2,
    ...                               targets=("critic",)),
    ...             critic_updater=TwinCriticSoftQLearning(lr=3e-4))
    >>> agent.config["hidden_sizes"], agent.config["critic_lr"]
    ((64, 64), 0.0003)
"""

from __future__ import annotations

from functools import partial

from ivy_rl.agents.ddpg import DDPG, MODEL, UPDATER
from ivy_rl.explorations import NoNoise
from ivy_rl.off_policy_models import ActorQModel
from ivy_rl.off_policy_updaters import TwinCriticSoftPolicyGradient, TwinCriticSoftQLearning

__all__ = ["SAC"]


class SAC(DDPG):
    """Soft actor-critic with twin critics and a learned temperature.

    Parts: ``model`` (:class:`~ivy_rl.off_policy_models.ActorQModel`, squashed Gaussian
    policy, twin critics, targets of the critics only), ``replay``, ``exploration``
    (:class:`~ivy_rl.explorations.NoNoise`: the policy samples), ``actor_updater``
    (:class:`~ivy_rl.off_policy_updaters.TwinCriticSoftPolicyGradient`, with the temperature),
    ``critic_updater`` (:class:`~ivy_rl.off_policy_updaters.TwinCriticSoftQLearning`).

    Args:
        As for :class:`~ivy_rl.agents.DDPG`; SAC explores by sampling its policy (no exploration
        noise), its temperature is part of its actor updater.

    Settings: the flat settings (``SAC(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``SAC.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults SAC Pendulum-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> SAC(initial_temperature=0.1, temperature_lr=3e-4).config["initial_temperature"]
        0.1
    """

    scheduled = ("actor_lr", "critic_lr", "temperature_lr")
    parts = {
        "model": (
            partial(ActorQModel, policy="squashed_gaussian", critics=2, targets=("critic",)),
            MODEL,
        ),
        "replay": DDPG.parts["replay"],
        "exploration": (NoNoise, {"start_steps": "start_steps"}),
        "actor_updater": (
            TwinCriticSoftPolicyGradient,
            {
                "actor_lr": "lr",
                "initial_temperature": "initial_temperature",
                "temperature_lr": "temperature_lr",
                "target_entropy": "target_entropy",
                **UPDATER,
            },
        ),
        "critic_updater": (TwinCriticSoftQLearning, {"critic_lr": "lr", **UPDATER}),
    }
