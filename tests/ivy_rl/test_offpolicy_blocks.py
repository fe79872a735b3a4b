"""Off-policy building blocks: the transition replay's n-step transitions against a reference
written here (resets, terminations, time limits, the ring wrapping around), its writers (the
rows of a piece, padded, wrapping around; compiled with the arrays donated), the categorical
projection, critics' heads, and the explorations."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from ivy_rl.buffers import TransitionReplay, n_step_batch, put_ring_rows
from ivy_rl.critics import (
    BranchingQHead,
    CriticEnsemble,
    DiscreteQHead,
    action_value_critic,
    project_categorical,
)
from ivy_rl.explorations import (
    EpsilonGreedy,
    NoNoise,
    NormalNoise,
    OrnsteinUhlenbeckNoise,
    make_exploration,
)

STEPS, WORKERS, OBS = 13, 2, 3


def _history(seed=3):
    """Synthetic steps of two workers: resets (some time limits, some terminations)."""
    data = np.random.default_rng(seed)
    obs = data.normal(size=(STEPS, WORKERS, OBS))
    nxt = data.normal(size=(STEPS, WORKERS, OBS))
    rewards = data.normal(size=(STEPS, WORKERS))
    actions = data.normal(size=(STEPS, WORKERS, 1))
    resets = np.zeros((STEPS, WORKERS), bool)
    terms = np.zeros((STEPS, WORKERS), bool)
    resets[[3, 7, 8], 0] = True  # worker 0: a termination at 3, time limits at 7 and 8
    terms[3, 0] = True
    resets[[5, 10], 1] = True  # worker 1: a time limit at 5, a termination at 10
    terms[10, 1] = True
    return obs, nxt, rewards, actions, resets, terms


def _store(replay, history, t):
    """Stage step ``t`` of :func:`_history`'s steps."""
    obs, nxt, rewards, actions, resets, terms = history
    replay.store(
        observations=obs[t],
        actions=actions[t],
        rewards=rewards[t],
        next_observations=nxt[t],
        resets=resets[t].astype(np.float64),
        terminations=terms[t].astype(np.float64),
    )


def _reference(rewards, nxt, resets, terms, t, w, n, discount, value):
    """The n-step target from absolute step ``t`` of worker ``w``, one step at a time."""
    total = 0.0
    for j in range(n):
        k = t + j
        total += discount**j * rewards[k, w]
        if resets[k, w] or j == n - 1:
            break
    bootstrap = 0.0 if terms[k, w] else discount ** (j + 1) * value(nxt[k, w])
    return total + bootstrap, nxt[k, w], (0.0 if terms[k, w] else discount ** (j + 1))


@pytest.mark.parametrize("return_steps", [1, 3])
def test_n_step_transitions_match_a_reference(backend, xp, return_steps):
    obs, nxt, rewards, actions, resets, terms = _history()
    capacity = 8  # 13 steps in a ring of 8: the oldest 5 are overwritten, the ring wraps
    replay = TransitionReplay(capacity * WORKERS, return_steps=return_steps)
    for t in range(STEPS):
        _store(replay, (obs, nxt, rewards, actions, resets, terms), t)
        if t in (4, 6):  # flushed in pieces, the last one wrapping around the ring
            replay.flush(xp, device="cpu")
    replay.flush(xp, device="cpu")
    assert replay.stored == capacity and replay.steps == capacity
    indices = replay.windows(np.random.default_rng(0), 4, 40)
    assert indices.shape == (4, return_steps, 40) and indices.dtype == np.int32
    weights = np.array([0.5, -1.0, 2.0])

    def value(o):
        return float(o @ weights)

    discount = 0.9
    oldest = STEPS - capacity
    seen = set()
    for b in range(indices.shape[0]):
        batch = n_step_batch(xp, replay.arrays, xp.asarray(indices[b]), discount=discount)
        batch = {k: np.asarray(ivy.to_numpy(a)) for k, a in batch.items()}
        targets = batch["returns"] + batch["discounts"] * (batch["next_observations"] @ weights)
        for i, flat in enumerate(indices[b, 0]):
            row, w = divmod(int(flat), WORKERS)
            t = oldest + (row - oldest) % capacity  # the absolute step held by that ring row
            assert oldest <= t <= STEPS - return_steps, "an incomplete window was drawn"
            seen.add((t, w))
            expected, next_obs, disc = _reference(
                rewards, nxt, resets, terms, t, w, return_steps, discount, value
            )
            np.testing.assert_allclose(targets[i], expected, rtol=1e-12, atol=1e-12)
            np.testing.assert_allclose(batch["next_observations"][i], next_obs, rtol=1e-12)
            np.testing.assert_allclose(batch["discounts"][i], disc, rtol=1e-12, atol=1e-15)
            np.testing.assert_allclose(batch["observations"][i], obs[t, w], rtol=1e-12)
            np.testing.assert_allclose(batch["actions"][i], actions[t, w], rtol=1e-12)
    # the draws covered the termination and the time limits (160 draws of 12 to 16 windows)
    assert len(seen) >= 10


