"""The console of a run people leave for hours: the start line, the progress bar over the whole
run (rate, elapsed time, time left), the line while the agent compiles, the summary (kept by
``--quiet``), Ctrl-C (a checkpoint where it stopped, how to resume, no traceback) and resuming a
finished run."""

from __future__ import annotations

import functools
import io
import json
import os
import re
import signal
import threading
import time

import numpy as np
import pytest

import ivy_rl
from ivy_rl import _cli, train
from ivy_rl import trainer as trainer_module
from ivy_rl.checkpoints import checkpoints
from ivy_rl.console import Console, format_duration
from ivy_rl.trainer import Trainer, TrainingInterrupted
from tests.ivy_rl.conftest import quick

PPO_TINY = {"hidden_sizes": [16], "segment_size": 8, "batch_size": 16, "epochs": 1}
TIME_COLUMNS = ("train/seconds", "train/epoch_seconds", "train/steps_per_second", "test/seconds")


class _Stream(io.StringIO):
    def __init__(self, tty: bool) -> None:
        super().__init__()
        self._tty = tty

    def isatty(self) -> bool:
        return self._tty


def test_the_bar_shows_the_whole_run_with_rate_elapsed_and_time_left():
    assert format_duration(3725.2) == "1:02:05" and format_duration(90061) == "1 day, 1:01:01"
    err = _Stream(tty=False)
    console = Console(stdout=io.StringIO(), stderr=err, line_seconds=0.0)
    console.progress(1_000, 20_000, elapsed=10.0)
    console._samples[0] = (console._samples[0][0] - 10.0, 1_000)  # 10 s ago
    console.progress(2_000, 20_000, elapsed=20.0)
    last = err.getvalue().splitlines()[-1]
    # 1,000 steps in 10 s: 100 steps/s, 18,000 steps left: 3 minutes
    assert last == (
        " 10% [###---------------------------] 2,000/20,000 steps | 100 steps/s | "
        "elapsed 0:00:20 | left 0:03:00"
    )
    # on a terminal the bar is redrawn in place, and lines printed meanwhile go above it
    tty = _Stream(tty=True)
    console = Console(stdout=tty, stderr=tty)
    console.progress(5, 10, elapsed=1.0, force=True)
    console.print("a line")
    assert tty.getvalue().startswith("\r\033[K 50% [") and "\r\033[Ka line\n\r\033[K 50%" in (
        tty.getvalue()
    )


def test_quiet_prints_only_the_summary():
    out, err = io.StringIO(), _Stream(tty=True)
    console = Console(quiet=True, stdout=out, stderr=err)
    console.start("training ...")
    console.progress(5, 10, elapsed=1.0, force=True)
    console.table({"train/steps": 5})
    console.summary(["finished: 10 steps"])
    assert out.getvalue() == "finished: 10 steps\n" and err.getvalue() == ""


def test_a_long_call_that_compiles_is_announced_and_timed():
    err = _Stream(tty=False)
    console = Console(stdout=io.StringIO(), stderr=err, compile_seconds=0.1)
    compiles = [0]
    console.watch_compiles(lambda: compiles[0], "the SAC's functions on torch")
    console.tick()
    compiles[0] += 1  # the agent counts a new signature, then compiles
    time.sleep(0.8)
    console.tick()
    console.tick()  # a slow call that compiles nothing is not announced
    time.sleep(0.5)
    console.close()
    lines = err.getvalue().splitlines()
    assert lines[0].startswith("compiling the SAC's functions on torch (")
    assert re.fullmatch(r"compiled in 0:00:0\d", lines[1]) and len(lines) == 2


class _StoppedPPO(ivy_rl.PPO):
    """PPO that presses Ctrl-C (once, or twice) during the update at a given step."""

    stop_at: int | None = None
    presses = 1

    def update(self, **infos):
        logs = super().update(**infos)
        self.seen = getattr(self, "seen", 0) + len(infos["rewards"])
        if self.seen == self.stop_at:
            for _ in range(self.presses):
                os.kill(os.getpid(), signal.SIGINT)
                time.sleep(0.05)  # the handler runs between bytecodes of this thread
        return logs


def _run(out, steps, f, *, stop_at=None, presses=1, resume=False, quiet=True):
    agent = _StoppedPPO(**PPO_TINY)
    agent.stop_at, agent.presses = stop_at, presses
    trainer = Trainer(steps, epoch_steps=32, test_episodes=1, show_progress=not quiet)
    return trainer.run(
        agent, "CartPole-v1", workers=2, seed=5, f=f, compile=f == "jax", out=str(out),
        resume=resume,
    )  # fmt: skip


