"""Omnidirectional cameras: ego-sphere coordinates, angular (equirectangular) pixel coordinates
and the padding of omnidirectional images.

Sphere coordinates are ivy_mechanics' spherical polar coordinates ``[phi, theta, r]``. With
``forward_facing_z`` (the default) they are taken in the frame whose axes are the camera's
``(z, x, y)``: the azimuth ``phi = atan2(x, z)`` is 0 straight ahead and ``+pi/2`` to the right,
the inclination ``theta`` is the angle from the camera's ``+y`` (down) axis, ``pi/2`` on the
horizon, and ``r`` is the radial depth.

Angular pixel coordinates ``[x, y, r]`` lay the sphere out as an equirectangular image of
``360 * ppd`` by ``180 * ppd`` pixels (``ppd`` pixels per degree) that keeps the pixel
conventions (``x`` rightwards, ``y`` downwards): ``x = ((phi + 180) mod 360) * ppd`` (straight
ahead in the middle column) and ``y = (180 - theta) * ppd`` (up at the top row), angles in
degrees. (The original ivy_vision mirrored both axes, ``x = ((180 - phi) mod 360) * ppd`` and
``y = (theta mod 180) * ppd``, an image rotated by 180 degrees.)

Example:
    >>> sphere = cam_to_sphere_coords(np.array([0., 0., 2.]))   # straight ahead
    >>> sphere_to_angular_pixel_coords(sphere, 1.0)
    array([180.,  90.,   2.])
"""

from __future__ import annotations

import math

import ivy
import ivy_mechanics as mech
from ivy.typing import Array, Framework
from ivy_vision import _common as C
from ivy_vision._checks import InputError, checked

__all__ = [
    "cam_to_sphere_coords",
    "sphere_to_cam_coords",
    "ds_pixel_to_sphere_coords",
    "sphere_to_ds_pixel_coords",
    "angular_pixel_to_sphere_coords",
    "sphere_to_angular_pixel_coords",
    "sphere_coords_to_world_ray_vectors",
    "pad_omni_image",
]

_DEG = 180.0 / math.pi


def _cam_to_sphere(xp, cam, forward_facing_z):
    if forward_facing_z:
        cam = xp.concat([cam[..., 2:3], cam[..., 0:1], cam[..., 1:2]], axis=-1)
    return mech.cartesian_to_polar_coords(cam, f=xp)


def _sphere_to_cam(xp, sphere, forward_facing_z):
    cam = mech.polar_to_cartesian_coords(sphere, f=xp)
    if forward_facing_z:
        cam = xp.concat([cam[..., 1:2], cam[..., 2:3], cam[..., 0:1]], axis=-1)
    return cam


@checked
def cam_to_sphere_coords(
    cam_coords: Array, forward_facing_z: bool = True, *, f: Framework = None
) -> Array:
    """Ego-sphere coordinates ``[phi, theta, r]`` of camera-frame points.

    Args:
        cam_coords: camera-frame points *[batch_shape, 3 or 4]*.
        forward_facing_z: measure the angles in the frame ``(z, x, y)`` (see the module
            docstring); else in the camera frame itself.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Sphere coordinates *[batch_shape, 3]*.

    Example:
        >>> cam_to_sphere_coords(np.array([1., 0., 0., 1.])) / [np.pi, np.pi, 1]
        array([0.5, 0.5, 1. ])
    """
    xp = ivy.get_framework(cam_coords, f=f)
    C.check_last_dim(xp, cam_coords, (3, 4), "cam_coords")
    return _cam_to_sphere(xp, cam_coords[..., 0:3], forward_facing_z)


