"""``python -m ivy_rl.train``: train an agent on a Gymnasium environment.

Example:
    python -m ivy_rl.train --agent PPO --environment CartPole-v1 --framework torch \\
        --steps 100000 --seed 0 --out runs/ppo-cartpole \\
        --agent-kwargs '{"segment_size": 32, "batch_size": 256, "epochs": 20}'

The run's folder gets ``config.json`` (the command's settings, read by ``ivy_rl.play`` and by
``--resume``), ``log.csv`` (one row per epoch), ``checkpoints/`` and, with ``--tensorboard``,
``tensorboard/``. ``--resume`` continues from the last checkpoint, on any framework.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from typing import Any

__all__ = ["main", "parse_args"]


def _json(text: str) -> dict[str, Any]:
    try:
        value = json.loads(text)
    except json.JSONDecodeError as error:
        raise argparse.ArgumentTypeError(f"not valid JSON ({error}): {text!r}") from None
    if not isinstance(value, dict):
        raise argparse.ArgumentTypeError(f"expected a JSON object {{...}}, got {text!r}")
    return value


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line's settings."""
    p = argparse.ArgumentParser(prog="python -m ivy_rl.train", description=__doc__.split("\n")[0])
    p.add_argument("--agent", default="PPO", help="A2C, PPO, TRPO, Uniform or Constant")
    p.add_argument("--agent-kwargs", type=_json, default={}, help="agent settings as JSON")
    p.add_argument("--environment", "--env", default="CartPole-v1", help="a Gymnasium id")
    p.add_argument("--env-kwargs", type=_json, default={}, help="gymnasium.make kwargs as JSON")
    p.add_argument("--framework", "-f", default="torch", help="torch, jax or tensorflow")
    p.add_argument("--dtype", default="float32", choices=("float32", "float64"))
    p.add_argument("--steps", type=int, default=100_000)
    p.add_argument("--epoch-steps", type=int, default=None)
    p.add_argument("--save-steps", type=int, default=None)
    p.add_argument("--test-episodes", type=int, default=5)
    p.add_argument("--workers", type=int, default=8, help="parallel environments")
    p.add_argument(
        "--vectorization",
        default="sync",
        choices=("sync", "async", "ray"),
        help="environment workers: one process, subprocesses, or Ray actors",
    )
    p.add_argument(
        "--ray-groups", type=int, default=None, help="Ray actors (with --vectorization ray)"
    )
    p.add_argument("--time-feature", action="store_true", help="append the remaining time")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument(
        "--out", default=None, help="the run's folder (default: runs/<agent>-<env>-<seed>)"
    )
    p.add_argument("--eager", action="store_true", help="do not compile the agent's functions")
    p.add_argument("--tensorboard", action="store_true", help="also log to TensorBoard")
    p.add_argument("--resume", action="store_true", help="continue from the last checkpoint")
    p.add_argument("--quiet", action="store_true", help="no progress bar or table")
    return p.parse_args(argv)


def _enable_float64(framework: str, dtype: str) -> None:
    if dtype == "float64" and framework == "jax":
        import jax

        jax.config.update("jax_enable_x64", True)


def main(argv: list[str] | None = None) -> list[dict[str, Any]]:
    """Run the command; returns the log's rows.

    Example:
        >>> main(["--agent", "A2C", "--steps", "2000", "--out", "runs/a2c"])
    """
    args = parse_args(argv)
    from ivy_rl.agents import make
    from ivy_rl.environments import check_environment_id
    from ivy_rl.trainer import Trainer

    agent = make(args.agent, **args.agent_kwargs)  # unknown agents fail before any work
    check_environment_id(args.environment)
    out = args.out or os.path.join(
        "runs", f"{args.agent}-{args.environment}-{args.seed}".replace("/", "_")
    )
    config = {k: v for k, v in vars(args).items() if k not in ("resume", "quiet")}
    config["out"] = out
    if args.resume:
        with open(os.path.join(out, "config.json")) as fh:
            saved = json.load(fh)
        for key in (
            "agent",
            "agent_kwargs",
            "environment",
            "env_kwargs",
            "workers",
            "seed",
            "time_feature",
            "dtype",
        ):
            if saved.get(key) != config.get(key):
                raise ValueError(
                    f"--resume: {key} is {config.get(key)!r} but the run {out!r} used "
                    f"{saved.get(key)!r}"
                )
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "config.json"), "w") as fh:
        json.dump(config, fh, indent=1)
    _enable_float64(args.framework, args.dtype)
    trainer = Trainer(
        args.steps,
        epoch_steps=args.epoch_steps,
        save_steps=args.save_steps,
        test_episodes=args.test_episodes,
        show_progress=not args.quiet,
        tensorboard=args.tensorboard,
    )
    return trainer.run(
        agent,
        args.environment,
        workers=args.workers,
        seed=args.seed,
        f=args.framework,
        dtype=args.dtype,
        compile=not args.eager,
        vectorization=args.vectorization,
        env_kwargs=args.env_kwargs,
        time_feature=args.time_feature,
        ray_groups=args.ray_groups,
        out=out,
        resume=args.resume,
    )


if __name__ == "__main__":
    import ivy

    try:
        main()
    except (ValueError, TypeError, FileNotFoundError, ivy.errors.IvyError) as error:
        print(f"error: {error}", file=sys.stderr)
        raise SystemExit(2) from None
