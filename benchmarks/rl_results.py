"""ivy_rl results: learning on CartPole-v1 (PPO, A2C, TRPO on torch, jax and tensorflow), and
PPO on Pendulum-v1 and Hopper-v5 against stable-baselines3's PPO with the same settings and
budget, in the same run: test scores and wall-clock steps per second.

Scores: ivy_rl's per-epoch test scores (``test_episodes`` new episodes per epoch, for the
curves), and, for every run of either library, the final policy's mean score over the same 10
fixed episodes (seeds 1000-1009, deterministic actions), so that both libraries are judged on
the same start states.

Steps per second: environment steps over the seconds spent training, without the first epoch
(compilation) and without test episodes (ivy_rl); steps over the seconds of ``model.learn``
(stable-baselines3). The machine's load average is recorded with each run.

stable-baselines3 is a benchmark-only peer: ``pip install stable-baselines3`` (it must leave
torch at 2.13.0; check with ``pip install --dry-run``). Without it the peer rows are skipped.
Where ivy_rl normalises observations (its default), stable-baselines3 runs in
``VecNormalize(norm_obs=True, norm_reward=False, clip_obs=10)``, the same normalisation.

Usage:
    python benchmarks/rl_results.py                      # everything (an hour here, loaded)
    python benchmarks/rl_results.py --only cartpole --frameworks jax
    python benchmarks/rl_results.py --steps 20000        # a quick look
    python -m ivy_rl.plot runs/bench/PPO-CartPole-v1-* --out curves.png

Each run writes its log to ``runs/bench/<name>``; the table goes to stdout and
``runs/bench/results.md``, every result to ``runs/bench/results.json``.
"""

from __future__ import annotations

import argparse
import json
import os
import time

import numpy as np
from _gym_scores import evaluate

# Every run uses the command line's defaults: ivy_rl.agents.DEFAULTS, the row of the agent and the
# environment's task family (the RL zoo's settings: for CartPole, PPO with a segment of 32 steps
# x 8 workers, 20 epochs of one mini-batch of 256, discount 0.98, lambda 0.8, learning rates 1e-3;
# Pendulum and Hopper: the classic-control-continuous and MuJoCo rows).
CARTPOLE = {"PPO": {}, "A2C": {}, "TRPO": {}}
PENDULUM: dict = {}
HOPPER: dict = {}


def run_ivy(agent, env_id, framework, steps, workers, kwargs, root, seed, test_episodes):
    from ivy_rl.agents import make
    from ivy_rl.trainer import Trainer

    if framework == "torch":
        import torch

        torch.set_num_threads(1)
    name = f"{agent}-{env_id}-{framework}-{seed}"
    load = os.getloadavg()[0]
    trainer = Trainer(
        steps, epoch_steps=steps // 10, test_episodes=test_episodes, show_progress=False
    )
    start = time.perf_counter()
    rows = trainer.run(
        make(agent, environment=env_id, **kwargs),
        env_id,
        workers=workers,
        seed=seed,
        f=framework,
        out=os.path.join(root, name),
    )
    seconds = time.perf_counter() - start
    later = rows[1:]
    trained = sum(r["train/steps"] - p["train/steps"] for p, r in zip(rows, rows[1:]))
    busy = sum(r["train/epoch_seconds"] - r["test/seconds"] for r in later)
    fixed = evaluate(lambda obs: trainer.agent.test_step(np.asarray(obs)[None])[0], env_id)
    return dict(
        name=name,
        library=f"ivy_rl ({framework}, fusion={trainer.agent.fusion})",
        agent=agent,
        env=env_id,
        seed=seed,
        steps=steps,
        seconds=seconds,
        first_epoch_seconds=rows[0]["train/epoch_seconds"],
        steps_per_second=trained / max(busy, 1e-9),
        fixed_score=fixed,
        curve=[(r["train/steps"], r["test/episode_score/mean"]) for r in rows],
        load=(load + os.getloadavg()[0]) / 2,
    )


