"""Agents: short trainings on each differentiable backend, reproducibility, the same update on
torch, jax and tensorflow in float64 (eager, one compiled function, compiled step by step), the
KL early stop as a mask, and clear errors."""

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
    "PPO": dict(TINY, batch_size=16, epochs=2, normalize_returns=True),
    "TRPO": dict(TINY, critic_iterations=2, cg_steps=3, backtrack_steps=3),
}
BRIEF_ENVIRONMENTS = {"A2C": "CartPole-v1", "PPO": "Pendulum-v1", "TRPO": "CartPole-v1"}
TIME_COLUMNS = ("train/seconds", "train/epoch_seconds", "train/steps_per_second", "test/seconds")
_trained: dict = {}


def _train(agent_name, backend, seed=0, *, cached=True):
    """The log of a brief training (64 steps, 2 workers: two updates); torch runs eagerly here
    (torch.compile is tested once, below), jax and tensorflow compiled."""
    key = (agent_name, backend, seed)
    if cached and key in _trained:
        return _trained[key]
    agent = ivy_rl.agents.make(agent_name, **SETTINGS[agent_name])
    trainer = Trainer(64, epoch_steps=64, test_episodes=1, show_progress=False)
    rows = trainer.run(
        agent,
        BRIEF_ENVIRONMENTS[agent_name],
        workers=2,
        seed=seed,
        f=backend,
        compile=backend != "torch",
    )
    _trained[key] = rows
    return rows


@pytest.mark.parametrize("agent_name", ["A2C", "PPO", "TRPO"])
def test_each_agent_trains_briefly(diff_backend, agent_name):
    rows = _train(agent_name, diff_backend)
    assert len(rows) == 1
    row = rows[0]
    assert row["train/steps"] == 64 and row["actor/iterations"] >= 1
    assert row["critic/iterations"] == (4 if agent_name == "PPO" else 2)
    for key in ("actor/loss", "critic/loss", "test/episode_score/mean"):
        assert np.isfinite(row[key]), key


def _without_time(rows):
    return [{k: v for k, v in r.items() if k not in TIME_COLUMNS} for r in rows]


def test_same_seed_gives_the_same_log(diff_backend):
    first = _train("PPO", diff_backend, seed=0)
    second = _train("PPO", diff_backend, seed=0, cached=False)
    other = _train("PPO", diff_backend, seed=1)
    assert _without_time(first) == _without_time(second)
    assert _without_time(first) != _without_time(other)


# ----------------------------------------------------------------------------------------------
# One update in float64 from the same transitions, on every backend and fusion level
# ----------------------------------------------------------------------------------------------

SPACES = {"Box": gym.spaces.Box(-2.0, 2.0, (2,)), "Discrete": gym.spaces.Discrete(3)}
_updates: dict = {}


def _one_update(agent_name, space, backend, compile=False, fusion="update", **settings):
    """``(v, optimizer states, logs, fusion level)``, as numpy, after the first update of an
    agent in float64 fed the same synthetic transitions (with terminations and time limits)."""
    key = (agent_name, space, backend, compile, fusion, tuple(sorted(settings.items())))
    if key in _updates:
        return _updates[key]
    obs_space = gym.spaces.Box(-5, 5, (3,), np.float64)
    kw = dict(SETTINGS[agent_name], fusion=fusion, **settings)
    agent = ivy_rl.agents.make(agent_name, **kw)
    agent.initialize(obs_space, SPACES[space], seed=7, f=backend, dtype="float64", compile=compile)
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
    arrays = ivy.nest.map_nest(
        lambda x: np.asarray(ivy.to_numpy(x)), (agent.v, agent.optimizer_states)
    )
    _updates[key] = (*arrays, logs, agent.fusion)
    return _updates[key]


def _assert_same(got, expected, *, rtol=1e-9, atol=1e-11):
    got_v, got_states, got_logs = got[:3]
    v, states, logs = expected[:3]
    for a, b in zip(
        ivy.nest.flatten_nest((got_v, got_states))[0], ivy.nest.flatten_nest((v, states))[0]
    ):
        np.testing.assert_allclose(a, b, rtol=rtol, atol=atol)
    assert set(got_logs) == set(logs)
    for key in logs:
        np.testing.assert_allclose(got_logs[key], logs[key], rtol=1e-8, atol=1e-10, err_msg=key)


# (backend, compile, fusion) compared with torch run eagerly
VARIANTS = [("jax", True, "update"), ("tensorflow", True, "update"), ("tensorflow", False, "steps")]