@checked
def sphere_to_cam_coords(
    sphere_coords: Array, forward_facing_z: bool = True, *, f: Framework = None
) -> Array:
    """Homogeneous camera-frame points of ego-sphere coordinates, the inverse of
    :func:`cam_to_sphere_coords`.

    Args:
        sphere_coords: ``[phi, theta, r]`` *[batch_shape, 3]*.
        forward_facing_z: as in :func:`cam_to_sphere_coords`.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Camera-frame points ``[x, y, z, 1]`` *[batch_shape, 4]*.

    Example:
        >>> sphere_to_cam_coords(np.array([0., np.pi / 2, 2.])).round(12) + 0.
        array([0., 0., 2., 1.])
    """
    xp = ivy.get_framework(sphere_coords, f=f)
    C.check_last_dim(xp, sphere_coords, 3, "sphere_coords")
    return C.homogeneous(xp, _sphere_to_cam(xp, sphere_coords, forward_facing_z))


@checked
def ds_pixel_to_sphere_coords(
    ds_pixel_coords: Array, inv_calib_mat: Array, *, f: Framework = None
) -> Array:
    """Ego-sphere coordinates of depth-scaled pixel coordinates (forward-facing ``z``).

    Args:
        ds_pixel_coords: ``[u*d, v*d, d]`` *[batch_shape, image_shape, 3]*.
        inv_calib_mat: inverse calibration matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Sphere coordinates *[batch_shape, image_shape, 3]*.

    Example:
        >>> ds_pixel_to_sphere_coords(np.array([0., 0., 3.]), np.eye(3)) / [1, np.pi, 1]
        array([0. , 0.5, 3. ])
    """
    xp = ivy.get_framework(ds_pixel_coords, inv_calib_mat, f=f)
    C.check_last_dim(xp, ds_pixel_coords, 3, "ds_pixel_coords")
    C.check_matrix(xp, inv_calib_mat, 3, 3, "inv_calib_mat")
    cam = C.transform(xp, ds_pixel_coords, inv_calib_mat, "ds_pixel_coords", "inv_calib_mat")
    return _cam_to_sphere(xp, cam, True)


@checked
def sphere_to_ds_pixel_coords(
    sphere_coords: Array, calib_mat: Array, *, f: Framework = None
) -> Array:
    """Depth-scaled pixel coordinates of ego-sphere coordinates (forward-facing ``z``).

    Args:
        sphere_coords: ``[phi, theta, r]`` *[batch_shape, image_shape, 3]*.
        calib_mat: calibration matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Depth-scaled pixel coordinates *[batch_shape, image_shape, 3]*.

    Example:
        >>> sphere_to_ds_pixel_coords(np.array([0., np.pi / 2, 3.]), np.eye(3)).round(12) + 0.
        array([0., 0., 3.])
    """
    xp = ivy.get_framework(sphere_coords, calib_mat, f=f)
    C.check_last_dim(xp, sphere_coords, 3, "sphere_coords")
    C.check_matrix(xp, calib_mat, 3, 3, "calib_mat")
    cam = _sphere_to_cam(xp, sphere_coords, True)
    return C.transform(xp, cam, calib_mat, "sphere_coords", "calib_mat")


@checked
def angular_pixel_to_sphere_coords(
    angular_pixel_coords: Array, pixels_per_degree: float, *, f: Framework = None
) -> Array:
    """Ego-sphere coordinates of angular pixel coordinates (see the module docstring).

    Args:
        angular_pixel_coords: ``[x, y, r]`` *[batch_shape, 3]*.
        pixels_per_degree: pixels per degree of the equirectangular image.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[phi, theta, r]`` with ``phi`` in ``[-pi, pi)`` *[batch_shape, 3]*.

    Example:
        >>> angular_pixel_to_sphere_coords(np.array([270., 90., 1.]), 1.0) / [np.pi, np.pi, 1]
        array([0.5, 0.5, 1. ])
    """
    xp = ivy.get_framework(angular_pixel_coords, f=f)
    C.check_last_dim(xp, angular_pixel_coords, 3, "angular_pixel_coords")
    degrees = angular_pixel_coords[..., 0:2] / pixels_per_degree
    phi = (xp.remainder(degrees[..., 0:1], 360.0) - 180.0) / _DEG
    theta = (180.0 - degrees[..., 1:2]) / _DEG
    return xp.concat([phi, theta, angular_pixel_coords[..., 2:3]], axis=-1)


