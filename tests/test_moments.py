"""Tests of critmoment.moments (fast: synthetic recordings only, no MuJoCo)."""

from __future__ import annotations

import dataclasses
import math
import tracemalloc
import types

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from critmoment.exceptions import CritmomentError, ParameterError, TrajectoryError
from critmoment.moments import (
    Moment,
    MomentDetector,
    MomentLabel,
    debounce,
    detect_change_points,
    detect_contact_events,
    find_moments,
    merge_moments,
    plot_moments,
    rank_moments,
)

DT = 0.002  # 500 Hz
TOL = 10  # steps: tolerance on recovered change points


@dataclasses.dataclass(frozen=True)
class FakeRecording:
    """Only the attributes the moments module relies on."""

    dt: float
    time: np.ndarray
    object_acc: np.ndarray
    actuator_norm: np.ndarray
    fos_contact: np.ndarray
    fos_motor: np.ndarray
    cost: np.ndarray
    contact_support: np.ndarray
    contact_gripper: np.ndarray
    gripper_names: tuple[str, ...]
    stage: np.ndarray


def make_recording(
    n_steps: int,
    *,
    object_acc: np.ndarray | None = None,
    actuator_norm: np.ndarray | None = None,
    support: np.ndarray | None = None,
    grip: np.ndarray | None = None,
    fos_contact: np.ndarray | None = None,
    dt: float = DT,
) -> FakeRecording:
    """A recording with neutral signals unless given."""
    support = np.ones(n_steps, bool) if support is None else support
    grip = np.zeros((n_steps, 2), bool) if grip is None else grip
    if fos_contact is None:
        fos_contact = np.where(grip, 3.0, np.inf)
    return FakeRecording(
        dt=dt,
        time=np.arange(n_steps) * dt,
        object_acc=np.zeros((n_steps, 3)) if object_acc is None else object_acc,
        actuator_norm=np.zeros((n_steps, 4)) if actuator_norm is None else actuator_norm,
        fos_contact=fos_contact,
        fos_motor=np.full(n_steps, 5.0),
        cost=np.zeros(n_steps),
        contact_support=support,
        contact_gripper=grip,
        gripper_names=("left", "right"),
        stage=np.zeros(n_steps, dtype=int),
    )


def piecewise_signal(seed: int, *, n_steps: int = 4000, dim: int = 5, n_cps: int = 6, noise: float = 0.5):
    """Piecewise-constant multichannel signal with Gaussian noise.

    At each change point a random non-empty subset of channels jumps by
    +-U(1.5, 3); segments are at least 150 samples long.
    """
    rng = np.random.default_rng(seed)
    while True:
        cps = np.sort(rng.choice(np.arange(150, n_steps - 150), n_cps, replace=False))
        if np.all(np.diff(cps) >= 150):
            break
    x = np.zeros((n_steps, dim))
    level = np.zeros(dim)
    bounds = np.r_[0, cps, n_steps]
    for i in range(len(bounds) - 1):
        if i > 0:
            ch = rng.choice(dim, rng.integers(1, dim + 1), replace=False)
            level = level.copy()
            level[ch] += rng.choice([-1.0, 1.0], len(ch)) * rng.uniform(1.5, 3.0, len(ch))
        x[bounds[i] : bounds[i + 1]] = level
    return x + noise * rng.standard_normal((n_steps, dim)), cps


def assert_recovered(found: np.ndarray, truth: np.ndarray, *, max_extra: int = 2) -> None:
    found = np.asarray(found)
    assert found.size, "no change point found"
    errors = [int(np.min(np.abs(found - c))) for c in truth]
    assert max(errors) <= TOL, f"true {truth.tolist()} found {found.tolist()} errors {errors}"
    assert found.size <= truth.size + max_extra, f"too many extras: {found.tolist()}"


def pick_and_handover(n_steps: int = 4000, *, chatter: bool = False) -> FakeRecording:
    """Left grasps at 500, lift-off at 800, right grasps at 2000, hand-over
    (left releases) at 2300, place at 3300, right releases at 3500."""
    rng = np.random.default_rng(7)
    support = np.ones(n_steps, bool)
    support[800:3300] = False
    grip = np.zeros((n_steps, 2), bool)
    grip[500:2300, 0] = True
    grip[2000:3500, 1] = True
    if chatter:  # 3-step contact flickers around the lift-off and during holding
        support[810:813] = True
        grip[1500:1503, 0] = False
    fos = np.where(grip, 3.0, np.inf)
    fos[800:2000, 0] = 1.4  # carrying alone loads the left contact
    fos[2300:3300, 1] = 1.6
    acc = 0.05 * rng.standard_normal((n_steps, 3))
    acc[800:820, 2] += 4.0  # lift-off jerk
    acc[3300:3315, 2] -= 6.0  # touchdown
    act = 0.02 * rng.standard_normal((n_steps, 4))
    act[500:2300, 0:2] += 0.3
    act[800:2300, 0:2] += 0.4  # left carries the weight
    act[2000:3500, 2:4] += 0.3
    act[2300:3300, 2:4] += 0.4
    return make_recording(n_steps, object_acc=acc, actuator_norm=act, support=support, grip=grip, fos_contact=fos)


