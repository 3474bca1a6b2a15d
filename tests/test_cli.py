"""The command line: outputs, JSON keys, exit codes, errors as one clear line."""

import dataclasses
import json

import numpy as np
import pytest

from critmoment.cli import main


@pytest.fixture(scope="module")
def traj_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("cli") / "traj.npz"
    assert main(["demo", "--seed", "0", "--out", str(path)]) == 0
    return path


def test_demo_writes_a_trajectory(traj_file):
    with np.load(traj_file) as z:
        assert z["actions"].shape == (400, 14)
        assert float(z["fps"]) == 50.0


def test_rollout_json(traj_file, capsys, tmp_path):
    assert main(["rollout", str(traj_file), "--json", "--out", str(tmp_path)]) == 0
    doc = json.loads(capsys.readouterr().out)
    for key in ("steps", "dt", "max_stage", "final_stage", "stage_first_step",
                "min_fos_contact", "min_fos_motor", "max_cost", "fit_warnings"):
        assert key in doc
    assert doc["fit_warnings"] == []
    assert doc["steps"] == 4000 and doc["final_stage"] == 4
    assert doc["completed"] is True and doc["shortfalls"] == []
    assert set(doc["stage_first_step"]) == {"1", "2", "3", "4"}
    assert (tmp_path / "recording.npz").is_file() and (tmp_path / "signals.png").is_file()
    # held over the persistence window, a dip counts only when it lasts: never lower
    assert doc["persistence"] == pytest.approx(0.02) and doc["threshold"] == 0.9
    assert doc["min_fos_contact_sustained"] >= doc["min_fos_contact"]
    assert doc["max_cost_sustained"] <= doc["max_cost"]


def test_rollout_names_why_a_run_never_touches_its_object(tmp_path, capsys):
    """``rollout`` alone already says why a run does not complete: the fit warnings of
    ``analyze``'s preflight, on stderr and in the JSON."""
    import warnings

    from critmoment import suite
    from critmoment.trajectory import save_trajectory

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        traj = suite.make("no_grasp", seed=0)
    path = tmp_path / "miss.npz"
    save_trajectory(traj, path)
    assert main(["rollout", str(path), "--json"]) == 0
    captured = capsys.readouterr()
    doc = json.loads(captured.out)
    assert len(doc["fit_warnings"]) == 1
    assert "never touches the object" in doc["fit_warnings"][0]
    assert "critmoment rollout: warning:" in captured.err
    assert "never touches the object" in captured.err
    # and what the task's rule misses, measured
    assert doc["completed"] is False
    assert doc["shortfalls"] == [
        "left does not hold the object at the end (it never touched it)",
        "the object rests on its support at the end"]
    assert main(["rollout", str(path)]) == 0
    out = capsys.readouterr().out
    assert ("short of the task: left does not hold the object at the end (it never "
            "touched it); the object rests on its support at the end") in out
    # a stage is named, not only numbered ("final stage 0" read as an error code)
    assert "max stage 0 (untouched), final stage 0 (untouched) (NOT completed)" in out


