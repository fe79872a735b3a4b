"""Agents that learn through ivy_gym's gradients (APG, SHAC): APG's loss and its gradient
against a numpy float64 reference and its finite differences, learning on ivy_gym's Pendulum
on a tiny budget (driven as the trainer drives them), the same update eagerly and compiled, and
the one-line error for an environment that is not differentiable."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import ivy
import ivy_gym  # noqa: F401  (registers the ivy_gym ids)
import ivy_rl
from ivy_gym.mujoco_env import gymnasium_asset
from ivy_rl.agents import APG, SHAC

PENDULUM = "ivy_gym/Pendulum-v1"


def _bound(agent, env_id=PENDULUM, env_kwargs=None, **init):
    """``agent`` set up as the trainer sets it up: ``bind_environment``, then ``initialize``;
    compiled by default where the compiler keeps loops as loops (elsewhere the tests run
    eagerly: compiling each critic step takes longer than these tests)."""
    init.setdefault("compile", ivy.get_framework(f=init["f"]).capabilities.compiled_loops)
    agent.bind_environment(env_id, env_kwargs or {})
    env = gym.make(env_id, **(env_kwargs or {}))
    agent.initialize(env.observation_space, env.action_space, **init)
    env.close()
    return agent


# ----------------------------------------------------------------------------------------------
# APG's loss: an independent numpy float64 reference, and its finite differences
# ----------------------------------------------------------------------------------------------


def _pendulum(states, policy, horizon, discount=1.0):
    """Discounted returns of ``policy(obs) -> torque`` on Gymnasium's Pendulum-v1 dynamics,
    written here in numpy (float64)."""
    th, thdot = states[:, 0].copy(), states[:, 1].copy()
    total = np.zeros(len(states))
    for t in range(horizon):
        obs = np.stack([np.cos(th), np.sin(th), thdot], axis=-1)
        u = np.clip(policy(obs), -2.0, 2.0)
        wrapped = (th + np.pi) % (2 * np.pi) - np.pi
        costs = wrapped**2 + 0.1 * thdot**2 + 0.001 * u**2
        thdot = np.clip(thdot + (3 * 10.0 / 2 * np.sin(th) + 3.0 * u) * 0.05, -8.0, 8.0)
        th = th + thdot * 0.05
        total += discount**t * -costs
    return total


def _reference_loss(params, start, horizon, discount):
    """APG's loss for a tanh-MLP policy (one hidden layer), in numpy: the negative mean
    discounted return per step; the action space is [-2, 2]."""
    w1, b1, w2, b2 = params

    def policy(obs):
        return 2.0 * np.tanh(np.tanh(obs @ w1.T + b1) @ w2.T + b2)[:, 0]

    return -np.mean(_pendulum(start, policy, horizon, discount)) / horizon


def _flat_params(actor_v, xp):
    torso = actor_v["torso"]["mlp"]["layers"]["0"]
    head = actor_v["head"]["layer"]
    return [
        np.asarray(xp.to_numpy(a), np.float64)
        for a in (torso["w"], torso["b"], head["w"], head["b"])
    ]


def test_apg_loss_and_gradient_match_a_numpy_reference(diff_backend):
    xp = ivy.get_framework(f=diff_backend)
    agent = _bound(
        APG(hidden_sizes=(4,), horizon=6, batch_size=3, discount=0.9),
        seed=3,
        f=diff_backend,
        dtype="float64",
        compile=False,
    )
    # a policy far from zero, so that the actions matter
    rng = np.random.default_rng(0)
    v = ivy.nest.map_nest(
        lambda a: xp.asarray(rng.normal(0, 0.7, tuple(a.shape)), dtype="float64"), agent.v["actor"]
    )
    start = np.array([[0.3, -0.5], [2.5, 0.8], [-1.2, 0.1]])

    def loss_and_grads(w, s):
        return xp.execute_with_gradients(lambda w: agent.policy_loss(w, s), w)[:2]

    if xp.capabilities.compilation:  # an eager jax rollout compiles each operation
        loss_and_grads = ivy.compile_fn(loss_and_grads, f=xp)
    loss, grads = loss_and_grads(v, xp.asarray(start, dtype="float64"))
    params = _flat_params(v, xp)
    expected = _reference_loss(params, start, 6, 0.9)
    np.testing.assert_allclose(float(xp.to_numpy(loss)), expected, rtol=1e-10)
    got = _flat_params(grads, xp)
    eps = 1e-6
    for i, p in enumerate(params):
        numeric = np.zeros_like(p)
        for idx in np.ndindex(p.shape):
            shifted = [q.copy() for q in params]
            shifted[i][idx] += eps
            up = _reference_loss(shifted, start, 6, 0.9)
            shifted[i][idx] -= 2 * eps
            down = _reference_loss(shifted, start, 6, 0.9)
            numeric[idx] = (up - down) / (2 * eps)
        np.testing.assert_allclose(got[i], numeric, rtol=1e-5, atol=1e-8)


# ----------------------------------------------------------------------------------------------
# Driven as the trainer drives them: they learn on ivy_gym's Pendulum on a tiny budget
# ----------------------------------------------------------------------------------------------


def _score(agent, starts, steps=32):
    """Mean return over ``steps`` steps of the agent's test policy from fixed initial states,
    on the numpy reference of the pendulum."""

    def policy(obs):
        return agent.test_step(obs.astype(np.float32))[:, 0].astype(np.float64)

    return float(np.mean(_pendulum(starts, policy, steps)))


def _drive(agent, steps, workers=2):
    """A small driver that calls the agent as the trainer does: ``step``, the environments'
    step, ``update``; the step count includes the agent's simulated steps."""
    envs = gym.make_vec(PENDULUM, num_envs=workers, vectorization_mode="sync")
    obs, _ = envs.reset(seed=0)
    counted, logs = 0, []
    while counted < steps:
        before = agent.simulated_steps
        obs, reward, terminated, truncated, _ = envs.step(agent.step(obs))
        out = agent.update(obs, reward, terminated | truncated, terminated)
        if out:
            logs.append(out)
        counted += workers + agent.simulated_steps - before
    envs.close()
    return counted, logs


