"""How noisy the gradient that SHAC and APG learn from is, as the horizon grows: the SHAC paper's
Figure 2 (Xu et al. 2022) on ivy_gym's locomotion tasks (Gymnasium's Hopper-v5 and Ant-v5,
contacts and joint limits on).

``N`` rollouts start from states drawn as the task's Gymnasium reset draws them. Rollout ``i``
runs SHAC's policy for the task family (initialised from ``--seed``) with its own offset ``b_i``
added to its actions, for ``K`` steps, and its loss is SHAC's and APG's without the critic:
``L_i = -(1/K) sum_t discount**t r_t`` (Gymnasium's rewards; 0 after a termination, where
Gymnasium's episode ends). ``L_i`` depends on ``b_i`` alone, so one backward pass of
``sum_i L_i`` gives every rollout's gradient ``g_i = dL_i/db_i`` at ``b = 0``: the gradient that
reaches the policy's parameters through its actions. For each ``K`` it reports:

- ``variance``: the mean over the action's components of the variance of ``g_i`` over the ``N``
  rollouts (the paper's measure of the gradient's noise);
- ``mean norm``: the norm of the mean of the ``g_i`` (the signal);
- ``terminated``: the fraction of rollouts that ended within ``K`` steps; their gradient stops at
  the termination (the healthy reward is a constant while the robot is healthy and 0 after: the
  gradient never sees falling);
- ``nonfinite``: the fraction of rollouts whose gradient is not finite;
- ``seconds``: the first call, its compilation included.

Usage:
    .venv/bin/python benchmarks/gradient_variance.py [--tasks Hopper-v5,Ant-v5]
        [--horizons 1,2,4,8,16,32,64,128] [--rollouts 64] [--framework jax]
        [--dtype float32] [--seed 0]
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def gradients(task: str, horizon: int, rollouts: int, framework: str, dtype: str, seed: int):
    """``(g [N, action_dim], terminated [N])`` for ``horizon`` steps of ``task``."""
    import gymnasium

    import ivy
    import ivy_gym
    from ivy_rl.agents import make

    env_id = f"ivy_gym/{task}"
    env = gymnasium.make(env_id)
    agent = make("SHAC", environment=env_id)
    agent.bind_environment(env_id, {})
    agent.initialize(env.observation_space, env.action_space, seed=seed, f=framework, dtype=dtype)
    xp, core = agent.xp, agent.core
    policy = agent._policy(agent._stats(agent.obs_moments))
    gamma = agent.config["discount"]
    discounts = xp.asarray(np.array([[gamma**t] for t in range(horizon)], dtype), dtype=dtype)
    start = xp.asarray(agent._initial_states(rollouts), dtype=dtype)

    def loss(offsets):
        traj = ivy_gym.rollout(
            core,
            start,
            policy=lambda obs, v: policy(obs, v["actor"]) + v["offsets"],
            v={"actor": agent.v["actor"], "offsets": offsets},
            horizon=horizon,
            f=xp,
        )
        per_rollout = -xp.sum(traj.rewards * discounts, axis=0) / horizon
        ended = xp.any(xp.logical_and(traj.terminated, traj.valid), axis=0)
        return xp.sum(per_rollout), ended

    def value_and_grad(offsets):
        total, grads, ended = xp.execute_with_gradients(loss, offsets)
        return total, grads, ended

    fn = ivy.compile_fn(value_and_grad) if agent.compiled else value_and_grad
    offsets = xp.zeros((rollouts, core.action_dim), dtype=dtype)
    began = time.perf_counter()
    _, grads, ended = fn(offsets)
    elapsed = time.perf_counter() - began
    return np.asarray(xp.to_numpy(grads), np.float64), np.asarray(xp.to_numpy(ended)), elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", default="Hopper-v5,Ant-v5")
    parser.add_argument("--horizons", default="1,2,4,8,16,32,64,128")
    parser.add_argument("--rollouts", type=int, default=64)
    parser.add_argument("--framework", default="jax")
    parser.add_argument("--dtype", default="float32")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()
    import ivy

    ivy.set_threads(args.framework, args.threads)
    print(
        f"{args.rollouts} rollouts, SHAC's initial policy (seed {args.seed}), "
        f"{args.framework} {args.dtype}"
    )
    print(
        f"{'task':12} {'K':>4} {'variance':>10} {'mean norm':>10} {'terminated':>10} "
        f"{'nonfinite':>9} {'seconds':>8}"
    )
    for task in args.tasks.split(","):
        for horizon in (int(k) for k in args.horizons.split(",")):
            g, ended, seconds = gradients(
                task, horizon, args.rollouts, args.framework, args.dtype, args.seed
            )
            finite = np.isfinite(g).all(axis=1)
            kept = g[finite]
            variance = kept.var(axis=0).mean() if len(kept) > 1 else float("nan")
            norm = np.linalg.norm(kept.mean(axis=0)) if len(kept) else float("nan")
            print(
                f"{task:12} {horizon:4d} {variance:10.3e} {norm:10.3e} {ended.mean():10.2f} "
                f"{1 - finite.mean():9.2f} {seconds:8.1f}",
                flush=True,
            )


if __name__ == "__main__":
    main()
