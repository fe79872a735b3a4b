"""``python -m ivy_rl.play``: reload a run's last checkpoint (or its best model) and run test
episodes, rendering them to a video or on screen; prints each episode's score and the mean and
spread over the episodes.

Example:
    python -m ivy_rl.play runs/ppo-cartpole --episodes 3 --video play.mp4
    python -m ivy_rl.play runs/ppo-cartpole --framework jax     # on another framework
    python -m ivy_rl.play runs/ppo-cartpole --best --episodes 10

Videos: ``.gif`` with imageio (Pillow), ``.mp4`` with imageio and imageio-ffmpeg.
"""

from __future__ import annotations

import argparse
import os
import warnings
from typing import Any

import numpy as np

from ivy_rl import _cli

__all__ = ["main", "play", "summary"]


def play(
    run: str,
    *,
    episodes: int = 3,
    video: str | None = None,
    framework: str | None = None,
    seed: int = 0,
    render: bool = False,
    fps: int = 30,
    best: bool = False,
    device: str | None = None,
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
        best: load the run's best model (``best/``, the best mean test score) instead of its
            last checkpoint.
        device: where the agent's arrays live (default: the run's device).

    Returns:
        ``[{'score': ..., 'length': ...}]`` per episode.

    Example:
        A run folder of a quick baseline run (any agent's run plays the same way):

        >>> import ivy_rl
        >>> trainer = ivy_rl.Trainer(steps=400, epoch_steps=200, show_progress=False)
        >>> rows = trainer.run("Uniform", "CartPole-v1", out="runs/uniform")
        finished: 400 steps in ...
        >>> episodes = play("runs/uniform", episodes=1, video="play.gif")
        episode 0: score 54.00, length 54
        score 54.00 +- 0.00 (min 54.00, max 54.00) over 1 episode, length 54.0
        wrote play.gif (54 frames, 30 fps)
        >>> episodes
        [{'score': 54.0, 'length': 54}]
    """
    from ivy_rl.agents import make
    from ivy_rl.checkpoints import check_checkpoint, usable_checkpoint
    from ivy_rl.environments import make_env

    if episodes < 1:
        raise ValueError(f"episodes must be >= 1, got {episodes}")
    config = _cli.read_config(run)
    if best:
        checkpoint = os.path.join(run, "best")
        if not os.path.isdir(checkpoint):
            raise FileNotFoundError(
                f"no best model in {checkpoint}: runs keep one when they have test episodes"
            )
        check_checkpoint(checkpoint)
    else:
        checkpoint = usable_checkpoint(run, warn=lambda m: warnings.warn(m, stacklevel=3))
        if checkpoint is None:
            raise FileNotFoundError(f"no checkpoint in {os.path.join(run, 'checkpoints')}")
    framework = framework or config["framework"]
    device = device or config.get("device")
    _cli.check_framework(framework, config["dtype"])
    _cli.check_device(device, framework)
    _cli.enable_float64(framework, config["dtype"])
    render_mode = "human" if render else ("rgb_array" if video else None)
    if not render:
        # frames drawn off screen: Gymnasium's pygame starts SDL's video, which without a
        # desktop session (no XDG_RUNTIME_DIR) prints an error though it succeeds
        os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    env = make_env(
        config["environment"],
        env_kwargs=config.get("env_kwargs"),
        time_feature=config.get("time_feature", False),
        wrappers=config.get("wrappers"),
        render_mode=render_mode,
    )
    settings = config.get("agent_config") or config.get("agent_kwargs", {})
    agent = make(config["agent"], environment=config["environment"], **settings)
    agent.initialize(
        env.observation_space,
        env.action_space,
        seed=config["seed"],
        f=framework,
        dtype=config["dtype"],
        compile=False,
        **({"device": device} if device else {}),
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
    print(summary(results))
    if video:
        _write_video(video, frames, fps)
        print(f"wrote {video} ({len(frames)} frames, {fps} fps)")
    return results


def summary(results: list[dict[str, float]]) -> str:
    """One line: the mean score of the episodes, its standard deviation, minimum and maximum,
    and the mean length.

    Example:
        >>> summary([{"score": 10.0, "length": 10}, {"score": 20.0, "length": 20}])
        'score 15.00 +- 5.00 (min 10.00, max 20.00) over 2 episodes, length 15.0'
    """
    scores = np.array([r["score"] for r in results], np.float64)
    lengths = np.array([r["length"] for r in results], np.float64)
    plural = "s" if len(results) != 1 else ""
    return (
        f"score {scores.mean():.2f} +- {scores.std():.2f} (min {scores.min():.2f}, "
        f"max {scores.max():.2f}) over {len(results)} episode{plural}, "
        f"length {lengths.mean():.1f}"
    )


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
    p.add_argument("--best", action="store_true", help="the best model, not the last")
    p.add_argument("--device", default=None, help="where the agent's arrays live")
    args = p.parse_args(argv)
    return play(
        args.run,
        episodes=args.episodes,
        video=args.video,
        framework=args.framework,
        seed=args.seed,
        render=args.render,
        fps=args.fps,
        best=args.best,
        device=args.device,
    )


if __name__ == "__main__":
    _cli.command_line(main)
