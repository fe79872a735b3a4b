"""Compile times of ivy_gym's optimisers, per backend: the first call of one compiled iteration
(a 100-step rollout of CartPole swing-up, its gradient, clipping and Adam's update), the second
call, and a later call; and the whole optimisation as one compiled loop (no callback).

Usage:
    python benchmarks/gym_compile_times.py --backends jax,tensorflow --horizon 100

Prints one Markdown row per (backend, optimiser). ``optimise_actions`` from one state,
``optimise_policy`` with an MLP 64-64 and a batch of 64, as in docs/ivy_gym.md.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import ivy
import ivy_gym


def _timed_iterations(run, iterations: int) -> list[float]:
    """Seconds of each of the first ``iterations`` calls, one iteration per call (a callback
    that never stops makes the optimiser call its compiled iteration once per iteration)."""
    stamps = [time.perf_counter()]

    def callback(i, variables):
        ivy.to_numpy(ivy.nest.nest_leaves(variables)[0])  # wait for the iteration's result
        stamps.append(time.perf_counter())

    run(iterations, callback)
    return list(np.diff(stamps))


def measure(backend: str, horizon: int, policy_iterations: int) -> list[str]:
    env = ivy_gym.CartPoleSwingUp()
    start = ivy.asarray(np.array([0.0, 0.0, np.pi, 0.0]), dtype="float32", f=backend)

    def actions(iterations, callback=None):
        return ivy_gym.optimise_actions(
            env, horizon, iterations, initial_state=start, seed=0, callback=callback
        )

    def policy(iterations, callback=None):
        mlp = ivy.MLP(5, (64, 64), 1, activation="tanh", output_activation="tanh", f=backend)
        return ivy_gym.optimise_policy(
            env, mlp, horizon, iterations, batch_size=64, seed=0, callback=callback
        )

    rows = []
    for name, run, loop_iterations in (
        ("optimise_actions", actions, 300),
        ("optimise_policy", policy, policy_iterations),
    ):
        times = _timed_iterations(run, 5)
        whole = run(loop_iterations)
        rows.append(
            f"| {backend} | {name} | {times[0]:.1f} s | {times[1]:.2f} s | "
            f"{1e3 * float(np.median(times[2:])):.0f} ms | {loop_iterations} iterations in "
            f"{whole.seconds:.1f} s |"
        )
        print(rows[-1], flush=True)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backends", default="jax,tensorflow")
    parser.add_argument("--horizon", type=int, default=100)
    parser.add_argument("--policy-iterations", type=int, default=100)
    args = parser.parse_args()
    print(
        "| backend | optimiser | first call (compiles) | second call | later calls | "
        "the whole loop compiled, compilation included |"
    )
    print("|---|---|---|---|---|---|")
    for backend in args.backends.split(","):
        measure(backend, args.horizon, args.policy_iterations)


if __name__ == "__main__":
    main()
