"""A NaN reaches only the outputs that depend on it, on every backend (jax's grouped float64
convolution on the CPU let it reach every group: NaN times the zeros between groups)."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import native, numpy_of


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_a_nan_stays_in_its_channel_of_a_depthwise_convolution(backend, dtype):
    x = np.ones((1, 4, 5, 3), dtype)
    x[0, 0, 0, 1] = np.nan
    out = numpy_of(
        ivy.depthwise_conv2d(
            native(x, backend), native(np.ones((3, 3, 3), dtype), backend), 1, "VALID"
        )
    )
    nan = np.isnan(out)
    assert nan[0, 0, 0, 1] and nan.sum() == 1, np.argwhere(nan).tolist()
    np.testing.assert_allclose(out[0, 1:, :, 0], 9.0)
