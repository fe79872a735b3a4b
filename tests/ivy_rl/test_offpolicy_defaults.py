"""The command line's defaults of the off-policy agents on MuJoCo tasks: TD3 has a row of its
own for the 'mujoco' family (measured on Hopper-v5 in docs/ivy_rl.md), and no MuJoCo task takes
the small torsos of the Pendulum row."""

import pytest

import ivy_rl
from ivy_rl.agents import DEFAULTS, defaults_for, make
from ivy_rl.agents.defaults import check_setting


@pytest.mark.parametrize("env_id", ["Hopper-v5", "Walker2d-v5", "HalfCheetah-v5"])
def test_mujoco_tasks_resolve_td3s_mujoco_row(env_id):
    row = DEFAULTS["TD3"].get("mujoco")
    assert row, "DEFAULTS has no 'mujoco' row for TD3"
    assert defaults_for("TD3", env_id) == row
    config = make("TD3", environment=env_id).config
    own = ivy_rl.TD3().config
    for key, value in row.items():
        assert config[key] == check_setting(key, value), key
    # the row changes something: the agent built for the task is not TD3's own
    assert any(config[key] != own[key] for key in row)
    # and the user's settings still win over it
    assert make("TD3", environment=env_id, hidden_sizes=[32]).config["hidden_sizes"] == (32,)


@pytest.mark.parametrize("agent", ["SAC", "TD3", "DDPG"])
def test_mujoco_does_not_take_the_pendulum_row(agent):
    pendulum = make(agent, environment="Pendulum-v1").config
    hopper = make(agent, environment="Hopper-v5").config
    assert pendulum["hidden_sizes"] == (64, 64)
    assert hopper["hidden_sizes"] != pendulum["hidden_sizes"]
    assert hopper["batch_size"] >= pendulum["batch_size"]
