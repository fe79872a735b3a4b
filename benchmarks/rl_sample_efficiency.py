"""Sample efficiency on ivy_gym's Pendulum and Reacher: test score against environment steps for
PPO, SAC (where ivy_rl has it), the analytic policy gradient (APG) and short-horizon
actor-critic (SHAC), and the environment steps each needs to reach a fixed score.

Environment steps count every step of the environment's dynamics that an agent consumed: the
steps of the trainer's environments, plus, for APG and SHAC, the steps of the differentiable
rollouts they learn from (``agent.simulated_steps``), as the trainer counts them.

Each run drives the agent as ``ivy_rl.Trainer`` does (``bind_environment`` for the
differentiable agents, then ``initialize``, ``step``, the environments' step, ``update``), and
every ``eval_steps`` environment steps scores the deterministic policy over ``test_episodes``
full episodes (200 steps) with fixed seeds.

Usage:
    python benchmarks/rl_sample_efficiency.py                       # the notebook's budgets
    python benchmarks/rl_sample_efficiency.py --agents APG,SHAC --seeds 0 --budget 20000
    python benchmarks/rl_sample_efficiency.py --out benchmarks/results/other.json

Results are appended to ``--out`` (JSON, one entry per agent, task and seed), so that a run can
be continued and ``notebooks/rl_sample_efficiency.ipynb`` can plot them.
"""

from __future__ import annotations

import argparse
import json
import os
import time
from typing import Any

import numpy as np

#: Tasks: Gymnasium id, budget of environment steps, the fixed score of the comparison.
TASKS: dict[str, dict[str, Any]] = {
    "Pendulum": {"env_id": "ivy_gym/Pendulum-v1", "budget": 100_000, "target": -200.0},
    "Reacher": {"env_id": "ivy_gym/Reacher-v0", "budget": 100_000, "target": 60.0},
}

#: Agents whose budget is smaller than the task's: SAC updates at every step (50 optimisation
#: steps every 50 steps), too slow here for the others' budget.
AGENT_BUDGETS: dict[str, int] = {"SAC": 20_000}


def budget_for(agent_name: str, task_budget: int) -> int:
    """The budget of ``agent_name`` on a task whose budget is ``task_budget``."""
    return min(task_budget, AGENT_BUDGETS.get(agent_name, task_budget))


#: Settings per agent and task, and the number of the trainer's environments (workers).
SETTINGS: dict[str, dict[str, Any]] = {
    "PPO": {
        "workers": 16,  # fewer calls of the agent than the zoo's 4 workers, same segments
        "Pendulum": dict(  # the RL zoo's PPO settings for Pendulum (without gSDE)
            segment_size=256,
            batch_size=64,
            epochs=10,
            discount=0.9,
            trace_decay=0.95,
            actor_lr=1e-3,
            critic_lr=1e-3,
            kl_threshold=None,
            actor_gradient_clip=0.5,
            critic_gradient_clip=0.5,
            normalize_returns=True,
        ),
        "Reacher": dict(
            segment_size=128,
            batch_size=64,
            epochs=10,
            discount=0.98,
            trace_decay=0.95,
            actor_lr=3e-4,
            critic_lr=1e-3,
            kl_threshold=None,
            actor_gradient_clip=0.5,
            critic_gradient_clip=0.5,
            normalize_returns=True,
        ),
    },
    "SAC": {  # ivy_rl's defaults for classic control with continuous actions
        "workers": 1,
        "Pendulum": dict(
            hidden_sizes=(64, 64),
            batch_size=128,
            start_steps=1000,
            update_after=1000,
            update_every=50,
            batch_iterations=50,
            actor_lr=1e-3,
            critic_lr=1e-3,
        ),
        "Reacher": dict(
            hidden_sizes=(64, 64),
            batch_size=128,
            start_steps=1000,
            update_after=1000,
            update_every=50,
            batch_iterations=50,
            actor_lr=1e-3,
            critic_lr=1e-3,
        ),
    },
    "APG": {
        "workers": 1,
        "Pendulum": dict(batch_size=16, horizon=32, update_every=1, actor_lr=1e-2),
        "Reacher": dict(batch_size=16, horizon=32, update_every=1, actor_lr=1e-2),
    },
    "SHAC": {
        "workers": 1,
        "Pendulum": dict(
            batch_size=16, horizon=32, update_every=1, actor_lr=1e-2, critic_iterations=4
        ),
        "Reacher": dict(
            batch_size=16, horizon=32, update_every=1, actor_lr=1e-2, critic_iterations=4
        ),
    },
}


def available_agents() -> list[str]:
    """The agents of the comparison that ivy_rl has (SAC comes with the off-policy agents)."""
    import ivy_rl

    return [name for name in ("PPO", "SAC", "APG", "SHAC") if name in ivy_rl.agents.AGENTS]


def _score(agent, env, seeds, episode_steps) -> float:
    """Mean score of the deterministic policy over one episode from each seed, all episodes
    stepped together in one vector environment."""
    obs, _ = env.reset(seed=[int(s) for s in seeds])
    total = np.zeros(len(seeds))
    alive = np.ones(len(seeds), bool)
    for _ in range(episode_steps):
        obs, reward, terminated, _, _ = env.step(agent.test_step(obs))
        total += np.where(alive, reward, 0.0)
        alive &= ~np.asarray(terminated, bool)
    return float(np.mean(total))