@pytest.mark.parametrize("flushes", [(2, 5, 9, 12), (12,)])
def test_the_ring_holds_the_last_steps_whatever_the_flushes(backend, xp, flushes):
    # the ring's rows against the last steps written by hand; flushes of a few steps, wrapping
    # around, and one flush of more steps than the ring holds (only the last ones survive)
    obs, nxt, rewards, actions, resets, terms = _history()
    capacity = 5
    replay = TransitionReplay(capacity * WORKERS)
    before = None
    for t in range(STEPS):
        _store(replay, (obs, nxt, rewards, actions, resets, terms), t)
        if t in flushes:
            replay.flush(xp, device="cpu")
            before = before or dict(replay.arrays)
    assert replay.stored == capacity and replay.position == STEPS % capacity
    expected = np.zeros((capacity, WORKERS, OBS))
    for t in range(STEPS - capacity, STEPS):
        expected[t % capacity] = obs[t]
    got = np.asarray(ivy.to_numpy(replay.arrays["observations"]))
    np.testing.assert_array_equal(got, expected.reshape(capacity * WORKERS, OBS))
    if xp.capabilities.mutable_arrays:  # written in place: the same arrays throughout
        assert all(replay.arrays[k] is before[k] for k in before)
        state = replay.state_dict()  # a copy, which later writes leave alone
        replay.arrays["rewards"][0] = 123.0
        assert state["arrays.rewards"][0] != 123.0


def test_replay_checkpoint_round_trip_and_errors(backend, xp):
    obs, nxt, rewards, actions, resets, terms = _history()
    replay = TransitionReplay(10, return_steps=2)
    with pytest.raises(RuntimeError, match="window"):
        replay.windows(np.random.default_rng(0), 1, 4)
    for t in range(7):
        _store(replay, (obs, nxt, rewards, actions, resets, terms), t)
        if t == 4:
            replay.flush(xp)
    state = replay.state_dict()  # two steps still staged
    other = TransitionReplay(10, return_steps=2)
    other.load_state_dict(state, xp)
    for r in (replay, other):
        r.flush(xp)
    draws = [r.windows(np.random.default_rng(5), 2, 6) for r in (replay, other)]
    np.testing.assert_array_equal(*draws)
    for key in replay.arrays:
        np.testing.assert_array_equal(
            ivy.to_numpy(replay.arrays[key]), ivy.to_numpy(other.arrays[key])
        )
    with pytest.raises(ValueError, match="rewards has shape"):
        replay.store(
            observations=obs[0],
            actions=actions[0],
            rewards=rewards[0, :1],
            next_observations=nxt[0],
            resets=resets[0].astype(float),
            terminations=terms[0].astype(float),
        )
    with pytest.raises(ValueError, match="return_steps"):
        TransitionReplay(10, return_steps=0)


def _ring_reference(arrays, chunk, start, length):
    """Row ``(start + j) % total`` takes ``chunk``'s row ``j`` for ``j < length``, one at a time."""
    out = {k: np.array(a, copy=True) for k, a in arrays.items()}
    for key, a in out.items():
        for j in range(length):
            a[(start + j) % len(a)] = chunk[key][j]
    return out


# (start, length, chunk rows) in arrays of 10 rows: inside, padded, wrapping around, empty,
# the whole ring, a start beyond the end
RING_WRITES = [(0, 3, 4), (8, 4, 4), (9, 2, 4), (5, 0, 3), (3, 10, 10), (13, 5, 6), (7, 1, 1)]