@pytest.mark.parametrize("cls", [APG, SHAC], ids=lambda c: c.__name__)
def test_learns_on_pendulum_through_the_trainers_calls(diff_backend, cls):
    settings = dict(hidden_sizes=(32,), batch_size=32, horizon=32, update_every=1, actor_lr=1e-2)
    if cls is SHAC:  # 4 critic steps per update (eager torch takes ~0.1 s a step here)
        # and a critic of raw values: the normalised one (the default) needs ~100 updates to
        # settle before the actor gains from it (benchmarks/rl_sample_efficiency.py)
        settings.update(critic_iterations=2, critic_batches=2, normalize_returns=False)
    agent = _bound(cls(**settings), seed=0, f=diff_backend)
    starts = np.random.default_rng(1).uniform([-np.pi, -1.0], [np.pi, 1.0], (64, 2))
    before = _score(agent, starts)
    counted, logs = _drive(agent, 60 * 32 * 32)
    after = _score(agent, starts)
    print(before, after)
    assert agent.simulated_steps == len(logs) * 32 * 32 and len(logs) >= 59
    assert counted == agent.simulated_steps + 2 * agent.updates
    assert all(np.isfinite(v) for log in logs for v in log.values())
    assert after > before + 15, (before, after)  # about 10%: -187 -> -153 (APG), -167 (SHAC)


