"""Factors of safety and cost (thesis eq. 12–15), pure NumPy and vectorised.

Every function broadcasts over leading axes, so the same code scores one
physics step, a whole recording (T, ...) or a batch of sparse evaluations
(n, ...).
"""

from __future__ import annotations

import numpy as np

from critmoment.scenario import CostParams

__all__ = ["contact_fos", "contact_load", "fos_ratio", "motor_fos", "cost", "task_stage",
           "format_fos", "FOS_SHOWN"]

#: factors of safety above this are printed as "> FOS_SHOWN" (a nearly unloaded joint's
#: ratio, 1e6 or 1e20, says only that it is far from its limit)
FOS_SHOWN = 1000.0


def contact_fos(normal: np.ndarray, tangential: np.ndarray, mu: np.ndarray | float,
                cohesion: np.ndarray | float = 0.0) -> np.ndarray:
    """Contact factor of safety of one gripper's contacts with the object (eq. 12).

    FOS = Σ λn_i / Σ λn_i · λt_i / (c_i + μ_i λn_i), which is Σλn / Σ(λt/μ) when c = 0:
    the ratio of the friction the contacts could supply to what they supply. Below 1
    the grip slips.

    Args:
        normal: normal force of each contact [N], (..., K); 0 for empty slots.
        tangential: magnitude of the tangential force of each contact [N], (..., K).
        mu: friction coefficient of each contact, broadcastable to (..., K).
        cohesion: cohesion of each contact [N], broadcastable to (..., K).

    Returns:
        (...) factor of safety; +inf where there is no contact or no tangential demand.
    """
    return fos_ratio(*contact_load(normal, tangential, mu, cohesion))


def contact_load(normal: np.ndarray, tangential: np.ndarray, mu: np.ndarray | float,
                 cohesion: np.ndarray | float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """The two sums of eq. 12 over the contacts (last axis): (Σ λn_i, Σ λn_i · λt_i /
    (c_i + μ_i λn_i)), each (...). Sums over several grippers' contacts add up, and
    :func:`fos_ratio` of the totals is the FOS of all the contacts together."""
    normal = np.asarray(normal, dtype=np.float64)
    tangential = np.asarray(tangential, dtype=np.float64)
    capacity = cohesion + np.asarray(mu, dtype=np.float64) * normal
    with np.errstate(divide="ignore", invalid="ignore"):
        use = np.where(capacity > 0, normal * tangential / capacity, 0.0)
    return normal.sum(axis=-1), use.sum(axis=-1)


def fos_ratio(total: np.ndarray, demand: np.ndarray) -> np.ndarray:
    """The contact FOS Σλn / demand from :func:`contact_load`'s sums; +inf without demand."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(demand > 0, total / demand, np.inf)


def motor_fos(force: np.ndarray, limit: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Motor factor of safety over actuators (eq. 13–14): min_i τmax_i / |τ_i|.

    Args:
        force: actuator forces [N·m or N], (..., n).
        limit: force limits [N·m or N], (n,).

    Returns:
        fos (...) (+inf when every force is 0) and the index (...) of the limiting actuator.
    """
    force = np.abs(np.asarray(force, dtype=np.float64))
    limit = np.asarray(limit, dtype=np.float64)
    with np.errstate(divide="ignore", over="ignore"):  # a subnormal force: inf, as 0
        ratio = np.where(force > 0, limit / force, np.inf)
    idx = np.argmin(ratio, axis=-1)
    return np.take_along_axis(ratio, idx[..., None], axis=-1)[..., 0], idx


def cost_terms(fos_contact: np.ndarray, fos_motor: np.ndarray, params: CostParams
               ) -> tuple[np.ndarray, np.ndarray]:
    """The cost's two terms, A·exp(−α(FOS_c − 1)) and B·exp(−β(FOS_m − 1)) (eq. 15), each
    (...); +inf factors of safety give 0. Overflow gives +inf without a warning."""
    with np.errstate(over="ignore"):
        c = params.A * np.exp(-params.alpha * (np.asarray(fos_contact) - 1.0))
        m = params.B * np.exp(-params.beta * (np.asarray(fos_motor) - 1.0))
    return c, m


def cost(fos_contact: np.ndarray, fos_motor: np.ndarray, params: CostParams) -> np.ndarray:
    """Cost C = A·exp(−α(FOS_c − 1)) + B·exp(−β(FOS_m − 1)) (eq. 15).

    Args:
        fos_contact: contact FOS, (...); use the minimum over grippers. +inf gives 0.
        fos_motor: motor FOS, (...).
        params: the cost constants.

    Returns:
        (...) cost; the motion fails where it exceeds ``params.threshold``.
    """
    c, m = cost_terms(fos_contact, fos_motor, params)
    return c + m


def sustained_fos(fos: np.ndarray, steps: int) -> np.ndarray:
    """The FOS held over ``steps`` consecutive steps from each step on, (T,) from (T,): the
    highest value of each window (a window that runs past the end is shorter). An
    excursion shorter than ``steps`` (contact chatter) does not lower it, as the sparse
    decision counts a contact-FOS excursion only when it persists (``[sparse]
    persistence``)."""
    fos = np.asarray(fos, dtype=float)
    steps = max(1, int(steps))
    if fos.size == 0 or steps == 1:
        return fos.copy()
    padded = np.concatenate([fos, np.full(steps - 1, np.nan)])
    windows = np.lib.stride_tricks.sliding_window_view(padded, steps)
    return np.nanmax(windows, axis=-1)


def task_stage(touch_picker: np.ndarray, touch_receiver: np.ndarray,
               touch_support: np.ndarray) -> np.ndarray:
    """ACT's transfer-cube reward 0..4 from contact flags (each (...) bool).

    1: the picker touches the object; 2: and the object is off the support;
    3: the receiver touches it; 4: and it is off the support. A later condition
    overrides an earlier one, as in ACT.
    """
    touch_picker = np.asarray(touch_picker, dtype=bool)
    touch_receiver = np.asarray(touch_receiver, dtype=bool)
    off = ~np.asarray(touch_support, dtype=bool)
    stage = np.zeros(np.broadcast(touch_picker, touch_receiver, off).shape, dtype=np.int8)
    stage[touch_picker] = 1
    stage[touch_picker & off] = 2
    stage[touch_receiver] = 3
    stage[touch_receiver & off] = 4
    return stage


def format_fos(value: float | None, spec: str = ".3g") -> str:
    """A factor of safety for people: formatted with ``spec``, "> 1000" above
    :data:`FOS_SHOWN`, "inf" where unloaded, "n/a" for None or NaN."""
    if value is None or np.isnan(value):
        return "n/a"
    if np.isinf(value):
        return "inf" if value > 0 else "-inf"
    if value > FOS_SHOWN:
        return f"> {FOS_SHOWN:g}"
    return format(value, spec)
