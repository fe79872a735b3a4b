"""ivy_rl's off-policy speed: SAC on Pendulum-v1 with the command line's defaults and one
thread, on torch, jax and tensorflow, against stable-baselines3's SAC with its defaults
(``torch.set_num_threads(1)``), in the same run.

Each library runs in a process of its own, one after the other (a framework's threads are set
before it starts, and the runs do not compete for the cores). Reported per run:

- steps per second after the first update's compilation: environment steps (all workers)
  over the seconds of the epochs after the one holding the first update (ivy_rl: epochs of
  ``--epoch-steps`` steps, without test episodes and checkpoints); stable-baselines3 over the
  same steps (from ``2 * epoch`` to the end, timed by a callback);
- steps per second including it: from the end of the random steps (``update_after``, 1000 for
  both) to the end;
- the ratio of each to stable-baselines3's, and the load average during the run.

Every run starts with empty compilation caches (``TORCHINDUCTOR_CACHE_DIR`` in a new folder;
jax and tensorflow keep none between processes by default), so the figures including the
compilation are those of a first run on a machine.

stable-baselines3 is a benchmark-only peer (``pip install stable-baselines3==2.9.2``); without
it the peer row is skipped and no ratio is given.

Usage:
    python benchmarks/rl_offpolicy_speed.py                   # 4000 steps each (3000 learning)
    python benchmarks/rl_offpolicy_speed.py --steps 8000 --frameworks torch jax
    python benchmarks/rl_offpolicy_speed.py --sb3-same-settings   # also SB3 with our settings

Note that the defaults differ: ivy_rl's command line trains on 8 environments with a 64x64
torso and batches of 128 (its row of Pendulum's task family), stable-baselines3 on one with
256x256 and batches of 256; both make one optimisation step per environment step. The ratios
are against stable-baselines3's defaults (the issue's target); ``--sb3-same-settings`` adds
stable-baselines3 with ivy_rl's settings, for the cost of the same work.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

ENV = "Pendulum-v1"
EPOCH = 1000  # the random steps before the first update (update_after and learning_starts)


def run_ivy(framework: str, steps: int) -> dict:
    """ivy_rl's SAC through the command line (its defaults, --threads 1)."""
    from ivy_rl.train import main

    with tempfile.TemporaryDirectory() as out:
        load = os.getloadavg()[0]
        rows = main(
            ["--agent", "SAC", "--environment", ENV, "-f", framework, "--steps", str(steps),
             "--epoch-steps", str(EPOCH), "--save-steps", str(steps), "--test-episodes", "0",
             "--threads", "1", "--quiet", "--out", os.path.join(out, "run")]
        )  # fmt: skip
        load = (load + os.getloadavg()[0]) / 2
    steps_at = [r["train/steps"] for r in rows]
    seconds = [r["train/epoch_seconds"] for r in rows]
    first_update = next(i for i, r in enumerate(rows) if "critic/loss" in r)
    after = slice(first_update + 1, None)
    including = slice(first_update, None)
    return {
        "library": f"ivy_rl ({framework})",
        "after_compile": (steps_at[-1] - steps_at[first_update]) / sum(seconds[after]),
        "including_compile": (steps_at[-1] - steps_at[first_update - 1]) / sum(seconds[including]),
        "first_update_epoch_seconds": seconds[first_update],
        "load": load,
        "compiles": rows[-1].get("train/compiles"),
    }


