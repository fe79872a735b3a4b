"""Environment steps per second of the trainer's workers (``ivy_rl.environments.Workers``, the
object the trainer steps, resets and records), random actions, one thread:

- ``batched``: ivy_gym's task, every worker in one batched, compiled call of the physics
  (``--vectorization batched``), at several worker counts;
- ``sync``: the same ivy_gym task, one facade per worker (``--vectorization sync``);
- ``gymnasium``: Gymnasium's own MuJoCo task (MuJoCo in C), one environment per worker, as the
  trainer runs it by default.

Each configuration first runs ``--warmup`` steps (compilation included, reported), then the
configurations take turns for ``--repeats`` rounds of ``--steps`` worker steps each; the best
round is reported, in environment steps (worker steps times workers) per second.

Usage:
    .venv/bin/python benchmarks/rl_batched_workers.py [--task Ant-v5] [--framework jax]
        [--batched 64,256,1024] [--sync 8] [--steps 20] [--repeats 3]
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--task", default="Ant-v5")
    parser.add_argument("--framework", default="jax")
    parser.add_argument("--batched", default="64,256,1024")
    parser.add_argument("--sync", type=int, default=8)
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--warmup", type=int, default=3)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    import ivy

    ivy.set_threads(args.framework, 1)
    from ivy_rl.environments import Workers

    kwargs = {"framework": args.framework}
    configs = {f"gymnasium {args.task}, {args.sync} sync": (args.task, args.sync, "sync", {})}
    configs[f"ivy_gym {args.task}, {args.sync} sync"] = (
        f"ivy_gym/{args.task}",
        args.sync,
        "sync",
        kwargs,
    )
    for count in (int(n) for n in args.batched.split(",")):
        configs[f"ivy_gym {args.task}, {count} batched"] = (
            f"ivy_gym/{args.task}",
            count,
            "batched",
            kwargs,
        )
    workers, rngs = {}, {}
    for name, (env_id, count, mode, env_kwargs) in configs.items():
        began = time.perf_counter()
        workers[name] = Workers(env_id, count, seed=0, vectorization=mode, env_kwargs=env_kwargs)
        workers[name].start()
        rngs[name] = np.random.default_rng(0)
        for _ in range(args.warmup):
            workers[name].step(_actions(workers[name], rngs[name]))
        print(f"{name}: ready in {time.perf_counter() - began:.1f} s", flush=True)
    best = {name: 0.0 for name in configs}
    for _ in range(args.repeats):
        for name, w in workers.items():
            actions = [_actions(w, rngs[name]) for _ in range(args.steps)]
            began = time.perf_counter()
            for a in actions:
                w.step(a)
            rate = args.steps * w.num_workers / (time.perf_counter() - began)
            best[name] = max(best[name], rate)
    base = best[f"gymnasium {args.task}, {args.sync} sync"]
    print(f"{'workers':40} {'steps/s':>10} {'x Gymnasium':>12}")
    for name, rate in best.items():
        print(f"{name:40} {rate:10.0f} {rate / base:12.2f}")
    for w in workers.values():
        w.close()


def _actions(workers, rng) -> np.ndarray:
    space = workers.action_space
    low, high = space.low, space.high
    return (low + (high - low) * rng.random((workers.num_workers, *low.shape))).astype(space.dtype)


if __name__ == "__main__":
    main()
