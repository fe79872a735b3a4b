"""Signed distance functions of spheres and cuboids (negative inside, zero on the surface).

Example:
    >>> sphere_signed_distances(np.zeros((1, 3)), np.ones((1, 1)), np.array([[0., 0., 3.]]))
    array([[2.]])
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_vision import _common as C
from ivy_vision._checks import InputError, checked

__all__ = ["sphere_signed_distances", "cuboid_signed_distances"]


def _queries(xp, query_positions):
    C.check_last_dim(xp, query_positions, 3, "query_positions")
    if len(C.shape_of(xp, query_positions)) < 2:
        raise InputError(
            f"query_positions must be [..., num_points, 3]; got shape "
            f"{C.shape_of(xp, query_positions)}."
        )


@checked
def sphere_signed_distances(
    sphere_positions: Array, sphere_radii: Array, query_positions: Array, *, f: Framework = None
) -> Array:
    """Signed distance from query points to the nearest of a set of spheres.

    Args:
        sphere_positions: sphere centres *[batch_shape, num_spheres, 3]*.
        sphere_radii: radii *[batch_shape, num_spheres, 1]*.
        query_positions: points *[batch_shape, num_points, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        The smallest signed distance of each point *[batch_shape, num_points, 1]*.

    Example:
        >>> sphere_signed_distances(np.zeros((1, 3)), np.full((1, 1), 2.), np.zeros((1, 3)))
        array([[-2.]])
    """
    xp = ivy.get_framework(sphere_positions, sphere_radii, query_positions, f=f)
    _queries(xp, query_positions)
    C.check_last_dim(xp, sphere_positions, 3, "sphere_positions")
    C.check_last_dim(xp, sphere_radii, 1, "sphere_radii")
    offsets = query_positions[..., None, :, :] - sphere_positions[..., :, None, :]
    distances = xp.safe_norm(offsets, axis=-1, keepdims=True) - sphere_radii[..., None, :]
    return xp.min(distances, axis=-3)


@checked
def cuboid_signed_distances(
    cuboid_ext_mats: Array, cuboid_dims: Array, query_positions: Array, *, f: Framework = None
) -> Array:
    """Exact signed distance from query points to the nearest of a set of cuboids.

    Args:
        cuboid_ext_mats: world-to-cuboid transformations ``[R | t]`` (cuboid frame at its
            centre, axes along its edges) *[batch_shape, num_cuboids, 3, 4]*.
        cuboid_dims: full edge lengths along the cuboid's x, y, z *[batch_shape, num_cuboids, 3]*.
        query_positions: points *[batch_shape, num_points, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        The smallest signed distance of each point *[batch_shape, num_points, 1]*.

    Example:
        >>> cuboid_signed_distances(np.eye(3, 4)[None], np.full((1, 3), 2.),
        ...                         np.array([[0., 0., 0.], [3., 0., 0.]]))
        array([[-1.],
               [ 2.]])
    """
    xp = ivy.get_framework(cuboid_ext_mats, cuboid_dims, query_positions, f=f)
    _queries(xp, query_positions)
    mshape = C.shape_of(xp, cuboid_ext_mats)
    if len(mshape) < 3 or mshape[-2:] != (3, 4):
        raise InputError(f"cuboid_ext_mats must be [..., num_cuboids, 3, 4]; got {mshape}.")
    C.check_last_dim(xp, cuboid_dims, 3, "cuboid_dims")
    # [*B, NC, NP, 3]: every point in every cuboid's frame
    rot, t = cuboid_ext_mats[..., None, :, 0:3], cuboid_ext_mats[..., None, :, 3]
    local = xp.matvec(rot, query_positions[..., None, :, :]) + t
    q = xp.abs(local) - cuboid_dims[..., :, None, :] / 2.0
    outside = xp.safe_norm(xp.where(q > 0, q, xp.zeros_like(q)), axis=-1, keepdims=True)
    deepest = xp.max(q, axis=-1, keepdims=True)
    inside = xp.where(deepest < 0, deepest, xp.zeros_like(deepest))
    return xp.min(outside + inside, axis=-3)
