"""Tests for critmoment.trajectory."""

from __future__ import annotations

import json
import warnings

import h5py
import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

from critmoment import budget
from critmoment.exceptions import (
    CritmomentWarning,
    InputFileError,
    ParameterError,
    ResourceLimitError,
    TrajectoryError,
)
from critmoment.trajectory import (
    RangePolicy,
    Trajectory,
    as_object_pose,
    check_ranges,
    input_identity,
    list_episodes,
    load_trajectory,
    save_trajectory,
    upsample,
)

NA = 14
GRIPPERS = np.zeros(NA, dtype=bool)
GRIPPERS[[6, 13]] = True


def _actions(rng: np.random.Generator, t: int = 40) -> np.ndarray:
    a = rng.uniform(-1.0, 1.0, size=(t, NA))
    a[:, GRIPPERS] = rng.uniform(0.0, 1.0, size=(t, 2))
    return a


# ---------------------------------------------------------------------------
# Trajectory container
# ---------------------------------------------------------------------------


def test_trajectory_properties_and_read_only():
    rng = np.random.default_rng(0)
    a = _actions(rng, 25)
    traj = Trajectory(a, fps=50)
    assert traj.n_steps == 25 and traj.n_channels == NA
    assert traj.duration == pytest.approx(0.5)
    np.testing.assert_array_equal(traj.times, np.arange(25) / 50.0)
    assert traj.actions.dtype == np.float64
    with pytest.raises(ValueError):
        traj.actions[0, 0] = 5.0
    a[0, 0] = 99.0  # the trajectory holds a copy
    assert traj.actions[0, 0] != 99.0


def test_int_actions_converted_and_quaternion_normalised():
    traj = Trajectory(np.arange(6).reshape(3, 2), object_pose=[0, 0, 0, 1.005, 0, 0, 0])
    assert traj.actions.dtype == np.float64
    np.testing.assert_array_equal(traj.object_pose, [0, 0, 0, 1, 0, 0, 0])


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"actions": np.zeros(5)}, r"2-D array.*got 1-D"),
        ({"actions": np.zeros((1, 3))}, r"at least 2 time steps"),
        ({"actions": np.array([["a", "b"], ["c", "d"]])}, r"real numeric"),
        ({"actions": np.zeros((3, 2)), "fps": 0.0}, r"fps.*> 0"),
        ({"actions": np.zeros((3, 2)), "start": np.zeros(3)}, r"start.*\(2,\)"),
        ({"actions": np.zeros((3, 2)), "object_pose": np.zeros(7)}, r"unit quaternion"),
        ({"actions": np.zeros((3, 2)), "qpos0": np.zeros((2, 2))}, r"qpos0.*1-D"),
        ({"actions": np.zeros((3, 2)), "meta": {"x": object()}}, r"JSON"),
    ],
)
def test_trajectory_validation(kwargs, match):
    with pytest.raises(TrajectoryError, match=match):
        Trajectory(**kwargs)


def test_nan_names_row_and_column():
    a = np.zeros((10, 4))
    a[7, 2] = np.nan
    with pytest.raises(TrajectoryError, match=r"row \(step\) 7, column \(channel\) 2"):
        Trajectory(a)


# ---------------------------------------------------------------------------
# npz
# ---------------------------------------------------------------------------


def test_npz_round_trip_exact(tmp_path):
    rng = np.random.default_rng(1)
    traj = Trajectory(
        _actions(rng),
        fps=30.0,
        start=rng.normal(size=NA),
        qpos0=rng.normal(size=23),
        object_pose=np.r_[rng.normal(size=3), (q := rng.normal(size=4)) / np.linalg.norm(q)],
        meta={"task": "transfer_cube", "n": 3, "ok": True, "list": [1.5, None]},
        source="unit test",
    )
    path = tmp_path / "traj.npz"
    save_trajectory(traj, path)
    back = load_trajectory(path)
    for name in ("actions", "start", "qpos0", "object_pose"):
        assert np.array_equal(getattr(back, name), getattr(traj, name)), name
    assert back.fps == traj.fps
    assert back.meta == traj.meta
    assert back.source == str(path)
    assert back == Trajectory(**{**traj.__dict__, "source": str(path)})


def test_npz_time_sets_fps_and_checks(tmp_path):
    a = np.zeros((20, 3))
    path = tmp_path / "t.npz"
    np.savez(path, actions=a, time=np.arange(20) * 0.04 + 1.0)
    assert load_trajectory(path).fps == pytest.approx(25.0)

    np.savez(path, actions=a, time=np.arange(20) * 0.04, fps=50.0)
    with pytest.raises(TrajectoryError, match=r"disagrees"):
        load_trajectory(path)

    t = np.arange(20) * 0.02
    t[5], t[6] = t[6], t[5]
    np.savez(path, actions=a, time=t)
    with pytest.raises(TrajectoryError, match=r"strictly increasing.*t\[5\] = 0\.12"):
        load_trajectory(path)
    # float32 epoch seconds: 128 s apart at 1.7e9, every frame rounds alike; named so
    np.savez(path, actions=a, time=(1.7e9 + np.arange(20) * 0.02).astype(np.float32))
    with pytest.raises(TrajectoryError, match=r"strictly increasing.*the times are float32, "
                                              r"which at 1\.7e\+09 s resolves only 128 s"):
        load_trajectory(path)

    # float32 seconds are rounded: from 1000 s to 61 µs, which made one 20 ms step read
    # 49.95 Hz; the rate is the mean over the span, a whole rate the rounding cannot tell
    # from it is that rate, and times too coarse to check the spacing say why
    for t0 in (0.0, 1000.0, 3.0e4):
        np.savez(path, actions=np.zeros((400, 3)),
                 time=(t0 + np.arange(400) / 50).astype(np.float32))
        assert load_trajectory(path).fps == 50.0
    np.savez(path, actions=np.zeros((400, 3)), time=(np.arange(400) / 29.97).astype(np.float32))
    assert load_trajectory(path).fps == pytest.approx(29.97, rel=1e-6)
    np.savez(path, actions=np.zeros((400, 3)),
             time=(1.0e5 + np.arange(400) / 50).astype(np.float32))
    with pytest.raises(TrajectoryError, match=r"expected uniform spacing.*the times are float32, "
                                              r"which at 1e\+05 s resolves only 0\.00781 s"):
        load_trajectory(path)

    t = np.arange(20) * 0.02
    t[10:] += 0.005
    np.savez(path, actions=a, time=t)
    with pytest.raises(TrajectoryError, match=r"uniform spacing"):
        load_trajectory(path)


