"""A feedback policy that swings the double pendulum up and balances it, learned with gradients,
per backend: the policy row of the swing-up in ``docs/ivy_gym.md``.

Least-squares shooting (``ivy_gym.optimise_actions_least_squares``) finds open-loop swing-ups,
but an open-loop sequence holds only the start it was optimised from, and Adam through the
rollouts of a policy finds no swing-up (``docs/ivy_gym.md``). This recipe, after guided policy
search, turns one swing-up into a policy:

1. nominal: the two-stage swing-up of ``double_pendulum_swing_up.py`` from ``--restarts``
   hanging starts, or ``--nominal FILE``: the ``s0`` ``(B, 6)``, ``states`` ``(T, B, 6)`` and
   ``actions`` ``(T, B, 1)`` of an earlier run (``--save-nominal`` writes them);
2. expert: along each solved swing-up, a time-varying LQR (the step's Jacobians with
   ``ivy.jacobian`` through ``env.step`` in float64, then a Riccati recursion on the host)
   that hands over to the upright LQR at its end; the swing-up whose expert holds the most of
   128 fresh starts under the action noise of step 3 is kept;
3. imitation (DAgger): an MLP 64-64 (tanh) fitted with Adam to the expert's actions at the
   states of the expert's rollouts under action noise, then, for ``--rounds`` rounds, also at
   the states the policy itself visits (labelled with the expert's action for that step), each
   rollout's states labelled only up to its first exit from a tube about the nominal;
4. refinement (off by default): ``ivy_gym.optimise_policy`` on the swing-up's reward,
   ``--refine`` iterations (windows of 25 steps, clipping at 1, lr 1e-4). It undoes the
   policy (``docs/ivy_gym.md``): the few starts it fails run the cart metres away (returns
   down to -1e8), and their gradients (norms of 1e9 to 1e13) drive Adam;
5. evaluation: 256 fresh starts, ``--horizon`` steps; solved: both poles within 18 degrees of
   upright (``cos > 0.95``) and every speed below 5 (rad/s, m/s) over the last ``--hold``
   steps, the cart within 1 m throughout.

Usage: python benchmarks/double_pendulum_policy.py [--backend jax] [--nominal FILE]
       [--rounds 4] [--refine 0] [--horizon 200] [--hold 150]
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

import ivy
import ivy_gym

warnings.filterwarnings("ignore")

STATE_COST = np.diag([1.0, 10.0, 10.0, 0.1, 0.1, 0.1])
ACTION_COST = np.array([[1.0]])


def compiled(fn, xp):
    """``fn`` compiled where the backend's compiler keeps loops (jax, tensorflow; the rule of
    ``ivy_gym``'s ``compile=None``); eager elsewhere: torch.compile unrolls the rollouts' loops
    and takes longer than the eager work."""
    caps = xp.capabilities
    return ivy.compile_fn(fn, f=xp) if caps.compilation and caps.compiled_loops else fn


def step_jacobians(env, xp):
    """``jacobians(states, actions) -> (A, B)``: the step's Jacobians ``(T, 6, 6)`` and
    ``(T, 6, 1)`` at ``states[t]``, ``actions[t]`` (float64 numpy), through the backend's
    autodiff (compiled on jax and tensorflow)."""
    n = env.state_dim
    # tensorflow's vectorised Jacobian (pfor) does not get through the step's loops
    method = "native" if xp.capabilities.vectorised_jacobian else "replicate"
    jac = compiled(
        ivy.jacobian(
            lambda z: env.step(z[..., :n], z[..., n:], f=xp)[0], batch_dims=1, method=method
        ),
        xp,
    )

    def jacobians(states, actions):
        z = xp.asarray(np.concatenate([states, actions], axis=-1), dtype="float64")
        out = np.asarray(ivy.to_numpy(jac(z)), np.float64)
        return out[..., :n], out[..., n:]

    return jacobians


def riccati_step(a, b, p):
    """One step of the LQR's backward recursion: the gain ``K`` (``u = K x``) and ``P``."""
    gain = -np.linalg.solve(ACTION_COST + b.T @ p @ b, b.T @ p @ a)
    p = STATE_COST + a.T @ p @ (a + b @ gain)
    return gain, (p + p.T) / 2


