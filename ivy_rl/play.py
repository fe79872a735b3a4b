"""``python -m ivy_rl.play``: reload a run's last checkpoint and run test episodes, rendering
them to a video or on screen.

Example:
    python -m ivy_rl.play runs/ppo-cartpole --episodes 3 --video play.mp4
    python -m ivy_rl.play runs/ppo-cartpole --framework jax     # on another framework

Videos: ``.gif`` with imageio (Pillow), ``.mp4`` with imageio and imageio-ffmpeg.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from typing import Any

import numpy as np

__all__ = ["main", "play"]


def play(
    run: str,
    *,
    episodes: int = 3,
    video: str | None = None,
    framework: str | None = None,
    seed: int = 0,
    render: bool = False,
    fps: int = 30,
) -> list[dict[str, float]]:
    """Run test episodes with the agent of the last checkpoint of ``run``.

    Args:
        run: a run folder written by ``python -m ivy_rl.train``.
        episodes: number of episodes.
        video: write the frames to this file (``.mp4`` or ``.gif``).
        framework: load the agent on this framework (default: the run's).
        seed: seed of the first episode (episode ``i`` uses ``seed + i``).
        render: show the episodes in a window (``render_mode='human'``).
        fps: frames per second of the video.

    Returns:
        ``[{'score': ..., 'length': ...}]`` per episode.

    Example:
        >>> play("runs/ppo-cartpole", episodes=1, video="play.gif")
    """
    from ivy_rl.agents import make
    from ivy_rl.environments import make_env
    from ivy_rl.trainer import latest_checkpoint

    config_path = os.path.join(run, "config.json")
    if not os.path.exists(config_path):
        raise FileNotFoundError(
            f"{run!r} is not a run folder: it has no config.json (python -m ivy_rl.train "
            "--out <folder> writes one)"
        )
    with open(config_path) as fh:
        config = json.load(fh)
    checkpoint = latest_checkpoint(run)
    if checkpoint is None:
        raise FileNotFoundError(f"no checkpoint in {os.path.join(run, 'checkpoints')}")
    framework = framework or config["framework"]
    if config["dtype"] == "float64" and framework == "jax":
        import jax

        jax.config.update("jax_enable_x64", True)
    render_mode = "human" if render else ("rgb_array" if video else None)
    env = make_env(
        config["environment"],
        env_kwargs=config.get("env_kwargs"),
        time_feature=config.get("time_feature", False),
        render_mode=render_mode,
    )
    agent = make(config["agent"], **config.get("agent_kwargs", {}))
    agent.initialize(
        env.observation_space,
        env.action_space,
        seed=config["seed"],
        f=framework,
        dtype=config["dtype"],
        compile=False,
    )
    agent.load(os.path.join(checkpoint, "agent"))
    frames, results = [], []
    for episode in range(episodes):
        obs, _ = env.reset(seed=seed + episode)
        score, length = 0.0, 0
        while True:
            if video:
                frames.append(np.asarray(env.render()))
            action = agent.test_step(np.asarray(obs)[None])[0]
            obs, reward, terminated, truncated, _ = env.step(action)
            score += float(reward)
            length += 1
            if terminated or truncated:
                break
        results.append({"score": score, "length": length})
        print(f"episode {episode}: score {score:.2f}, length {length}")
    env.close()
    if video:
        _write_video(video, frames, fps)
    return results


def _write_video(path: str, frames: list[np.ndarray], fps: int) -> None:
    try:
        import imageio.v2 as imageio
    except ImportError as error:
        raise ImportError("--video needs imageio: pip install 'ivy[rl]'") from error
    if path.endswith(".gif"):
        imageio.mimsave(path, frames, duration=1000 / fps, loop=0)
        return
    try:
        writer = imageio.get_writer(path, fps=fps)
    except (ImportError, ValueError, RuntimeError) as error:
        raise RuntimeError(
            f"cannot write {path!r}: mp4 needs imageio-ffmpeg (pip install imageio-ffmpeg); "
            "or write a .gif"
        ) from error
    with writer:
        for frame in frames:
            writer.append_data(frame)


def main(argv: list[str] | None = None) -> list[dict[str, Any]]:
    p = argparse.ArgumentParser(prog="python -m ivy_rl.play", description=__doc__.split("\n")[0])
    p.add_argument("run", help="a run folder")
    p.add_argument("--episodes", type=int, default=3)
    p.add_argument("--video", default=None, help="write a video (.mp4 or .gif)")
    p.add_argument("--framework", "-f", default=None, help="load on this framework")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--render", action="store_true", help="show the episodes in a window")
    p.add_argument("--fps", type=int, default=30)
    args = p.parse_args(argv)
    return play(
        args.run,
        episodes=args.episodes,
        video=args.video,
        framework=args.framework,
        seed=args.seed,
        render=args.render,
        fps=args.fps,
    )


if __name__ == "__main__":
    try:
        main()
    except (ValueError, TypeError, FileNotFoundError) as error:
        print(f"error: {error}", file=sys.stderr)
        raise SystemExit(2) from None