def test_npz_unknown_key_warns_and_fps_conflict(tmp_path):
    path = tmp_path / "u.npz"
    np.savez(path, actions=np.zeros((3, 2)), fps=20.0, extra=np.ones(2))
    with pytest.warns(UserWarning, match=r"unknown key.*extra"):
        traj = load_trajectory(path)
    assert traj.fps == 20.0
    with pytest.raises(TrajectoryError, match=r"fps argument 50 Hz disagrees"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            load_trajectory(path, fps=50)


def test_npz_time_base_under_another_name_is_refused(tmp_path):
    """A 25 Hz file whose rate is stored as 'timestamp' (LeRobot's column), 'dt' or 'FPS':
    the key was ignored with a warning and the run went on at the scenario's 50 Hz, twice
    the recorded speed, exit 0."""
    path = tmp_path / "r.npz"
    for key, value in (("timestamp", np.arange(6) / 25), ("dt", 0.04), ("FPS", 25.0),
                       ("control_freq", 25.0)):
        np.savez(path, actions=np.zeros((6, 2)), **{key: value})
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            with pytest.raises(TrajectoryError, match=rf"\['{key}'\] look like the trajectory's "
                                                      r"time base.*'fps'.*'time'"):
                load_trajectory(path)
            assert load_trajectory(path, fps=25).fps == 25  # the rate given: read as before
    # beside a rate critmoment reads, such a key is only ignored, with the warning
    np.savez(path, actions=np.zeros((6, 2)), fps=25.0, dt=0.04)
    with pytest.warns(UserWarning, match=r"unknown key.*'dt'"):
        assert load_trajectory(path).fps == 25


def test_npz_missing_actions(tmp_path):
    path = tmp_path / "m.npz"
    np.savez(path, act=np.zeros((3, 2)))
    with pytest.raises(TrajectoryError, match=r"expected key 'actions'.*'act'"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            load_trajectory(path)


def test_corrupt_npz(tmp_path):
    path = tmp_path / "bad.npz"
    path.write_bytes(b"this is not a zip archive at all")
    with pytest.raises(InputFileError, match=r"cannot read .*bad\.npz"):
        load_trajectory(path)
    good = tmp_path / "good.npz"
    np.savez(good, actions=np.zeros((50, 3)))
    trunc = tmp_path / "trunc.npz"
    trunc.write_bytes(good.read_bytes()[:-60])
    with pytest.raises(InputFileError, match=r"trunc\.npz"):
        load_trajectory(trunc)


def test_missing_file_and_unknown_suffix(tmp_path):
    with pytest.raises(InputFileError, match=r"nope\.npz.*does not exist"):
        load_trajectory(tmp_path / "nope.npz")
    assert issubclass(InputFileError, FileNotFoundError)
    odd = tmp_path / "traj.csv"
    odd.write_text("1,2\n")
    with pytest.raises(InputFileError, match=r"'\.csv'.*\.npz.*\.hdf5.*\.parquet.*LeRobot"):
        load_trajectory(odd)
    with pytest.raises(InputFileError, match=r"without meta/info\.json"):
        load_trajectory(tmp_path)


# ---------------------------------------------------------------------------
# ACT HDF5
# ---------------------------------------------------------------------------


def test_act_hdf5_reads_start_and_attrs(tmp_path):
    rng = np.random.default_rng(2)
    act = _actions(rng, 30)
    qpos = _actions(rng, 30)
    path = tmp_path / "episode_0.hdf5"
    with h5py.File(path, "w") as f:
        f.attrs["sim"] = True
        f.attrs["compress"] = False
        f.create_dataset("action", data=act)
        obs = f.create_group("observations")
        obs.create_dataset("qpos", data=qpos)
        obs.create_dataset("qvel", data=np.zeros_like(qpos))
    traj = load_trajectory(path)
    np.testing.assert_array_equal(traj.actions, act)
    np.testing.assert_array_equal(traj.start, qpos[0])
    # the recorded joint path, against which the feasibility check may measure the joints
    np.testing.assert_array_equal(traj.observed, qpos)
    assert traj.fps == 50.0
    assert traj.meta["sim"] is True and traj.meta["source_format"] == "act_hdf5"
    json.dumps(traj.meta)
    assert load_trajectory(path, fps=25).fps == 25.0


def test_act_hdf5_null_action_is_named(tmp_path):
    """A /action declared with no shape (an HDF5 null dataspace) was "corrupt or truncated
    HDF5 data ... TypeError: 'NoneType' object is not iterable"."""
    path = tmp_path / "null.hdf5"
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=h5py.Empty("f8"))
    with pytest.raises(TrajectoryError, match=r"dataset /action: expected an array of "
                                              r"numbers, got an empty \(null\) dataset"):
        load_trajectory(path)


def test_act_hdf5_nan_rate_is_named_as_a_number(tmp_path):
    """A float attribute control_freq = NaN was reported as "got text 'nan'"."""
    path = tmp_path / "nan.hdf5"
    with h5py.File(path, "w") as f:
        f.attrs["control_freq"] = np.nan
        f.create_dataset("action", data=np.zeros((10, 14)))
    with pytest.raises(TrajectoryError, match=r"attribute 'control_freq': expected a finite "
                                              r"number > 0 \[Hz\], got (float64 )?nan"):
        load_trajectory(path)


def test_act_hdf5_missing_action(tmp_path):
    path = tmp_path / "episode_1.h5"
    with h5py.File(path, "w") as f:
        f.create_dataset("observations/qpos", data=np.zeros((5, NA)))
    with pytest.raises(TrajectoryError, match=r"/action.*found datasets.*/observations/qpos"):
        load_trajectory(path)


def test_corrupt_hdf5(tmp_path):
    path = tmp_path / "bad.hdf5"
    path.write_bytes(b"\x00" * 64)
    with pytest.raises(InputFileError, match=r"HDF5"):
        load_trajectory(path)


# ---------------------------------------------------------------------------
# LeRobot parquet
# ---------------------------------------------------------------------------


def _write_lerobot(root, rng, lengths=(12, 9), fps=30, shuffle=False):
    (root / "meta").mkdir(parents=True)
    (root / "meta" / "info.json").write_text(
        json.dumps({"codebase_version": "v2.1", "robot_type": "aloha", "fps": fps})
    )
    data_dir = root / "data" / "chunk-000"
    data_dir.mkdir(parents=True)
    actions, states, ep_idx, frame_idx, stamps = [], [], [], [], []
    per_episode = {}
    for ep, n in enumerate(lengths):
        a = _actions(rng, n).astype(np.float32)
        s = _actions(rng, n).astype(np.float32)
        per_episode[ep] = (a, s)
        actions += list(a)
        states += list(s)
        ep_idx += [ep] * n
        frame_idx += list(range(n))
        stamps += list(np.arange(n, dtype=np.float32) / np.float32(fps))
    order = np.arange(len(actions))
    if shuffle:
        order = rng.permutation(order)
    table = pa.table(
        {
            "action": pa.array([actions[i].tolist() for i in order], pa.list_(pa.float32())),
            "observation.state": pa.array(
                [states[i].tolist() for i in order], pa.list_(pa.float32())
            ),
            "timestamp": pa.array([stamps[i] for i in order], pa.float32()),
            "frame_index": pa.array([frame_idx[i] for i in order], pa.int64()),
            "episode_index": pa.array([ep_idx[i] for i in order], pa.int64()),
        }
    )
    path = data_dir / "episode_000000.parquet"
    pq.write_table(table, path)
    return path, per_episode


def test_lerobot_directory_selects_episode(tmp_path):
    rng = np.random.default_rng(3)
    root = tmp_path / "ds"
    _, eps = _write_lerobot(root, rng, shuffle=True)
    traj = load_trajectory(root, episode=1)
    a, s = eps[1]
    np.testing.assert_array_equal(traj.actions, a.astype(np.float64))
    np.testing.assert_array_equal(traj.start, s[0].astype(np.float64))
    np.testing.assert_array_equal(traj.observed, s.astype(np.float64))
    assert traj.fps == 30.0
    assert traj.meta["episode_index"] == 1 and traj.meta["robot_type"] == "aloha"


def test_lerobot_file_finds_info_in_ancestors(tmp_path):
    rng = np.random.default_rng(4)
    path, eps = _write_lerobot(tmp_path / "ds", rng)
    traj = load_trajectory(path, episode=0)
    assert traj.fps == 30.0
    np.testing.assert_array_equal(traj.actions, eps[0][0].astype(np.float64))


def test_lerobot_ambiguous_and_missing_episode(tmp_path):
    rng = np.random.default_rng(5)
    root = tmp_path / "ds"
    _write_lerobot(root, rng)
    with pytest.raises(TrajectoryError, match=r"2 episodes.*ambiguous.*\[0, 1\]"):
        load_trajectory(root)
    with pytest.raises(TrajectoryError, match=r"episode 7 not found.*\[0, 1\]"):
        load_trajectory(root, episode=7)
    with pytest.raises(TrajectoryError, match=r"fps argument 50 Hz disagrees"):
        load_trajectory(root, episode=0, fps=50)


def test_lerobot_single_file_without_info_warns_default_fps(tmp_path):
    path = tmp_path / "ep.parquet"
    pq.write_table(
        pa.table({"action": pa.array([[0.0, 1.0], [0.5, 1.0], [1.0, 1.0]])}), path
    )
    with pytest.warns(UserWarning, match=r"assuming 50 Hz"):
        traj = load_trajectory(path)
    assert traj.fps == 50.0 and traj.start is None
    assert load_trajectory(path, fps=10).fps == 10.0


def test_lerobot_non_monotonic_timestamp(tmp_path):
    path = tmp_path / "ep.parquet"
    pq.write_table(
        pa.table(
            {
                "action": pa.array([[0.0], [0.5], [1.0], [1.5]]),
                "timestamp": pa.array([0.0, 0.1, 0.05, 0.3]),
            }
        ),
        path,
    )
    with pytest.raises(TrajectoryError, match=r"strictly increasing"):
        load_trajectory(path)


# ---------------------------------------------------------------------------
# Range checking
# ---------------------------------------------------------------------------


def _range_case():
    a = np.zeros((6, 3))
    a[4, 1] = 2.0  # beyond upper 1
    a[2, 2] = -3.0  # beyond lower -2
    a[1, 0] = 1.0 + 1e-9  # within tolerance
    return a, np.array([-1.0, -1.0, -2.0]), np.array([1.0, 1.0, 2.0])


def test_range_error_names_channel():
    a, lo, hi = _range_case()
    with pytest.raises(TrajectoryError, match=r"'wrist' \(index 2\).*step 2.*-3\.0"):
        check_ranges(a, lo, hi, names=["waist", "elbow", "wrist"])
    ok = check_ranges(np.clip(a, lo, hi), lo, hi)
    assert isinstance(ok, np.ndarray)


def test_range_clip_warns_and_clips():
    a, lo, hi = _range_case()
    traj = Trajectory(a)
    with pytest.warns(UserWarning, match=r"clipped 3 action value"):
        out = check_ranges(traj, lo, hi, policy=RangePolicy.CLIP)
    assert isinstance(out, Trajectory)
    assert np.all(out.actions >= lo) and np.all(out.actions <= hi)
    assert out.actions[4, 1] == 1.0 and out.actions[2, 2] == -2.0
    assert traj.actions[4, 1] == 2.0  # input untouched


def test_range_warn_keeps():
    a, lo, hi = _range_case()
    with pytest.warns(UserWarning, match=r"kept unchanged.*channel 1"):
        out = check_ranges(a, lo, hi, policy="warn")
    assert out is a


def test_range_bad_policy_and_bounds():
    a, lo, hi = _range_case()
    with pytest.raises(ParameterError, match=r"ERROR.*CLIP.*WARN"):
        check_ranges(a, lo, hi, policy="ignore")
    with pytest.raises(ParameterError, match=r"shape \(3,\)"):
        check_ranges(a, lo[:2], hi)


# ---------------------------------------------------------------------------
# Upsampling
# ---------------------------------------------------------------------------


def test_upsample_reproduces_cubic():
    fps, dt, t_len = 50.0, 0.002, 30
    t = np.arange(t_len) / fps
    def cubic(x):
        return 0.3 - 1.2 * x + 4.0 * x**2 - 7.5 * x**3
    a = np.stack([cubic(t), 2 * cubic(t)], axis=1)
    out = upsample(a, fps=fps, physics_dt=dt)
    n = round(t_len / fps / dt)
    assert out.shape == (n, 2)
    tk = np.arange(n) * dt
    interior = tk <= t[-1] + 1e-12
    np.testing.assert_allclose(out[interior, 0], cubic(tk[interior]), rtol=0, atol=1e-9)
    # Beyond the last sample time: hold the last action.
    np.testing.assert_array_equal(out[~interior], np.broadcast_to(a[-1], out[~interior].shape))
    # Sample times are hit exactly.
    np.testing.assert_array_equal(out[::10][:t_len], a)


def test_upsample_gripper_step_bounded_and_monotone():
    t_len = 20
    a = np.zeros((t_len, 3))
    a[:, 0] = np.sin(np.arange(t_len) / 3.0)
    a[10:, 1] = 1.0  # gripper opens 0 -> 1
    a[:, 2] = np.linspace(0.0, 1.0, t_len)
    mask = np.array([False, True, False])
    out = upsample(
        a, fps=50, physics_dt=0.002, bounded=mask,
        lower=[-2.0, 0.0, 0.0], upper=[2.0, 1.0, 1.0],
    )
    g = out[:, 1]
    assert g.min() >= 0.0 and g.max() <= 1.0
    assert np.all(np.diff(g) >= 0.0)
    assert np.any((g > 0.0) & (g < 1.0))  # interpolated, not a hard step


def test_upsample_clips_spline_overshoot_with_warning():
    a = np.zeros((12, 1))
    a[6:] = 1.0  # a cubic spline rings past 1 here
    with pytest.warns(UserWarning, match=r"clipped.*channel 0 \(cubic spline\)"):
        out = upsample(a, fps=50, physics_dt=0.002, lower=[0.0], upper=[1.0])
    assert out.min() >= 0.0 and out.max() <= 1.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        free = upsample(a, fps=50, physics_dt=0.002)
    assert free.max() > 1.0


def test_upsample_from_trajectory_and_non_integer_ratio():
    rng = np.random.default_rng(6)
    traj = Trajectory(_actions(rng, 15), fps=30.0)
    out = traj.upsample(0.004, bounded=GRIPPERS)
    assert out.shape == (round(15 / 30.0 / 0.004), NA)
    # 30 Hz vs 250 Hz: step 25 is t = 0.1 s = sample 3.
    np.testing.assert_array_equal(out[25], traj.actions[3])
    np.testing.assert_array_equal(out[0], traj.actions[0])


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"physics_dt": 0.0}, r"physics_dt.*0 < physics_dt"),
        ({"physics_dt": 0.05}, r"physics_dt.*<= 1 / fps"),
        ({"physics_dt": 0.002, "bounded": [1, 0]}, r"bool mask of shape \(2,\)"),
        ({"physics_dt": 0.002, "lower": [1.0, 0.0], "upper": [0.0, 1.0]}, r"lower <= upper"),
    ],
)
def test_upsample_parameter_errors(kwargs, match):
    with pytest.raises(ParameterError, match=match):
        upsample(np.zeros((5, 2)), fps=50, **kwargs)


