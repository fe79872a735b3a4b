"""The trainer: steps the environments, hands the agent observations, rewards, resets and
terminations, runs test episodes each epoch on an environment of their own, logs, keeps the best
model, and saves checkpoints that resume exactly.

A checkpoint (``<out>/checkpoints/step_<steps>/``) holds the agent's whole state (weights,
optimiser states, normalisers, replay, random generator) and the trainer's (counters, the
environments' seeds and the actions of their current episodes, which bring the environments
back to the same state). Resuming therefore continues with the same numbers as a run that was
never interrupted, and a checkpoint written on one framework continues on another. A checkpoint
is written into a hidden folder and renamed once complete; the last ``keep_checkpoints`` are
kept, so that a checkpoint damaged later (a full disk, a copy cut short) has a predecessor to
resume from. The agent with the best mean test score so far is kept in ``<out>/best/``.

Example:
    >>> trainer = Trainer(steps=100_000, epoch_steps=10_000)
    >>> rows = trainer.run("PPO", "CartPole-v1", workers=8, seed=0, f="torch", out="runs/ppo")
"""

from __future__ import annotations

import glob
import importlib
import json
import os
import shutil
import time
import zipfile
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

import ivy
from ivy_rl.agents import Agent, make
from ivy_rl.environments import Workers, make_env
from ivy_rl.logger import Logger

