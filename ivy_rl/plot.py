"""``python -m ivy_rl.plot``: learning curves of runs, the mean and the spread over seeds.

Runs are grouped by their folder name without a trailing ``-<seed>`` (or by ``--labels``); each
group is drawn as its mean over runs with the min-max band, against ``train/steps``.

Example:
    python -m ivy_rl.plot runs/ppo-cartpole-0 runs/ppo-cartpole-1 runs/a2c-cartpole-0 \\
        --out curves.png
"""

from __future__ import annotations

import argparse
import os
import re
from collections.abc import Sequence
from typing import Any

import numpy as np

from ivy_rl import _cli
from ivy_rl.logger import read_log

__all__ = ["main", "plot", "group_runs"]


def group_runs(paths: Sequence[str]) -> dict[str, list[str]]:
    """Run folders grouped by name less a trailing ``-<number>`` (the seed).

    Example:
        >>> group_runs(["runs/ppo-0", "runs/ppo-1"])
        {'ppo': ['runs/ppo-0', 'runs/ppo-1']}
    """
    groups: dict[str, list[str]] = {}
    for path in paths:
        name = os.path.basename(os.path.normpath(path))
        groups.setdefault(re.sub(r"-\d+$", "", name), []).append(path)
    return groups


def plot(
    paths: Sequence[str],
    out: str,
    *,
    y: str = "test/episode_score/mean",
    x: str = "train/steps",
    labels: Sequence[str] | None = None,
    title: str | None = None,
) -> dict[str, Any]:
    """Draw the curves of ``y`` against ``x`` for the runs in ``paths`` into the image ``out``.

    Args:
        paths: run folders (each with a ``log.csv``).
        out: image file (``.png``, ``.pdf``, ``.svg``).
        y, x: columns of ``log.csv``.
        labels: one label per run (runs with the same label are averaged); default: by folder.
        title: the figure's title.

    Returns:
        ``{label: (x, mean, low, high)}`` of the curves drawn.

    Example:
        Two seeds of a quick baseline run, averaged into one curve (``-0`` and ``-1``, the
        seeds, are one label):

        >>> import ivy_rl
        >>> for seed in (0, 1):
        ...     trainer = ivy_rl.Trainer(steps=400, epoch_steps=200, show_progress=False)
        ...     rows = trainer.run("Uniform", "CartPole-v1", seed=seed, out=f"runs/uniform-{seed}")
        finished: 400 steps in ...
        finished: 400 steps in ...
        >>> curves = plot(["runs/uniform-0", "runs/uniform-1"], "curves.png")
        >>> steps, mean, low, high = curves["uniform"]
        >>> steps, mean
        (array([200., 400.]), array([23.5, 22.5]))
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    for path in paths:
        if not os.path.isdir(path):
            raise FileNotFoundError(f"no run folder {path!r}: it does not exist")
        if not os.path.exists(os.path.join(path, "log.csv")):
            raise FileNotFoundError(
                f"{path!r} is not a run folder: it has no log.csv (python -m ivy_rl.train "
                "--out <folder> writes one)"
            )
    if labels is not None:
        if len(labels) != len(paths):
            raise ValueError(f"{len(labels)} labels for {len(paths)} runs")
        groups: dict[str, list[str]] = {}
        for label, path in zip(labels, paths):
            groups.setdefault(label, []).append(path)
    else:
        groups = group_runs(paths)
    curves = {}
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, runs in groups.items():
        logs = [read_log(os.path.join(p, "log.csv")) for p in runs]
        series = []
        for rows in logs:
            points = [(r[x], r[y]) for r in rows if x in r and y in r]
            if not points:
                raise ValueError(
                    f"no column {y!r} against {x!r} in a log of {label!r} (a run without test "
                    "episodes has no test/ columns: choose --y train/episode_score/mean)"
                )
            series.append(np.asarray(points))
        grid = np.unique(np.concatenate([s[:, 0] for s in series]))
        values = np.stack([np.interp(grid, s[:, 0], s[:, 1]) for s in series])
        mean, low, high = values.mean(axis=0), values.min(axis=0), values.max(axis=0)
        ax.plot(grid, mean, label=f"{label} ({len(runs)} run{'s' if len(runs) > 1 else ''})")
        ax.fill_between(grid, low, high, alpha=0.2)
        curves[label] = (grid, mean, low, high)
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    if title:
        ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return curves


def main(argv: list[str] | None = None) -> dict[str, Any]:
    p = argparse.ArgumentParser(prog="python -m ivy_rl.plot", description=__doc__.split("\n")[0])
    p.add_argument("runs", nargs="+", help="run folders")
    p.add_argument("--out", default="curves.png")
    p.add_argument("--y", default="test/episode_score/mean")
    p.add_argument("--x", default="train/steps")
    p.add_argument("--labels", nargs="+", default=None)
    p.add_argument("--title", default=None)
    args = p.parse_args(argv)
    curves = plot(args.runs, args.out, y=args.y, x=args.x, labels=args.labels, title=args.title)
    print(f"wrote {args.out} ({len(curves)} curve{'s' if len(curves) > 1 else ''})")
    return curves


if __name__ == "__main__":
    _cli.command_line(main)
