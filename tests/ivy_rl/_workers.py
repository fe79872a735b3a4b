"""Worker comparisons shared by the tests, and the Ray check, run as its own process
(``python -m tests.ivy_rl._workers``): Ray starts its local instance with subprocesses whose
start runs Python code after a fork, which must not happen in a process where jax's threads are
running (the test session has jax loaded); this process loads torch only."""

from __future__ import annotations

import numpy as np

from ivy_rl import environments


def observed(mode, count, seed, actions, env_id="CartPole-v1", **kwargs):
    """Everything a run of Workers returns for fixed actions."""
    workers = environments.Workers(env_id, count, seed=seed, vectorization=mode, **kwargs)
    seen = [workers.start()]
    for a in actions:
        obs, infos = workers.step(a)
        seen += [obs, infos["observations"], infos["rewards"], infos["resets"]]
    workers.close()
    return seen


def assert_same_runs(first, second):
    assert len(first) == len(second)
    for a, b in zip(first, second):
        np.testing.assert_array_equal(a, b)


def ray_check() -> None:
    """Ray workers see what sync workers see, and a short PPO training runs on them."""
    import ray

    import ivy_rl
    from ivy_rl.trainer import Trainer

    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        actions = np.random.default_rng(1).integers(0, 2, size=(40, 4))
        assert_same_runs(
            observed("sync", 4, 3, actions), observed("ray", 4, 3, actions, ray_groups=2)
        )
        agent = ivy_rl.PPO(hidden_sizes=(16,), segment_size=8, batch_size=16, epochs=1)
        rows = Trainer(32, epoch_steps=32, test_episodes=1, show_progress=False).run(
            agent,
            "CartPole-v1",
            workers=4,
            vectorization="ray",
            ray_groups=2,
            f="torch",
            compile=False,
        )
        assert rows[-1]["train/steps"] == 32 and np.isfinite(rows[-1]["actor/loss"])
    finally:
        ray.shutdown()
    print("ray workers: ok")


if __name__ == "__main__":
    ray_check()
