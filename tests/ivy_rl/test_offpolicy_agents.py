"""Off-policy agents: the same update on torch, jax and tensorflow in float64 (eager, one
compiled function, compiled step by step), brief trainings on every differentiable backend,
learning a one-step task, checkpoints that continue exactly, and clear errors."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import ivy
import ivy_rl

TINY = dict(
    hidden_sizes=(8,),
    batch_size=8,
    start_steps=6,
    update_after=6,
    update_every=4,
    batch_iterations=2,
    return_steps=2,
)
SETTINGS = {
    "DDPG": dict(TINY, exploration="ornstein_uhlenbeck"),
    "TD3": dict(TINY),
    "SAC": dict(TINY),
    "MPO": dict(TINY, num_samples=3),
    "D4PG": dict(TINY, atoms=7, v_min=-5.0, v_max=5.0),
    "DQN": dict(TINY, epsilon_decay_steps=20),
    "BranchingDQN": dict(TINY, epsilon_decay_steps=20),
}
OBSERVATIONS = gym.spaces.Box(-5, 5, (3,), np.float64)
ACTIONS = {
    "DDPG": gym.spaces.Box(-2.0, 2.0, (2,)),
    "DQN": gym.spaces.Discrete(3),
    "BranchingDQN": gym.spaces.MultiDiscrete([2, 3]),
}
AGENTS = list(SETTINGS)


def _actions(name):
    return ACTIONS.get(name, ACTIONS["DDPG"])


def _run(agent, steps, *, seed=11):
    """Feed ``agent`` synthetic transitions (time limits and terminations); the last logs."""
    data = np.random.default_rng(seed)
    obs = data.normal(size=(2, 3))
    logs, last = [], {}
    for t in range(steps):
        actions = agent.step(obs)
        assert agent.action_space.contains(actions[0]), actions[0]
        nxt = data.normal(size=(2, 3))
        resets = np.array([t % 5 == 4, t % 7 == 6])
        terms = np.array([t % 5 == 4, False])
        last = agent.update(nxt, data.normal(size=2), resets, terms)
        if last:
            logs.append(last)
        obs = nxt
    return logs


def _numpy(nest):
    return ivy.nest.map_nest(lambda x: np.asarray(ivy.to_numpy(x)), nest)


_updates: dict = {}


def _one_update(name, backend, compile=False, fusion="update"):
    """``(v, targets, optimiser states, last logs, fusion)`` as numpy after four updates of an
    agent in float64 fed the same transitions (acting with its policy in between)."""
    key = (name, backend, compile, fusion)
    if key not in _updates:
        agent = ivy_rl.agents.make(name, fusion=fusion, **SETTINGS[name])
        agent.initialize(
            OBSERVATIONS, _actions(name), seed=7, f=backend, dtype="float64", compile=compile
        )
        logs = _run(agent, 10)  # 20 environment steps: updates after 8, 12, 16 and 20
        assert len(logs) == 4
        _updates[key] = (
            *_numpy((agent.v, agent.targets, agent.optimizer_states)),
            logs[-1],
            agent.fusion,
        )
    return _updates[key]


def _assert_same(got, expected, *, rtol=1e-9, atol=1e-11):
    for a, b in zip(ivy.nest.flatten_nest(got[:3])[0], ivy.nest.flatten_nest(expected[:3])[0]):
        np.testing.assert_allclose(a, b, rtol=rtol, atol=atol)
    assert set(got[3]) == set(expected[3])
    for key, value in expected[3].items():
        np.testing.assert_allclose(got[3][key], value, rtol=1e-8, atol=1e-10, err_msg=key)


# (backend, compile, fusion) compared with torch run eagerly
VARIANTS = [("jax", True, "update"), ("tensorflow", False, "update")]


@pytest.mark.parametrize("name", AGENTS)
def test_same_update_on_every_backend_in_float64(name):
    reference = _one_update(name, "torch")
    fresh = ivy_rl.agents.make(name, **SETTINGS[name])
    fresh.initialize(OBSERVATIONS, _actions(name), seed=7, f="torch", dtype="float64")
    initial = _numpy(fresh.v)
    for part in initial:
        moved = [
            np.max(np.abs(a - b))
            for a, b in zip(
                ivy.nest.flatten_nest(reference[0][part])[0],
                ivy.nest.flatten_nest(initial[part])[0],
            )
        ]
        assert max(moved) > 1e-6, f"the update did not change {part}"
    for backend, compile, fusion in VARIANTS:
        _assert_same(_one_update(name, backend, compile, fusion), reference)


@pytest.mark.parametrize(
    "name,framework,fusion",
    [("TD3", "tensorflow", "update"), ("SAC", "jax", "steps"), ("DQN", "torch", "auto")],
)
def test_compiled_update_equals_eager(name, framework, fusion):
    # tensorflow's whole update as one graph, jax step by step, and torch.compile, where 'auto'
    # finds that the compiler unrolls loops and compiles each step on its own
    compiled = _one_update(name, framework, compile=True, fusion=fusion)
    assert compiled[4] == ("update" if fusion == "update" else "steps")
    _assert_same(compiled, _one_update(name, "torch"))


@pytest.mark.parametrize("name", AGENTS)
def test_each_agent_trains_a_few_hundred_steps(diff_backend, name):
    agent = ivy_rl.agents.make(name, **dict(SETTINGS[name], update_every=50, batch_iterations=4))
    agent.initialize(OBSERVATIONS, _actions(name), seed=0, f=diff_backend, compile=False)
    logs = _run(agent, 200)  # 400 environment steps of two workers, 7 updates
    assert len(logs) == 7
    for key in ("critic/loss", "critic/iterations"):
        assert all(np.isfinite(row[key]) for row in logs), key
    actions = agent.test_step(np.zeros((4, 3)))
    assert actions.shape[0] == 4 and all(agent.action_space.contains(a) for a in actions)


class _MatchTheSign(gym.Env):
    """A one-step task: the reward is ``-(a - s)^2`` (Box) or 1 for the action matching the
    sign of ``s`` (Discrete); every episode ends after one step."""

    def __init__(self, discrete):
        self.observation_space = gym.spaces.Box(-1, 1, (1,), np.float64)
        self.action_space = gym.spaces.Discrete(2) if discrete else gym.spaces.Box(-1, 1, (1,))


def _one_step_score(agent, rng, discrete, steps):
    for _ in range(steps):
        obs = rng.uniform(-1, 1, size=(4, 1))
        actions = agent.step(obs)
        if discrete:
            rewards = (actions == (obs[:, 0] > 0)).astype(float)
        else:
            rewards = -np.square(actions[:, 0] - obs[:, 0])
        done = np.ones(4, bool)
        agent.update(obs, rewards, done, done)
    obs = np.linspace(-0.9, 0.9, 10)[:, None]
    actions = agent.test_step(obs)
    if discrete:
        return float(np.mean(actions == (obs[:, 0] > 0)))
    return float(np.mean(np.abs(actions[:, 0] - obs[:, 0])))


@pytest.mark.parametrize("name", ["TD3", "SAC", "DQN"])
def test_learns_a_one_step_task(name):
    discrete = name == "DQN"
    env = _MatchTheSign(discrete)
    settings = dict(
        hidden_sizes=(32,),
        batch_size=32,
        start_steps=40,
        update_after=40,
        update_every=8,
        batch_iterations=8,
        normalize_observations=False,
    )
    if discrete:
        settings["epsilon_decay_steps"] = 200
    agent = ivy_rl.agents.make(name, **settings)
    agent.initialize(env.observation_space, env.action_space, seed=0, f="torch", compile=False)
    score = _one_step_score(agent, np.random.default_rng(0), discrete, 120)
    if discrete:
        assert score == 1.0  # every sign matched
    else:
        assert score < 0.15, score  # a random policy is off by about 0.67 on average


def test_checkpoint_continues_exactly_on_another_backend(tmp_path):
    def make(backend):
        agent = ivy_rl.agents.make("SAC", **SETTINGS["SAC"])
        return agent.initialize(
            OBSERVATIONS, _actions("SAC"), seed=3, f=backend, dtype="float64", compile=False
        )

    first = make("torch")
    _run(first, 13, seed=1)
    first.step(np.ones((2, 3)))  # a pending transition, and steps staged in the replay
    first.save(tmp_path / "agent")
    data = np.random.default_rng(9)
    obs = [data.normal(size=(2, 3)) for _ in range(12)]
    results = []
    for agent in (first, make("jax").load(tmp_path / "agent")):
        agent.update(obs[0], np.ones(2), np.zeros(2, bool), np.zeros(2, bool))
        for t in range(1, 12):
            agent.step(obs[t - 1])
            agent.update(obs[t], np.full(2, 0.5 * t), np.array([t == 5, False]), np.zeros(2))
        results.append(_numpy((agent.v, agent.targets, agent.optimizer_states)))
    for a, b in zip(*(ivy.nest.flatten_nest(r)[0] for r in results)):
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-11)


def test_clear_errors():
    box, discrete = ACTIONS["DDPG"], ACTIONS["DQN"]
    for name, space in [("DQN", box), ("SAC", discrete), ("BranchingDQN", discrete)]:
        with pytest.raises(TypeError, match=f"{name} does not support the action space"):
            ivy_rl.agents.make(name).initialize(OBSERVATIONS, space, f="torch")
    with pytest.raises(ValueError, match="multiple of policy_delay"):
        ivy_rl.agents.make("TD3", batch_iterations=5, policy_delay=2)
    with pytest.raises(ValueError, match="v_min"):
        ivy_rl.agents.make("D4PG", v_min=1.0, v_max=0.0)
    with pytest.raises(ValueError, match="'return_steps'"):
        ivy_rl.agents.make("DDPG", return_steps=0)
    with pytest.raises(ValueError, match="'exploration'"):
        ivy_rl.agents.make("TD3", exploration="gaussian")
    with pytest.raises(TypeError, match="unknown settings"):
        ivy_rl.agents.make("SAC", exploration="normal")
    with pytest.raises(ivy.errors.UnsupportedError, match="gradients"):
        ivy_rl.agents.make("DQN").initialize(OBSERVATIONS, discrete, f="numpy")