class Expert:
    """A time-varying LQR along a nominal swing-up, then the upright LQR."""

    def __init__(self, jacobians, states, actions):
        a, b = jacobians(np.zeros((1, 6)), np.zeros((1, 1)))
        self.upright_gain, p = None, STATE_COST
        for _ in range(2000):  # the infinite-horizon upright LQR
            self.upright_gain, p = riccati_step(a[0], b[0], p)
        a, b = jacobians(states[:-1], actions)
        self.gains = np.zeros((len(actions), 1, 6))
        for t in reversed(range(len(actions))):
            self.gains[t], p = riccati_step(a[t], b[t], p)
        self.states, self.actions = states, actions

    def __call__(self, state, t):
        """The action ``(B, 1)`` at ``state`` ``(B, 6)`` at step ``t``."""
        if t < len(self.actions):
            u = self.actions[t] + (state - self.states[t]) @ self.gains[t].T
        else:
            wrapped = state.copy()
            wrapped[..., 1:3] = np.arctan2(np.sin(state[..., 1:3]), np.cos(state[..., 1:3]))
            u = wrapped @ self.upright_gain.T
        return np.clip(u, -1.0, 1.0)

    def deviation(self, state, t):
        """The largest deviation ``(B,)`` of the cart's position and the hinges' angles from the
        nominal at step ``t`` (from upright, angles wrapped, after its end)."""
        if t < len(self.actions):
            return np.abs(state[..., :3] - self.states[t][:3]).max(axis=-1)
        angles = np.arctan2(np.sin(state[..., 1:3]), np.cos(state[..., 1:3]))
        return np.maximum(np.abs(state[..., 0]), np.abs(angles).max(axis=-1))

    def rollout(self, step, initial, horizon, noise=0.0, rng=None):
        """The states before each step ``(T, B, 6)``, the expert's actions there, and the states
        after, float64; ``noise`` (Gaussian, clipped to the box) perturbs the applied actions."""
        state, before, labels, after = initial, [], [], []
        for t in range(horizon):
            u = self(state, t)
            applied = u if noise == 0 else np.clip(u + noise * rng.standard_normal(u.shape), -1, 1)
            before.append(state)
            labels.append(u)
            state = step(state, applied)
            after.append(state)
        return np.stack(before), np.stack(labels), np.stack(after)


def host_step(env, xp):
    """``step(state, action)`` on float64 numpy arrays, through the backend (compiled where
    the backend's compiler keeps loops: jax and tensorflow)."""

    def kernel(state, action):
        return env.step(state, action, f=xp)[0]

    kernel = compiled(kernel, xp)

    def step(state, action):
        state = kernel(xp.asarray(state, dtype="float64"), xp.asarray(action, dtype="float64"))
        return np.asarray(ivy.to_numpy(state), np.float64)

    return step


def in_tube(expert, states, tube):
    """``(T, B)``: the states of each rollout ``(T, B, 6)`` up to its first exit from a tube of
    radius ``tube`` about the nominal. Only those are labelled: far from the nominal the
    expert's linear feedback saturates, and its actions there spoil the fit."""
    inside = np.stack([expert.deviation(s, t) < tube for t, s in enumerate(states)])
    return np.cumprod(inside, axis=0).astype(bool)


def solved(states, hold):
    """Per start: both poles upright and slow (every speed below 5 rad/s or m/s: a pole that
    turns whole turns between steps looks upright at every step) over the last ``hold``
    states, the cart within 1 m throughout."""
    last = states[-hold:]
    upright = (np.cos(last[..., 1]) > 0.95) & (np.cos(last[..., 1] + last[..., 2]) > 0.95)
    upright &= np.abs(last[..., 3:]).max(axis=-1) < 5.0
    return upright.all(axis=0) & (np.abs(states[..., 0]).max(axis=0) < 1.0)


