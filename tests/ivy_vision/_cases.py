"""One table of the geometry functions of ivy_vision: inputs (numpy float64) and independent
numpy references, used by the value, dtype, batch and compilation tests."""

from __future__ import annotations

import numpy as np

from tests.ivy_vision import _reference as R

_data = np.random.default_rng(2024)  # constants only; tests: the rng fixture
B, H, W, N = 2, 4, 5, 7

K = np.stack([R.calib(300.0, 310.0, 160.5, 119.5), R.calib(250.0, 240.0, 2.0, 1.5)])
K_SKEW = K.copy()
K_SKEW[:, 0, 1] = [0.7, -1.2]
K_INV = np.linalg.inv(K)
ROT = np.stack([R.random_rotation(_data) for _ in range(B)])
CENTER = _data.uniform(-2, 2, (B, 3))
EXT = np.concatenate([ROT, -ROT @ CENTER[..., None]], -1)
EXT_INV = np.concatenate([np.swapaxes(ROT, -1, -2), CENTER[..., None]], -1)
FULL = K @ EXT
FULL_INV = np.linalg.inv(np.concatenate([FULL, np.broadcast_to([[0, 0, 0, 1.0]], (B, 1, 4))], -2))[
    :, :3
]
DEPTH = _data.uniform(1.0, 3.0, (B, H, W, 1))
GRID = R.pixel_grid(H, W)
DS = GRID * DEPTH
CAM = np.concatenate([_data.uniform(-1, 1, (B, N, 2)), _data.uniform(1, 3, (B, N, 1))], -1)
WORLD = _data.uniform(-2, 2, (B, N, 3))
PIXELS = _data.uniform(0, 30, (B, N, 2))
ANGLES = _data.uniform(0.5, 2.0, (B, 2))
SPHERE = np.stack(
    [_data.uniform(-3, 3, (B, N)), _data.uniform(0.2, 2.9, (B, N)), _data.uniform(0.5, 3, (B, N))],
    -1,
)
ANGULAR = np.stack(
    [_data.uniform(0, 720, (B, N)), _data.uniform(1, 359, (B, N)), _data.uniform(0.5, 3, (B, N))],
    -1,
)
PPD = 2.0
OMNI = _data.standard_normal((B, 6, 8, 2))
MAT = _data.standard_normal((B, 2, 3))

# a second camera for the two-view functions
ROT2 = np.stack([R.random_rotation(_data) for _ in range(B)])
CENTER2 = _data.uniform(-2, 2, (B, 3))
EXT2 = np.concatenate([ROT2, -ROT2 @ CENTER2[..., None]], -1)
FULL2 = K @ EXT2


def homo44(m):
    return np.concatenate([m, np.broadcast_to([[0, 0, 0, 1.0]], m.shape[:-2] + (1, 4))], -2)


EXT12 = (homo44(EXT2) @ np.linalg.inv(homo44(EXT)))[:, :3]
FULL12 = (homo44(FULL2) @ np.linalg.inv(homo44(FULL)))[:, :3]


def _skew(v):
    z = np.zeros_like(v[..., 0])
    return np.stack(
        [
            np.stack([z, -v[..., 2], v[..., 1]], -1),
            np.stack([v[..., 2], z, -v[..., 0]], -1),
            np.stack([-v[..., 1], v[..., 0], z], -1),
        ],
        -2,
    )


def _ray_lengths(k_inv):
    return np.linalg.norm(R.apply(k_inv[:, None, None], GRID[None]), axis=-1, keepdims=True)


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _angular_to_sphere(a, ppd):
    phi = np.deg2rad(np.mod(a[..., 0] / ppd, 360.0) - 180.0)
    theta = np.deg2rad(180.0 - a[..., 1] / ppd)
    return np.stack([phi, theta, a[..., 2]], -1)


def _sphere_to_angular(s, ppd):
    x = np.mod(np.rad2deg(s[..., 0]) + 180.0, 360.0) * ppd
    y = (180.0 - np.rad2deg(s[..., 1])) * ppd
    return np.stack([x, y, s[..., 2]], -1)