__all__ = [
    "Trainer",
    "CheckpointError",
    "checkpoints",
    "check_checkpoint",
    "latest_checkpoint",
    "usable_checkpoint",
    "RUN_ENTRIES",
    "set_threads",
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
        >>> checkpoints("runs/ppo")
        ['runs/ppo/checkpoints/step_90000', 'runs/ppo/checkpoints/step_100000']
    """
    paths = glob.glob(os.path.join(out, "checkpoints", "step_*"))
    paths = [p for p in paths if _step_of(p) >= 0]
    paths = [p for p in paths if os.path.exists(os.path.join(p, "trainer.json"))]
    return sorted(paths, key=_step_of)


def latest_checkpoint(out: str) -> str | None:
    """The folder of the last complete checkpoint of a run (``<out>/checkpoints/step_<n>``), or
    None.

    Example:
        >>> latest_checkpoint("runs/ppo")
        'runs/ppo/checkpoints/step_100000'
    """
    found = checkpoints(out)
    return found[-1] if found else None


def _read_json(path: str) -> Any:
    try:
        with open(path) as fh:
            return json.load(fh)
    except FileNotFoundError:
        raise CheckpointError(f"{path} is missing") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as error:
        raise CheckpointError(f"{path} is not valid JSON ({error})") from None


def _read_npz(path: str) -> dict[str, np.ndarray]:
    try:
        with np.load(path, allow_pickle=False) as data:
            return {key: data[key] for key in data.files}
    except FileNotFoundError:
        raise CheckpointError(f"{path} is missing") from None
    except (zipfile.BadZipFile, ValueError, OSError, EOFError) as error:
        raise CheckpointError(f"{path} is damaged ({type(error).__name__}: {error})") from None


def check_checkpoint(path: str) -> None:
    """Read every file of a checkpoint (an agent's folder, or a trainer's checkpoint holding
    ``agent/``); raise :class:`CheckpointError` naming the first file that is missing or
    damaged (truncated arrays, broken JSON).

    Example:
        >>> check_checkpoint("runs/ppo/checkpoints/step_100000")
    """
    agent = os.path.join(path, "agent")
    if os.path.exists(os.path.join(path, "trainer.json")):
        _read_json(os.path.join(path, "trainer.json"))
        _read_npz(os.path.join(path, "workers.npz"))
    elif not os.path.isdir(agent):
        agent = path
    _read_json(os.path.join(agent, "agent.json"))
    _read_npz(os.path.join(agent, "arrays.npz"))


def usable_checkpoint(out: str, *, warn: Callable[[str], None] | None = None) -> str | None:
    """The last checkpoint of a run whose files all read (:func:`check_checkpoint`); damaged
    later ones are skipped, each with a message to ``warn``.

    Returns:
        The checkpoint's folder, or None when the run has none.

    Raises:
        CheckpointError: every checkpoint is damaged (naming the files).

    Example:
        >>> usable_checkpoint("runs/ppo", warn=print)
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


def set_threads(xp: Any, threads: int) -> str:
    """Set the intra-op threads of the framework behind ``xp`` (a backend namespace, or a
    framework's name: a name does not load ivy's backend, and tensorflow's threads can only be
    set before anything, ivy's backend included, runs on it) to ``threads``.

    The setter is found by what the framework offers, not by its name: a
    ``set_num_threads`` function (torch; its inter-op pool is left alone, it can be sized only
    before its first use), ``config.threading``'s intra- and inter-op setters (tensorflow; they
    are settable only before its first operation, afterwards a value that differs is reported in
    a warning), or XLA's ``XLA_FLAGS`` (jax: ``--xla_cpu_multi_thread_eigen=false`` and
    ``intra_op_parallelism_threads=N`` for one thread, read when XLA starts, so they act only if
    set before jax's first computation; afterwards a warning says so). Frameworks with none of
    these (numpy, whose element-wise functions use one thread) are left as they are.

    Args:
        xp: a backend namespace (``ivy.get_framework(f="torch")``) or a framework's name.
        threads: intra-op threads, an integer >= 1 (1: small models run fastest on a shared
            machine).

    Returns:
        What was done, in words (``'torch.set_num_threads(1)'``, ``'not settable'``...).

    Example:
        >>> set_threads(ivy.get_framework(f="torch"), 1)
        'torch.set_num_threads(1)'
    """
    _check_count("threads", threads, 1)
    threads = int(threads)
    name = xp if isinstance(xp, str) else str(getattr(xp, "backend", ""))
    try:
        native = importlib.import_module(ivy.framework_handler.native_package(name))
    except (ImportError, ivy.framework_handler.UnknownFrameworkError):
        return "not settable"
    name = native.__name__
    if callable(getattr(native, "set_num_threads", None)):
        native.set_num_threads(threads)
        return f"{name}.set_num_threads({threads})"
    threading = getattr(getattr(native, "config", None), "threading", None)
    if threading is not None and hasattr(threading, "set_intra_op_parallelism_threads"):
        pairs = (
            (
                threading.get_intra_op_parallelism_threads,
                threading.set_intra_op_parallelism_threads,
            ),
            (
                threading.get_inter_op_parallelism_threads,
                threading.set_inter_op_parallelism_threads,
            ),
        )
        for get, put in pairs:
            if get() == threads:
                continue
            try:
                put(threads)
            except RuntimeError:
                _warn(
                    f"{name} already ran operations with {get() or 'its default'} threads; its "
                    f"threads can be set only before: set them ({put.__name__}) first in the "
                    "process, or run the command in a new process"
                )
                return f"{name}: not changed (already started)"
        return f"{name}.config.threading: intra/inter-op {threads}"
    try:
        bridge = importlib.import_module(f"{name}._src.xla_bridge")
    except ImportError:
        bridge = None
    if bridge is not None and hasattr(bridge, "backends_are_initialized"):
        if threads != 1:
            return f"{name}: XLA's default threads (only one thread can be asked for)"
        flags = "--xla_cpu_multi_thread_eigen=false intra_op_parallelism_threads=1"
        current = os.environ.get("XLA_FLAGS", "")
        if flags in current:
            return f"{name}: XLA_FLAGS {flags}"
        if bridge.backends_are_initialized():
            _warn(
                f"{name} has started XLA, which reads its threads from XLA_FLAGS only when it "
                f"starts: set XLA_FLAGS='{flags}' before the process's first {name} computation"
            )
            return f"{name}: not changed (already started)"
        os.environ["XLA_FLAGS"] = f"{current} {flags}".strip()
        return f"{name}: XLA_FLAGS {flags}"
    return "not settable"


def _check_count(name: str, value: Any, minimum: int, *, optional: bool = False) -> None:
    if value is None and optional:
        return
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")


class Trainer:
    """Trains an agent on a Gymnasium environment.

    Args:
        steps: environment steps in total (all workers together, and the steps an agent
            simulates in its own differentiable rollouts).
        epoch_steps: steps per epoch (one log row and one round of test episodes per epoch);
            default: ``steps / 20``.
        save_steps: steps between checkpoints (taken at the end of an epoch); default: every
            epoch. A checkpoint is always saved at the end.
        test_episodes: test episodes (with ``agent.test_step``) at the end of each epoch, on a
            separate environment; 0: none.
        keep_checkpoints: the number of checkpoints kept (the last ones); None: all.
        show_progress: print the progress bar and the table of each epoch.
        tensorboard: also write the scalars to TensorBoard (``<out>/tensorboard``).
        threads: intra-op threads of the agent's framework (:func:`set_threads`), set when a
            run starts; 1 (the default) is fastest for small models, above all on a shared
            machine, where more threads wait on each other.

    Example:
        >>> Trainer(steps=50_000, epoch_steps=5_000, test_episodes=5)
    """

    def __init__(
        self,
        steps: int = 100_000,
        *,
        epoch_steps: int | None = None,
        save_steps: int | None = None,
        test_episodes: int = 5,
        keep_checkpoints: int | None = 2,
        show_progress: bool = True,
        tensorboard: bool = False,
        threads: int = 1,
    ) -> None:
        _check_count("steps", steps, 1)
        _check_count("threads", threads, 1)
        _check_count("epoch_steps", epoch_steps, 1, optional=True)
        _check_count("save_steps", save_steps, 1, optional=True)
        _check_count("test_episodes", test_episodes, 0)
        _check_count("keep_checkpoints", keep_checkpoints, 1, optional=True)
        self.max_steps = int(steps)
        self.epoch_steps = int(epoch_steps or max(self.max_steps // 20, 1))
        self.save_steps = int(save_steps or self.epoch_steps)
        self.test_episodes = int(test_episodes)
        self.keep_checkpoints = keep_checkpoints
        self.show_progress = show_progress
        self.tensorboard = tensorboard
        self.threads = int(threads)

    def run(
        self,
        agent: Agent | str,
        environment: str,
        *,
        workers: int = 1,
        seed: int = 0,
        f: Any = None,
        dtype: str | None = None,
        compile: bool = True,
        device: str | None = None,
        vectorization: str = "sync",
        env_kwargs: dict[str, Any] | None = None,
        time_feature: bool = False,
        wrappers: Sequence[str] | None = None,
        ray_groups: int | None = None,
        out: str | None = None,
        resume: bool = False,
        overwrite: bool = False,
        config: dict[str, Any] | None = None,
    ) -> list[dict[str, Any]]:
        """Train ``agent`` (an :class:`~ivy_rl.agents.Agent` or a name) on ``environment``.

        An agent that is already initialized (or loaded from a checkpoint) is trained from its
        current weights; it must fit the environment's spaces, and ``f``, ``dtype`` and
        ``device``, when given, must be its own.

        Args:
            agent: the agent, or its name (``'PPO'``) for the defaults of the environment's
                task family (:func:`ivy_rl.agents.make`).
            environment: a Gymnasium id, or ``'module:EnvId'`` (the module registers it).
            workers: parallel environments.
            seed: seed of the agent and of the environments.
            f: framework (``'torch'``, ``'jax'``, ``'tensorflow'``).
            dtype: float dtype of the agent (default ``'float32'``).
            compile: compile the agent's functions (False: eager).
            device: where the agent's arrays live (``'cpu'``, ``'gpu:0'``).
            vectorization: ``'sync'``, ``'async'`` or ``'ray'``.
            env_kwargs: keyword arguments of ``gymnasium.make``.
            time_feature: append the remaining time to the observations, and treat time limits
                as terminal (False: time limits are resets that agents bootstrap through).
            wrappers: Gymnasium wrappers by name (``['FlattenObservation']``).
            ray_groups: number of Ray actors with ``vectorization='ray'``.
            out: the run's folder (``config.json``, ``log.csv``, ``checkpoints/``, ``best/``);
                None: no files. A folder that is not empty is refused unless ``resume`` or
                ``overwrite``.
            resume: continue from the last usable checkpoint in ``out``.
            overwrite: start again in ``out``, removing its run (config, log, checkpoints).
            config: further entries for ``config.json`` (the command line's settings).

        Returns:
            The log's rows, one per epoch.
        """
        checkpoint = self._prepare_folder(out, resume, overwrite)
        if isinstance(agent, str):
            agent = make(agent, environment=environment)
        if getattr(agent, "differentiable", False):
            agent.bind_environment(environment, dict(env_kwargs or {}))
        self.workers = Workers(
            environment,
            workers,
            seed=seed,
            vectorization=vectorization,
            env_kwargs=env_kwargs,
            time_feature=time_feature,
            wrappers=wrappers,
            ray_groups=ray_groups,
        )
        self.test_env = None
        try:
            self.test_env = make_env(
                environment, env_kwargs=env_kwargs, time_feature=time_feature, wrappers=wrappers
            )
            self.threads_set = set_threads(_framework_of(agent, f), self.threads)
            self._initialize(agent, seed, f, dtype, compile, device)
            record = self._record(
                agent, environment, workers, seed, env_kwargs, wrappers, time_feature,
                vectorization, ray_groups, compile,
            )  # fmt: skip
            record.update(config or {})
            if out is not None:
                self._write_config(out, record, resume, overwrite)
        except BaseException:
            self.workers.close()
            if self.test_env is not None:
                self.test_env.close()
            raise
        self.agent, self.seed, self.out = agent, int(seed), out
        self.config = record
        self.logger = Logger(out, tensorboard=self.tensorboard, quiet=not self.show_progress)
        num = self.workers.num_workers
        self.steps, self.epochs, self.episodes, self.elapsed = 0, 0, 0, 0.0
        self.scores, self.lengths = np.zeros(num), np.zeros(num, np.int64)
        self.best_score = -np.inf
        self._compile_baseline: int | None = None
        self._tested = False
        try:
            if checkpoint is not None:
                observations = self._load(checkpoint)
            else:
                observations = self.workers.start()
                self.logger.restore(0) if out else None
            self._loop(observations)
        finally:
            self.logger.close()
            self.workers.close()
            self.test_env.close()
        return self.logger.rows

    # ------------------------------------------------------------------------------------------
    # Set-up
    # ------------------------------------------------------------------------------------------

    def _prepare_folder(self, out: str | None, resume: bool, overwrite: bool) -> str | None:
        """Check the run's folder before anything is built; the checkpoint to resume from."""
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
            checkpoint = usable_checkpoint(out, warn=_warn)
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

    def _initialize(self, agent, seed, f, dtype, compile, device) -> None:
        spaces = (self.workers.observation_space, self.workers.action_space)
        if not getattr(agent, "initialized", False):
            kwargs = {"device": device} if device is not None else {}
            agent.initialize(
                *spaces, seed=seed, f=f, dtype=dtype or "float32", compile=compile, **kwargs
            )
            return
        name = type(agent).__name__
        if not all(map(_fits, (agent.observation_space, agent.action_space), spaces)):
            raise ValueError(
                f"the {name} was initialized for observations {agent.observation_space} and "
                f"actions {agent.action_space}, but the environment has {spaces[0]} and "
                f"{spaces[1]}; initialize it for this environment, or pass an uninitialized agent"
            )
        if f is not None and ivy.get_framework(f=f) is not agent.xp:
            raise ValueError(
                f"the {name} was initialized on {agent.xp.backend}, not on {f!r}; leave f=None "
                "to train it where it is, or pass an uninitialized agent"
            )
        for key, asked, own in (("dtype", dtype, agent.dtype), ("device", device, agent.device)):
            if asked is not None and asked != own:
                raise ValueError(
                    f"the {name} was initialized with {key}={own!r}, not {asked!r}; leave "
                    f"{key}=None to train it as it is, or pass an uninitialized agent"
                )

    def _record(
        self, agent, environment, workers, seed, env_kwargs, wrappers, time_feature,
        vectorization, ray_groups, compile,
    ) -> dict[str, Any]:  # fmt: skip
        """What ``config.json`` records of the run: every value used."""
        return {
            "agent": type(agent).__name__,
            "agent_config": dict(agent.config),
            "environment": environment,
            "env_kwargs": dict(env_kwargs or {}),
            "wrappers": [w if isinstance(w, str) else _qualified(w) for w in wrappers or ()],
            "time_feature": bool(time_feature),
            "workers": self.workers.num_workers,
            "vectorization": vectorization,
            "ray_groups": ray_groups,
            "seed": int(seed),
            "framework": agent.xp.backend,
            "dtype": agent.dtype,
            "device": str(agent.device),
            "eager": not compile,
            "steps": self.max_steps,
            "epoch_steps": self.epoch_steps,
            "save_steps": self.save_steps,
            "test_episodes": self.test_episodes,
            "keep_checkpoints": self.keep_checkpoints,
            "tensorboard": self.tensorboard,
            "threads": self.threads,
        }

    def _write_config(self, out: str, record: dict[str, Any], resume: bool, overwrite: bool):
        path = os.path.join(out, "config.json")
        if resume and os.path.exists(path):
            saved = _read_json(path)
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
        _write_json(path, record)

    # ------------------------------------------------------------------------------------------

    def _total_steps(self) -> int:
        """Environment steps of the workers and steps the agent simulated itself."""
        return self.steps + int(getattr(self.agent, "simulated_steps", 0))

    def _loop(self, observations: np.ndarray) -> None:
        agent, logger, num = self.agent, self.logger, self.workers.num_workers
        counts_compiles = hasattr(agent, "compiles")
        simulates = hasattr(agent, "simulated_steps")
        set_progress = getattr(agent, "set_progress", None)
        start = time.monotonic() - self.elapsed
        epoch_start, epoch_begin = time.monotonic(), self._total_steps()
        since_save = 0
        total = self._total_steps()
        while total < self.max_steps:
            actions = agent.step(observations)
            observations, infos = self.workers.step(actions)
            if set_progress is not None:
                set_progress(total / self.max_steps)
            logs = agent.update(**infos)
            for key, value in logs.items():
                logger.store(key, value)
            if logs and counts_compiles:
                self._check_compiles("its update")
            self.scores += infos["rewards"]
            self.lengths += 1
            self.steps += num
            before, total = total, self._total_steps()
            since_save += total - before
            for i in np.flatnonzero(infos["resets"]):
                logger.store("train/episode_score", self.scores[i], stats=True)
                logger.store("train/episode_length", self.lengths[i], stats=True)
                self.scores[i], self.lengths[i] = 0.0, 0
                self.episodes += 1
            epoch_steps = total - epoch_begin
            if self.show_progress:
                logger.progress(total, epoch_steps, self.epoch_steps, self.max_steps)
            last = total >= self.max_steps
            if epoch_steps >= self.epoch_steps or last:
                test_start = time.monotonic()
                self._test()
                test_seconds = time.monotonic() - test_start
                self.epochs += 1
                now = time.monotonic()
                self.elapsed = now - start
                fixed = {
                    "train/steps": total,
                    "train/epochs": self.epochs,
                    "train/episodes": self.episodes,
                    "train/seconds": self.elapsed,
                    "train/epoch_seconds": now - epoch_start,
                    "train/steps_per_second": epoch_steps
                    / max(now - epoch_start - test_seconds, 1e-9),
                    "test/seconds": test_seconds,
                }
                if simulates:
                    fixed["train/simulated_steps"] = int(agent.simulated_steps)
                if counts_compiles:
                    fixed["train/compiles"] = int(agent.compiles)
                row = logger.dump(fixed)
                self._keep_best(row)
                epoch_start, epoch_begin = time.monotonic(), total
                if self.out is not None and (since_save >= self.save_steps or last):
                    self._save()
                    since_save = 0

    def _check_compiles(self, where: str) -> None:
        """Warn (once per growth) when the agent compiles again after its first update."""
        compiles = int(self.agent.compiles)
        if self._compile_baseline is None:
            self._compile_baseline = compiles
        elif compiles > self._compile_baseline:
            self.logger.warning(
                f"{type(self.agent).__name__} compiled again in {where} at step "
                f"{self._total_steps()} ({self._compile_baseline} -> {compiles} compilations "
                "since its first update): a setting, shape or dtype changes between calls"
            )
            self._compile_baseline = compiles

    def _test(self) -> None:
        if self.test_episodes < 1:
            return
        counts = hasattr(self.agent, "compiles")
        before = int(self.agent.compiles) if counts else 0
        seeds = np.random.SeedSequence([self.seed, 3, self.epochs]).generate_state(
            self.test_episodes
        )
        for episode_seed in seeds:
            obs, _ = self.test_env.reset(seed=int(episode_seed))
            score, length = 0.0, 0
            while True:
                action = self.agent.test_step(np.asarray(obs)[None])[0]
                obs, reward, terminated, truncated, _ = self.test_env.step(action)
                score += float(reward)
                length += 1
                if terminated or truncated:
                    break
            self.logger.store("test/episode_score", score, stats=True)
            self.logger.store("test/episode_length", length, stats=True)
        if counts:
            if not self._tested and self._compile_baseline is not None:
                # the test policy's first compilation is expected
                self._compile_baseline += int(self.agent.compiles) - before
            elif self._compile_baseline is not None:
                self._check_compiles("its test episodes")
        self._tested = True

    def _keep_best(self, row: dict[str, Any]) -> None:
        score = row.get("test/episode_score/mean")
        if self.out is None or score is None or not score > self.best_score:
            return
        self.best_score = float(score)
        best = os.path.join(self.out, "best")
        partial = os.path.join(self.out, ".best.partial")
        shutil.rmtree(partial, ignore_errors=True)
        self.agent.save(os.path.join(partial, "agent"))
        _write_json(
            os.path.join(partial, "best.json"),
            {"steps": row["train/steps"], "epochs": self.epochs, "test_score": self.best_score},
        )
        shutil.rmtree(best, ignore_errors=True)
        os.replace(partial, best)

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def _save(self) -> None:
        root = os.path.join(self.out, "checkpoints")
        name = f"step_{self._total_steps()}"
        path, partial = os.path.join(root, name), os.path.join(root, f".{name}.partial")
        shutil.rmtree(partial, ignore_errors=True)
        self.agent.save(os.path.join(partial, "agent"))
        arrays, meta = self.workers.state_dict()
        with open(os.path.join(partial, "workers.npz"), "wb") as fh:
            np.savez(fh, **arrays)
        state = {
            "steps": self.steps,
            "epochs": self.epochs,
            "episodes": self.episodes,
            "elapsed": self.elapsed,
            "scores": self.scores.tolist(),
            "lengths": self.lengths.tolist(),
            "best_score": self.best_score if np.isfinite(self.best_score) else None,
            "workers": meta,
        }
        _write_json(os.path.join(partial, "trainer.json"), state)
        shutil.rmtree(path, ignore_errors=True)
        os.replace(partial, path)  # the checkpoint appears complete, or not at all
        if self.keep_checkpoints is not None:
            kept = checkpoints(self.out)
            for old in kept[: -self.keep_checkpoints]:
                shutil.rmtree(old, ignore_errors=True)

    def _load(self, path: str) -> np.ndarray:
        state = _read_json(os.path.join(path, "trainer.json"))
        agent_path = os.path.join(path, "agent")
        try:
            self.agent.load(agent_path)
        except (KeyError, OSError, zipfile.BadZipFile, json.JSONDecodeError) as error:
            raise CheckpointError(f"cannot load the agent of {agent_path}: {error}") from None
        arrays = _read_npz(os.path.join(path, "workers.npz"))
        observations = self.workers.load_state_dict(arrays, state["workers"])
        self.steps, self.epochs = int(state["steps"]), int(state["epochs"])
        self.episodes, self.elapsed = int(state["episodes"]), float(state["elapsed"])
        self.scores = np.asarray(state["scores"], np.float64)
        self.lengths = np.asarray(state["lengths"], np.int64)
        best = state.get("best_score")
        self.best_score = -np.inf if best is None else float(best)
        self.logger.restore(self.epochs)
        return observations


def _framework_of(agent: Any, f: Any) -> Any:
    """The framework the agent computes with: its own namespace once initialized, else ``f``
    (the global framework, else numpy, as :meth:`Agent.initialize` chooses), not yet loaded."""
    if getattr(agent, "initialized", False) and getattr(agent, "xp", None) is not None:
        return agent.xp
    return f if f is not None else ivy.current_framework() or "numpy"


def _fits(own: Any, other: Any) -> bool:
    """Whether an agent built for the space ``own`` acts in ``other`` (the same kind, shape
    and, for discrete spaces, the same actions; Box bounds may differ)."""
    if type(own) is not type(other) or own.shape != other.shape:
        return False
    return all(
        np.array_equal(getattr(own, key), getattr(other, key))
        for key in ("n", "start", "nvec")
        if hasattr(own, key)
    )


def _warn(message: str) -> None:
    import warnings

    warnings.warn(message, RuntimeWarning, stacklevel=3)


def _qualified(obj: Any) -> str:
    return f"{obj.__module__}:{obj.__qualname__}"


def _json_value(value: Any) -> Any:
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, type):
        return _qualified(value)
    return str(value)  # schedules and other settings written as text


def _same(key: str, saved: Any, value: Any) -> bool:
    if key == "agent":
        return str(saved).lower() == str(value).lower()
    return _jsonable(saved) == _jsonable(value)


def _jsonable(value: Any) -> Any:
    return json.loads(json.dumps(value, default=_json_value))


def _write_json(path: str, value: Any) -> None:
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        json.dump(value, fh, indent=1, default=_json_value)