def test_upsample_requires_fps_for_arrays():
    with pytest.raises(ParameterError, match=r"fps"):
        upsample(np.zeros((5, 2)), physics_dt=0.002)


# ---------------------------------------------------------------------------
# Object pose, episodes, input identity, declared sizes (issue 14)
# ---------------------------------------------------------------------------


def test_missing_object_pose_warns_and_option_overrides(tmp_path):
    path = tmp_path / "t.npz"
    np.savez(path, actions=np.zeros((5, 3)), fps=50.0)
    with pytest.warns(CritmomentWarning, match="gives no object start pose"):
        assert load_trajectory(path).object_pose is None
    pose = [0.1, 0.2, 0.05, 2.0 ** -0.5, 0.0, 0.0, 0.70711]  # norm 1.000002: normalised
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        traj = load_trajectory(path, object_pose=pose)
    np.testing.assert_allclose(traj.object_pose[:3], [0.1, 0.2, 0.05])
    assert np.linalg.norm(traj.object_pose[3:]) == pytest.approx(1.0, abs=1e-15)
    np.savez(path, actions=np.zeros((5, 3)), object_pose=[0, 0, 0, 1, 0, 0, 0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the file's own pose: no warning
        assert load_trajectory(path, object_pose=pose).object_pose[0] == 0.1  # option wins


@pytest.mark.parametrize("pose, match", [
    ([0, 0, 0, 1, 0, 0], "7 numbers"),
    ([0, 0, np.nan, 1, 0, 0, 0], "finite"),
    ([0, 0, 0, 0, 0, 0, 0], "unit quaternion"),
    ([0, 0, 0, 1, 0, 0, 1], "norm 1.41421"),
])
def test_object_pose_rejected(pose, match):
    with pytest.raises(ParameterError, match=match):
        as_object_pose(pose)


def test_act_env_state_gives_the_object_pose(tmp_path):
    path = tmp_path / "episode_0.hdf5"
    env = np.zeros((30, 7))
    env[:, :3] = [0.05, 0.5, 0.02]
    env[:, 3] = 2.0  # an unnormalised but usable quaternion is normalised
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=np.zeros((30, NA)))
        f.create_dataset("observations/qpos", data=np.zeros((30, NA)))
        f.create_dataset("observations/env_state", data=env)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(CritmomentWarning, match="not an object pose"):
            load_trajectory(path)  # norm 2 is not within 1 % of a unit quaternion
    env[:, 3] = 1.0
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=np.zeros((30, NA)))
        f.create_dataset("observations/qpos", data=np.zeros((30, NA)))
        f.create_dataset("observations/env_state", data=env)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        traj = load_trajectory(path)
    np.testing.assert_array_equal(traj.object_pose, [0.05, 0.5, 0.02, 1, 0, 0, 0])
    with h5py.File(path, "w") as f:  # insertion: peg then socket pose; the first is taken
        f.create_dataset("action", data=np.zeros((30, NA)))
        f.create_dataset("observations/qpos", data=np.zeros((30, NA)))
        f.attrs["env_state"] = np.r_[env[0], env[0] + [1, 0, 0, 0, 0, 0, 0]]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        np.testing.assert_array_equal(load_trajectory(path).object_pose[:3], [0.05, 0.5, 0.02])
    with h5py.File(path, "w") as f:  # an empty env_state is ignored with a warning
        f.create_dataset("action", data=np.zeros((30, NA)))
        f.create_dataset("observations/qpos", data=np.zeros((30, NA)))
        f.create_dataset("observations/env_state", data=np.zeros((0, 7)))
    with pytest.warns(CritmomentWarning, match=r"env_state is not an object pose .*shape "
                      r"\(0, 7\): no rows"):
        assert load_trajectory(path).object_pose is None


