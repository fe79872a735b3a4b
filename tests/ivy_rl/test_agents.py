"""Agents: short trainings on each differentiable backend, reproducibility, the same update on
torch, jax and tensorflow in float64, compiled equals eager, and clear errors."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import ivy
import ivy_rl
from ivy_rl.trainer import Trainer

TINY = dict(hidden_sizes=(16,), segment_size=16)
SETTINGS = {
    "A2C": dict(TINY, critic_iterations=2),
    "PPO": dict(TINY, batch_size=16, epochs=2),
    "TRPO": dict(TINY, critic_iterations=2, cg_steps=3, backtrack_steps=3),
}
TIME_COLUMNS = ("train/seconds", "train/epoch_seconds", "train/steps_per_second")


def _train(agent_name, env_id, backend, seed=0, steps=64, **kw):
    agent = ivy_rl.agents.make(agent_name, **SETTINGS[agent_name])
    trainer = Trainer(steps, epoch_steps=steps, test_episodes=1, show_progress=False)
    # torch.compile takes long to start: torch runs eagerly here (test_torch_compiled_ppo)
    return trainer.run(
        agent, env_id, workers=2, seed=seed, f=backend, compile=backend != "torch", **kw
    )


@pytest.mark.parametrize("agent_name", ["A2C", "PPO", "TRPO"])
@pytest.mark.parametrize("env_id", ["CartPole-v1", "Pendulum-v1"])
def test_each_agent_trains_briefly(diff_backend, agent_name, env_id):
    rows = _train(agent_name, env_id, diff_backend)
    assert len(rows) == 1
    row = rows[0]
    assert row["train/steps"] == 64
    for key in ("actor/loss", "critic/loss", "test/episode_score/mean"):
        assert np.isfinite(row[key]), key


def _without_time(rows):
    return [{k: v for k, v in r.items() if k not in TIME_COLUMNS} for r in rows]


def test_same_seed_gives_the_same_log(diff_backend):
    first = _train("PPO", "CartPole-v1", diff_backend, seed=3)
    second = _train("PPO", "CartPole-v1", diff_backend, seed=3)
    other = _train("PPO", "CartPole-v1", diff_backend, seed=4)
    assert _without_time(first) == _without_time(second)
    assert _without_time(first) != _without_time(other)


def _one_update(agent_name, backend, space, compile=False, **settings):
    """An agent in float64 fed the same synthetic transitions until its first update."""
    obs_space = gym.spaces.Box(-5, 5, (3,), np.float64)
    kw = dict(SETTINGS[agent_name], **settings)
    agent = ivy_rl.agents.make(agent_name, **kw)
    agent.initialize(obs_space, space, seed=7, f=backend, dtype="float64", compile=compile)
    data = np.random.default_rng(11)
    workers = 2
    obs = data.normal(size=(workers, 3))
    logs = {}
    for t in range(agent.config["segment_size"]):
        agent.step(obs)
        nxt = data.normal(size=(workers, 3))
        resets = np.array([t % 5 == 4, t % 7 == 6])
        terms = np.array([t % 5 == 4, False])
        logs = agent.update(nxt, data.normal(size=workers), resets, terms)
        obs = nxt
    assert logs, "the agent did not update"
    return ivy.nest.map_nest(lambda x: np.asarray(ivy.to_numpy(x)), agent.v), logs


SPACES = {"Box": gym.spaces.Box(-2.0, 2.0, (2,)), "Discrete": gym.spaces.Discrete(3)}


@pytest.mark.parametrize("agent_name", ["A2C", "PPO", "TRPO"])
@pytest.mark.parametrize("space", ["Box", "Discrete"])
def test_same_update_on_torch_jax_and_tensorflow_in_float64(agent_name, space):
    results = {b: _one_update(agent_name, b, SPACES[space]) for b in ("torch", "jax", "tensorflow")}
    ref_v, ref_logs = results["torch"]
    initial = ivy.nest.flatten_nest(
        ivy_rl.models.actor_critic(
            gym.spaces.Box(-5, 5, (3,)),
            SPACES[space],
            rng=np.random.default_rng(7),
            actor_sizes=(16,),
            critic_sizes=(16,),
            f="numpy",
            dtype="float64",
        ).v
    )[0]
    moved = [np.max(np.abs(a - b)) for a, b in zip(ivy.nest.flatten_nest(ref_v)[0], initial)]
    assert max(moved) > 1e-4, "the update changed nothing"
    for backend in ("jax", "tensorflow"):
        v, logs = results[backend]
        for a, b in zip(ivy.nest.flatten_nest(v)[0], ivy.nest.flatten_nest(ref_v)[0]):
            np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-11)
        for key in ref_logs:
            np.testing.assert_allclose(logs[key], ref_logs[key], rtol=1e-8, atol=1e-10)


@pytest.mark.parametrize("agent_name", ["PPO", "TRPO"])
def test_compiled_update_equals_eager(graph_backend, agent_name):
    eager, _ = _one_update(agent_name, graph_backend, SPACES["Box"], compile=False)
    compiled, _ = _one_update(agent_name, graph_backend, SPACES["Box"], compile=True)
    for a, b in zip(ivy.nest.flatten_nest(compiled)[0], ivy.nest.flatten_nest(eager)[0]):
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-11)


def test_torch_compiled_ppo_equals_eager():
    # one compiled iteration function (no KL stop), the acting and the values functions
    eager, _ = _one_update("PPO", "torch", SPACES["Discrete"], kl_threshold=None, epochs=1)
    compiled, _ = _one_update(
        "PPO", "torch", SPACES["Discrete"], compile=True, kl_threshold=None, epochs=1
    )
    for a, b in zip(ivy.nest.flatten_nest(compiled)[0], ivy.nest.flatten_nest(eager)[0]):
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-11)


def test_ppo_stops_the_actor_when_the_kl_is_exceeded():
    _, strict = _one_update("PPO", "jax", SPACES["Box"], kl_threshold=0.0, epochs=4, actor_lr=1e-2)
    _, loose = _one_update("PPO", "jax", SPACES["Box"], kl_threshold=None, epochs=4, actor_lr=1e-2)
    assert strict["actor/iterations"] < loose["actor/iterations"] == 8
    assert strict["critic/iterations"] == loose["critic/iterations"] == 8


def test_baselines_act_in_the_action_space():
    obs = np.zeros((6, 3))
    box = gym.spaces.Box(np.array([0.0, -4.0]), np.array([1.0, 4.0]))
    for space in (box, gym.spaces.Discrete(4, start=2)):
        agent = ivy_rl.Uniform().initialize(gym.spaces.Box(-1, 1, (3,)), space, seed=1)
        actions = agent.step(obs)
        assert all(space.contains(a) for a in actions)
        again = ivy_rl.Uniform().initialize(gym.spaces.Box(-1, 1, (3,)), space, seed=1).step(obs)
        np.testing.assert_array_equal(actions, again)
    const = ivy_rl.Constant().initialize(gym.spaces.Box(-1, 1, (3,)), box)
    np.testing.assert_allclose(const.test_step(obs), np.tile([0.5, 0.0], (6, 1)))
    rows = Trainer(40, epoch_steps=20, test_episodes=1, show_progress=False).run(
        "Uniform", "CartPole-v1", workers=2
    )
    assert len(rows) == 2 and rows[-1]["train/steps"] == 40


def test_clear_errors_list_what_is_available():
    with pytest.raises(ValueError, match="available agents: A2C, PPO, TRPO, Uniform, Constant"):
        ivy_rl.agents.make("DQN")
    with pytest.raises(TypeError, match="its settings are"):
        ivy_rl.PPO(learning_rate=1.0)
    with pytest.raises(TypeError, match="supported action spaces: Box, Discrete"):
        ivy_rl.PPO().initialize(gym.spaces.Box(-1, 1, (3,)), gym.spaces.MultiBinary(2), f="jax")
    with pytest.raises(ivy.errors.UnsupportedError, match="torch', 'jax' or 'tensorflow"):
        ivy_rl.A2C().initialize(gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2), f="numpy")
    with pytest.raises(ValueError, match="did you mean: CartPole-v1"):
        ivy_rl.environments.check_environment_id("CartPol-v1")
    agent = ivy_rl.PPO(**SETTINGS["PPO"]).initialize(
        gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2), f="jax"
    )
    with pytest.raises(RuntimeError, match="before step"):
        agent.update(np.zeros((1, 3)), np.zeros(1), np.zeros(1), np.zeros(1))
