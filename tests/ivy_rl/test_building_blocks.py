"""Distributions, models, normalisers, the segment replay and the updaters' numerics, against
scipy and numpy references."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest
import scipy.stats

import ivy
from ivy_rl import distributions as D
from ivy_rl import models, normalizers, replays, updaters
from tests.helpers import assert_close, native

_data = np.random.default_rng(0)  # constants only; tests: the rng fixture
LOC, SCALE = _data.normal(size=(4, 3)), _data.uniform(0.3, 2.0, size=(4, 3))
ACTIONS = _data.normal(size=(4, 3))
LOGITS = _data.normal(size=(4, 5))


def test_normal_matches_scipy(rng, backend, xp):
    d = D.Normal(xp, native(LOC, backend), native(SCALE, backend))
    assert_close(
        d.log_prob(native(ACTIONS, backend)), scipy.stats.norm.logpdf(ACTIONS, LOC, SCALE).sum(-1)
    )
    assert_close(d.entropy(), scipy.stats.norm.entropy(LOC, SCALE).sum(-1))
    other = D.Normal(xp, native(LOC * 0.5, backend), native(SCALE * 1.5, backend))
    # KL of Gaussians by numerical integration over each dimension
    grid = np.linspace(-30, 30, 200001)
    kl = np.zeros(4)
    for i in range(4):
        for j in range(3):
            p = scipy.stats.norm.pdf(grid, LOC[i, j], SCALE[i, j])
            q = scipy.stats.norm.logpdf(grid, LOC[i, j] * 0.5, SCALE[i, j] * 1.5)
            kl[i] += np.trapezoid(p * (np.log(np.maximum(p, 1e-300)) - q), grid)
    assert_close(d.kl(other), kl, rtol=1e-6, atol=1e-6)
    noise = rng.normal(size=(4, 3))
    assert_close(d.sample(native(noise, backend)), LOC + SCALE * noise)


def test_squashed_normal_log_prob_is_change_of_variables(backend, xp):
    d = D.SquashedNormal(xp, native(LOC, backend), native(SCALE, backend))
    raw = ACTIONS * 3.0  # large values test the stable log(1 - tanh^2)
    expected = (scipy.stats.norm.logpdf(raw, LOC, SCALE) - np.log1p(-(np.tanh(raw) ** 2))).sum(-1)
    assert_close(d.log_prob_raw(native(raw, backend)), expected, rtol=1e-9, atol=1e-9)
    assert_close(d.raw_to_action(native(raw, backend)), np.tanh(raw))


def test_categorical_matches_numpy(rng, backend, xp):
    d = D.Categorical(xp, native(LOGITS, backend))
    logp = LOGITS - scipy.special.logsumexp(LOGITS, axis=-1, keepdims=True)
    actions = np.array([0, 4, 2, 1])
    assert_close(d.log_prob(native(actions, backend)), logp[np.arange(4), actions])
    assert_close(d.entropy(), scipy.stats.entropy(np.exp(logp), axis=-1))
    other = D.Categorical(xp, native(LOGITS[::-1].copy(), backend))
    p = np.exp(logp)
    assert_close(d.kl(other), (p * (logp - logp[::-1])).sum(-1))
    gumbel = rng.gumbel(size=(4, 5))
    assert np.array_equal(
        ivy.to_numpy(d.sample(native(gumbel, backend))), np.argmax(logp + gumbel, -1)
    )


def test_gumbel_sampling_follows_the_probabilities():
    d = D.Categorical(ivy.numpy, np.log(np.array([[0.2, 0.5, 0.3]])))
    draws = d.sample(np.random.default_rng(1).gumbel(size=(20000, 3)))
    freq = np.bincount(draws, minlength=3) / draws.size
    np.testing.assert_allclose(freq, [0.2, 0.5, 0.3], atol=0.015)


def test_mean_std_matches_numpy_over_several_updates(rng):
    data = rng.normal(2.0, 3.0, size=(50, 4))
    norm = normalizers.MeanStd((4,))
    norm.record(data[:20])
    norm.update()
    norm.record(data[20:])
    norm.update()
    np.testing.assert_allclose(norm.mean, data.mean(0), rtol=1e-12)
    np.testing.assert_allclose(norm.std, data.std(0), rtol=1e-10)
    state = norm.state_dict()
    other = normalizers.MeanStd((4,))
    other.load_state_dict(state)
    np.testing.assert_array_equal(other.stats("float64")["std"], norm.std)
    with pytest.raises(ValueError, match="do not end with"):
        norm.record(np.ones((3, 2)))


def test_segment_stores_steps_and_draws_minibatch_orders():
    seg = replays.Segment(4, batch_size=3, batch_iterations=2)
    for t in range(4):
        assert not seg.ready()
        seg.store(
            observations=np.full((2, 1), t, np.float32),
            rewards=np.ones(2),
            resets=np.array([t == 1, False]),
        )
    assert seg.ready() and seg.workers == 2
    np.testing.assert_array_equal(
        seg.buffers["observations"][:, :, 0], [[0, 0], [1, 1], [2, 2], [3, 3]]
    )
    with pytest.raises(RuntimeError, match="full"):
        seg.store(observations=np.zeros((2, 1)), rewards=np.ones(2), resets=np.zeros(2, bool))
    # two passes over the 8 transitions, each a permutation cut into 2 full batches of 3
    orders = seg.batch_orders(np.random.default_rng(0))
    rng = np.random.default_rng(0)
    expected = [p[:6].reshape(2, 3) for p in (rng.permutation(8), rng.permutation(8))]
    np.testing.assert_array_equal(orders, np.concatenate(expected))
    assert orders.dtype == np.int32
    whole = replays.Segment(4, batch_size=None, batch_iterations=3)
    for _ in range(4):
        whole.store(rewards=np.ones(2))
    np.testing.assert_array_equal(whole.batch_orders(rng), np.tile(np.arange(8), (3, 1)))
    state = seg.state_dict()
    other = replays.Segment(4)
    other.load_state_dict(state)
    np.testing.assert_array_equal(other.buffers["resets"], seg.buffers["resets"])
    assert other.ready()


def test_return_moments_fold_as_the_host_normalizer_does(rng):
    data = rng.normal(3.0, 2.0, size=(2, 40))
    host = normalizers.ReturnNormalizer()
    folded = normalizers.ReturnNormalizer()
    for part in data:
        host.record(part)
        host.update()
        m = folded.moments("float64")
        count, mean, mean_sq = normalizers._fold_moments(
            m["count"], m["mean"], m["mean_sq"], part.size, part.sum(), np.square(part).sum()
        )
        folded.set_moments(count, mean, mean_sq)
    assert folded.count == host.count == 80
    np.testing.assert_allclose(folded.mean, data.mean(), rtol=1e-12)
    np.testing.assert_allclose(folded.std, data.std(), rtol=1e-10)
    np.testing.assert_allclose(folded.std, host.std, rtol=1e-12)


@pytest.mark.parametrize(
    "space,head",
    [
        (gym.spaces.Discrete(3), "categorical"),
        (gym.spaces.Box(-2, 2, (2,)), "gaussian"),
        (gym.spaces.Box(-1, 1, (2,)), "squashed_gaussian"),
        (gym.spaces.Box(-1, 1, (2,)), "deterministic"),
    ],
)
def test_actor_critic_models_on_every_backend(rng, backend, xp, space, head):
    obs_space = gym.spaces.Box(-1, 1, (4,))
    model = models.actor_critic(
        obs_space, space, rng=np.random.default_rng(0), head=head, f=backend
    )
    obs = native(rng.normal(size=(5, 4)).astype(np.float32), backend)
    stats = {
        "mean": native(np.ones(4, np.float32), backend),
        "std": native(np.full(4, 2.0, np.float32), backend),
    }
    dist, values = model(obs, stats, None)
    assert tuple(values.shape) == (5,)
    mode = ivy.to_numpy(dist.mode())
    assert mode.shape == ((5,) if head == "categorical" else (5, 2))
    # the same seed gives the same weights on every backend (numpy initializers)
    ref = models.actor_critic(obs_space, space, rng=np.random.default_rng(0), head=head, f="numpy")
    for a, b in zip(ivy.nest.flatten_nest(model.v)[0], ivy.nest.flatten_nest(ref.v)[0]):
        np.testing.assert_array_equal(ivy.to_numpy(a), b)


def test_targets_follow_by_polyak_averaging(xp, backend):
    obs_space, act_space = gym.spaces.Box(-1, 1, (3,)), gym.spaces.Box(-1, 1, (1,))
    model = models.actor_critic(
        obs_space, act_space, rng=np.random.default_rng(0), with_targets=True, f=backend
    )
    old = ivy.nest.map_nest(ivy.to_numpy, model.target_v)
    model.v = ivy.nest.map_nest(lambda x: x + 1.0, model.v)
    model.update_targets(tau=0.25)
    for new, before in zip(ivy.nest.flatten_nest(model.target_v)[0], ivy.nest.flatten_nest(old)[0]):
        assert_close(new, before + 0.25)


def test_unsupported_action_spaces_list_the_supported_ones(rng):
    with pytest.raises(TypeError, match="supported action spaces: Box, Discrete"):
        models.actor_critic(
            gym.spaces.Box(-1, 1, (3,)), gym.spaces.MultiDiscrete([2, 2]), rng=rng, f="numpy"
        )
    with pytest.raises(ValueError, match="choose one of"):
        models.actor_critic(
            gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2), rng=rng, head="gaussian", f="numpy"
        )


def test_conjugate_gradient_solves_a_positive_definite_system(rng):
    a = rng.normal(size=(6, 6))
    matrix = a @ a.T + 6 * np.eye(6)
    b = {"x": rng.normal(size=4), "y": rng.normal(size=2)}

    def matvec(v):
        out = matrix @ np.concatenate([v["x"], v["y"]])
        return {"x": out[:4], "y": out[4:]}

    x = updaters.conjugate_gradient(ivy.numpy, matvec, b, steps=6, eps=0.0)
    expected = np.linalg.solve(matrix, np.concatenate([b["x"], b["y"]]))
    np.testing.assert_allclose(np.concatenate([x["x"], x["y"]]), expected, rtol=1e-8)


def test_trust_region_step_respects_the_kl_bound(diff_backend):
    xp = ivy.get_framework(f=diff_backend)
    target = native(np.array([3.0, -2.0]), diff_backend)
    v = {"loc": native(np.zeros(2), diff_backend)}
    scale = native(np.ones(2), diff_backend)
    # the old policy's arrays are separate from the variables: tensorflow's tape watches
    # tensors by identity, so an alias of v["loc"] would be differentiated too
    old = D.Normal(xp, native(np.zeros(2), diff_backend), scale)

    def loss(w):
        return xp.sum(xp.square(w["loc"] - target))

    def kl(w):
        return old.kl(D.Normal(xp, w["loc"], scale))

    new, infos = updaters.trust_region_step(xp, v, loss, kl, max_kl=0.01, damping=0.0)
    step = ivy.to_numpy(new["loc"])
    # the natural gradient points at the target; its KL (= |step|^2 / 2) is at most 0.01
    assert float(ivy.to_numpy(infos["kl"])) <= 0.01 + 1e-12
    np.testing.assert_allclose(0.5 * np.sum(step**2), ivy.to_numpy(infos["kl"]), rtol=1e-9)
    direction = np.array([3.0, -2.0]) / np.sqrt(13.0)
    np.testing.assert_allclose(step / np.linalg.norm(step), direction, rtol=1e-9)
    assert float(ivy.to_numpy(infos["loss"])) < 13.0


del _data  # no test draws from a generator shared by the module