# ---------------------------------------------------------------- change points


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4, 5])
def test_change_points_recovered_on_piecewise_constant_signals(seed):
    x, truth = piecewise_signal(seed)
    result = detect_change_points(x, min_size=10)
    assert result.decimation == 2 and result.n_samples == 2000
    assert_recovered(result.steps, truth)
    assert result.magnitudes.shape == result.steps.shape
    assert result.deltas.shape == (result.steps.size, x.shape[1])


@pytest.mark.parametrize("seed", [10, 11, 12])
def test_detector_recovers_change_points_from_recording(seed):
    x, truth = piecewise_signal(seed)
    rec = make_recording(x.shape[0], object_acc=x[:, :3], actuator_norm=x[:, 3:])
    det = MomentDetector(acc_components=True, max_candidates=None).fit(rec)
    assert det.events_ == []  # flags never change
    assert_recovered(det.change_points_.steps, truth)
    steps = [m.step for m in det.candidates_]
    assert all(m.label is MomentLabel.CHANGE_POINT for m in det.candidates_)
    assert_recovered(np.array(steps), truth)


@pytest.mark.parametrize("dim", [1, 3, 17])
def test_white_noise_gives_no_change_point(dim):
    for seed in range(3):
        x = np.random.default_rng(seed).standard_normal((4000, dim))
        assert detect_change_points(x).steps.size == 0


def test_penalty_scales_with_length_and_dimension():
    x = np.random.default_rng(0).standard_normal((1000, 4))
    r = detect_change_points(x, penalty_scale=1.5)
    assert r.penalty == pytest.approx(1.5 * (4 + 1) * math.log(1000))
    x[:, 2] = 3.0  # a constant channel adds no parameter and is ignored
    r = detect_change_points(x, penalty_scale=1.5)
    assert r.penalty == pytest.approx(1.5 * (3 + 1) * math.log(1000))
    assert r.scale[2] == 0


def test_constant_and_short_signals():
    assert detect_change_points(np.ones((500, 3))).steps.size == 0
    assert detect_change_points(np.arange(3.0)).steps.size == 0
    noiseless = np.r_[np.zeros(300), np.ones(300)]  # MAD of differences is 0: guarded
    np.testing.assert_array_equal(detect_change_points(noiseless).steps, [300])


# ---------------------------------------------------------------- contact events


def test_debounce_removes_flickers_without_delay():
    x = np.zeros(100, bool)
    x[20:60] = True
    x[30:33] = False  # 3-step flicker inside contact
    x[80:82] = True  # 2-step flicker outside
    out = debounce(x, 5)
    expected = np.zeros(100, bool)
    expected[20:60] = True
    np.testing.assert_array_equal(out, expected)
    # chatter at the transition: state changes at the start of the lasting run
    y = np.zeros(50, bool)
    y[10:12] = True
    y[13:15] = True
    y[16:] = True
    np.testing.assert_array_equal(np.flatnonzero(np.diff(debounce(y, 5).astype(int))) + 1, [16])
    np.testing.assert_array_equal(debounce(x, 1), x)


def test_lift_off_and_hand_over_steps_are_exact():
    events = detect_contact_events(pick_and_handover())
    got = [(m.step, m.label, m.gripper) for m in events]
    assert got == [
        (500, MomentLabel.GRASP, "left"),
        (800, MomentLabel.LIFT_OFF, None),
        (2000, MomentLabel.GRASP, "right"),
        (2300, MomentLabel.HAND_OVER, "left"),
        (3300, MomentLabel.PLACE, None),
        (3500, MomentLabel.RELEASE, "right"),
    ]
    lift = events[1]
    assert lift.time == pytest.approx(800 * DT)
    assert "object leaves its support (contact lost)" in lift.reason and "'left'" in lift.reason
    assert "'right' holds it (hand-over)" in events[3].reason
    assert events[2].reason == "gripper 'right' touches object while 'left' holds it"


