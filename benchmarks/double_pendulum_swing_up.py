"""The double pendulum's swing-up by Levenberg-Marquardt shooting through differentiable rollouts
(``ivy_gym.optimise_actions_least_squares``), per backend: the row of ``docs/ivy_gym.md``.

The recipe, in two stages from ``--restarts`` hanging states (Gymnasium's reset noise, seed 0):

1. reach: ``--reach-steps`` actions (uniform logits in [-0.5, 0.5]) optimised for the
   residuals of the last state alone (``swing_up_residuals(traj, hold=1)``: upright, still,
   the cart centred), ``--iterations`` steps;
2. hold: those actions extended by ``--hold`` zero logits and optimised again for the residuals
   of the last ``--hold`` states, ``--iterations`` steps.

A restart is solved when, replayed, both poles stay within 18 degrees of upright (``cos > 0.95``)
over the last ``--hold`` steps and the cart within 1 m of the centre throughout.

Usage: python benchmarks/double_pendulum_swing_up.py [--backend jax] [--restarts 32]
       [--reach-steps 40] [--hold 10] [--iterations 60]
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

import ivy
import ivy_gym

warnings.filterwarnings("ignore")


def swing_up(env, backend, restarts, reach_steps, hold, iterations):
    """The two stages; returns the final result and the first stage's."""
    reach = ivy_gym.optimise_actions_least_squares(
        env,
        reach_steps,
        iterations,
        lambda traj: env.swing_up_residuals(traj, hold=1),
        batch_shape=(restarts,),
        seed=0,
        f=backend,
    )
    logits = ivy.to_numpy(reach.variables)
    logits = np.concatenate([logits, np.zeros((hold, *logits.shape[1:]), logits.dtype)])
    held = ivy_gym.optimise_actions_least_squares(
        env,
        reach_steps + hold,
        iterations,
        lambda traj: env.swing_up_residuals(traj, hold=hold),
        initial_state=reach.initial_state,
        initial_logits=logits,
        f=backend,
    )
    return held, reach


def solved(env, result, hold):
    """Per restart: the poles upright over the last ``hold`` steps, the cart within 1 m."""
    states = ivy.to_numpy(ivy_gym.rollout(env, result.initial_state, result.actions).states)
    last = np.asarray(states[-hold:], np.float64)
    upright = (np.cos(last[..., 1]) > 0.95) & (np.cos(last[..., 1] + last[..., 2]) > 0.95)
    return upright.all(axis=0) & (np.abs(states[..., 0]).max(axis=0) < 1.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backend", default="jax")
    parser.add_argument("--restarts", type=int, default=32)
    parser.add_argument("--reach-steps", type=int, default=40)
    parser.add_argument("--hold", type=int, default=10)
    parser.add_argument("--iterations", type=int, default=60)
    args = parser.parse_args()
    env = ivy_gym.InvertedDoublePendulum(swing_up=True)
    start = time.perf_counter()
    held, reach = swing_up(
        env, args.backend, args.restarts, args.reach_steps, args.hold, args.iterations
    )
    seconds = time.perf_counter() - start
    ok = solved(env, held, args.hold)
    print(
        f"{args.backend}: {int(ok.sum())} of {args.restarts} restarts swing up and hold "
        f"{args.hold} steps ({args.reach_steps} + {args.hold} steps, {args.iterations} + "
        f"{args.iterations} iterations) in {seconds:.0f} s, compilation included (first "
        f"iteration of each stage: {reach.first_seconds:.1f} s, {held.first_seconds:.1f} s)"
    )
    print(f"  reach stage: {int((reach.costs < 0.1).sum())} restarts below a cost of 0.1")
    print(f"  final costs, lowest 8: {np.round(np.sort(held.costs)[:8], 3).tolist()}")
    print(f"  mean return: {held.returns[0]:.1f} -> {held.final_return:.1f}")


if __name__ == "__main__":
    main()
