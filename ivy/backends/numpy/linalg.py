"""numpy backend: what differs from the shared layer's linear algebra
(``ivy/backends/array_api/linalg.py``)."""

from __future__ import annotations

import numpy as np


def cross(x1, x2, /, *, axis=-1):
    return np.cross(x1, x2, axis=axis)  # np.linalg.cross refuses what the tests give np.cross
