"""The trainer, its environments and checkpoints, the commands, and Ray workers."""

from __future__ import annotations

import importlib.util
import json
import os
import struct
import subprocess
import sys

import gymnasium as gym
import numpy as np
import pytest

import ivy
import ivy_rl
from ivy_rl import environments, schedules
from ivy_rl.trainer import Trainer, latest_checkpoint
from tests.ivy_rl._workers import assert_same_runs, observed

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TIME_COLUMNS = ("train/seconds", "train/epoch_seconds", "train/steps_per_second", "test/seconds")
PPO_TINY = dict(hidden_sizes=(16,), segment_size=24, batch_size=16, epochs=2)


def _rows(rows):
    return [{k: v for k, v in r.items() if k not in TIME_COLUMNS} for r in rows]


def _run(out, steps, *, resume=False, f="torch", keep=2, compile=False):
    trainer = Trainer(
        steps, epoch_steps=32, test_episodes=1, show_progress=False, keep_checkpoints=keep
    )
    return trainer.run(
        ivy_rl.PPO(**PPO_TINY),
        "CartPole-v1",
        workers=2,
        seed=5,
        f=f,
        compile=compile,
        out=str(out),
        resume=resume,
    )


def test_resuming_gives_the_log_of_an_uninterrupted_run(tmp_path):
    full = _run(tmp_path / "full", 128)
    assert _rows(_run(tmp_path / "again", 128)) == _rows(full)  # same seed, same log
    _run(tmp_path / "cut", 64)  # ends mid-episode and mid-segment (24 steps per worker)
    cut = tmp_path / "cut"
    assert latest_checkpoint(str(cut)).endswith("step_64")
    resumed = _run(cut, 128, resume=True)
    assert _rows(resumed) == _rows(full)
    on_disk = ivy_rl.logger.read_log(str(cut / "log.csv"))
    assert _rows(on_disk) == _rows(full)


def test_a_torch_checkpoint_loads_on_jax_and_tensorflow_and_continues_on_jax(tmp_path):
    _run(tmp_path / "run", 64)
    checkpoint = os.path.join(latest_checkpoint(str(tmp_path / "run")), "agent")
    obs_space, act_space = gym.spaces.Box(-np.inf, np.inf, (4,)), gym.spaces.Discrete(2)
    reference = ivy_rl.PPO(**PPO_TINY).initialize(obs_space, act_space, f="torch").load(checkpoint)
    obs = np.random.default_rng(0).normal(size=(3, 4))
    for framework in ("jax", "tensorflow"):
        agent = ivy_rl.PPO(**PPO_TINY).initialize(obs_space, act_space, f=framework)
        agent.load(checkpoint)
        for a, b in zip(ivy.nest.flatten_nest(agent.v)[0], ivy.nest.flatten_nest(reference.v)[0]):
            np.testing.assert_array_equal(ivy.to_numpy(a), ivy.to_numpy(b))
        np.testing.assert_array_equal(agent.test_step(obs), reference.test_step(obs))
    # the run goes on on jax, through an update (at 96 steps; compiled: jax's eager mode
    # compiles each operation of the update)
    rows = _run(tmp_path / "run", 96, resume=True, f="jax", compile=True)
    assert rows[-1]["train/steps"] == 96 and len(rows) == 3
    assert np.isfinite(rows[-1]["actor/loss"])


