"""Array helpers shared by ivy_robot's kernels (private). Every helper takes the backend
namespace ``xp`` first; nothing here dispatches.

Model constants are kept once, as float64 numpy arrays computed when a model is built.
:func:`constant` brings one into a kernel through the core's ``xp.constant``, in the dtype and
on the device of the kernel's input: it traces on every compiler (``jax.jit`` and
``tf.function`` embed it, ``torch.compile`` takes it as a graph input without a break), and in
eager code it is converted once per dtype and device and kept, so a loop pays no conversion and
no host-to-device copy per call. Constants are never written after the model is built.
"""

from __future__ import annotations

import numpy as np


def to_backend(xp, value, like):
    """``value`` (numpy array, number, nested list, or array) as an array of ``like``'s
    framework, dtype and device; arrays that already are pass through, keeping gradients."""
    if isinstance(value, type(like)) and value.dtype == like.dtype:
        return value
    if isinstance(value, (np.ndarray, np.generic)):
        value = value.tolist()
    return xp.asarray(value, dtype=like.dtype, device=xp.dev(like))


def constant(xp, value: np.ndarray, like):
    """The model constant ``value`` (a numpy array made once) in ``like``'s dtype, on its
    device (``xp.constant``: trace-safe, converted once in eager code)."""
    return xp.constant(value, dtype=like.dtype, device=xp.dev(like))


def constants(xp, like, arrays: dict) -> dict:
    """``{name: numpy constant}`` -> ``{name: backend array}`` of ``like``'s dtype and device."""
    return {k: constant(xp, v, like) for k, v in arrays.items()}


def check_last_axis(xp, x, size: int, name: str, owner: str, meaning: str) -> None:
    """Raise a ValueError unless ``x`` is ``[..., size]``, and a TypeError unless it is
    floating."""
    shape = tuple(x.shape)
    if len(shape) == 0 or shape[-1] != size:
        raise ValueError(f"{owner}: {name} has shape {shape}; its last axis must hold {meaning}")
    check_floating(xp, x, name, owner)


def check_floating(xp, x, name: str, owner: str) -> None:
    """Raise a TypeError unless ``x`` has a real floating dtype."""
    if not xp.isdtype(x.dtype, "real floating"):
        raise TypeError(
            f"{owner}: {name} has dtype {x.dtype}; give a floating-point array (float32 or float64)"
        )


def batch_shape_of(x, trailing: int) -> tuple | None:
    """The leading shape of ``x`` before its last ``trailing`` axes; None if unknown (a
    ``tf.function`` traced with a None dimension)."""
    shape = tuple(x.shape)
    lead = shape[: len(shape) - trailing]
    return None if any(d is None for d in lead) else lead


def broadcast_leading(xp, const, like, like_trailing: int):
    """``const`` (unbatched) broadcast to the batch shape of ``like``."""
    lead = batch_shape_of(like, like_trailing)
    if lead is not None:
        return xp.broadcast_to(const, lead + tuple(const.shape))
    # unknown batch shape: broadcast by adding zeros of the right leading shape
    zeros = xp.zeros_like(like[(Ellipsis,) + (0,) * like_trailing])
    return const + zeros[(Ellipsis,) + (None,) * len(const.shape)]


def gather_spec(indices, size: int):
    """A static gather of ``x[..., indices]`` along a last axis of length ``size``:
    ``("slice", start, stop)`` when the indices are contiguous, else ``("matrix", rows)``, a 0/1
    selection matrix (numpy; exact: sums of ``x * 1`` and zeros; no fancy indexing, which
    tensorflow lacks)."""
    indices = [int(i) for i in indices]
    if indices and indices == list(range(indices[0], indices[0] + len(indices))):
        return ("slice", indices[0], indices[0] + len(indices))
    rows = np.asarray([[1.0 if i == j else 0.0 for j in indices] for i in range(size)])
    return ("matrix", rows)


def gather_last(xp, x, spec):
    """``x[..., indices]`` for a :func:`gather_spec`."""
    if spec[0] == "slice":
        return x[..., spec[1] : spec[2]]
    selection = constant(xp, spec[1], x)
    return xp.matmul(x[..., None, :], selection)[..., 0, :]


def skew(axis: np.ndarray) -> np.ndarray:
    """The cross-product matrix of a numpy 3-vector."""
    x, y, z = axis
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