def _rows(rows):
    return [{k: v for k, v in r.items() if k not in TIME_COLUMNS} for r in rows]


def test_ctrl_c_saves_where_it_stops_and_the_run_resumes_as_if_uninterrupted(
    diff_backend, tmp_path, capsys
):
    if threading.current_thread() is not threading.main_thread():
        pytest.skip("Python delivers signals to the main thread only")
    full = _run(tmp_path / "full", 64, diff_backend)
    out = tmp_path / "run"
    with pytest.raises(TrainingInterrupted) as stop:
        _run(out, 64, diff_backend, stop_at=40)  # within the second epoch (steps 33 to 64)
    assert stop.value.checkpoint == str(out / "checkpoints" / "step_40")
    err = capsys.readouterr().err
    assert "Ctrl-C: stopping after this step (saving a checkpoint)" in err
    assert f"interrupted at step 40 of 64: saved {out}/checkpoints/step_40" in err
    assert f"resume with: python -m ivy_rl.train --out {out} --resume" in err
    rows = _run(out, 64, diff_backend, resume=True, quiet=False)
    said = capsys.readouterr().out.splitlines()[0]
    mode = "compiled" if diff_backend == "jax" else "eager"
    assert said == (
        f"resuming _StoppedPPO on CartPole-v1 with {diff_backend} (float32, cpu, {mode}) from "
        f"step 40 (checkpoints/step_40) to 64 steps -> {out}"
    )
    assert _rows(rows) == _rows(full)  # the epoch's values before Ctrl-C were kept
    # a second Ctrl-C stops at once, without saving
    with pytest.raises(TrainingInterrupted) as stop:
        _run(tmp_path / "twice", 64, diff_backend, stop_at=40, presses=2)
    assert stop.value.checkpoint is None
    assert "not saved (the last checkpoint is step_32)" in capsys.readouterr().err


def test_the_command_line_exits_after_ctrl_c_with_130_and_no_traceback(capsys):
    for interrupt, said in (
        (TrainingInterrupted(None, 3), ""),
        (KeyboardInterrupt(), "interrupted\n"),
    ):

        def main(argv, interrupt=interrupt):
            raise interrupt

        with pytest.raises(SystemExit) as exit_:
            _cli.command_line(main, [])
        assert exit_.value.code == 130 and capsys.readouterr().err == said


