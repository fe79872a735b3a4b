"""The gradient of ``clip`` where ``x`` equals a bound is 1 on every backend (torch's and
tensorflow's; ``jnp.clip`` gave 1/2 there, which halved the gradient of a bilinear sample
clamped to an image's edge in ``ivy_vision.inverse_warp``)."""

from __future__ import annotations

import numpy as np

import ivy
from tests.helpers import native, numpy_of


def test_clip_passes_the_gradient_at_its_bounds(diff_backend):
    x = native(np.array([-1.0, 0.0, 0.5, 1.0, 2.0]), diff_backend)
    _, grad = ivy.execute_with_gradients(lambda v: ivy.sum(ivy.clip(v, 0.0, 1.0)), x)
    np.testing.assert_array_equal(numpy_of(grad), [0.0, 1.0, 1.0, 1.0, 0.0])


def test_clip_with_array_bounds_passes_the_gradient_at_them(diff_backend):
    x = native(np.array([0.0, 3.0, 5.0]), diff_backend)
    low = native(np.array([0.0, 1.0, 1.0]), diff_backend)
    high = native(np.array([2.0, 3.0, 4.0]), diff_backend)
    _, grad = ivy.execute_with_gradients(lambda v: ivy.sum(ivy.clip(v, low, high)), x)
    np.testing.assert_array_equal(numpy_of(grad), [1.0, 1.0, 0.0])
