"""Reports and output folders: written whole or not at all, one run per folder."""

from __future__ import annotations

import dataclasses
import errno
import json
import os
import re
import threading
import warnings
from pathlib import Path

import pytest

from critmoment import report
from critmoment.exceptions import OutputError
from critmoment.report import (
    MARKER,
    Figures,
    StagedOutput,
    check_output_path,
    report_json,
    write_report,
)


@pytest.fixture(scope="module")
def audit():
    import critmoment as cm
    from critmoment import analysis, demos

    twin = cm.Twin(cm.load_scenario())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        traj = demos.scripted_transfer(0, twin=twin)
        return analysis.analyze(traj, twin=twin, options=analysis.AnalyzeOptions(
            seed=0, n_samples=16, max_moments=2, verify=None))


def _files(folder):
    return sorted(os.listdir(folder))


@pytest.mark.parametrize("figures, pngs", [
    (Figures.NONE, set()),
    (Figures.SUMMARY, {"signals.png", "moments.png", "cost_map.png"}),
    (Figures.ALL, {"signals.png", "moments.png", "cost_map.png", "moment_*"}),
])
def test_write_report_figures(audit, tmp_path, figures, pngs):
    paths = write_report(audit, tmp_path / "r", figures=figures)
    names = set(_files(tmp_path / "r"))
    assert {"report.json", "report.html", MARKER} <= names
    got = {n for n in names if n.endswith(".png")}
    per_moment = {n for n in got if n.startswith("moment_")}
    assert got - per_moment == pngs - {"moment_*"}
    assert len(per_moment) == (len(audit.moments) if figures is Figures.ALL else 0)
    doc = json.loads((tmp_path / "r" / "report.json").read_text())
    assert doc["verdict"] == audit.verdict.value
    html = (tmp_path / "r" / "report.html").read_text(encoding="utf-8")
    assert html.count("data:image/png;base64,") == len(got)
    assert all(p.parent == tmp_path / "r" for p in paths.values())
    marker = json.loads((tmp_path / "r" / MARKER).read_text())
    assert marker["command"] == "analyze" and "report.json" in marker["files"]
    assert _files(tmp_path) == ["r"]  # no temporary folder left


def test_rewrite_replaces_the_whole_folder(audit, tmp_path):
    out = tmp_path / "r"
    write_report(audit, out, figures="all")
    stale = sorted(n for n in _files(out) if n.startswith("moment_"))
    assert stale
    write_report(audit, out, figures="none")
    assert not [n for n in _files(out) if n.endswith(".png")]  # nothing of the earlier run


def test_failed_run_keeps_the_previous_output(tmp_path):
    out = tmp_path / "r"
    with StagedOutput(out, command="test") as stage:
        (stage.path / "report.json").write_text("old")
    with pytest.raises(RuntimeError, match="boom"), StagedOutput(out, command="test") as stage:
        (stage.path / "report.json").write_text("new, half-writ")
        raise RuntimeError("boom")
    assert (out / "report.json").read_text() == "old"
    assert _files(tmp_path) == ["r"]


def test_disk_full_is_an_output_error_and_changes_nothing(tmp_path):
    out = tmp_path / "r"
    with StagedOutput(out, command="test") as stage:
        (stage.path / "report.json").write_text("old")
    with pytest.raises(OutputError, match="writing failed, nothing was changed"), \
            StagedOutput(out, command="test"):
        raise OSError(errno.ENOSPC, "No space left on device")
    assert (out / "report.json").read_text() == "old"
    assert _files(tmp_path) == ["r"]


def test_swap_without_renameat2(tmp_path, monkeypatch):
    monkeypatch.setattr(report, "_exchange", lambda a, b: False)
    out = tmp_path / "r"
    for text in ("one", "two"):
        with StagedOutput(out, command="test") as stage:
            (stage.path / f"{text}.json").write_text(text)
    assert _files(out) == [MARKER, "two.json"]
    assert _files(tmp_path) == ["r"]