# ----------------------------------------------------------------------------------------------
# Eager and compiled: the same numbers
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("cls", [APG, SHAC], ids=lambda c: c.__name__)
def test_compiled_update_equals_eager(diff_backend, cls):
    xp = ivy.get_framework(f=diff_backend)
    if not xp.capabilities.compiled_loops:
        pytest.skip("compiles one optimisation step at a time here; the rollout runs eagerly")
    results = []
    for compile in (False, True):
        agent = _bound(
            cls(hidden_sizes=(8,), batch_size=4, horizon=3, update_every=1, critic_batches=2)
            if cls is SHAC
            else cls(hidden_sizes=(8,), batch_size=4, horizon=3, update_every=1),
            seed=0,
            f=diff_backend,
            dtype="float64",
            compile=compile,
        )
        assert agent.fusion == "update"
        obs = np.zeros((1, 3))
        logs = [agent.update(obs, np.zeros(1), np.zeros(1, bool), np.zeros(1, bool))]
        results.append((logs, [np.asarray(xp.to_numpy(a)) for a in ivy.nest.nest_leaves(agent.v)]))
        if compile:  # one compilation of the update, and none at later updates
            assert agent.compiles == 1
            agent.update(obs, np.zeros(1), np.zeros(1, bool), np.zeros(1, bool))
            assert agent.compiles == 1
    (eager_logs, eager_v), (compiled_logs, compiled_v) = results
    for a, b in zip(eager_v, compiled_v):
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-12)
    for a, b in zip(eager_logs, compiled_logs):
        assert a.keys() == b.keys()
        np.testing.assert_allclose([a[k] for k in a], [b[k] for k in a], rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("cls", [APG, SHAC], ids=lambda c: c.__name__)
def test_scheduled_learning_rates_are_the_constant_ones_at_the_progress(diff_backend, cls):
    """``linear:`` learning rates read at the run's progress: the scheduled update (compiled
    where loops stay loops) equals the eager update with the constants at that progress, and a
    new progress compiles nothing new."""
    xp = ivy.get_framework(f=diff_backend)
    tiny = dict(hidden_sizes=(8,), batch_size=4, horizon=3, update_every=1)
    if cls is SHAC:
        tiny.update(critic_batches=2, critic_iterations=1)
    scheduled = dict(actor_lr="linear:4e-2:0")
    constant = dict(actor_lr=1e-2)
    if cls is SHAC:
        scheduled["critic_lr"], constant["critic_lr"] = "linear:1e-2:3e-2", 2.5e-2
    obs, zeros, no = np.zeros((1, 3)), np.zeros(1), np.zeros(1, bool)

    def run(settings, compile, progress):
        init = {} if compile else {"compile": False}  # compiled: where loops stay loops
        agent = _bound(cls(**tiny, **settings), seed=0, f=diff_backend, dtype="float64", **init)
        compiles = []
        for p in progress:
            agent.set_progress(p)
            agent.update(obs, zeros, no, no)
            compiles.append(agent.compiles)
        return [np.asarray(xp.to_numpy(a)) for a in ivy.nest.nest_leaves(agent.v)], compiles

    weights, _ = run(scheduled, True, [0.75, 0.75])
    same, _ = run(constant, False, [0.75, 0.75])
    for a, b in zip(weights, same):
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-12)
    _, compiles = run(scheduled, True, [0.1, 0.4, 0.9])
    assert len(set(compiles)) == 1, compiles  # a changing value compiles nothing new
    start, _ = run({k: float(v.split(":")[1]) for k, v in scheduled.items()}, False, [0.75] * 2)
    assert any(not np.allclose(a, b) for a, b in zip(weights, start))


# ----------------------------------------------------------------------------------------------
# Registration, checkpoints and errors
# ----------------------------------------------------------------------------------------------


def test_registered_and_marked_differentiable():
    for name in ("APG", "SHAC"):
        cls = ivy_rl.agents.AGENTS[name]
        assert cls.differentiable is True
        assert type(ivy_rl.agents.make(name.lower())) is cls


@pytest.mark.parametrize("env_id", ["CartPole-v1", "Pendulum-v1", "ivy_gym/CartPole-v1", "Nope-v0"])
@pytest.mark.parametrize("cls", [APG, SHAC], ids=lambda c: c.__name__)
def test_non_differentiable_environment_is_refused_in_one_line(cls, env_id):
    with pytest.raises(ValueError) as info:
        cls().bind_environment(env_id, {})
    message = str(info.value)
    assert "\n" not in message and env_id in message and cls.__name__ in message


def test_acting_needs_no_environment_learning_does(tmp_path, diff_backend):
    """``play`` builds an agent from its checkpoint without binding an environment: it acts
    as the trained agent did; learning asks for ``bind_environment``."""
    settings = dict(hidden_sizes=(8,), batch_size=4, horizon=4, update_every=1)
    trained = _bound(SHAC(**settings), f=diff_backend)
    obs, zeros, flags = np.ones((2, 3), np.float32), np.zeros(2), np.zeros(2, bool)
    trained.update(obs, zeros, flags, flags)
    trained.save(tmp_path / "agent")
    env = gym.make(PENDULUM)
    player = SHAC(**settings)
    compile = ivy.get_framework(f=diff_backend).capabilities.compiled_loops
    player.initialize(env.observation_space, env.action_space, f=diff_backend, compile=compile)
    player.load(tmp_path / "agent")
    np.testing.assert_array_equal(player.test_step(obs), trained.test_step(obs))
    with pytest.raises(RuntimeError, match="bind_environment"):
        player.update(obs, zeros, flags, flags)