@pytest.mark.parametrize("agent_name", ["A2C", "PPO", "TRPO"])
@pytest.mark.parametrize("space", ["Box", "Discrete"])
def test_same_update_on_every_backend_and_fusion_level_in_float64(agent_name, space):
    reference = _one_update(agent_name, space, "torch")
    initial = ivy_rl.models.actor_critic(
        gym.spaces.Box(-5, 5, (3,)),
        SPACES[space],
        rng=np.random.default_rng(7),
        actor_sizes=(16,),
        critic_sizes=(16,),
        f="numpy",
        dtype="float64",
    ).v
    for part in ("actor", "critic"):
        moved = [
            np.max(np.abs(a - b))
            for a, b in zip(
                ivy.nest.flatten_nest(reference[0][part])[0],
                ivy.nest.flatten_nest(initial[part])[0],
            )
        ]
        assert max(moved) > 1e-4, f"the update did not change the {part}"
    for backend, compile, fusion in VARIANTS:
        _assert_same(_one_update(agent_name, space, backend, compile, fusion), reference)


@pytest.mark.parametrize(
    "agent_name,space,framework,fusion",
    [
        ("PPO", "Discrete", "torch", "auto"),
        ("TRPO", "Box", "jax", "steps"),
        ("A2C", "Box", "jax", "steps"),
    ],
)
def test_compiled_step_by_step_equals_eager(agent_name, space, framework, fusion):
    # the returns and each optimisation step compiled on their own (torch.compile here: the
    # one torch-compiled case of the suite, where 'auto' finds that torch.compile unrolls loops)
    compiled = _one_update(agent_name, space, framework, compile=True, fusion=fusion)
    assert compiled[3] == "steps"
    _assert_same(compiled, _one_update(agent_name, space, "torch"))


def test_fusion_auto_fuses_where_compiled_loops_are_loops():
    # jax and tensorflow compile ivy.scan as a loop: the whole update is one function
    assert not ivy_rl.agents.compiled_scan_unrolls(f="jax")
    assert not ivy_rl.agents.compiled_scan_unrolls(f="tensorflow")
    for backend in ("jax", "tensorflow"):
        agent = ivy_rl.PPO(**SETTINGS["PPO"]).initialize(
            gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2), f=backend
        )
        assert agent.fusion == "update"


def test_ppo_kl_stop_masks_the_remaining_actor_steps():
    # a threshold every KL exceeds: after the first mini-batch the actor stops, inside the
    # compiled update (jax); batch_size None: every epoch is one step on the whole segment
    whole = dict(batch_size=None, actor_lr=1e-2)
    stopped = _one_update("PPO", "Box", "jax", True, kl_threshold=-1.0, epochs=4, **whole)
    one_step = _one_update("PPO", "Box", "torch", kl_threshold=None, epochs=1, **whole)
    free = _one_update("PPO", "Box", "torch", kl_threshold=None, epochs=4, **whole)
    assert stopped[2]["actor/iterations"] == 1 and free[2]["actor/iterations"] == 4
    assert stopped[2]["critic/iterations"] == free[2]["critic/iterations"] == 4
    # the actor and its Adam state after 4 masked epochs are those after one step...
    _assert_same(
        ({"a": stopped[0]["actor"]}, {"a": stopped[1]["actor"]}, {}),
        ({"a": one_step[0]["actor"]}, {"a": one_step[1]["actor"]}, {}),
    )
    # ... while the critic took its 4 steps, as without the stop
    for a, b in zip(
        ivy.nest.flatten_nest(stopped[0]["critic"])[0], ivy.nest.flatten_nest(free[0]["critic"])[0]
    ):
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-11)
    moved = ivy.nest.flatten_nest(free[0]["actor"])[0]
    assert (
        max(
            np.max(np.abs(a - b))
            for a, b in zip(moved, ivy.nest.flatten_nest(one_step[0]["actor"])[0])
        )
        > 1e-4
    )


def test_baselines_act_in_the_action_space():
    obs = np.zeros((6, 3))
    box = gym.spaces.Box(np.array([0.0, -4.0], np.float32), np.array([1.0, 4.0], np.float32))
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
    listed = ", ".join(ivy_rl.AGENTS)
    with pytest.raises(ValueError, match=f"available agents: {listed}"):
        ivy_rl.agents.make("NoSuchAgent")
    with pytest.raises(TypeError, match="its settings are"):
        ivy_rl.PPO(learning_rate=1.0)
    with pytest.raises(
        ValueError, match="setting .fusion. must be one of .auto., .update., .steps., got .all."
    ):
        ivy_rl.PPO(fusion="all")
    with pytest.raises(TypeError, match="supported action spaces: Box, Discrete"):
        ivy_rl.PPO().initialize(gym.spaces.Box(-1, 1, (3,)), gym.spaces.MultiBinary(2), f="jax")
    with pytest.raises(TypeError, match="supported observation spaces: Box"):
        ivy_rl.PPO().initialize(gym.spaces.Discrete(16), gym.spaces.Discrete(2), f="jax")
    with pytest.raises(ivy.errors.UnsupportedError, match="torch', 'jax' or 'tensorflow"):
        ivy_rl.A2C().initialize(gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2), f="numpy")
    with pytest.raises(ValueError, match="did you mean: CartPole-v1"):
        ivy_rl.environments.check_environment_id("CartPol-v1")
    agent = ivy_rl.PPO(**SETTINGS["PPO"]).initialize(
        gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2), f="jax"
    )
    with pytest.raises(RuntimeError, match="before step"):
        agent.update(np.zeros((1, 3)), np.zeros(1), np.zeros(1), np.zeros(1))