@checked
def sphere_to_angular_pixel_coords(
    sphere_coords: Array, pixels_per_degree: float, *, f: Framework = None
) -> Array:
    """Angular pixel coordinates ``[x, y, r]`` of ego-sphere coordinates.

    Args:
        sphere_coords: ``[phi, theta, r]`` *[batch_shape, 3]*.
        pixels_per_degree: pixels per degree of the equirectangular image.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Angular pixel coordinates, ``x`` in ``[0, 360 ppd)``, ``y`` in ``[0, 180 ppd]``
        *[batch_shape, 3]*.

    Example:
        >>> sphere_to_angular_pixel_coords(np.array([np.pi / 2, np.pi / 2, 1.]), 2.0)
        array([540., 180.,   1.])
    """
    xp = ivy.get_framework(sphere_coords, f=f)
    C.check_last_dim(xp, sphere_coords, 3, "sphere_coords")
    x = xp.remainder(sphere_coords[..., 0:1] * _DEG + 180.0, 360.0) * pixels_per_degree
    y = (180.0 - sphere_coords[..., 1:2] * _DEG) * pixels_per_degree
    return xp.concat([x, y, sphere_coords[..., 2:3]], axis=-1)


@checked
def sphere_coords_to_world_ray_vectors(
    sphere_coords: Array, inv_rotation_mat: Array, *, f: Framework = None
) -> Array:
    """Unit world-frame ray directions of ego-sphere coordinates (forward-facing ``z``).

    Args:
        sphere_coords: ``[phi, theta, r]`` *[batch_shape, image_shape, 3]*.
        inv_rotation_mat: camera-to-world rotations ``R^T`` *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Unit directions *[batch_shape, image_shape, 3]*.

    Example:
        >>> sphere_coords_to_world_ray_vectors(np.array([0., np.pi / 2, 5.]), np.eye(3)).round(12)
        array([0., 0., 1.])
    """
    xp = ivy.get_framework(sphere_coords, inv_rotation_mat, f=f)
    C.check_last_dim(xp, sphere_coords, 3, "sphere_coords")
    C.check_matrix(xp, inv_rotation_mat, 3, 3, "inv_rotation_mat")
    cam = _sphere_to_cam(xp, sphere_coords, True)
    return C.normalize(
        xp, C.transform(xp, cam, inv_rotation_mat, "sphere_coords", "inv_rotation_mat")
    )


@checked
def pad_omni_image(image: Array, pad_size: int, *, f: Framework = None) -> Array:
    """Pad an equirectangular image with its own wrapped content: columns wrap around the
    sides, and rows continue over the poles from the opposite half of the image (mirrored).

    Args:
        image: omnidirectional images *[batch_shape, h, w, d]*.
        pad_size: pixels to add on each side, ``0 <= pad_size <= min(h, w)``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Padded images *[batch_shape, h + 2 pad_size, w + 2 pad_size, d]*.

    Example:
        >>> pad_omni_image(np.arange(8.).reshape(2, 4, 1), 1)[..., 0]
        array([[1., 2., 3., 0., 1., 2.],
               [3., 0., 1., 2., 3., 0.],
               [7., 4., 5., 6., 7., 4.],
               [5., 6., 7., 4., 5., 6.]])
    """
    xp = ivy.get_framework(image, f=f)
    h, w = C.check_image(xp, image, "image")
    pad = int(pad_size)
    if pad < 0 or pad > min(h, w):
        raise InputError(f"pad_size must be in [0, {min(h, w)}]; got {pad_size}.")
    if pad == 0:
        return image
    half = w // 2

    def over_pole(rows):
        rolled = xp.concat([rows[..., half:, :], rows[..., :half, :]], axis=-2)
        return xp.flip(rolled, axis=-3)

    tall = xp.concat(
        [over_pole(image[..., :pad, :, :]), image, over_pole(image[..., h - pad :, :, :])], axis=-3
    )
    return xp.concat([tall[..., w - pad :, :], tall, tall[..., :pad, :]], axis=-2)
