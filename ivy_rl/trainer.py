"""The trainer: steps the environments, hands the agent observations, rewards, resets and
terminations, runs test episodes each epoch on an environment of their own, logs, keeps the best
model, and saves checkpoints that resume exactly (:mod:`ivy_rl.checkpoints` holds their format),
on any framework. What it prints is :mod:`ivy_rl.console`'s: a start line, a progress bar over
the whole run, a line while the agent compiles, a table per epoch and a summary.

Ctrl-C stops a run cleanly: the trainer finishes the step it is in, saves a checkpoint there
(within an epoch too: the epoch's values so far are kept) and raises
:class:`TrainingInterrupted` after printing how to resume; a second Ctrl-C stops at once,
without saving.

Example:
    A short run of A2C (CartPole-v1 takes about ``steps=100_000`` to learn), printing only its
    summary:

    >>> import os
    >>> trainer = Trainer(steps=2_000, epoch_steps=1_000, test_episodes=1, show_progress=False)
    >>> rows = trainer.run("A2C", "CartPole-v1", workers=8, seed=0, f="jax", out="runs/a2c")
    finished: 2,000 steps in ...
    >>> sorted(os.listdir("runs/a2c"))                  # the run folder (ivy_rl.checkpoints)
    ['best', 'checkpoints', 'config.json', 'log.csv']
"""

from __future__ import annotations

import contextlib
import signal
import threading
import time
from collections.abc import Sequence
from typing import Any

import numpy as np

import ivy
from ivy.threads import set_threads
from ivy_rl import console as messages
from ivy_rl.agents import Agent, make
from ivy_rl.checkpoints import (
    RUN_ENTRIES,
    CheckpointError,
    check_checkpoint,
    checkpoints,
    latest_checkpoint,
    load_checkpoint,
    prepare_run_folder,
    save_best,
    save_checkpoint,
    usable_checkpoint,
    write_config,
)
from ivy_rl.console import Console
from ivy_rl.environments import Workers, make_env, run_env_kwargs
from ivy_rl.logger import Logger

__all__ = [
    "Trainer",
    "TrainingInterrupted",
    # kept here for code that imports them from the trainer (their home is ivy_rl.checkpoints
    # and ivy.set_threads)
    "CheckpointError",
    "checkpoints",
    "check_checkpoint",
    "latest_checkpoint",
    "usable_checkpoint",
    "RUN_ENTRIES",
    "set_threads",
]


class TrainingInterrupted(KeyboardInterrupt):
    """A run stopped by Ctrl-C, after the console said so (and how to resume).

    Attributes:
        checkpoint: the checkpoint saved where it stopped (None: nothing was saved).
        steps: the run's steps when it stopped.
    """

    reported = True  # the console has told the user; the command line exits quietly

    def __init__(self, checkpoint: str | None, steps: int) -> None:
        super().__init__(f"training interrupted at step {steps}")
        self.checkpoint, self.steps = checkpoint, steps


def _check_count(name: str, value: Any, minimum: int, *, optional: bool = False) -> None:
    if value is None and optional:
        return
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")


