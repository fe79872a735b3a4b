"""A run's checkpoints: their format, how they are written and rotated, how they are checked and
read back.

A run folder (``--out``) holds::

    config.json               every setting of the run (ivy_rl.train, ivy_rl.play read it)
    log.csv                   one row per epoch
    checkpoints/step_<n>/     the last ``keep`` checkpoints, n the run's steps when written
        agent/agent.json      the agent's class, settings, random generator, counters
        agent/arrays.npz      weights, optimiser states, normalisers, the replay's filled rows
        trainer.json          the trainer's counters, the epoch in progress, the best score
        workers.npz           the environments' seeds and the actions of their episodes
    best/                     what ``play --best`` needs: the agent with the best test score
        agent/                weights, normalisers and settings (no optimiser states, replay
                              or pending transitions: Agent.save(..., training=False))
        best.json             its steps, epoch and test score

Resuming from a checkpoint continues with the same numbers as a run that was never interrupted,
on any framework (the arrays are numpy's). A checkpoint is written into a hidden folder
(``.step_<n>.partial``) and renamed once complete, so it appears whole or not at all; the last
``keep`` are kept, so that one damaged later (a full disk, a copy cut short) has a predecessor:
:func:`usable_checkpoint` skips damaged ones, naming their files.

Example:
    >>> import ivy_rl
    >>> trainer = ivy_rl.Trainer(steps=400, epoch_steps=200, show_progress=False)
    >>> rows = trainer.run("Uniform", "CartPole-v1", out="runs/uniform")  # a quick baseline run
    finished: 400 steps in ...
    >>> path = usable_checkpoint("runs/uniform"); path
    'runs/uniform/checkpoints/step_400'
    >>> check_checkpoint(path)                          # every file reads
"""

from __future__ import annotations

import glob
import json
import os
import shutil
import zipfile
from collections.abc import Callable
from typing import Any

import numpy as np

__all__ = [
    "RUN_ENTRIES",
    "CheckpointError",
    "checkpoints",
    "latest_checkpoint",
    "check_checkpoint",
    "usable_checkpoint",
    "save_checkpoint",
    "load_checkpoint",
    "save_best",
    "read_json",
    "write_json",
    "prepare_run_folder",
    "write_config",
    "RUN_DEFINING",
]

RUN_ENTRIES = ("config.json", "log.csv", "checkpoints", "best", "tensorboard")
# settings that define a run: resuming it with other values is refused
RUN_DEFINING = (
    "agent",
    "environment",
    "env_kwargs",
    "wrappers",
    "workers",
    "seed",
    "time_feature",
    "dtype",
    "epoch_steps",
    "save_steps",
    "test_episodes",
    "threads",
)


class CheckpointError(ValueError):
    """A checkpoint that cannot be read; the message names the file."""


def _step_of(path: str) -> int:
    try:
        return int(os.path.basename(path).rsplit("_", 1)[1])
    except (IndexError, ValueError):
        return -1


def checkpoints(out: str) -> list[str]:
    """The complete checkpoints of a run (those with ``trainer.json``), oldest first.

    Example:
        >>> import ivy_rl
        >>> trainer = ivy_rl.Trainer(steps=400, epoch_steps=200, show_progress=False)
        >>> rows = trainer.run("Uniform", "CartPole-v1", out="runs/uniform")  # a quick baseline run
        finished: 400 steps in ...
        >>> checkpoints("runs/uniform")                  # one per epoch, the last 2 kept
        ['runs/uniform/checkpoints/step_200', 'runs/uniform/checkpoints/step_400']
    """
    paths = glob.glob(os.path.join(out, "checkpoints", "step_*"))
    paths = [p for p in paths if _step_of(p) >= 0]
    paths = [p for p in paths if os.path.exists(os.path.join(p, "trainer.json"))]
    return sorted(paths, key=_step_of)


def latest_checkpoint(out: str) -> str | None:
    """The folder of the last complete checkpoint of a run (``<out>/checkpoints/step_<n>``), or
    None.

    Example:
        >>> import ivy_rl
        >>> trainer = ivy_rl.Trainer(steps=400, epoch_steps=200, show_progress=False)
        >>> rows = trainer.run("Uniform", "CartPole-v1", out="runs/uniform")  # a quick baseline run
        finished: 400 steps in ...
        >>> latest_checkpoint("runs/uniform")
        'runs/uniform/checkpoints/step_400'
        >>> latest_checkpoint("runs/none") is None
        True
    """
    found = checkpoints(out)
    return found[-1] if found else None


def read_json(path: str) -> Any:
    """A JSON file; :class:`CheckpointError` names it when missing or damaged."""
    try:
        with open(path) as fh:
            return json.load(fh)
    except FileNotFoundError:
        raise CheckpointError(f"{path} is missing") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as error:
        raise CheckpointError(f"{path} is not valid JSON ({error})") from None