def run_sb3(env_id, steps, workers, kwargs, seed, normalize):
    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.env_util import make_vec_env
    from stable_baselines3.common.vec_env import VecNormalize

    torch.set_num_threads(1)
    load = os.getloadavg()[0]
    env = make_vec_env(env_id, n_envs=workers, seed=seed)
    if normalize:
        env = VecNormalize(env, norm_obs=True, norm_reward=False, clip_obs=10.0)
    model = PPO("MlpPolicy", env, seed=seed, device="cpu", verbose=0, **kwargs)
    start = time.perf_counter()
    model.learn(steps)
    seconds = time.perf_counter() - start
    if normalize:
        env.training = False

    def act(obs):
        obs = env.normalize_obs(obs[None])[0] if normalize else obs
        return model.predict(obs, deterministic=True)[0]

    return dict(
        name=f"sb3-PPO-{env_id}-{seed}",
        library="stable-baselines3 (torch, 1 thread)",
        agent="PPO",
        env=env_id,
        seed=seed,
        steps=steps,
        seconds=seconds,
        first_epoch_seconds=float("nan"),
        steps_per_second=steps / seconds,
        fixed_score=evaluate(act, env_id),
        curve=[],
        load=(load + os.getloadavg()[0]) / 2,
    )


def sb3_settings(config, workers):
    """stable-baselines3's PPO arguments for an ivy_rl PPO config."""
    return dict(
        n_steps=config["segment_size"],
        batch_size=config["batch_size"],
        n_epochs=config["epochs"],
        gamma=config["discount"],
        gae_lambda=config["trace_decay"],
        learning_rate=config["actor_lr"],
        clip_range=0.2,
        ent_coef=0.0,
        max_grad_norm=config["actor_gradient_clip"],
    )


def table(results):
    lines = [
        "| run | library | seed | steps | test score (last epoch) | best epoch | first epoch "
        "≥ 475 | score on the 10 fixed episodes | seconds (first epoch) | steps/s | load |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in results:
        curve = r["curve"]
        first = next((s for s, v in curve if v >= 475), None)
        last = f"{curve[-1][1]:.1f}" if curve else "–"
        best = f"{max(v for _, v in curve):.1f}" if curve else "–"
        reached = (
            "–"
            if not curve or "CartPole" not in r["env"]
            else (f"{first:,}" if first is not None else "not reached")
        )
        first_epoch = (
            "" if np.isnan(r["first_epoch_seconds"]) else f" ({r['first_epoch_seconds']:.1f})"
        )
        lines.append(
            f"| {r['agent']} {r['env']} | {r['library']} | {r['seed']} | {r['steps']:,} | {last} "
            f"| {best} | {reached} | {r['fixed_score']:.1f} | {r['seconds']:.1f}{first_epoch} "
            f"| {r['steps_per_second']:,.0f} | {r['load']:.1f} |"
        )
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--only", nargs="+", default=["cartpole", "pendulum", "hopper"])
    p.add_argument("--frameworks", nargs="+", default=["torch", "jax", "tensorflow"])
    p.add_argument("--agents", nargs="+", default=["PPO", "A2C", "TRPO"])
    p.add_argument("--seeds", nargs="+", type=int, default=[0])
    p.add_argument("--steps", type=int, default=None, help="override every budget")
    p.add_argument("--out", default="runs/bench")
    p.add_argument("--no-peers", action="store_true", help="skip stable-baselines3's runs")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    results = []

    def record(result):
        results.append(result)
        print(table([result]).splitlines()[-1], flush=True)
        with open(os.path.join(args.out, "results.json"), "w") as fh:
            json.dump(results, fh, indent=1)

    have_sb3 = not args.no_peers
    try:
        import stable_baselines3  # noqa: F401
    except ImportError:
        have_sb3 = False
        print("stable-baselines3 is not installed: its rows are skipped")
    print(f"cores: {os.cpu_count()}, load average at the start: {os.getloadavg()}", flush=True)
    tasks = []
    if "cartpole" in args.only:
        for agent in args.agents:
            tasks.append((agent, "CartPole-v1", CARTPOLE[agent], 8, 100_000, 5))
    if "pendulum" in args.only:
        tasks.append(("PPO", "Pendulum-v1", PENDULUM, 4, 100_000, 5))
    if "hopper" in args.only:
        tasks.append(("PPO", "Hopper-v5", HOPPER, 4, 100_000, 3))
    for agent, env_id, config, workers, default_steps, test_episodes in tasks:
        steps = args.steps or default_steps
        for seed in args.seeds:
            for fw in args.frameworks:
                record(
                    run_ivy(
                        agent, env_id, fw, steps, workers, config, args.out, seed, test_episodes
                    )
                )
            if have_sb3 and agent == "PPO":
                from ivy_rl.agents import make

                used = make(agent, environment=env_id, **config).config
                normalize = used["normalize_observations"]
                record(
                    run_sb3(env_id, steps, workers, sb3_settings(used, workers), seed, normalize)
                )
    text = table(results)
    print(text)
    print(f"load average at the end: {os.getloadavg()}")
    with open(os.path.join(args.out, "results.md"), "w") as fh:
        fh.write(text + "\n")


if __name__ == "__main__":
    main()
