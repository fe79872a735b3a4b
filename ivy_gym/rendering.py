"""Pictures of states drawn with numpy (no display, no pygame), and videos written with imageio.

:class:`Canvas` fills convex polygons, discs and thick lines given in world coordinates (y up)
into an RGB uint8 image. :func:`render_trajectory` draws a trajectory frame by frame and
:func:`save_video` writes frames to a GIF or an MP4 (MP4 needs ``imageio-ffmpeg``).

Example:
    >>> env = ivy_gym.CartPoleSwingUp()
    >>> traj = ivy_gym.rollout(env, env.reset(f="numpy"), np.zeros((50, 1), np.float32))
    >>> frames = ivy_gym.render_trajectory(env, traj.states)
    >>> ivy_gym.save_video(frames, "swing.gif", fps=env.render_fps)
    'swing.gif'
"""

from __future__ import annotations

import os
from collections.abc import Sequence

import numpy as np

import ivy
from ivy.typing import Array, Framework

__all__ = ["Canvas", "render_trajectory", "save_video"]

Color = tuple[int, int, int]


class Canvas:
    """An RGB image with a world coordinate frame: x to the right, y up.

    Args:
        width, height: size in pixels.
        view: the world box ``(x_min, x_max, y_min, y_max)`` the image shows.
        background: RGB colour of the empty image.

    Example:
        >>> canvas = Canvas(200, 100, (-2, 2, -1, 1))
        >>> canvas.disc((0, 0), 0.5, (200, 0, 0))
        >>> canvas.image.shape
        (100, 200, 3)
    """

    def __init__(
        self,
        width: int,
        height: int,
        view: Sequence[float],
        background: Color = (255, 255, 255),
    ) -> None:
        self.width, self.height = int(width), int(height)
        self.x_min, self.x_max, self.y_min, self.y_max = (float(v) for v in view)
        self.image = np.empty((self.height, self.width, 3), np.uint8)
        self.image[...] = background
        self._scale = self.width / (self.x_max - self.x_min)

    def pixels(self, points) -> np.ndarray:
        """World points ``(..., 2)`` as pixel coordinates ``(..., 2)`` (column, row)."""
        p = np.asarray(points, np.float64)
        col = (p[..., 0] - self.x_min) / (self.x_max - self.x_min) * self.width
        row = (self.y_max - p[..., 1]) / (self.y_max - self.y_min) * self.height
        return np.stack([col, row], axis=-1)

    def _grid(self, lo, hi):
        """Pixel centres in the pixel box [lo, hi] clipped to the image, or None if empty."""
        c0, r0 = np.maximum(np.floor(lo).astype(int), 0)
        c1 = min(int(np.ceil(hi[0])), self.width)
        r1 = min(int(np.ceil(hi[1])), self.height)
        if c0 >= c1 or r0 >= r1:
            return None
        cols, rows = np.meshgrid(np.arange(c0, c1) + 0.5, np.arange(r0, r1) + 0.5)
        return (slice(r0, r1), slice(c0, c1)), cols, rows

    def polygon(self, points, color: Color) -> None:
        """Fill the convex polygon with world vertices ``points`` ``(n, 2)`` (either order)."""
        p = self.pixels(points)
        grid = self._grid(p.min(0), p.max(0))
        if grid is None:
            return
        box, cols, rows = grid
        inside_left = np.ones(cols.shape, bool)
        inside_right = np.ones(cols.shape, bool)
        for a, b in zip(p, np.roll(p, -1, axis=0)):
            cross = (b[0] - a[0]) * (rows - a[1]) - (b[1] - a[1]) * (cols - a[0])
            inside_left &= cross >= 0
            inside_right &= cross <= 0
        self.image[box][inside_left | inside_right] = color

    def disc(self, center, radius: float, color: Color) -> None:
        """Fill the disc of world ``center`` and ``radius``."""
        c = self.pixels(center)
        r = radius * self._scale
        grid = self._grid(c - r, c + r)
        if grid is None:
            return
        box, cols, rows = grid
        self.image[box][(cols - c[0]) ** 2 + (rows - c[1]) ** 2 <= r * r] = color

    def line(self, start, end, width: float, color: Color) -> None:
        """A thick segment from ``start`` to ``end`` (world units), with square ends."""
        a, b = np.asarray(start, np.float64), np.asarray(end, np.float64)
        d = b - a
        length = np.hypot(*d)
        if length == 0:
            return
        n = np.array([-d[1], d[0]]) / length * width / 2
        self.polygon([a + n, b + n, b - n, a - n], color)

    def polyline(self, points, width: float, color: Color) -> None:
        """Thick segments through ``points`` ``(n, 2)`` with round joints."""
        points = np.asarray(points, np.float64)
        for a, b in zip(points[:-1], points[1:]):
            self.line(a, b, width, color)
        for p in points[1:-1]:
            self.disc(p, width / 2, color)


