"""Independent references for the ivy_gym tests.

- Gymnasium's own environments run the faithful tasks (CartPole-v1, Pendulum-v1,
  MountainCarContinuous-v0) step by step from a given state.
- The original ivy_gym's tasks and the ``smooth=True`` variants are written here once more in
  plain numpy float64, from their equations (one state at a time, loops over the batch), so that
  no ivy code is involved.
"""

from __future__ import annotations

import math

import gymnasium
import numpy as np

FAITHFUL = {
    "CartPole": "CartPole-v1",
    "Pendulum": "Pendulum-v1",
    "MountainCarContinuous": "MountainCarContinuous-v0",
}


def gymnasium_trajectory(
    task: str, state: np.ndarray, policy, steps: int, action_dtype=np.float64, **params
):
    """Step Gymnasium's own ``task`` from ``state`` for ``steps`` steps or until it terminates,
    with the actions ``policy(t, state)`` in ``action_dtype`` (the core's continuous action;
    CartPole's is sent to Gymnasium as 1 if positive else 0).

    MountainCarContinuous's state is set as float32 where its values are float32 numbers (as
    Gymnasium stores it after a step), else as float64 (as Gymnasium's reset draws it).

    Returns (states (n, D), rewards (n,), terminated (n,), actions (n, A)); the states and
    rewards float64, the actions in ``action_dtype``.
    """
    env = gymnasium.make(FAITHFUL[task]).unwrapped
    env.reset(seed=0)
    for name, value in params.items():
        setattr(env, name, value)
    if task == "CartPole":  # Gymnasium derives these in __init__
        env.total_mass = env.masspole + env.masscart
        env.polemass_length = env.masspole * env.length
    float32_state = np.array_equal(state.astype(np.float32), state)
    if task == "MountainCarContinuous" and float32_state:
        env.state = state.astype(np.float32)
    else:
        env.state = state.copy()
    states, rewards, terminated, actions = [], [], [], []
    for t in range(steps):
        a = np.asarray(policy(t, np.asarray(env.state, np.float64)), action_dtype)
        if task == "CartPole":  # Gymnasium pushes with +-force_mag: the core's action +-1
            a = np.where(a > 0, 1.0, -1.0)
        _, reward, term, _, _ = env.step(int(a[0] > 0) if task == "CartPole" else a)
        states.append(np.asarray(env.state, np.float64))
        rewards.append(float(reward))
        terminated.append(bool(term))
        actions.append(a)
        if term:
            break
    return np.array(states), np.array(rewards), np.array(terminated), np.array(actions)


# ----------------------------------------------------------------------------------------------
# One step of each task for one state, in numpy float64: (new_state, obs, reward, terminated)
# ----------------------------------------------------------------------------------------------


def cartpole_swing_up(s, a, g=9.8, mc=1.0, mp=0.1, half=0.5, force_mag=10.0, tau=0.02):
    x, xd, th, thd = s
    force = force_mag * a[0]
    c, sn = math.cos(th), math.sin(th)
    temp = (force + mp * half * thd**2 * sn) / (mc + mp)
    thacc = (g * sn - c * temp) / (half * (4 / 3 - mp * c**2 / (mc + mp)))
    xacc = temp - mp * half * thacc * c / (mc + mp)
    xd = xd + tau * xacc
    x = x + tau * xd
    thd = thd + tau * thacc
    th = th + tau * thd
    reward = math.exp(-(x**2)) * (math.cos(th) + 1) / 2
    obs = np.array([x, xd, math.cos(th), math.sin(th), thd])
    return np.array([x, xd, th, thd]), obs, reward, False


def pendulum_smooth(s, a, g=9.8, m=1.0, length=1.0, dt=0.05, torque_scale=1.0):
    th, thd = s
    thd = thd + dt * (
        3 * g / (2 * length) * math.sin(th) + 3 / (m * length**2) * torque_scale * a[0]
    )
    th = th + dt * thd
    obs = np.array([math.cos(th), math.sin(th), thd])
    return np.array([th, thd]), obs, (math.cos(th) + 1) / 2, False


def pendulum_gymnasium_no_speed_clip(s, a, g=10.0, m=1.0, length=1.0, dt=0.05, max_torque=2.0):
    th, thd = s
    u = min(max(a[0], -max_torque), max_torque)
    wrapped = (th + math.pi) % (2 * math.pi) - math.pi
    cost = wrapped**2 + 0.1 * thd**2 + 0.001 * u**2
    thd = thd + (3 * g / (2 * length) * math.sin(th) + 3 / (m * length**2) * u) * dt
    th = th + thd * dt
    return np.array([th, thd]), np.array([math.cos(th), math.sin(th), thd]), -cost, False


def mountain_car_no_walls(s, a, power=0.0015, goal=0.45):
    position, velocity = s
    force = min(max(a[0], -1.0), 1.0)
    velocity = velocity + force * power - 0.0025 * math.cos(3 * position)
    position = position + velocity
    done = position >= goal and velocity >= 0.0
    reward = (100.0 if done else 0.0) - 0.1 * a[0] ** 2
    state = np.array([position, velocity])
    return state, state, reward, done


def mountain_car_shaped(s, a, g=9.8, dt=0.02, torque_scale=3.0, goal=0.45):
    x, v = s
    v = v + dt * (torque_scale * a[0] - g * math.cos(3 * x))
    x = x + dt * v
    state = np.array([x, v])
    return state, state, math.exp(-5 * (x - goal) ** 2), False


def reacher(s, a, dt=0.05, torque_scale=1.0):
    n = len(a)
    angles, vels, goal = s[:n], s[n : 2 * n], s[2 * n :]
    vels = vels + dt * torque_scale * np.asarray(a)
    angles = angles + dt * vels
    tip = np.array([np.cos(angles).sum(), np.sin(angles).sum()])
    reward = math.exp(-np.sum((tip - goal) ** 2))
    obs = np.concatenate([np.cos(angles), np.sin(angles), vels, goal])
    return np.concatenate([angles, vels, goal]), obs, reward, False


def swimmer(s, a, dt=0.05, goal_sharpness=0.5, urchin_sharpness=30.0):
    u = len(s) - 6
    urchins, xy, vel, goal = s[:u].reshape(-1, 2), s[u : u + 2], s[u + 2 : u + 4], s[u + 4 :]
    vel = vel + dt * np.asarray(a)
    xy = xy + dt * vel
    reward = math.exp(-goal_sharpness * np.sum((xy - goal) ** 2))
    for c in urchins:
        reward *= 1 - math.exp(-urchin_sharpness * np.sum((xy - c) ** 2))
    state = np.concatenate([urchins.ravel(), xy, vel, goal])
    return state, state, reward, False


def reference_rollout(step, states: np.ndarray, actions: np.ndarray, **params):
    """Run ``step`` from each of ``states`` ``(B, D)`` with ``actions`` ``(T, B, A)``.
    Returns (states (T, B, D), observations (T, B, O), rewards (T, B))."""
    out_s, out_o, out_r = [], [], []
    current = [np.asarray(s, np.float64) for s in states]
    for a_t in actions:
        row_s, row_o, row_r = [], [], []
        for b, a in enumerate(a_t):
            current[b], obs, reward, _ = step(current[b], a, **params)
            row_s.append(current[b])
            row_o.append(obs)
            row_r.append(reward)
        out_s.append(row_s)
        out_o.append(row_o)
        out_r.append(row_r)
    return np.array(out_s), np.array(out_o), np.array(out_r)
