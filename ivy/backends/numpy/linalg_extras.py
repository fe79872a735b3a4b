"""numpy backend: linear algebra beyond the Array API extension."""

from __future__ import annotations

import numpy as np

__all__ = ["einsum"]

einsum = np.einsum