# ----------------------------------------------------------------------------------------------
# Parts, make's defaults and checks, compile counts, checkpoints' settings, devices
# ----------------------------------------------------------------------------------------------


def test_an_agent_of_parts_equals_the_agent_of_the_same_settings():
    from ivy_rl.models import ActorCriticModel
    from ivy_rl.replays import Segment
    from ivy_rl.updaters import ClippedRatio, ValueRegression

    parts = dict(
        model=ActorCriticModel(hidden_sizes=(16,), normalize_returns=True),
        replay=Segment(16, batch_size=16, batch_iterations=2),
        actor_updater=ClippedRatio(lr=3e-4, kl_threshold=0.015, gradient_clip=0.5),
        critic_updater=ValueRegression(lr=1e-3, gradient_clip=0.5),
    )
    agent = ivy_rl.PPO(fusion="update", **parts)
    flat = ivy_rl.agents.make("PPO", fusion="update", **SETTINGS["PPO"])
    assert agent.config == flat.config
    assert agent.model is parts["model"] and agent.actor_updater is parts["actor_updater"]
    np.testing.assert_equal(_update_of(agent, "Box"), _update_of(flat, "Box"))
    with pytest.raises(TypeError, match=r"settings \['epochs'\] belong to the replay given"):
        ivy_rl.PPO(replay=Segment(16), epochs=3)


def _update_of(agent, space):
    """The variables after one update of ``agent`` (float64, torch eager) on fixed data."""
    agent.initialize(
        gym.spaces.Box(-5, 5, (3,)),
        SPACES[space],
        seed=7,
        f="torch",
        dtype="float64",
        compile=False,
    )
    data = np.random.default_rng(11)
    obs = data.normal(size=(2, 3))
    for t in range(agent.config["segment_size"]):
        agent.step(obs)
        obs = data.normal(size=(2, 3))
        agent.update(obs, data.normal(size=2), np.array([t % 5 == 4, False]), np.zeros(2, bool))
    return ivy.nest.flatten_nest(ivy.nest.map_nest(lambda x: np.asarray(ivy.to_numpy(x)), agent.v))[
        0
    ]


def test_make_applies_the_family_defaults_and_checks_every_setting():
    families = ivy_rl.agents.defaults.FAMILIES
    for env_id, family in [
        ("CartPole-v1", "classic_discrete"),
        ("Pendulum-v1", "classic_continuous"),
        ("Hopper-v5", "mujoco"),
        ("ivy_gym/Pendulum-v0", "ivy_gym"),
    ]:
        assert ivy_rl.agents.task_family(env_id) == family and family in families
    cartpole = ivy_rl.agents.make("ppo", environment="CartPole-v1", epochs=5)
    row = ivy_rl.agents.DEFAULTS["PPO"]["classic_discrete"]
    assert cartpole.config["segment_size"] == row["segment_size"] == 32
    assert cartpole.config["epochs"] == 5  # the user's settings win
    assert ivy_rl.agents.make("PPO").config["segment_size"] == 2048  # no environment: PPO's own
    assert set(cartpole.config) == set(ivy_rl.PPO().config)  # every value used is recorded
    for settings, error, words in [
        ({"segment_size": "32"}, TypeError, "setting 'segment_size' must be an integer >= 1"),
        ({"hidden_sizes": 64}, TypeError, "setting 'hidden_sizes' must be a non-empty list"),
        ({"discount": 1.5}, ValueError, "setting 'discount' must be a number >= 0 and <= 1"),
        ({"batch_size": 0}, ValueError, "setting 'batch_size' must be an integer >= 1 or None"),
        ({"normalize_returns": 1}, TypeError, "setting 'normalize_returns' must be true or"),
        ({"learning_rate": 1.0}, TypeError, "unknown settings \\['learning_rate'\\]"),
    ]:
        with pytest.raises(error, match=words):
            ivy_rl.agents.make("PPO", environment="CartPole-v1", **settings)