def test_a_brush_and_chatter_are_not_called_a_grasp_and_a_release():
    """A finger brushing the object on the way out, and a grip that loses contact for a
    few tens of ms while closing, were reported as "touches object" and "releases object
    onto the table". The events keep their steps and labels (the audit's moments do not
    move); their reasons say what happened."""
    rec = pick_and_handover()
    rec.contact_gripper[440:470, 0] = True  # the left fingers close: 60 ms, a 60 ms gap, hold
    rec.contact_gripper[3700:3720, 1] = True  # the right fingers brush it leaving: 40 ms
    events = detect_contact_events(rec)
    reasons = {(m.step, m.label): m.reason for m in events}
    assert reasons[(440, MomentLabel.GRASP)] == (
        "gripper 'left' touches object for 60 ms only (a brush, not a hold)")
    assert reasons[(470, MomentLabel.RELEASE)] == (
        "gripper 'left' loses contact with the object for 60 ms, then touches it again "
        "(contact chatter, not a release)")
    assert reasons[(500, MomentLabel.GRASP)] == "gripper 'left' touches object"
    assert reasons[(3700, MomentLabel.GRASP)] == (
        "gripper 'right' touches object for 40 ms only (a brush, not a hold)")
    assert reasons[(3720, MomentLabel.RELEASE)] == "gripper 'right' releases object onto the table"
    assert reasons[(3500, MomentLabel.RELEASE)] == "gripper 'right' releases object onto the table"


def test_three_step_flicker_is_ignored():
    clean = detect_contact_events(pick_and_handover())
    chattering = detect_contact_events(pick_and_handover(chatter=True), debounce_time=0.01)
    assert [(m.step, m.label) for m in chattering] == [(m.step, m.label) for m in clean]
    # without debouncing, the flickers show up as extra events
    assert len(detect_contact_events(pick_and_handover(chatter=True), debounce_time=0.0)) == len(clean) + 4


def test_release_in_air_then_drop():
    n = 1000
    support = np.ones(n, bool)
    support[300:700] = False
    grip = np.zeros((n, 2), bool)
    grip[100:500, 1] = True
    events = detect_contact_events(make_recording(n, support=support, grip=grip))
    assert [(m.step, m.label, m.gripper) for m in events] == [
        (100, MomentLabel.GRASP, "right"),
        (300, MomentLabel.LIFT_OFF, None),
        (500, MomentLabel.RELEASE, "right"),
        (700, MomentLabel.DROP, None),
    ]
    assert "in the air" in events[2].reason
    assert events[2].tag == "release-right"


# ---------------------------------------------------------------- merging


def _moment(step, label=MomentLabel.CHANGE_POINT, magnitude=math.nan, reason="r", gripper=None):
    return Moment(step, step * DT, label, reason, gripper=gripper, magnitude=magnitude, reasons=(reason,))


def test_merge_prefers_contact_events_within_window():
    moments = [
        _moment(990, magnitude=2.0, reason="change point in actuator forces"),
        _moment(1000, MomentLabel.LIFT_OFF, reason="object leaves its support (contact lost)"),
        _moment(1010, magnitude=5.0, reason="change point in object acceleration"),
        _moment(1008, MomentLabel.GRASP, reason="gripper 'left' touches object", gripper="left"),
        _moment(3000, magnitude=1.0, reason="a"),
        _moment(3012, magnitude=4.0, reason="b"),  # 24 ms after 3000: merged, bigger wins
        _moment(3100, magnitude=9.0, reason="c"),  # 200 ms later: separate
    ]
    merged = merge_moments(moments, window=0.04, dt=DT)
    assert [(m.step, m.label) for m in merged] == [
        (1000, MomentLabel.LIFT_OFF),
        (3012, MomentLabel.CHANGE_POINT),
        (3100, MomentLabel.CHANGE_POINT),
    ]
    lift = merged[0]
    assert lift.reasons == (
        "object leaves its support (contact lost)",
        "gripper 'left' touches object",
        "change point in actuator forces",
        "change point in object acceleration",
    )
    assert lift.reason == "; ".join(lift.reasons)
    assert lift.magnitude == 5.0 and lift.gripper is None
    assert merged[1].reasons == ("b", "a") and merged[1].magnitude == 4.0
    # a zero window only merges identical steps
    assert len(merge_moments(moments, window=0.0, dt=DT)) == len(moments)


