"""The trainer: steps the environments, hands the agent observations, rewards, resets and
terminations, runs test episodes each epoch, logs, and saves checkpoints that resume exactly.

A checkpoint (``<out>/checkpoints/step_<steps>/``) holds the agent's whole state (weights,
optimiser states, normalisers, replay, random generator) and the trainer's (counters, the
environments' seeds and the actions of their current episodes, which bring the environments
back to the same state). Resuming therefore continues with the same numbers as a run that was
never interrupted, and a checkpoint written on one framework continues on another.

Example:
    >>> trainer = Trainer(steps=100_000, epoch_steps=10_000)
    >>> rows = trainer.run("PPO", "CartPole-v1", workers=8, seed=0, f="torch", out="runs/ppo")
"""

from __future__ import annotations

import glob
import json
import os
import shutil
import time
from typing import Any

import numpy as np

from ivy_rl.agents import Agent, make
from ivy_rl.environments import Workers, make_env
from ivy_rl.logger import Logger

__all__ = ["Trainer", "latest_checkpoint"]


def latest_checkpoint(out: str) -> str | None:
    """The folder of the last checkpoint of a run (``<out>/checkpoints/step_<n>``), or None.

    Example:
        >>> latest_checkpoint("runs/ppo")
        'runs/ppo/checkpoints/step_100000'
    """
    paths = glob.glob(os.path.join(out, "checkpoints", "step_*"))
    paths = [p for p in paths if os.path.exists(os.path.join(p, "trainer.json"))]
    if not paths:
        return None
    return max(paths, key=lambda p: int(p.rsplit("_", 1)[1]))


