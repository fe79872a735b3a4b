"""Activation functions, elementwise unless an ``axis`` says otherwise.

``relu``, ``sigmoid``, ``softmax``, ``log_softmax`` and ``gelu`` are backend functions: each
framework's own kernel (torch ``torch.relu``/``sigmoid``/``softmax``/``F.gelu``, jax ``jax.nn``,
tf ``tf.nn``/``tf.math``; numpy has stable numpy formulas, with ``scipy.special.expit`` and
``erfc`` when scipy is installed). They are stable and, being fused, several times faster than
a composition of primitives (``benchmarks/nn_functions.py``). The others are compositions
written once (``xp = ivy.get_framework(x, f=f)``, then ``xp.where``, ``xp.exp``...) in forms
that stay finite, in value and in gradient, where the naive formula overflows: ``softplus``
exponentiates only ``-|x|``, and the unused branch of a ``where`` is never infinite (so that its
zero gradient cannot become ``0 * inf = nan``).

``tanh`` is in the elementwise group: ``ivy.tanh``.
"""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition, dispatch
from ivy.core._floats import floating
from ivy.typing import Array, Framework

__all__ = [
    "relu",
    "leaky_relu",
    "gelu",
    "sigmoid",
    "softmax",
    "log_softmax",
    "softplus",
    "silu",
    "elu",
]


@dispatch
def relu(x: Array, /, *, f: Framework = None) -> Array:
    """Rectified linear unit ``max(x, 0)`` (gradient 0 at 0; NaN stays NaN).

    Args:
        x: input array.

    Returns:
        An array like ``x``.

    Example:
        >>> ivy.relu(np.array([-1., 0., 2.]))
        array([0., 0., 2.])
    """


@composition
def leaky_relu(x: Array, /, alpha: float = 0.2, *, f: Framework = None) -> Array:
    """Leaky rectified linear unit: ``x`` where ``x > 0``, else ``alpha * x``.

    Args:
        x: input array.
        alpha: slope for negative inputs (default 0.2, as in tf; torch uses 0.01).

    Returns:
        An array like ``x``.

    Example:
        >>> ivy.leaky_relu(np.array([-1., 2.]))
        array([-0.2,  2. ])
    """
    xp = _fh.get_framework(x, f=f)
    x = floating(xp, x)
    return xp.where(xp.greater(x, 0), x, xp.multiply(x, alpha))


@dispatch(reals=True)
def gelu(x: Array, /, approximate: bool = False, *, f: Framework = None) -> Array:
    """Gaussian error linear unit ``x * Phi(x) = x / 2 * (1 + erf(x / sqrt(2)))``.

    Args:
        x: input array.
        approximate: use the tanh approximation
            ``x / 2 * (1 + tanh(sqrt(2 / pi) * (x + 0.044715 x**3)))``.

    Returns:
        An array like ``x``.

    Example:
        >>> ivy.gelu(np.array([-1., 0., 1.]))
        array([-0.15865525,  0.        ,  0.84134475])
    """


@dispatch(reals=True)
def sigmoid(x: Array, /, *, f: Framework = None) -> Array:
    """Logistic function ``1 / (1 + exp(-x))``, finite with a finite gradient everywhere.

    Args:
        x: input array.

    Returns:
        An array like ``x``, in ``[0, 1]``.

    Example:
        >>> ivy.sigmoid(np.array([-1000., 0., 1000.]))
        array([0. , 0.5, 1. ])
    """


@dispatch(reals=True)
def softmax(x: Array, /, axis: int = -1, *, f: Framework = None) -> Array:
    """``exp(x) / sum(exp(x))`` along ``axis``, computed after subtracting the maximum.

    Args:
        x: input array (logits).
        axis: the axis that sums to one.

    Returns:
        An array like ``x``. A slice that is all ``-inf``, or that holds NaN or ``+inf``, is NaN
        throughout (``inf - inf`` is NaN), on every backend.

    Example:
        >>> ivy.softmax(np.array([1000., 1000.]))
        array([0.5, 0.5])
    """


@dispatch(reals=True)
def log_softmax(x: Array, /, axis: int = -1, *, f: Framework = None) -> Array:
    """``x - logsumexp(x)`` along ``axis``: the log of :func:`softmax`, without underflow.

    Args:
        x: input array (logits).
        axis: the normalised axis.

    Returns:
        An array like ``x``.

    Example:
        >>> ivy.log_softmax(np.array([0., 1000.]))
        array([-1000.,     0.])
    """


@composition
def softplus(x: Array, /, *, f: Framework = None) -> Array:
    """``log(1 + exp(x))``, computed as ``max(x, 0) + log1p(exp(-|x|))``.

    Args:
        x: input array.

    Returns:
        An array like ``x``, positive.

    Example:
        >>> ivy.softplus(np.array([-1000., 0., 1000.]))
        array([0.00000000e+00, 6.93147181e-01, 1.00000000e+03])
    """
    xp = _fh.get_framework(x, f=f)
    x = floating(xp, x)
    positive = xp.greater(x, 0)
    exp_minus_abs = xp.exp(xp.where(positive, xp.negative(x), x))
    return xp.add(xp.where(positive, x, 0), xp.log1p(exp_minus_abs))


@composition
def silu(x: Array, /, *, f: Framework = None) -> Array:
    """Sigmoid linear unit (swish) ``x * sigmoid(x)``.

    Args:
        x: input array.

    Returns:
        An array like ``x``.

    Example:
        >>> ivy.silu(np.array([0., 1.]))
        array([0.        , 0.73105858])
    """
    xp = _fh.get_framework(x, f=f)
    x = floating(xp, x)
    return xp.multiply(x, xp.sigmoid(x))


@composition
def elu(x: Array, /, alpha: float = 1.0, *, f: Framework = None) -> Array:
    """Exponential linear unit: ``x`` where ``x > 0``, else ``alpha * (exp(x) - 1)``.

    Args:
        x: input array.
        alpha: the negative saturation value is ``-alpha``.

    Returns:
        An array like ``x``.

    Example:
        >>> ivy.elu(np.array([-1., 2.]))
        array([-0.63212056,  2.        ])
    """
    xp = _fh.get_framework(x, f=f)
    x = floating(xp, x)
    positive = xp.greater(x, 0)
    negative_part = xp.multiply(xp.expm1(xp.where(positive, 0, x)), alpha)
    return xp.where(positive, x, negative_part)
