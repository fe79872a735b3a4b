"""ivy_rl results: learning on CartPole-v1 (PPO, A2C, TRPO on torch, jax and tensorflow), and
PPO on Pendulum-v1 and Hopper-v5 against stable-baselines3's PPO with the same budget, in the
same run: test scores and wall-clock steps per second.

stable-baselines3 is a benchmark-only peer: ``pip install stable-baselines3`` (it must leave
torch at 2.13.0; check with ``pip install --dry-run``). Without it the peer rows are skipped.

Usage:
    python benchmarks/rl_results.py                      # everything (about 30 min here)
    python benchmarks/rl_results.py --only cartpole --frameworks jax
    python benchmarks/rl_results.py --steps 20000        # a quick look

Each run writes its log to ``runs/bench/<name>`` (plot with ``python -m ivy_rl.plot``) and the
table goes to stdout and ``runs/bench/results.md``.
"""

from __future__ import annotations

import argparse
import json
import os
import time

CARTPOLE = {  # the RL zoo's PPO hyperparameters for CartPole (constant learning rate and clip)
    "PPO": dict(
        segment_size=32,
        batch_size=256,
        epochs=20,
        discount=0.98,
        trace_decay=0.8,
        actor_lr=1e-3,
        critic_lr=1e-3,
        kl_threshold=None,
        gradient_clip=0.5,
    ),
    "A2C": dict(
        segment_size=16,
        actor_lr=3e-3,
        critic_lr=1e-3,
        critic_iterations=5,
        discount=0.99,
        trace_decay=0.95,
    ),
    "TRPO": dict(
        segment_size=128,
        max_kl=0.03,
        critic_iterations=10,
        batch_size=256,
        discount=0.99,
        trace_decay=0.95,
    ),
}
PENDULUM = dict(
    segment_size=1024,
    batch_size=64,
    epochs=10,
    discount=0.9,
    trace_decay=0.95,
    actor_lr=1e-3,
    critic_lr=1e-3,
    kl_threshold=None,
    gradient_clip=0.5,
    hidden_sizes=(64, 64),
    normalize_returns=True,
)
HOPPER = dict(
    segment_size=512,
    batch_size=64,
    epochs=10,
    discount=0.99,
    trace_decay=0.95,
    actor_lr=3e-4,
    critic_lr=3e-4,
    kl_threshold=None,
    gradient_clip=0.5,
    hidden_sizes=(64, 64),
    normalize_returns=True,
)


def run_ivy(name, agent, env_id, framework, steps, workers, kwargs, root, test_episodes=5):
    from ivy_rl.agents import make
    from ivy_rl.trainer import Trainer

    if framework == "torch":
        import torch

        torch.set_num_threads(1)
    out = os.path.join(root, name)
    start = time.perf_counter()
    rows = Trainer(
        steps, epoch_steps=steps // 10, test_episodes=test_episodes, show_progress=False
    ).run(make(agent, **kwargs), env_id, workers=workers, seed=0, f=framework, out=out)
    seconds = time.perf_counter() - start
    scores = [(r["train/steps"], r["test/episode_score/mean"]) for r in rows]
    # steps per second without the test episodes and the first epoch's compilation
    later = rows[1:] or rows
    sps = (
        sum(r["train/steps"] - p["train/steps"] for p, r in zip(rows, rows[1:]))
        / max(sum(r["train/epoch_seconds"] for r in later), 1e-9)
        if len(rows) > 1
        else rows[0]["train/steps_per_second"]
    )
    return dict(
        name=name,
        library=f"ivy_rl ({framework})",
        agent=agent,
        env=env_id,
        steps=steps,
        seconds=seconds,
        steps_per_second=sps,
        final_test=scores[-1][1],
        best_test=max(s for _, s in scores),
        curve=scores,
    )


def run_sb3(name, env_id, steps, workers, kwargs, test_episodes=10):
    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.env_util import make_vec_env
    from stable_baselines3.common.evaluation import evaluate_policy

    torch.set_num_threads(1)
    env = make_vec_env(env_id, n_envs=workers, seed=0)
    model = PPO("MlpPolicy", env, seed=0, device="cpu", verbose=0, **kwargs)
    start = time.perf_counter()
    model.learn(steps)
    seconds = time.perf_counter() - start
    score, _ = evaluate_policy(
        model,
        make_vec_env(env_id, n_envs=1, seed=1),
        n_eval_episodes=test_episodes,
        deterministic=True,
    )
    return dict(
        name=name,
        library="stable-baselines3 (torch)",
        agent="PPO",
        env=env_id,
        steps=steps,
        seconds=seconds,
        steps_per_second=steps / seconds,
        final_test=float(score),
        best_test=float("nan"),
        curve=[],
    )


def table(results):
    lines = [
        "| run | library | steps | final test score | best test score | first ≥ 475 | "
        "seconds | steps/s |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in results:
        first = next((s for s, v in r["curve"] if v >= 475), None)
        lines.append(
            f"| {r['agent']} {r['env']} | {r['library']} | {r['steps']:,} | {r['final_test']:.1f} | "
            f"{r['best_test']:.1f} | {'' if first is None else f'{first:,}'} | "
            f"{r['seconds']:.1f} | {r['steps_per_second']:,.0f} |"
        )
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--only", nargs="+", default=["cartpole", "pendulum", "hopper"])
    p.add_argument("--frameworks", nargs="+", default=["torch", "jax", "tensorflow"])
    p.add_argument("--agents", nargs="+", default=["PPO", "A2C", "TRPO"])
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
    if "cartpole" in args.only:
        steps = args.steps or 100_000
        for agent in args.agents:
            for fw in args.frameworks:
                record(
                    run_ivy(
                        f"{agent}-CartPole-{fw}-0",
                        agent,
                        "CartPole-v1",
                        fw,
                        steps,
                        8,
                        CARTPOLE[agent],
                        args.out,
                    )
                )
        if have_sb3:
            record(
                run_sb3(
                    "sb3-PPO-CartPole",
                    "CartPole-v1",
                    steps,
                    8,
                    dict(
                        n_steps=32,
                        batch_size=256,
                        gae_lambda=0.8,
                        gamma=0.98,
                        n_epochs=20,
                        ent_coef=0.0,
                        learning_rate=1e-3,
                        clip_range=0.2,
                    ),
                )
            )
    for key, env_id, config, workers, default_steps in (
        ("pendulum", "Pendulum-v1", PENDULUM, 4, 100_000),
        ("hopper", "Hopper-v5", HOPPER, 4, 100_000),
    ):
        if key not in args.only:
            continue
        steps = args.steps or default_steps
        for fw in args.frameworks:
            record(
                run_ivy(
                    f"PPO-{env_id}-{fw}-0",
                    "PPO",
                    env_id,
                    fw,
                    steps,
                    workers,
                    config,
                    args.out,
                    test_episodes=3,
                )
            )
        if have_sb3:
            record(
                run_sb3(
                    f"sb3-PPO-{env_id}",
                    env_id,
                    steps,
                    workers,
                    dict(
                        n_steps=config["segment_size"],
                        batch_size=config["batch_size"],
                        n_epochs=config["epochs"],
                        gamma=config["discount"],
                        gae_lambda=config["trace_decay"],
                        learning_rate=config["actor_lr"],
                        clip_range=0.2,
                        ent_coef=0.0,
                    ),
                    test_episodes=5,
                )
            )
    text = table(results)
    print(text)
    with open(os.path.join(args.out, "results.md"), "w") as fh:
        fh.write(text + "\n")


if __name__ == "__main__":
    main()