def test_a_mount_point_is_written_in_place(tmp_path, monkeypatch):
    """A folder that is a mount point (a container's results volume given as ``--out``)
    can be neither swapped nor renamed (EBUSY): the whole audit ran and then failed with
    "cannot move the output into place". It is now staged inside and filled file by file;
    an earlier output's files the new one lacks go, other files make it refused."""
    out = tmp_path / "volume"
    out.mkdir()
    monkeypatch.setattr(os.path, "ismount", lambda p: os.fspath(p) == os.fspath(out))

    def busy(a, b):
        raise OSError(errno.EBUSY, "Device or resource busy", str(b))

    monkeypatch.setattr(report, "_exchange", busy)
    for names in (("report.json", "signals.png"), ("report.json",)):
        with StagedOutput(out, command="test") as stage:
            for name in names:
                (stage.path / name).write_text(name)
        assert _files(out) == sorted([MARKER, *names])
    assert _files(tmp_path) == ["volume"]
    (out / "notes.txt").write_text("mine")
    with pytest.raises(OutputError, match="other files"):
        StagedOutput(out, command="test")


def test_a_shared_folder_without_a_marker_keeps_the_users_pictures(tmp_path):
    """``write_report`` into a folder of the user's (shared) removed their own
    ``signals.png`` when the folder had no marker: files named like figures were taken for
    an earlier output's. Only files a marker lists are an earlier output's there."""
    out = tmp_path / "work"
    out.mkdir()
    for name in ("signals.png", "moment_12.png", "traj.npz"):
        (out / name).write_text("user's")
    with StagedOutput(out, command="test", shared=True) as stage:
        (stage.path / "report.json").write_text("new")
    assert _files(out) == sorted([MARKER, "moment_12.png", "report.json", "signals.png",
                                  "traj.npz"])
    assert (out / "signals.png").read_text() == "user's"
    # a marked earlier output's files the new one lacks are removed
    with StagedOutput(out, command="test", shared=True) as stage:
        (stage.path / "other.json").write_text("newer")
    assert "report.json" not in _files(out) and "signals.png" in _files(out)


def test_concurrent_runs_do_not_interleave(tmp_path):
    out = tmp_path / "r"
    barrier = threading.Barrier(4)

    def run(k):
        with StagedOutput(out, command="test") as stage:
            for i in range(20):
                (stage.path / f"run{k}_{i}.json").write_text(str(k))
                if i == 10:
                    barrier.wait()  # every run is half-written at the same time

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    names = [n for n in _files(out) if n != MARKER]
    runs = {n.split("_")[0] for n in names}
    assert len(runs) == 1 and len(names) == 20  # one whole run, not a mix
    assert _files(tmp_path) == ["r"]


@pytest.mark.parametrize("setup, match", [
    (lambda tmp: (tmp / "f").write_text("x") and tmp / "f", "existing file"),
    (lambda tmp: (tmp / "f").write_text("x") and tmp / "f" / "sub", "is a file"),
    (lambda tmp: ((tmp / "home").mkdir(), (tmp / "home" / "notes.txt").write_text("x"),
                  tmp / "home")[2], "other files"),
    (lambda tmp: tmp / ("n" * 400), "cannot be used|at most"),
])
def test_bad_destinations_are_refused_before_work(tmp_path, setup, match):
    dest = setup(tmp_path)
    before = _files(tmp_path)
    with pytest.raises(OutputError, match=match):
        StagedOutput(dest, command="test")
    assert _files(tmp_path) == before


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux's /proc")
def test_a_folder_where_no_file_can_be_created_says_so():
    """/proc takes no new files: the message said only "No such file or directory"."""
    with pytest.raises(OutputError, match=r"cannot write in '/proc' \(.*\); expected "
                                          r"a folder on a writable file system"):
        with StagedOutput("/proc/critmoment-report", command="analyze"):
            pass


def test_a_file_destination_and_a_folder_in_its_place(tmp_path):
    with StagedOutput(tmp_path / "a" / "t.npz", command="demo", kind="file") as stage:
        stage.path.write_bytes(b"npz")
    assert (tmp_path / "a" / "t.npz").read_bytes() == b"npz"
    assert _files(tmp_path / "a") == ["t.npz"]
    (tmp_path / "d.npz").mkdir()
    with pytest.raises(OutputError, match="existing folder"):
        StagedOutput(tmp_path / "d.npz", command="demo", kind="file")


