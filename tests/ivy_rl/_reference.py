"""Hand-written float64 references of returns, one episode at a time, from the definitions."""

from __future__ import annotations

import numpy as np


def episodes_of(resets, length):
    """(start, end) index pairs of the episodes (pieces) of one worker's segment."""
    pieces, start = [], 0
    for t in range(length):
        if resets[t]:
            pieces.append((start, t + 1))
            start = t + 1
    if start < length:
        pieces.append((start, length))
    return pieces


def n_step(rewards, next_values, resets, terminations, discount, n):
    """G^(n)_t for one worker: sum of up to n discounted rewards within the episode piece, then
    the bootstrap V(s'_{k}) at the last transition k used unless it is a termination."""
    T = len(rewards)
    out = np.zeros(T)
    for t in range(T):
        total, k = 0.0, t
        for j in range(n):
            k = t + j
            total += discount**j * rewards[k]
            if resets[k] or k == T - 1 or j == n - 1:
                break
        used = k - t + 1
        if not terminations[k]:
            total += discount**used * next_values[k]
        out[t] = total
    return out


def lambda_return(rewards, next_values, resets, terminations, discount, lam):
    """G^λ_t = (1-λ) Σ_{n=1}^{N-1} λ^{n-1} G^(n)_t + λ^{N-1} G^(N)_t, N the steps left in the
    episode piece (G^(n) is constant for n >= N)."""
    T = len(rewards)
    out = np.zeros(T)
    for start, end in episodes_of(resets, T):
        for t in range(start, end):
            N = end - t
            total = 0.0
            for n in range(1, N):
                total += (
                    (1 - lam)
                    * lam ** (n - 1)
                    * n_step(rewards, next_values, resets, terminations, discount, n)[t]
                )
            total += (
                lam ** (N - 1) * n_step(rewards, next_values, resets, terminations, discount, N)[t]
            )
            out[t] = total
    return out


def gae(rewards, values, next_values, resets, terminations, discount, lam):
    """A_t = Σ_k (γλ)^k δ_{t+k} within the episode piece."""
    T = len(rewards)
    deltas = [
        rewards[t] + discount * (0.0 if terminations[t] else next_values[t]) - values[t]
        for t in range(T)
    ]
    out = np.zeros(T)
    for start, end in episodes_of(resets, T):
        for t in range(start, end):
            out[t] = sum((discount * lam) ** (k - t) * deltas[k] for k in range(t, end))
    return out