def test_list_episodes(tmp_path):
    rng = np.random.default_rng(5)
    path, per_episode = _write_lerobot(tmp_path / "ds", rng, lengths=(12, 9, 4))
    episodes = list_episodes(tmp_path / "ds")
    assert [(e.index, e.frames) for e in episodes] == [(0, 12), (1, 9), (2, 4)]
    assert all(e.file == str(path) for e in episodes)
    assert [e.frames for e in list_episodes(path)] == [12, 9, 4]
    npz = tmp_path / "t.npz"
    np.savez(npz, actions=np.zeros((7, 3)), object_pose=[0, 0, 0, 1, 0, 0, 0])
    assert [(e.index, e.frames) for e in list_episodes(npz)] == [(None, 7)]
    # a dataset folder with no episode files: the error loading it gives, not "0 episodes"
    empty = tmp_path / "empty"
    (empty / "meta").mkdir(parents=True)
    (empty / "meta" / "info.json").write_text('{"fps": 50}')
    with pytest.raises(InputFileError, match=r"expected episode parquet files.*found none"):
        list_episodes(empty)


def test_lerobot_float_episode_index_is_accepted_when_integral(tmp_path):
    root = tmp_path / "ds"
    (root / "meta").mkdir(parents=True)
    (root / "meta" / "info.json").write_text('{"fps": 50}')
    (root / "data").mkdir()
    pq.write_table(pa.table({"action": [[0.0] * 3] * 6, "episode_index": [0.0] * 3 + [1.0] * 3,
                             "frame_index": [0, 1, 2] * 2}), root / "data" / "e.parquet")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert load_trajectory(root, episode=1).n_steps == 3
    pq.write_table(pa.table({"action": [[0.0] * 3] * 6,
                             "episode_index": [0.0] * 3 + [np.nan] * 3}),
                   root / "data" / "e.parquet")
    with pytest.raises(TrajectoryError, match=r"episode_index.*expected integers, got nan"):
        load_trajectory(root, episode=0)