@pytest.mark.parametrize("start, length, size", RING_WRITES)
def test_put_ring_rows_writes_the_piece_and_keeps_the_other_rows(backend, xp, start, length, size):
    data = np.random.default_rng(start * 10 + length)
    arrays = {"o": data.normal(size=(10, 2)), "r": data.normal(size=10)}
    chunk = {"o": data.normal(size=(size, 2)), "r": data.normal(size=size)}
    expected = _ring_reference(arrays, chunk, start, length)

    def inputs():
        return (
            {k: xp.asarray(a) for k, a in arrays.items()},
            {k: xp.asarray(a) for k, a in chunk.items()},
            xp.asarray(np.int32(start)),
            xp.asarray(np.int32(length)),
        )

    new = put_ring_rows(*inputs())
    for key in arrays:
        np.testing.assert_array_equal(ivy.to_numpy(new[key]), expected[key])
    arrays_in, chunk_in, start_in, length_in = inputs()
    too_long = {k: xp.concat([c] * 11) for k, c in chunk_in.items()}
    with pytest.raises(ValueError, match="does not fit"):
        put_ring_rows(arrays_in, too_long, start_in, length_in)


def test_flush_compiled_with_the_arrays_donated_holds_what_eager_flushes_do(graph_backend):
    """The immutable-array path in padded pieces that wrap around, its writer compiled with
    the arrays donated, against the same flushes run eagerly and the last steps written by
    hand; on jax the arrays held before a flush are deleted by it (nothing may keep them)."""
    xp = getattr(ivy, graph_backend)
    obs, nxt, rewards, actions, resets, terms = _history()
    capacity = 5
    compiled, eager = TransitionReplay(capacity * WORKERS), TransitionReplay(capacity * WORKERS)

    def donating(fn):
        return ivy.compile_fn(fn, donate_argnums=0)

    for t in range(STEPS):
        for replay in (compiled, eager):
            _store(replay, (obs, nxt, rewards, actions, resets, terms), t)
        if t in (3, 4, 11, 12):  # pieces of 2 steps, padded; the ring wraps around
            before = dict(compiled.arrays or {})
            compiled.flush(xp, chunk_steps=2, compile=donating)
            eager.flush(xp, chunk_steps=2)
            if graph_backend == "jax" and before:
                assert all(a.is_deleted() for a in before.values())
            for key in eager.arrays:
                np.testing.assert_array_equal(
                    ivy.to_numpy(compiled.arrays[key]), ivy.to_numpy(eager.arrays[key])
                )
    expected = np.zeros((capacity, WORKERS, OBS))
    for t in range(STEPS - capacity, STEPS):
        expected[t % capacity] = obs[t]
    got = ivy.to_numpy(compiled.arrays["observations"])
    np.testing.assert_array_equal(got, expected.reshape(capacity * WORKERS, OBS))
    assert compiled.position == eager.position == STEPS % capacity


def _project_reference(probs, returns, discounts, support):
    """C51's projection, atom by atom, with floor and ceiling."""
    v_min, v_max = support[0], support[-1]
    dz = (v_max - v_min) / (len(support) - 1)
    out = np.zeros_like(probs)
    for b in range(probs.shape[0]):
        for j, z in enumerate(support):
            tz = np.clip(returns[b] + discounts[b] * z, v_min, v_max)
            pos = (tz - v_min) / dz
            low, up = int(np.floor(pos)), int(np.ceil(pos))
            if low == up:
                out[b, low] += probs[b, j]
            else:
                out[b, low] += probs[b, j] * (up - pos)
                out[b, up] += probs[b, j] * (pos - low)
    return out


