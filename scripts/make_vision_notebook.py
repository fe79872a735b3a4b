"""Write ``notebooks/vision_multiview.ipynb`` from the cells below (run it after editing them):

    python scripts/make_vision_notebook.py [--execute]

``--execute`` runs it once (the first cell's defaults: torch, 160 pixels wide, 100^3 voxels)
and saves it with its outputs, so that the figures show where the notebook is read.

The notebook: several depth cameras of a MuJoCo scene -> point clouds fused in a voxel grid
(the paper's 100^3 example) -> rendered into a new view; and an inverse warp between two views.
"""

from __future__ import annotations

from _notebooks import write_notebook  # scripts/ is on the path of `python scripts/...`

CELLS = [
    (
        "markdown",
        """# ivy_vision: multi-view fusion and warping, on any backend

Depth and colour images of a MuJoCo scene are ray-cast from four cameras; ivy_vision unprojects
them to point clouds, fuses them in a voxel grid (the paper's 100³ example), renders the grid
into a new view with a depth buffer, and inverse-warps one view into another.

The first cell chooses the backend (`numpy`, `torch`, `jax` or `tensorflow`) and the size of
the problem; the tests run the notebook at low resolution through environment variables.""",
    ),
    (
        "code",
        """import os

BACKEND = os.environ.get("VISION_NOTEBOOK_BACKEND", "torch")  # numpy, torch, jax or tensorflow
WIDTH = int(os.environ.get("VISION_NOTEBOOK_WIDTH", "160"))    # image width in pixels
VOXELS = int(os.environ.get("VISION_NOTEBOOK_VOXELS", "100"))  # voxels per axis (paper: 100)""",
    ),
    (
        "code",
        """%matplotlib inline
import matplotlib.pyplot as plt
import mujoco
import numpy as np

import ivy
import ivy_vision as vis

HEIGHT = WIDTH * 3 // 4


def to_ivy(x):
    return ivy.asarray(np.asarray(x, np.float32), f=BACKEND)


def to_np(x):
    return ivy.to_numpy(x)""",
    ),
    (
        "markdown",
        """## The scene and its cameras

Four primitives on a floor. Each camera looks at the scene's centre; its depth (planar, along
the camera's z axis) and colour (the hit geom's colour, shaded by the surface normal) come from
`mujoco.mj_multiRay`, one ray per pixel centre.""",
    ),
    (
        "code",
        """SCENE = '''
<mujoco>
  <worldbody>
    <geom type="plane" size="0 0 1" rgba="0.8 0.8 0.8 1"/>
    <geom type="sphere" pos="0.3 0.25 0.25" size="0.25" rgba="0.9 0.2 0.2 1"/>
    <geom type="box" pos="-0.35 -0.1 0.2" size="0.2 0.15 0.2" euler="0 0 30" rgba="0.2 0.7 0.3 1"/>
    <geom type="cylinder" pos="0.25 -0.45 0.3" size="0.1 0.3" rgba="0.2 0.3 0.9 1"/>
    <geom type="capsule" pos="-0.2 0.45 0.15" size="0.08 0.15" euler="0 90 0" rgba="0.9 0.8 0.1 1"/>
  </worldbody>
</mujoco>'''
model = mujoco.MjModel.from_xml_string(SCENE)
data = mujoco.MjData(model)
mujoco.mj_forward(model, data)
TARGET = np.array([0.0, 0.0, 0.2])
BOUNDS = (-0.8, -0.8, -0.01, 0.8, 0.8, 0.6)  # the voxel grid's region


def look_at(eye):
    forward = TARGET - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, [0, 0, 1.0])
    right /= np.linalg.norm(right)
    return np.stack([right, np.cross(forward, right), forward])  # rows: x right, y down, z fwd


def camera(eye):
    focal = WIDTH / (2 * np.tan(np.radians(55) / 2))  # 55 degrees horizontal field of view
    return vis.Camera.from_focal_lengths(
        to_ivy([focal, focal]), to_ivy([(WIDTH - 1) / 2, (HEIGHT - 1) / 2]),
        to_ivy(look_at(np.asarray(eye, float))), to_ivy(eye))


def ray_cast(cam):
    '''Planar depth [H, W, 1] and shaded colour [H, W, 3] from MuJoCo, one ray per pixel.'''
    rays = to_np(vis.pixel_coords_to_world_ray_vectors(cam.inv_full_mat, image_dims=(HEIGHT, WIDTH)))
    rays = rays.reshape(-1, 3).astype(np.float64)
    rot = to_np(cam.rotation_mat).astype(np.float64)
    rays = rays / (rays @ rot[2])[:, None]  # unit camera z: distances are planar depths
    n = len(rays)
    geom, dist, normal = np.zeros(n, np.int32), np.zeros(n), np.zeros(3 * n)
    mujoco.mj_multiRay(model, data, to_np(cam.camera_center).astype(np.float64), rays.ravel(),
                       None, 1, -1, geom, dist, normal, n, 50.0)
    hit = dist >= 0
    shade = 0.4 + 0.6 * np.abs(np.sum(normal.reshape(-1, 3) * rays, -1)) / np.linalg.norm(rays, axis=-1)
    colour = np.where(hit[:, None], model.geom_rgba[geom, :3] * shade[:, None], 0.0)
    depth = np.where(hit, dist, 0.0)
    return depth.reshape(HEIGHT, WIDTH, 1), colour.reshape(HEIGHT, WIDTH, 3)


eyes = [(1.6, -1.2, 1.2), (-1.5, -1.3, 1.0), (-1.2, 1.5, 1.3), (1.4, 1.4, 0.9)]
cams = [camera(e) for e in eyes]
views = [ray_cast(c) for c in cams]
fig, axes = plt.subplots(2, 4, figsize=(12, 4))
for k, (depth, colour) in enumerate(views):
    axes[0, k].imshow(colour)
    axes[1, k].imshow(depth[..., 0], cmap="viridis")
    axes[0, k].set_title(f"camera {k}")
for ax in axes.ravel():
    ax.axis("off")
plt.show()""",
    ),
    (
        "markdown",
        """## Point clouds fused in a voxel grid

`depth_to_world_coords` unprojects every pixel with the inverse full matrix `P⁻¹`;
`coords_to_voxel_grid` bins the points of all cameras (with their colours as features) into a
`VOXELS³` grid: each voxel holds the mean point, the mean colour and the number of points.""",
    ),
    (
        "code",
        """points, colours = [], []
for cam, (depth, colour) in zip(cams, views):
    world = vis.depth_to_world_coords(to_ivy(depth), cam.inv_full_mat)  # [H, W, 4]
    points.append(to_np(world)[..., :3][depth[..., 0] > 0])
    colours.append(colour[depth[..., 0] > 0])
points, colours = np.concatenate(points), np.concatenate(colours)
grid, dims, res, lower = vis.coords_to_voxel_grid(
    to_ivy(points), (VOXELS, VOXELS, VOXELS), coord_bounds=BOUNDS, features=to_ivy(colours))
grid = to_np(grid)
occupied = grid[..., -1] > 0
print(f"{len(points)} points -> {occupied.sum()} occupied voxels of {VOXELS}^3, "
      f"resolution {to_np(res).round(4)} m")
assert occupied.sum() > 0.005 * len(points)
# the occupied voxels seen from above: the highest occupied voxel's colour in each column
top = occupied.shape[2] - 1 - np.argmax(occupied[..., ::-1], axis=2)
top_colour = np.take_along_axis(grid[..., 3:6], top[..., None, None], axis=2)[:, :, 0]
plt.figure(figsize=(4, 4))
plt.imshow(np.where(occupied.any(2)[..., None], top_colour, 1.0).transpose(1, 0, 2)[::-1])
plt.title("voxel grid from above")
plt.axis("off")
plt.show()""",
    ),
    (
        "markdown",
        """## Rendering the grid into a new view

The voxels' mean points are projected into a camera that took no picture, and
`quantize_to_image` renders them with a depth buffer: the nearest voxel wins each pixel. Empty
voxels get a variance above the threshold, so they are left out. The result is compared with
that camera's own MuJoCo ray cast.""",
    ),
    (
        "code",
        """new_cam = camera((0.2, -1.9, 1.4))
true_depth, true_colour = ray_cast(new_cam)
flat = grid.reshape(-1, grid.shape[-1])
ds = vis.world_to_ds_pixel_coords(to_ivy(flat[:, :3]), new_cam.full_mat)
pixels = vis.ds_pixel_coords_to_pixel_coords(ds)
feat = np.concatenate([to_np(ds)[:, 2:3], flat[:, 3:6]], -1)
variance = np.where(flat[:, -1:] > 0, 1e-3, 1e13) * np.ones((1, 2))
mean, _, count = vis.quantize_to_image(pixels, (HEIGHT, WIDTH), to_ivy(feat), with_db=True,
                                       pixel_coords_var=to_ivy(variance))
mean, count = to_np(mean), to_np(count)
rendered_depth = np.where(count > 0, mean[..., 2:3], 0.0)
rendered = np.where(count > 0, mean[..., 3:6], 1.0)
both = (count[..., 0] > 0) & (true_depth[..., 0] > 0)
error = np.abs(rendered_depth - true_depth)[..., 0][both]
voxel = float(np.max(to_np(res)))
print(f"rendered {both.mean():.0%} of the pixels; median depth error {np.median(error):.4f} m "
      f"(voxel size {voxel:.4f} m)")
assert both.mean() > 0.2 and np.median(error) < 2 * voxel
fig, axes = plt.subplots(1, 3, figsize=(12, 3))
axes[0].imshow(rendered); axes[0].set_title("voxel grid rendered")
axes[1].imshow(true_colour); axes[1].set_title("MuJoCo ray cast")
axes[2].imshow(np.where(both, np.abs(rendered_depth - true_depth)[..., 0], np.nan))
axes[2].set_title("depth error (m)")
for ax in axes:
    ax.axis("off")
plt.show()""",
    ),
    (
        "markdown",
        """## Inverse warping between two views

Camera 1's colour image is warped into camera 0 through camera 0's depth and the relative
pose (`inverse_warp`). Pixels that camera 1 cannot see (outside its image, or hidden behind
another surface: the reprojected depth disagrees with camera 1's own depth there) are masked.""",
    ),
    (
        "code",
        """depth0, colour0 = views[0]
depth1, colour1 = views[1]
cam0_to_1 = cams[0].full_mat_to(cams[1])
warped, valid = vis.inverse_warp(to_ivy(colour1), to_ivy(depth0), cam0_to_1, with_validity=True)
# occlusion test: camera 0's points seen from camera 1 against camera 1's own depth there
ds01 = vis.ds_pixel_to_ds_pixel_coords(vis.depth_to_ds_pixel_coords(to_ivy(depth0)), cam0_to_1)
seen_depth = vis.sample_image(to_ivy(depth1), vis.ds_pixel_coords_to_pixel_coords(ds01),
                              method="nearest")
visible = np.abs(to_np(seen_depth) - to_np(ds01)[..., 2:3]) < 0.05
mask = to_np(valid) & visible & (depth0 > 0)
warped = np.where(mask, to_np(warped), 0.0)
error = np.abs(warped - colour0)[mask[..., 0]]
print(f"{mask.mean():.0%} of camera 0's pixels seen by camera 1; mean colour error {error.mean():.3f}")
assert mask.mean() > 0.2 and error.mean() < 0.1
fig, axes = plt.subplots(1, 3, figsize=(12, 3))
axes[0].imshow(colour1); axes[0].set_title("camera 1")
axes[1].imshow(warped); axes[1].set_title("camera 1 warped into camera 0")
axes[2].imshow(colour0); axes[2].set_title("camera 0")
for ax in axes:
    ax.axis("off")
plt.show()""",
    ),
]


def main():
    write_notebook(CELLS, "vision_multiview.ipynb", __doc__.splitlines()[0], timeout=600)


if __name__ == "__main__":
    main()
