"""Gradients with each framework's own autodiff: finite everywhere (identity, rotations by pi,
gimbal lock, the origin, the poles), and equal to central finite differences (float64) at
generic points, near the singular points, and at the singular points of smooth maps."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import ivy_mechanics as mech
from tests.ivy_mechanics._cases import CASES, SMOOTH_AT_SINGULAR, make_inputs, near_singular_inputs
from tests.ivy_mechanics._utils import finite_difference, gradients

pytestmark = pytest.mark.filterwarnings("ignore:Gimbal lock")


def _check_fd(backend, fn, inputs, weights, grads, what):
    for wrt, g in enumerate(grads):
        fd = finite_difference(fn, inputs, weights, wrt)
        np.testing.assert_allclose(
            g, fd, rtol=1e-6, atol=1e-6 * max(1.0, np.abs(fd).max()), err_msg=f"{what} arg {wrt}"
        )


def test_gradients(diff_backend):
    rng = np.random.default_rng(61)
    failures = []
    for name in sorted(CASES):
        kinds, kwargs = CASES[name]
        convention = kwargs.get("convention", "zyx")
        fn = functools.partial(getattr(mech, name), **kwargs)
        sets = {
            "singular": make_inputs(kinds, None, convention, singular=True),
            "generic": make_inputs(kinds, rng, convention),
            "near singular": near_singular_inputs(kinds, rng, convention),
        }
        for what, inputs in sets.items():
            weights = rng.standard_normal(np.shape(fn(*inputs)))
            grads = gradients(diff_backend, fn, inputs, weights)
            for g, x in zip(grads, inputs):
                assert g.shape == x.shape
                if not np.all(np.isfinite(g)):
                    failures.append(f"{name} {what}: gradient not finite")
            if what != "singular" or name in SMOOTH_AT_SINGULAR:
                try:
                    _check_fd(diff_backend, fn, inputs, weights, grads, f"{name} {what}")
                except AssertionError as e:
                    failures.append(str(e).strip().splitlines()[1])
    assert not failures, "\n".join(failures)