def test_categorical_projection_matches_c51(backend, xp):
    data = np.random.default_rng(1)
    support = np.linspace(-10.0, 10.0, 11)
    probs = data.dirichlet(np.ones(11), size=6)
    returns = np.array([0.0, 3.3, -25.0, 25.0, 1.0, -0.7])
    discounts = np.array([0.9, 0.0, 0.81, 0.9, 1.0, 0.5])
    got = project_categorical(
        xp, xp.asarray(probs), xp.asarray(returns), xp.asarray(discounts), xp.asarray(support)
    )
    expected = _project_reference(probs, returns, discounts, support)
    np.testing.assert_allclose(ivy.to_numpy(got), expected, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(expected.sum(-1), 1.0)


def test_dueling_and_branching_heads(backend, xp):
    rng = np.random.default_rng(0)
    x = rng.normal(size=(5, 4))
    head = DiscreteQHead(4, 3, dueling=True, dtype="float64", f=xp)
    v = ivy.nest.map_nest(lambda a: np.asarray(ivy.to_numpy(a)), head.v)
    advantages = x @ v["advantages"]["w"].T + v["advantages"]["b"]
    value = x @ v["value"]["layer"]["w"].T + v["value"]["layer"]["b"]
    expected = value + advantages - advantages.mean(-1, keepdims=True)
    np.testing.assert_allclose(ivy.to_numpy(head(xp.asarray(x))), expected, rtol=1e-12)
    branching = BranchingQHead(4, [2, 5], dueling=False, dtype="float64", f=xp)
    assert [tuple(q.shape) for q in branching(xp.asarray(x))] == [(5, 2), (5, 5)]


def test_twin_critics_and_distributional_critic(diff_backend):
    xp = getattr(ivy, diff_backend)
    rng = np.random.default_rng(0)
    critics = [action_value_critic(3, 2, (8,), rng=rng, dtype="float64", f=xp) for _ in range(2)]
    twin = CriticEnsemble(critics)
    obs, act = xp.asarray(rng.normal(size=(4, 3))), xp.asarray(rng.normal(size=(4, 2)))
    both = ivy.to_numpy(twin(obs, act, None))
    assert both.shape == (2, 4) and not np.allclose(both[0], both[1])
    np.testing.assert_allclose(both[1], ivy.to_numpy(critics[1](obs, act, None)), rtol=1e-12)
    dist = action_value_critic(
        3, 2, (8,), rng=rng, head="categorical", v_min=-1, v_max=1, atoms=5, dtype="float64", f=xp
    )(obs, act, None)
    probs = ivy.to_numpy(dist.probs())
    np.testing.assert_allclose(probs.sum(-1), 1.0, rtol=1e-6)
    np.testing.assert_allclose(
        ivy.to_numpy(dist.mean()), probs @ np.linspace(-1, 1, 5), rtol=1e-5, atol=1e-6
    )
    with pytest.raises(ValueError, match="'value' or 'categorical'"):
        action_value_critic(3, 2, (8,), rng=rng, head="quantile", f=xp)


def test_explorations_follow_their_definitions():
    actions = np.array([[0.5, -0.95], [0.0, 0.9]])
    normal = NormalNoise(0.3)(actions, np.random.default_rng(4))
    draws = np.random.default_rng(4).standard_normal(actions.shape)
    np.testing.assert_allclose(normal, np.clip(actions + 0.3 * draws, -1, 1))
    assert (NoNoise()(actions, np.random.default_rng(0)) == actions).all()

    ou = OrnsteinUhlenbeckNoise(0.5, theta=0.2, dt=0.1)
    rng, ref_rng, state = np.random.default_rng(2), np.random.default_rng(2), np.zeros((2, 2))
    for step in range(4):
        got = ou(actions, rng)
        state = state - 0.2 * state * 0.1 + 0.5 * np.sqrt(0.1) * ref_rng.standard_normal((2, 2))
        np.testing.assert_allclose(got, np.clip(actions + state, -1, 1))
        if step == 1:
            ou.reset(np.array([True, False]))
            state[0] = 0.0
    restored = OrnsteinUhlenbeckNoise(0.5, theta=0.2, dt=0.1)
    restored.load_state_dict(ou.state_dict())
    np.testing.assert_array_equal(restored.state, ou.state)

    greedy = EpsilonGreedy(1.0, 0.1, 100)
    assert greedy.epsilon(0) == 1.0 and greedy.epsilon(50) == pytest.approx(0.55)
    assert greedy.epsilon(1000) == pytest.approx(0.1)
    # once decayed, ε is exactly its end (1 + 1 * (0.05 - 1) rounds to 0.050000000000000044)
    assert EpsilonGreedy(1.0, 0.05, 10_000).epsilon(20_000) == 0.05
    assert EpsilonGreedy(0.3, 0.01, 7).epsilon(7) == 0.01
    chosen = greedy(np.full(20_000, 2), np.random.default_rng(0), num_actions=4, steps=50)
    assert set(np.unique(chosen)) == {0, 1, 2, 3}
    # greedy with probability 1 - 0.55 + 0.55 / 4
    assert np.mean(chosen == 2) == pytest.approx(1 - 0.55 * 0.75, abs=0.01)
    branching = greedy(
        np.zeros((500, 2), np.int64), np.random.default_rng(0), num_actions=(2, 7), steps=0
    )
    assert branching[:, 0].max() == 1 and branching[:, 1].max() == 6
    with pytest.raises(ValueError, match="unknown exploration 'gaussian'"):
        make_exploration("gaussian")
    assert isinstance(make_exploration("none"), NoNoise)
