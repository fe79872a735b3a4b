"""The family defaults: settings per agent and task family, as the RL zoo keeps them, in one
table; and how to see an agent's settings with the defaults that apply.

A setting's defaults come in two layers, and nowhere else: the agent's own (each part declares
its settings and their defaults once, the agent states where it differs:
:meth:`ivy_rl.agents.Agent.settings`), then the row of :data:`DEFAULTS` for the task family of
the environment (:data:`FAMILIES`). ``SAC()`` takes the first; ``ivy_rl.agents.make("SAC",
environment="Pendulum-v1")`` and the command line (``python -m ivy_rl.train --agent SAC --env
Pendulum-v1``) take both, then the user's settings. :func:`settings_table` shows the two side by
side (``python -m ivy_rl.agents.defaults SAC Pendulum-v1`` prints it). Adding an agent: its
parts declare its settings; add its family rows to :data:`DEFAULTS`.

Example:
    >>> task_family("CartPole-v1"), task_family("Hopper-v5"), task_family("ivy_gym/Pendulum-v0")
    ('classic_discrete', 'mujoco', 'ivy_gym')
    >>> check_setting("segment_size", "32")
    Traceback (most recent call last):
    TypeError: setting 'segment_size' must be an integer >= 1, got '32' (str): ...
"""

from __future__ import annotations

from typing import Any

from ivy_rl.settings import Setting, check

__all__ = [
    "FAMILIES",
    "FALLBACK",
    "DEFAULTS",
    "SETTINGS",
    "Setting",
    "task_family",
    "check_setting",
    "defaults_for",
    "settings_table",
]

FAMILIES: dict[str, str] = {
    "classic_discrete": "classic control, discrete actions (CartPole, Acrobot, MountainCar)",
    "classic_continuous": "classic control, continuous actions (Pendulum, MountainCarContinuous)",
    "mujoco": "MuJoCo locomotion and manipulation (Hopper, HalfCheetah, Walker2d, Ant, Reacher)",
    "ivy_gym": "ivy_gym's differentiable environments (ivy_gym/<Name>-v<N>)",
    "ivy_gym_locomotion": (
        "ivy_gym's MuJoCo locomotion tasks (ivy_gym/Hopper-v5, Walker2d-v5, HalfCheetah-v5, "
        "Ant-v5, Swimmer-v5, Humanoid-v5); an agent without a row here takes its mujoco row"
    ),
}

#: Where a family has no row for an agent, the family whose row it takes instead: ivy_gym's
#: locomotion tasks are Gymnasium's MuJoCo tasks, batched and differentiable.
FALLBACK: dict[str, str] = {"ivy_gym_locomotion": "mujoco"}

