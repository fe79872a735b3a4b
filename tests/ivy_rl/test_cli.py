"""The commands for long unattended runs: run folders that are never silently overwritten,
``--resume`` from ``config.json``, settings checked before anything is written, damaged
checkpoints, one-line errors, ``module:EnvId``, wrappers by name, the best model and ``play``'s
summary."""

from __future__ import annotations

import json
import os

import numpy as np
import pytest

from ivy_rl import _cli, play, plot, train
from ivy_rl.logger import read_log
from ivy_rl.trainer import CheckpointError, checkpoints
from tests.ivy_rl.conftest import quick

TIME_COLUMNS = ("train/seconds", "train/epoch_seconds", "train/steps_per_second", "test/seconds")
PPO_TINY = {"hidden_sizes": [16], "segment_size": 8, "batch_size": 16, "epochs": 1}


def _uniform(out, *extra):
    """A cheap run: random actions on CartPole, 16 steps per epoch."""
    base = ["--agent", "Uniform", "--workers", "2", "--epoch-steps", "16", "--quiet"]
    return train.main([*base, "--test-episodes", "1", "--out", str(out), *extra])


def _rows(rows):
    return [{k: v for k, v in r.items() if k not in TIME_COLUMNS} for r in rows]


def _config(out):
    with open(os.path.join(out, "config.json")) as fh:
        return json.load(fh)


def _listing(folder):
    found = {}
    for root, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(root, name)
            with open(path, "rb") as fh:
                found[os.path.relpath(path, folder)] = fh.read()
    return found


def test_a_used_output_folder_is_refused_unless_resume_or_overwrite(tmp_path):
    out = tmp_path / "run"
    _uniform(out, "--steps", "48")
    assert [os.path.basename(p) for p in checkpoints(str(out))] == ["step_32", "step_48"]
    before = _listing(out)
    with pytest.raises(ValueError, match="not empty.*--resume.*--overwrite"):
        _uniform(out, "--steps", "16", "--seed", "3")
    assert _listing(out) == before  # nothing was written
    with pytest.raises(ValueError, match="choose one"):
        _uniform(out, "--resume", "--overwrite")
    # a folder that holds something else is refused too
    (tmp_path / "notes").mkdir()
    (tmp_path / "notes" / "todo.txt").write_text("x")
    with pytest.raises(ValueError, match="not empty"):
        _uniform(tmp_path / "notes", "--steps", "16")
    # --overwrite starts again: the old checkpoints and log rows are gone
    rows = _uniform(out, "--steps", "16", "--seed", "3", "--overwrite")
    assert len(rows) == 1 and len(read_log(str(out / "log.csv"))) == 1
    assert [os.path.basename(p) for p in checkpoints(str(out))] == ["step_16"]
    assert _config(out)["seed"] == 3


def test_resume_alone_continues_the_run_as_configured(tmp_path):
    # A run on tensorflow, resumed without -f, stays on tensorflow (it used to switch to the
    # default, torch); it continues on torch when asked explicitly; flags that contradict the
    # run are errors naming the flag.
    out = tmp_path / "ppo"
    args = ["--agent", "PPO", "--agent-kwargs", json.dumps(PPO_TINY), "--eager", "-f", "tensorflow"]
    first = _uniform(out, *args, "--steps", "32", "--seed", "4", "--agent", "PPO")
    assert _config(out)["framework"] == "tensorflow" and len(first) == 2
    before = _listing(out)
    for flag, value in (
        ("--seed", "5"),
        ("--agent-kwargs", json.dumps({**PPO_TINY, "epochs": 2})),
        ("--environment", "Pendulum-v1"),
        ("--epoch-steps", "8"),
        ("--threads", "2"),
    ):
        with pytest.raises(ValueError, match=f"{flag} .*the run has"):
            train.main(["--out", str(out), "--resume", flag, value])
    assert _listing(out) == before
    rows = train.main(["--out", str(out), "--resume", "--steps", "48", "--quiet"])
    config = _config(out)
    assert config["framework"] == "tensorflow" and config["seed"] == 4 and config["steps"] == 48
    assert config["agent_kwargs"] == PPO_TINY and config["epoch_steps"] == 16
    assert config["threads"] == 1  # the saved run's value (the default), kept on resume
    assert [r["train/steps"] for r in rows] == [16, 32, 48]
    assert _rows(rows[:2]) == _rows(first)
    assert np.isfinite(rows[-1]["actor/loss"])  # it learned after the resume
    rows = train.main(["--out", str(out), "--resume", "--steps", "64", "-f", "torch"])
    assert _config(out)["framework"] == "torch" and rows[-1]["train/steps"] == 64


