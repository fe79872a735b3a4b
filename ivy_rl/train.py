"""``python -m ivy_rl.train``: train an agent on a Gymnasium environment.

Example:
    python -m ivy_rl.train --agent PPO --environment CartPole-v1 --framework torch \\
        --steps 100000 --seed 0 --out runs/ppo-cartpole \\
        --agent-kwargs '{"segment_size": 32, "batch_size": 256, "epochs": 20}'
    python -m ivy_rl.train --out runs/ppo-cartpole --resume       # continue it as configured
    python -m ivy_rl.train --out runs/ppo-cartpole --resume --steps 200000 -f jax

The run's folder gets ``config.json`` (every setting used, read by ``ivy_rl.play`` and by
``--resume``), ``log.csv`` (one row per epoch), ``checkpoints/`` (the last
``--keep-checkpoints``), ``best/`` (the agent with the best test score) and, with
``--tensorboard``, ``tensorboard/``. Every setting is checked before anything is written. A
folder that is not empty is refused unless ``--resume`` (continue its run) or ``--overwrite``
(start again). ``--resume`` takes the run's settings from its ``config.json``; an explicit flag
may change only ``--steps``, ``--framework``, ``--device``, ``--vectorization``,
``--ray-groups``, ``--eager``, ``--tensorboard``, ``--keep-checkpoints`` and ``--quiet``, and
any other flag that contradicts the saved run is an error (``--threads`` included: a resumed run
keeps its threads).

The agent takes the defaults of the environment's task family (:mod:`ivy_rl.agents.defaults`),
then ``--agent-kwargs``; under the start line, a new run lists where the family's defaults differ
from the agent class's own (``SAC()``'s; ``python -m ivy_rl.agents.defaults SAC Pendulum-v1``
shows every setting).
"""

from __future__ import annotations

import argparse
import json
import os
from typing import Any

from ivy_rl import _cli

__all__ = ["main", "parse_args", "DEFAULTS", "CHANGEABLE_ON_RESUME"]

DEFAULTS: dict[str, Any] = {
    "agent": "PPO",
    "agent_kwargs": {},
    "environment": "CartPole-v1",
    "env_kwargs": {},
    "wrappers": [],
    "framework": "torch",
    "dtype": "float32",
    "device": None,
    "steps": 100_000,
    "epoch_steps": None,
    "save_steps": None,
    "test_episodes": 5,
    "keep_checkpoints": 2,
    "workers": 8,
    "vectorization": "sync",
    "ray_groups": None,
    "time_feature": False,
    "seed": 0,
    "out": None,
    "eager": False,
    "tensorboard": False,
    "resume": False,
    "overwrite": False,
    "quiet": False,
    "threads": 1,
}
# what a resumed run may change; every other setting comes from its config.json
CHANGEABLE_ON_RESUME = (
    "steps",
    "framework",
    "device",
    "vectorization",
    "ray_groups",
    "eager",
    "tensorboard",
    "keep_checkpoints",
    "quiet",
    "out",
    "resume",
)


def _json(text: str) -> dict[str, Any]:
    try:
        value = json.loads(text)
    except json.JSONDecodeError as error:
        raise argparse.ArgumentTypeError(f"not valid JSON ({error}): {text!r}") from None
    if not isinstance(value, dict):
        raise argparse.ArgumentTypeError(f"expected a JSON object {{...}}, got {text!r}")
    return value


