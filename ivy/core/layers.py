"""Layers written once as compositions: linear, layer norm, dropout, attention, LSTM.

Each resolves the backend once (``xp = ivy.get_framework(x, f=f)``) and then calls ``xp``'s
functions, so they run, differentiate and compile on every backend. Arrays are batch-first with
features last; any number of leading batch axes is allowed. Convolutions and pools are in
``ivy.core.convolutions`` and ``ivy.core.pooling``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition
from ivy.typing import Array, Framework

__all__ = ["linear", "dropout", "layer_norm", "scaled_dot_product_attention", "lstm_update"]


def _shape_error(fn, message):
    return ValueError(f"{fn}: {message}")


@composition
def linear(x: Array, weight: Array, /, bias: Array | None = None, *, f: Framework = None) -> Array:
    """Affine map ``x @ weight.T + bias`` (torch's ``F.linear``).

    Args:
        x: input ``[..., in]``.
        weight: ``[out, in]``.
        bias: optional ``[out]``.

    Returns:
        ``[..., out]``.

    Example:
        >>> ivy.linear(np.ones((2, 3)), np.ones((4, 3)), np.zeros(4)).shape
        (2, 4)
    """
    xp = _fh.get_framework(x, f=f)
    x_shape, w_shape = xp.shape(x), xp.shape(weight)
    if len(w_shape) != 2 or x_shape[-1:] != w_shape[1:]:
        raise _shape_error(
            "linear",
            f"weight must be [out, in] with in = x's last axis; got x {tuple(x_shape)} "
            f"and weight {tuple(w_shape)}.",
        )
    y = xp.matmul(x, xp.swapaxes(weight, 0, 1))
    return y if bias is None else xp.add(y, bias)


@composition
def dropout(
    x: Array, prob: float, /, *, training: bool = True, scale: bool = True, f: Framework = None
) -> Array:
    """Zero each element of ``x`` with probability ``prob`` (a new draw on every call).

    The mask comes from the backend's ``random_uniform`` (seed it with ``ivy.seed``).

    Args:
        x: input array.
        prob: the probability to drop an element, a Python float in ``[0, 1]``.
        training: when False, ``x`` is returned as it is.
        scale: multiply the kept elements by ``1 / (1 - prob)`` so that the expectation is ``x``.

    Returns:
        An array like ``x``.

    Example:
        >>> y = ivy.dropout(np.ones(1000), 0.25)  # about 750 entries of 4/3, the rest 0
    """
    if not 0 <= prob <= 1:
        raise ValueError(f"dropout: prob must be in [0, 1], got {prob!r}.")
    if not training or prob == 0:
        return x
    xp = _fh.get_framework(x, f=f)
    if prob == 1:
        return xp.zeros_like(x)
    u = xp.random_uniform(shape=xp.shape(x), dtype=xp.dtype(x), device=xp.dev(x))
    kept = xp.multiply(x, 1 / (1 - prob)) if scale else x
    return xp.where(xp.greater_equal(u, prob), kept, 0)


@composition
def layer_norm(
    x: Array,
    normalized_axes: int | Sequence[int] = -1,
    /,
    *,
    scale: Array | None = None,
    offset: Array | None = None,
    eps: float = 1e-5,
    f: Framework = None,
) -> Array:
    """Normalise ``x`` to zero mean and unit variance over ``normalized_axes``, then scale and
    offset: ``(x - mean) / sqrt(var + eps) * scale + offset`` (biased variance, as torch and tf).

    Args:
        x: input array.
        normalized_axes: an axis or a tuple of axes (default: the last).
        scale: optional array broadcastable to ``x`` (e.g. ``[features]``).
        offset: optional array broadcastable to ``x``.
        eps: added to the variance.

    Returns:
        An array like ``x``.

    Example:
        >>> ivy.layer_norm(np.array([[1., 2., 3.]]), eps=0.0)
        array([[-1.22474487,  0.        ,  1.22474487]])
    """
    xp = _fh.get_framework(x, f=f)
    axes = (normalized_axes,) if isinstance(normalized_axes, int) else tuple(normalized_axes)
    centred = xp.subtract(x, xp.mean(x, axis=axes, keepdims=True))
    var = xp.mean(xp.square(centred), axis=axes, keepdims=True)
    y = xp.divide(centred, xp.sqrt(xp.add(var, eps)))
    if scale is not None:
        y = xp.multiply(y, scale)
    if offset is not None:
        y = xp.add(y, offset)
    return y


@composition
def scaled_dot_product_attention(
    q: Array,
    k: Array,
    v: Array,
    /,
    *,
    mask: Array | None = None,
    scale: float | None = None,
    f: Framework = None,
) -> Array:
    """Attention ``softmax(q @ k^T * scale + mask) @ v``.

    Args:
        q: queries ``[..., Lq, d]`` (e.g. ``[batch, heads, Lq, d]``).
        k: keys ``[..., Lk, d]``.
        v: values ``[..., Lk, dv]``.
        mask: optional, broadcastable to ``[..., Lq, Lk]``: boolean (True = attend, as torch's
            ``attn_mask``; a query with no key to attend gets NaN) or float (added to the scores,
            e.g. 0 and ``-inf``).
        scale: the scores' factor; default ``1 / sqrt(d)``.

    Returns:
        ``[..., Lq, dv]``.

    Example:
        >>> q = k = v = np.eye(2)[None]
        >>> ivy.scaled_dot_product_attention(q, k, v, scale=1000.)
        array([[[1., 0.],
                [0., 1.]]])
    """
    xp = _fh.get_framework(q, f=f)
    q_shape, k_shape, v_shape = xp.shape(q), xp.shape(k), xp.shape(v)
    if q_shape[-1] != k_shape[-1] or k_shape[-2] != v_shape[-2]:
        raise _shape_error(
            "scaled_dot_product_attention",
            f"expected q [..., Lq, d], k [..., Lk, d], v [..., Lk, dv]; got q {tuple(q_shape)}, "
            f"k {tuple(k_shape)}, v {tuple(v_shape)}.",
        )
    if scale is None:
        scale = 1 / math.sqrt(q_shape[-1])
    scores = xp.multiply(xp.matmul(q, xp.swapaxes(k, -1, -2)), scale)
    if mask is not None:
        if xp.dtype(mask, as_str=True) == "bool":
            scores = xp.where(mask, scores, -math.inf)
        else:
            scores = xp.add(scores, mask)
    return xp.matmul(xp.softmax(scores, -1), v)


@composition
def lstm_update(
    x: Array,
    init_h: Array,
    init_c: Array,
    kernel: Array,
    recurrent_kernel: Array,
    /,
    bias: Array | None = None,
    recurrent_bias: Array | None = None,
    *,
    f: Framework = None,
) -> tuple[Array, tuple[Array, Array]]:
    """Run an LSTM over the time axis of ``x`` (gates ordered i, f, g, o as in torch and keras).

    Per step: ``z = x_t @ kernel + bias + h @ recurrent_kernel + recurrent_bias``, split into
    ``i, f, g, o``; ``c = sigmoid(f) * c + sigmoid(i) * tanh(g)``, ``h = sigmoid(o) * tanh(c)``.
    The input projection is one matrix product for all steps; the steps are a Python loop (which
    ``jax.jit`` and ``tf.function`` unroll).

    Args:
        x: inputs ``[batch, time, in]`` (any leading batch axes; time is the second last).
        init_h: initial hidden state ``[batch, hidden]``.
        init_c: initial cell state ``[batch, hidden]``.
        kernel: ``[in, 4 * hidden]``.
        recurrent_kernel: ``[hidden, 4 * hidden]``.
        bias: optional ``[4 * hidden]``.
        recurrent_bias: optional ``[4 * hidden]``.

    Returns:
        ``(hs, (h, c))``: the hidden states of every step ``[batch, time, hidden]`` and the final
        hidden and cell states ``[batch, hidden]``.

    Example:
        >>> x, h0 = np.ones((2, 5, 3)), np.zeros((2, 4))
        >>> hs, (h, c) = ivy.lstm_update(x, h0, h0, np.ones((3, 16)), np.ones((4, 16)))
        >>> hs.shape, h.shape
        ((2, 5, 4), (2, 4))
    """
    xp = _fh.get_framework(x, f=f)
    x_shape, k_shape, r_shape = xp.shape(x), xp.shape(kernel), xp.shape(recurrent_kernel)
    if len(x_shape) < 2 or x_shape[-2] == 0:
        raise _shape_error(
            "lstm_update", f"x must be [batch, time, in] with time >= 1, got {tuple(x_shape)}."
        )
    if len(r_shape) != 2 or r_shape[1] != 4 * r_shape[0]:
        raise _shape_error(
            "lstm_update",
            f"recurrent_kernel must be [hidden, 4 * hidden], got {tuple(r_shape)}.",
        )
    if len(k_shape) != 2 or k_shape[0] != x_shape[-1] or k_shape[1] != r_shape[1]:
        raise _shape_error(
            "lstm_update",
            f"kernel must be [in, 4 * hidden] = [{x_shape[-1]}, {r_shape[1]}], got "
            f"{tuple(k_shape)}.",
        )
    projected = xp.matmul(x, kernel)
    for b in (bias, recurrent_bias):
        if b is not None:
            projected = xp.add(projected, b)
    h, c = init_h, init_c
    hs = []
    for x_t in xp.unstack(projected, axis=-2):
        z = xp.add(x_t, xp.matmul(h, recurrent_kernel))
        i, f_gate, g, o = xp.split(z, 4, axis=-1)
        c = xp.add(xp.multiply(xp.sigmoid(f_gate), c), xp.multiply(xp.sigmoid(i), xp.tanh(g)))
        h = xp.multiply(xp.sigmoid(o), xp.tanh(c))
        hs.append(h)
    return xp.stack(hs, axis=-2), (h, c)
