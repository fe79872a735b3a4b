"""Coordinates of positions: spherical polar, cylindrical and homogeneous.

Component orders:

- spherical polar ``[phi, theta, r]``: azimuth ``phi`` in (-pi, pi] from +x towards +y,
  inclination ``theta`` in [0, pi] from +z, radius ``r >= 0`` (the order of the original
  ivy_mech), so ``x = r sin(theta) cos(phi)``, ``y = r sin(theta) sin(phi)``,
  ``z = r cos(theta)``.
- cylindrical ``[rho, phi, z]``: distance ``rho`` from the z axis, azimuth ``phi`` as above,
  height ``z``.

At the origin (and, for the angles, on the z axis) the angles are undefined; 0 is returned and
the gradients stay finite.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes

__all__ = [
    "polar_to_cartesian_coords",
    "cartesian_to_polar_coords",
    "cylindrical_to_cartesian_coords",
    "cartesian_to_cylindrical_coords",
    "make_coordinates_homogeneous",
]


@takes("polar_coords")
def polar_to_cartesian_coords(polar_coords: Array, *, f: Framework = None) -> Array:
    """Cartesian coordinates of spherical polar coordinates ``[phi, theta, r]``.

    Args:
        polar_coords: azimuth, inclination and radius *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Cartesian coordinates ``[x, y, z]`` *[batch_shape, 3]*.

    Example:
        >>> polar_to_cartesian_coords(np.array([np.pi / 2, np.pi / 2, 2.])).round(6) + 0.
        array([0., 2., 0.])
    """
    xp = ivy.get_framework(polar_coords, f=f)
    phi, theta, r = polar_coords[..., 0:1], polar_coords[..., 1:2], polar_coords[..., 2:3]
    r_sin_theta = r * xp.sin(theta)
    return xp.concat(
        [r_sin_theta * xp.cos(phi), r_sin_theta * xp.sin(phi), r * xp.cos(theta)], axis=-1
    )


@takes("cartesian_coords")
def cartesian_to_polar_coords(cartesian_coords: Array, *, f: Framework = None) -> Array:
    """Spherical polar coordinates ``[phi, theta, r]`` of cartesian coordinates.

    The inclination is ``atan2(hypot(x, y), z)`` (accurate at the poles, unlike ``acos``).

    Args:
        cartesian_coords: ``[x, y, z]`` *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Azimuth, inclination and radius *[batch_shape, 3]*.

    Example:
        >>> cartesian_to_polar_coords(np.array([0., 2., 0.])).round(6)
        array([1.570796, 1.570796, 2.      ])
    """
    xp = ivy.get_framework(cartesian_coords, f=f)
    x, y, z = cartesian_coords[..., 0:1], cartesian_coords[..., 1:2], cartesian_coords[..., 2:3]
    phi = xp.safe_atan2(y, x)
    theta = xp.safe_atan2(xp.safe_hypot(x, y), z)
    return xp.concat([phi, theta, xp.safe_norm(cartesian_coords, keepdims=True)], axis=-1)


@takes("cylindrical_coords")
def cylindrical_to_cartesian_coords(cylindrical_coords: Array, *, f: Framework = None) -> Array:
    """Cartesian coordinates of cylindrical coordinates ``[rho, phi, z]``.

    Args:
        cylindrical_coords: radial distance, azimuth and height *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Cartesian coordinates ``[x, y, z]`` *[batch_shape, 3]*.

    Example:
        >>> cylindrical_to_cartesian_coords(np.array([2., np.pi, 1.])).round(6) + 0.
        array([-2.,  0.,  1.])
    """
    xp = ivy.get_framework(cylindrical_coords, f=f)
    rho, phi = cylindrical_coords[..., 0:1], cylindrical_coords[..., 1:2]
    return xp.concat([rho * xp.cos(phi), rho * xp.sin(phi), cylindrical_coords[..., 2:3]], axis=-1)


@takes("cartesian_coords")
def cartesian_to_cylindrical_coords(cartesian_coords: Array, *, f: Framework = None) -> Array:
    """Cylindrical coordinates ``[rho, phi, z]`` of cartesian coordinates.

    Args:
        cartesian_coords: ``[x, y, z]`` *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Radial distance, azimuth and height *[batch_shape, 3]*.

    Example:
        >>> cartesian_to_cylindrical_coords(np.array([0., -3., 1.])).round(6)
        array([ 3.      , -1.570796,  1.      ])
    """
    xp = ivy.get_framework(cartesian_coords, f=f)
    x, y = cartesian_coords[..., 0:1], cartesian_coords[..., 1:2]
    return xp.concat(
        [xp.safe_hypot(x, y), xp.safe_atan2(y, x), cartesian_coords[..., 2:3]], axis=-1
    )


@takes("coords")
def make_coordinates_homogeneous(coords: Array, *, f: Framework = None) -> Array:
    """Append a 1 to each coordinate vector.

    Args:
        coords: coordinates *[batch_shape, n]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Homogeneous coordinates *[batch_shape, n + 1]*.

    Example:
        >>> make_coordinates_homogeneous(np.array([1., 2., 3.]))
        array([1., 2., 3., 1.])
    """
    xp = ivy.get_framework(coords, f=f)
    return xp.concat([coords, xp.ones_like(coords[..., 0:1])], axis=-1)
