"""Trajectory optimisation steps of ivy_robot's planners: how long ``ivy.compile_fn`` takes to
build one step (cost, gradient by ``ivy.execute_with_gradients``, Adam update) on each
differentiable backend, and the time per step compiled and eager, measured in the same run.
The compile time is wall-clock seconds of the first call (trace and compile; inductor builds
its C++ in worker processes, which a process's CPU time leaves out; torch reuses kernels
cached on disk by an earlier run, so a second run compiles faster).

The problems are those of the tests (``tests/ivy_robot/_models.py``): the MJCF Panda (7 hinges,
31 collision spheres, 40 path samples) around a post, and a drone (pose space, 40 samples)
around pillars, in float64. The first call of the compiled step traces and compiles it; the
steady-state figures are minimums over interleaved repeats (``benchmarks/_timing.py``), wall
clock and process CPU time (``--clock``). torch runs single-threaded by default.

Usage:
    .venv/bin/python benchmarks/robot_planning.py [--backends torch,jax,tensorflow]
        [--planners arm,drone] [--repeats 5] [--clock wall|cpu] [--torch-threads 1]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
import timeit
import warnings

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..")]

from _timing import interleaved_samples  # noqa: E402
from robot_kinematics import installed_backends  # noqa: E402

import ivy  # noqa: E402
import ivy_robot  # noqa: E402
from tests.ivy_robot import _models as M  # noqa: E402


def planners():
    arm_xml = ivy_robot.panda_mjcf(M.ARM_OBSTACLES)
    tree = ivy_robot.KinematicTree.from_mjcf(arm_xml)
    arm = ivy_robot.ArmPlanner(
        tree, ivy_robot.SceneSDF.from_mjcf(arm_xml, exclude=["link0"]), num_samples=40
    )
    drone = ivy_robot.DronePlanner(
        ivy_robot.RigidMobile(M.DRONE_POINTS),
        ivy_robot.SceneSDF.from_mjcf(M.DRONE_SCENE, exclude=["drone"]),
        body_radius=M.DRONE_RADIUS,
        num_samples=40,
    )
    return {
        "arm": (arm, M.ARM_START, M.ARM_GOAL),
        "drone": (drone, M.DRONE_START, M.DRONE_GOAL),
    }


def _blocking(backend, step):
    if backend != "jax":
        return step
    return lambda *args: [x.block_until_ready() for x in step(*args)[:2]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--backends", default="torch,jax,tensorflow")
    parser.add_argument("--planners", default="arm,drone")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--number", type=int, default=5)
    parser.add_argument("--clock", choices=("wall", "cpu"), default="wall")
    parser.add_argument("--torch-threads", type=int, default=1)
    args = parser.parse_args()
    backends = installed_backends(args.backends, args.torch_threads)
    warnings.filterwarnings("ignore")
    clock = time.perf_counter if args.clock == "wall" else time.process_time
    problems = planners()
    print(f"planner steps, float64; clock: {args.clock}; load average: {os.getloadavg()[0]:.1f}")
    head = f"{'planner':8s} {'backend':11s} {'compile (s)':>12s} {'compiled':>12s} {'eager':>12s}"
    print(head + f" {'eager/compiled':>15s}")
    for name in args.planners.split(","):
        planner, start_np, goal_np = problems[name]
        for backend in backends:
            xp = getattr(ivy, backend)
            start, goal = xp.asarray(start_np), xp.asarray(goal_np)
            optimizer = ivy.Adam(0.05)
            anchors = planner.initial_anchors(start, goal)
            state = optimizer.init({"anchors": anchors})
            inputs = (anchors, state, start, goal)
            compiled = _blocking(backend, planner.step_fn(optimizer))
            eager = _blocking(backend, planner.step_fn(optimizer, compile=False))
            began = time.perf_counter()  # wall: inductor compiles in worker processes
            compiled(*inputs)
            compile_s = time.perf_counter() - began
            eager(*inputs)
            samples = interleaved_samples(
                {
                    "compiled": timeit.Timer(lambda f=compiled, a=inputs: f(*a), timer=clock),
                    "eager": timeit.Timer(lambda f=eager, a=inputs: f(*a), timer=clock),
                },
                args.number,
                args.repeats,
            )
            best = {k: min(v) for k, v in samples.items()}
            print(
                f"{name:8s} {backend:11s} {compile_s:12.1f} {best['compiled'] * 1e3:10.2f}ms "
                f"{best['eager'] * 1e3:10.2f}ms {best['eager'] / best['compiled']:15.1f}"
            )


if __name__ == "__main__":
    main()
