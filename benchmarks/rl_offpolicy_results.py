"""ivy_rl off-policy results: the issue's table (DQN on CartPole-v1, SAC/TD3/DDPG/D4PG/MPO on
Pendulum-v1, SAC and TD3 on Hopper-v5) through the command line with its defaults, and
stable-baselines3's agent of the same name with its own defaults, same budget and seed, in the
same run.

ivy_rl: ``ivy_rl.train.main(["--agent", A, "--environment", E, "-f", FW, "--steps", N,
"--seed", S, "--out", DIR, "--quiet", "--overwrite"])``, no ``--agent-kwargs``: what a user gets
from ``python -m ivy_rl.train`` (8 workers, 5 test episodes per epoch of steps / 20, the row of
``ivy_rl.agents.DEFAULTS`` for the agent and the task family). Its score is the trainer's test
score after the last epoch (``test/episode_score/mean``), the measure of the issue's table.

stable-baselines3 (a benchmark-only peer: ``pip install stable-baselines3==2.9.2``; its rows
are skipped without it): ``Agent("MlpPolicy", gymnasium.make(E), seed=S, device="cpu")`` with
its default settings, ``torch.set_num_threads(1)``, ``model.learn(N)``. It has no D4PG or MPO.

Both libraries' final policies are also scored on the same 10 fixed episodes (seeds 1000-1009,
deterministic actions; ivy_rl's through ``ivy_rl.play`` on the run's last checkpoint).
Seconds: the whole run (ivy_rl: with compilation and test episodes, and ``train/seconds``
of its log); the machine's load average is recorded with each run.

Usage:
    python benchmarks/rl_offpolicy_results.py                           # every row, jax
    python benchmarks/rl_offpolicy_results.py --rows td3-hopper sac-hopper
    python benchmarks/rl_offpolicy_results.py --rows sac-pendulum --frameworks torch tensorflow
    python benchmarks/rl_offpolicy_results.py --rows dqn-cartpole --steps 5000 --no-peers

Each result is merged into ``benchmarks/results/rl_offpolicy.json`` (``--results``; one entry per
run name, so separate invocations add to the same file) and printed as a table row; the runs'
folders go to ``runs/offpolicy/<name>``.
"""

from __future__ import annotations

import argparse
import contextlib
import fcntl
import json
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
# this checkout's ivy_rl, not an installed one (``python benchmarks/...`` puts only benchmarks/
# on the path)
sys.path.insert(0, os.path.dirname(HERE))
RESULTS = os.path.join(HERE, "results", "rl_offpolicy.json")

from _gym_scores import FIXED_EPISODES, evaluate  # noqa: E402

# name: (agent, environment, steps, the target)
ROWS: dict[str, tuple[str, str, int, str]] = {
    "dqn-cartpole": ("DQN", "CartPole-v1", 50_000, ">= 475"),
    "sac-pendulum": ("SAC", "Pendulum-v1", 20_000, ">= -200"),
    "td3-pendulum": ("TD3", "Pendulum-v1", 20_000, ">= -200"),
    "ddpg-pendulum": ("DDPG", "Pendulum-v1", 20_000, ">= -200"),
    "d4pg-pendulum": ("D4PG", "Pendulum-v1", 20_000, ">= -200"),
    "mpo-pendulum": ("MPO", "Pendulum-v1", 20_000, ">= -200"),
    "sac-hopper": ("SAC", "Hopper-v5", 30_000, ">= stable-baselines3"),
    "td3-hopper": ("TD3", "Hopper-v5", 30_000, ">= stable-baselines3"),
}
SB3_AGENTS = ("DQN", "SAC", "TD3", "DDPG")


def _load() -> float:
    return os.getloadavg()[0]


def run_ivy(agent: str, env_id: str, framework: str, steps: int, seed: int, root: str) -> dict:
    """One run of the command line with its defaults."""
    from ivy_rl.play import play
    from ivy_rl.train import main

    if framework == "torch":
        import torch

        torch.set_num_threads(1)
    name = f"ivy_rl-{agent}-{env_id}-{framework}-{seed}-{steps}"
    out = os.path.join(root, name)
    argv = ["--agent", agent, "--environment", env_id, "-f", framework, "--steps", str(steps)]
    argv += ["--seed", str(seed), "--out", out, "--quiet", "--overwrite"]
    load = _load()
    start = time.perf_counter()
    rows = main(argv)
    seconds = time.perf_counter() - start
    load = (load + _load()) / 2
    with contextlib.redirect_stdout(open(os.devnull, "w")):
        fixed = play(out, episodes=len(FIXED_EPISODES), seed=FIXED_EPISODES[0])
    with open(os.path.join(out, "config.json")) as fh:
        used = json.load(fh).get("agent_config", {})
    return dict(
        name=name,
        library="ivy_rl",
        framework=framework,
        agent=agent,
        env=env_id,
        seed=seed,
        steps=steps,
        command="python -m ivy_rl.train " + " ".join(argv),
        test_score=float(rows[-1]["test/episode_score/mean"]),
        best_test_score=float(max(r["test/episode_score/mean"] for r in rows)),
        fixed_score=float(np.mean([r["score"] for r in fixed])),
        curve=[(int(r["train/steps"]), float(r["test/episode_score/mean"])) for r in rows],
        seconds=seconds,
        train_seconds=float(rows[-1].get("train/seconds", float("nan"))),
        load=load,
        settings=used,
    )


