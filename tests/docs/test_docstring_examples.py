"""Every docstring example of the core, ivy_gym and ivy_rl runs, on the backends it names
(``tests/_doctests.py``; ivy_mechanics', ivy_vision's and ivy_robot's run in their own
``test_api.py`` through the same helper)."""

from __future__ import annotations

import pytest

import ivy_gym
import ivy_rl
from tests._doctests import docstring_examples, run_example

#: ivy_rl's examples known to fail, by docstring, with the first error (ivy_rl was being rewritten
#: when these were collected; most are snippets that use names they never define). Each entry is
#: a defect to fix in its docstring, then to remove from here: one that passes shows as XPASS.
IVY_RL_XFAIL = {
    "ivy_rl.agents": "NameError: name 'env' is not defined",
    "ivy_rl.agents.a2c": "NameError: name 'env' is not defined",
    "ivy_rl.agents.a2c.A2C": "A2C(segment_size=64, actor_lr=1e-3) -> output differs",
    "ivy_rl.agents.agent": "NameError: name 'env' is not defined",
    "ivy_rl.agents.agent.Agent.compiles": "NameError: name 'agent' is not defined",
    "ivy_rl.agents.agent.Agent.initialize": "NameError: name 'env' is not defined",
    "ivy_rl.agents.agent.Agent.load": "NameError: name 'obs_space' is not defined",
    "ivy_rl.agents.agent.Agent.predict": "NameError: name 'agent' is not defined",
    "ivy_rl.agents.agent.Agent.save": "NameError: name 'agent' is not defined",
    "ivy_rl.agents.agent.Agent.set_progress": "NameError: name 'agent' is not defined",
    "ivy_rl.agents.apg": "NameError: name 'obs_space' is not defined",
    "ivy_rl.agents.apg.APG": "APG(horizon=64, actor_lr=1e-3) -> output differs",
    "ivy_rl.agents.apg.APG.policy_loss": "NameError: name 'agent' is not defined",
    "ivy_rl.agents.baselines": "NameError: name 'env' is not defined",
    "ivy_rl.agents.baselines.Constant": "NameError: name 'obs_space' is not defined",
    "ivy_rl.agents.baselines.Uniform": "NameError: name 'obs_space' is not defined",
    "ivy_rl.agents.d4pg.D4PG": "D4PG(v_min=-1000.0, v_max=0.0, atoms=51) -> output differs",
    "ivy_rl.agents.ddpg": "NameError: name 'env' is not defined",
    "ivy_rl.agents.ddpg.DDPG": "DDPG(hidden_sizes=(64, 64), exploration_scale=0.2) -> output differs",
    "ivy_rl.agents.defaults": "TypeError: setting 'segment_size' must be an integer >= 1, got '32' (str): steps per worker between u",
    "ivy_rl.agents.defaults.check_setting": "TypeError: setting 'hidden_sizes' must be a non-empty list of integers >= 1, e.g. [64, 64], got 64 (i",
    "ivy_rl.agents.dqn": "NameError: name 'env' is not defined",
    "ivy_rl.agents.dqn.BranchingDQN": "NameError: name 'obs_space' is not defined",
    "ivy_rl.agents.dqn.DQN": "DQN(hidden_sizes=(64, 64), epsilon_decay_steps=10_000) -> output differs",
    "ivy_rl.agents.mpo": "NameError: name 'env' is not defined",
    "ivy_rl.agents.mpo.MPO": "MPO(hidden_sizes=(256, 256), num_samples=20) -> output differs",
    "ivy_rl.agents.ppo": "NameError: name 'env' is not defined",
    "ivy_rl.agents.ppo.PPO": "PPO(ratio_clip=0.2, kl_threshold=0.015, epochs=10, batch_size=64) -> output differs",
    "ivy_rl.agents.sac": "NameError: name 'env' is not defined",
    "ivy_rl.agents.sac.SAC": "SAC(initial_temperature=0.1, temperature_lr=3e-4) -> output differs",
    "ivy_rl.agents.shac": "NameError: name 'obs_space' is not defined",
    "ivy_rl.agents.shac.SHAC": "SHAC(horizon=32, critic_iterations=16) -> output differs",
    "ivy_rl.agents.td3": "NameError: name 'env' is not defined",
    "ivy_rl.agents.td3.TD3": "TD3(hidden_sizes=(64, 64), policy_delay=2) -> output differs",
    "ivy_rl.agents.through_gym": "NameError: name 'obs_space' is not defined",
    "ivy_rl.agents.trpo": "NameError: name 'env' is not defined",
    "ivy_rl.agents.trpo.TRPO": "TRPO(max_kl=0.01, cg_steps=10, backtrack_steps=10) -> output differs",
    "ivy_rl.buffers": "NameError: name 'obs' is not defined",
    "ivy_rl.buffers.TransitionReplay.windows": "NameError: name 'replay' is not defined",
    "ivy_rl.buffers.n_step_batch": "NameError: name 'replay' is not defined",
    "ivy_rl.checkpoints": "TypeError: expected str, bytes or os.PathLike object, not NoneType",
    "ivy_rl.checkpoints.check_checkpoint": "CheckpointError: runs/ppo/checkpoints/step_100000/agent.json is missing",
    "ivy_rl.checkpoints.checkpoints": "checkpoints('runs/ppo') -> output differs",
    "ivy_rl.checkpoints.latest_checkpoint": "latest_checkpoint('runs/ppo') -> output differs",
    "ivy_rl.critics": "NameError: name 'rng' is not defined",
    "ivy_rl.critics.ActionValueCritic": "NoFrameworkError: A Module needs a framework to create its variables. Pass f='torch' (or f=ivy.torch), a fra",
    "ivy_rl.critics.BranchingQHead": "NameError: name 'x' is not defined",
    "ivy_rl.critics.CategoricalValueHead": "NameError: name 'x' is not defined",
    "ivy_rl.critics.CriticEnsemble": "NameError: name 'critic_a' is not defined",
    "ivy_rl.critics.DiscreteQHead": "NameError: name 'x' is not defined",
    "ivy_rl.critics.QNetwork": "NoFrameworkError: A Module needs a framework to create its variables. Pass f='torch' (or f=ivy.torch), a fra",
    "ivy_rl.critics.project_categorical": "NameError: name 'p' is not defined",
    "ivy_rl.distributions.Categorical": "NameError: name 'logits' is not defined",
    "ivy_rl.distributions.Deterministic": "NameError: name 'actions' is not defined",
    "ivy_rl.distributions.Normal": "NameError: name 'loc' is not defined",
    "ivy_rl.distributions.SquashedNormal": "NameError: name 'loc' is not defined",
    "ivy_rl.environments": "NameError: name 'actions' is not defined",
    "ivy_rl.environments.TimeFeature": "NameError: name 'gymnasium' is not defined",
    "ivy_rl.explorations": "NameError: name 'policy_actions' is not defined",
    "ivy_rl.explorations.EpsilonGreedy": "NameError: name 'greedy' is not defined",
    "ivy_rl.explorations.NoNoise": "NameError: name 'rng' is not defined",
    "ivy_rl.explorations.NormalNoise": "NameError: name 'actions' is not defined",
    "ivy_rl.explorations.OrnsteinUhlenbeckNoise": "NameError: name 'actions' is not defined",
    "ivy_rl.logger": "log.dump({'train/steps': 1000}) -> output differs",
    "ivy_rl.logger.read_log": "KeyError: 'test/episode_score/mean'",
    "ivy_rl.models.Actor": "actor(torch.zeros(1, 4), None).mode() -> output differs",
    "ivy_rl.models.ActorCritic": "NameError: name 'obs_space' is not defined",
    "ivy_rl.models.ActorCriticWithTargets": "NameError: name 'actor' is not defined",
    "ivy_rl.models.CategoricalHead": "NameError: name 'x' is not defined",
    "ivy_rl.models.Critic": "NameError: name 'critic' is not defined",
    "ivy_rl.models.DeterministicHead": "NameError: name 'x' is not defined",
    "ivy_rl.models.GaussianHead": "NameError: name 'features' is not defined",
    "ivy_rl.models.ObservationEncoder": "enc(jnp.ones((2, 3)), {'mean': jnp.ones(3), 'std': jnp.full(3, 2.0)}) -> output differs",
    "ivy_rl.models.SquashedGaussianHead": "NameError: name 'x' is not defined",
    "ivy_rl.models.ValueHead": "NameError: name 'x' is not defined",
    "ivy_rl.models.actor_critic": "NameError: name 'env' is not defined",
    "ivy_rl.models.check_observation_space": "NameError: name 'gymnasium' is not defined",
    "ivy_rl.models.glorot_init": "NameError: name 'rng' is not defined",
    "ivy_rl.models.orthogonal_init": "NameError: name 'rng' is not defined",
    "ivy_rl.models.polyak_update": "NameError: name 'target' is not defined",
    "ivy_rl.models.space_kind": "NameError: name 'gymnasium' is not defined",
    "ivy_rl.normalizers.MeanStd": "NameError: name 'obs_batch' is not defined",
    "ivy_rl.normalizers.ReturnNormalizer": "TypeError: float() argument must be a string or a real number, not 'module'",
    "ivy_rl.play.play": "FileNotFoundError: no run folder 'runs/ppo-cartpole': it does not exist",
    "ivy_rl.plot.plot": "FileNotFoundError: no run folder 'runs/ppo-0': it does not exist",
    "ivy_rl.replays": "NameError: name 'obs' is not defined",
    "ivy_rl.replays.Segment.batch_orders": "NameError: name 'rng' is not defined",
    "ivy_rl.returns.generalized_advantages": "NameError: name 'r' is not defined",
    "ivy_rl.returns.lambda_returns": "NameError: name 'r' is not defined",
    "ivy_rl.returns.n_step_returns": "NameError: name 'r' is not defined",
    "ivy_rl.schedules.as_schedule": "as_schedule('linear:1e-3:1e-4')(1.0) -> output differs",
    "ivy_rl.updaters": "NameError: name 'dist' is not defined",
    "ivy_rl.updaters.ClippedRatio": "ivy_rl.PPO(actor_updater=ClippedRatio(lr=1e-3, ratio_clip=0.2, kl_thre -> output differs",
    "ivy_rl.updaters.GradientUpdater": "NameError: name 'v' is not defined",
    "ivy_rl.updaters.StochasticPolicyGradient": "ivy_rl.A2C(actor_updater=StochasticPolicyGradient(lr=3e-3)) -> output differs",
    "ivy_rl.updaters.TrustRegionPolicyGradient": "ivy_rl.TRPO(actor_updater=TrustRegionPolicyGradient(max_kl=0.01)) -> output differs",
    "ivy_rl.updaters.ValueRegression": "ivy_rl.A2C(critic_updater=ValueRegression(lr=1e-3)) -> output differs",
    "ivy_rl.updaters.conjugate_gradient": "NameError: name 'grads' is not defined",
}