def _parser() -> argparse.ArgumentParser:
    """The parser; flags that are not given are absent from its namespace."""
    p = argparse.ArgumentParser(
        prog="python -m ivy_rl.train",
        description=__doc__.split("\n")[0],
        argument_default=argparse.SUPPRESS,
    )
    p.add_argument("--agent", help="a name of ivy_rl.agents.AGENTS (default PPO)")
    p.add_argument("--agent-kwargs", type=_json, help="agent settings as JSON")
    p.add_argument(
        "--environment", "--env", help="a Gymnasium id, or module:EnvId (default CartPole-v1)"
    )
    p.add_argument("--env-kwargs", type=_json, help="gymnasium.make kwargs as JSON")
    p.add_argument(
        "--wrappers",
        nargs="+",
        metavar="WRAPPER",
        help="Gymnasium wrappers by name (FlattenObservation, or package.module:Class)",
    )
    p.add_argument("--framework", "-f", help="torch, jax or tensorflow (default torch)")
    p.add_argument("--dtype", choices=("float32", "float64"))
    p.add_argument("--device", help="where the agent's arrays live: cpu, gpu:0 ...")
    p.add_argument("--steps", type=int, help="environment steps (default 100000)")
    p.add_argument("--epoch-steps", type=int, help="steps per epoch (default steps / 20)")
    p.add_argument("--save-steps", type=int, help="steps between checkpoints (default: epoch)")
    p.add_argument("--test-episodes", type=int, help="test episodes per epoch (default 5)")
    p.add_argument("--keep-checkpoints", type=int, help="checkpoints kept (default 2)")
    p.add_argument("--workers", type=int, help="parallel environments (default 8)")
    p.add_argument(
        "--vectorization",
        choices=("sync", "async", "ray", "batched"),
        help="environment workers: one process, subprocesses, Ray actors, or (ivy_gym) one "
        "batched call",
    )
    p.add_argument("--ray-groups", type=int, help="Ray actors (with --vectorization ray)")
    p.add_argument(
        "--time-feature",
        action="store_true",
        help="the remaining time is an input and time limits are terminal (default: time "
        "limits are bootstrapped through)",
    )
    p.add_argument("--seed", type=int)
    p.add_argument(
        "--out", help="the run's folder (default: runs/<agent>-<env>-<framework>-<seed>)"
    )
    p.add_argument("--eager", action="store_true", help="do not compile the agent's functions")
    p.add_argument("--tensorboard", action="store_true", help="also log to TensorBoard")
    p.add_argument("--resume", action="store_true", help="continue the run in --out")
    p.add_argument("--overwrite", action="store_true", help="start again in a used --out")
    p.add_argument(
        "--quiet", action="store_true", help="print only the summary (no progress bar or table)"
    )
    p.add_argument(
        "--threads",
        type=int,
        help="intra-op threads of the framework (default 1: fastest for small models)",
    )
    return p


def _explicit(argv: list[str] | None) -> dict[str, Any]:
    return vars(_parser().parse_args(argv))


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line's settings, with the defaults for those not given (without the saved
    settings that ``--resume`` reads)."""
    return argparse.Namespace(**{**DEFAULTS, **_explicit(argv)})


def _flag(key: str) -> str:
    return "--" + key.replace("_", "-")


def _default_out(settings: dict[str, Any]) -> str:
    """``runs/<agent>-<environment>-<framework>-<seed>``: a run on each framework has its own."""
    name = "-".join(str(settings[key]) for key in ("agent", "environment", "framework", "seed"))
    return os.path.join("runs", name.replace("/", "_").replace(":", "_"))


def _run_on_another_framework(settings: dict[str, Any]) -> str | None:
    """The default folder of the same run on another framework, when exactly one exists (a run
    resumed with ``--framework`` and no ``--out`` continues there)."""
    found = [
        path
        for framework in ("torch", "jax", "tensorflow", "numpy")
        if framework != settings["framework"]
        and os.path.isdir(path := _default_out({**settings, "framework": framework}))
    ]
    return found[0] if len(found) == 1 else None


def _resumed(explicit: dict[str, Any], out: str) -> dict[str, Any]:
    """The saved run's settings, with the explicit flags that may change on resume."""
    saved = _cli.read_config(out)
    problems = []
    for key, value in explicit.items():
        if key in CHANGEABLE_ON_RESUME or key not in saved or saved[key] is None:
            continue
        same = (
            str(saved[key]).lower() == str(value).lower()
            if key == "agent"
            else json.loads(json.dumps(saved[key])) == json.loads(json.dumps(value))
        )
        if not same:
            problems.append(f"{_flag(key)} {value!r} (the run has {saved[key]!r})")
    if problems:
        raise ValueError(
            f"--resume continues the run in {out!r} as it was configured; these flags contradict "
            f"it: {'; '.join(problems)}. Leave them out, or start a new run (another --out, or "
            "--overwrite)"
        )
    settings = {**DEFAULTS, **{k: v for k, v in saved.items() if k in DEFAULTS}}
    if isinstance(saved.get("agent_config"), dict):
        settings["agent_config"] = saved["agent_config"]
    settings.update({k: v for k, v in explicit.items() if k in CHANGEABLE_ON_RESUME})
    return settings


