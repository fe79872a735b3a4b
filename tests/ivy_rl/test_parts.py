"""The off-policy agents' parts, one by one: the models (:mod:`ivy_rl.off_policy_models`), the
updaters (:mod:`ivy_rl.off_policy_updaters`) against references written here in numpy float64,
the replay and exploration parts, and agents composed from parts (``SAC(model=..., ...)``)
equal to the agents of the same flat settings."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest

import ivy
import ivy_rl
from ivy_rl.explorations import EpsilonGreedy, NoNoise, NormalNoise, make_exploration
from ivy_rl.models import polyak_update
from ivy_rl.off_policy_models import ActorQModel, QModel
from ivy_rl.off_policy_updaters import (
    DeterministicPolicyGradient,
    DeterministicQLearning,
    DistributionalDeterministicPolicyGradient,
    QLearning,
    TwinCriticDeterministicQLearning,
    TwinCriticSoftPolicyGradient,
    TwinCriticSoftQLearning,
)
from ivy_rl.replays import Transitions

OBS = gym.spaces.Box(-5, 5, (3,), np.float64)
BOX = gym.spaces.Box(-1.0, 1.0, (2,))
BATCH = 6


def _np(a):
    return np.asarray(ivy.to_numpy(a), np.float64)


def _relu_mlp(torso_v, x):
    layers = torso_v["mlp"]["layers"]
    for key in sorted(layers, key=int):
        x = np.maximum(x @ _np(layers[key]["w"]).T + _np(layers[key]["b"]), 0.0)
    return x


def _dense(layer_v, x):
    return x @ _np(layer_v["w"]).T + _np(layer_v["b"])


def _actor(actor_v, obs):
    """The deterministic policy ``tanh(dense(relu-MLP(obs)))`` in numpy."""
    return np.tanh(_dense(actor_v["head"]["layer"], _relu_mlp(actor_v["torso"], obs)))


def _q(critic_v, obs, actions):
    """One scalar critic ``dense(relu-MLP([obs, a]))`` in numpy ``[batch]``."""
    h = _relu_mlp(critic_v["torso"], np.concatenate([obs, actions], axis=-1))
    return _dense(critic_v["head"]["layer"], h)[..., 0]


def _batch(xp, data):
    """A batch of n-step transitions (as :func:`ivy_rl.buffers.n_step_batch` gives them)."""
    batch = {
        "observations": data.normal(size=(BATCH, 3)),
        "actions": data.uniform(-1, 1, size=(BATCH, 2)),
        "returns": data.normal(size=BATCH),
        "discounts": np.where(data.random(BATCH) < 0.3, 0.0, 0.99**2),
        "next_observations": data.normal(size=(BATCH, 3)),
    }
    return batch, {k: xp.asarray(a, dtype="float64") for k, a in batch.items()}


def _model(xp, **kwargs):
    model = ActorQModel((5,), **kwargs)
    return model.initialize(OBS, BOX, rng=np.random.default_rng(0), dtype="float64", f=xp)


def _updater(cls, xp, model, **kwargs):
    return cls(**kwargs).initialize(xp, model, dtype="float64", device="cpu")


def test_actor_q_model_matches_numpy(backend, xp):
    model = _model(xp, critics=2)
    obs = np.random.default_rng(1).normal(size=(4, 3))
    actions = _np(model.mode(model.v, None, xp.asarray(obs)))
    np.testing.assert_allclose(actions, _actor(model.v["actor"], obs), rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(_np(model.act(model.v, None, xp.asarray(obs), None)), actions)
    q = _np(model.q(model.v["critic"], xp.asarray(obs), xp.asarray(actions), None))
    critics = model.v["critic"]["critics"]
    expected = np.stack([_q(critics[k], obs, actions) for k in ("0", "1")])
    np.testing.assert_allclose(q, expected, rtol=1e-10, atol=1e-12)
    assert set(model.target_v) == {"actor", "critic"} and not model.samples
    sac = _model(xp, policy="squashed_gaussian", critics=2, targets=("critic",))
    assert set(sac.target_v) == {"critic"} and sac.samples
    with pytest.raises(ValueError, match="policy must be one of"):
        ActorQModel(policy="beta")


def test_q_model_matches_numpy(backend, xp):
    model = QModel((5,), dueling=True).initialize(
        OBS, gym.spaces.Discrete(3), rng=np.random.default_rng(0), dtype="float64", f=xp
    )
    obs = np.random.default_rng(2).normal(size=(4, 3))
    (values,) = model.branches(model.v["q"], xp.asarray(obs), None)
    head = model.v["q"]["head"]
    h = _relu_mlp(model.v["q"]["torso"], obs)
    adv = _dense(head["advantages"], h)
    expected = _dense(head["value"]["layer"], h) + adv - adv.mean(-1, keepdims=True)
    np.testing.assert_allclose(_np(values), expected, rtol=1e-10, atol=1e-12)
    greedy = _np(model.mode(model.v, None, xp.asarray(obs)))
    np.testing.assert_array_equal(greedy, expected.argmax(-1))


def test_deterministic_updaters_match_numpy(diff_backend):
    xp = getattr(ivy, diff_backend)
    model = _model(xp)
    v, targets = dict(model.v), dict(model.target_v)
    raw, batch = _batch(xp, np.random.default_rng(3))
    critic = _updater(DeterministicQLearning, xp, model, lr=1e-3)
    goal = critic.goal(v, targets, batch, None, {})
    nxt = raw["next_observations"]
    expected_goal = raw["returns"] + raw["discounts"] * _q(
        targets["critic"], nxt, _actor(targets["actor"], nxt)
    )
    np.testing.assert_allclose(_np(goal), expected_goal, rtol=1e-10, atol=1e-12)
    expected_loss = np.mean(
        (_q(v["critic"], raw["observations"], raw["actions"]) - expected_goal) ** 2
    )
    states = {"critic": critic.optimizer.init(v["critic"])}
    new_v, _, infos = critic.step(v, targets, states, batch, None, {}, {})
    np.testing.assert_allclose(float(_np(infos["loss"])), expected_loss, rtol=1e-10)
    assert (
        _np(new_v["actor"]["head"]["layer"]["w"]).tolist()
        == _np(v["actor"]["head"]["layer"]["w"]).tolist()
    )
    actor = _updater(DeterministicPolicyGradient, xp, model, lr=1e-3)
    loss = actor.loss(v["actor"], v["critic"], batch, None, {})
    obs = raw["observations"]
    expected = -np.mean(_q(v["critic"], obs, _actor(v["actor"], obs)))
    np.testing.assert_allclose(float(_np(loss)), expected, rtol=1e-10)


def test_td3_critic_target_takes_the_smaller_smoothed_twin(diff_backend):
    xp = getattr(ivy, diff_backend)
    model = _model(xp, critics=2)
    raw, batch = _batch(xp, np.random.default_rng(4))
    critic = _updater(TwinCriticDeterministicQLearning, xp, model, target_noise=0.3)
    noise = critic.draw(np.random.default_rng(5), 1, BATCH)["noise"][0]
    assert noise.shape == (BATCH, 2)
    goal = critic.goal(model.v, model.target_v, batch, None, {"noise": xp.asarray(noise)})
    nxt, t = raw["next_observations"], model.target_v
    a = np.clip(_actor(t["actor"], nxt) + np.clip(0.3 * noise, -0.5, 0.5), -1.0, 1.0)
    twins = [_q(t["critic"]["critics"][k], nxt, a) for k in ("0", "1")]
    expected = raw["returns"] + raw["discounts"] * np.minimum(*twins)
    np.testing.assert_allclose(_np(goal), expected, rtol=1e-10, atol=1e-12)


def test_d4pg_actor_ascends_the_expected_value(diff_backend):
    xp = getattr(ivy, diff_backend)
    model = _model(xp, critic_head="categorical", v_min=-2.0, v_max=2.0, atoms=5)
    raw, batch = _batch(xp, np.random.default_rng(6))
    actor = _updater(DistributionalDeterministicPolicyGradient, xp, model)
    loss = actor.loss(model.v["actor"], model.v["critic"], batch, None, {})
    obs = raw["observations"]
    c = model.v["critic"]
    h = _relu_mlp(c["torso"], np.concatenate([obs, _actor(model.v["actor"], obs)], -1))
    logits = _dense(c["head"]["layer"], h)
    probs = np.exp(logits - logits.max(-1, keepdims=True))
    probs /= probs.sum(-1, keepdims=True)
    expected = -np.mean(probs @ np.linspace(-2.0, 2.0, 5))
    np.testing.assert_allclose(float(_np(loss)), expected, rtol=1e-9)


def test_sac_temperature_follows_the_entropy_gap(diff_backend):
    xp = getattr(ivy, diff_backend)
    model = _model(xp, policy="squashed_gaussian", critics=2, targets=("critic",))
    _, batch = _batch(xp, np.random.default_rng(7))
    actor = _updater(
        TwinCriticSoftPolicyGradient, xp, model, initial_temperature=0.5, temperature_lr=0.01
    )
    critic = _updater(TwinCriticSoftQLearning, xp, model)
    v = {**model.v, **actor.variables()}
    states = {k: opt.init(v[k]) for k, opt in actor.optimizers().items()}
    states.update({k: opt.init(v[k]) for k, opt in critic.optimizers().items()})
    rng = np.random.default_rng(8)
    x = {
        k: xp.asarray(a[0])
        for k, a in {**critic.draw(rng, 1, BATCH), **actor.draw(rng, 1, BATCH)}.items()
    }
    v, states, infos = critic.step(v, model.target_v, states, batch, None, x, {})
    v, states, infos = actor.step(v, model.target_v, states, batch, None, x, {})
    # Adam's first step is lr * sign(-gradient); the gradient of -log α (H* - H) is H - H*
    gap = -2.0 - float(_np(infos["entropy"]))
    expected = np.log(0.5) + 0.01 * np.sign(gap)
    np.testing.assert_allclose(float(_np(v["temperature"]["log_alpha"])), expected, rtol=1e-6)
    np.testing.assert_allclose(float(_np(infos["temperature"])), np.exp(expected), rtol=1e-6)


@pytest.mark.parametrize("double", [True, False])
def test_q_learning_matches_numpy(diff_backend, double):
    xp = getattr(ivy, diff_backend)
    model = QModel((5,), dueling=False).initialize(
        OBS, gym.spaces.Discrete(3), rng=np.random.default_rng(0), dtype="float64", f=xp
    )
    data = np.random.default_rng(9)
    raw, batch = _batch(xp, data)
    raw["actions"] = data.integers(0, 3, size=BATCH)
    batch["actions"] = xp.asarray(raw["actions"], dtype="int32")
    target_v = {"q": ivy.nest.map_nest(lambda a: a * 0.5, model.v["q"])}
    updater = _updater(QLearning, xp, model, double=double)
    goal = updater.goal(model.v, target_v, batch, None, {})

    def q(v, obs):
        return _dense(v["head"]["advantages"], _relu_mlp(v["torso"], obs))

    nxt = raw["next_observations"]
    target = q(target_v["q"], nxt)
    chosen = q(model.v["q"], nxt).argmax(-1) if double else target.argmax(-1)
    expected = raw["returns"] + raw["discounts"] * target[np.arange(BATCH), chosen]
    np.testing.assert_allclose(_np(goal), expected, rtol=1e-10, atol=1e-12)
    error = q(model.v["q"], raw["observations"])[np.arange(BATCH), raw["actions"]] - expected
    huber = np.where(np.abs(error) < 1, 0.5 * error**2, np.abs(error) - 0.5).mean()
    loss = updater.loss(model.v["q"], batch, goal, None)
    np.testing.assert_allclose(float(_np(loss)), huber, rtol=1e-10)


def test_replay_and_exploration_parts_hold_their_settings():
    replay = Transitions(100, return_steps=3, batch_size=8, update_every=4, discount=0.9)
    assert (replay.size, replay.return_steps, replay.batch_size) == (100, 3, 8)
    assert (replay.update_every, replay.discount) == (4, 0.9)
    with pytest.raises(ValueError, match="batch_size"):
        Transitions(batch_size=0)
    assert make_exploration("normal", 0.2, start_steps=7).start_steps == 7
    assert NoNoise(start_steps=3).name == "none" and NormalNoise().name == "normal"
    actions = np.zeros((2, 1))
    np.testing.assert_array_equal(NoNoise()(actions, np.random.default_rng(0)), actions)
    with pytest.raises(ValueError, match="start_steps"):
        EpsilonGreedy(start_steps=-1)


def test_polyak_update_is_the_one_soft_update():
    target, online = {"a": np.zeros(2)}, {"a": np.ones(2)}
    np.testing.assert_allclose(polyak_update(target, online, 0.25, f="numpy")["a"], 0.25)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        from ivy_rl.critics import soft_update

        np.testing.assert_allclose(soft_update(target, online, 0.25, f="numpy")["a"], 0.25)
    assert any("polyak_update" in str(w.message) for w in caught)


TINY = dict(
    hidden_sizes=(8,),
    batch_size=8,
    start_steps=6,
    update_after=6,
    update_every=4,
    batch_iterations=2,
    return_steps=2,
)


def _feed(agent, steps=6):
    data = np.random.default_rng(11)
    obs = data.normal(size=(2, 3))
    for t in range(steps):
        agent.step(obs)
        nxt = data.normal(size=(2, 3))
        resets = (t + np.arange(2)) % 5 == 4
        agent.update(nxt, data.normal(size=2), resets, resets & (np.arange(2) == 0))
        obs = nxt
    return ivy.nest.flatten_nest(ivy.nest.map_nest(_np, agent.v))[0]


def test_an_agent_of_parts_equals_the_agent_of_the_same_settings():
    from ivy_rl.agents import DQN, SAC

    parts = SAC(
        model=ActorQModel((8,), policy="squashed_gaussian", critics=2, targets=("critic",)),
        replay=Transitions(
            1_000_000,
            return_steps=2,
            batch_size=8,
            batch_iterations=2,
            update_after=6,
            update_every=4,
        ),
        exploration=NoNoise(start_steps=6),
        actor_updater=TwinCriticSoftPolicyGradient(),
        critic_updater=TwinCriticSoftQLearning(),
    )
    flat = SAC(**TINY)
    assert parts.config == flat.config
    for agent in (parts, flat):
        agent.initialize(OBS, BOX, seed=3, f="torch", dtype="float64", compile=False)
    for a, b in zip(_feed(parts), _feed(flat)):
        np.testing.assert_array_equal(a, b)
    with pytest.raises(TypeError, match="belong to the model given"):
        SAC(model=ActorQModel(), hidden_sizes=(8,))
    assert DQN(updater=QLearning(lr=5e-4, double=False)).config["double"] is False
    assert set(SAC.parts) == {"model", "replay", "exploration", "actor_updater", "critic_updater"}
    assert set(DQN.parts) == {"model", "replay", "exploration", "updater"}


# ----------------------------------------------------------------------------------------------
# Settings: declared once by the parts, derived by the agents
# ----------------------------------------------------------------------------------------------


def test_every_agents_settings_are_derived_from_its_parts():
    from ivy_rl.agents import AGENTS
    from ivy_rl.settings import declared

    for name, cls in AGENTS.items():
        if cls.parts is None:
            continue
        table = cls.settings()
        assert set(cls().config) == set(table), name
        for factory, names in cls.parts.values():
            spec = declared(factory)
            for flat, param in names.items():
                assert table[flat][0] == spec[param][0], (name, flat)
        # an agent's default that is not one of its settings would be a typo
        own = vars(cls).get("_defaults", {})
        assert set(own) <= set(table), (name, set(own) - set(table))
    spec, default, role = AGENTS["SAC"].settings()["batch_size"]
    assert (default, role, spec.kind) == (256, "replay", "int")
    assert AGENTS["DQN"].settings()["batch_size"][1] == 128  # DQN's difference from its replay


def test_settings_are_checked_once_with_the_parts_declarations():
    from ivy_rl.agents import SAC, TD3

    with pytest.raises(ValueError, match="setting 'target_tau' must be a number > 0 and <= 1"):
        SAC(target_tau=0.0)
    with pytest.raises(TypeError, match="setting 'policy_delay' must be an integer >= 1"):
        TD3(policy_delay=1.5)
    assert SAC(hidden_sizes=[8, 8]).config["hidden_sizes"] == (8, 8)
    assert ivy_rl.agents.check_setting("batch_iterations", 3) == 3


def test_settings_table_states_where_make_differs_from_the_constructor():
    rows = {r["name"]: r for r in ivy_rl.agents.settings_table("SAC", "Pendulum-v1")}
    assert rows["batch_size"]["agent_default"] == ivy_rl.agents.SAC().config["batch_size"]
    made = ivy_rl.agents.make("SAC", environment="Pendulum-v1").config
    assert all(made[name] == row["family_default"] for name, row in rows.items())
    assert rows["hidden_sizes"]["part"] == "model" and rows["fusion"]["part"] == "agent"


# ----------------------------------------------------------------------------------------------
# MPO's critic, and the parts of the agents that learn through ivy_gym's gradients
# ----------------------------------------------------------------------------------------------


def test_expected_sarsa_averages_the_target_critic_over_sampled_actions(diff_backend):
    from ivy_rl.off_policy_updaters import ExpectedSARSA

    xp = getattr(ivy, diff_backend)
    model = _model(xp, policy="gaussian")
    raw, batch = _batch(xp, np.random.default_rng(12))
    critic = _updater(ExpectedSARSA, xp, model, num_samples=3)
    noise = critic.draw(np.random.default_rng(13), 1, BATCH)["next_noise"][0]
    assert noise.shape == (3, BATCH, 2)
    goal = critic.goal(model.v, model.target_v, batch, None, {"next_noise": xp.asarray(noise)})
    nxt, t = raw["next_observations"], model.target_v
    dist = model.actor(xp.asarray(nxt), None, v=t["actor"])
    actions = np.clip(_np(dist.loc)[None] + _np(dist.scale)[None] * noise, -1.0, 1.0)
    values = np.mean([_q(t["critic"], nxt, a) for a in actions], axis=0)
    expected = raw["returns"] + raw["discounts"] * values
    np.testing.assert_allclose(_np(goal), expected, rtol=1e-10, atol=1e-12)


def _tanh_mlp(torso_v, x):
    layers = torso_v["mlp"]["layers"]
    for key in sorted(layers, key=int):
        x = np.tanh(x @ _np(layers[key]["w"]).T + _np(layers[key]["b"]))
    return x


def test_actor_value_model_matches_numpy(backend, xp):
    from ivy_rl.differentiable_parts import ActorValueModel

    model = ActorValueModel((5,), critic=True).initialize(
        3, 2, rng=np.random.default_rng(0), dtype="float64", f=xp
    )
    obs = np.random.default_rng(14).normal(size=(4, 3))
    actor_v = model.v["actor"]
    expected = np.tanh(_dense(actor_v["head"]["layer"], _tanh_mlp(actor_v["torso"], obs)))
    got = _np(model.actor(xp.asarray(obs), None, v=actor_v).mode())
    np.testing.assert_allclose(got, expected, rtol=1e-10, atol=1e-12)
    assert set(model.v) == {"actor", "critic", "target"}
    assert set(ActorValueModel((5,)).initialize(3, 2, rng=np.random.default_rng(0), f=xp).v) == {
        "actor"
    }


def test_analytic_policy_gradient_clips_and_logs_the_norm(diff_backend):
    from ivy_rl.differentiable_parts import AnalyticPolicyGradient

    xp = getattr(ivy, diff_backend)
    updater = AnalyticPolicyGradient(lr=0.1, gradient_clip=1.0).initialize(xp)
    v = {"w": xp.asarray(np.array([3.0, 4.0]))}
    state = updater.init_state(v)
    new_v, _, infos = updater.minimize(lambda w: (xp.sum(w["w"] ** 2) / 2, {}), v, state)
    # gradient w = (3, 4), norm 5; Adam's first step moves each weight by lr against its sign
    np.testing.assert_allclose(float(_np(infos["gradient_norm"])), 5.0, rtol=1e-12)
    np.testing.assert_allclose(float(_np(infos["loss"])), 12.5, rtol=1e-12)
    np.testing.assert_allclose(_np(new_v["w"]), [2.9, 3.9], rtol=1e-6)


def test_target_value_regression_matches_numpy(diff_backend):
    from ivy_rl.differentiable_parts import ActorValueModel, TargetValueRegression

    xp = getattr(ivy, diff_backend)
    model = ActorValueModel((5,), critic=True).initialize(
        3, 2, rng=np.random.default_rng(0), dtype="float64", f=xp
    )
    updater = TargetValueRegression(lr=1e-3, iterations=2, batches=2, target_update=0.25)
    updater.initialize(xp)
    orders = updater.orders(np.random.default_rng(1), 8)
    assert orders.shape == (4, 4) and sorted(orders[:2].ravel()) == list(range(8))
    data = np.random.default_rng(15)
    raw = {
        "observations": data.normal(size=(8, 3)),
        "targets": data.normal(size=8),
        "weights": (data.random(8) < 0.7).astype(np.float64),
    }
    batch = {k: xp.asarray(a) for k, a in raw.items()}
    critic_v = model.v["critic"]
    carry = (critic_v, updater.init_state(critic_v))
    (_, _), infos = updater.step(model.critic, carry, xp.asarray(orders[0]), batch)
    rows = orders[0]
    h = _tanh_mlp(critic_v["torso"], raw["observations"][rows])
    values = _dense(critic_v["head"]["layer"], h)[..., 0]
    w = raw["weights"][rows]
    expected = np.mean((values * w - raw["targets"][rows] * w) ** 2)
    np.testing.assert_allclose(float(_np(infos["loss"])), expected, rtol=1e-10)
    moved = updater.update_target({"a": xp.asarray(np.zeros(2))}, {"a": xp.asarray(np.ones(2))})
    np.testing.assert_allclose(_np(moved["a"]), 0.25)


def test_apg_and_shac_of_parts_take_their_settings_from_them():
    from ivy_rl.agents import APG, SHAC
    from ivy_rl.differentiable_parts import AnalyticPolicyGradient, TargetValueRegression
    from ivy_rl.replays import Rollouts

    agent = APG(replay=Rollouts(batch_size=4, horizon=8, update_every=2))
    assert (agent.config["batch_size"], agent.config["horizon"]) == (4, 8)
    shac = SHAC(
        actor_updater=AnalyticPolicyGradient(lr=5e-3),
        critic_updater=TargetValueRegression(iterations=3),
    )
    assert shac.config["actor_lr"] == 5e-3 and shac.config["critic_iterations"] == 3
    with pytest.raises(ValueError, match="horizon"):
        Rollouts(horizon=0)
    assert set(SHAC.parts) == {"model", "replay", "exploration", "actor_updater", "critic_updater"}
