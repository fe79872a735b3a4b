"""The score of a trained agent as the RL results benchmarks report it: the mean return of a
fixed set of seeded episodes of the Gymnasium environment itself (``rl_results.py``,
``rl_offpolicy_results.py``), the same episodes for every agent and library."""

from __future__ import annotations

import numpy as np

__all__ = ["FIXED_EPISODES", "evaluate"]

FIXED_EPISODES = range(1000, 1010)


def evaluate(act, env_id: str) -> float:
    """Mean score of ``act(observation) -> action`` over the fixed episodes."""
    import gymnasium as gym

    env = gym.make(env_id)
    scores = []
    for seed in FIXED_EPISODES:
        obs, _ = env.reset(seed=seed)
        score, done = 0.0, False
        while not done:
            obs, reward, terminated, truncated, _ = env.step(act(obs))
            score += float(reward)
            done = terminated or truncated
        scores.append(score)
    env.close()
    return float(np.mean(scores))
