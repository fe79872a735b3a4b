"""Schedules of learning rates and PPO's clipping over a run: the formula, the settings' checks,
the scheduled update against the constant one at the same progress, no retracing when the value
changes, checkpoints, and the trainer and command line telling agents the progress."""

from __future__ import annotations

import json
import os

import gymnasium as gym
import numpy as np
import pytest

import ivy
import ivy_rl
from ivy_rl import train
from ivy_rl.schedules import LinearSchedule, as_schedule
from ivy_rl.trainer import Trainer
from tests.conftest import capable

PPO_TINY = dict(hidden_sizes=[8], segment_size=4, batch_size=4, epochs=1)
SAC_TINY = dict(
    hidden_sizes=[8],
    batch_size=4,
    update_after=4,
    update_every=4,
    batch_iterations=2,
    start_steps=0,
    replay_size=64,
)


def test_linear_schedule_follows_the_formula_and_round_trips():
    start, end = 3e-4, 1e-5
    schedule = as_schedule(f"linear:{start}:{end}")
    for progress in (0.0, 0.5, 1.0):
        assert schedule(progress) == pytest.approx(start + (end - start) * progress, rel=1e-12)
    down = as_schedule("linear:3e-4")
    assert [down(p) for p in (0.0, 0.5, 1.0)] == pytest.approx([3e-4, 1.5e-4, 0.0], rel=1e-12)
    assert down(1.5) == 0.0 and down(-1.0) == 3e-4  # clamped outside the run
    assert as_schedule(str(schedule)) == schedule and str(down) == "linear:0.0003:0.0"
    assert as_schedule(0.2)(0.7) == 0.2


def test_linear_schedule_ends_exactly_at_its_end_values():
    # start + (end - start) * 1 rounds to 0.00010000000000000005 for these: the run ended
    # on a value it was never given
    for start, end in ((1e-3, 1e-4), (3e-4, 1e-5), (0.2, 0.1), (-1.0, 0.3)):
        schedule = LinearSchedule(start, end)
        assert schedule(0.0) == start and schedule(1.0) == end
        assert schedule(2.0) == end and schedule(-1.0) == start


def test_agents_accept_schedules_and_refuse_bad_ones_by_name():
    agent = ivy_rl.agents.make("PPO", actor_lr="linear:1e-3", ratio_clip=LinearSchedule(0.3, 0.1))
    assert agent.config["actor_lr"] == "linear:0.001:0.0"
    assert agent.config["ratio_clip"] == "linear:0.3:0.1"
    json.dumps(agent.config)  # the JSON form
    assert agent.scheduled_values(0.5) == pytest.approx(
        {"actor_lr": 5e-4, "critic_lr": agent.config["critic_lr"], "ratio_clip": 0.2}
    )
    for bad in ("linear:abc", "cosine:1e-3", "linear:1e-3:2:3", "linear:-1e-3", "linear:0"):
        with pytest.raises(ValueError, match="'actor_lr'.*linear:<start>"):
            ivy_rl.agents.make("PPO", actor_lr=bad)
    with pytest.raises(ValueError, match="'ratio_clip'"):
        ivy_rl.agents.make("PPO", ratio_clip="linear:0.2:-0.1")
    with pytest.raises(ValueError, match="'dual_lr'"):
        ivy_rl.agents.make("MPO", dual_lr="cosine:1e-3")

    # an agent that reads a setting as a constant refuses a schedule, naming it
    class ConstantRateAPG(ivy_rl.agents.APG):
        scheduled = ()

    with pytest.raises(
        ValueError, match="ConstantRateAPG does not schedule the setting 'actor_lr'"
    ):
        ConstantRateAPG(actor_lr="linear:1e-3")
    assert ivy_rl.agents.make("APG", actor_lr="linear:1e-3").scheduled_values(0.5) == {
        "actor_lr": pytest.approx(5e-4)
    }


def _run(name, env_id, backend, progress, steps, compile=True, **settings):
    """An agent after ``steps`` steps of random observations, told ``progress[i]`` before each
    update; returns the agent and its compile counts after each step."""
    env = gym.make(env_id)
    caps = ivy.framework_handler.capabilities(backend)
    agent = ivy_rl.agents.make(name, **settings).initialize(
        env.observation_space,
        env.action_space,
        seed=0,
        f=backend,
        dtype="float64" if caps.float64 else "float32",
        compile=compile,
    )
    rng = np.random.default_rng(1)
    shape = (2,) + env.observation_space.shape
    compiles = []
    for i in range(steps):
        agent.step(rng.normal(size=shape))
        agent.set_progress(progress[i])
        agent.update(
            rng.normal(size=shape), rng.normal(size=2), np.zeros(2, bool), np.zeros(2, bool)
        )
        compiles.append(agent.compiles)
    return agent, compiles


def _weights(agent):
    return [np.asarray(ivy.to_numpy(a)) for a in ivy.nest.flatten_nest(agent.v)[0]]


