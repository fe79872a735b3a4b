"""ivy's main demo: a CartPole swing-up optimised through a differentiable rollout, with the same
code on every installed backend.

A cart-pole starts hanging down (the original ivy_gym's swing-up task: reward
``exp(-x**2) * (cos(theta) + 1) / 2`` per step, at most 100 in 100 steps). A sequence of 100
actions is optimised with Adam by gradients of the return through the whole rollout
(``ivy_gym.optimise_actions``: ``ivy.scan`` compiled with ``ivy.compile_fn`` on jax and
tensorflow, eager on torch), from the same initial actions on torch, jax and tensorflow. numpy
has no gradients: it replays the actions the others found and gets the same return. The demo
prints the return before and after and the time per backend, and saves a plot of the return
per iteration and a GIF of the swing-up.

Usage: python scripts/demo.py [--iterations 300] [--out demo_out]
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

import ivy
import ivy_gym

HANGING = np.array([0.0, 0.0, np.pi, 0.0])  # x, x_dot, theta (from upright), theta_dot


def swing_up(framework: str, iterations: int = 300, horizon: int = 100, lr: float = 0.1):
    """Optimise the swing-up's actions on ``framework``; the same initial logits everywhere.

    Returns:
        ``(result, seconds)``: the :class:`ivy_gym.OptimisationResult` and the wall time,
        the framework's import and compilation included.
    """
    start = time.perf_counter()
    env = ivy_gym.CartPoleSwingUp()
    logits = np.random.default_rng(0).uniform(-1, 1, size=(horizon, env.action_dim))
    state = ivy.asarray(HANGING, dtype="float32", f=framework)
    result = ivy_gym.optimise_actions(
        env, horizon, iterations, initial_state=state, initial_logits=logits, lr=lr
    )
    return result, time.perf_counter() - start


def replay(framework: str, actions) -> float:
    """The return of ``actions`` (numpy) from the hanging state, rolled out on ``framework``."""
    env = ivy_gym.CartPoleSwingUp()
    state = ivy.asarray(HANGING, dtype="float32", f=framework)
    traj = ivy_gym.rollout(env, state, ivy.asarray(actions, dtype="float32", f=framework))
    return float(ivy.to_numpy(ivy.sum(traj.rewards)))


def main(iterations: int = 300, horizon: int = 100, out_dir: str = "demo_out") -> dict:
    frameworks = ivy.installed_frameworks()
    differentiable = [f for f in ("jax", "tensorflow", "torch") if f in frameworks]
    print(
        f"CartPole swing-up: {horizon} actions optimised through a differentiable rollout, "
        f"{iterations} Adam iterations, on {', '.join(differentiable) or 'no differentiable backend'}"
    )
    print(f"\n{'backend':<12}{'return before':>14}{'after':>9}{'(of max)':>10}{'time':>9}")
    results = {}
    for name in differentiable:
        result, seconds = swing_up(name, iterations, horizon)
        results[name] = result
        print(
            f"{name:<12}{result.returns[0]:14.2f}{result.final_return:9.2f}{horizon:>10}"
            f"{seconds:8.1f}s"
        )
    if not results:
        raise SystemExit("install torch, jax or tensorflow: the demo needs gradients")
    best = max(results, key=lambda n: results[n].final_return)
    actions = np.asarray(ivy.to_numpy(results[best].actions))
    replays = {name: replay(name, actions) for name in frameworks}
    print(f"\nthe actions found on {best}, replayed on every backend (float32):")
    print("  " + ", ".join(f"{name} {value:.3f}" for name, value in replays.items()))

    os.makedirs(out_dir, exist_ok=True)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 3.5))
    for name, result in results.items():
        ax.plot(result.returns, label=name)
    ax.set_xlabel("Adam iteration")
    ax.set_ylabel(f"return (of {horizon})")
    ax.set_title("CartPole swing-up through a differentiable rollout")
    ax.legend()
    fig.tight_layout()
    plot = os.path.join(out_dir, "swing_up_returns.png")
    fig.savefig(plot, dpi=100)
    plt.close(fig)
    env = ivy_gym.CartPoleSwingUp()
    traj = ivy_gym.rollout(env, HANGING.astype(np.float32), actions.astype(np.float32))
    frames = ivy_gym.render_trajectory(env, traj.states, width=320, height=240)
    gif = ivy_gym.save_video(frames, os.path.join(out_dir, "cartpole_swing_up.gif"), fps=25)
    print(f"\nsaved {plot} and {gif}")
    return {"results": results, "replays": replays, "plot": plot, "gif": gif}


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--iterations", type=int, default=300)
    parser.add_argument("--horizon", type=int, default=100)
    parser.add_argument("--out", default="demo_out")
    args = parser.parse_args()
    main(args.iterations, args.horizon, args.out)