# Off-policy agents: small torsos and updates every 50 steps (50 optimisation steps), so that
# the 20k-step Pendulum budget of the issue runs fast (SAC -120, TD3 -119 after 20k steps on
# jax, seed 0). DQN on CartPole: half an optimisation step per environment step and slow
# targets (500 from 30k to 50k steps; one step per environment step and target_tau=0.01
# reached 500 at 20k but fell to 132 at 50k).
_OFF_POLICY_CONTINUOUS = dict(
    hidden_sizes=(64, 64),
    batch_size=128,
    start_steps=1000,
    update_after=1000,
    update_every=50,
    batch_iterations=50,
    actor_lr=1e-3,
    critic_lr=1e-3,
)
# TD3 on MuJoCo: the RL zoo's and stable-baselines3's torsos (400, 300), without observation
# normalisation (stable-baselines3 does not normalise either). Measured on Hopper-v5, 30k steps,
# jax (docs/ivy_rl.md, "Off-policy results"): over seeds 0-4, 359.7 on average on the fixed
# episodes against 291.9 for stable-baselines3's TD3 with its defaults (ahead on 3 of 5 seeds).
# The agent's own settings ((256, 256), normalised observations) stayed below 40 for 20k steps
# and ended at 239 on seed 0 (302 with this row). Not adopted, on single seeds: one worker
# instead of 8, no exploration noise (as stable-baselines3). The zoo's 10k steps before
# learning would spend a third of the budget; the agent's 1000 random steps and 50
# optimisation steps every 50 environment steps (one per step, as train_freq 1) are kept. SAC
# and DDPG keep their own settings on MuJoCo (SAC: 2127 on the same budget).
_TD3_MUJOCO = dict(hidden_sizes=(400, 300), normalize_observations=False)
# The RL zoo's settings (rl-baselines3-zoo, hyperparams/ppo.yml, a2c.yml, trpo.yml) where they
# carry over; learning rates and clipping are constant here. CartPole's PPO row is measured in
# docs/ivy_rl.md (test score 500 in 100k steps on torch, jax and tensorflow).
# SHAC's published settings (Xu et al. 2022, their Hopper configuration): 32-step windows,
# an ELU policy of (128, 64, 32) and critic of (64, 64), Adam with decay rates 0.7 and 0.95,
# learning rates decaying linearly from 2e-3 (policy) and 2e-4 (critic), gradients clipped at a
# global norm of 1, observations normalised by running moments, returns not; the critic: 16
# passes of 4 mini-batches on TD(0.95) targets, its target moved 80% of the way per update.
# Their Hopper runs 256 environments; 64 here (their Ant's): an update at 256 takes 4x as long
# on a 2-core CPU, for the same steps per second. APG takes the policy's side. Two changes,
# measured on ivy_gym's Hopper-v5 (seed 0, jax; docs/ivy_rl.md, "Learning through contacts"):
# windows of 16 steps, not 32, and the critic's rate of the paper's Ant, 2e-3, not 2e-4.
# Gymnasium's Hopper rewards staying up by a constant and a termination, which have no gradient
# (the paper's dflex Hopper rewards height and angle): with 32 steps the policy learned to dive
# (34 after 1M steps; the windows ended terminated, so the critic's value, the only term that
# knows what falling costs, never entered the loss); with 8 it stood still (about 1,000); with
# 16 it stood, then fell again; with 16 and the faster critic it hopped: 1,902 at 144k steps,
# 2,114 at 206k.
_SHAC_PAPER_ACTOR = dict(
    batch_size=64,
    horizon=32,
    update_every=1,
    hidden_sizes=(128, 64, 32),
    activation="elu",
    actor_lr="linear:2e-3",
    actor_gradient_clip=1.0,
    adam_beta1=0.7,
    adam_beta2=0.95,
    discount=0.99,
    normalize_observations=True,
)
DEFAULTS: dict[str, dict[str, dict[str, Any]]] = {
    "PPO": {
        "classic_discrete": dict(
            segment_size=32,
            batch_size=256,
            epochs=20,
            discount=0.98,
            trace_decay=0.8,
            actor_lr=1e-3,
            critic_lr=1e-3,
            kl_threshold=None,
            actor_gradient_clip=0.5,
            critic_gradient_clip=0.5,
        ),
        "classic_continuous": dict(
            segment_size=1024,
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
        "mujoco": dict(
            segment_size=512,
            batch_size=64,
            epochs=10,
            discount=0.99,
            trace_decay=0.95,
            actor_lr=3e-4,
            critic_lr=3e-4,
            kl_threshold=None,
            actor_gradient_clip=0.5,
            critic_gradient_clip=0.5,
            normalize_returns=True,
        ),
        "ivy_gym": dict(
            segment_size=256,
            batch_size=64,
            epochs=10,
            discount=0.99,
            trace_decay=0.95,
            actor_lr=1e-3,
            critic_lr=1e-3,
            kl_threshold=None,
            actor_gradient_clip=0.5,
            critic_gradient_clip=0.5,
            normalize_returns=True,
        ),
    },
    "A2C": {
        "classic_discrete": dict(
            segment_size=16,
            actor_lr=3e-3,
            critic_lr=1e-3,
            critic_iterations=5,
            discount=0.99,
            trace_decay=0.95,
        ),
    },
    # ivy_gym's Pendulum and Reacher (benchmarks/rl_sample_efficiency.py)
    "APG": {
        "ivy_gym": dict(batch_size=16, horizon=32, update_every=1, actor_lr=1e-2),
        "ivy_gym_locomotion": dict(_SHAC_PAPER_ACTOR),
    },
    "SHAC": {
        "ivy_gym": dict(
            batch_size=16, horizon=32, update_every=1, actor_lr=1e-2, critic_iterations=4
        ),
        "ivy_gym_locomotion": dict(
            _SHAC_PAPER_ACTOR,
            horizon=16,
            critic_hidden_sizes=(64, 64),
            critic_lr="linear:2e-3",
            critic_iterations=16,
            critic_batches=4,
            target_update=0.8,
            trace_decay=0.95,
            normalize_returns=False,
        ),
    },
    "TRPO": {
        "classic_discrete": dict(
            segment_size=128,
            max_kl=0.03,
            critic_iterations=10,
            batch_size=256,
            discount=0.99,
            trace_decay=0.95,
        ),
    },
    "SAC": {"classic_continuous": dict(_OFF_POLICY_CONTINUOUS)},
    "TD3": {
        "classic_continuous": dict(_OFF_POLICY_CONTINUOUS),
        "mujoco": dict(_TD3_MUJOCO),
    },
    "DDPG": {"classic_continuous": dict(_OFF_POLICY_CONTINUOUS)},
    "D4PG": {
        "classic_continuous": dict(_OFF_POLICY_CONTINUOUS, return_steps=3, v_min=-1500.0, v_max=0.0)
    },
    "MPO": {"classic_continuous": dict(_OFF_POLICY_CONTINUOUS, actor_lr=3e-4)},
    "DQN": {
        "classic_discrete": dict(
            hidden_sizes=(64, 64),
            batch_size=128,
            update_after=1000,
            update_every=50,
            batch_iterations=25,
            critic_lr=1e-3,
            return_steps=3,
            epsilon_decay_steps=10_000,
            target_tau=0.005,
        )
    },
}


#: every flat setting of the agents (name: what it takes), derived from the settings their parts
#: declare (:meth:`ivy_rl.agents.Agent.settings`); filled when :mod:`ivy_rl.agents` is imported
SETTINGS: dict[str, Setting] = {}


def check_setting(name: str, value: Any) -> Any:
    """``value`` checked against the setting ``name`` of any agent (:data:`SETTINGS`, declared
    by the parts) and normalised (sizes as a tuple, integers as ``int``, numbers as
    ``float``); a TypeError or ValueError naming the setting, what it takes and what it got
    otherwise. Unknown names pass unchecked (an agent's constructor refuses names it does not
    know, and checks its own settings against its parts').

    Example:
        >>> check_setting("hidden_sizes", [64, 64])
        (64, 64)
        >>> check_setting("hidden_sizes", 64)
        Traceback (most recent call last):
        TypeError: setting 'hidden_sizes' must be a non-empty list of integers >= 1, ...
    """
    return check(name, SETTINGS.get(name), value)


def task_family(environment: Any) -> str | None:
    """The task family (a key of :data:`FAMILIES`) of an environment: a Gymnasium id (also
    ``module:EnvId``) or an environment object; None when it is None or unknown.

    Classic control and Box2D tasks are split by their action space (Discrete or Box), read from
    the environment (made once for an id that is not one of the known names).

    Example:
        >>> task_family("Pendulum-v1")
        'classic_continuous'
    """
    if environment is None:
        return None
    if not isinstance(environment, str):
        return _family_of_space(getattr(environment, "action_space", None), None)
    env_id = environment.split(":", 1)[-1]
    if env_id.startswith("ivy_gym/"):
        locomotion = env_id.split("/")[-1].split("-v")[0] in _LOCOMOTION
        return "ivy_gym_locomotion" if locomotion else "ivy_gym"
    name = env_id.split("/")[-1].split("-v")[0]
    if name in _MUJOCO:
        return "mujoco"
    if name in _CLASSIC_DISCRETE:
        return "classic_discrete"
    if name in _CLASSIC_CONTINUOUS:
        return "classic_continuous"
    try:
        import gymnasium as gym

        spec = gym.spec(env_id)
        entry = str(spec.entry_point)
        if "mujoco" in entry:
            return "mujoco"
        if "classic_control" in entry or "box2d" in entry:
            env = gym.make(env_id)
            try:
                return _family_of_space(env.action_space, None)
            finally:
                env.close()
    except Exception:  # an id the registry does not know: no family row
        return None
    return None


def _family_of_space(space: Any, default: str | None) -> str | None:
    kind = type(space).__name__
    if kind == "Discrete":
        return "classic_discrete"
    if kind == "Box":
        return "classic_continuous"
    return default


_LOCOMOTION = {"Ant", "HalfCheetah", "Hopper", "Humanoid", "Swimmer", "Walker2d"}
_MUJOCO = {
    "Ant",
    "HalfCheetah",
    "Hopper",
    "Humanoid",
    "HumanoidStandup",
    "InvertedDoublePendulum",
    "InvertedPendulum",
    "Pusher",
    "Reacher",
    "Swimmer",
    "Walker2d",
}
_CLASSIC_DISCRETE = {"CartPole", "Acrobot", "MountainCar", "LunarLander"}
_CLASSIC_CONTINUOUS = {"Pendulum", "MountainCarContinuous", "LunarLanderContinuous"}


def defaults_for(name: str, environment: Any = None) -> dict[str, Any]:
    """The row of :data:`DEFAULTS` for the agent ``name`` and the family of ``environment``
    (empty when there is none).

    Example:
        >>> defaults_for("PPO", "CartPole-v1")["segment_size"]
        32
    """
    family = task_family(environment)
    rows = DEFAULTS.get(name, {})
    if family not in rows:
        family = FALLBACK.get(family)
    return dict(rows.get(family, {})) if family else {}


def settings_table(name: str, environment: Any = None) -> list[dict[str, Any]]:
    """Every setting of the agent ``name``: its part, what it takes, the agent's default
    (``SAC()``'s), the default of ``environment``'s family (``make(name, environment=...)``'s
    and the command line's; the agent's where the family row does not set it), whether the two
    differ (``differs``: a tuple and a list of the same values do not) and its meaning.

    Example:
        >>> row = settings_table("SAC", "Pendulum-v1")[0]
        >>> row["name"], row["agent_default"], row["family_default"]
        ('activation', 'relu', 'relu')
    """
    from ivy_rl.agents import AGENTS, make
    from ivy_rl.settings import describe

    key = make.resolve(name)
    family = defaults_for(key, environment)
    rows = []
    for setting, (spec, default, role) in sorted(AGENTS[key].settings().items()):
        family_default = family.get(setting, default)
        rows.append(
            {
                "name": setting,
                "part": role or "agent",
                "takes": describe(spec),
                "agent_default": default,
                "family_default": family_default,
                "differs": _as_list(family_default) != _as_list(default),
                "meaning": spec.meaning,
            }
        )
    return rows


def _as_list(value: Any) -> Any:
    return list(value) if isinstance(value, tuple) else value


def _main(argv: list[str] | None = None) -> None:
    """``python -m ivy_rl.agents.defaults AGENT [ENVIRONMENT]``: the agent's settings."""
    import sys

    args = sys.argv[1:] if argv is None else argv
    if not args or args[0] in ("-h", "--help"):
        print("usage: python -m ivy_rl.agents.defaults AGENT [ENVIRONMENT]")
        return
    environment = args[1] if len(args) > 1 else None
    family = task_family(environment)
    column = f"{environment} ({family})" if family else "family (none)"
    print(f"{'setting':24} {'part':15} {'SAC()'.replace('SAC', args[0]):>14} {column:>28}")
    for row in settings_table(args[0], environment):
        changed = "*" if row["differs"] else " "
        print(
            f"{row['name']:24} {row['part']:15} {str(row['agent_default']):>14} "
            f"{str(row['family_default']):>27}{changed} {row['meaning']}"
        )


if __name__ == "__main__":
    _main()