def test_detector_merges_change_points_into_contact_events():
    det = MomentDetector().fit(pick_and_handover())
    labels = {m.label for m in det.candidates_}
    assert {MomentLabel.LIFT_OFF, MomentLabel.HAND_OVER, MomentLabel.PLACE} <= labels
    steps = np.array([m.step for m in det.candidates_])
    assert np.all(np.diff(steps) > 0)
    lift = next(m for m in det.candidates_ if m.label is MomentLabel.LIFT_OFF)
    assert lift.step == 800
    assert any(r.startswith("change point in") for r in lift.reasons)  # the jerk was merged in
    assert not math.isnan(lift.magnitude)


def test_max_candidates_keeps_the_heuristically_best():
    det = MomentDetector(max_candidates=3).fit(pick_and_handover())
    assert [(m.step, m.label) for m in det.candidates_] == [
        (800, MomentLabel.LIFT_OFF),
        (2300, MomentLabel.HAND_OVER),
        (3300, MomentLabel.PLACE),
    ]


# ---------------------------------------------------------------- ranking


def test_ranking_with_fake_sensitivity():
    det = MomentDetector(max_moments=3).fit(pick_and_handover())
    calls = []

    def sensitivity(steps):
        calls.append(steps.copy())
        return np.where(steps >= 2000, 0.5 + steps / 4000.0, 0.1)  # later is worse

    ranked = det.predict(sensitivity=sensitivity, threshold=0.9)
    assert len(calls) == 1 and calls[0].dtype == np.int64
    np.testing.assert_array_equal(calls[0], np.sort(calls[0]))
    assert len(ranked) == 3
    scores = [m.score for m in ranked]
    assert scores == sorted(scores, reverse=True)
    assert [m.step for m in ranked] == sorted((s for s in calls[0] if s >= 2000), reverse=True)[:3]
    assert all(m.critical == (m.score > 0.9) for m in ranked)
    assert any(m.critical for m in ranked)


def test_no_moment_above_threshold_for_flat_sensitivity():
    det = MomentDetector().fit(pick_and_handover())
    ranked = det.predict(sensitivity=lambda steps: np.full(steps.shape, 0.2), threshold=0.9)
    assert ranked and not any(m.critical for m in ranked)
    assert all(m.score == 0.2 for m in ranked)
    steps = [m.step for m in ranked]
    assert steps == sorted(steps)  # ties broken by step


def test_rank_moments_ties_and_limits():
    moments = [_moment(s) for s in (50, 10, 30, 20)]
    ranked = rank_moments(moments, [1.0, 2.0, 2.0, np.inf], threshold=1.5, max_moments=3)
    assert [(m.step, m.score, m.critical) for m in ranked] == [(20, np.inf, True), (10, 2.0, True), (30, 2.0, True)]
    with pytest.raises(CritmomentError, match="expected 4 scores"):
        rank_moments(moments, [1.0, 2.0])
    with pytest.raises(CritmomentError, match="NaN at steps \\[10\\]"):
        rank_moments(moments, [1.0, np.nan, 0.0, 0.0])


def test_heuristic_ranking_puts_contact_events_first():
    det = MomentDetector(max_moments=4).fit(pick_and_handover())
    ranked = det.predict()
    assert [m.label for m in ranked[:2]] == [MomentLabel.LIFT_OFF, MomentLabel.HAND_OVER]
    assert all(math.isnan(m.score) and not m.critical for m in ranked)
    moments = [_moment(5, magnitude=1.0), _moment(9, magnitude=3.0), _moment(7, MomentLabel.GRASP, gripper="left")]
    assert [m.step for m in rank_moments(moments)] == [7, 9, 5]


def test_find_moments_end_to_end():
    moments = find_moments(pick_and_handover(chatter=True), sensitivity=lambda s: s / 4000.0, threshold=0.5)
    assert len(moments) <= 8
    tags = {m.tag for m in moments}
    assert "lift-off" in tags and "hand-over-left" in tags
    assert all(m.critical == (m.score > 0.5) for m in moments)


# ---------------------------------------------------------------- long recordings


