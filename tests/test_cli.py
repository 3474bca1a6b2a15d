"""The command line: outputs, JSON keys, exit codes, errors as one clear line."""

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
                "min_fos_contact", "min_fos_motor", "max_cost"):
        assert key in doc
    assert doc["steps"] == 4000 and doc["final_stage"] == 4
    assert set(doc["stage_first_step"]) == {"1", "2", "3", "4"}
    assert (tmp_path / "recording.npz").is_file() and (tmp_path / "signals.png").is_file()


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
    assert "expected 14 action values" in capsys.readouterr().err
