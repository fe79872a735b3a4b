"""torch backend: random numbers from torch's global generator (``seed`` calls
``torch.manual_seed``, which seeds the CPU and every GPU)."""

from __future__ import annotations

import torch

from ivy.backends._sample_args import categorical_args, check_draw_bounds, floating_draw
from ivy.backends.torch._helpers import device_of, native_device, native_dtype


def seed(seed_value=0):
    torch.manual_seed(seed_value)


def _draw_args(a, b, shape, dtype, device, default_dtype):
    """Target dtype, device and shape of a draw with bounds ``a``, ``b`` (scalars or tensors)."""
    dtype = native_dtype(dtype) or default_dtype
    device = native_device(device) or device_of(a, b)
    if shape is None:
        shape = torch.broadcast_shapes(*(x.shape for x in (a, b) if isinstance(x, torch.Tensor)))
    return dtype, device, shape


def random_uniform(low=0.0, high=1.0, shape=None, *, dtype=None, device=None):
    dtype, device, shape = _draw_args(low, high, shape, dtype, device, torch.float32)
    floating_draw("random_uniform", "torch", dtype, dtype.is_floating_point or dtype.is_complex)
    check_draw_bounds("random_uniform", low, high, "torch")
    u = torch.rand(shape, dtype=dtype, device=device)
    return (low + (high - low) * u).to(dtype)


def random_normal(mean=0.0, std=1.0, shape=None, *, dtype=None, device=None):
    dtype, device, shape = _draw_args(mean, std, shape, dtype, device, torch.float32)
    floating_draw("random_normal", "torch", dtype, dtype.is_floating_point or dtype.is_complex)
    check_draw_bounds("random_normal", mean, std, "torch")
    z = torch.randn(shape, dtype=dtype, device=device)
    return (mean + std * z).to(dtype)


def randint(low, high, shape=None, *, dtype=None, device=None):
    check_draw_bounds("randint", low, high, "torch")
    dtype, device, shape = _draw_args(low, high, shape, dtype, device, torch.int64)
    shape = (shape,) if isinstance(shape, int) else tuple(shape)
    if not isinstance(low, torch.Tensor) and not isinstance(high, torch.Tensor):
        return torch.randint(low, high, shape, dtype=dtype, device=device)
    low, high = torch.as_tensor(low, device=device), torch.as_tensor(high, device=device)
    span = high - low
    if (span <= 0).any():
        raise ValueError("randint: every low must be smaller than its high.")
    # uniform 62-bit integers folded onto [0, span): the bias is below span / 2**62
    raw = torch.randint(0, 2**62, shape, device=device)
    return (low + raw % span).to(dtype)


def shuffle(x, /):
    return x[torch.randperm(x.shape[0], device=x.device)]


def random_categorical(logits, /, *, num_samples=1, dtype=None):
    n = categorical_args(logits.shape, num_samples)
    dtype = native_dtype(dtype) or torch.int64
    if logits.dtype not in (torch.float32, torch.float64):
        logits = logits.to(torch.float32)
    batch = logits.shape[:-1]
    probs = torch.softmax(logits.reshape(-1, n), dim=-1)
    if probs.shape[0] == 0 or num_samples == 0:
        return torch.zeros((*batch, num_samples), dtype=dtype, device=logits.device)
    out = torch.multinomial(probs, num_samples, replacement=True)
    return out.reshape(*batch, num_samples).to(dtype)
