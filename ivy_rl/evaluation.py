"""Evaluating an agent on episodes of an environment, as stable-baselines3's
``evaluate_policy`` does.

Example:
    >>> import gymnasium
    >>> env = gymnasium.make("CartPole-v1")
    >>> agent = ivy_rl.Constant().initialize(env.observation_space, env.action_space)
    >>> mean, std = ivy_rl.evaluate(agent, env, episodes=10)
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["evaluate"]


def evaluate(
    agent: Any,
    env: Any,
    episodes: int = 10,
    *,
    deterministic: bool = True,
    seed: int | None = 0,
    return_episode_rewards: bool = False,
) -> tuple[float, float] | tuple[list[float], list[int]]:
    """Run ``episodes`` episodes of ``agent`` (initialized, or loaded) on ``env``.

    Args:
        agent: an initialized agent (:meth:`~ivy_rl.agents.Agent.predict` chooses its actions).
        env: a Gymnasium environment, or an id (made with :func:`ivy_rl.environments.make_env`
            and closed afterwards).
        episodes: the number of episodes, >= 1.
        deterministic: act as in tests (no exploration), as stable-baselines3's argument.
        seed: seed of the first episode (episode ``i`` resets with ``seed + i``); None: the
            environment's own sequence.
        return_episode_rewards: return each episode's score and length instead of the mean and
            standard deviation of the scores.

    Returns:
        ``(mean, std)`` of the episodes' scores, or ``(scores, lengths)``.

    Example:
        >>> import gymnasium
        >>> env = gymnasium.make("CartPole-v1")
        >>> agent = ivy_rl.Constant().initialize(env.observation_space, env.action_space)
        >>> ivy_rl.evaluate(agent, env, episodes=3)  # always pushing left
        (10.0, 0.816496580927726)
        >>> ivy_rl.evaluate(agent, "CartPole-v1", episodes=3, return_episode_rewards=True)
        ([11.0, 10.0, 9.0], [11, 10, 9])
    """
    if isinstance(episodes, bool) or not isinstance(episodes, (int, np.integer)) or episodes < 1:
        raise ValueError(f"episodes must be an integer >= 1, got {episodes!r}")
    owned = isinstance(env, str)
    if owned:
        from ivy_rl.environments import make_env

        env = make_env(env)
    scores, lengths = [], []
    try:
        for episode in range(int(episodes)):
            obs, _ = env.reset(seed=None if seed is None else seed + episode)
            score, length = 0.0, 0
            while True:
                action, _ = agent.predict(obs, deterministic=deterministic)
                obs, reward, terminated, truncated, _ = env.step(action)
                score += float(reward)
                length += 1
                if terminated or truncated:
                    break
            scores.append(score)
            lengths.append(length)
    finally:
        if owned:
            env.close()
    if return_episode_rewards:
        return scores, lengths
    return float(np.mean(scores)), float(np.std(scores))
