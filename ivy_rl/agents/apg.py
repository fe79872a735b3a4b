"""APG: the analytic policy gradient, the gradient of the return of differentiable rollouts.

Each update draws ``batch_size`` initial states from the environment's reset box, runs the
deterministic policy for ``horizon`` steps through the ivy_gym core (``ivy_gym.rollout``), and
takes one Adam step on the negative mean discounted return, differentiated through the
dynamics (backpropagation through time). See :mod:`ivy_rl.agents.through_gym` for what it
shares with :class:`~ivy_rl.agents.SHAC` and its contract with the trainer.

Example:
    >>> import gymnasium as gym, ivy_gym                 # ivy_gym registers its ids
    >>> env = gym.make("ivy_gym/Pendulum-v1")
    >>> agent = APG(horizon=64, batch_size=32)
    >>> agent.bind_environment("ivy_gym/Pendulum-v1", {})  # what the trainer does first
    >>> agent = agent.initialize(env.observation_space, env.action_space, seed=0, f="jax")
    >>> type(agent.core).__name__                       # the differentiable core it learns through
    'Pendulum'
"""

from __future__ import annotations

from typing import Any

from ivy_rl.agents.through_gym import DifferentiableAgent

__all__ = ["APG"]


class APG(DifferentiableAgent):
    """Analytic policy gradient through an ivy_gym environment.

    Loss: ``-mean_b sum_t discount**t r_t / horizon`` over ``batch_size`` rollouts of
    ``horizon`` steps from fresh initial states; one Adam step per update, the gradient's
    global norm clipped at ``actor_gradient_clip``.

    Args:
        settings: the flat settings of its parts (an
            :class:`~ivy_rl.models.ActorValueModel`, :class:`~ivy_rl.replays.Rollouts`, a
            :class:`~ivy_rl.explorations.NormalNoise` on the actions taken in the trainer's
            environments, an :class:`~ivy_rl.updaters.AnalyticPolicyGradient`), and ``fusion``
            (:mod:`ivy_rl.agents.through_gym`). Learning rates take a number or a schedule of
            the run's progress (:mod:`ivy_rl.schedules`).

    Settings: the flat settings (``APG(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``APG.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults APG ivy_gym/Pendulum-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> APG(horizon=64, actor_lr=1e-3).config["horizon"]
        64
    """

    _defaults: dict[str, Any] = dict(horizon=64)

    def _build_learner(self) -> None:
        self.v = self._placed({"actor": self.actor.v})
        self.optimizer_states = {"actor": self.actor_optimizer.init(self.v["actor"])}

    def _update_fn(self, v, states, obs_moments, start, scheduled):
        """One Adam step of the actor from rollouts of the initial states ``start``, at the
        scheduled learning rate; the observations' moments with the rollouts' added."""
        actor_v, actor_state, logs, observations = self._actor_step(
            v["actor"], states["actor"], self._stats(obs_moments), start, scheduled["actor_lr"]
        )
        obs_moments = self._fold_observations(obs_moments, observations)
        return {"actor": actor_v}, {"actor": actor_state}, obs_moments, logs

    def policy_loss(
        self, actor_v: Any, start: Any, obs_stats: Any = None
    ) -> tuple[Any, dict[str, Any]]:
        """APG's loss: ``-mean_b sum_t discount**t r_t / horizon`` of ``horizon``-step rollouts
        of the policy with variables ``actor_v`` from the initial states ``start``, a
        differentiable function of both.

        Args:
            actor_v: the policy's variables (``agent.v['actor']``).
            start: ``(batch, state_dim)`` initial states of the environment's core.
            obs_stats: ``{'mean', 'std'}`` that normalise the policy's observations (None:
                none; with ``normalize_observations``, the agent passes its running ones).

        Returns:
            ``(loss, {'rollout_reward': mean reward per step, 'observations': the rollouts'
            observations})``.

        Example:
            >>> import gymnasium as gym, ivy_gym, torch, ivy
            >>> env = gym.make("ivy_gym/Pendulum-v1")
            >>> agent = APG(horizon=4)
            >>> agent.bind_environment("ivy_gym/Pendulum-v1", {})
            >>> agent = agent.initialize(env.observation_space, env.action_space, f="torch")
            >>> start = torch.tensor([[0.0, 0.0], [3.0, 0.5]])  # (angle, angular velocity)
            >>> loss, grads, infos = ivy.execute_with_gradients(
            ...     lambda v: agent.policy_loss(v, start), agent.v["actor"])
            >>> grads["head"]["layer"]["w"].shape               # through the dynamics
            torch.Size([1, 64])
        """
        self._check_initialized()
        xp = self.xp
        horizon = self.config["horizon"]
        traj = self._rollout(actor_v, start, horizon, obs_stats=obs_stats)
        rewards = traj.rewards
        discounted = xp.sum(rewards * self._discounts(horizon, rewards.dtype), axis=0)
        reward = xp.stop_gradient(xp.mean(rewards))
        observations = xp.stop_gradient(traj.observations)
        return -xp.mean(discounted) / horizon, {
            "rollout_reward": reward,
            "observations": observations,
        }

    def _actor_step(self, actor_v, actor_state, obs_stats, start, lr):
        def loss_fn(w):
            return self.policy_loss(w, start, obs_stats)

        actor_v, actor_state, infos = self._actor_minimize(loss_fn, actor_v, actor_state, lr)
        observations = infos.pop("observations")
        logs = {f"actor/{k}": x for k, x in infos.items()}
        return actor_v, actor_state, logs, observations

    def _learn(self) -> dict[str, float]:
        c = self.config
        start = self._asarray(self._initial_states(c["batch_size"]))
        self.v, self.optimizer_states, self.obs_moments, logs = self._update(
            self.v, self.optimizer_states, self.obs_moments, start, self._scheduled_arrays()
        )
        self.simulated_steps += c["batch_size"] * c["horizon"]
        return self._logs(logs)