def test_input_identity_ignores_the_spelling(tmp_path, monkeypatch):
    path = tmp_path / "sub" / "t.npz"
    path.parent.mkdir()
    np.savez(path, actions=np.zeros((5, 3)))
    monkeypatch.chdir(tmp_path)
    spellings = [path, "sub/t.npz", "./sub/../sub/t.npz"]
    (tmp_path / "link.npz").symlink_to(path)
    ids = [input_identity(s) for s in [*spellings, "link.npz"]]
    assert all(i == ids[0] for i in ids)
    assert ids[0]["name"] == "t.npz" and len(ids[0]["sha256"]) == 64
    assert input_identity("a description") == {"name": "a description", "sha256": None}


def test_declared_sizes_are_checked_before_reading(tmp_path):
    path = tmp_path / "t.npz"
    np.savez(path, actions=np.zeros((400, 14)))
    with budget.limits(max_input_bytes=1000):
        with pytest.raises(ResourceLimitError, match=r"actions\.npy.*max_input_bytes.*"
                                                     r"--max-input-bytes"):
            load_trajectory(path)
    h5 = tmp_path / "e.hdf5"
    with h5py.File(h5, "w") as f:  # declared, never written: the file stays tiny
        f.create_dataset("action", shape=(10**8, 14), chunks=(1024, 14), dtype="f8")
    assert h5.stat().st_size < 100_000
    with pytest.raises(ResourceLimitError, match="11,200,000,000 bytes"):
        load_trajectory(h5)