def test_a_loaded_agent_is_trained_from_its_weights(tmp_path):
    _run(tmp_path / "run", 64)
    checkpoint = os.path.join(latest_checkpoint(str(tmp_path / "run")), "agent")
    obs_space, act_space = gym.spaces.Box(-np.inf, np.inf, (4,)), gym.spaces.Discrete(2)
    agent = ivy_rl.PPO(**PPO_TINY).initialize(obs_space, act_space, f="torch", compile=False)
    agent.load(checkpoint)
    loaded = [ivy.to_numpy(a).copy() for a in ivy.nest.flatten_nest(agent.v)[0]]
    quick = Trainer(8, test_episodes=0, show_progress=False)  # 4 steps per worker: no update
    quick.run(agent, "CartPole-v1", workers=2, seed=5)
    for a, b in zip(ivy.nest.flatten_nest(agent.v)[0], loaded):
        np.testing.assert_array_equal(ivy.to_numpy(a), b)
    with pytest.raises(ValueError, match="initialized on torch"):
        quick.run(agent, "CartPole-v1", workers=2, f="jax")
    with pytest.raises(ValueError, match="initialized for observations"):
        quick.run(agent, "Acrobot-v1", workers=2)


class _Probe(ivy_rl.agents.Agent):
    """An agent that shows what the trainer does with the optional hooks: a differentiable
    agent's environment binding, its simulated steps, compilation counts, the run's progress
    (for schedules) and the device."""

    differentiable = True
    compiles = 0  # counted by hand here

    def __init__(self, recompile_at=None):
        super().__init__()
        self.recompile_at, self.calls, self.progress = recompile_at, [], []
        self.simulated_steps = self.compiles = self.learned = self.tested = 0

    def bind_environment(self, environment, env_kwargs):
        self.calls.append(("bind", environment, env_kwargs))

    def initialize(self, *spaces, **kwargs):
        self.calls.append(("initialize", kwargs.get("device")))
        return super().initialize(*spaces, **kwargs)

    def step(self, observations):
        return np.zeros(len(observations), np.int64)

    def test_step(self, observations):
        self.compiles += self.tested == 0  # the test policy compiles at its first call
        self.tested += 1
        return self.step(observations)

    def set_progress(self, progress):
        self.progress.append(progress)

    def update(self, observations, rewards, resets, terminations):
        if len(self.progress) % 4:
            return {}
        self.learned += 1
        self.simulated_steps += 10  # steps of its own differentiable rollouts
        self.compiles += self.learned in (1, self.recompile_at)
        return {"probe/loss": float(self.learned)}


