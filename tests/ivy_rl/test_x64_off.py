"""ivy_rl on jax as users run it: 64-bit types off (the suite turns them on in
``tests/conftest.py``, so this runs in a fresh process). The command line trains an off-policy
agent (compiled), continues the run and plays it; an agent predicts and is evaluated; the API
refuses float64 by name before writing anything; the replay on its own takes Gymnasium's float64
observations (stored as float32)."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

SCRIPT = """
import json, os, sys, warnings
warnings.filterwarnings("ignore", category=DeprecationWarning)
import jax
assert not jax.config.jax_enable_x64
import numpy as np
import ivy
import ivy_rl
from ivy_rl import play, train
from ivy_rl.environments import make_env

root = sys.argv[1]
common = ["-f", "jax", "--workers", "2", "--test-episodes", "1", "--quiet"]
sac = {"hidden_sizes": [16], "start_steps": 16, "update_after": 16, "update_every": 8,
       "batch_size": 16, "batch_iterations": 2}
rows = train.main(["--agent", "SAC", "--environment", "Pendulum-v1", "--steps", "48",
                   "--epoch-steps", "24", "--agent-kwargs", json.dumps(sac),
                   "--out", f"{root}/sac", *common])
rows = train.main(["--out", f"{root}/sac", "--resume", "--steps", "64", "--quiet"])
assert [r["train/steps"] for r in rows] == [24, 48, 64], rows
assert np.isfinite(rows[-1]["critic/loss"]) and np.isfinite(rows[-1]["actor/loss"])
ppo = {"hidden_sizes": [16], "segment_size": 8, "batch_size": 16, "epochs": 1}
results = play.main([f"{root}/sac", "--best", "--episodes", "1"])
assert results[0]["length"] == 200
env = make_env("CartPole-v1")
agent = ivy_rl.agents.make("PPO", environment="CartPole-v1", **ppo)
agent.initialize(env.observation_space, env.action_space, seed=0, f="jax", compile=False)
action, _ = agent.predict(env.reset(seed=0)[0], deterministic=True)
assert env.action_space.contains(action)
mean, std = ivy_rl.evaluate(agent, env, episodes=2)
assert mean >= 8 and std >= 0
try:
    ivy_rl.Trainer(32, show_progress=False).run("PPO", "CartPole-v1", workers=2, f="jax",
                                                dtype="float64", out=f"{root}/f64")
    error = None
except Exception as raised:
    error = raised
assert error is not None and "64-bit types disabled" in str(error), error
assert not os.path.exists(f"{root}/f64")  # nothing was written
assert not jax.config.jax_enable_x64
# the replay on its own takes Gymnasium's float64 (stored as float32, as jax holds them)
from ivy_rl.buffers import TransitionReplay
replay = TransitionReplay(8)
zeros = {k: np.zeros((2, 3)) for k in ("observations", "actions", "next_observations")}
replay.store(**zeros, rewards=np.zeros(2), resets=np.zeros(2, bool), terminations=np.zeros(2))
replay.flush(ivy.get_framework(f="jax"))
assert replay.arrays["observations"].dtype == np.float32
print("ok")
"""


def test_training_on_jax_without_64_bit_types(tmp_path):
    if importlib.util.find_spec("jax") is None:
        pytest.skip("needs jax")
    env = {**os.environ, "JAX_ENABLE_X64": "0", "PYTHONPATH": ROOT}
    done = subprocess.run(
        [sys.executable, "-c", SCRIPT, str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=600,
        env=env,
        cwd=ROOT,
    )
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-4000:]
    assert done.stdout.strip().splitlines()[-1] == "ok"