def test_moments_json(traj_file, capsys):
    assert main(["moments", str(traj_file), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert 1 <= len(doc["moments"]) <= 8
    assert set(doc["moments"][0]) >= {"step", "time", "label", "reason", "score"}
    labels = {m["label"] for m in doc["moments"]}
    assert {"lift-off", "hand-over"} <= labels


def test_analyze_exit_codes(traj_file, capsys, tmp_path):
    code = main(["analyze", str(traj_file), "--samples", "32", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 1 and "CONDITIONAL" in out  # not SAFE over the whole box
    assert (tmp_path / "report.html").is_file() and (tmp_path / "report.json").is_file()
    doc = json.loads((tmp_path / "report.json").read_text())
    # a low enough required probability accepts the CONDITIONAL verdict
    assert main(["analyze", str(traj_file), "--samples", "32", "--json",
                 "--min-success", str(doc["p_success"] / 2)]) == 0
    assert json.loads(capsys.readouterr().out)["verdict"] == "CONDITIONAL"


def test_a_file_name_that_is_not_utf8_is_written_escaped(traj_file, capsys, tmp_path):
    """A trajectory named with a Latin-1 byte (``caf\xe9.npz``): the whole audit ran, then
    writing the report's HTML failed ("unexpected UnicodeEncodeError ... a bug")."""
    import os
    import shutil

    name = os.fsdecode(b"caf\xe9.npz")
    shutil.copy(traj_file, tmp_path / name)
    out = tmp_path / "out"
    assert main(["analyze", str(tmp_path / name), "--samples", "8", "--no-verify",
                 "--max-moments", "2", "--figures", "none", "--out", str(out)]) == 1
    doc = json.loads((out / "report.json").read_text(encoding="utf-8"))
    assert doc["manifest"]["trajectory"] == "caf\\xe9.npz"
    assert "caf\\xe9.npz" in (out / "report.html").read_text(encoding="utf-8")


def test_analyze_method_flags(traj_file, capsys):
    assert main(["analyze", str(traj_file), "--samples", "16", "--json", "--no-verify",
                 "--max-moments", "3", "--horizon", "5"]) == 1
    doc = json.loads(capsys.readouterr().out)
    assert doc["verification"] is None and len(doc["moments"]) == 3 and doc["horizon"] == 5
    assert doc["manifest"]["options"]["max_moments"] == 3
    assert doc["manifest"]["options"]["exhaustive"] is False
    assert main(["analyze", str(traj_file), "--samples", "16", "--json", "--no-verify",
                 "--max-moments", "3", "--horizon", "5", "--exhaustive"]) == 1
    full = json.loads(capsys.readouterr().out)
    assert full["manifest"]["options"]["exhaustive"] is True
    assert all(m["reached"] == 1.0 for m in full["moments"])
    assert full["p_success"] == doc["p_success"] and full["verdict"] == doc["verdict"]
    assert main(["analyze", str(traj_file), "--samples", "16", "--json", "--verify", "0.5"]) == 1
    assert json.loads(capsys.readouterr().out)["verification"]["fraction"] == 0.5
    assert main(["analyze", str(traj_file), "--verify", "2"]) == 2
    assert "verify" in capsys.readouterr().err


@pytest.mark.parametrize("args, message", [
    (["rollout", "missing.npz"], "does not exist"),
    (["rollout", "{traj}", "--scenario", "no_such_scenario"], "scenario file not found"),
    (["demo", "--out", "traj.txt"], "expected a path ending in .npz"),
])
def test_bad_input_exits_2_with_one_line(args, message, traj_file, capsys, monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)
    args = [a.format(traj=traj_file) for a in args]
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and message in err[0] and "Traceback" not in err[0]


def test_wrong_action_width_is_a_clear_error(tmp_path, capsys):
    path = tmp_path / "bad.npz"
    np.savez(path, actions=np.zeros((50, 12)), fps=50.0)
    assert main(["rollout", str(path)]) == 2
    err = capsys.readouterr().err
    assert "the trajectory has 12 action values per step" in err and "expects 14" in err
    assert "--scenario" in err


# -- issue 14: episodes, object pose, warnings, manifests, timings -------------------
@pytest.fixture(scope="module")
def lerobot_dataset(traj_file, tmp_path_factory):
    """A LeRobot dataset holding two 10-frame episodes of the demo."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    root = tmp_path_factory.mktemp("lerobot") / "ds"
    (root / "meta").mkdir(parents=True)
    (root / "meta" / "info.json").write_text('{"fps": 50}')
    (root / "data" / "chunk-000").mkdir(parents=True)
    with np.load(traj_file) as z:
        actions = z["actions"]
    rows = [list(map(float, r)) for r in np.r_[actions[:10], actions[100:110]]]
    pq.write_table(pa.table({"action": rows, "episode_index": [0] * 10 + [1] * 10,
                             "frame_index": list(range(10)) * 2}),
                   root / "data" / "chunk-000" / "episode_000000.parquet")
    return root


def test_episodes_lists_a_dataset(lerobot_dataset, capsys):
    assert main(["episodes", str(lerobot_dataset), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert [(e["index"], e["frames"]) for e in doc["episodes"]] == [(0, 10), (1, 10)]
    assert main(["episodes", str(lerobot_dataset)]) == 0
    out = capsys.readouterr().out
    assert "2 episode(s)" in out and "episode 1: 10 frames" in out


def test_episode_option_selects_the_episode(lerobot_dataset, capsys):
    pose = ["0.1", "0.5", "0.02", "1", "0", "0", "0"]
    assert main(["rollout", str(lerobot_dataset), "--episode", "1", "--json",
                 "--object-pose", *pose]) == 0
    cap = capsys.readouterr()
    assert json.loads(cap.out)["steps"] == 100  # 10 frames at 50 Hz, 500 Hz physics
    # the pose was given: no default-pose warning (a 0.2 s episode never reaches the cube,
    # which the fit check says)
    assert "gives no object start pose" not in cap.err
    assert main(["rollout", str(lerobot_dataset), "--json"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--episode" in err[0] and "[0, 1]" in err[0]


def test_default_pose_warning_is_one_line(lerobot_dataset, capsys):
    assert main(["rollout", str(lerobot_dataset), "--episode", "0", "--json"]) == 0
    warns = [line for line in capsys.readouterr().err.splitlines() if "gives no object start pose" in line]
    assert len(warns) == 1 and warns[0].startswith("critmoment rollout: warning: ")


def test_manifest_does_not_depend_on_the_path_spelling(traj_file, capsys, monkeypatch):
    monkeypatch.chdir(traj_file.parent)
    docs = []
    for spelling in (str(traj_file), traj_file.name, f"./../{traj_file.parent.name}/traj.npz"):
        assert main(["analyze", spelling, "--samples", "16", "--max-moments", "2",
                     "--no-verify", "--json"]) == 1
        doc = json.loads(capsys.readouterr().out)
        doc.pop("timings")
        docs.append(doc)
    assert docs[0] == docs[1] == docs[2]
    man = docs[0]["manifest"]
    assert man["trajectory"] == "traj.npz" and len(man["trajectory_sha256"]) == 64
    assert "/" not in (man["scenario_file"] or "")


def test_validate_puts_every_wall_time_under_timings(traj_file, capsys, tmp_path):
    tiny = tmp_path / "tiny.npz"
    with np.load(traj_file) as z:
        np.savez(tiny, actions=z["actions"][:10], fps=50.0, object_pose=z["object_pose"])
    assert main(["validate", str(tiny), "--samples", "4", "--max-moments", "1", "--no-verify",
                 "--json"]) in (0, 1)
    doc = json.loads(capsys.readouterr().out)
    assert set(doc["timings"]) == {"sparse_seconds", "brute_force_seconds", "compute_ratio"}
    assert doc["timings"]["sparse_seconds"] > 0


def test_verbose_errors_add_the_traceback(capsys):
    assert main(["-v", "rollout", "missing.npz"]) == 2
    err = capsys.readouterr().err
    assert "Traceback" in err and err.strip().splitlines()[-1].startswith(
        "critmoment rollout: error: ")


@pytest.mark.parametrize("name", ["SIGTERM", "SIGHUP", "SIGQUIT", "SIGUSR1"])
def test_sigterm_ends_a_run_as_ctrl_c_does(traj_file, tmp_path, capsys, monkeypatch, name):
    """``kill`` (SIGTERM) during an audit: exit 2, "interrupted", the previous output kept
    whole and no temporary folder left behind (it used to leave ``.DIR.critmoment-tmp-*``
    and die with 143); the process's own SIGTERM handler is back afterwards. The same for a
    closed terminal's SIGHUP, SIGQUIT and SIGUSR1 (they had left the folder, exit 129)."""
    import os
    import signal

    from critmoment import analysis

    if not hasattr(signal, name):
        pytest.skip(f"no {name} here")
    sig = getattr(signal, name)

    out = tmp_path / "report"
    assert main(["rollout", str(traj_file), "--out", str(out)]) == 0
    before = sorted(p.name for p in out.iterdir())
    capsys.readouterr()

    def killed(*args, **kwargs):
        os.kill(os.getpid(), sig)
        raise AssertionError(f"{name} did not stop the audit")

    monkeypatch.setattr(analysis, "analyze", killed)
    handler = signal.getsignal(sig)
    assert main(["analyze", str(traj_file), "--samples", "8", "--out", str(out)]) == 2
    assert "critmoment analyze: error: interrupted; no output was written" in capsys.readouterr().err
    assert sorted(p.name for p in out.iterdir()) == before
    assert [p.name for p in tmp_path.iterdir()] == ["report"]
    assert signal.getsignal(sig) is handler


def test_a_stop_signal_a_library_swallows_still_stops_the_run(traj_file, tmp_path, capsys,
                                                             monkeypatch):
    """A SIGTERM from another process, landing in CasADi's IPOPT call, had its interrupt
    swallowed there: the audit finished, replaced ``--out`` and exited 0 (3 of 18 timed
    kills). The handler's stop request stands: exit 2, the previous output kept whole."""
    import os
    import signal

    from critmoment import analysis

    out = tmp_path / "report"
    assert main(["rollout", str(traj_file), "--out", str(out)]) == 0
    before = sorted(p.name for p in out.iterdir())
    capsys.readouterr()
    real = analysis.analyze

    def swallowed(*args, **kwargs):
        try:
            os.kill(os.getpid(), signal.SIGTERM)
        except KeyboardInterrupt:
            pass  # as a library that catches it would
        return real(*args, **kwargs)

    monkeypatch.setattr(analysis, "analyze", swallowed)
    assert main(["analyze", str(traj_file), "--samples", "8", "--figures", "none",
                 "--out", str(out)]) == 2
    assert "interrupted" in capsys.readouterr().err
    assert sorted(p.name for p in out.iterdir()) == before
    assert [p.name for p in tmp_path.iterdir()] == ["report"]
    monkeypatch.setattr(analysis, "analyze", real)  # the next command is not stopped
    assert main(["rollout", str(traj_file), "--out", str(out)]) == 0


def test_a_closed_stdout_keeps_the_exit_code(traj_file, tmp_path):
    """``critmoment ... >&-``: Python's stdout is None, and flushing it had turned a
    finished command (its output written whole) into exit 2, "unexpected AttributeError"."""
    import os
    import subprocess
    import sys

    out = tmp_path / "rolled"
    proc = subprocess.run(
        [sys.executable, "-c", "from critmoment.cli import run; run()", "rollout",
         str(traj_file), "--out", str(out)], stderr=subprocess.PIPE, text=True,
        env={**os.environ, "MPLBACKEND": "Agg"}, preexec_fn=lambda: os.close(1),
        timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "AttributeError" not in proc.stderr and out.is_dir()


def test_a_closed_stderr_keeps_json_on_stdout_clean(traj_file, tmp_path):
    """``critmoment ... 2>&-``: Python's stderr is None and ``print(file=None)`` writes to
    stdout, so the warnings and the error line had landed in ``--json``'s document."""
    import os
    import subprocess
    import sys

    import numpy as np

    # a trajectory without its object pose: the run warns that the model's pose is used
    data = dict(np.load(traj_file))
    data.pop("object_pose", None)
    data.pop("qpos0", None)
    bare = tmp_path / "bare.npz"
    np.savez(bare, **data)

    def cli(*args):
        return subprocess.run(
            [sys.executable, "-c", "from critmoment.cli import run; run()", *args],
            stdout=subprocess.PIPE, text=True, env={**os.environ, "MPLBACKEND": "Agg"},
            preexec_fn=lambda: os.close(2), timeout=300)

    proc = cli("rollout", str(bare), "--json")
    assert proc.returncode == 0
    assert "steps" in json.loads(proc.stdout)  # the document alone
    proc = cli("rollout", str(tmp_path / "missing.npz"), "--json")
    assert proc.returncode == 2 and proc.stdout == ""


def test_a_console_that_cannot_encode_the_summary_keeps_the_exit_code(traj_file):
    """With PYTHONIOENCODING=ascii (or a console code page without "≤"), a SAFE or
    CONDITIONAL audit wrote its report whole and then exited 2 on a UnicodeEncodeError
    printing its summary: the characters are escaped, the code is the command's."""
    import os
    import subprocess
    import sys

    env = {**os.environ, "PYTHONIOENCODING": "ascii", "MPLBACKEND": "Agg"}
    proc = subprocess.run(
        [sys.executable, "-c", "from critmoment.cli import run; run()", "moments",
         str(traj_file)], capture_output=True, text=True, encoding="ascii",
        errors="strict", env=env, timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "UnicodeEncodeError" not in proc.stderr


def test_the_command_line_loads_the_heavy_libraries_inside_its_interrupt_handling():
    """``import critmoment.cli`` (what the console script does before ``main``) leaves
    NumPy, MuJoCo, Optuna, Pinocchio, CasADi, ruptures and the audit's modules unloaded: a
    Ctrl-C in the second they take to import is then caught by ``main`` (it printed a
    traceback, or exited 1 when it cut NumPy's initialisation short)."""
    import subprocess
    import sys

    code = ("import sys, critmoment.cli, critmoment; "
            "print(sorted(m for m in ('numpy', 'mujoco', 'optuna', 'pinocchio', 'casadi', 'ruptures', "
            "'critmoment.analysis', 'critmoment.sparse') if m in sys.modules)); "
            "print(critmoment.Twin.__name__, critmoment.sparse.__name__)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.splitlines()
    assert out == ["[]", "Twin critmoment.sparse"]


def test_ctrl_c_while_the_package_loads_exits_2_without_a_traceback(monkeypatch, capsys):
    import sys
    import types

    class Loading(types.ModuleType):
        def __getattr__(self, name):
            raise KeyboardInterrupt

    monkeypatch.setitem(sys.modules, "critmoment.twin", Loading("critmoment.twin"))
    assert main(["rollout", "missing.npz"]) == 2
    err = capsys.readouterr().err
    assert err == "critmoment: error: interrupted; no output was written\n"


def test_a_diverging_run_prints_one_line_and_writes_no_mujoco_log(tmp_path, capfd,
                                                                  monkeypatch):
    """MuJoCo's own log is off during a command: a diverging rollout used to leave
    MUJOCO_LOG.TXT in the user's folder and a MuJoCo warning on stderr before critmoment's
    error line; the log settings are back afterwards."""
    import shutil

    import mujoco

    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "stiff"
    shutil.copytree(bundled_scenario_path().parent, folder)
    arm = folder / "vx300s.xml"
    old = 'name="elbow" joint="elbow" kp="200" kv="6" forcerange="-15 15"'
    arm.write_text(arm.read_text().replace(old, 'name="elbow" joint="elbow" kp="3e5" kv="6"'))
    traj = tmp_path / "hold.npz"
    np.savez(traj, actions=np.tile([0, -0.96, 1.16, 0, -0.3, 0, 1.0] * 2, (20, 1)), fps=50.0)
    monkeypatch.chdir(tmp_path)
    before = mujoco.MjLogConfig.get()
    assert main(["rollout", str(traj), "--scenario", str(folder)]) == 2
    err = capfd.readouterr().err
    assert "critmoment rollout: error: simulation diverged at physics step" in err
    assert "Nan, Inf or huge value" not in err
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()
    after = mujoco.MjLogConfig.get()
    assert (after.logto_file, after.logto_console) == (before.logto_file, before.logto_console)


def test_library_log_lines_read_as_the_commands_own_warnings():
    """A library warning (critmoment.sparse's divergence line) prints as ``critmoment
    analyze: warning: ...`` (the logger named with --verbose), and the record keeps its own
    level name for other handlers."""
    import logging

    from critmoment.cli import _CommandFormatter

    record = logging.LogRecord("critmoment.sparse", logging.WARNING, __file__, 1,
                               "diverged at step %d", (7,), None)
    assert (_CommandFormatter("analyze", verbose=False).format(record)
            == "critmoment analyze: warning: diverged at step 7")
    assert (_CommandFormatter("analyze", verbose=True).format(record)
            == "critmoment analyze: warning: critmoment.sparse: diverged at step 7")
    assert record.levelname == "WARNING"


def test_a_signal_while_the_libraries_load_is_delivered_after_them(monkeypatch, capsys):
    """SIGINT during the imports in ``main`` waits for them to finish (held), then ends the
    run as an interruption: exit 2, one line."""
    import signal
    import sys
    import threading
    import types

    class Loading(types.ModuleType):
        def __getattr__(self, name):
            if name != "quiet_mujoco_log":
                raise AttributeError(name)
            # to this (the main) thread: a signal to the process would go to any other
            # thread earlier tests left running (MuJoCo's), and Python 3.11 handles a signal
            # caught there only later; at the command line no other thread exists yet
            signal.pthread_kill(threading.main_thread().ident, signal.SIGINT)  # held
            return lambda: __import__("contextlib").nullcontext()

    monkeypatch.setitem(sys.modules, "critmoment.twin", Loading("critmoment.twin"))
    # Python's own Ctrl-C handler, whatever this process inherited: a shell without job
    # control starts a background command with SIGINT ignored, and Python then keeps it so
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        assert main(["rollout", "missing.npz"]) == 2
    finally:
        signal.signal(signal.SIGINT, previous)
    assert capsys.readouterr().err == "critmoment: error: interrupted; no output was written\n"


def test_a_trajectory_naming_an_unknown_scenario_is_warned_of(traj_file, tmp_path, capsys):
    from critmoment.trajectory import load_trajectory, save_trajectory

    traj = load_trajectory(traj_file)
    path = tmp_path / "t.npz"
    save_trajectory(dataclasses.replace(traj, meta={**traj.meta, "scenario": "my_robot"}), path)
    assert main(["rollout", str(path)]) == 0
    err = capsys.readouterr().err
    assert "meta names scenario 'my_robot', which is not a bundled one" in err


def test_rollout_warns_of_what_analyze_would_refuse(traj_file, tmp_path, capsys):
    """A shoulder limit the motion exceeds: analyze exits 2 (the twin cannot follow);
    rollout runs what was asked, exit 0, and says so (it said nothing)."""
    import shutil

    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "weak"
    shutil.copytree(bundled_scenario_path().parent, folder)
    toml = folder / "scenario.toml"
    toml.write_text(toml.read_text().replace("shoulder = 20.0", "shoulder = 2.0"))
    assert main(["rollout", str(traj_file), "--scenario", str(folder), "--json"]) == 0
    out, err = capsys.readouterr()
    assert "cannot reproduce the nominal motion: actuator 'right/shoulder'" in err
    # holding the arm up, not its speed: its targets' acceleration peaks briefly in the
    # 3.4 s at the limit, and a cause read at that peak had called the motion too fast
    assert "right/shoulder') is at (or above) its force limit 2 N·m ([limits]) for 3.44 s" in err
    assert "too fast" not in err and "likely cause: too weak for the load" in err
    assert any("right/shoulder" in p for p in json.loads(out)["feasibility_problems"])
    # and the ground truth's verdict on the run itself, as analyze states it for the nominal
    # (a joint held at its limit by a bin's wall for 1.2 s had read "(completed)" alone)
    assert ("the run fails by the ground truth's rules: motor overload: actuator "
            "'right/shoulder' held at 99.9% of its force limit") in err
    assert json.loads(out)["ground_truth_failure"].startswith("motor overload")


def test_the_scenarios_fps_sets_the_rate_of_a_file_that_records_none(traj_file, capsys,
                                                                      tmp_path):
    from critmoment.scenario import bundled_scenario_path

    # the first 100 actions without 'fps' or 'time': 50 Hz assumed, unless the scenario's
    # [actions] fps says otherwise (it was parsed and ignored)
    with np.load(traj_file) as z:
        fields = {k: z[k] for k in z.files if k not in ("fps", "time")}
    fields["actions"] = fields["actions"][:100]
    bare = tmp_path / "bare.npz"
    np.savez(bare, **fields)
    bundled = bundled_scenario_path("aloha_transfer_cube").parent
    text = (bundled / "scenario.toml").read_text()
    text = text.replace('mjcf = "scene.xml"', f'mjcf = "{(bundled / "scene.xml").as_posix()}"')
    assert "fps = 50.0" in text
    (tmp_path / "s25.toml").write_text(text.replace("fps = 50.0", "fps = 25.0"))
    durations = {}
    for name, scenario in (("default", "aloha_transfer_cube"),
                           ("25", str(tmp_path / "s25.toml"))):
        assert main(["rollout", str(bare), "--scenario", scenario, "--json"]) in (0, 1)
        durations[name] = json.loads(capsys.readouterr().out)["duration"]
    assert durations == {"default": pytest.approx(2.0), "25": pytest.approx(4.0)}
    # a recorded rate stays authoritative
    assert main(["rollout", str(traj_file), "--scenario", str(tmp_path / "s25.toml"),
                 "--json"]) in (0, 1)
    assert json.loads(capsys.readouterr().out)["duration"] == pytest.approx(8.0)
    # the library reads the file as the command line does
    from critmoment import load_scenario, load_trajectory, rollout

    rec = rollout(load_trajectory(bare), load_scenario(tmp_path / "s25.toml"))
    assert (len(rec.states) - 1) * rec.dt == pytest.approx(4.0)


def test_the_console_command_keeps_the_exit_code_once_main_has_returned(monkeypatch, capsys):
    import signal

    from critmoment import cli

    saved = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
    try:
        monkeypatch.setattr(cli, "main", lambda: 1)
        with pytest.raises(SystemExit) as done:
            cli.run()
        assert done.value.code == 1
        # a Ctrl-C during the interpreter's shutdown no longer replaces the verdict's code
        assert signal.getsignal(signal.SIGINT) == signal.SIG_IGN

        def interrupted():
            raise KeyboardInterrupt

        monkeypatch.setattr(cli, "main", interrupted)
        with pytest.raises(SystemExit) as done:
            cli.run()
        assert done.value.code == 2 and "interrupted" in capsys.readouterr().err
    finally:
        for sig, handler in saved.items():
            signal.signal(sig, handler)


def test_an_interrupt_after_the_output_is_written_says_so(traj_file, tmp_path, capsys,
                                                          monkeypatch):
    """Ctrl-C while the summary printed (a slow pipe): the report was already swapped in
    whole, and the line said "no output was written"."""
    from critmoment import cli

    def cut(*args, **kwargs):
        raise KeyboardInterrupt

    out = tmp_path / "roll"
    monkeypatch.setattr(cli._Stdout, "emit", staticmethod(cut))
    assert main(["rollout", str(traj_file), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert f"critmoment rollout: error: interrupted after the output was written whole to " \
           f"{out}" in err
    assert (out / "recording.npz").is_file()


def test_demo_does_not_replace_a_file_it_did_not_write(tmp_path, capsys):
    import numpy as np

    mine = tmp_path / "episode.npz"
    np.savez(mine, data=np.arange(5))
    assert main(["demo", "--out", str(mine)]) == 2
    assert "exists and is not a trajectory critmoment demo wrote" in capsys.readouterr().err
    assert list(np.load(mine).files) == ["data"]
    ours = tmp_path / "traj.NPZ"
    assert main(["demo", "--out", str(ours)]) == 0
    assert main(["demo", "--out", str(ours), "--seed", "3"]) == 0  # its own: replaced
    assert main(["demo", "--out", str(mine), "--force"]) == 0
    assert "actions" in np.load(mine).files


def test_verbose_after_the_command_logs_the_audits_progress(traj_file, capsys):
    """`-v` logged nothing for analyze (progress went only to a terminal) and was refused
    after the command."""
    assert main(["analyze", str(traj_file), "--samples", "8", "--figures", "none", "-v"]) in (0, 1)
    err = capsys.readouterr().err
    assert "critmoment: rollout ..." in err and "critmoment: sweep done in" in err
    # with --json too (on stderr: stdout holds only the JSON); it had printed nothing
    assert main(["-v", "analyze", str(traj_file), "--samples", "8", "--json"]) in (0, 1)
    out, err = capsys.readouterr()
    assert "critmoment: sweep done in" in err and json.loads(out)["verdict"]


def test_version(capsys):
    from critmoment import __version__

    assert main(["--version"]) == 0
    assert capsys.readouterr().out.strip() == f"critmoment {__version__}"


def test_validate_min_agreement_fails_a_conservative_validation(traj_file, monkeypatch,
                                                               capsys):
    """genesis' franka_sim Panda: 60 false unsafes of 64 (agreement 0.062) exited 0, which a
    script checking the exit code could not see; --min-agreement makes it exit 1."""
    from types import SimpleNamespace

    from critmoment import validation

    fake = SimpleNamespace(confusion={"false_safe": 0}, vacuous=False, agreement=0.062,
                           to_json=lambda: {"agreement": 0.062}, summary_text=lambda: "summary")
    monkeypatch.setattr(validation, "validate", lambda *a, **k: fake)
    assert main(["validate", str(traj_file), "--samples", "8"]) == 0
    assert main(["validate", str(traj_file), "--samples", "8", "--min-agreement", "0.95"]) == 1
    fake.agreement = 0.97
    assert main(["validate", str(traj_file), "--samples", "8", "--min-agreement", "0.95"]) == 0


def test_a_model_without_force_limits_writes_json_with_nulls(tmp_path, capsys):
    """trossen-arm-sim's WidowX AI and gymnasium-robotics' ADROIT as shipped: no actuator
    has a force limit, the motor FOS is infinite, and ``rollout --json`` (and ``analyze``'s
    report.json, after the whole audit) died with "Out of range float values are not JSON
    compliant". JSON has no infinity: the FOS is null."""
    from inline_models import arm_scenario_toml, arm_xml

    from critmoment.trajectory import Trajectory, save_trajectory

    xml = arm_xml()
    for limit in (' forcerange="-60 60"', ' forcerange="-40 40"', ' forcerange="-20 20"'):
        xml = xml.replace(limit, "")
    assert "forcerange" not in xml
    (tmp_path / "arm.xml").write_text(xml)
    (tmp_path / "scenario.toml").write_text(arm_scenario_toml())
    t = np.linspace(0.0, 1.0, 51)
    traj = Trajectory(actions=np.stack([0.02 * t, -0.02 * t, np.ones_like(t)], axis=1),
                      fps=50.0)
    path = tmp_path / "traj.npz"
    save_trajectory(traj, path)
    capsys.readouterr()
    assert main(["rollout", str(path), "--scenario", str(tmp_path), "--json"]) in (0, 1)
    doc = json.loads(capsys.readouterr().out)
    assert doc["min_fos_motor"] is None and doc["limiting_actuator"] is None
    assert main(["rollout", str(path), "--scenario", str(tmp_path)]) in (0, 1)
    assert "(no force limit)" in capsys.readouterr().out


def test_a_full_standard_output_is_named(monkeypatch, capsys):
    """``critmoment rollout --json > /dev/full`` said only "No space left on device"."""
    import errno
    import io

    from critmoment import cli

    class Full(io.StringIO):
        def write(self, text):
            raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(cli._Stdout, "closed", False)
    monkeypatch.setattr(cli._Stdout, "silence", classmethod(lambda cls: None))
    monkeypatch.setattr("sys.stdout", Full())
    assert main(["inspect", _bundled_scene()]) == 2
    err = capsys.readouterr().err
    assert "writing to the standard output failed: No space left on device" in err


def _bundled_scene() -> str:
    from critmoment.scenario import load_scenario

    return str(load_scenario().mjcf)


def test_report_json_records_the_runs_warnings(traj_file, tmp_path, capsys):
    """Input warnings (here: an unknown key in the trajectory file, which is ignored) went
    to stderr only; the archived report said nothing of them."""
    with np.load(traj_file) as z:
        arrays = dict(z)
    arrays["my_extra_key"] = np.zeros(3)
    np.savez(tmp_path / "extra.npz", **arrays)
    out = tmp_path / "rep"
    assert main(["analyze", str(tmp_path / "extra.npz"), "--samples", "16", "--max-moments",
                 "2", "--no-verify", "--figures", "none", "--out", str(out)]) == 1
    err = capsys.readouterr().err
    doc = json.loads((out / "report.json").read_text())
    assert doc["warnings"] and any("my_extra_key" in w for w in doc["warnings"])
    for w in doc["warnings"]:
        assert f"critmoment analyze: warning: {w}" in err


def test_rollout_runs_the_contact_models_check(tmp_path, capsys):
    """rollout said "completed" of a nominal grip whose own cube moved 3 cm in a Jaco hand
    (round 32); it now runs the contact model's check as analyze and validate do: a soft
    cube contact on the bundled Panda (solref 0.05) moves the nominal cube about 14 mm."""
    import shutil

    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "soft"
    shutil.copytree(bundled_scenario_path("panda_pick_place").parent, folder)
    scene = folder / "scene.xml"
    scene.write_text(scene.read_text().replace('solref="0.01 1"/>', 'solref="0.05 1"/>'))
    traj = tmp_path / "panda.npz"
    assert main(["demo", "--scenario", "panda_pick_place", "--seed", "0", "--out",
                 str(traj)]) == 0
    capsys.readouterr()
    assert main(["rollout", str(traj), "--scenario", str(folder), "--json"]) == 0
    out, err = capsys.readouterr()
    assert "the nominal run's own object moves 1" in err
    assert "slip is counted beyond that" in json.loads(out)["contact_model"]


def test_negative_numbers_in_exponent_notation_are_values():
    """argparse reads only -1 and -0.5 as negative numbers: a pose printed with %g
    (``--object-pose ... 1 -3.4e-05 0 0``) was refused, "expected 7 arguments"."""
    from critmoment.cli import build_parser

    args = build_parser().parse_args(["rollout", "t.npz", "--object-pose", "0.1", "0.2",
                                      "0.3", "1", "-3.4e-05", "-0.", "-1E3"])
    assert args.object_pose == [0.1, 0.2, 0.3, 1.0, -3.4e-05, -0.0, -1000.0]
    args = build_parser().parse_args(["init", "m.xml", "--object", "cube", "--task",
                                      "pick_place", "--goal", "-1e-2", "-.5", "2e-1"])
    assert args.goal == [-0.01, -0.5, 0.2]


def test_a_broken_dependency_is_an_error_not_the_not_safe_code(tmp_path):
    """A library that fails to load (a broken install, too little memory) raised from the
    parser's construction: a raw traceback and exit 1, the "not safe" code, on every
    command."""
    import os
    import subprocess
    import sys

    broken = tmp_path / "ruptures"
    broken.mkdir()
    (broken / "__init__.py").write_text("raise RuntimeError('broken install')\n")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(tmp_path), *sys.path])}
    proc = subprocess.run([sys.executable, "-c", "from critmoment.cli import run; run()",
                           "--version"], capture_output=True, text=True, env=env, timeout=300)
    assert proc.returncode == 2
    assert proc.stderr.strip().splitlines() == [
        "critmoment: error: RuntimeError: broken install (a dependency is missing or broken: "
        "reinstall critmoment)"]


def test_running_out_of_memory_or_threads_is_not_called_a_bug():
    """Under ``ulimit -v`` the run failed with "unexpected ValueError: thread constructor
    failed ... (a bug in critmoment)", or a CasADi plugin that could not load."""
    from critmoment.cli import _describe

    said = _describe(ValueError("thread constructor failed: Resource temporarily unavailable"))
    assert said.startswith("out of resources") and "bug" not in said
    said = _describe(RuntimeError(".../casadi_nlpsol.cpp:41: Plugin 'ipopt' is not found."))
    assert "solver plugin could not load" in said and "bug" not in said
    assert "a bug in critmoment" in _describe(RuntimeError("something else"))
    # the model's own arena (<size memory>) is not the machine's memory: lowering --samples
    # or a ulimit does not help (probe r37)
    said = _describe(RuntimeError(
        "MuJoCo raised in 1 of 14 simulations (4); simulation 4: mj_stackAlloc: out of memory, "
        "stack overflow at PrimalAllocate ... narena = 43008 (increase <size memory=\"...\"/>)"))
    assert said.startswith("the model's arena is too small for this run") and "ulimit" not in said
    assert 'raise <size memory="..."/> in the MJCF' in said
    from critmoment.recording import _divergence_words

    assert "raise <size memory" in _divergence_words("mjWARN_CNSTRFULL")
    assert "size memory" not in _divergence_words("mjWARN_BADQACC")


def test_fps_gives_the_rate_of_a_file_that_records_none_under_its_name(traj_file, capsys,
                                                                       tmp_path):
    """probe r35: the errors said "give the rate (--fps)", but no command took --fps. An ACT
    episode whose rate is a root attribute ``dt`` is refused without it and read at the
    given rate with it; a rate that disagrees with a recorded one is an error."""
    import h5py

    with np.load(traj_file) as z:
        actions = z["actions"]
    path = tmp_path / "episode.hdf5"
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=actions)
        f.attrs["dt"] = 0.02
    pose = ["--object-pose", "0.0", "0.5", "0.02", "1", "0", "0", "0"]
    assert main(["rollout", str(path), *pose, "--json"]) == 2
    assert "look(s) like the episode's time base" in capsys.readouterr().err
    assert main(["rollout", str(path), *pose, "--fps", "50", "--json"]) in (0, 1)
    assert json.loads(capsys.readouterr().out)["steps"] == 4000
    assert main(["rollout", str(traj_file), "--fps", "25", "--json"]) == 2
    assert "disagrees with the rate 50 Hz recorded" in capsys.readouterr().err
    assert main(["rollout", str(path), "--fps", "0"]) == 2


def test_the_manifest_names_the_episode_audited(lerobot_dataset, capsys):
    """probe r35: two episodes of one dataset file gave identical manifests (the file's name
    and hash): the report never said which episode it audited."""
    docs = []
    for ep in ("0", "1"):
        assert main(["analyze", str(lerobot_dataset), "--episode", ep, "--samples", "8",
                     "--figures", "none", "--json", "--no-verify"]) in (0, 1)
        docs.append(json.loads(capsys.readouterr().out))
    assert [d["manifest"]["episode"] for d in docs] == [0, 1]