@pytest.mark.parametrize(
    "flags, message",
    [
        (["--epoch-steps", "-8"], "--epoch-steps must be an integer >= 1"),
        (["--test-episodes", "-3"], "--test-episodes must be an integer >= 0"),
        (["--steps", "0"], "--steps must be"),
        (["--save-steps", "0"], "--save-steps must be"),
        (["--workers", "0"], "--workers must be"),
        (["--keep-checkpoints", "0"], "--keep-checkpoints must be"),
        (["--seed", "-1"], "--seed must be"),
        (["--threads", "0"], "--threads must be an integer >= 1"),
        (["--ray-groups", "2"], "--ray-groups needs --vectorization ray"),
        (["--device", "quantum:0"], "--device 'quantum:0' is not a device"),
        (["--framework", "caffe"], "Unknown framework 'caffe'"),
        (["--wrappers", "FlattenObservations"], "did you mean: FlattenObservation"),
        (["--environment", "no_such_module:Task-v0"], "cannot import the module"),
        (["--agent", "PPQ"], "unknown agent 'PPQ'"),
        (["--agent", "PPO", "--agent-kwargs", '{"hidden_sizes": 64}'], "hidden_sizes"),
        (["--agent", "PPO", "--agent-kwargs", '{"segment_size": "32"}'], "segment_size"),
    ],
)
def test_settings_are_checked_before_anything_is_written(tmp_path, flags, message):
    out = tmp_path / "run"
    with pytest.raises((ValueError, TypeError), match=message):
        train.main(["--out", str(out), "--steps", "32", "--workers", "1", *flags])
    assert not out.exists()


def test_damaged_checkpoints_are_named_and_the_previous_one_is_used(tmp_path):
    out = tmp_path / "run"
    full = _uniform(tmp_path / "full", "--steps", "64")
    _uniform(out, "--steps", "48")
    last = out / "checkpoints" / "step_48"
    arrays = last / "agent" / "arrays.npz"
    arrays.write_bytes(arrays.read_bytes()[:20])  # a copy cut short
    with pytest.warns(RuntimeWarning, match="step_48/agent/arrays.npz is damaged.*step_32"):
        rows = _uniform(out, "--resume", "--steps", "64")
    assert _rows(rows) == _rows(full)  # from step 32 on, as if nothing had happened
    # every checkpoint damaged: an error that names each file
    for path in checkpoints(str(out)):
        with open(os.path.join(path, "trainer.json"), "w") as fh:
            fh.write('{"steps": 4')
    with pytest.raises(CheckpointError, match=r"step_64/trainer.json is not valid JSON"):
        _uniform(out, "--resume", "--steps", "80")
    with pytest.raises(CheckpointError, match=r"step_48/trainer.json"):
        play.main([str(out), "--episodes", "1"])


def test_commands_give_one_line_errors(tmp_path, capsys):
    missing = str(tmp_path / "missing")
    for main, argv in (
        (plot.main, [missing, "--out", str(tmp_path / "c.png")]),
        (play.main, [missing]),
        (train.main, ["--out", missing, "--resume"]),
    ):
        with pytest.raises(SystemExit) as stop:
            _cli.command_line(main, argv)
        assert stop.value.code == 2
        err = capsys.readouterr().err
        assert err.startswith("error: ") and err.count("\n") == 1, err
        assert "missing" in err
    (tmp_path / "empty").mkdir()
    with pytest.raises(FileNotFoundError, match="not a run folder: it has no log.csv"):
        plot.main([str(tmp_path / "empty")])