def _pad_omni(image, p):
    h, w = image.shape[-3:-1]
    rolled = np.roll(image, -(w // 2), axis=-2)
    top = rolled[..., :p, :, :][..., ::-1, :, :]
    bottom = rolled[..., h - p :, :, :][..., ::-1, :, :]
    tall = np.concatenate([top, image, bottom], -3)
    return np.concatenate([tall[..., w - p :, :], tall, tall[..., :p, :]], -2)


#: name -> (positional numpy args, keyword args, reference(*args) -> expected)
CASES = {
    "persp_angles_to_focal_lengths": (
        (ANGLES, (24, 32)),
        {},
        lambda a, d: np.stack([32 / (2 * np.tan(a[:, 0] / 2)), 24 / (2 * np.tan(a[:, 1] / 2))], -1),
    ),
    "focal_lengths_to_persp_angles": (
        (np.array([[30.0, 31.0], [100.0, 12.0]]), (24, 32)),
        {},
        lambda fl, d: np.stack(
            [2 * np.arctan(32 / (2 * fl[:, 0])), 2 * np.arctan(24 / (2 * fl[:, 1]))], -1
        ),
    ),
    "focal_lengths_and_pp_offsets_to_calib_mat": (
        (K[:, [0, 1], [0, 1]], K[:, 0:2, 2]),
        {},
        lambda fl, pp: K,
    ),
    "calib_mat_to_focal_lengths_and_pp_offsets": (
        (K,),
        {},
        lambda k: (k[:, [0, 1], [0, 1]], k[:, 0:2, 2]),
    ),
    "invert_calib_mat": ((K_SKEW,), {}, np.linalg.inv),
    "rot_mat_and_cam_center_to_ext_mat": ((ROT, CENTER), {}, lambda r, c: EXT),
    "ext_mat_to_rot_mat_and_cam_center": ((EXT,), {}, lambda e: (ROT, CENTER)),
    "calib_and_ext_to_full_mat": ((K, EXT), {}, lambda k, e: FULL),
    "inv_ext_mat_to_camera_center": ((EXT_INV,), {}, lambda e: CENTER),
    "depth_to_ds_pixel_coords": ((DEPTH,), {}, lambda d: DS),
    "ds_pixel_coords_to_pixel_coords": ((DS,), {}, lambda ds: GRID[..., :2] + 0 * ds[..., :2]),
    "depth_to_radial_depth": ((DEPTH, K_INV), {}, lambda d, ki: d * _ray_lengths(ki)),
    "radial_depth_to_depth": ((DEPTH, K_INV), {}, lambda d, ki: d / _ray_lengths(ki)),
    "ds_pixel_coords_to_radial_depth": (
        (DS, K_INV),
        {},
        lambda ds, ki: np.linalg.norm(R.apply(ki, ds), axis=-1, keepdims=True),
    ),
    "cam_to_ds_pixel_coords": ((CAM, K), {}, lambda c, k: R.apply(k, c)),
    "cam_coords_to_depth": ((R.homogeneous(CAM), K), {}, lambda c, k: CAM[..., 2:3]),
    "ds_pixel_to_cam_coords": ((DS, K_INV), {}, lambda ds, ki: R.homogeneous(R.apply(ki, ds))),
    "depth_to_cam_coords": (
        (DEPTH, K_INV),
        {},
        lambda d, ki: R.homogeneous(R.apply(ki, DS)),
    ),
    "world_to_cam_coords": (
        (R.homogeneous(WORLD), EXT),
        {},
        lambda w, e: R.homogeneous(R.apply(e, WORLD)),
    ),
    "cam_to_world_coords": ((CAM, EXT_INV), {}, lambda c, e: R.homogeneous(R.apply(e, c))),
    "world_to_ds_pixel_coords": ((WORLD, FULL), {}, lambda w, p: R.apply(p, w)),
    "world_coords_to_depth": ((WORLD, FULL), {}, lambda w, p: R.apply(p, w)[..., 2:3]),
    "ds_pixel_to_world_coords": ((DS, FULL_INV), {}, lambda ds, pi: R.homogeneous(R.apply(pi, ds))),
    "depth_to_world_coords": ((DEPTH, FULL_INV), {}, lambda d, pi: R.homogeneous(R.apply(pi, DS))),
    "pixel_coords_to_world_ray_vectors": (
        (FULL_INV, PIXELS),
        {},
        lambda pi, px: _unit(R.apply(pi[..., :3], R.homogeneous(px))),
    ),
    "cam_to_sphere_coords": ((CAM,), {}, R.sphere_of),
    "sphere_to_cam_coords": ((SPHERE,), {}, lambda s: R.homogeneous(R.cam_of_sphere(s))),
    "ds_pixel_to_sphere_coords": ((DS, K_INV), {}, lambda ds, ki: R.sphere_of(R.apply(ki, ds))),
    "sphere_to_ds_pixel_coords": ((SPHERE, K), {}, lambda s, k: R.apply(k, R.cam_of_sphere(s))),
    "angular_pixel_to_sphere_coords": ((ANGULAR, PPD), {}, _angular_to_sphere),
    "sphere_to_angular_pixel_coords": ((SPHERE, PPD), {}, _sphere_to_angular),
    "sphere_coords_to_world_ray_vectors": (
        (SPHERE, np.swapaxes(ROT, -1, -2)),
        {},
        lambda s, rt: _unit(R.apply(rt, R.cam_of_sphere(s))),
    ),
    "pad_omni_image": ((OMNI, 2), {}, _pad_omni),
    "transform": ((CAM, MAT), {}, lambda c, m: R.apply(m, c)),
    "projection_matrix_inverse": ((FULL,), {}, lambda p: FULL_INV),
    "projection_matrix_pseudo_inverse": ((FULL,), {}, np.linalg.pinv),
    "ds_pixel_to_ds_pixel_coords": ((DS, FULL12), {}, lambda ds, m: R.apply(m, ds)),
    "cam_to_cam_coords": ((CAM, EXT12), {}, lambda c, m: R.homogeneous(R.apply(m, c))),
    "sphere_to_sphere_coords": (
        (SPHERE, EXT12),
        {},
        lambda s, m: R.sphere_of(R.apply(m, R.cam_of_sphere(s))),
    ),
    "angular_pixel_to_angular_pixel_coords": (
        (ANGULAR, EXT12, PPD),
        {},
        lambda a, m, ppd: _sphere_to_angular(
            R.sphere_of(R.apply(m, R.cam_of_sphere(_angular_to_sphere(a, ppd)))), ppd
        ),
    ),
    "ext_mats_to_cam1to2_ext_mat": ((EXT, EXT2), {}, lambda a, b: EXT12),
    "full_mats_to_cam1to2_full_mat": ((FULL, FULL2), {}, lambda a, b: FULL12),
    "get_essential_matrix": ((EXT, EXT2), {}, lambda a, b: _skew(EXT12[:, :, 3]) @ EXT12[:, :, :3]),
}


#: Functions whose values have a spread (pixel coordinates in the hundreds): float32 tolerance
#: is scaled by the largest magnitude of the reference.
def scale_of(expected) -> float:
    values = expected if isinstance(expected, tuple) else (expected,)
    return max(float(np.max(np.abs(v))) for v in values)


del _data  # no test draws from a generator shared by the module