def test_the_command_prints_a_start_line_progress_and_a_summary_and_quiet_keeps_it(
    backend, tmp_path, capsys, monkeypatch
):
    # on each backend, in the default folder (which names the framework): PPO where it learns,
    # random actions on numpy (no autodiff)
    monkeypatch.chdir(tmp_path)
    learns = backend != "numpy"
    agent = ["--agent", "PPO", "--agent-kwargs", json.dumps(PPO_TINY)] if learns else []
    agent = agent or ["--agent", "Uniform"]
    base = [*agent, "-f", backend, *quick(backend), "--workers", "2"]
    base += ["--epoch-steps", "16", "--test-episodes", "1"]
    name = "PPO" if learns else "Uniform"
    out = f"runs/{name}-CartPole-v1-{backend}-0"
    mode = "compiled" if backend == "jax" else "eager"
    rows = train.main([*base, "--steps", "32"])
    captured = capsys.readouterr()
    lines = captured.out.splitlines()
    assert lines[0] == (
        f"training {name} on CartPole-v1 with {backend} (float32, cpu, {mode}): 32 steps, "
        f"2 workers, seed 0 -> {out}"
    )
    assert os.path.isfile(os.path.join(out, "config.json"))
    if learns:  # the family's defaults where they differ from PPO()'s, the user's left out
        assert lines[1] == "defaults of the classic_discrete family where they differ from PPO()'s:"
        notes = lines[
            2 : lines.index("  every setting: python -m ivy_rl.agents.defaults PPO CartPole-v1")
        ]
        assert "actor_lr 0.001 (PPO(): 0.0003)" in " ".join(notes)
        assert not any(key in " ".join(notes) for key in PPO_TINY)
    else:
        assert not any("defaults of" in line for line in lines)
    assert "| test/episode_score/mean" in captured.out  # the epochs' tables
    assert re.search(r"100% \[#+\] 32/32 steps \| .* \| elapsed 0:00:\d\d \| left", captured.err)
    assert [r["train/steps"] for r in rows] == [16, 32]  # --steps is exact
    best = max(r["test/episode_score/mean"] for r in rows)
    summary = lines[-6:]
    assert re.fullmatch(r"finished: 32 steps in 0:00:\d\d \([\d,]+ steps/s\)", summary[0])
    assert summary[1].startswith(f"test score: best {best:.2f} at step ")
    assert summary[2:] == [
        f"run folder: {out}",
        f"  play:   python -m ivy_rl.play {out} --best",
        f"  plot:   python -m ivy_rl.plot {out} --out {out}/curves.png",
        f"  go on:  python -m ivy_rl.train --out {out} --resume --steps 64",
    ]
    # --quiet: the summary only; a finished run resumed says so
    rows = train.main(["--out", out, "--resume", "--steps", "48", "--quiet"])
    captured = capsys.readouterr()
    assert captured.err == "" and captured.out.startswith("finished: 48 steps")
    assert "| train/steps" not in captured.out and len(rows) == 3
    again = train.main(["--out", out, "--resume", "--quiet"])
    said = capsys.readouterr().out
    assert said.startswith(f"the run in {out} has done its 48 steps (its last checkpoint, step_48")
    assert "resume with --steps above 48" in said and len(again) == 3
    assert [os.path.basename(p) for p in checkpoints(out)] == ["step_32", "step_48"]
    # resumed (without --out: the default folder), the run says from which step
    rows = train.main([*base, "--resume", "--steps", "64"])
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == (
        f"resuming {name} on CartPole-v1 with {backend} (float32, cpu, {mode}) from step 48 "
        f"(checkpoints/step_48) to 64 steps -> {out}"
    )
    assert lines[1].startswith("-----")  # the epoch's table: no defaults again
    assert [r["train/steps"] for r in rows] == [16, 32, 48, 64]
    # a --steps that is not whole steps of the workers is refused before anything is written
    with pytest.raises(ValueError, match=r"--steps 50 is not a multiple of --workers 3.*48 or 51"):
        train.main([*base, "--steps", "50", "--workers", "3", "--out", "x"])
    assert not os.path.exists("x")


def test_a_compiling_run_says_so_and_how_long_it_took(graph_backend, tmp_path, capsys, monkeypatch):
    # jax.jit and tf.function (torch.compile takes minutes: its line is the same code, tested
    # with a counter in test_a_long_call_that_compiles_is_announced_and_timed)
    monkeypatch.setattr(trainer_module, "Console", functools.partial(Console, compile_seconds=0.01))
    agent = ["--agent", "PPO", "--agent-kwargs", json.dumps(PPO_TINY), "-f", graph_backend]
    train.main(
        [*agent, "--workers", "2", "--steps", "16", "--test-episodes", "0", "--out", str(tmp_path)]
    )
    captured = capsys.readouterr()
    assert captured.out.startswith(
        f"training PPO on CartPole-v1 with {graph_backend} (float32, cpu, compiled)"
    )
    lines = [line for line in captured.err.splitlines() if "compil" in line]
    assert lines and lines[0].startswith(
        f"compiling the PPO's functions on {graph_backend} (its first calls"
    )
    assert re.fullmatch(r"compiled in \d:\d\d:\d\d", lines[1]), lines


def test_predict_and_evaluate_as_in_stable_baselines3():
    import gymnasium as gym

    env = gym.make("CartPole-v1")
    agent = ivy_rl.Constant().initialize(env.observation_space, env.action_space, seed=0)
    obs, _ = env.reset(seed=0)
    action, state = agent.predict(obs, deterministic=True)
    assert state is None and env.action_space.contains(action)
    actions, _ = agent.predict(np.stack([obs, obs]))
    assert actions.shape == (2,)
    mean, std = ivy_rl.evaluate(agent, env, episodes=3)
    scores, lengths = ivy_rl.evaluate(agent, "CartPole-v1", 3, return_episode_rewards=True)
    assert mean == pytest.approx(np.mean(scores)) and std == pytest.approx(np.std(scores))
    assert scores == [float(n) for n in lengths]  # a reward of 1 per step
    with pytest.raises(ValueError, match="episodes must be an integer >= 1"):
        ivy_rl.evaluate(agent, env, 0)
