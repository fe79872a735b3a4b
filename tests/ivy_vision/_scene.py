"""Ground truth from MuJoCo: a scene of primitives (a floor plane, a sphere, a rotated box and a
cylinder) ray-cast with ``mujoco.mj_multiRay`` from pinhole cameras with known intrinsics and
poses, all in numpy float64 and never through ivy.

The cameras follow the ivy_vision conventions (x right, y down, z forward; ``E = R [I | -C]``),
built here from look-at poses with numpy alone. The analytic signed distance of the scene is
written out here too, independently of ``ivy_vision.sdf``.
"""

from __future__ import annotations

import functools

import mujoco
import numpy as np

BOX_YAW = 0.5
SCENE_XML = f"""
<mujoco>
  <compiler angle="radian"/>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1"/>
    <geom name="ball" type="sphere" pos="0.3 0.25 0.4" size="0.25"/>
    <geom name="box" type="box" pos="-0.4 -0.1 0.3" euler="0 0 {BOX_YAW}" size="0.2 0.15 0.3"/>
    <geom name="post" type="cylinder" pos="0.25 -0.45 0.35" size="0.1 0.35"/>
  </worldbody>
</mujoco>
"""

BALL = (np.array([0.3, 0.25, 0.4]), 0.25)
BOX = (np.array([-0.4, -0.1, 0.3]), np.array([0.2, 0.15, 0.3]))
POST = (np.array([0.25, -0.45, 0.35]), 0.1, 0.35)


@functools.lru_cache(maxsize=1)
def model():
    m = mujoco.MjModel.from_xml_string(SCENE_XML)
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    return m, d


def scene_sdf(points: np.ndarray) -> np.ndarray:
    """Exact signed distance of ``points`` ``[..., 3]`` to the scene (min over primitives)."""
    p = np.asarray(points, np.float64)
    floor = p[..., 2]
    ball = np.linalg.norm(p - BALL[0], axis=-1) - BALL[1]
    c, s = np.cos(BOX_YAW), np.sin(BOX_YAW)
    rel = p - BOX[0]
    local = np.stack(
        [c * rel[..., 0] + s * rel[..., 1], -s * rel[..., 0] + c * rel[..., 1], rel[..., 2]], -1
    )
    q = np.abs(local) - BOX[1]
    box = np.linalg.norm(np.maximum(q, 0), axis=-1) + np.minimum(q.max(-1), 0)
    rel = p - POST[0]
    q = np.stack([np.hypot(rel[..., 0], rel[..., 1]) - POST[1], np.abs(rel[..., 2]) - POST[2]], -1)
    post = np.linalg.norm(np.maximum(q, 0), axis=-1) + np.minimum(q.max(-1), 0)
    return np.min(np.stack([floor, ball, box, post]), axis=0)


def look_at(eye, target, up=(0.0, 0.0, 1.0)):
    """World-to-camera rotation ``R`` of a camera at ``eye`` looking at ``target`` (x right,
    y down, z forward)."""
    forward = np.asarray(target, float) - np.asarray(eye, float)
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    down = np.cross(forward, right)
    return np.stack([right, down, forward])  # rows: the camera axes in the world


class PinholeCamera:
    """A camera in numpy float64: ``K``, ``R``, ``C`` and the matrices derived by hand."""

    def __init__(self, eye, target, image_dims=(24, 32), focal=(30.0, 31.0), roll=0.0):
        self.h, self.w = image_dims
        self.K = np.array(
            [
                [focal[0], 0.0, (self.w - 1) / 2 + 0.3],
                [0.0, focal[1], (self.h - 1) / 2 - 0.2],
                [0.0, 0.0, 1.0],
            ]
        )
        r = look_at(eye, target)
        cr, sr = np.cos(roll), np.sin(roll)
        self.R = np.array([[cr, -sr, 0], [sr, cr, 0], [0, 0, 1.0]]) @ r
        self.C = np.asarray(eye, np.float64)
        self.E = np.concatenate([self.R, -self.R @ self.C[:, None]], -1)
        self.P = self.K @ self.E
        homo = np.concatenate([self.P, [[0, 0, 0, 1.0]]], 0)
        self.P_inv = np.linalg.inv(homo)[:3]
        self.E_inv = np.concatenate([self.R.T, self.C[:, None]], -1)
        self.K_inv = np.linalg.inv(self.K)

    def pixel_rays(self, pixels):
        """World directions ``R^T K^-1 [u, v, 1]`` (unit camera-z) of pixels ``[N, 2]``."""
        homo = np.concatenate([pixels, np.ones_like(pixels[:, :1])], -1)
        return (self.R.T @ self.K_inv @ homo.T).T

    def cast(self, pixels, normalize=False):
        """Ray-cast distances through ``pixels`` ``[N, 2]``: planar depth (rays with unit
        camera-z), or radial depth (``normalize``); -1 where the ray hits nothing."""
        vec = self.pixel_rays(pixels)
        if normalize:
            vec = vec / np.linalg.norm(vec, axis=-1, keepdims=True)
        m, d = model()
        n = len(vec)
        geom = np.zeros(n, np.int32)
        dist = np.zeros(n)
        mujoco.mj_multiRay(
            m,
            d,
            self.C,
            np.ascontiguousarray(vec.reshape(-1)),
            None,
            1,
            -1,
            geom,
            dist,
            None,
            n,
            100.0,
        )
        return dist

    def grid(self):
        ys, xs = np.mgrid[0 : self.h, 0 : self.w]
        return np.stack([xs.ravel(), ys.ravel()], -1).astype(np.float64)

    def depth_image(self, normalize=False):
        """``[H, W, 1]`` ray-cast depth (planar by default); -1 where nothing is hit."""
        return self.cast(self.grid(), normalize).reshape(self.h, self.w, 1)


def cameras(image_dims=(24, 32)):
    """Two cameras looking at the scene from different sides (the second rolled a little)."""
    first = PinholeCamera((1.8, -1.6, 1.3), (0.0, 0.0, 0.3), image_dims)
    second = PinholeCamera((-1.5, -1.9, 1.1), (0.0, -0.1, 0.3), image_dims, (28.0, 29.0), 0.1)
    return first, second


def texture(points):
    """A smooth colour ``[..., 3]`` of world points, for warping tests."""
    p = np.asarray(points)[..., 0:3]
    return (
        np.stack([np.sin(3 * p[..., 0]), np.cos(2 * p[..., 1]), np.sin(p[..., 2] + p[..., 0])], -1)
        * 0.5
        + 0.5
    )