def test_lerobot_missing_frames_are_refused_without_timestamps(tmp_path, rng):
    """Frames 0-5 then 9-14: without a 'timestamp' column (only frame_index) the gap was
    taken silently, the actions around it played back to back."""
    a = _actions(rng, 12).astype(np.float32)
    frames = list(range(6)) + list(range(9, 15))
    pq.write_table(pa.table({
        "action": pa.array([r.tolist() for r in a], pa.list_(pa.float32())),
        "frame_index": pa.array(frames, pa.int64()),
        "episode_index": pa.array([0] * 12, pa.int64()),
    }), tmp_path / "ep.parquet")
    with pytest.raises(TrajectoryError, match=r"expected consecutive frame_index values, got "
                       r"a jump from frame 5 to 9 \(1 gap\(s\) in all\)"):
        load_trajectory(tmp_path / "ep.parquet", fps=50)


def test_an_episode_split_over_two_files_is_refused_by_listing_and_loading(tmp_path, rng):
    """Episode 0 in two parquet files of one dataset: loading refused it while `episodes`
    listed it twice; both now say the same."""
    _write_lerobot(tmp_path / "ds", rng, lengths=(12,))
    first = next((tmp_path / "ds" / "data").rglob("*.parquet"))
    (first.parent / "episode_000001.parquet").write_bytes(first.read_bytes())
    for call in (lambda: list_episodes(tmp_path / "ds"),
                 lambda: load_trajectory(tmp_path / "ds", episode=0)):
        with pytest.raises(TrajectoryError, match="expected episode 0 in one parquet file"):
            call()


def test_act_hdf5_uses_a_recorded_rate(tmp_path):
    """A root attribute fps = 25 is the episode's rate (it was ignored for ACT's 50 Hz); an
    fps argument that disagrees with it is an error, as for LeRobot data."""
    path = tmp_path / "episode_0.hdf5"
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=np.zeros((30, NA)))
        f.create_dataset("observations/qpos", data=np.zeros((30, NA)))
        f.attrs["fps"] = 25
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert load_trajectory(path).fps == 25.0
        assert load_trajectory(path, fps=25.0).fps == 25.0
        with pytest.raises(TrajectoryError, match=r"fps argument 50 Hz disagrees with the rate "
                           r"25 Hz recorded in"):
            load_trajectory(path, fps=50.0)


def test_lerobot_negative_indices_are_refused(tmp_path, rng):
    a = _actions(rng, 6).astype(np.float32)
    pq.write_table(pa.table({
        "action": pa.array([r.tolist() for r in a], pa.list_(pa.float32())),
        "frame_index": pa.array(range(6), pa.int64()),
        "episode_index": pa.array([-3] * 6, pa.int64()),
    }), tmp_path / "ep.parquet")
    with pytest.raises(TrajectoryError, match=r"column 'episode_index': expected indices >= 0, "
                       r"got -3 at row 0"):
        load_trajectory(tmp_path / "ep.parquet", fps=50)


def test_a_fifo_is_refused_before_it_is_read(tmp_path):
    """Opening a FIFO named like a trajectory waited forever."""
    import os

    fifo = tmp_path / "x.npz"
    os.mkfifo(fifo)
    with pytest.raises(InputFileError, match="not a regular file"):
        load_trajectory(fifo)


def test_an_npz_with_a_key_twice_is_ambiguous(tmp_path):
    import zipfile

    path = tmp_path / "dup.npz"
    save_trajectory(Trajectory(actions=np.zeros((3, 2)), fps=50.0), path)
    extra = tmp_path / "x.npz"
    np.savez(extra, actions=np.ones((3, 2)))
    with zipfile.ZipFile(extra) as src, warnings.catch_warnings():
        warnings.simplefilter("ignore")  # zipfile warns of the duplicate name it writes
        with zipfile.ZipFile(path, "a") as dst:
            dst.writestr("actions.npy", src.read("actions.npy"))
    with pytest.raises(InputFileError, match=r"\['actions.npy'\] more than once"):
        load_trajectory(path)


def test_a_trajectorys_object_pose_needs_a_unit_quaternion():
    """As --object-pose, ACT env_state and qpos0 require: [x, y, z, 2, 0, 0, 0] was
    rescaled silently."""
    with pytest.raises(TrajectoryError, match="expected a unit quaternion"):
        Trajectory(actions=np.zeros((3, 2)), fps=50.0,
                   object_pose=[0.1, 0.0, 0.02, 2.0, 0.0, 0.0, 0.0])
    pose = Trajectory(actions=np.zeros((3, 2)), fps=50.0,
                      object_pose=[0.1, 0.0, 0.02, 1.004, 0.0, 0.0, 0.0]).object_pose
    assert np.linalg.norm(pose[3:]) == pytest.approx(1.0, abs=1e-12)