def test_legacy_output_without_marker_is_replaceable(tmp_path):
    out = tmp_path / "r"
    out.mkdir()
    for name in ("signals.png", "moment_12.png"):
        (out / name).write_text("old")
    (out / "report.json").write_text('{"schema": "critmoment.report/1", "verdict": "SAFE"}')
    (out / "report.html").write_text("<html><title>critmoment report</title></html>")
    assert check_output_path(out) == out.resolve()


def test_a_folder_of_the_users_pictures_is_not_an_earlier_output(tmp_path):
    """Without the marker only the figure names critmoment writes count as its own: a
    folder of photos was replaced whole (and the photos deleted)."""
    out = tmp_path / "pics"
    out.mkdir()
    (out / "holiday.png").write_text("photo")
    with pytest.raises(OutputError, match="holiday.png"):
        check_output_path(out)
    # a marker nested too deeply to parse is no marker (it raised RecursionError)
    (out / ".critmoment-output.json").write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(OutputError, match="holiday.png"):
        check_output_path(out)


def test_dollar_signs_are_not_mathtext():
    assert report._tex_safe("run $\\frac{1$.npz") == "run \\$\\frac{1\\$.npz"


def test_figures_parse():
    assert Figures.parse("ALL") is Figures.ALL
    with pytest.raises(Exception, match="figures: expected one of"):
        Figures.parse("pretty")