def _check(settings: dict[str, Any]) -> None:
    """Every setting, before anything is written; each error names its flag."""
    for key, minimum in (
        ("steps", 1),
        ("epoch_steps", 1),
        ("save_steps", 1),
        ("test_episodes", 0),
        ("keep_checkpoints", 1),
        ("workers", 1),
        ("ray_groups", 1),
        ("seed", 0),
        ("threads", 1),
    ):
        value = settings[key]
        if value is None and key in ("epoch_steps", "save_steps", "ray_groups"):
            continue
        if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
            raise ValueError(f"{_flag(key)} must be an integer >= {minimum}, got {value!r}")
    workers, steps = settings["workers"], settings["steps"]
    if steps % workers and not _simulates(settings["agent"]):
        low = steps - steps % workers
        options = " or ".join(str(n) for n in (low, low + workers) if n)
        raise ValueError(
            f"--steps {steps} is not a multiple of --workers {workers} (each step of the workers "
            f"is {workers} environment steps, and a run stops exactly at --steps): use {options}"
        )
    if settings["ray_groups"] is not None:
        if settings["vectorization"] != "ray":
            raise ValueError("--ray-groups needs --vectorization ray")
        if settings["ray_groups"] > settings["workers"]:
            raise ValueError(
                f"--ray-groups {settings['ray_groups']} exceeds --workers {settings['workers']}"
            )
    for key in ("agent_kwargs", "env_kwargs"):
        if not isinstance(settings[key], dict):
            raise ValueError(f"{_flag(key)} must be a JSON object, got {settings[key]!r}")
    _cli.check_framework(settings["framework"], settings["dtype"])
    _cli.check_device(settings["device"], settings["framework"])

    from ivy_rl.environments import check_environment_id, resolve_wrappers

    check_environment_id(settings["environment"])
    resolve_wrappers(settings["wrappers"])


def _simulates(agent: str) -> bool:
    """Whether the agent counts steps of its own rollouts (its steps need not be whole steps of
    the workers)."""
    from ivy_rl.agents import AGENTS

    cls = {name.lower(): cls for name, cls in AGENTS.items()}.get(str(agent).lower())
    return bool(getattr(cls, "differentiable", False))


def main(argv: list[str] | None = None) -> list[dict[str, Any]]:
    """Run the command; returns the log's rows.

    Example:
        ``python -m ivy_rl.train --agent A2C ...`` from Python, in a short run (CartPole-v1,
        the default environment, takes about ``--steps 100000`` to learn):

        >>> rows = main(["--agent", "A2C", "--framework", "jax", "--steps", "2000",
        ...              "--epoch-steps", "1000", "--test-episodes", "1", "--quiet",
        ...              "--out", "runs/a2c"])
        finished: 2,000 steps in ...
        >>> rows[-1]["train/steps"]
        2000
    """
    explicit = _explicit(argv)
    if explicit.get("resume") and explicit.get("overwrite"):
        raise ValueError("--resume continues a run and --overwrite starts again: choose one")
    settings = {**DEFAULTS, **explicit}
    out = settings["out"] or _default_out(settings)
    if settings["resume"] and not settings["out"] and not os.path.isdir(out):
        out = _run_on_another_framework(settings) or out
    if settings["resume"]:
        settings = _resumed(explicit, out)
    settings["out"] = out
    _check(settings)

    from ivy_rl.agents import make
    from ivy_rl.console import family_defaults
    from ivy_rl.trainer import Trainer

    # the defaults of the environment's task family, then the user's settings, each checked;
    # a resumed run is rebuilt with every value it used (its config.json's agent_config)
    agent_settings = settings.get("agent_config") or settings["agent_kwargs"]
    agent = make(settings["agent"], environment=settings["environment"], **agent_settings)
    trainer = Trainer(
        settings["steps"],
        epoch_steps=settings["epoch_steps"],
        save_steps=settings["save_steps"],
        test_episodes=settings["test_episodes"],
        keep_checkpoints=settings["keep_checkpoints"],
        show_progress=not settings["quiet"],
        tensorboard=settings["tensorboard"],
        threads=settings["threads"],
    )
    _cli.enable_float64(settings["framework"], settings["dtype"])
    record = {"agent": settings["agent"], "agent_kwargs": settings["agent_kwargs"], "out": out}
    return trainer.run(
        agent,
        settings["environment"],
        workers=settings["workers"],
        seed=settings["seed"],
        f=settings["framework"],
        dtype=settings["dtype"],
        device=settings["device"],
        compile=not settings["eager"],
        vectorization=settings["vectorization"],
        env_kwargs=settings["env_kwargs"],
        time_feature=settings["time_feature"],
        wrappers=settings["wrappers"],
        ray_groups=settings["ray_groups"],
        out=out,
        resume=settings["resume"],
        overwrite=settings["overwrite"],
        config=record,
        # where the family's defaults, taken here, differ from the class's own (SAC()'s)
        notes=family_defaults(
            settings["agent"], settings["environment"], given=settings["agent_kwargs"]
        ),
    )


if __name__ == "__main__":
    _cli.command_line(main)