def test_an_act_episode_with_two_different_rates_is_refused(tmp_path):
    path = tmp_path / "episode_0.hdf5"
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=np.zeros((10, 14)))
        f.attrs["fps"] = 50
        f.attrs["frame_rate"] = 25
    with pytest.raises(TrajectoryError, match=r"different rates \(fps = 50, frame_rate = 25\)"):
        load_trajectory(path)
    assert load_trajectory(path, fps=25).fps == 25


def test_a_spline_grazing_a_limit_is_clipped_without_a_warning():
    """A motion planned to a joint limit overshoots it by micrometres in the cubic spline
    (6 µm on a SCARA's quill): clipped, but only an overshoot over 0.1 % of the range is
    warned of."""
    import warnings as _w

    from critmoment.exceptions import CritmomentWarning
    from critmoment.trajectory import upsample

    lo, hi = np.array([-1.0]), np.array([1.0])
    gentle = np.array([[0.99], [0.995], [1.0], [1.0], [0.995]])  # reaches the limit 1.0
    with _w.catch_warnings():
        _w.simplefilter("error")
        out = upsample(gentle, fps=10.0, physics_dt=0.01, lower=lo, upper=hi)
    assert out.max() == 1.0
    steep = np.array([[0.0], [0.5], [1.0], [1.0], [0.5]])
    with pytest.warns(CritmomentWarning, match=r"channel 0 \(cubic spline\): \d+ step\(s\), "
                      r"worst by"):
        upsample(steep, fps=10.0, physics_dt=0.01, lower=lo, upper=hi)


def test_act_hdf5_rate_under_another_name_is_refused(tmp_path):
    """probe r35: an ACT episode whose rate is a root attribute ``dt`` (or ``FPS``, ``hz``,
    an ``fps`` attribute on /action, a /timestamps dataset) was played at ACT's 50 Hz
    without a word; the npz reader refuses the same keys. Given the rate, it loads."""
    act = np.zeros((30, NA))
    cases = {"dt": lambda f: f.attrs.__setitem__("dt", 1 / 30),
             "FPS": lambda f: f.attrs.__setitem__("FPS", 30),
             "action_fps": lambda f: f["action"].attrs.__setitem__("fps", 30),
             "timestamps": lambda f: f.create_dataset("timestamps", data=np.arange(30) / 30)}
    for name, edit in cases.items():
        path = tmp_path / f"{name}.hdf5"
        with h5py.File(path, "w") as f:
            f.create_dataset("action", data=act)
            edit(f)
        with pytest.raises(TrajectoryError, match=r"look\(s\) like the episode's time base.*"
                                                  r"CLI --fps"):
            load_trajectory(path)
        assert load_trajectory(path, fps=30).fps == 30.0
    path = tmp_path / "fps.hdf5"  # the attribute critmoment reads, beside another name
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=act)
        f.attrs["fps"] = 30
        f.attrs["dt"] = 1 / 30
    assert load_trajectory(path).fps == 30.0


def test_act_hdf5_qpos_rows_not_one_per_action_leave_the_start_unknown(tmp_path):
    """probe r35: /observations/qpos of 401 rows for 400 actions: qpos[0] was taken as the
    start without a word (the verdict: a motor overload at t = 0)."""
    path = tmp_path / "rows.hdf5"
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=np.zeros((40, NA)))
        f.create_dataset("observations/qpos", data=np.ones((41, NA)))
    with pytest.warns(CritmomentWarning, match=r"41 rows for 40 actions.*start state is left "
                                               r"unknown"):
        traj = load_trajectory(path)
    assert traj.start is None


def _named_lerobot(root, action_names, state_names=None, actions=None, state=None):
    """A one-episode LeRobot dataset whose info.json names the action's (and state's)
    components."""
    features = {"action": {"dtype": "float32", "shape": [len(action_names)],
                           "names": action_names}}
    if state_names is not None:
        features["observation.state"] = {"dtype": "float32", "shape": [len(state_names)],
                                         "names": {"motors": state_names}}
    (root / "meta").mkdir(parents=True)
    (root / "meta" / "info.json").write_text(json.dumps({"fps": 50, "features": features}))
    (root / "data" / "chunk-000").mkdir(parents=True)
    n = actions.shape[0]
    cols = {"action": pa.array(actions.tolist(), pa.list_(pa.float32())),
            "frame_index": pa.array(range(n), pa.int64()),
            "episode_index": pa.array([0] * n, pa.int64())}
    if state is not None:
        cols["observation.state"] = pa.array(state.tolist(), pa.list_(pa.float32()))
    pq.write_table(pa.table(cols), root / "data" / "chunk-000" / "episode_000000.parquet")


def test_lerobot_action_names_map_the_columns_onto_the_scenarios_channels(tmp_path):
    """probe r35: a LeRobot dataset whose info.json names its action's components in another
    order than the scenario's channels (a left wrist's angle and rotation swapped) was
    audited in file order, without a word. The columns are now mapped by name onto the
    channels (``left_waist`` is ``left/waist``), with a warning; the state named in yet
    another order becomes the start in the action's order; names that only partly match
    the channels are refused."""
    import critmoment as cm
    from critmoment.recording import at_scenario_rate

    twin = cm.Twin(cm.load_scenario())
    labels = list(twin.scenario.actions.labels)
    rng = np.random.default_rng(4)
    data = rng.uniform(-0.1, 0.1, size=(20, len(labels))).astype(np.float32)
    names = [lab.replace("/", "_") for lab in labels]
    order = list(range(len(names)))
    order[4], order[5] = 5, 4           # the data's columns 4 and 5 are the channels 5 and 4
    state_order = order[::-1]
    _named_lerobot(tmp_path / "ds", [names[i] for i in order],
                   [names[i] for i in state_order], data[:, order], data[:, state_order])
    traj = load_trajectory(tmp_path / "ds", episode=0)
    np.testing.assert_array_equal(traj.start, data[0, order])  # in the action's columns
    with pytest.warns(CritmomentWarning, match=r"another order than the scenario's channels"):
        mapped = at_scenario_rate(traj, twin)
    np.testing.assert_array_equal(mapped.actions, data.astype(np.float64))
    np.testing.assert_array_equal(mapped.start, data[0].astype(np.float64))
    assert at_scenario_rate(mapped, twin).actions is not None  # mapped once, not again
    np.testing.assert_array_equal(at_scenario_rate(mapped, twin).actions, mapped.actions)
    partial = [names[i] for i in order]
    partial[0] = "base_yaw"
    _named_lerobot(tmp_path / "partial", partial, actions=data)
    with pytest.raises(TrajectoryError, match=r"sit at other positions"):
        at_scenario_rate(load_trajectory(tmp_path / "partial", episode=0), twin)
    other = [f"motor_{i}" for i in range(len(names))]  # names that are not the channels
    _named_lerobot(tmp_path / "other", other, actions=data)
    kept = at_scenario_rate(load_trajectory(tmp_path / "other", episode=0), twin)
    np.testing.assert_array_equal(kept.actions, data.astype(np.float64))