class Trainer:
    """Trains an agent on a Gymnasium environment.

    Args:
        steps: environment steps in total (all workers together, and the steps an agent
            simulates in its own differentiable rollouts): a multiple of the workers, where the
            run stops exactly.
        epoch_steps: steps per epoch (one log row and one round of test episodes per epoch);
            default: ``steps / 20``, rounded to whole steps of the workers.
        save_steps: steps between checkpoints (taken at the end of an epoch); default: every
            epoch. A checkpoint is always saved at the end.
        test_episodes: test episodes (with ``agent.test_step``) at the end of each epoch, on a
            separate environment; 0: none.
        keep_checkpoints: the number of checkpoints kept (the last ones); None: all.
        show_progress: print the start line, the progress bar, compilations and the table of
            each epoch (False: only the summary at the end and interruptions).
        tensorboard: also write the scalars to TensorBoard (``<out>/tensorboard``).
        threads: intra-op threads of the agent's framework (:func:`set_threads`), set when a
            run starts; 1 (the default) is fastest for small models, above all on a shared
            machine, where more threads wait on each other.

    Example:
        >>> trainer = Trainer(steps=50_000, epoch_steps=5_000, test_episodes=5)
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
        self._default_epoch, self._default_save = epoch_steps is None, save_steps is None
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
        notes: Sequence[str] | None = None,
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
            vectorization: ``'sync'``, ``'async'``, ``'ray'`` or ``'batched'`` (ivy_gym's tasks,
                every worker in one call: :func:`ivy_rl.environments.make_vector_env`).
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
            notes: lines printed under the start line of a new run (None: for an agent given by
                name, where its task family's defaults differ from the class's own,
                :func:`ivy_rl.console.family_defaults`).

        Returns:
            The log's rows, one per epoch.
        """
        checkpoint = prepare_run_folder(out, resume, overwrite, warn=_warn)
        if isinstance(agent, str):
            if notes is None:
                notes = messages.family_defaults(agent, environment)
            agent = make(agent, environment=environment)
        # an ivy_gym MuJoCo task runs on the run's framework where it compiles loops
        env_kwargs = run_env_kwargs(environment, env_kwargs, _framework_of(agent, f))
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
            self._check_steps(agent, self.workers.num_workers)
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
                write_config(out, record, resume=resume, overwrite=overwrite)
        except BaseException:
            self.workers.close()
            if self.test_env is not None:
                self.test_env.close()
            raise
        self.agent, self.seed, self.out = agent, int(seed), out
        self.config = record
        self.environment = environment
        self.logger = Logger(out, tensorboard=self.tensorboard)
        self.console = Console(quiet=not self.show_progress)
        num = self.workers.num_workers
        self.steps, self.epochs, self.episodes, self.elapsed = 0, 0, 0, 0.0
        self.scores, self.lengths = np.zeros(num), np.zeros(num, np.int64)
        self.best_score, self.best_steps = -np.inf, None
        self._epoch_begin, self._epoch_elapsed, self._since_save = 0, 0.0, 0
        self._compile_baseline: int | None = None
        self._tested = False
        self._stop_requested = False
        self.checkpoint: str | None = checkpoint
        try:
            if checkpoint is not None:
                observations = self._load(checkpoint)
            else:
                observations = self.workers.start()
                self.logger.restore(0) if out else None
            if checkpoint is not None and self._total_steps() >= self.max_steps:
                self._report_finished(checkpoint)
                return self.logger.rows
            self.console.start(self._start_line(checkpoint))
            if checkpoint is None and notes:
                self.console.print("\n".join(notes))
            self._session_start = (time.monotonic(), self._total_steps())
            with self._interruptible():
                try:
                    self._loop(observations)
                except TrainingInterrupted:
                    raise
                except KeyboardInterrupt:  # a second Ctrl-C: stopped at once, nothing saved
                    self._report_interrupted(None)
                    raise TrainingInterrupted(None, self._total_steps()) from None
            self.console.close()
            self.console.summary(self._summary())
        finally:
            self.console.close()
            self.logger.close()
            self.workers.close()
            self.test_env.close()
        return self.logger.rows

    def _check_steps(self, agent: Any, workers: int) -> None:
        """Steps and epochs in whole steps of the workers: ``steps`` must be a multiple of
        ``workers`` (the run stops exactly there), and the default epoch is rounded to one.
        Agents that simulate steps of their own (differentiable rollouts) are exempt."""
        if getattr(agent, "differentiable", False) or workers == 1:
            return
        if self.max_steps % workers:
            low = self.max_steps - self.max_steps % workers
            options = " or ".join(f"{n:,}".replace(",", "") for n in (low, low + workers) if n)
            raise ValueError(
                f"steps={self.max_steps} is not a multiple of the {workers} workers (each step "
                f"of the workers is {workers} environment steps): use {options}"
            )
        if self._default_epoch:
            per_epoch = max(round(self.max_steps / 20 / workers), 1) * workers
            self.epoch_steps = per_epoch
            if self._default_save:
                self.save_steps = per_epoch

    # ------------------------------------------------------------------------------------------
    # Set-up
    # ------------------------------------------------------------------------------------------

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

    # ------------------------------------------------------------------------------------------

    def _total_steps(self) -> int:
        """Environment steps of the workers and steps the agent simulated itself."""
        return self.steps + int(getattr(self.agent, "simulated_steps", 0))

    def _loop(self, observations: np.ndarray) -> None:
        agent, logger, num = self.agent, self.logger, self.workers.num_workers
        console = self.console
        counts_compiles = hasattr(agent, "compiles")
        simulates = hasattr(agent, "simulated_steps")
        set_progress = getattr(agent, "set_progress", None)
        start = time.monotonic() - self.elapsed
        epoch_start = time.monotonic() - self._epoch_elapsed
        total = self._total_steps()
        if counts_compiles:
            console.watch_compiles(
                lambda: agent.compiles,
                f"the {type(agent).__name__}'s functions on {agent.xp.backend}",
            )
        console.progress(total, self.max_steps, elapsed=self.elapsed, force=True)
        while total < self.max_steps:
            console.tick()
            if self._stop_requested:
                self.elapsed = time.monotonic() - start
                self._epoch_elapsed = time.monotonic() - epoch_start
                self._stop_here()
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
            self._since_save += total - before
            for i in np.flatnonzero(infos["resets"]):
                logger.store("train/episode_score", self.scores[i], stats=True)
                logger.store("train/episode_length", self.lengths[i], stats=True)
                self.scores[i], self.lengths[i] = 0.0, 0
                self.episodes += 1
            epoch_steps = total - self._epoch_begin
            console.progress(total, self.max_steps, elapsed=time.monotonic() - start)
            last = total >= self.max_steps
            if epoch_steps >= self.epoch_steps or last:
                test_start = time.monotonic()
                self._test()
                console.tick()
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
                console.table(row)
                self._keep_best(row)
                epoch_start, self._epoch_begin, self._epoch_elapsed = time.monotonic(), total, 0.0
                if self.out is not None and (self._since_save >= self.save_steps or last):
                    self._save()
                console.progress(total, self.max_steps, elapsed=self.elapsed, force=True)

    # ------------------------------------------------------------------------------------------
    # What the run prints, and Ctrl-C
    # ------------------------------------------------------------------------------------------

    @contextlib.contextmanager
    def _interruptible(self):
        """While training, a first Ctrl-C asks the loop to stop after its step (and save); a
        second one stops at once. Only in the main thread (where Python delivers signals)."""
        if threading.current_thread() is not threading.main_thread():
            yield
            return

        def handler(signum, frame):
            if self._stop_requested:
                raise KeyboardInterrupt
            self._stop_requested = True
            what = "saving a checkpoint" if self.out is not None else "no --out: nothing is saved"
            self.console.print(
                f"Ctrl-C: stopping after this step ({what}); Ctrl-C again stops at once "
                "without saving",
                always=True,
                error=True,
            )

        previous = signal.signal(signal.SIGINT, handler)
        try:
            yield
        finally:
            signal.signal(signal.SIGINT, previous)

    def _stop_here(self) -> None:
        """Save where the loop stands (between steps), say how to resume, and stop."""
        path = self._save() if self.out is not None else None
        self._report_interrupted(path)
        raise TrainingInterrupted(path, self._total_steps())

    def _report_interrupted(self, saved: str | None) -> None:
        last = None if saved or self.out is None else latest_checkpoint(self.out)
        text = messages.interrupted(self._total_steps(), self.max_steps, self.out, saved, last)
        self.console.print(text, always=True, error=True)

    def _start_line(self, checkpoint: str | None) -> str:
        agent = self.agent
        return messages.start_line(
            type(agent).__name__,
            self.environment,
            framework=agent.xp.backend,
            dtype=agent.dtype,
            device=agent.device,
            compiled=getattr(agent, "compiled", True),
            steps=self.max_steps,
            workers=self.workers.num_workers,
            seed=self.seed,
            out=self.out,
            resumed_at=self._total_steps() if checkpoint is not None else None,
            checkpoint=checkpoint,
        )

    def _report_finished(self, checkpoint: str) -> None:
        text = messages.finished(self.out, self.max_steps, self._total_steps(), checkpoint)
        self.console.print(text, always=True)
        self.console.summary(self._summary(session=None))

    def _summary(self, *, session: tuple[float, int] | None = ()) -> list[str]:
        session = self._session_start if session == () else session
        rate = None
        if session is not None:
            done, seconds = self._total_steps() - session[1], time.monotonic() - session[0]
            rate = done / seconds if done > 0 and seconds > 0 else None
        return messages.summary(
            self.logger.rows,
            steps=self._total_steps() if session is not None else None,
            max_steps=self.max_steps,
            elapsed=self.elapsed,
            rate=rate,
            test_episodes=self.test_episodes,
            out=self.out,
        )

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
        self.best_steps = int(row["train/steps"])
        record = {"steps": row["train/steps"], "epochs": self.epochs, "test_score": self.best_score}
        save_best(self.out, self.agent, record)

    # ------------------------------------------------------------------------------------------
    # Checkpoints (their format: ivy_rl.checkpoints)
    # ------------------------------------------------------------------------------------------

    def _save(self) -> str:
        state = {
            "steps": self.steps,
            "epochs": self.epochs,
            "episodes": self.episodes,
            "elapsed": self.elapsed,
            "scores": self.scores.tolist(),
            "lengths": self.lengths.tolist(),
            "best_score": self.best_score if np.isfinite(self.best_score) else None,
            # the epoch in progress (a checkpoint taken within an epoch: Ctrl-C)
            "epoch_begin": self._epoch_begin,
            "epoch_elapsed": self._epoch_elapsed,
            "since_save": 0,
            "pending": self.logger.pending(),
        }
        path = save_checkpoint(
            self.out, self._total_steps(), self.agent, self.workers, state,
            keep=self.keep_checkpoints,
        )  # fmt: skip
        self._since_save = 0
        self.checkpoint = path
        return path

    def _load(self, path: str) -> np.ndarray:
        state, observations = load_checkpoint(path, self.agent, self.workers)
        self.steps, self.epochs = int(state["steps"]), int(state["epochs"])
        self.episodes, self.elapsed = int(state["episodes"]), float(state["elapsed"])
        self.scores = np.asarray(state["scores"], np.float64)
        self.lengths = np.asarray(state["lengths"], np.int64)
        best = state.get("best_score")
        self.best_score = -np.inf if best is None else float(best)
        # checkpoints from before the epoch in progress was saved were taken at an epoch's end
        self._epoch_begin = int(state.get("epoch_begin", self._total_steps()))
        self._epoch_elapsed = float(state.get("epoch_elapsed", 0.0))
        self._since_save = int(state.get("since_save", 0))
        self.logger.restore(self.epochs)
        self.logger.restore_pending(state.get("pending"))
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