def read_npz(path: str) -> dict[str, np.ndarray]:
    """The arrays of an ``.npz`` file; :class:`CheckpointError` names it when missing or
    damaged."""
    try:
        with np.load(path, allow_pickle=False) as data:
            return {key: data[key] for key in data.files}
    except FileNotFoundError:
        raise CheckpointError(f"{path} is missing") from None
    except (zipfile.BadZipFile, ValueError, OSError, EOFError) as error:
        raise CheckpointError(f"{path} is damaged ({type(error).__name__}: {error})") from None


def write_json(path: str, value: Any) -> None:
    """Write ``value`` as JSON (numpy scalars and arrays as numbers and lists, classes by their
    qualified name, other objects as text), making the folder."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "w") as fh:
        json.dump(value, fh, indent=1, default=json_value)


def json_value(value: Any) -> Any:
    """What :func:`write_json` writes for a value JSON does not know."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, type):
        return f"{value.__module__}:{value.__qualname__}"
    return str(value)  # schedules and other settings written as text


def check_checkpoint(path: str) -> None:
    """Read every file of a checkpoint (an agent's folder, or a trainer's checkpoint holding
    ``agent/``); raise :class:`CheckpointError` naming the first file that is missing or
    damaged (truncated arrays, broken JSON).

    Example:
        >>> import ivy_rl
        >>> trainer = ivy_rl.Trainer(steps=400, epoch_steps=200, show_progress=False)
        >>> rows = trainer.run("Uniform", "CartPole-v1", out="runs/uniform")  # a quick baseline run
        finished: 400 steps in ...
        >>> check_checkpoint("runs/uniform/checkpoints/step_400")
        >>> import os
        >>> os.remove("runs/uniform/checkpoints/step_400/agent/arrays.npz")
        >>> check_checkpoint("runs/uniform/checkpoints/step_400")
        Traceback (most recent call last):
        ivy_rl.checkpoints.CheckpointError: runs/uniform/.../step_400/agent/arrays.npz is missing
    """
    agent = os.path.join(path, "agent")
    if os.path.exists(os.path.join(path, "trainer.json")):
        read_json(os.path.join(path, "trainer.json"))
        read_npz(os.path.join(path, "workers.npz"))
    elif not os.path.isdir(agent):
        agent = path
    read_json(os.path.join(agent, "agent.json"))
    read_npz(os.path.join(agent, "arrays.npz"))


def usable_checkpoint(out: str, *, warn: Callable[[str], None] | None = None) -> str | None:
    """The last checkpoint of a run whose files all read (:func:`check_checkpoint`); damaged
    later ones are skipped, each with a message to ``warn``.

    Returns:
        The checkpoint's folder, or None when the run has none.

    Raises:
        CheckpointError: every checkpoint is damaged (naming the files).

    Example:
        >>> import ivy_rl
        >>> trainer = ivy_rl.Trainer(steps=400, epoch_steps=200, show_progress=False)
        >>> rows = trainer.run("Uniform", "CartPole-v1", out="runs/uniform")  # a quick baseline run
        finished: 400 steps in ...
        >>> import os
        >>> os.remove("runs/uniform/checkpoints/step_400/agent/arrays.npz")  # a damaged one
        >>> usable_checkpoint("runs/uniform", warn=print)
        skipping damaged checkpoints (runs/.../step_400/agent/arrays.npz is missing); using step_200
        'runs/uniform/checkpoints/step_200'
    """
    found = checkpoints(out)
    problems = []
    for path in reversed(found):
        try:
            check_checkpoint(path)
        except CheckpointError as error:
            problems.append(str(error))
            continue
        if problems and warn is not None:
            warn(
                f"skipping damaged checkpoints ({'; '.join(problems)}); using "
                f"{os.path.basename(path)}"
            )
        return path
    if problems:
        raise CheckpointError(f"no usable checkpoint in {out}: {'; '.join(problems)}")
    return None


def save_checkpoint(
    out: str,
    steps: int,
    agent: Any,
    workers: Any,
    state: dict[str, Any],
    *,
    keep: int | None = None,
) -> str:
    """Write ``<out>/checkpoints/step_<steps>`` (whole, or not at all) and remove all but the
    last ``keep`` checkpoints.

    Args:
        out: the run's folder.
        steps: the run's steps (the folder's name).
        agent: the agent (its :meth:`save` writes ``agent/``).
        workers: the :class:`~ivy_rl.environments.Workers` (their ``state_dict()``).
        state: the trainer's state (``trainer.json``, JSON-serialisable); the workers' record is
            added under ``'workers'``.
        keep: checkpoints kept (None: all).

    Returns:
        The checkpoint's folder.
    """
    root = os.path.join(out, "checkpoints")
    name = f"step_{int(steps)}"
    path, partial = os.path.join(root, name), os.path.join(root, f".{name}.partial")
    shutil.rmtree(partial, ignore_errors=True)
    agent.save(os.path.join(partial, "agent"))
    arrays, meta = workers.state_dict()
    with open(os.path.join(partial, "workers.npz"), "wb") as fh:
        np.savez(fh, **arrays)
    write_json(os.path.join(partial, "trainer.json"), {**state, "workers": meta})
    shutil.rmtree(path, ignore_errors=True)
    os.replace(partial, path)  # the checkpoint appears complete, or not at all
    if keep is not None:
        for old in checkpoints(out)[:-keep]:
            shutil.rmtree(old, ignore_errors=True)
    return path