def test_bad_settings_name_the_setting():
    with pytest.raises(ValueError, match="horizon"):
        APG(horizon=0)
    with pytest.raises(TypeError, match="unknown settings"):
        SHAC(segment_size=3)


def test_make_applies_the_ivy_gym_defaults():
    agent = ivy_rl.agents.make("SHAC", environment=PENDULUM, horizon=16)
    row = ivy_rl.agents.DEFAULTS["SHAC"]["ivy_gym"]
    assert agent.config["horizon"] == 16
    assert agent.config["critic_iterations"] == row["critic_iterations"]
    with pytest.raises(ValueError, match="horizon"):
        ivy_rl.agents.make("APG", environment=PENDULUM, horizon=0)


def test_core_parameters_reach_the_core():
    agent = APG()
    agent.bind_environment("ivy_gym/Reacher-v0", {"num_joints": 3})
    assert agent.core.num_joints == 3 and agent.episode_steps == 200


def test_checkpoint_continues_exactly(tmp_path, diff_backend):
    def make():  # the observations' moments are part of the checkpoint
        return _bound(
            SHAC(
                normalize_observations=True,
                hidden_sizes=(8,),
                batch_size=2,
                horizon=4,
                update_every=1,
                critic_iterations=1,
                critic_batches=1,
            ),
            seed=0,
            f=diff_backend,
            dtype="float64",
        )

    obs, zeros, flags = np.zeros((1, 3)), np.zeros(1), np.zeros(1, bool)
    first = make()
    first.update(obs, zeros, flags, flags)
    first.save(tmp_path / "agent")
    expected = first.update(obs, zeros, flags, flags)
    second = make().load(tmp_path / "agent")
    assert second.simulated_steps == 8
    assert second.update(obs, zeros, flags, flags) == expected


