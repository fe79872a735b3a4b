"""Independent references in numpy float64 (and scipy) for the ivy_vision tests: written from
the definitions, by loops where that is clearer, never with ivy."""

from __future__ import annotations

import numpy as np
import scipy.ndimage as ndi

import ivy
from tests.helpers import native, numpy_of

# ----------------------------------------------------------------------------------------------
# Running ivy_vision on a backend from numpy inputs
# ----------------------------------------------------------------------------------------------


def to_backend(value, backend, dtype=None):
    """A numpy array (in ``dtype`` if given) as a native array; other values pass through."""
    if isinstance(value, np.ndarray):
        if dtype is not None and value.dtype.kind == "f":
            value = value.astype(dtype)
        return native(value, backend)
    return value


def run(fn, backend, *args, dtype=None, **kwargs):
    """``fn`` on native arrays of ``backend``; array results (or tuples of them) as numpy."""
    out = fn(
        *[to_backend(a, backend, dtype) for a in args],
        **{k: to_backend(v, backend, dtype) for k, v in kwargs.items()},
    )
    if isinstance(out, tuple):
        return tuple(numpy_of(o) for o in out)
    return numpy_of(out)


def framework(backend):
    return getattr(ivy, backend)


# ----------------------------------------------------------------------------------------------
# Geometry
# ----------------------------------------------------------------------------------------------


def random_rotation(rng):
    q, r = np.linalg.qr(rng.standard_normal((3, 3)))
    q = q * np.sign(np.diag(r))
    return q * np.linalg.det(q)


def calib(fx, fy, px, py):
    return np.array([[fx, 0.0, px], [0.0, fy, py], [0.0, 0.0, 1.0]])


def pixel_grid(h, w):
    ys, xs = np.mgrid[0:h, 0:w]
    return np.stack([xs, ys, np.ones_like(xs)], -1).astype(np.float64)


def apply(mat, points):
    """``mat @ [p, 1]`` (``[m, n + 1]`` matrices) or ``mat @ p`` (``[m, n]``), point by point,
    batched over leading dims of ``mat`` that prefix those of ``points``."""
    mat = np.asarray(mat)
    points = np.asarray(points)
    if points.shape[-1] == mat.shape[-1] - 1:
        points = np.concatenate([points, np.ones_like(points[..., :1])], -1)
    nb = mat.ndim - 2
    ni = points.ndim - 1 - nb
    m = mat.reshape(mat.shape[:nb] + (1,) * ni + mat.shape[-2:])
    return np.einsum("...ij,...j->...i", m, points)


def homogeneous(p):
    return np.concatenate([p, np.ones_like(p[..., :1])], -1)


def sphere_of(cam):
    """``[phi, theta, r]`` of camera points, forward-facing z: angles in the frame (z, x, y)."""
    x, y, z = cam[..., 0], cam[..., 1], cam[..., 2]
    return np.stack(
        [np.arctan2(x, z), np.arctan2(np.hypot(z, x), y), np.sqrt(x * x + y * y + z * z)], -1
    )


def cam_of_sphere(s):
    phi, theta, r = s[..., 0], s[..., 1], s[..., 2]
    return np.stack(
        [r * np.sin(theta) * np.sin(phi), r * np.cos(theta), r * np.sin(theta) * np.cos(phi)], -1
    )


# ----------------------------------------------------------------------------------------------
# Sampling and warping
# ----------------------------------------------------------------------------------------------

SCIPY_MODES = {"border": "nearest", "zeros": "grid-constant"}


def sample(image, coords, method="bilinear", padding="border"):
    """scipy's ``map_coordinates`` over every batch item and channel: ``image [*B, H, W, C]``,
    ``coords [*B, *I, 2]`` as ``(x, y)``."""
    image, coords = np.asarray(image), np.asarray(coords)
    batch = image.shape[:-3]
    out = np.zeros(coords.shape[:-1] + image.shape[-1:])
    for b in np.ndindex(*batch):
        pts = coords[b].reshape(-1, 2)[:, ::-1].T
        for c in range(image.shape[-1]):
            vals = ndi.map_coordinates(
                image[b][..., c],
                pts,
                order=1 if method == "bilinear" else 0,
                mode=SCIPY_MODES[padding],
                cval=0.0,
            )
            out[b][..., c] = vals.reshape(coords.shape[len(batch) : -1])
    return out


def inverse_warp(image_src, depth_tgt, full_mat, padding="zeros"):
    """Pixel by pixel: unproject with the depth, project with ``full_mat``, sample with scipy;
    0 behind the source camera."""
    h, w = depth_tgt.shape[-3:-1]
    ds = pixel_grid(h, w) * depth_tgt
    projected = apply(full_mat, ds)
    z = projected[..., 2:3]
    with np.errstate(all="ignore"):
        coords = np.where(z > 0, projected[..., :2] / np.where(z > 0, z, 1), -2.0)
    out = sample(image_src, coords, "bilinear", padding)
    return np.where(z > 0, out, 0.0)


def splat(image, depth, full_mat, dims, with_db=True):
    """Forward warping by a loop over the source pixels (numpy float64)."""
    h, w = depth.shape[:2]
    ht, wt = dims
    best = {}
    for i in range(h):
        for j in range(w):
            p = full_mat[:, :3] @ (np.array([j, i, 1.0]) * depth[i, j, 0]) + full_mat[:, 3]
            if p[2] <= 0 or depth[i, j, 0] <= 0:
                continue
            col, row = np.floor(p[0] / p[2] + 0.5), np.floor(p[1] / p[2] + 0.5)
            if not (0 <= col < wt and 0 <= row < ht):
                continue
            key = (int(row), int(col))
            value = np.concatenate([image[i, j], [p[2]]])
            best.setdefault(key, []).append(value)
    out = np.zeros((ht, wt, image.shape[-1] + 1))
    valid = np.zeros((ht, wt, 1), bool)
    for (r, c), values in best.items():
        values = np.array(values)
        if with_db:
            values = values[values[:, -1] == values[:, -1].min()]
        out[r, c] = values.mean(0)
        valid[r, c] = True
    return out[..., :-1], out[..., -1:], valid