def run_sb3(agent: str, env_id: str, steps: int, seed: int) -> dict:
    """stable-baselines3's agent of the same name, its defaults, one torch thread."""
    import gymnasium as gym
    import stable_baselines3
    import torch

    torch.set_num_threads(1)
    cls = getattr(stable_baselines3, agent)
    env = gym.make(env_id)
    model = cls("MlpPolicy", env, seed=seed, device="cpu", verbose=0)
    load = _load()
    start = time.perf_counter()
    model.learn(steps)
    seconds = time.perf_counter() - start
    load = (load + _load()) / 2
    fixed = evaluate(lambda obs: model.predict(obs, deterministic=True)[0], env_id)
    return dict(
        name=f"sb3-{agent}-{env_id}-{seed}-{steps}",
        library=f"stable-baselines3 {stable_baselines3.__version__}",
        framework="torch (1 thread)",
        agent=agent,
        env=env_id,
        seed=seed,
        steps=steps,
        command=f'{agent}("MlpPolicy", gymnasium.make("{env_id}"), seed={seed}).learn({steps})',
        test_score=None,
        best_test_score=None,
        fixed_score=fixed,
        curve=[],
        seconds=seconds,
        train_seconds=seconds,
        load=load,
        settings={},
    )


@contextlib.contextmanager
def _locked(path: str):
    """The results file locked against other invocations writing at the same time."""
    with open(path + ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def merge(path: str, result: dict) -> list[dict]:
    """``result`` written into the JSON list at ``path`` (replacing the entry of the same name);
    the list returned."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with _locked(path):
        results = []
        if os.path.exists(path):
            with open(path) as fh:
                results = json.load(fh)
        results = [r for r in results if r["name"] != result["name"]] + [result]
        tmp = path + ".tmp"
        with open(tmp, "w") as fh:
            json.dump(results, fh, indent=1)
        os.replace(tmp, path)
    return results


def table(results: list[dict]) -> str:
    def number(value):
        return "–" if value is None else f"{value:.1f}"

    lines = [
        "| agent, task, steps | library (framework) | seed | test score, last epoch (best) "
        "| 10 fixed episodes | seconds (training) | load |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in results:
        score = number(r["test_score"])
        if r["best_test_score"] is not None:
            score += f" ({r['best_test_score']:.1f})"
        lines.append(
            f"| {r['agent']} {r['env']} {r['steps'] // 1000}k | {r['library']} ({r['framework']}) "
            f"| {r['seed']} | {score} | {r['fixed_score']:.1f} "
            f"| {r['seconds']:.0f} ({r['train_seconds']:.0f}) | {r['load']:.1f} |"
        )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> list[dict]:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rows", nargs="+", default=list(ROWS), choices=list(ROWS))
    p.add_argument("--frameworks", nargs="+", default=["jax"])
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--steps", type=int, default=None, help="override every row's budget")
    p.add_argument("--no-peers", action="store_true", help="skip stable-baselines3's runs")
    p.add_argument("--peers-only", action="store_true", help="only stable-baselines3's runs")
    p.add_argument("--results", default=RESULTS)
    p.add_argument("--runs", default=os.path.join("runs", "offpolicy"))
    args = p.parse_args(argv)
    have_sb3 = not args.no_peers
    try:
        import stable_baselines3  # noqa: F401
    except ImportError:
        have_sb3 = False
        print("stable-baselines3 is not installed: its rows are skipped")
    print(f"cores: {os.cpu_count()}, load average at the start: {os.getloadavg()}", flush=True)
    done = []
    for key in args.rows:
        agent, env_id, steps, _ = ROWS[key]
        steps = args.steps or steps
        runs = [] if args.peers_only else [("ivy", fw) for fw in args.frameworks]
        if have_sb3 and agent in SB3_AGENTS:
            runs.append(("sb3", None))
        for library, fw in runs:
            if library == "ivy":
                result = run_ivy(agent, env_id, fw, steps, args.seed, args.runs)
            else:
                result = run_sb3(agent, env_id, steps, args.seed)
            merge(args.results, result)
            done.append(result)
            print(table([result]).splitlines()[-1], flush=True)
    print(table(done))
    print(f"load average at the end: {os.getloadavg()}")
    return done


if __name__ == "__main__":
    main()