#: ivy_rl's examples that train for real or start a Ray cluster (which forks the process under
#: jax's threads): they run with ``IVY_SLOW_EXAMPLES=1``.
IVY_RL_SLOW = {
    "ivy_rl.distributed": "starts a local Ray cluster",
    "ivy_rl.distributed.RayVectorEnv": "starts a local Ray cluster",
    "ivy_rl": "trains PPO on CartPole for 100,000 steps",
    "ivy_rl.trainer": "trains PPO on CartPole for 100,000 steps",
    "ivy_rl.train.main": "trains A2C for 2,000 steps",
}


@pytest.mark.parametrize("example", docstring_examples("ivy"))
def test_ivy(example, request, tmp_path, monkeypatch):
    run_example(example, {}, request.config, tmp_path, monkeypatch)


#: ivy_gym's examples that optimise at full size (minutes on CI's two cores): they run with
#: ``IVY_SLOW_EXAMPLES=1``.
IVY_GYM_SLOW = {
    "ivy_gym.optimise": "200 Adam iterations through 100-step rollouts",
    "ivy_gym.optimise.optimise_actions": "300 Adam iterations through 100-step rollouts",
    "ivy_gym.optimise.optimise_actions_least_squares": "40 Gauss-Newton steps, a MuJoCo model",
    "ivy_gym.optimise.optimise_policy": "500 iterations of a 64-64 MLP policy",
    "ivy_gym.inverted_double_pendulum.InvertedDoublePendulum.swing_up_residuals": (
        "40 Gauss-Newton steps through a MuJoCo model"
    ),
}


@pytest.mark.parametrize("example", docstring_examples("ivy_gym", slow=IVY_GYM_SLOW))
def test_ivy_gym(example, request, tmp_path, monkeypatch):
    run_example(example, {"ivy_gym": ivy_gym}, request.config, tmp_path, monkeypatch)


@pytest.mark.parametrize(
    "example", docstring_examples("ivy_rl", xfail=IVY_RL_XFAIL, slow=IVY_RL_SLOW)
)
def test_ivy_rl(example, request, tmp_path, monkeypatch):
    globs = {"ivy_rl": ivy_rl, **{n: getattr(ivy_rl, n) for n in ivy_rl.__all__}}
    run_example(example, globs, request.config, tmp_path, monkeypatch)
