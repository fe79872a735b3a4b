"""What one update of ivy_rl's agents costs per backend and fusion level: the first update
(which compiles) and the following ones, on synthetic transitions of the benchmark settings.

``fusion="update"`` compiles the whole update (returns by ``ivy.scan``, every mini-batch step,
the KL stop) as one function; ``fusion="steps"`` compiles the returns and each optimisation step
as separate functions looped over on the host. ``torch.compile`` unrolls ``ivy.scan``, so its
compile time grows with the number of steps in one function.

Usage:
    python benchmarks/rl_update.py                                # every case, 300 s limit each
    python benchmarks/rl_update.py --cases PPO-CartPole --backends jax torch --limit 600

Each case runs in its own process (a fresh compiler cache); a case over ``--limit`` seconds is
reported as such.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time

CASES = {
    # name: (agent, observation size, action space, workers, settings)
    "PPO-CartPole": (
        "PPO",
        4,
        "Discrete",
        8,
        dict(segment_size=32, batch_size=256, epochs=20, kl_threshold=None),
    ),
    "PPO-Pendulum": (
        "PPO",
        3,
        "Box",
        4,
        dict(segment_size=1024, batch_size=64, epochs=10, normalize_returns=True),
    ),
    "A2C-CartPole": ("A2C", 4, "Discrete", 8, dict(segment_size=16, critic_iterations=5)),
    "TRPO-CartPole": (
        "TRPO",
        4,
        "Discrete",
        8,
        dict(segment_size=128, critic_iterations=10, batch_size=256),
    ),
}


def measure(case: str, backend: str, fusion: str, updates: int) -> dict:
    """Run in a child process: times of the first and of later updates."""
    import gymnasium as gym
    import numpy as np

    import ivy_rl

    if backend == "torch":
        import torch

        torch.set_num_threads(1)
    agent_name, obs_size, space_kind, workers, settings = CASES[case]
    space = gym.spaces.Discrete(2) if space_kind == "Discrete" else gym.spaces.Box(-1, 1, (1,))
    agent = ivy_rl.agents.make(agent_name, fusion=fusion, **settings)
    agent.initialize(gym.spaces.Box(-np.inf, np.inf, (obs_size,)), space, seed=0, f=backend)
    data = np.random.default_rng(0)
    obs = data.normal(size=(workers, obs_size))
    agent.step(obs)  # compiles the acting function outside the timings
    times, ends = [], data.random((10_000, workers)) < 0.02
    t, compiles = 0, []
    while len(times) < updates:
        start = time.perf_counter()
        logs = agent.update(
            data.normal(size=(workers, obs_size)), np.ones(workers), ends[t], ends[t]
        )
        if logs:
            times.append(time.perf_counter() - start)
            compiles.append(agent.compiles)
        t += 1
        agent.step(obs)
    return {
        "first": times[0],
        "later": float(np.median(times[1:])),
        "compiles": f"{compiles[0]} / {compiles[-1]}",
    }


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--cases", nargs="+", default=list(CASES))
    p.add_argument("--backends", nargs="+", default=["jax", "tensorflow", "torch"])
    p.add_argument("--fusions", nargs="+", default=["update", "steps"])
    p.add_argument("--updates", type=int, default=4)
    p.add_argument("--limit", type=float, default=300.0, help="seconds per case")
    p.add_argument("--child", nargs=3, help=argparse.SUPPRESS)
    args = p.parse_args()
    if args.child:
        print(json.dumps(measure(*args.child, args.updates)))
        return
    print(
        "| case | backend | fusion | first update (compiles) s | later updates ms | "
        "agent.compiles after the first / last update |"
    )
    print("|---|---|---|---|---|---|")
    for case in args.cases:
        for backend in args.backends:
            for fusion in args.fusions:
                command = [sys.executable, __file__, "--child", case, backend, fusion]
                command += ["--updates", str(args.updates)]
                try:
                    done = subprocess.run(
                        command, capture_output=True, text=True, timeout=args.limit
                    )
                    result = json.loads(done.stdout.strip().splitlines()[-1])
                    first, later = f"{result['first']:.1f}", f"{1000 * result['later']:.1f}"
                    compiles = result["compiles"]
                except subprocess.TimeoutExpired:
                    first, later, compiles = f"> {args.limit:.0f} (stopped)", "–", "–"
                except (IndexError, json.JSONDecodeError):
                    first, later = "failed", done.stderr.strip().splitlines()[-1][:80]
                    compiles = "–"
                print(
                    f"| {case} | {backend} | {fusion} | {first} | {later} | {compiles} |",
                    flush=True,
                )


if __name__ == "__main__":
    main()