def reward_color(value: float) -> Color:
    """Red (0) to green (1) for a reward in [0, 1], as the original ivy_gym coloured its bodies."""
    v = float(np.clip(value, 0.0, 1.0))
    return int(255 * (1 - v)), int(200 * v), 40


def render_trajectory(
    env,
    states: Array,
    *,
    index: int | tuple[int, ...] = (),
    width: int = 400,
    height: int = 400,
    f: Framework = None,
) -> list[np.ndarray]:
    """The frames of a trajectory of states, one per step.

    Args:
        env: the environment.
        states: ``(T, *batch, state_dim)``, e.g. ``traj.states``, of any backend.
        index: which batch element to draw (an int or a tuple, for batched trajectories).
        width, height: size of each frame.
        f: unused (states of any backend are converted to numpy); kept for a uniform signature.

    Returns:
        A list of ``T`` uint8 arrays ``(height, width, 3)``.

    Example:
        >>> env = ivy_gym.CartPoleSwingUp()
        >>> state = env.reset((2,), f="numpy")
        >>> traj = ivy_gym.rollout(env, state, np.zeros((10, 2, 1), np.float32))
        >>> frames = ivy_gym.render_trajectory(env, traj.states, index=0)
    """
    s = np.asarray(ivy.to_numpy(states), np.float64)
    index = (index,) if isinstance(index, int) else tuple(index)
    expected = f"(T, *batch, {env.state_dim})"
    if s.ndim < 2 or s.shape[-1] != env.state_dim:
        raise ValueError(
            f"render_trajectory: states must have shape {expected}, e.g. traj.states; got "
            f"shape {s.shape}."
        )
    batch = s.shape[1:-1]
    if len(index) != len(batch):
        fix = (
            "drop index= (the trajectory is unbatched)"
            if not batch
            else f"pass index= with {len(batch)} integer(s), one per batch axis, e.g. "
            f"index={(0,) * len(batch) if len(batch) > 1 else 0}"
        )
        raise ValueError(
            f"render_trajectory: states of shape {s.shape} have the batch {batch}, and "
            f"index={index if len(index) != 1 else index[0]} picks {len(index)} batch axes; "
            f"{fix}."
        )
    s = s[(slice(None), *index)]
    return [env.render(row, width=width, height=height) for row in s]


def save_video(frames: Sequence[np.ndarray], path: str | os.PathLike, *, fps: int = 30) -> str:
    """Write frames to a GIF (pillow) or MP4 (ffmpeg) file, chosen by the extension.

    Args:
        frames: uint8 arrays ``(H, W, 3)`` of one size.
        path: output file ending in ``.gif`` or ``.mp4``.
        fps: frames per second.

    Returns:
        The path written, as a string.

    Example:
        >>> frames = [np.zeros((32, 32, 3), np.uint8)] * 3
        >>> ivy_gym.save_video(frames, "demo_out/pendulum.gif", fps=30)
        'demo_out/pendulum.gif'
    """
    import imageio.v3 as iio

    path = os.fspath(path)
    ext = os.path.splitext(path)[1].lower()
    if not frames:
        raise ValueError("save_video: no frames to write.")
    stack = np.stack([np.asarray(fr, np.uint8) for fr in frames])
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    if ext == ".gif":
        iio.imwrite(path, stack, duration=1000.0 / fps, loop=0)
    elif ext == ".mp4":
        try:
            import imageio_ffmpeg  # noqa: F401
        except ImportError as error:
            raise ImportError(
                "save_video: writing MP4 needs imageio-ffmpeg (pip install imageio-ffmpeg, or "
                "install ivy with the [gym] extra); or write a .gif."
            ) from error
        import imageio.v2 as iio2

        iio2.mimwrite(path, list(stack), fps=fps, macro_block_size=1)
    else:
        raise ValueError(f"save_video: unknown extension {ext!r}; use .gif or .mp4.")
    return path