def test_a_lerobot_file_reached_through_a_link_finds_its_dataset(tmp_path):
    """probe r35: the Hugging Face hub cache links ``snapshots/<rev>/data/...`` to a blob file
    named by its hash; the dataset's meta/info.json was looked for beside the blob, so its
    30 Hz was replaced by 50 Hz with a warning that there was none."""
    rng = np.random.default_rng(5)
    root = tmp_path / "snapshots" / "rev"
    data, _ = _write_lerobot(root, rng, lengths=(12,), fps=30)
    blobs = tmp_path / "blobs"
    blobs.mkdir()
    blob = blobs / "6f1e0c9a"
    data.rename(blob)
    data.symlink_to(blob)
    with warnings.catch_warnings():
        warnings.simplefilter("error", CritmomentWarning)  # no "no meta/info.json fps"
        warnings.filterwarnings("ignore", message=".*object start pose")
        traj = load_trajectory(data)
    assert traj.fps == 30.0


def test_lerobot_sidecars_bom_one_row_and_reversed_rows(tmp_path):
    """probe r35: a macOS ``._`` sidecar under data/ or a UTF-8 BOM in info.json made a
    dataset unreadable; a one-row episode "disagreed with the rate nan Hz"; rows stored
    newest first were blamed on float32 time resolution."""
    rng = np.random.default_rng(6)
    root = tmp_path / "ds"
    data, eps = _write_lerobot(root, rng, lengths=(12,), fps=30)
    (data.parent / ("._" + data.name)).write_bytes(b"\x00\x05\x16\x07" + b"\x00" * 60)
    info = root / "meta" / "info.json"
    info.write_bytes(b"\xef\xbb\xbf" + info.read_bytes())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        traj = load_trajectory(root, episode=0)
    assert traj.fps == 30.0 and traj.n_steps == 12
    one = tmp_path / "one.parquet"
    pq.write_table(pa.table({"action": pa.array([[0.0] * NA], pa.list_(pa.float64())),
                             "timestamp": pa.array([0.0])}), one)
    with pytest.raises(TrajectoryError, match=r"at least 2 time steps"):
        load_trajectory(one)
    back = tmp_path / "back.parquet"
    pq.write_table(pa.table({"action": pa.array([[0.0] * NA] * 5, pa.list_(pa.float64())),
                             "timestamp": pa.array((np.arange(5)[::-1] * 0.02)
                                                   .astype(np.float32))}), back)
    with pytest.raises(TrajectoryError, match=r"rows stored newest first"):
        load_trajectory(back)


def test_episodes_of_a_metadata_table_and_huge_indices_are_refused(tmp_path):
    """probe r35: ``critmoment episodes meta/episodes/chunk-000/file-000.parquet`` (LeRobot's
    episode metadata, no actions) listed "1 frames" episodes; a uint64 frame_index of 2**63
    read as -9223372036854775808."""
    meta = tmp_path / "file-000.parquet"
    pq.write_table(pa.table({"episode_index": pa.array([0, 1, 2], pa.int64()),
                             "length": pa.array([400, 400, 400], pa.int64())}), meta)
    with pytest.raises(TrajectoryError, match=r"expected episode data with a column 'action'.*"
                                              r"meta/episodes"):
        list_episodes(meta)
    huge = tmp_path / "huge.parquet"
    pq.write_table(pa.table({"action": pa.array([[0.0] * NA] * 2, pa.list_(pa.float64())),
                             "episode_index": pa.array([0, 0], pa.int64()),
                             "frame_index": pa.array([0, 2 ** 63], pa.uint64())}), huge)
    with pytest.raises(TrajectoryError, match=r"expected indices below 2\*\*63, got "
                                              r"9223372036854775808"):
        load_trajectory(huge)


def test_an_observed_path_round_trips_through_npz(tmp_path):
    """``observed`` (T, na): the joints' planned or recorded path, saved and read back bit
    for bit; it counts in the content hash only where present (other hashes unchanged)."""
    rng = np.random.default_rng(7)
    act = _actions(rng, 20)
    plain = Trajectory(actions=act, fps=50.0)
    traj = Trajectory(actions=act, fps=50.0, observed=act - 0.1)
    path = tmp_path / "t.npz"
    save_trajectory(traj, path)
    back = load_trajectory(path)
    np.testing.assert_array_equal(back.observed, act - 0.1)
    assert traj != plain
    assert traj.content_sha256() != plain.content_sha256()
    with pytest.raises(TrajectoryError, match="observed: expected finite values"):
        Trajectory(actions=act, fps=50.0, observed=np.where(act > 0, np.nan, act))
