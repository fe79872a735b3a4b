"""DDPG: deep deterministic policy gradient (Lillicrap et al., 2016), the base of TD3 and D4PG.

A deterministic actor ``tanh(dense(torso(obs)))`` explores with noise added on the host
(:mod:`ivy_rl.explorations`); a critic ``Q(s, a)`` regresses on n-step targets
``R + γ^k Q'(s', π'(s'))`` from the target networks; the actor ascends ``Q(s, π(s))``; the
targets follow by soft updates. One compiled function per update (see
:mod:`ivy_rl.agents.off_policy`).

The agent is its parts, as in Tonic: ``DDPG(model=ActorQModel(...), replay=Transitions(...),
exploration=NormalNoise(...), actor_updater=DeterministicPolicyGradient(...),
critic_updater=DeterministicQLearning(...))``; flat settings build the parts not given.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = DDPG(exploration="ornstein_uhlenbeck").initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
    >>> agent.step(np.zeros((2, 3), np.float32)).shape
    (2, 1)
"""

from __future__ import annotations

from functools import partial

from ivy_rl.agents.off_policy import OffPolicyAgent
from ivy_rl.explorations import make_exploration
from ivy_rl.off_policy_models import ActorQModel
from ivy_rl.off_policy_updaters import DeterministicPolicyGradient, DeterministicQLearning
from ivy_rl.replays import Transitions

__all__ = ["DDPG", "REPLAY", "MODEL", "UPDATER"]

#: the flat settings of the off-policy parts, by part parameter
REPLAY = {
    "replay_size": "size",
    "return_steps": "return_steps",
    "batch_size": "batch_size",
    "batch_iterations": "batch_iterations",
    "discount": "discount",
    "update_after": "update_after",
    "update_every": "update_every",
}
MODEL = {
    "hidden_sizes": "hidden_sizes",
    "critic_hidden_sizes": "critic_hidden_sizes",
    "activation": "activation",
    "normalize_observations": "normalize_observations",
    "target_tau": "target_tau",
}
UPDATER = {"gradient_clip": "gradient_clip"}


class DDPG(OffPolicyAgent):
    """Deep deterministic policy gradient, with n-step returns and partial-episode
    bootstrapping.

    Parts: ``model`` (:class:`~ivy_rl.off_policy_models.ActorQModel`, deterministic policy, one
    critic), ``replay`` (:class:`~ivy_rl.replays.Transitions`), ``exploration``
    (:mod:`ivy_rl.explorations`), ``actor_updater``
    (:class:`~ivy_rl.off_policy_updaters.DeterministicPolicyGradient`), ``critic_updater``
    (:class:`~ivy_rl.off_policy_updaters.DeterministicQLearning`).

    Args:
        model, replay, exploration, actor_updater, critic_updater: the parts (default: built
            from the flat settings, see Parts); ``exploration`` also takes a name:
            ``'normal'``, ``'ornstein_uhlenbeck'`` or ``'none'``.
        settings: the flat settings of the parts not given, and ``fusion``
            (:mod:`ivy_rl.agents.fusion`).

    Settings: the flat settings (``DDPG(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``DDPG.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults DDPG Pendulum-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> DDPG(hidden_sizes=(64, 64), exploration_scale=0.2).config["exploration_scale"]
        0.2
    """

    supported_action_spaces = ("Box",)
    parts = {
        "model": (partial(ActorQModel, policy="deterministic"), MODEL),
        "replay": (Transitions, REPLAY),
        "exploration": (
            make_exploration,
            {"exploration": "name", "exploration_scale": "scale", "start_steps": "start_steps"},
        ),
        "actor_updater": (DeterministicPolicyGradient, {"actor_lr": "lr", **UPDATER}),
        "critic_updater": (DeterministicQLearning, {"critic_lr": "lr", **UPDATER}),
    }