def run_sb3(steps: int, same_settings: bool = False) -> dict:
    """stable-baselines3's SAC with its defaults, one thread; with ``same_settings``, with
    ivy_rl's settings for Pendulum (8 environments, a 64x64 torso, batches of 128, learning
    from step 1000, 48 optimisation steps every 48 environment steps, learning rates 1e-3; no
    observation normalisation)."""
    import torch

    torch.set_num_threads(1)
    from stable_baselines3 import SAC
    from stable_baselines3.common.callbacks import BaseCallback
    from stable_baselines3.common.env_util import make_vec_env

    times: dict[int, float] = {}

    class Clock(BaseCallback):
        def _on_step(self) -> bool:
            crossed = self.num_timesteps // EPOCH * EPOCH
            if crossed and crossed not in times and self.num_timesteps - crossed < 8:
                times[crossed] = time.perf_counter()
            return True

    load = os.getloadavg()[0]
    if same_settings:
        model = SAC(
            "MlpPolicy", make_vec_env(ENV, n_envs=8, seed=0), seed=0, verbose=0, device="cpu",
            policy_kwargs={"net_arch": [64, 64]}, batch_size=128, learning_starts=EPOCH,
            train_freq=6, gradient_steps=-1, learning_rate=1e-3,
        )  # fmt: skip
    else:
        model = SAC("MlpPolicy", ENV, seed=0, verbose=0, device="cpu")
    model.learn(total_timesteps=steps, callback=Clock())
    load = (load + os.getloadavg()[0]) / 2
    end = max(times)
    return {
        "library": "stable-baselines3 (torch)"
        + (", ivy_rl's Pendulum settings" if same_settings else ""),
        "after_compile": (end - 2 * EPOCH) / (times[end] - times[2 * EPOCH]),
        "including_compile": (end - EPOCH) / (times[end] - times[EPOCH]),
        "load": load,
    }


def child(which: str, steps: int) -> None:
    if which.startswith("sb3"):
        result = run_sb3(steps, same_settings=which == "sb3-same")
    else:
        result = run_ivy(which, steps)
    print("RESULT " + json.dumps(result))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=4000)
    parser.add_argument("--frameworks", nargs="+", default=["torch", "jax", "tensorflow"])
    parser.add_argument(
        "--sb3-same-settings",
        action="store_true",
        help="also stable-baselines3 with ivy_rl's settings (8 environments, 64x64, batch 128)",
    )
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        child(args.child, args.steps)
        return
    if args.steps < 3 * EPOCH:
        parser.error(f"--steps must be at least {3 * EPOCH}")
    results = []
    try:
        import stable_baselines3  # noqa: F401

        runs = ["sb3", *args.frameworks]
        if args.sb3_same_settings:
            runs.append("sb3-same")
    except ImportError:
        print("stable-baselines3 is not installed: the peer row is skipped", file=sys.stderr)
        runs = list(args.frameworks)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    for which in runs:
        started = time.monotonic()
        cache = tempfile.mkdtemp(prefix="inductor-cache-")
        env = {
            **os.environ,
            "PYTHONPATH": root + os.pathsep + os.environ.get("PYTHONPATH", ""),
            "TORCHINDUCTOR_CACHE_DIR": cache,
        }
        done = subprocess.run(
            [sys.executable, os.path.abspath(__file__), "--child", which, "--steps",
             str(args.steps)],
            capture_output=True, text=True, cwd=root,
            env=env,
        )  # fmt: skip
        shutil.rmtree(cache, ignore_errors=True)
        lines = [x for x in done.stdout.splitlines() if x.startswith("RESULT ")]
        if done.returncode or not lines:
            print(f"{which} failed:\n{done.stderr[-3000:]}", file=sys.stderr)
            continue
        result = json.loads(lines[-1][len("RESULT ") :])
        result["wall_seconds"] = time.monotonic() - started
        results.append(result)
        print(json.dumps(result), file=sys.stderr, flush=True)
    peer = next((r for r in results if r["library"] == "stable-baselines3 (torch)"), None)
    print(f"SAC, {ENV}, {args.steps} steps (learning from step {EPOCH}), one thread each\n")
    print(
        "| library | steps/s after the first compilation | ratio to SB3 | steps/s including "
        "it | ratio to SB3 | load |"
    )
    print("|---|---|---|---|---|---|")
    for r in results:
        ratios = [
            f"{r[k] / peer[k]:.1f}x" if peer else "-"
            for k in ("after_compile", "including_compile")
        ]
        print(
            f"| {r['library']} | {r['after_compile']:.0f} | {ratios[0]} | "
            f"{r['including_compile']:.0f} | {ratios[1]} | {r['load']:.1f} |"
        )


if __name__ == "__main__":
    main()