def nominal_swing_ups(env, args):
    """``(s0, states, actions)`` float64 of the solved open-loop swing-ups."""
    if args.nominal:
        data = np.load(args.nominal)
        s0, states, actions = data["s0"], data["states"], data["actions"]
    else:
        from double_pendulum_swing_up import swing_up

        held, _ = swing_up(env, args.backend, args.restarts, 40, 10, 60)
        s0 = ivy.to_numpy(held.initial_state)
        actions = ivy.to_numpy(held.actions)
        states = ivy.to_numpy(ivy_gym.rollout(env, held.initial_state, held.actions).states)
        if args.save_nominal:
            np.savez(args.save_nominal, s0=s0, states=states, actions=actions)
    keep = solved(np.asarray(states, np.float64), 10)
    s0, states, actions = (np.asarray(a, np.float64) for a in (s0, states, actions))
    return s0[keep], states[:, keep], actions[:, keep]


def choose_expert(env, jacobians, step, nominal, horizon, hold, noise):
    """The expert, among the solved swing-ups', that holds the most of 128 fresh starts under
    the action noise of the imitation's first rollouts: the most robust teacher."""
    s0, states, actions = nominal
    starts = env.draw_initial(np.random.default_rng(0), 128)
    best, best_share = None, -1.0
    for b in range(len(s0)):
        expert = Expert(jacobians, np.concatenate([s0[b][None], states[:, b]]), actions[:, b])
        rng = np.random.default_rng(0)
        share = solved(expert.rollout(step, starts, horizon, noise, rng)[2], hold).mean()
        if share > best_share:
            best, best_share = expert, share
    return best, best_share


class Imitation:
    """Adam on the mean squared error between the policy's and the expert's actions, on
    minibatches of ``batch_size`` states drawn at random from all the states so far."""

    def __init__(self, policy, xp, lr=1e-3, batch_size=16384):
        self.policy, self.xp, self.opt = policy, xp, ivy.Adam(lr, f=xp)
        self.batch_size, self.rng = batch_size, np.random.default_rng(2)

        def update(v, opt_state, obs, actions):
            def loss_fn(v):
                return xp.mean((policy(obs, v=v) - actions) ** 2)

            loss, grads = ivy.execute_with_gradients(loss_fn, v)[:2]
            v, opt_state = self.opt.step(v, grads, opt_state)
            return v, opt_state, loss

        self.update = compiled(update, xp)

    def fit(self, v, env, states, actions, iterations):
        obs = ivy.to_numpy(env.observe(self.xp.asarray(states.reshape(-1, 6)), f=self.xp))
        obs, actions = np.asarray(obs, np.float32), actions.reshape(-1, 1).astype(np.float32)
        opt_state = self.opt.init(v)
        for _ in range(iterations):
            batch = self.rng.integers(0, len(obs), self.batch_size)
            v, opt_state, loss = self.update(
                v, opt_state, self.xp.asarray(obs[batch]), self.xp.asarray(actions[batch])
            )
        return v, float(ivy.to_numpy(loss))


def policy_rollouts(env, xp, policy, horizon):
    """``run(v, initial) -> (states, rewards)``: the policy's rollouts from ``initial`` as
    float64 and float32 numpy arrays, compiled on jax and tensorflow (eager, an evaluation
    took jax 3 minutes against 6 s compiled)."""

    def rollout(v, initial):
        traj = ivy_gym.rollout(env, initial, policy=policy, v=v, horizon=horizon, f=xp)
        return traj.states, traj.rewards

    rollout = compiled(rollout, xp)

    def run(v, initial):
        states, rewards = rollout(v, xp.asarray(initial, dtype="float32"))
        return np.asarray(ivy.to_numpy(states), np.float64), ivy.to_numpy(rewards)

    return run