def test_long_recording_has_bounded_memory():
    n = 100_000  # 200 s at 500 Hz
    rng = np.random.default_rng(3)
    acc = 0.05 * rng.standard_normal((n, 3))
    act = 0.02 * rng.standard_normal((n, 14))
    act[37_123:, 0:7] += 0.5  # a step in the left arm forces
    support = np.ones(n, bool)
    support[60_000:90_000] = False
    grip = np.zeros((n, 2), bool)
    grip[55_000:95_000, 0] = True
    rec = make_recording(n, object_acc=acc, actuator_norm=act, support=support, grip=grip)

    tracemalloc.start()
    det = MomentDetector().fit(rec)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()

    assert det.n_samples_ == 2000 and det.decimation_ == 50  # what ruptures saw
    assert det.change_points_.n_samples <= det.max_samples
    assert peak < 64 * 2**20  # raw full-rate features: 100k x 19 floats = 15 MB
    steps = det.change_points_.steps
    assert np.min(np.abs(steps - 37_123)) <= 2  # refined to physics-step resolution
    assert np.min(np.abs(steps - 55_000)) <= 2  # contact load appears (grasp)
    lift = next(m for m in det.candidates_ if m.label is MomentLabel.LIFT_OFF)
    assert lift.step == 60_000


# ---------------------------------------------------------------- errors


@pytest.mark.parametrize(
    ("options", "match"),
    [
        ({"window": -0.01}, "window must be finite and >= 0"),
        ({"debounce": float("nan")}, "debounce must be finite"),
        ({"min_separation": "20ms"}, "min_separation must be a number of seconds"),
        ({"penalty_scale": 0}, "penalty_scale must be finite and > 0"),
        ({"noise_floor": -1.0}, "noise_floor must be finite and >= 0"),
        ({"max_samples": 3}, "max_samples must be an integer >= 16"),
        ({"max_samples": 2000.0}, "max_samples must be an integer"),
        ({"max_moments": 0}, "max_moments must be an integer >= 1"),
        ({"max_candidates": 0}, "max_candidates must be an integer >= 1"),
        ({"acc_components": "yes"}, "acc_components must be True or False"),
    ],
)
def test_bad_options_raise_parameter_error(options, match):
    with pytest.raises(ParameterError, match=match):
        MomentDetector(**options)


def test_bad_calls_raise():
    rec = pick_and_handover(1000)
    with pytest.raises(ParameterError, match="unknown option.*'windw'"):
        find_moments(rec, windw=0.1)
    with pytest.raises(CritmomentError, match="before fit"):
        MomentDetector().predict()
    det = MomentDetector().fit(rec)
    with pytest.raises(ParameterError, match="threshold must be a real number"):
        det.predict(threshold=float("nan"))
    with pytest.raises(ParameterError, match="sensitivity must be callable"):
        det.predict(sensitivity=0.5)
    with pytest.raises(CritmomentError, match="scores"):
        det.predict(sensitivity=lambda steps: np.zeros(steps.size + 1))
    with pytest.raises(ParameterError, match="max_moments"):
        det.predict(max_moments=-1)


def test_bad_recordings_raise_trajectory_error():
    rec = pick_and_handover(500)
    acc = rec.object_acc.copy()
    acc[10, 0] = np.nan
    with pytest.raises(TrajectoryError, match="object_acc contains non-finite"):
        MomentDetector().fit(dataclasses.replace(rec, object_acc=acc))
    with pytest.raises(TrajectoryError, match=r"object_acc must have shape \(\?, 3\)"):
        MomentDetector().fit(dataclasses.replace(rec, object_acc=acc[:, :2]))
    with pytest.raises(TrajectoryError, match="fos_contact must be >= 0"):
        MomentDetector().fit(dataclasses.replace(rec, fos_contact=-rec.fos_contact))
    with pytest.raises(TrajectoryError, match="contact_support must be boolean"):
        MomentDetector().fit(dataclasses.replace(rec, contact_support=rec.contact_support.astype(int)))
    with pytest.raises(TrajectoryError, match="gripper_names has 1 names"):
        MomentDetector().fit(dataclasses.replace(rec, gripper_names=("left",)))
    with pytest.raises(TrajectoryError, match="dt must be finite and > 0"):
        MomentDetector().fit(dataclasses.replace(rec, dt=0.0))
    fields = {f.name: getattr(rec, f.name) for f in dataclasses.fields(rec) if f.name != "fos_contact"}
    with pytest.raises(TrajectoryError, match="no attribute 'fos_contact'"):
        MomentDetector().fit(types.SimpleNamespace(**fields))


# ---------------------------------------------------------------- misc