# ----------------------------------------------------------------------------------------------
# SHAC's published settings: observation normalisation, Adam's decay rates, the family row
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("cls", [APG, SHAC])
def test_observation_moments_are_those_of_every_rollout(diff_backend, cls):
    """With ``normalize_observations``, after two updates the moments are the mean and mean of
    squares of every observation of both updates' rollouts (numpy float64 of the rollouts run
    again from the recorded starts), and acting normalises by them."""
    agent = _bound(
        cls(normalize_observations=True, hidden_sizes=(8,), batch_size=4, horizon=3),
        seed=1,
        f=diff_backend,
        dtype="float64",
    )
    xp, observations = agent.xp, []
    for _ in range(2):
        moments, actor_v = agent.obs_moments, agent.v["actor"]
        if cls is SHAC:
            start = agent._states.copy()
        else:  # APG draws its starts in the update: replay the generator
            state = agent.rng.bit_generator.state
            start = agent._initial_states(4)
            agent.rng.bit_generator.state = state
        traj = agent._rollout(actor_v, xp.asarray(start), 3, obs_stats=agent._stats(moments))
        observations.append(np.asarray(xp.to_numpy(traj.observations)).reshape(-1, 3))
        agent._learn()
    seen = np.concatenate(observations)
    got = {k: np.asarray(xp.to_numpy(v)) for k, v in agent.obs_moments.items()}
    assert got["count"] == len(seen) == 24
    np.testing.assert_allclose(got["mean"], seen.mean(0), rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(got["mean_sq"], (seen**2).mean(0), rtol=1e-10, atol=1e-12)
    obs = np.array([[0.3, -0.2, 4.0]])
    std = np.maximum(np.sqrt(np.maximum(seen.var(0), 0.0)), 1e-2)
    normalized = np.clip((obs - seen.mean(0)) / std, -10.0, 10.0)
    mode = agent.actor(xp.asarray(normalized), None, v=agent.v["actor"]).mode()
    expected = 2.0 * np.asarray(xp.to_numpy(mode))  # Pendulum's torque bound is 2
    np.testing.assert_allclose(agent.test_step(obs), expected, rtol=1e-6)  # float32 actions


def test_adam_decay_rates_reach_the_optimiser(diff_backend):
    """Two steps of the policy's updater with SHAC's decay rates equal Adam written in numpy."""
    from ivy_rl.differentiable_parts import AnalyticPolicyGradient

    xp = ivy.get_framework(f=diff_backend)
    updater = AnalyticPolicyGradient(lr=0.1, gradient_clip=0.0, beta1=0.7, beta2=0.95)
    updater.initialize(xp)
    target = np.array([1.0, -2.0, 0.5])
    v = {"w": xp.asarray(np.zeros(3))}
    state = updater.init_state(v)
    w, m, s = np.zeros(3), np.zeros(3), np.zeros(3)
    for t in (1, 2):
        v, state, _ = updater.minimize(
            lambda v: (xp.sum((v["w"] - xp.asarray(target)) ** 2), {}), v, state
        )
        g = 2.0 * (w - target)
        m, s = 0.7 * m + 0.3 * g, 0.95 * s + 0.05 * g * g
        w = w - 0.1 * (m / (1 - 0.7**t)) / (np.sqrt(s / (1 - 0.95**t)) + 1e-8)
    np.testing.assert_allclose(np.asarray(xp.to_numpy(v["w"])), w, rtol=1e-6)


def test_locomotion_family_takes_shacs_settings_and_the_mujoco_rows():
    from ivy_rl.agents.defaults import defaults_for, task_family

    assert task_family("ivy_gym/Hopper-v5") == "ivy_gym_locomotion"
    assert task_family("ivy_gym/Reacher-v5") == "ivy_gym"
    shac = ivy_rl.agents.make("SHAC", environment="ivy_gym/Ant-v5")
    assert shac.config["normalize_observations"] and shac.config["adam_beta1"] == 0.7
    assert shac.config["hidden_sizes"] == (128, 64, 32) and shac.config["activation"] == "elu"
    assert shac.critic_updater.beta2 == shac.actor_updater.beta2 == 0.95
    # agents without a locomotion row take their row for Gymnasium's MuJoCo tasks
    assert defaults_for("PPO", "ivy_gym/Hopper-v5") == defaults_for("PPO", "Hopper-v5") != {}


def test_initial_states_are_drawn_as_the_task_resets():
    """The starts of the rollouts on the Ant carry the torso's position as MuJoCo computes it
    (the forward reward's first step reads it), from Gymnasium's reset draws."""
    mujoco = pytest.importorskip("mujoco")
    agent = SHAC(batch_size=5)
    agent.bind_environment("ivy_gym/Ant-v5", {})
    agent.rng, agent.np_dtype = np.random.default_rng(3), np.float64
    states = agent._initial_states(5)
    core = agent.core
    model = mujoco.MjModel.from_xml_path(gymnasium_asset(core.params.xml_file))
    data = mujoco.MjData(model)
    nq, nv = model.nq, model.nv
    for state in states:
        data.qpos[:], data.qvel[:] = state[:nq], state[nq : nq + nv]
        mujoco.mj_forward(model, data)
        np.testing.assert_allclose(state[-2:], data.body("torso").xpos[:2], atol=1e-12)
    noise = states[:, :nq] - core.init_qpos
    assert np.abs(noise).max() <= 0.1 and noise.std() > 0.01


def test_a_gradient_that_is_not_finite_is_not_applied(diff_backend):
    """A rollout whose derivative overflows leaves the policy and Adam's state as they were
    (and says so in ``skipped``); the next finite gradient is applied as usual."""
    from ivy_rl.differentiable_parts import AnalyticPolicyGradient

    xp = ivy.get_framework(f=diff_backend)
    updater = AnalyticPolicyGradient(lr=0.1).initialize(xp)
    v = {"w": xp.asarray(np.array([0.0, 1.0]))}
    state = updater.init_state(v)

    def overflowing(v):  # sqrt's derivative at 0 is infinite
        return xp.sum(xp.sqrt(v["w"])), {}

    new_v, new_state, infos = updater.minimize(overflowing, v, state)
    assert float(xp.to_numpy(infos["skipped"])) == 1.0
    assert not np.isfinite(float(xp.to_numpy(infos["gradient_norm"])))
    for new, old in zip(ivy.nest.nest_leaves((new_v, new_state)), ivy.nest.nest_leaves((v, state))):
        np.testing.assert_array_equal(np.asarray(xp.to_numpy(new)), np.asarray(xp.to_numpy(old)))
    new_v, _, infos = updater.minimize(lambda v: (xp.sum(v["w"] ** 2), {}), v, state)
    assert float(xp.to_numpy(infos["skipped"])) == 0.0
    np.testing.assert_allclose(np.asarray(xp.to_numpy(new_v["w"])), [0.0, 0.9], atol=1e-6)