def test_the_working_directory_is_never_replaced(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(OutputError, match="current working directory"):
        StagedOutput(".", command="test")
    (tmp_path / "sub").mkdir()
    monkeypatch.chdir(tmp_path / "sub")
    with pytest.raises(OutputError, match="current working directory"):
        StagedOutput("..", command="test")


def test_write_report_keeps_other_files_beside_the_report(audit, tmp_path):
    (tmp_path / "traj.npz").write_bytes(b"the user's trajectory")
    (tmp_path / "notes").mkdir()
    write_report(audit, tmp_path, figures="all")
    first = set(_files(tmp_path))
    assert {"traj.npz", "notes", "report.json", "report.html", MARKER} <= first
    write_report(audit, tmp_path, figures="none")  # a later report replaces the earlier one
    assert set(_files(tmp_path)) == {"traj.npz", "notes", "report.json", "report.html", MARKER}
    assert (tmp_path / "traj.npz").read_bytes() == b"the user's trajectory"
    with pytest.raises(OutputError, match="other files"):  # strict, as the CLI's --out
        StagedOutput(tmp_path, command="analyze")


def test_reused_moment_figure_draws_what_a_fresh_one_draws(audit):
    """The per-moment PNGs come from one figure whose lines are updated: byte-identical."""
    reused = dict(report._moment_pngs(audit))
    assert len(reused) == len(audit.moments) >= 2
    for mr in audit.moments:
        step = int(mr.moment.step)
        fresh = report._png(report._lighten(report.plot_curves(audit, step)))
        assert reused[f"moment_{step}"] == fresh


def test_a_special_file_is_never_replaced_as_an_output(tmp_path):
    import os

    fifo = tmp_path / "out.npz"
    os.mkfifo(fifo)
    with pytest.raises(OutputError, match="special file"):
        StagedOutput(fifo, command="demo", kind="file")
    assert not fifo.is_file() and fifo.exists()


def test_the_verification_line_counts_the_chain_failures_its_rollouts_overruled():
    # 12 chained failures, 2 doubtful ones re-run in full and 1 confirmed: 11 fail, as the
    # causes' line says; the line said only "12 of them fail there"
    from critmoment.report import _verification_text

    text = _verification_text({"near": 9, "cost_from": 0.72, "near_failed": 7, "chained": 16,
                               "chained_failed": 12, "chained_rolled_out": 2,
                               "chained_confirmed": 1})
    assert text.endswith("12 of them fail there (2 of those re-run in full, 1 confirmed: "
                         "11 fail)")


def test_the_headline_cost_says_where_it_is_taken_and_the_whole_runs_when_higher(audit):
    """A report said "nominal max cost 0.000" where `rollout` said 1.000 for the same run:
    the headline is the moments' figure; the nominal run's cost held over the persistence
    is added when it is higher."""
    import dataclasses

    from critmoment.report import summary_text

    held = audit.recording.sustained(audit.scenario)
    head = summary_text(audit).splitlines()[1]
    assert f"nominal max cost {audit.nominal_cost:.3f} at the audited moments" in head
    low = dataclasses.replace(audit, nominal_cost=held["max_cost_sustained"] - 0.05)
    head = summary_text(low).splitlines()[1]
    assert head.endswith(f"; over the whole nominal run {held['max_cost_sustained']:.3f} (held "
                         f"20 ms, at t = {held['max_cost_sustained_time']:.2f} s)")
    # above the threshold on a run that completes its task: said to be the force ratio alone
    from critmoment.scenario import CostParams

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        strict = audit.scenario.replace(cost=CostParams(threshold=held["max_cost_sustained"]
                                                        - 0.02))
    head = summary_text(dataclasses.replace(low, scenario=strict)).splitlines()[1]
    assert head.endswith("s), by the force ratio alone: the nominal run completes its task, "
                         "which decides it")


def test_a_moment_failing_only_in_combination_does_not_say_never_crosses(audit):
    """A moment line read "max cost 1.000 ...; critical: never crosses": the worst case
    combined two parameters, while the critical values move one alone."""
    import dataclasses

    from critmoment.report import summary_text

    mr = audit.moments[0]
    high = dataclasses.replace(mr, max_cost=2.0, critical={k: None for k in mr.critical})
    low = dataclasses.replace(mr, max_cost=0.1, critical={k: None for k in mr.critical})
    text = summary_text(dataclasses.replace(audit, moments=[high, low]))
    lines = [ln for ln in text.splitlines() if ln.startswith(("  1.", "  2."))]
    assert lines[0].endswith("critical: none of one parameter alone (the others at nominal)")
    assert lines[1].endswith("critical: never crosses")


def test_the_verification_line_names_the_margin_reruns():
    from critmoment.report import _verification_text

    text = _verification_text({"near": 0, "cost_from": 0.72, "near_failed": 0, "margin": 39,
                               "margin_failed": 0})
    assert text.endswith("; 39 failing only by the cost's margin with every motor under its "
                         "limit re-run in full, 0 of them fail")


def test_a_moment_audited_before_the_runs_end_is_drawn(tmp_path, twin, demo_traj):
    """A moment within the horizon of the run's end is audited from the last step whose
    horizon fits; the report looked its curves up under the moment's own step (KeyError,
    "a bug in critmoment", Menagerie Panda pick_hold cut at 330 actions)."""
    import json

    from critmoment import analysis
    from critmoment.report import Figures, write_report

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        report = analysis.analyze(demo_traj, twin=twin, options=analysis.AnalyzeOptions(
            seed=0, n_samples=8, max_moments=8, horizon=500, search=False, critical_grid=5,
            map_resolution=6))
    moved = [mr for mr in report.moments if mr.step != mr.moment.step]
    assert moved and all(mr.step == report.recording.n_steps - 500 for mr in moved)
    write_report(report, tmp_path / "out", figures=Figures.ALL)
    doc = json.loads((tmp_path / "out" / "report.json").read_text())
    assert [m["audited_step"] for m in doc["moments"]] == [mr.step for mr in report.moments]
    assert (tmp_path / "out" / f"moment_{moved[0].moment.step}.png").is_file()


def test_a_worst_case_over_the_threshold_that_does_not_fail_says_why(twin, demo_recording,
                                                                     audit):
    """The demo's hand-over moment read "max cost 0.923 at mass=10, friction=0.2; ... fails
    0% of the box here; critical: none of one parameter alone": a cost over the threshold
    0.9 beside no failure. The worst case's own evaluation passes it (the contact term
    keeps the cost over the threshold for less than the persistence): the line says so,
    and report.json carries it."""
    import dataclasses

    from critmoment.analysis import _passing_note, audit_evaluator
    from critmoment.report import report_json, summary_text

    ev, _ = audit_evaluator(demo_recording, twin)
    one = ev.evaluate([3241], [[10.0, 0.2]])
    assert one.cost[0, 0] > twin.scenario.cost.threshold and not one.failed[0, 0]
    note = _passing_note(one, ev)
    assert re.fullmatch(r"the cost stays over the threshold for \d+ ms, under the 20 ms a "
                        r"contact failure must persist", note)
    mr = dataclasses.replace(audit.moments[0], max_cost=float(one.cost[0, 0]),
                             critical={k: None for k in audit.moments[0].critical},
                             worst_fails=False, worst_note=note)
    report = dataclasses.replace(audit, moments=[mr])
    line = next(ln for ln in summary_text(report).splitlines() if ln.startswith("  1."))
    assert f"(not a failure: {note})" in line
    assert line.endswith("critical: none: the worst case does not fail")
    doc = report_json(report)
    assert doc["moments"][0]["worst_fails"] is False and doc["moments"][0]["worst_note"] == note
    # and the failure causes do not list it
    from critmoment.verdict import _causes

    assert _causes([dataclasses.replace(mr, dominant="contact", fail_fraction=0.0)], 0.9) == []


def test_the_report_names_each_parameter_kind_as_the_scenario_does(audit):
    """report.json wrote com_offset and force_limit as "comoffset" and "forcelimit", names
    no scenario accepts."""
    from critmoment import params

    box = audit.scenario.box
    extra = (params.ComOffsetParameter(name="com", target="box", low=-0.01, high=0.01,
                                       nominal=0.0),
             params.ForceLimitParameter(name="grip", target="left/left_finger", low=1.0,
                                        high=5.0, nominal=5.0))
    wide = dataclasses.replace(box, parameters=box.parameters + extra)
    doc = report_json(dataclasses.replace(
        audit, scenario=dataclasses.replace(audit.scenario, box=wide)))
    assert {k: v["kind"] for k, v in doc["uncertainty"].items()} == {
        "mass": "mass", "friction": "friction", "com": "com_offset", "grip": "force_limit"}
    assert all(params.kind_of(cls.__new__(cls)) == kind
               for kind, (cls, _) in params.PARAMETER_KINDS.items())


_READ_ONLY_SCRIPT = """
import os, sys
from pathlib import Path
from critmoment.report import StagedOutput
out = Path(sys.argv[1]) / "r"
with StagedOutput(out, command="test") as stage:
    (stage.path / "report.json").write_text("old")
os.chmod(out, 0o555)
with StagedOutput(out, command="test") as stage:
    (stage.path / "report.json").write_text("new")
print(sorted(os.listdir(out.parent)), (out / "report.json").read_text())
"""


def test_a_read_only_earlier_output_leaves_nothing_behind(tmp_path):
    """An earlier output folder made read-only was replaced, and the old one stayed, whole,
    as ``.r.critmoment-tmp-*`` (its files could not be removed from a read-only folder),
    where a batch globbing ``**/report.json`` found the old report. Run without the
    privilege to ignore permissions (root's is dropped with setpriv)."""
    import shutil
    import subprocess
    import sys

    cmd = [sys.executable, "-c", _READ_ONLY_SCRIPT, str(tmp_path)]
    if os.geteuid() == 0:
        if shutil.which("setpriv") is None:
            pytest.skip("root without setpriv: permissions cannot be made to apply")
        cmd = ["setpriv", "--bounding-set", "-dac_override,-dac_read_search,-fowner"] + cmd
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "['r'] new"


def test_the_runs_warnings_are_in_the_page_too(audit, tmp_path):
    """report.json keeps the run's warnings; the HTML page showed none of them."""
    warned = dataclasses.replace(audit, warnings=("the object moves 9.8 mm <before> the grasp",))
    write_report(warned, tmp_path / "w", figures=Figures.NONE)
    html = (tmp_path / "w" / "report.html").read_text(encoding="utf-8")
    assert "<h2>Warnings</h2>" in html and "9.8 mm &lt;before&gt; the grasp" in html
    write_report(audit, tmp_path / "q", figures=Figures.NONE)
    assert "<h2>Warnings</h2>" not in (tmp_path / "q" / "report.html").read_text(encoding="utf-8")


def test_the_model_hash_is_the_compiled_models(tmp_path):
    """``model_sha256`` hashed the *.xml files beside the scene when the report was
    written: an unrelated XML there changed it, tripled link masses in an included file
    of a subfolder did not. It is the compiled model's now, taken when the twin loads."""
    import shutil

    import critmoment as cm
    from critmoment.recording import model_hash
    from critmoment.scenario import bundled_scenario_path

    src = bundled_scenario_path("aloha_transfer_cube").parent
    copy = tmp_path / "copy"
    shutil.copytree(src, copy)
    base = cm.Twin(cm.load_scenario(copy))
    assert base.model_sha256 == cm.Twin(cm.load_scenario(src)).model_sha256  # path-free
    (copy / "notes.xml").write_text("<notes/>")
    assert model_hash(cm.load_scenario(copy)) == base.model_sha256
    arm = copy / "vx300s.xml"
    text = arm.read_text()
    heavier = text.replace('mass="', 'mass="3', 1)
    assert heavier != text
    arm.write_text(heavier)
    assert model_hash(cm.load_scenario(copy)) != base.model_sha256
    assert model_hash(base) == base.model_sha256  # the twin's, as it loaded


def test_a_long_multibyte_output_name_is_staged_beside_it(tmp_path):
    """An output folder named with 84 CJK characters (252 bytes, a valid name): its
    staging name kept 80 characters (240 bytes) and was refused, "File name too long"."""
    out = tmp_path / ("質" * 84)
    with StagedOutput(out, command="test") as stage:
        (stage.path / "report.json").write_text("{}")
    assert (out / "report.json").read_text() == "{}"
    assert report._head("質" * 84).encode() == ("質" * 26).encode()


def test_another_tools_report_in_an_unmarked_folder_is_not_replaced(tmp_path):
    """A CI folder holding only pytest-html's ``report.html``: taken for an earlier
    critmoment output (its name) and replaced whole. Without a marker, a file named like
    an output counts as one only by its content."""
    out = tmp_path / "ci_reports"
    out.mkdir()
    (out / "report.html").write_text("<html><title>pytest-html</title></html>")
    with pytest.raises(OutputError, match="other files"):
        StagedOutput(out, command="test")
    # an unmarked earlier critmoment report (before the marker) is still replaced
    (out / "report.html").write_text("<html><title>critmoment report</title></html>")
    (out / "report.json").write_text('{"schema": "critmoment.report/1", "verdict": "SAFE"}')
    with StagedOutput(out, command="test") as stage:
        (stage.path / "rollout.json").write_text("{}")
    assert _files(out) == [MARKER, "rollout.json"]


def test_warnings_raised_drawing_the_figures_are_recorded(audit, tmp_path, monkeypatch):
    """A parameter named in a script the figures' font lacks: matplotlib's "Glyph ...
    missing" was printed as the CLI's warning, but report.json said "warnings": []."""
    import json
    import warnings

    drawn = report.report_figures

    def lacking_a_glyph(*args, **kwargs):
        warnings.warn("Glyph 36136 missing from font(s) DejaVu Sans.", UserWarning,
                      stacklevel=2)
        return drawn(*args, **kwargs)

    monkeypatch.setattr(report, "report_figures", lacking_a_glyph)
    with pytest.warns(UserWarning, match="Glyph 36136"):
        report.write_report_files(audit, tmp_path, figures="summary", record_warnings=True)
    doc = json.loads((tmp_path / "report.json").read_text())
    assert doc["warnings"][-1] == "Glyph 36136 missing from font(s) DejaVu Sans."
    assert "Glyph 36136" in (tmp_path / "report.html").read_text()