def test_moment_is_frozen_and_plot_is_agg_safe(tmp_path):
    rec = pick_and_handover()
    moments = find_moments(rec, sensitivity=lambda s: s / 4000.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        moments[0].step = 3  # type: ignore[misc]
    path = tmp_path / "moments.png"
    fig = plot_moments(rec, moments, path=path)
    assert path.stat().st_size > 0
    assert len(fig.axes) == 3
    assert sum(len(ax.lines) for ax in fig.axes) >= 3 * len(moments)

    from matplotlib.figure import Figure

    ax = Figure().subplots()
    assert plot_moments(rec, moments[:2], ax=ax) is ax.figure
    with pytest.raises(ParameterError, match="sequence of 3 Axes"):
        plot_moments(rec, moments, ax=[ax, ax])


# --------------------------------------------------------------------------
# peak loads
# --------------------------------------------------------------------------


def test_peak_loads_first_overload_and_separated_lows():
    from critmoment.moments import detect_peak_loads

    dt = 0.002
    t = np.arange(2000) * dt
    # two smooth dips (1.3 at 0.5 s, 1.2 at 3.0 s), a brief touch of the limit at 1.0 s
    # (10 ms), and a saturation held for 0.1 s from 2.0 s
    fos = 3.0 - 1.7 * np.exp(-((t - 0.5) / 0.05) ** 2) - 1.8 * np.exp(-((t - 3.0) / 0.05) ** 2)
    fos[500:505] = 1.0
    fos[1000:1050] = 1.0
    out = detect_peak_loads(fos, dt=dt, level=1.5, max_peaks=2, separation=0.1)
    assert all(m.label is MomentLabel.PEAK_LOAD for m in out)
    first = [m for m in out if m.reason.startswith("first overload")]
    assert [m.step for m in first] == [1000]  # the short touch at 1.0 s does not last 50 ms
    lows = sorted(m.step for m in out if m.reason.startswith("peak load"))
    # the lowest lows at least 0.1 s from the first overload: the brief touch, then 3.0 s
    assert lows == [500, 1500]
    assert [m.step for m in out] == sorted(m.step for m in out)
    assert detect_peak_loads(np.full(100, 3.0), dt=dt) == []
    assert len(detect_peak_loads(fos, dt=dt, max_peaks=0)) == 1
    with pytest.raises(TrajectoryError, match="fos"):
        detect_peak_loads(np.full((3, 2), 1.0), dt=dt)
    with pytest.raises(ParameterError, match="saturation"):
        detect_peak_loads(fos, dt=dt, saturation=0.0)


def test_detector_adds_peak_loads_of_the_recording_and_of_an_extra_bound():
    rec = _peak_recording()
    plain = MomentDetector(peak_level=None).fit(rec)
    assert not any(m.label is MomentLabel.PEAK_LOAD for m in plain.candidates_)
    det = MomentDetector().fit(rec)
    peaks = [m for m in det.candidates_ if m.label is MomentLabel.PEAK_LOAD]
    assert [m.step for m in peaks] == [300]
    assert "nominal run" in peaks[0].reason
    bound = np.full(rec.time.size, 4.0)
    bound[700] = 0.5
    extra = MomentDetector().fit(rec, load_fos=bound, load_source="bound at 2 kg")
    found = {m.step: m.reason for m in extra.candidates_ if m.label is MomentLabel.PEAK_LOAD}
    assert 300 in found and 700 in found and "bound at 2 kg" in found[700]
    with pytest.raises(TrajectoryError, match="shape"):
        MomentDetector().fit(rec, load_fos=bound[:10])


def _peak_recording():
    """A quiet synthetic recording whose motor FOS dips to 1.2 at step 300, no contacts."""
    n = 1000
    fos = np.full(n, 3.0)
    fos[290:311] = 1.2 + np.abs(np.arange(-10, 11)) * 0.01
    return types.SimpleNamespace(
        dt=0.002, time=np.arange(n) * 0.002, object_acc=np.zeros((n, 3)),
        actuator_norm=np.zeros((n, 1)), fos_contact=np.full((n, 1), np.inf), fos_motor=fos,
        contact_support=np.ones(n, bool), contact_gripper=np.zeros((n, 1), bool),
        gripper_names=("hand",))


def test_a_jump_off_a_flat_signal_is_not_given_as_a_huge_sigma():
    """A gantry holding a constant force read "jump 212844.1 sigma"."""
    from critmoment.moments import _change_point_reasons

    assert _change_point_reasons(np.array([3.0, 0.1]), ["object acceleration", "x"]) == (
        "change point in object acceleration (jump 3.0 sigma)",)
    assert _change_point_reasons(np.array([212844.1, 0.0]), ["actuator load", "x"]) == (
        "change point in actuator load (jump over 1000 sigma, from a flat signal)",)
