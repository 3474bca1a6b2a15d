"""ACT-like execution of a nominal action sequence.
A chunk planned at step j from a slightly perturbed state = the nominal actions time-shifted by
an integer s_j in [-shift, shift] plus a constant offset d_j ~ N(0, sigma) on the arm joints
(gripper channels only time-shifted). Without ensembling the chunk at j = 0, C, 2C, ... is
executed open-loop (jumps at boundaries); with ACT's temporal ensembling a chunk is queried every
step and the executed action is sum_i w_i chunk_{t-i}(t) / sum w, w = exp(-k * age order), the
oldest chunk weighted most (ACT's exp(-0.01 * i) over the chunks oldest first)."""
import numpy as np


def _chunk(nom, j, C, arm, grip, s, d):
    T = len(nom)
    idx = np.clip(np.arange(j, min(j + C, T)) + s, 0, T - 1)
    c = nom[idx].copy()
    c[:, arm] += d
    return c


def chunked(nom, C, arm, grip, sigma, shift, seed):
    rng = np.random.default_rng(seed)
    out = nom.copy()
    for j in range(0, len(nom), C):
        s = int(rng.integers(-shift, shift + 1)) if j > 0 else 0
        d = rng.normal(0, sigma, len(arm)) if j > 0 else np.zeros(len(arm))
        c = _chunk(nom, j, C, arm, grip, s, d)
        out[j:j + len(c)] = c
    out[0] = nom[0]
    return out


def ensembled(nom, C, arm, grip, sigma, shift, seed, k=0.01):
    rng = np.random.default_rng(seed)
    T = len(nom)
    num = np.zeros_like(nom); den = np.zeros(T)
    chunks = []
    for j in range(T):
        s = int(rng.integers(-shift, shift + 1)) if j > 0 else 0
        d = rng.normal(0, sigma, len(arm)) if j > 0 else np.zeros(len(arm))
        chunks.append((j, _chunk(nom, j, C, arm, grip, s, d)))
    out = np.empty_like(nom)
    for t in range(T):
        live = [(j, c) for j, c in chunks if j <= t < j + len(c)]   # oldest first
        w = np.exp(-k * np.arange(len(live)))
        out[t] = sum(wi * c[t - j] for wi, (j, c) in zip(w, live)) / w.sum()
    out[0] = nom[0]
    return out


def ar_noise(nom, arm, sigma, rho, seed):
    """AR(1) noise with stationary std sigma and lag-1 correlation rho on the arm channels."""
    rng = np.random.default_rng(seed)
    T = len(nom)
    e = np.zeros((T, len(arm)))
    e[0] = rng.normal(0, sigma, len(arm))
    for t in range(1, T):
        e[t] = rho * e[t - 1] + np.sqrt(1 - rho ** 2) * rng.normal(0, sigma, len(arm))
    out = nom.copy(); out[:, arm] += e; out[0] = nom[0]
    return out


def insert_bump(nom, at, D, ch, amp, ramp):
    """insert D steps after step `at` that hold nom[at], with a smooth bump of `amp` [rad] on
    channel(s) ch: min-jerk up over `ramp` steps, hold, min-jerk back over `ramp` steps."""
    hold = np.repeat(nom[at:at + 1], D, axis=0)
    s = np.arange(D, dtype=float)
    up = np.clip(s / ramp, 0, 1); dn = np.clip((D - 1 - s) / ramp, 0, 1)
    mj = lambda x: x ** 3 * (10 - 15 * x + 6 * x ** 2)
    prof = np.minimum(mj(up), mj(dn))
    for c, a in zip(np.atleast_1d(ch), np.atleast_1d(amp)):
        hold[:, c] += a * prof
    return np.concatenate([nom[:at + 1], hold, nom[at + 1:]])