def test_the_trainer_binds_counts_and_reports_the_agents_hooks(tmp_path):
    import warnings

    probe = _Probe()
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # no recompilation warning
        rows = Trainer(96, epoch_steps=32, test_episodes=1, show_progress=False).run(
            probe, "CartPole-v1", workers=2, f="numpy", device="cpu", out=str(tmp_path / "a"),
            env_kwargs={"sutton_barto_reward": True},
        )  # fmt: skip
    assert probe.calls == [
        ("bind", "CartPole-v1", {"sutton_barto_reward": True}),
        ("initialize", "cpu"),
    ]
    # the budget and the logged steps count the simulated steps too
    steps = [r["train/steps"] for r in rows]
    simulated = [r["train/simulated_steps"] for r in rows]
    environment_steps = 2 * len(probe.progress)
    assert steps[-1] == environment_steps + probe.simulated_steps == 96
    assert simulated[-1] == probe.simulated_steps == 10 * probe.learned
    assert all(b - a >= 32 for a, b in zip(steps[:-1], steps[1:-1]))
    # the progress handed to schedules: the fraction of the budget done before each update
    expected = [0.0]
    for k in range(1, len(probe.progress)):
        expected.append((2 * k + 10 * (k // 4)) / 96)
    np.testing.assert_allclose(probe.progress, expected)
    assert [r["train/compiles"] for r in rows][-1] == 2
    with open(tmp_path / "a" / "config.json") as fh:
        config = json.load(fh)
    assert config["device"] == "cpu" and config["threads"] == 1
    # a compilation after the first update is reported once
    with pytest.warns(RuntimeWarning, match=r"compiled again .* \(2 -> 3 compilations"):
        Trainer(96, epoch_steps=32, test_episodes=1, show_progress=False).run(
            _Probe(recompile_at=3), "CartPole-v1", workers=2, f="numpy"
        )


def test_threads_are_checked_recorded_and_set_on_torch(tmp_path):
    torch = pytest.importorskip("torch")
    from ivy_rl.threads import set_threads  # ivy.set_threads, under its old name

    assert set_threads is ivy.set_threads  # tested on every backend in tests/ivy/test_threads.py

    for bad in (0, -1, 1.5, True, "2"):
        with pytest.raises(ValueError, match="threads must be an integer >= 1"):
            Trainer(32, threads=bad)
        with pytest.raises(ValueError, match="threads must be an integer >= 1"):
            set_threads(ivy.get_framework(f="torch"), bad)
    before = torch.get_num_threads()
    try:
        Trainer(16, epoch_steps=16, test_episodes=0, show_progress=False, threads=2).run(
            "A2C", "CartPole-v1", workers=1, f="torch", compile=False, out=str(tmp_path / "r")
        )
        assert torch.get_num_threads() == 2
        with open(tmp_path / "r" / "config.json") as fh:
            assert json.load(fh)["threads"] == 2
        # resuming with other threads is refused, naming the setting
        with pytest.raises(ValueError, match="threads: this run 1, the saved run 2"):
            Trainer(32, epoch_steps=16, test_episodes=0, show_progress=False).run(
                "A2C", "CartPole-v1", workers=1, f="torch", out=str(tmp_path / "r"), resume=True
            )
        assert set_threads(ivy.get_framework(f="torch"), 1) == "torch.set_num_threads(1)"
        assert torch.get_num_threads() == 1
    finally:
        torch.set_num_threads(before)


def test_schedules_follow_the_runs_progress():
    lr = schedules.as_schedule("linear:3e-4")
    for p in (0.0, 0.3, 1.0, 1.7):
        assert lr(p) == pytest.approx(3e-4 * (1 - min(p, 1.0)), abs=1e-15)
    clip = schedules.as_schedule("linear:0.3:0.1")
    assert clip(0.5) == pytest.approx(0.2) and str(clip) == "linear:0.3:0.1"
    assert schedules.as_schedule(str(clip)) == clip
    assert schedules.as_schedule(0.2)(0.9) == 0.2
    assert schedules.as_schedule(clip) is clip and schedules.is_schedule("linear:1")
    assert not schedules.is_schedule(0.1)
    for bad in ("linear", "linear:a", "cosine:1e-3", "linear:1:2:3", True, None, [1e-3]):
        with pytest.raises((ValueError, TypeError), match="actor_lr"):
            schedules.as_schedule(bad, name="actor_lr")
    with pytest.raises(ValueError, match="finite"):
        lr(float("nan"))


def test_wrappers_by_name_and_module_environment_ids():
    wrappers = environments.resolve_wrappers(
        ["FlattenObservation", "gymnasium.wrappers:ClipAction", gym.wrappers.ClipReward]
    )
    assert wrappers == [
        gym.wrappers.FlattenObservation,
        gym.wrappers.ClipAction,
        gym.wrappers.ClipReward,
    ]
    with pytest.raises(ValueError, match="unknown wrapper 'os:path'"):
        environments.resolve_wrappers(["os:path"])
    with pytest.raises(ValueError, match="cannot import 'no_such_pkg'"):
        environments.resolve_wrappers(["no_such_pkg:Wrapper"])
    environments.check_environment_id("gymnasium.envs.classic_control:CartPole-v1")
    with pytest.raises(ValueError, match="unknown environment.*did you mean: CartPole-v1"):
        environments.check_environment_id("gymnasium:CartPol-v1")
    env = environments.make_env("FrozenLake-v1", wrappers=["FlattenObservation"])
    assert env.observation_space.shape == (16,)
    env.close()


def test_time_limits_are_terminal_with_the_time_feature():
    # time awareness (Pardo et al., 2018): with the remaining time as an input, the time limit
    # is part of the task and the last step is terminal; without it, a reset to bootstrap
    for time_feature in (True, False):
        workers = environments.Workers("Pendulum-v1", 2, seed=0, time_feature=time_feature)
        workers.start()
        for _ in range(200):
            _, infos = workers.step(np.zeros((2, 1), np.float32))
        assert infos["resets"].all()
        assert infos["terminations"].all() == time_feature
        assert not infos["terminations"].any() or time_feature
        if time_feature:
            np.testing.assert_allclose(infos["observations"][:, -1], 0.0)
        workers.close()


def test_workers_keep_time_limits_apart_from_terminations():
    workers = environments.Workers("Pendulum-v1", 2, seed=0)
    workers.start()
    for t in range(200):
        next_obs, infos = workers.step(np.zeros((2, 1), np.float32))
        if t < 199:
            assert not infos["resets"].any()
            np.testing.assert_array_equal(next_obs, infos["observations"])
    # Pendulum's time limit: a reset that is not a termination; the true last observation is
    # given apart from the first observation of the next episode
    assert infos["resets"].all() and not infos["terminations"].any()
    assert not np.allclose(next_obs, infos["observations"])
    cart = environments.Workers("CartPole-v1", 1, seed=0)
    cart.start()
    for _ in range(500):
        _, infos = cart.step(np.ones(1, np.int64))
        if infos["resets"][0]:
            break
    assert infos["terminations"][0]
    workers.close()
    cart.close()


def test_async_workers_match_sync_workers():
    # async workers start by forkserver (this process has jax threads running); the
    # time-awareness wrapper travels to them
    actions = np.random.default_rng(0).integers(0, 2, size=(60, 3))
    sync = observed("sync", 3, 2, actions, time_feature=True)
    assert_same_runs(sync, observed("async", 3, 2, actions, time_feature=True))
    first, after_one = sync[0], sync[1]
    assert first.shape == (3, 5)
    np.testing.assert_allclose(first[:, -1], 1.0)
    np.testing.assert_allclose(after_one[:, -1], 1.0 - 1.0 / 500, rtol=1e-6)


def test_batched_workers_match_sync_workers_and_restore_from_checkpoints():
    """``vectorization='batched'``: every worker of an ivy_gym task in one call of the physics,
    with what sync workers of the same task see (episodes ending and restarting with their own
    seeds), and a checkpoint's replay brings new workers to the same state."""
    actions = np.random.default_rng(0).integers(0, 2, size=(80, 5))
    sync = observed("sync", 5, 2, actions, env_id="ivy_gym/CartPole-v1")
    assert_same_runs(sync, observed("batched", 5, 2, actions, env_id="ivy_gym/CartPole-v1"))
    assert sum(resets.sum() for resets in sync[4::4]) >= 5  # episodes ended and restarted
    first = environments.Workers("ivy_gym/CartPole-v1", 5, seed=2, vectorization="batched")
    first.start()
    for a in actions[:30]:
        first.step(a)
    arrays, meta = first.state_dict()
    second = environments.Workers("ivy_gym/CartPole-v1", 5, seed=9, vectorization="batched")
    np.testing.assert_array_equal(second.load_state_dict(arrays, meta), first.observations)
    for a in actions[30:]:
        assert_same_runs([*first.step(a)[1].values()], [*second.step(a)[1].values()])
    with pytest.raises(ValueError, match="'batched' steps every copy of an ivy_gym task"):
        environments.Workers("CartPole-v1", 2, vectorization="batched")
    with pytest.raises(ValueError, match="no wrappers or time feature"):
        environments.Workers("ivy_gym/CartPole-v1", 2, vectorization="batched", time_feature=True)


def test_time_feature_counts_down_to_the_time_limit():
    env = environments.TimeFeature(gym.make("Pendulum-v1"))
    obs, _ = env.reset(seed=0)
    assert obs.shape == (4,) and obs[-1] == 1.0
    for _t in range(200):
        obs, _, _, truncated, _ = env.step(np.zeros(1, np.float32))
    np.testing.assert_allclose(obs[-1], 0.0)
    assert truncated
    short = environments.TimeFeature(gym.make("Pendulum-v1"), max_steps=4)
    short.reset(seed=0)
    np.testing.assert_allclose(short.step(np.zeros(1, np.float32))[0][-1], 0.75)
    with pytest.raises(TypeError, match="Box observation space"):
        environments.TimeFeature(gym.make("FrozenLake-v1"))


def _scalars(folder):
    """Scalars of TensorBoard event files, read from the records without tensorflow."""
    from tensorboard.compat.proto.event_pb2 import Event

    values = {}
    for name in os.listdir(folder):
        with open(os.path.join(folder, name), "rb") as fh:
            data = fh.read()
        i = 0
        while i < len(data):
            (length,) = struct.unpack("<Q", data[i : i + 8])
            event = Event.FromString(data[i + 12 : i + 12 + length])
            i += 12 + length + 4
            for v in event.summary.value:
                values.setdefault(v.tag, []).append(v.simple_value)
    return values


def test_train_plot_and_play_commands(tmp_path, capsys):
    from ivy_rl import play, plot, train

    out = str(tmp_path / "ppo-cartpole-0")
    rows = train.main(
        [
            "--agent",
            "PPO",
            "--environment",
            "CartPole-v1",
            "--framework",
            "jax",
            "--steps",
            "64",
            "--epoch-steps",
            "32",
            "--workers",
            "2",
            "--seed",
            "0",
            "--out",
            out,
            "--agent-kwargs",
            json.dumps(PPO_TINY),
            "--env-kwargs",
            '{"sutton_barto_reward": false}',
            "--tensorboard",
            "--test-episodes",
            "1",
        ]
    )
    assert len(rows) == 2
    header = open(os.path.join(out, "log.csv")).readline().strip().split(",")
    for column in (
        "train/steps",
        "train/seconds",
        "train/episode_score/mean",
        "test/episode_score/mean",
        "test/episode_length/mean",
        "actor/loss",
        "critic/loss",
    ):
        assert column in header, column
    assert "test/episode_score/mean" in capsys.readouterr().out  # the console table
    scalars = _scalars(os.path.join(out, "tensorboard"))
    np.testing.assert_allclose(scalars["train/steps"], [32, 64])
    assert len(scalars["actor/loss"]) == 1  # the first epoch had no update yet
    curves = plot.main([out, out, "--out", str(tmp_path / "curves.png"), "--labels", "a", "b"])
    assert set(curves) == {"a", "b"} and os.path.getsize(tmp_path / "curves.png") > 1000
    results = play.main(
        [out, "--episodes", "1", "--video", str(tmp_path / "play.gif"), "-f", "torch"]
    )
    assert results[0]["length"] >= 1 and os.path.getsize(tmp_path / "play.gif") > 1000


def test_command_line_errors_list_what_is_available(tmp_path):
    from ivy_rl import play, train

    with pytest.raises(ValueError, match="available agents"):
        train.main(["--agent", "NoSuchAgent"])
    # the three closest ids, not Gymnasium's whole registry
    with pytest.raises(
        ValueError, match=r"did you mean: CartPole-v1, CartPole-v0, [^,]+\? \("
    ) as error:
        train.main(["--environment", "CartPol-v1"])
    assert len(str(error.value)) < 200
    done = subprocess.run(
        [sys.executable, "-m", "ivy_rl.train", "--agent", "NoSuchAgent"],
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": ROOT},
        cwd=ROOT,
    )
    assert done.returncode == 2 and "available agents: A2C, PPO" in done.stderr
    with pytest.raises(FileNotFoundError, match="not a run folder"):
        play.main([str(tmp_path)])


def test_ray_workers_match_sync_workers():
    pytest.importorskip("ray", reason="Ray workers need the [distributed] extra")
    # in a process of its own, without jax (see tests/ivy_rl/_workers.py)
    done = subprocess.run(
        [sys.executable, "-m", "tests.ivy_rl._workers"],
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHONPATH": ROOT},
        cwd=ROOT,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    assert "ray workers: ok" in done.stdout


def test_a_globally_set_framework_gives_the_same_log(tmp_path):
    """Agents compile with ``ivy.compile_fn(fn, f=xp)``: under ``ivy.set_framework`` that is
    the backend's composition, which takes the same ``f``; the run's log does not change."""
    expected = _rows(_run(tmp_path / "plain", 64, f="jax", compile=True))
    with ivy.set_framework("jax"):
        assert _rows(_run(tmp_path / "set", 64, f="jax", compile=True)) == expected


def test_the_replay_saves_its_filled_rows_and_loads_them_into_the_whole_ring():
    from ivy_rl.buffers import TransitionReplay

    xp = ivy.get_framework(f="numpy")
    rng = np.random.default_rng(0)
    replay = TransitionReplay(1_000, return_steps=2)
    for step in range(7):
        replay.store(
            observations=rng.normal(size=(2, 3)), actions=rng.normal(size=(2, 1)),
            rewards=rng.normal(size=2), next_observations=rng.normal(size=(2, 3)),
            resets=np.zeros(2, bool), terminations=np.zeros(2, bool),
        )  # fmt: skip
        if step == 4:
            replay.flush(xp)
    state = replay.state_dict()
    assert state["arrays.observations"].shape == (10, 3)  # 5 flushed steps of 2 workers
    assert state["staged.observations"].shape == (2, 2, 3)  # 2 staged steps
    again = TransitionReplay(1_000, return_steps=2)
    again.load_state_dict(state, xp)
    assert again.arrays["observations"].shape == (1_000, 3)
    for replica in (replay, again):
        replica.flush(xp)
    for key, value in replay.arrays.items():
        np.testing.assert_array_equal(again.arrays[key], value)
    draw = [r.windows(np.random.default_rng(1), 2, 4) for r in (replay, again)]
    np.testing.assert_array_equal(*draw)
    # a state saved with the whole ring (checkpoints before) loads too
    full = {**replay.state_dict(), **{f"arrays.{k}": v for k, v in replay.arrays.items()}}
    again.load_state_dict(full, xp)
    np.testing.assert_array_equal(again.arrays["rewards"], replay.arrays["rewards"])


def test_ivy_gym_mujoco_tasks_run_on_the_runs_compiling_framework():
    """An ivy_gym MuJoCo task's workers and test environment run on the run's framework where
    its compiler keeps loops (a compiled Hopper step is 18x faster on jax than on numpy);
    elsewhere, and for the classic tasks and Gymnasium's own, the facade's default; a
    framework the user gives is kept."""
    from ivy_rl.environments import run_env_kwargs

    pytest.importorskip("jax")
    assert run_env_kwargs("ivy_gym/Hopper-v5", None, "jax") == {"framework": "jax"}
    assert run_env_kwargs("ivy_gym/Ant-v5", {"healthy_reward": 2.0}, ivy.jax) == {
        "healthy_reward": 2.0,
        "framework": "jax",
    }
    assert run_env_kwargs("ivy_gym/Hopper-v5", {"framework": "numpy"}, "jax") == {
        "framework": "numpy"
    }
    assert run_env_kwargs("ivy_gym/Hopper-v5", {}, "numpy") == {}
    assert run_env_kwargs("ivy_gym/Pendulum-v1", {}, "jax") == {}
    assert run_env_kwargs("Hopper-v5", {}, "jax") == {}
    if importlib.util.find_spec("torch") is not None:  # torch.compile unrolls loops
        assert run_env_kwargs("ivy_gym/Hopper-v5", {}, "torch") == {}