@pytest.mark.parametrize(
    "name, env_id, tiny, scheduled, constant, start",
    [
        (
            "PPO",
            "CartPole-v1",
            PPO_TINY,
            dict(actor_lr="linear:2e-3", critic_lr="linear:4e-3:0", ratio_clip="linear:0.1:0.3"),
            dict(actor_lr=1e-3, critic_lr=2e-3, ratio_clip=0.2),
            dict(actor_lr=2e-3, critic_lr=4e-3, ratio_clip=0.1),
        ),
        (
            "SAC",
            "Pendulum-v1",
            SAC_TINY,
            dict(actor_lr="linear:2e-3", critic_lr="linear:2e-3", temperature_lr="linear:2e-3"),
            dict(actor_lr=1e-3, critic_lr=1e-3, temperature_lr=1e-3),
            dict(actor_lr=2e-3, critic_lr=2e-3, temperature_lr=2e-3),
        ),
    ],
)
def test_a_scheduled_update_is_the_constant_update_at_its_progress(
    diff_backend, name, env_id, tiny, scheduled, constant, start
):
    halfway = [0.5] * 4
    # compiled where compiling is quick (torch.compile took 30 to 50 s per agent here; its
    # compiled schedules are run by test_a_changing_progress_compiles_nothing_new)
    compiled = capable(diff_backend, "fast_graph")
    agent, _ = _run(name, env_id, diff_backend, halfway, 4, compiled, **tiny, **scheduled)
    # the references run eagerly: the scheduled run compiled takes its values as arrays
    same, _ = _run(name, env_id, diff_backend, halfway, 4, False, **tiny, **constant)
    first, _ = _run(name, env_id, diff_backend, halfway, 4, False, **tiny, **start)
    rtol = 1e-9 if agent.dtype == "float64" else 1e-5
    for a, b in zip(_weights(agent), _weights(same)):
        np.testing.assert_allclose(a, b, rtol=rtol, atol=rtol)
    # the values at the start would give other weights: the schedule was read at 0.5
    assert any(not np.allclose(a, b) for a, b in zip(_weights(agent), _weights(first)))


def test_a_changing_progress_compiles_nothing_new(diff_backend):
    progress = [0.1, 0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9]
    agent, compiles = _run(
        "PPO", "CartPole-v1", diff_backend, progress, 8, actor_lr="linear:1e-3", **PPO_TINY
    )
    assert agent.updates == 2  # after steps 4 and 8, at progress 0.4 and 0.9
    assert len(set(compiles[3:])) == 1, compiles


def test_a_checkpoint_keeps_the_schedule_and_progress(tmp_path):
    agent, _ = _run(
        "PPO", "CartPole-v1", "torch", [0.25] * 4, 4, actor_lr="linear:1e-3:1e-4", **PPO_TINY
    )
    agent.save(tmp_path / "ckpt")
    env = gym.make("CartPole-v1")
    again = ivy_rl.agents.make("PPO", **agent.config).initialize(
        env.observation_space, env.action_space, seed=3, f="jax", dtype=agent.dtype
    )
    again.load(tmp_path / "ckpt")
    assert again.config["actor_lr"] == "linear:0.001:0.0001"
    assert again.progress == 0.25
    assert again.scheduled_values() == agent.scheduled_values()
    other = ivy_rl.agents.make("PPO", **{**agent.config, "actor_lr": 1e-3}).initialize(
        env.observation_space, env.action_space, f="jax", dtype=agent.dtype
    )
    with pytest.raises(ValueError, match="actor_lr: 'linear:0.001:0.0001' in the checkpoint"):
        other.load(tmp_path / "ckpt")


def test_the_trainer_and_command_line_drive_the_schedule(tmp_path):
    agent = ivy_rl.agents.make("PPO", actor_lr="linear:1e-3", **PPO_TINY)
    Trainer(16, epoch_steps=16, test_episodes=1, show_progress=False).run(
        agent, "CartPole-v1", workers=2, seed=0, f="jax"
    )
    # told before each update call: 14 of 16 steps were done before the last
    assert agent.progress == pytest.approx(14 / 16)
    assert agent.scheduled_values()["actor_lr"] == pytest.approx(1e-3 * (1 - 14 / 16))
    out = tmp_path / "run"
    kwargs = json.dumps({**PPO_TINY, "actor_lr": "linear:1e-3", "ratio_clip": "linear:0.3:0.1"})
    flags = ["--agent", "PPO", "--agent-kwargs", kwargs, "--steps", "16", "--workers", "2"]
    rows = train.main(
        [*flags, "--epoch-steps", "16", "--test-episodes", "1", "--quiet"]
        + [
            "--out",
            str(out),
            "-f",
            "jax",
        ]
    )
    assert rows
    with open(os.path.join(out, "config.json")) as fh:
        config = json.load(fh)
    text = json.dumps(config)
    assert "linear:0.001:0.0" in text and "linear:0.3:0.1" in text
