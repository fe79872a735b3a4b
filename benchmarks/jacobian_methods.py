"""The two methods of ``ivy.execute_with_jacobian`` on the Jacobian that the double pendulum's
swing-up takes at every Levenberg-Marquardt iteration (``ivy_gym.optimise_actions_least_squares``,
the hold stage): the residuals ``swing_up_residuals(traj, hold)`` of a ``--steps``-step rollout
of ``--restarts`` initial states, with respect to each restart's action logits.

- ``native``: the framework's own (``jax.jacrev``; torch's backward pass vectorised over the
  rows; tensorflow's ``GradientTape.jacobian``, vectorised by pfor);
- ``replicate``: one backward pass of the rollout over one copy of the batch per residual.

Compiled as the optimiser runs them (``ivy.compile_fn`` on jax and tensorflow, eager on torch);
both methods are first checked against each other, then timed in turns (benchmarks/_timing.py),
the minimum per Jacobian reported with the ratio replicate / native (< 1: replicate is faster).
``--methods replicate`` leaves out the native method (tensorflow's pfor through the rollout's
``tf.while_loop`` does not finish at the swing-up's size on a 2-core machine).

Usage: python benchmarks/jacobian_methods.py [--backends jax,torch,tensorflow] [--restarts 32]
       [--steps 50] [--hold 10] [--repeats 3] [--methods native,replicate]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
import timeit
import warnings

import numpy as np

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..")]

from _timing import interleaved_samples  # noqa: E402

import ivy  # noqa: E402
import ivy_gym  # noqa: E402
from ivy_gym.optimise import squash_actions  # noqa: E402

warnings.filterwarnings("ignore")


def jacobian_fn(env, backend, state, steps, hold, method):
    """``u (B, steps) -> J (B, R, steps)``, compiled where the optimiser compiles."""
    xp = getattr(ivy, backend)

    def residuals(u):
        lead = tuple(u.shape[:-1])
        logits = xp.permute_dims(u, (len(lead), *range(len(lead))))[..., None]
        start = xp.broadcast_to(state, (*lead, env.state_dim))
        traj = ivy_gym.rollout(env, start, squash_actions(logits, env, f=xp), f=xp)
        return env.swing_up_residuals(traj, hold=hold)

    def jac(u):
        return xp.execute_with_jacobian(residuals, u, batch_dims=1, method=method)[1]

    return jac if backend == "torch" else ivy.compile_fn(jac)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backends", default="jax,torch,tensorflow")
    parser.add_argument("--restarts", type=int, default=32)
    parser.add_argument("--steps", type=int, default=50)
    parser.add_argument("--hold", type=int, default=10)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--methods", default="native,replicate")
    args = parser.parse_args()
    env = ivy_gym.InvertedDoublePendulum(swing_up=True)
    methods = args.methods.split(",")
    rng = np.random.default_rng(0)
    logits = rng.uniform(-0.5, 0.5, (args.restarts, args.steps)).astype(np.float32)
    print(
        f"swing-up Jacobian: {args.restarts} restarts, {args.steps} steps, "
        f"{8 * args.hold + args.steps} residuals per restart; float32"
    )
    for backend in args.backends.split(","):
        xp = getattr(ivy, backend)
        ivy.seed(0, f=backend)
        state = env.reset((args.restarts,), f=backend)
        u = xp.asarray(logits)
        fns, jacs, first = {}, {}, {}
        for method in methods:
            fns[method] = jacobian_fn(env, backend, state, args.steps, args.hold, method)
            start = time.perf_counter()
            jacs[method] = np.asarray(ivy.to_numpy(fns[method](u)))
            first[method] = time.perf_counter() - start
        if len(jacs) == 2:
            a, b = jacs.values()
            scale = np.abs(a).max()
            assert np.abs(a - b).max() <= 1e-3 * scale, (backend, np.abs(a - b).max(), scale)
        timers = {m: timeit.Timer(lambda fn=fns[m], u=u: ivy.to_numpy(fn(u))) for m in methods}
        samples = interleaved_samples(timers, number=1, repeats=args.repeats)
        best = {m: min(s) for m, s in samples.items()}
        line = ", ".join(f"{m} {best[m]:.2f} s (first call {first[m]:.1f} s)" for m in methods)
        ratio = (
            f"; replicate / native = {best['replicate'] / best['native']:.2f}"
            if len(best) == 2
            else ""
        )
        print(f"{backend}: {line}{ratio}", flush=True)


if __name__ == "__main__":
    main()