class Trainer:
    """Trains an agent on a Gymnasium environment.

    Args:
        steps: environment steps in total (all workers together).
        epoch_steps: steps per epoch (one log row and one round of test episodes per epoch);
            default: ``steps / 20``.
        save_steps: steps between checkpoints (taken at the end of an epoch); default: every
            epoch. A checkpoint is always saved at the end.
        test_episodes: test episodes (with ``agent.test_step``) at the end of each epoch.
        keep_checkpoints: keep every checkpoint (False: only the last).
        show_progress: print the progress bar and the table of each epoch.
        tensorboard: also write the scalars to TensorBoard (``<out>/tensorboard``).

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
        keep_checkpoints: bool = False,
        show_progress: bool = True,
        tensorboard: bool = False,
    ) -> None:
        if steps < 1:
            raise ValueError(f"steps must be >= 1, got {steps}")
        self.max_steps = int(steps)
        self.epoch_steps = int(epoch_steps or max(self.max_steps // 20, 1))
        self.save_steps = int(save_steps or self.epoch_steps)
        self.test_episodes = int(test_episodes)
        self.keep_checkpoints = keep_checkpoints
        self.show_progress = show_progress
        self.tensorboard = tensorboard

    def run(
        self,
        agent: Agent | str,
        environment: str,
        *,
        workers: int = 1,
        seed: int = 0,
        f: Any = None,
        dtype: str = "float32",
        compile: bool = True,
        vectorization: str = "sync",
        env_kwargs: dict[str, Any] | None = None,
        time_feature: bool = False,
        ray_groups: int | None = None,
        out: str | None = None,
        resume: bool = False,
    ) -> list[dict[str, Any]]:
        """Train ``agent`` (an :class:`~ivy_rl.agents.Agent` or a name) on ``environment``.

        Args:
            agent: the agent, or its name (``'PPO'``) for default settings.
            environment: a Gymnasium id.
            workers: parallel environments.
            seed: seed of the agent and of the environments.
            f: framework (``'torch'``, ``'jax'``, ``'tensorflow'``).
            dtype: float dtype of the agent.
            compile: compile the agent's functions (False: eager).
            vectorization: ``'sync'``, ``'async'`` or ``'ray'``.
            env_kwargs: keyword arguments of ``gymnasium.make``.
            time_feature: append the remaining time to the observations.
            ray_groups: number of Ray actors with ``vectorization='ray'``.
            out: the run's folder (``log.csv``, ``config.json``, ``checkpoints/``); None: no
                files.
            resume: continue from the last checkpoint in ``out``.

        Returns:
            The log's rows, one per epoch.
        """
        if isinstance(agent, str):
            agent = make(agent)
        self.workers = Workers(
            environment,
            workers,
            seed=seed,
            vectorization=vectorization,
            env_kwargs=env_kwargs,
            time_feature=time_feature,
            ray_groups=ray_groups,
        )
        self.test_env = make_env(environment, env_kwargs=env_kwargs, time_feature=time_feature)
        agent.initialize(
            self.workers.observation_space,
            self.workers.action_space,
            seed=seed,
            f=f,
            dtype=dtype,
            compile=compile,
        )
        self.agent, self.seed, self.out = agent, int(seed), out
        self.logger = Logger(out, tensorboard=self.tensorboard, quiet=not self.show_progress)
        num = self.workers.num_workers
        self.steps, self.epochs, self.episodes, self.elapsed = 0, 0, 0, 0.0
        self.scores, self.lengths = np.zeros(num), np.zeros(num, np.int64)
        checkpoint = latest_checkpoint(out) if (resume and out) else None
        if resume and out and checkpoint is None:
            raise FileNotFoundError(
                f"cannot resume: no checkpoint in {os.path.join(out, 'checkpoints')}"
            )
        if checkpoint is not None:
            observations = self._load(checkpoint)
        else:
            observations = self.workers.start()
            self.logger.restore(0) if out else None
        try:
            self._loop(observations)
        finally:
            self.logger.close()
            self.workers.close()
            self.test_env.close()
        return self.logger.rows

    # ------------------------------------------------------------------------------------------

    def _loop(self, observations: np.ndarray) -> None:
        agent, logger, num = self.agent, self.logger, self.workers.num_workers
        start = time.monotonic() - self.elapsed
        epoch_start, epoch_steps = time.monotonic(), 0
        since_save = 0
        while self.steps < self.max_steps:
            actions = agent.step(observations)
            observations, infos = self.workers.step(actions)
            for key, value in agent.update(**infos).items():
                logger.store(key, value)
            self.scores += infos["rewards"]
            self.lengths += 1
            self.steps += num
            epoch_steps += num
            since_save += num
            for i in np.flatnonzero(infos["resets"]):
                logger.store("train/episode_score", self.scores[i], stats=True)
                logger.store("train/episode_length", self.lengths[i], stats=True)
                self.scores[i], self.lengths[i] = 0.0, 0
                self.episodes += 1
            if self.show_progress:
                logger.progress(self.steps, epoch_steps, self.epoch_steps, self.max_steps)
            last = self.steps >= self.max_steps
            if epoch_steps >= self.epoch_steps or last:
                test_start = time.monotonic()
                self._test()
                test_seconds = time.monotonic() - test_start
                self.epochs += 1
                now = time.monotonic()
                self.elapsed = now - start
                logger.dump(
                    {
                        "train/steps": self.steps,
                        "train/epochs": self.epochs,
                        "train/episodes": self.episodes,
                        "train/seconds": self.elapsed,
                        "train/epoch_seconds": now - epoch_start,
                        "train/steps_per_second": epoch_steps
                        / max(now - epoch_start - test_seconds, 1e-9),
                        "test/seconds": test_seconds,
                    }
                )
                epoch_start, epoch_steps = time.monotonic(), 0
                if self.out is not None and (since_save >= self.save_steps or last):
                    self._save()
                    since_save = 0

    def _test(self) -> None:
        if self.test_episodes < 1:
            return
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

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def _save(self) -> None:
        root = os.path.join(self.out, "checkpoints")
        path = os.path.join(root, f"step_{self.steps}")
        previous = glob.glob(os.path.join(root, "step_*"))
        self.agent.save(os.path.join(path, "agent"))
        arrays, meta = self.workers.state_dict()
        with open(os.path.join(path, "workers.npz"), "wb") as fh:
            np.savez(fh, **arrays)
        state = {
            "steps": self.steps,
            "epochs": self.epochs,
            "episodes": self.episodes,
            "elapsed": self.elapsed,
            "scores": self.scores.tolist(),
            "lengths": self.lengths.tolist(),
            "workers": meta,
        }
        with open(os.path.join(path, "trainer.json"), "w") as fh:
            json.dump(state, fh)  # written last: marks the checkpoint complete
        if not self.keep_checkpoints:
            for old in previous:
                if os.path.abspath(old) != os.path.abspath(path):
                    shutil.rmtree(old, ignore_errors=True)

    def _load(self, path: str) -> np.ndarray:
        with open(os.path.join(path, "trainer.json")) as fh:
            state = json.load(fh)
        self.agent.load(os.path.join(path, "agent"))
        with np.load(os.path.join(path, "workers.npz"), allow_pickle=False) as data:
            arrays = {k: data[k] for k in data.files}
        observations = self.workers.load_state_dict(arrays, state["workers"])
        self.steps, self.epochs = int(state["steps"]), int(state["epochs"])
        self.episodes, self.elapsed = int(state["episodes"]), float(state["elapsed"])
        self.scores = np.asarray(state["scores"], np.float64)
        self.lengths = np.asarray(state["lengths"], np.int64)
        self.logger.restore(self.epochs)
        return observations