def evaluation(env, xp, run, hold, seed=123):
    """``evaluate(v) -> (share, median return)``: the share of 256 fresh starts (the same ones
    at every call) that ``run``'s rollouts solve, and the median of their returns."""
    xp.seed(seed)
    initial = env.reset((256,), f=xp)

    def evaluate(v):
        states, rewards = run(v, initial)
        return float(solved(states, hold).mean()), float(np.median(rewards.sum(axis=0)))

    return evaluate


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backend", default="jax")
    parser.add_argument("--restarts", type=int, default=32)
    parser.add_argument("--nominal", default=None)
    parser.add_argument("--save-nominal", default=None)
    parser.add_argument("--save-policy", default=None)
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--fit-iterations", type=int, default=3000)
    parser.add_argument("--noise", type=float, default=0.2)
    parser.add_argument("--tube", type=float, default=0.3)
    parser.add_argument("--refine", type=int, default=0)
    parser.add_argument("--horizon", type=int, default=200)
    parser.add_argument("--hold", type=int, default=150)
    args = parser.parse_args()
    if args.backend == "jax":  # the expert's Jacobians are float64
        import jax

        jax.config.update("jax_enable_x64", True)
    xp = ivy.get_framework(f=args.backend)
    env = ivy_gym.InvertedDoublePendulum(swing_up=True)
    start = time.perf_counter()

    def report(stage, v):
        share, ret = evaluate(v)
        seconds = time.perf_counter() - start
        print(f"{stage}: {share:.0%} solved, median return {ret:.4g}, {seconds:.0f} s", flush=True)
        if args.save_policy:
            leaves = ivy.nest.nest_leaves(v)
            np.savez(args.save_policy, *[np.asarray(ivy.to_numpy(x)) for x in leaves])

    nominal = nominal_swing_ups(env, args)
    step = host_step(env, xp)
    jacobians = step_jacobians(env, xp)
    expert, share = choose_expert(
        env, jacobians, step, nominal, args.horizon, args.hold, args.noise
    )
    print(
        f"{args.backend}: {len(nominal[0])} solved swing-ups; the best expert holds {share:.0%} "
        f"of 128 fresh starts under action noise ({time.perf_counter() - start:.0f} s)",
        flush=True,
    )
    xp.seed(0)
    policy = ivy.MLP(
        env.observation_dim, (64, 64), env.action_dim, activation="tanh",
        output_activation="tanh", dtype="float32", f=xp,
    )  # fmt: skip
    imitation = Imitation(policy, xp)
    evaluate = evaluation(env, xp, policy_rollouts(env, xp, policy, args.horizon), args.hold)
    visit = policy_rollouts(env, xp, policy, args.horizon // 2)
    rng = np.random.default_rng(1)
    states, labels, _ = expert.rollout(
        step, env.draw_initial(rng, 256), args.horizon // 2, args.noise, rng
    )
    inside = in_tube(expert, states, args.tube)
    states, labels = states[inside], labels[inside]
    v, loss = imitation.fit(policy.v, env, states, labels, args.fit_iterations)
    report(f"imitation of the expert's noisy rollouts (loss {loss:.3g})", v)
    for r in range(args.rounds):
        initial = env.draw_initial(rng, 256)
        after = visit(v, initial)[0]
        visited = np.concatenate([initial[None], after[:-1]])
        inside = in_tube(expert, visited, args.tube)
        new_labels = np.stack([expert(s, t) for t, s in enumerate(visited)])
        states = np.concatenate([states, visited[inside]])
        labels = np.concatenate([labels, new_labels[inside]])
        v, loss = imitation.fit(v, env, states, labels, args.fit_iterations)
        report(f"DAgger round {r + 1} ({len(states)} states, loss {loss:.3g})", v)
    if args.refine:
        result = ivy_gym.optimise_policy(
            env, policy, args.horizon // 2, args.refine, v=v, lr=1e-4, window=25,
            max_grad_norm=1.0, seed=0, f=xp,
        )  # fmt: skip
        v = result.variables
        report(f"optimise_policy, {args.refine} iterations", v)


if __name__ == "__main__":
    main()
