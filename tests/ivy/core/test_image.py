"""Tests of the core group ``image`` (``ivy/core/image.py``), on every backend.

Images (channel-last ``[..., H, W, C]``) on every backend, against references written here with
Python loops in float64: bilinear_resample, gradient_image, stack_images.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import ivy
from tests.helpers import api, check, native, tolerance


def _image(rng, shape, dtype="float32"):
    return (rng.standard_normal(shape) * 3).astype(dtype)


def _bilinear_reference(image, warp):
    """One image ``[H, W, C]`` sampled at ``[N, 2]`` (x, y) points, border clamped."""
    h, w, _ = image.shape
    out = []
    for x, y in warp:
        x, y = min(max(x, 0.0), w - 1.0), min(max(y, 0.0), h - 1.0)
        x0, y0 = math.floor(x), math.floor(y)
        x1, y1 = min(x0 + 1, w - 1), min(y0 + 1, h - 1)
        ax, ay = x - x0, y - y0
        top = image[y0, x0] * (1 - ax) + image[y0, x1] * ax
        bottom = image[y1, x0] * (1 - ax) + image[y1, x1] * ax
        out.append(top * (1 - ay) + bottom * ay)
    return np.array(out)


def _batched_reference(images, warps):
    batch = images.shape[:-3]
    out = np.empty((*batch, warps.shape[-2], images.shape[-1]))
    for index in np.ndindex(batch):
        out[index] = _bilinear_reference(images[index].astype(np.float64), warps[index])
    return out


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("batch", [(), (2,), (2, 3)], ids=str)
def test_bilinear_resample(rng, backend, dtype, batch):
    images = _image(rng, (*batch, 4, 5, 3), dtype)
    inside = rng.uniform([0, 0], [4, 3], (*batch, 6, 2))
    outside = np.array([[-1.5, 0.5], [4.5, 2.25], [2.0, -3.0], [9.0, 9.0]])  # clamped
    warps = np.concatenate([inside, np.broadcast_to(outside, (*batch, 4, 2))], axis=-2)
    warps = warps.astype(dtype)
    expected = _batched_reference(images, warps.astype(np.float64))
    for fn in api(backend, "bilinear_resample"):
        out = fn(native(images, backend), native(warps, backend))
        check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


def test_bilinear_resample_at_pixel_centres_and_midpoints(backend):
    image = np.arange(12, dtype=np.float32).reshape(3, 4, 1)
    warp = np.array([[0, 0], [3, 2], [1, 2], [0.5, 0], [0, 0.5], [1.5, 1.5]], np.float32)
    # pixel (row y, column x) is image[y, x]; midpoints average their neighbours
    expected = np.array([[0], [11], [9], [0.5], [2], [7.5]], np.float32)
    for fn in api(backend, "bilinear_resample"):
        check(fn(native(image, backend), native(warp, backend)), expected, backend)


def test_bilinear_resample_of_integer_images_takes_the_warp_dtype(backend):
    image = np.arange(6, dtype=np.uint8).reshape(2, 3, 1)
    warp = np.array([[0.5, 0.5]], np.float64)
    for fn in api(backend, "bilinear_resample"):
        check(fn(native(image, backend), native(warp, backend)), np.array([[2.0]]), backend)


def test_bilinear_resample_refuses_mismatched_shapes(rng, backend):
    image = native(_image(rng, (2, 4, 5, 3)), backend)
    for warp_shape in [(3, 6, 2), (2, 6, 3)]:
        for fn in api(backend, "bilinear_resample"):
            with pytest.raises(ValueError, match="bilinear_resample"):
                fn(image, native(np.zeros(warp_shape, np.float32), backend))


def _gradient_reference(images):
    x = images.astype(np.float64)
    dy, dx = np.zeros_like(x), np.zeros_like(x)
    h, w = x.shape[-3:-1]
    for i in range(h - 1):
        dy[..., i, :, :] = x[..., i + 1, :, :] - x[..., i, :, :]
    for j in range(w - 1):
        dx[..., :, j, :] = x[..., :, j + 1, :] - x[..., :, j, :]
    return dy, dx


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("shape", [(4, 5, 3), (2, 3, 4, 1), (1, 1, 2), (2, 2, 3, 4, 2)], ids=str)
def test_gradient_image(rng, backend, dtype, shape):
    images = _image(rng, shape, dtype)
    dy_ref, dx_ref = _gradient_reference(images)
    for fn in api(backend, "gradient_image"):
        dy, dx = fn(native(images, backend))
        check(dy, dy_ref.astype(dtype), backend, **tolerance(dtype, 10))
        check(dx, dx_ref.astype(dtype), backend, **tolerance(dtype, 10))


def test_gradient_image_of_uint8_images_is_signed_float32(backend):
    images = np.array([[[10], [3]], [[0], [255]]], np.uint8)  # [2, 2, 1]
    dy_ref, dx_ref = _gradient_reference(images)
    for fn in api(backend, "gradient_image"):
        dy, dx = fn(native(images, backend))
        check(dy, dy_ref.astype(np.float32), backend)
        check(dx, dx_ref.astype(np.float32), backend)


# (count, image height, width, desired aspect ratio) -> (rows, columns)
GRIDS = {
    (1, 4, 4, (1, 1)): (1, 1),
    (4, 4, 4, (1, 1)): (2, 2),
    (3, 4, 4, (1, 1)): (2, 2),  # one blank cell
    (2, 4, 4, (1, 2)): (1, 2),
    (2, 4, 4, (2, 1)): (2, 1),
    (6, 2, 4, (1, 1)): (3, 2),  # wide images stack taller
    (5, 4, 4, (1, 1)): (2, 3),  # 2x3 (1 blank) is as square as 3x2 (1 blank): fewer rows
    (3, 4, 4, (1, 3)): (1, 3),
}


@pytest.mark.parametrize("case", list(GRIDS), ids=str)
def test_stack_images_grid(case):
    count, height, width, ratio = case
    rows, cols = GRIDS[case]
    images = [np.ones((height, width, 1), np.float32)] * count
    out = ivy.stack_images(images, desired_aspect_ratio=ratio)
    assert out.shape == (rows * height, cols * width, 1)


def test_the_grid_helper_is_not_public():
    # stack_images' docstring says how it chooses the grid; the helper is private (issue 17)
    assert not hasattr(ivy, "image_grid") and "image_grid" not in ivy.__all__


def _stack_reference(images, rows, cols):
    blank = np.zeros_like(images[0])
    cells = list(images) + [blank] * (rows * cols - len(images))
    h, w = images[0].shape[-3:-1]
    out = np.zeros(
        (*images[0].shape[:-3], rows * h, cols * w, images[0].shape[-1]), images[0].dtype
    )
    for k, cell in enumerate(cells):
        r, c = divmod(k, cols)
        out[..., r * h : (r + 1) * h, c * w : (c + 1) * w, :] = cell
    return out


@pytest.mark.parametrize("case", list(GRIDS), ids=str)
def test_stack_images(rng, backend, case):
    count, h, w, ratio = case
    images = [_image(rng, (2, h, w, 3)) for _ in range(count)]
    expected = _stack_reference(images, *GRIDS[case])
    for fn in api(backend, "stack_images"):
        out = fn([native(im, backend) for im in images], desired_aspect_ratio=ratio)
        check(out, expected, backend)


def test_stack_images_defaults_to_square(rng, backend):
    images = [_image(rng, (3, 3, 1), "float64") for _ in range(4)]
    for fn in api(backend, "stack_images"):
        check(fn([native(im, backend) for im in images]), _stack_reference(images, 2, 2), backend)


def test_stack_images_refuses_no_images_and_mixed_shapes(rng, backend):
    for fn in api(backend, "stack_images"):
        with pytest.raises(ValueError, match="at least one"):
            fn([])
    mixed = [native(_image(rng, (2, 2, 1)), backend), native(_image(rng, (3, 2, 1)), backend)]
    for fn in api(backend, "stack_images"):
        with pytest.raises(ValueError, match="one shape"):
            fn(mixed)