def test_module_environment_ids_and_wrappers_by_name(tmp_path, monkeypatch):
    # an environment registered by the user's own module, with Discrete observations that
    # FlattenObservation turns into one-hot vectors the agents accept
    (tmp_path / "my_tasks.py").write_text(
        "import gymnasium\n"
        "gymnasium.register(id='MyLake-v0', max_episode_steps=12,\n"
        "    entry_point='gymnasium.envs.toy_text.frozen_lake:FrozenLakeEnv')\n"
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    args = ["--agent", "PPO", "--agent-kwargs", json.dumps(PPO_TINY), "--eager"]
    args += ["--environment", "my_tasks:MyLake-v0", "--steps", "32"]
    with pytest.raises(TypeError, match="Box"):
        _uniform(tmp_path / "plain", *args)
    out = tmp_path / "flat"
    rows = _uniform(out, *args, "--wrappers", "FlattenObservation")
    assert rows[-1]["train/steps"] == 32 and np.isfinite(rows[-1]["actor/loss"])
    config = _config(out)
    assert config["wrappers"] == ["FlattenObservation"]
    assert config["environment"] == "my_tasks:MyLake-v0"
    results = play.main([str(out), "--episodes", "2"])  # play rebuilds the same wrappers
    assert all(1 <= r["length"] <= 12 for r in results)


def test_the_best_model_is_kept_and_play_summarises_its_episodes(tmp_path, capsys):
    out = tmp_path / "run"
    rows = _uniform(out, "--steps", "64", "--test-episodes", "2")
    scores = [r["test/episode_score/mean"] for r in rows]
    with open(out / "best" / "best.json") as fh:
        best = json.load(fh)
    assert best["test_score"] == max(scores)
    assert best["steps"] == rows[int(np.argmax(scores))]["train/steps"]
    assert os.path.exists(out / "best" / "agent" / "agent.json")
    capsys.readouterr()
    results = play.main([str(out), "--episodes", "3", "--best"])
    printed = capsys.readouterr().out.strip().splitlines()[-1]
    values = np.array([r["score"] for r in results])
    assert printed.startswith(f"score {values.mean():.2f} +- {values.std():.2f}")
    assert f"(min {values.min():.2f}, max {values.max():.2f}) over 3 episodes" in printed


def test_play_summary_reports_the_mean_and_spread():
    line = play.summary([{"score": 10.0, "length": 10}, {"score": 20.0, "length": 30}])
    assert line == "score 15.00 +- 5.00 (min 10.00, max 20.00) over 2 episodes, length 20.0"


def test_run_files_default_folders_exact_steps_and_a_log_kept_as_written(tmp_path, monkeypatch):
    # the default folder names the framework: the same run on a second framework is its own
    monkeypatch.chdir(tmp_path)
    base = ["--agent", "Uniform", "--workers", "2", "--steps", "32", "--epoch-steps", "16"]
    for framework in ("numpy", "torch"):
        train.main([*base, "--test-episodes", "1", "--quiet", "-f", framework])
        if framework == "numpy":  # resumed on another framework, without --out: continued there
            rows = train.main([*base, "--resume", "--steps", "48", "-f", "torch", "--quiet"])
            assert rows[-1]["train/steps"] == 48
            assert (
                _config(tmp_path / "runs" / "Uniform-CartPole-v1-numpy-0")["framework"] == "torch"
            )
    assert sorted(os.listdir(tmp_path / "runs")) == [
        "Uniform-CartPole-v1-numpy-0",
        "Uniform-CartPole-v1-torch-0",
    ]
    # --steps is exact: a value that is not whole steps of the workers is refused, naming both
    with pytest.raises(
        ValueError, match=r"--steps 9100 is not a multiple of --workers 8.*9096 or 9104"
    ):
        train.main(["--steps", "9100", "--workers", "8", "--out", str(tmp_path / "x")])
    assert not (tmp_path / "x").exists()
    rows = _uniform(tmp_path / "odd", "--steps", "36", "--workers", "3", "--epoch-steps", "12")
    assert [r["train/steps"] for r in rows] == [12, 24, 36]
    # the rows before a resume are kept as written (integers stay integers)
    out = tmp_path / "runs" / "Uniform-CartPole-v1-torch-0"
    before = (out / "log.csv").read_text().splitlines()
    train.main(["--out", str(out), "--resume", "--steps", "48", "--quiet"])
    after = (out / "log.csv").read_text().splitlines()
    assert after[: len(before)] == before and len(after) == len(before) + 1
    assert after[1].split(",")[0] == "16"


SAC_TINY = dict(hidden_sizes=[16], start_steps=16, update_after=16, update_every=8)
SAC_TINY.update(batch_size=16, batch_iterations=1, replay_size=100_000)


def _arrays(folder):
    with np.load(os.path.join(folder, "arrays.npz")) as data:
        return {key: data[key] for key in data.files}


def _sac(f, seed=0):
    import gymnasium as gym

    from ivy_rl.agents import make

    env = gym.make("Pendulum-v1")
    agent = make("SAC", environment="Pendulum-v1", **SAC_TINY)
    return agent.initialize(env.observation_space, env.action_space, seed=seed, f=f, compile=False)


def test_checkpoints_hold_the_filled_replay_and_best_what_play_needs(diff_backend, tmp_path, capfd):
    # SAC, whose checkpoints hold a replay, target networks and three optimisers, on each
    # backend: 32 steps on 2 workers, test episodes of 20 steps
    out = tmp_path / "sac"
    args = [
        "--agent",
        "SAC",
        "--environment",
        "Pendulum-v1",
        "--agent-kwargs",
        json.dumps(SAC_TINY),
    ]
    args += ["--env-kwargs", '{"max_episode_steps": 20}', "-f", diff_backend, *quick(diff_backend)]
    rows = _uniform(out, *args, "--steps", "32", "--epoch-steps", "32")
    assert [r["train/steps"] for r in rows] == [32]
    checkpoint = out / "checkpoints" / "step_32" / "agent"
    saved = _arrays(checkpoint)
    rows = {k: v.shape[0] for k, v in saved.items() if k.startswith("replay/arrays.")}
    # 32 steps staged on 2 workers, flushed before each update: the filled rows, not 100,000
    assert rows and set(rows.values()) <= {30, 32}, rows
    optimizer = {k: v for k, v in saved.items() if k.startswith("optimizer/")}
    assert len(optimizer) > 10  # the actor's, critics' and temperature's Adam moments and steps
    # best/ holds what acting needs: the weights (and targets), the normaliser, the settings
    best = _arrays(out / "best" / "agent")
    assert {k.split("/")[0] for k in best} == {"v", "targets", "observation_normalizer"}
    for key, value in best.items():  # the one epoch's agent, the checkpoint's
        np.testing.assert_array_equal(value, saved[key], err_msg=key)
    with open(out / "best" / "agent" / "agent.json") as fh:
        assert json.load(fh)["training_state"] is False
    # predict from best/ acts as the checkpoint's agent; its optimisers are a new agent's
    observations = np.random.default_rng(0).normal(size=(5, 3)).astype(np.float32)
    from_best, from_checkpoint = _sac(diff_backend).load(out / "best" / "agent"), _sac(diff_backend)
    from_checkpoint.load(checkpoint)
    np.testing.assert_allclose(
        from_best.predict(observations, deterministic=True)[0],
        from_checkpoint.predict(observations, deterministic=True)[0],
        rtol=1e-6,
    )
    for agent, name in ((from_best, "best"), (_sac(diff_backend), "new")):
        agent.save(tmp_path / name)
    new, reloaded = _arrays(tmp_path / "new"), _arrays(tmp_path / "best")
    for key in optimizer:
        np.testing.assert_array_equal(reloaded[key], new[key], err_msg=key)
    # a checkpoint (what resuming loads) restores the optimiser states exactly
    from_checkpoint.save(tmp_path / "again")
    again = _arrays(tmp_path / "again")
    assert saved["optimizer/actor/step"] > 0 and new["optimizer/actor/step"] == 0
    for key, value in optimizer.items():
        np.testing.assert_array_equal(again[key], value, err_msg=key)
    # play --best on the run's framework
    capfd.readouterr()
    results = play.main([str(out), "--best", "--episodes", "1", "--video", str(tmp_path / "p.gif")])
    assert results[0]["length"] == 20 and os.path.getsize(tmp_path / "p.gif") > 1000
    captured = capfd.readouterr()
    assert "XDG_RUNTIME_DIR" not in captured.err and "wrote " in captured.out