def load_checkpoint(path: str, agent: Any, workers: Any) -> tuple[dict[str, Any], np.ndarray]:
    """Load a checkpoint into an initialized agent and running workers.

    Returns:
        The trainer's state (``trainer.json``) and the observations the workers are at.

    Raises:
        CheckpointError: a file is missing or damaged, or the agent cannot load its state.
    """
    state = read_json(os.path.join(path, "trainer.json"))
    agent_path = os.path.join(path, "agent")
    try:
        agent.load(agent_path)
    except (KeyError, OSError, zipfile.BadZipFile, json.JSONDecodeError) as error:
        raise CheckpointError(f"cannot load the agent of {agent_path}: {error}") from None
    arrays = read_npz(os.path.join(path, "workers.npz"))
    observations = workers.load_state_dict(arrays, state["workers"])
    return state, observations


def save_best(out: str, agent: Any, record: dict[str, Any]) -> str:
    """Write ``<out>/best/`` (whole, or not at all): the agent as ``play`` needs it (weights,
    normalisers and settings: ``agent.save(..., training=False)``, without optimiser states,
    replay or pending transitions) and ``best.json`` (``record``).

    Returns:
        The folder.
    """
    best = os.path.join(out, "best")
    partial = os.path.join(out, ".best.partial")
    shutil.rmtree(partial, ignore_errors=True)
    agent.save(os.path.join(partial, "agent"), training=False)
    write_json(os.path.join(partial, "best.json"), record)
    shutil.rmtree(best, ignore_errors=True)
    os.replace(partial, best)
    return best


# ------------------------------------------------------------------------------------------
# The run's folder
# ------------------------------------------------------------------------------------------


def prepare_run_folder(
    out: str | None, resume: bool, overwrite: bool, *, warn: Callable[[str], None] | None = None
) -> str | None:
    """Check a run's folder before anything is built or written: a folder that is not empty is
    refused unless ``resume`` (continue its run) or ``overwrite`` (start again).

    Returns:
        The checkpoint to resume from (``resume``; damaged later ones are skipped, each named to
        ``warn``), else None.
    """
    if resume and overwrite:
        raise ValueError("resume and overwrite exclude each other: continue, or start again")
    if out is None:
        if resume:
            raise ValueError("resume needs the run's folder (out=...)")
        return None
    if os.path.exists(out) and not os.path.isdir(out):
        raise ValueError(f"out={out!r} is a file, not a folder")
    entries = os.listdir(out) if os.path.isdir(out) else []
    if resume:
        checkpoint = usable_checkpoint(out, warn=warn)
        if checkpoint is None:
            raise FileNotFoundError(
                f"cannot resume: no checkpoint in {os.path.join(out, 'checkpoints')}"
            )
        return checkpoint
    if entries and not overwrite:
        what = [e for e in entries if e in RUN_ENTRIES] or sorted(entries)[:5]
        raise ValueError(
            f"the output folder {out!r} is not empty ({', '.join(sorted(what))}): pass "
            "--resume to continue its run, --overwrite to start again there, or choose "
            "another --out"
        )
    return None


def write_config(out: str, record: dict[str, Any], *, resume: bool, overwrite: bool) -> None:
    """Write ``<out>/config.json``; resuming, refuse settings that differ from the saved run's
    (:data:`RUN_DEFINING`); overwriting, remove the run's entries first."""
    path = os.path.join(out, "config.json")
    if resume and os.path.exists(path):
        saved = read_json(path)
        differ = [
            f"{key}: this run {record[key]!r}, the saved run {saved[key]!r}"
            for key in RUN_DEFINING
            if saved.get(key) is not None and _same(key, saved[key], record[key]) is False
        ]
        if differ:
            raise ValueError(
                f"cannot resume the run in {out!r} with other settings ({'; '.join(differ)})"
            )
    if overwrite:
        for entry in (*RUN_ENTRIES, ".best.partial"):
            target = os.path.join(out, entry)
            if os.path.isdir(target):
                shutil.rmtree(target)
            elif os.path.exists(target):
                os.remove(target)
    os.makedirs(out, exist_ok=True)
    write_json(path, record)


def _same(key: str, saved: Any, value: Any) -> bool:
    if key == "agent":
        return str(saved).lower() == str(value).lower()
    return _jsonable(saved) == _jsonable(value)


def _jsonable(value: Any) -> Any:
    return json.loads(json.dumps(value, default=json_value))