def learning_curve(
    agent_name: str,
    task: str,
    seed: int,
    budget: int,
    *,
    eval_steps: int | None = None,
    test_episodes: int = 5,
    f: str = "jax",
    settings: dict[str, Any] | None = None,
) -> dict[str, Any]:
    """Train one agent on one task for ``budget`` environment steps (simulated ones included).

    Returns:
        ``{'agent', 'task', 'seed', 'budget', 'steps': [...], 'scores': [...], 'seconds'}``: the
        test score of the deterministic policy after each ``eval_steps`` steps (and at 0).

    Example:
        >>> learning_curve("APG", "Pendulum", 0, 20_000)["scores"]
    """
    import gymnasium

    import ivy_rl
    from ivy_rl.environments import Workers, make_vector_env

    env_id = TASKS[task]["env_id"]
    config = SETTINGS[agent_name]
    agent = ivy_rl.agents.make(agent_name, **(settings or config[task]))
    if getattr(agent, "differentiable", False):
        agent.bind_environment(env_id, {})
    workers = Workers(env_id, config["workers"], seed=seed)
    test_env = make_vector_env(env_id, test_episodes)
    episode_steps = gymnasium.spec(env_id).max_episode_steps
    agent.initialize(workers.observation_space, workers.action_space, seed=seed, f=f)
    eval_steps = eval_steps or max(budget // 10, 1)
    test_seeds = np.random.SeedSequence([seed, 11]).generate_state(test_episodes)
    start = time.perf_counter()
    steps, next_eval = 0, eval_steps
    curve_steps, scores = [0], [_score(agent, test_env, test_seeds, episode_steps)]
    observations = workers.start()
    while steps < budget:
        simulated = getattr(agent, "simulated_steps", 0)
        observations, infos = workers.step(agent.step(observations))
        agent.update(**infos)
        steps += workers.num_workers + getattr(agent, "simulated_steps", 0) - simulated
        if steps >= next_eval or steps >= budget:
            curve_steps.append(steps)
            scores.append(_score(agent, test_env, test_seeds, episode_steps))
            while next_eval <= steps:
                next_eval += eval_steps
    workers.env.close()
    test_env.close()
    return {
        "agent": agent_name,
        "task": task,
        "seed": int(seed),
        "budget": int(budget),
        "steps": curve_steps,
        "scores": scores,
        "seconds": time.perf_counter() - start,
    }


def steps_to_target(result: dict[str, Any], target: float) -> int | None:
    """The first evaluated step count whose test score reaches ``target`` (None: never)."""
    for steps, score in zip(result["steps"], result["scores"]):
        if score >= target:
            return int(steps)
    return None


def load(path: str) -> list[dict[str, Any]]:
    if not path or not os.path.exists(path):
        return []
    with open(path) as fh:
        return json.load(fh)


def run_all(
    agents: list[str],
    tasks: list[str],
    seeds: list[int],
    budgets: dict[str, int],
    *,
    out: str | None = None,
    f: str = "jax",
    verbose: bool = True,
    compute: bool = True,
) -> list[dict[str, Any]]:
    """Every learning curve of ``agents x tasks x seeds`` (``budgets`` per task, less for the
    agents of :data:`AGENT_BUDGETS`); with ``out``, the results already in
    that JSON file (same agent, task, seed and budget) are reused and new ones appended;
    ``compute=False`` returns the stored results only."""
    results = load(out) if out else []
    for seed in seeds:  # seed by seed, so that an interrupted run has every agent's curves
        for task in tasks:
            for agent_name in agents:
                budget = budget_for(agent_name, budgets[task])
                key = (agent_name, task, seed, budget)
                if any((r["agent"], r["task"], r["seed"], r["budget"]) == key for r in results):
                    continue
                if not compute:
                    continue
                result = learning_curve(agent_name, task, seed, budget, f=f)
                results.append(result)
                if verbose:
                    print(
                        f"{agent_name:5s} {task:9s} seed {seed}: final score "
                        f"{result['scores'][-1]:8.1f} after {result['steps'][-1]} steps, "
                        f"{result['seconds']:.0f} s",
                        flush=True,
                    )
                if out:
                    with open(out, "w") as fh:
                        json.dump(results, fh)
    return results


def summary(results: list[dict[str, Any]], targets: dict[str, float]) -> str:
    """A markdown table: per agent and task, the steps each seed needed to reach the target
    score, and the final scores."""
    lines = [
        "| task (target) | agent | steps to the target, per seed | final score, per seed |",
        "|---|---|---|---|",
    ]
    for task, target in targets.items():
        for agent_name in ("PPO", "SAC", "APG", "SHAC"):
            runs = sorted(
                (r for r in results if r["task"] == task and r["agent"] == agent_name),
                key=lambda r: r["seed"],
            )
            if not runs:
                continue
            reached = [steps_to_target(r, target) for r in runs]
            steps = ", ".join("never" if s is None else f"{s:,}" for s in reached)
            finals = ", ".join(f"{r['scores'][-1]:.0f}" for r in runs)
            lines.append(f"| {task} ({target:g}) | {agent_name} | {steps} | {finals} |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--agents", default=None, help="comma-separated (default: all available)")
    parser.add_argument("--tasks", default=",".join(TASKS))
    parser.add_argument("--seeds", default="0,1,2")
    parser.add_argument("--budget", type=int, default=None, help="steps per run (all tasks)")
    parser.add_argument("--framework", default="jax")
    parser.add_argument("--out", default="benchmarks/results/rl_sample_efficiency.json")
    args = parser.parse_args()
    agents = args.agents.split(",") if args.agents else available_agents()
    tasks = args.tasks.split(",")
    budgets = {t: args.budget or TASKS[t]["budget"] for t in tasks}
    if os.path.dirname(args.out):
        os.makedirs(os.path.dirname(args.out), exist_ok=True)
    results = run_all(
        agents, tasks, [int(s) for s in args.seeds.split(",")], budgets, out=args.out,
        f=args.framework,
    )  # fmt: skip
    print(summary(results, {t: TASKS[t]["target"] for t in tasks}))


if __name__ == "__main__":
    main()
