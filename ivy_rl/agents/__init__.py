"""Agents: the :class:`Agent` interface, baselines (``Uniform``, ``Constant``) and the
on-policy agents ``A2C``, ``PPO`` and ``TRPO`` (Box and Discrete actions).

Example:
    >>> agent = ivy_rl.agents.make("PPO", batch_size=64)
    >>> agent.initialize(env.observation_space, env.action_space, seed=0, f="torch")
"""

from __future__ import annotations

from typing import Any

from ivy_rl.agents.a2c import A2C
from ivy_rl.agents.agent import Agent
from ivy_rl.agents.apg import APG
from ivy_rl.agents.baselines import Constant, Uniform
from ivy_rl.agents.d4pg import D4PG
from ivy_rl.agents.ddpg import DDPG
from ivy_rl.agents.defaults import DEFAULTS, check_setting, defaults_for, task_family
from ivy_rl.agents.dqn import DQN, BranchingDQN
from ivy_rl.agents.fusion import FUSION_LEVELS, compiled_scan_unrolls
from ivy_rl.agents.mpo import MPO
from ivy_rl.agents.ppo import PPO
from ivy_rl.agents.sac import SAC
from ivy_rl.agents.shac import SHAC
from ivy_rl.agents.td3 import TD3
from ivy_rl.agents.trpo import TRPO

__all__ = [
    "Agent",
    "Uniform",
    "Constant",
    "A2C",
    "PPO",
    "TRPO",
    "APG",
    "SHAC",
    "DDPG",
    "TD3",
    "SAC",
    "MPO",
    "D4PG",
    "DQN",
    "BranchingDQN",
    "AGENTS",
    "make",
    "DEFAULTS",
    "task_family",
    "compiled_scan_unrolls",
    "FUSION_LEVELS",
]

AGENTS: dict[str, type[Agent]] = {
    "A2C": A2C,
    "PPO": PPO,
    "TRPO": TRPO,
    "APG": APG,
    "SHAC": SHAC,
    "DDPG": DDPG,
    "TD3": TD3,
    "SAC": SAC,
    "MPO": MPO,
    "D4PG": D4PG,
    "DQN": DQN,
    "BranchingDQN": BranchingDQN,
    "Uniform": Uniform,
    "Constant": Constant,
}


def make(name: str, *, environment: Any = None, **settings: Any) -> Agent:
    """An agent by name (``'PPO'``, ``'A2C'``, ``'TRPO'``, ``'Uniform'``, ``'Constant'``;
    case-insensitive) with the defaults of the environment's task family
    (:data:`~ivy_rl.agents.defaults.DEFAULTS`), overridden by ``settings``.

    Every setting is checked (type and range) before anything is built, and the error names
    it; ``agent.config`` holds every value used.

    Args:
        name: the agent's name.
        environment: a Gymnasium id (or environment) whose family's defaults apply; None: the
            agent's own defaults.
        settings: settings that override the defaults (JSON values, as ``--agent-kwargs``).

    Returns:
        The agent, not initialized.

    Example:
        >>> make("PPO", environment="CartPole-v1").config["segment_size"]
        32
    """
    by_lower = {key.lower(): key for key in AGENTS}
    key = by_lower.get(str(name).lower())
    if key is None:
        raise ValueError(f"unknown agent {name!r}; available agents: {', '.join(AGENTS)}")
    merged = {**defaults_for(key, environment), **settings}
    checked = {k: check_setting(k, v) for k, v in merged.items()}
    return AGENTS[key](**checked)
