"""λ-returns, GAE and n-step returns against hand-written references, on every backend, with
resets, terminations and time limits (partial-episode bootstrapping)."""

from __future__ import annotations

import numpy as np
import pytest

import ivy_rl
from tests.helpers import assert_close, native
from tests.ivy_rl import _reference as ref

T, WORKERS = 12, 3


def _segment(seed):
    """A segment of 3 workers: worker 0 terminates twice, worker 1 hits time limits (resets that
    are not terminations), worker 2 runs one long episode."""
    rng = np.random.default_rng(seed)
    rewards = rng.normal(size=(T, WORKERS))
    values = rng.normal(size=(T, WORKERS))
    next_values = rng.normal(size=(T, WORKERS))
    resets = np.zeros((T, WORKERS), bool)
    terms = np.zeros((T, WORKERS), bool)
    resets[[3, 8], 0] = terms[[3, 8], 0] = True  # terminations
    resets[[4, 10], 1] = True  # time limits
    resets[6, 1] = terms[6, 1] = True
    return rewards, values, next_values, resets, terms


CASES = [(0.99, 0.95), (0.9, 0.0), (0.97, 1.0), (0.5, 0.5)]


@pytest.mark.parametrize("discount,lam", CASES)
def test_lambda_returns_and_gae_match_the_definitions(backend, discount, lam):
    r, v, nv, resets, terms = _segment(1)
    args = [native(a, backend) for a in (r, nv, resets, terms)]
    got = ivy_rl.lambda_returns(*args, discount=discount, trace_decay=lam)
    expected = np.stack(
        [
            ref.lambda_return(r[:, w], nv[:, w], resets[:, w], terms[:, w], discount, lam)
            for w in range(WORKERS)
        ],
        axis=1,
    )
    assert_close(got, expected, "float64", rtol=1e-10, atol=1e-10)
    adv = ivy_rl.generalized_advantages(
        native(r, backend), native(v, backend), *args[1:], discount=discount, trace_decay=lam
    )
    expected_adv = np.stack(
        [
            ref.gae(r[:, w], v[:, w], nv[:, w], resets[:, w], terms[:, w], discount, lam)
            for w in range(WORKERS)
        ],
        axis=1,
    )
    assert_close(adv, expected_adv, "float64", rtol=1e-10, atol=1e-10)


@pytest.mark.parametrize("n", [1, 3, 20])
def test_n_step_returns_match_the_definition(backend, n):
    r, _, nv, resets, terms = _segment(2)
    got = ivy_rl.n_step_returns(
        *(native(a, backend) for a in (r, nv, resets, terms)), discount=0.9, steps=n
    )
    expected = np.stack(
        [ref.n_step(r[:, w], nv[:, w], resets[:, w], terms[:, w], 0.9, n) for w in range(WORKERS)],
        axis=1,
    )
    assert_close(got, expected, "float64", rtol=1e-10, atol=1e-10)


def test_partial_episode_bootstrapping_at_time_limits_only():
    """One-step targets: r + γ V(s') after a time limit, r alone after a termination."""
    r = np.array([[1.0], [2.0], [3.0]])
    nv = np.array([[10.0], [20.0], [30.0]])
    resets = np.array([[True], [True], [False]])
    terms = np.array([[False], [True], [False]])
    for fn in (ivy_rl.lambda_returns, ivy_rl.n_step_returns):
        kwargs = {"trace_decay": 0.0} if fn is ivy_rl.lambda_returns else {"steps": 1}
        got = fn(r, nv, resets, terms, discount=0.5, **kwargs)
        np.testing.assert_allclose(got[:, 0], [1.0 + 0.5 * 10.0, 2.0, 3.0 + 0.5 * 30.0])
    # λ = 1: the time limit at step 0 bootstraps V(s'_0) and the segment's end V(s'_2)
    got = ivy_rl.lambda_returns(r, nv, resets, terms, discount=0.5, trace_decay=1.0)
    np.testing.assert_allclose(got[:, 0], [6.0, 2.0, 18.0])


def test_gae_equals_lambda_returns_minus_values_within_episodes():
    r, _, nv, resets, terms = _segment(3)
    values = np.concatenate([nv[:1] * 0.3, nv[:-1]])  # V(s_{t+1}) == V(s'_t) where no reset
    adv = ivy_rl.generalized_advantages(
        r, values, nv, resets, terms, discount=0.99, trace_decay=0.9
    )
    ret = ivy_rl.lambda_returns(r, nv, resets, terms, discount=0.99, trace_decay=0.9)
    # at steps after a reset V(s_t) is the new episode's first value, which need not equal nv
    np.testing.assert_allclose(adv, ret - values, rtol=1e-10, atol=1e-10)


def test_returns_keep_float32_and_batch_dimensions(backend):
    r = np.ones((5, 2, 3), np.float32)
    flags = np.zeros((5, 2, 3), bool)
    got = ivy_rl.lambda_returns(
        native(r, backend), native(r, backend), native(flags, backend), native(flags, backend)
    )
    assert tuple(got.shape) == (5, 2, 3) and "float32" in str(got.dtype)


def test_bad_shapes_and_steps_are_refused():
    with pytest.raises(ValueError, match="same shape"):
        ivy_rl.lambda_returns(np.ones((3, 2)), np.ones((3, 1)), np.zeros((3, 2)), np.zeros((3, 2)))
    with pytest.raises(ValueError, match="steps must be an integer"):
        ivy_rl.n_step_returns(np.ones(3), np.ones(3), np.zeros(3), np.zeros(3), steps=0)


@pytest.mark.parametrize("setting", [{"discount": 1.5}, {"discount": -0.1}, {"trace_decay": 2.0}])
def test_discount_and_trace_decay_outside_zero_one_are_refused(backend, setting):
    """They gave numbers that look like returns and are none (growing with the horizon)."""
    r, z = native(np.ones((3, 2)), backend), native(np.zeros((3, 2)), backend)
    with pytest.raises(ValueError, match=f"{next(iter(setting))} must be in \\[0, 1\\]"):
        ivy_rl.lambda_returns(r, r, z, z, **setting)
    with pytest.raises(ValueError, match="must be in \\[0, 1\\]"):
        ivy_rl.generalized_advantages(r, r, r, z, z, **setting)
    if "discount" in setting:
        with pytest.raises(ValueError, match="discount must be in \\[0, 1\\]"):
            ivy_rl.n_step_returns(r, r, z, z, **setting)
