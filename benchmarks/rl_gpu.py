"""PPO on N ivy_gym Pendulums on one device (default 4,096 on jax): environment steps per
second and the time to a fixed test score, against the same agent on the CPU, in one run.

The agent is ``ivy_rl.agents.make("PPO", environment="ivy_gym/Pendulum-v1", segment_size=...,
batch_size=...)`` (the ivy_gym family's defaults but a short segment and large mini-batches, so
that N environments update often), trained by ``ivy_rl.Trainer`` on ``workers`` environments of ivy_gym's native
vector env; ``device=`` places the agent's models, optimiser states and each update's segment.
Both runs (``--device`` and ``cpu``) use the same seed, steps and epochs. Reported per device:
environment steps per second (``train/steps_per_second`` of the last epoch, so after
compilation), the training seconds, the first epoch whose mean test score reaches ``--score``
and the training seconds until then; then the ratios device / CPU.

Usage: python benchmarks/rl_gpu.py [--device gpu:0] [--workers 4096] [--steps 4194304]
       [--epochs 8] [--score -400] [--framework jax] [--segment-size 32] [--batch-size 2048]
       [--no-cpu-peer]
"""

from __future__ import annotations

import argparse
import warnings

import ivy_gym.gymnasium  # noqa: F401  (registers the ivy_gym/... ids)
import ivy_rl
from ivy_rl.agents import make

warnings.filterwarnings("ignore")
ENV = "ivy_gym/Pendulum-v1"


def train(device: str, args) -> dict:
    """One PPO run on ``device``: steps/s, seconds, the first epoch reaching the score."""
    agent = make("PPO", environment=ENV, segment_size=args.segment_size, batch_size=args.batch_size)
    trainer = ivy_rl.Trainer(
        steps=args.steps,
        epoch_steps=args.steps // args.epochs,
        test_episodes=args.test_episodes,
        show_progress=False,
    )
    rows = trainer.run(agent, ENV, workers=args.workers, seed=0, f=args.framework, device=device)
    reached, seconds = None, None
    for row in rows:
        if row.get("test/episode_score/mean", float("-inf")) >= args.score:
            reached, seconds = int(row["train/epochs"]), float(row["train/seconds"])
            break
    last = rows[-1]
    return {
        "steps/s": float(last["train/steps_per_second"]),
        "seconds": float(last["train/seconds"]),
        "score": float(last.get("test/episode_score/mean", float("nan"))),
        "epoch": reached,
        "to score": seconds,
    }


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--device", default="cpu", help="'cpu' or 'gpu:0' (CUDA)")
    parser.add_argument("--framework", default="jax")
    parser.add_argument("--workers", type=int, default=4096)
    parser.add_argument("--steps", type=int, default=4096 * 1024)
    parser.add_argument("--epochs", type=int, default=8)
    parser.add_argument("--test-episodes", type=int, default=5)
    parser.add_argument("--score", type=float, default=-400.0, help="the fixed test score")
    parser.add_argument(
        "--segment-size",
        type=int,
        default=32,
        help="steps per worker per update (the ivy_gym "
        "family's 256 would give one update per million steps at 4,096 workers)",
    )
    parser.add_argument("--batch-size", type=int, default=2048, help="PPO's mini-batch size")
    parser.add_argument("--no-cpu-peer", action="store_true", help="skip the run on the CPU")
    args = parser.parse_args(argv)

    devices = [args.device] + ([] if args.no_cpu_peer or args.device == "cpu" else ["cpu"])
    print(
        f"PPO on {args.workers} {ENV} ({args.framework}), {args.steps} steps in "
        f"{args.epochs} epochs; fixed score {args.score}"
    )
    print(f"{'device':8} {'steps/s':>10} {'seconds':>9} {'last score':>10} "
          f"{'epoch>=score':>12} {'s to score':>10}")  # fmt: skip
    results = {}
    for device in devices:  # each row printed as soon as it is measured
        r = results[device] = train(device, args)
        to = f"{r['to score']:10.1f}" if r["to score"] is not None else f"{'-':>10}"
        epoch = f"{r['epoch']:12d}" if r["epoch"] is not None else f"{'not reached':>12}"
        print(
            f"{device:8} {r['steps/s']:10.0f} {r['seconds']:9.1f} {r['score']:10.1f} {epoch} {to}"
        )
    if len(results) == 2:
        dev, cpu = results[args.device], results["cpu"]
        print(f"{args.device} / cpu steps per second: {dev['steps/s'] / cpu['steps/s']:.2f}")
        if dev["to score"] is not None and cpu["to score"] is not None:
            print(f"cpu / {args.device} time to score: {cpu['to score'] / dev['to score']:.2f}")


if __name__ == "__main__":
    main()