def test_no_compilation_after_the_first_update_and_loaded_weights_are_kept(tmp_path):
    # jax: the acting, testing and update functions compile once each, on their first call
    obs_space, act_space = gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2)
    agent = ivy_rl.PPO(**SETTINGS["PPO"]).initialize(obs_space, act_space, seed=3, f="jax")
    data = np.random.default_rng(0)
    counts = []
    for _update in range(3):
        for _t in range(agent.config["segment_size"]):
            agent.step(data.normal(size=(2, 3)))
            agent.update(data.normal(size=(2, 3)), np.ones(2), np.zeros(2, bool), np.zeros(2, bool))
        agent.test_step(data.normal(size=(1, 3)))
        counts.append(agent.compiles)
    assert counts[0] == 3 and counts == [counts[0]] * 3, counts
    # a loaded agent keeps its weights when initialized again with the same setup
    agent.save(tmp_path / "ckpt")
    loaded = ivy_rl.PPO(**SETTINGS["PPO"]).initialize(obs_space, act_space, seed=9, f="jax")
    loaded.load(tmp_path / "ckpt")
    weights = ivy.to_numpy(loaded.v["actor"]["head"]["logits"]["w"])
    assert loaded.initialize(obs_space, act_space, seed=9, f="jax") is loaded
    np.testing.assert_array_equal(ivy.to_numpy(loaded.v["actor"]["head"]["logits"]["w"]), weights)
    with pytest.raises(ValueError, match="already initialized, differently .*framework: 'jax'"):
        loaded.initialize(obs_space, act_space, f="torch")
    # ... and refuses a checkpoint of other settings, naming each
    other = ivy_rl.PPO(**dict(SETTINGS["PPO"], epochs=3, actor_lr=1e-3))
    other.initialize(obs_space, act_space, f="jax")
    with pytest.raises(ValueError, match="actor_lr: 0.0003 in the checkpoint, 0.001 here; epochs"):
        other.load(tmp_path / "ckpt")


def test_arrays_live_on_the_agents_device(diff_backend, target_device):
    # compiled where the compiler keeps loops (seconds), eager where it unrolls them
    compile = ivy.get_framework(f=diff_backend).capabilities.compiled_loops
    agent = ivy_rl.TRPO(**dict(SETTINGS["TRPO"], cg_steps=1, backtrack_steps=1)).initialize(
        gym.spaces.Box(-1, 1, (3,)),
        gym.spaces.Box(-1, 1, (2,)),
        f=diff_backend,
        compile=compile,
        device=target_device,
    )
    xp = agent.xp
    data = np.random.default_rng(0)
    for _t in range(agent.config["segment_size"]):
        agent.step(data.normal(size=(2, 3)))
        agent.update(data.normal(size=(2, 3)), np.ones(2), np.zeros(2, bool), np.zeros(2, bool))
    assert agent.updates == 1
    # weights, optimiser states, statistics, and the segment the update reads (with TRPO's
    # stored distribution parameters)
    leaves = ivy.nest.flatten_nest((agent.v, agent.optimizer_states, agent.stats))[0]
    segment = agent._segment()
    assert set(segment["distribution"]) == {"loc", "scale"}
    leaves += ivy.nest.flatten_nest(segment)[0]
    assert leaves and {str(xp.dev(leaf)) for leaf in leaves} == {target_device}


def test_compile_counts_follow_signatures_without_flattening_every_call():
    # Agent._counted: the full signature on the first two calls, on a new cheap key (the
    # shapes of the arrays passed directly) and every _FULL_EVERY-th call
    from ivy_rl.agents import agent as agent_module

    agent = ivy_rl.agents.Agent()
    agent.xp = ivy.get_framework(f="numpy")
    agent._signatures = {}
    full = []
    real = agent_module._signature
    calls = []

    def counting(xp, args):
        full.append(len(calls) + 1)  # the number of the call being made
        return real(xp, args)

    counted = agent._counted(lambda *args: calls.append(args) or len(calls), "fn")
    every = agent_module._FULL_EVERY
    weights = {"w": np.zeros((2, 3), np.float32)}
    try:
        agent_module._signature = counting
        for _ in range(every + 5):
            assert counted(weights, np.zeros((4, 3), np.float32)) == len(calls)
        assert agent.compiles == 1
        assert full == [1, 2, every]  # not per call
        counted(weights, np.zeros((1, 3), np.float32))  # a new batch shape: counted at once
        assert agent.compiles == 2 and full[-1] == len(calls)
        counted(weights, np.zeros((1, 3), np.float64))  # a new dtype
        assert agent.compiles == 3
        # a change deep inside a nest is counted at the next full check
        deeper = {"w": np.zeros((5, 3), np.float32)}
        while len(calls) % every:
            counted(deeper, np.zeros((4, 3), np.float32))
        assert agent.compiles == 4
    finally:
        agent_module._signature = real
