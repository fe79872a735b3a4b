"""numpy backend: the activations with a kernel of their own (the rest are compositions).

numpy has no activation functions: these are written with numpy's elementwise functions, in the
stable forms (``scipy.special.expit`` for the sigmoid when scipy is installed).
"""

from __future__ import annotations

import math

import numpy as np

from ivy.backends.numpy._helpers import as_inexact

try:  # scipy is optional for the numpy backend
    from scipy.special import erfc as _erfc
    from scipy.special import expit as _expit
except ImportError:  # pragma: no cover - scipy is installed with the test extra
    _erfc = np.vectorize(math.erfc, otypes=[np.float64])  # exact, elementwise in Python
    _expit = None

_SQRT_HALF = math.sqrt(0.5)
_SQRT_2_OVER_PI = math.sqrt(2 / math.pi)


def _like(out, x):
    return out.astype(x.dtype, copy=False) if np.issubdtype(x.dtype, np.floating) else out


def relu(x, /):
    return np.maximum(x, 0)


def gelu(x, /, approximate=False):
    x = as_inexact(x)
    if approximate:
        out = 0.5 * x * (1 + np.tanh(_SQRT_2_OVER_PI * (x + 0.044715 * x**3)))
    else:
        out = 0.5 * x * _erfc(-_SQRT_HALF * x)  # erfc: accurate in the negative tail too
    return _like(out, x)


def sigmoid(x, /):
    x = as_inexact(x)
    if _expit is not None:
        return _like(_expit(x), x)  # (scipy's float16 expit is float64)
    z = np.exp(-np.abs(x))  # pragma: no cover
    return _like(np.where(x >= 0, 1 / (1 + z), z / (1 + z)), x)  # pragma: no cover


def softmax(x, /, axis=-1):
    x = as_inexact(x)
    e = np.exp(x - np.max(x, axis=axis, keepdims=True, initial=-np.inf))  # (-inf: empty rows)
    return e / np.sum(e, axis=axis, keepdims=True)


def log_softmax(x, /, axis=-1):
    x = as_inexact(x)
    shifted = x - np.max(x, axis=axis, keepdims=True, initial=-np.inf)
    return shifted - np.log(np.sum(np.exp(shifted), axis=axis, keepdims=True))
