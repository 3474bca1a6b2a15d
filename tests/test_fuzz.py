"""A generated corpus of bad inputs: every one ends in one clear line, exit 2, nothing written.

Classes (issue 14): A wrong answers / exit codes, B output folders, C memory and work
bounds, D readers, E scenario values, F seeds, G multi-episode LeRobot data,
H reproducibility. Each case runs the CLI in-process (``critmoment.cli.main``) and checks

* the exit code (2, or the verdict's code for the closed-pipe cases of class A),
* exactly one line on stderr, ``critmoment COMMAND: error: ...``, and no traceback,
* the output folder (a previous run's output) byte-for-byte unchanged, and no
  temporary folder left beside it.

The inputs are tiny and fail before any physics, except the few marked as running a real
audit (class A's closed pipe).
"""

from __future__ import annotations

import hashlib
import io
import json
import math
import os
import shutil
import subprocess
import sys
import zipfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import h5py
import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

from critmoment.cli import main
from critmoment.report import MARKER

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

MODELS = Path(__file__).resolve().parents[1] / "models" / "aloha_transfer_cube"


# -- assets ------------------------------------------------------------------------
@pytest.fixture(scope="module")
def assets(tmp_path_factory):
    """A valid demo trajectory, a tiny valid one (10 actions), and a previous output."""
    root = tmp_path_factory.mktemp("fuzz_assets")
    demo = root / "demo.npz"
    assert main(["demo", "--seed", "0", "--out", str(demo)]) == 0
    with np.load(demo) as z:
        actions, pose = z["actions"], z["object_pose"]
    tiny = root / "tiny.npz"
    np.savez(tiny, actions=actions[:10], fps=50.0, object_pose=pose)
    return {"root": root, "demo": demo, "tiny": tiny, "actions": actions, "pose": pose}


def _previous_output(folder: Path) -> None:
    """What an earlier run left: a marked folder with a report."""
    folder.mkdir(parents=True)
    (folder / "report.json").write_text('{"verdict": "SAFE", "old": true}\n')
    (folder / "report.html").write_text("<html>old</html>\n")
    (folder / "signals.png").write_bytes(b"\x89PNG old")
    (folder / MARKER).write_text('{"command": "analyze"}\n')


def _snapshot(folder: Path) -> dict:
    if not folder.exists():
        return {}
    out = {}
    for p in sorted(folder.rglob("*")):
        rel = str(p.relative_to(folder))
        out[rel] = hashlib.sha256(p.read_bytes()).hexdigest() if p.is_file() else "dir"
    return out


# -- the corpus --------------------------------------------------------------------
@dataclass(frozen=True)
class Case:
    """One bad input: ``build(tmp, assets)`` returns the argv; ``code`` the exit code."""

    id: str
    cls: str
    build: Callable[[Path, dict], list[str]]
    code: int = 2
    out: bool = True          # pass --out PREV (a previous output that must survive)
    match: str = ""           # a phrase the error line must contain
    marks: tuple = ()
    env: tuple = ()           # (name, value) environment variables


CASES: list[Case] = []
TRAJ_COMMANDS = ("rollout", "moments", "analyze", "validate")


def case(cls, id, build, **kw):
    CASES.append(Case(id=f"{cls}-{id}", cls=cls, build=build, **kw))


def argv(*parts):
    """An argv builder: each part is a string, or ``f(tmp, assets)`` giving a path or a list."""
    def build(tmp: Path, a: dict) -> list[str]:
        out: list[str] = []
        for part in parts:
            value = part(tmp, a) if callable(part) else part
            out.extend(map(str, value) if isinstance(value, (list, tuple)) else [str(value)])
        return out
    return build


def asset(name):
    return lambda tmp, a: a[name]


# D: npz files -------------------------------------------------------------------
def _npz(**arrays):
    def make(tmp: Path, a: dict) -> Path:
        path = tmp / "traj.npz"
        np.savez(path, **{k: (v(a) if callable(v) else v) for k, v in arrays.items()})
        return path
    return make


def _good(a):
    return a["actions"][:10]


def _zip_member(name: str, data: bytes, *, flag: int = 0):
    def make(tmp: Path, a: dict) -> Path:
        path = tmp / "traj.npz"
        with zipfile.ZipFile(path, "w") as zf:
            zf.writestr(zipfile.ZipInfo(name), data)
        if flag:  # zipfile clears the flags it writes: set them in both headers
            raw = bytearray(path.read_bytes())
            raw[6] |= flag
            central = raw.rfind(b"PK\x01\x02")
            raw[central + 8] |= flag
            path.write_bytes(bytes(raw))
        return path
    return make


def _npy_bytes(arr) -> bytes:
    buf = io.BytesIO()
    np.save(buf, arr)
    return buf.getvalue()


def _npy_header(shape, dtype="<f8") -> bytes:
    buf = io.BytesIO()
    np.lib.format.write_array_header_1_0(
        buf, {"descr": dtype, "fortran_order": False, "shape": shape})
    return buf.getvalue()  # magic string included


def _corrupt_deflate(tmp: Path, a: dict) -> Path:
    path = tmp / "traj.npz"
    np.savez_compressed(path, actions=a["actions"], fps=50.0)
    data = bytearray(path.read_bytes())
    with zipfile.ZipFile(path) as zf:
        info = zf.getinfo("actions.npy")
    start = info.header_offset + 30 + len(info.filename) + 40
    for i in range(start, start + 64):
        data[i] ^= 0xA5
    path.write_bytes(bytes(data))
    return path


def _method_99(tmp: Path, a: dict) -> Path:
    path = _zip_member("actions.npy", _npy_bytes(np.zeros((10, 14))))(tmp, a)
    data = bytearray(path.read_bytes())
    # compression method: local header offset 8, central directory entry offset 10
    data[8:10] = (99).to_bytes(2, "little")
    central = data.rfind(b"PK\x01\x02")
    data[central + 10:central + 12] = (99).to_bytes(2, "little")
    path.write_bytes(bytes(data))
    return path


def _truncated(fraction):
    def make(tmp: Path, a: dict) -> Path:
        path = tmp / "traj.npz"
        np.savez_compressed(path, actions=a["actions"], fps=50.0)
        data = path.read_bytes()
        path.write_bytes(data[: int(len(data) * fraction)])
        return path
    return make


def _raw(name: str, data: bytes):
    def make(tmp: Path, a: dict) -> Path:
        path = tmp / name
        path.write_bytes(data)
        return path
    return make


def _npy_as_npz(tmp: Path, a: dict) -> Path:
    path = tmp / "traj.npz"
    with open(path, "wb") as fh:
        np.save(fh, a["actions"])
    return path


NPZ_FILES = {
    "corrupt-deflate": (_corrupt_deflate, ""),
    "encrypted-member": (_zip_member("actions.npy", _npy_bytes(np.zeros((10, 14))), flag=0x1),
                         "encrypted"),
    "unsupported-method": (_method_99, "compression method 99"),
    "truncated-half": (_truncated(0.5), ""),
    "truncated-tail": (_truncated(0.97), ""),
    "not-a-zip": (_raw("traj.npz", b"hello, this is not a zip archive\n" * 4), "not a zip"),
    "empty-file": (_raw("traj.npz", b""), ""),
    "npy-renamed": (_npy_as_npz, "single .npy"),
    "header-72TiB": (_zip_member("actions.npy", _npy_header((10**7, 10**6))),
                     "max_input_bytes"),
    "header-beyond-data": (_zip_member("actions.npy", _npy_header((1000, 14)) + b"\0" * 64),
                           "holds only"),
    "header-negative-shape": (_zip_member("actions.npy", b"\x93NUMPY\x01\x00v\x00{'descr': "
                                          b"'<f8', 'fortran_order': False, 'shape': (-5, 14), }"
                                          + b" " * 49 + b"\n"), ""),
    "header-garbage": (_zip_member("actions.npy", b"\x93NUMPY\x01\x00\x10\x00{{{{{{{{{{{{{{{\n"),
                       ""),
    "npy-version-9": (_zip_member("actions.npy", b"\x93NUMPY\x09\x00" + b"\0" * 40), ""),
    "pickled-actions": (_zip_member("actions.npy", _npy_bytes(np.array([{"a": 1}, None],
                                                                        dtype=object))),
                        "pickled"),
    "meta-bad-utf8": (_npz(actions=_good, meta=np.array(b'{"x": "\xff\xfe"}')), "UTF-8"),
    "meta-not-json": (_npz(actions=_good, meta=np.array("{not json")), "not valid JSON"),
    "meta-json-list": (_npz(actions=_good, meta=np.array("[1, 2]")), "JSON object"),
    "meta-numeric": (_npz(actions=_good, meta=np.arange(3)), "'meta'"),
    "no-actions": (_npz(fps=50.0), "expected key 'actions'"),
    "actions-1d": (_npz(actions=np.zeros(14)), "2-D"),
    "actions-3d": (_npz(actions=np.zeros((4, 14, 2))), "2-D"),
    "actions-strings": (_npz(actions=np.array([["a"] * 14] * 5)), "numeric"),
    "actions-complex": (_npz(actions=np.zeros((5, 14), complex)), "numeric"),
    "actions-nan": (_npz(actions=lambda a: np.where(np.arange(14) == 3, np.nan, _good(a))),
                    "finite"),
    "actions-inf": (_npz(actions=lambda a: np.where(np.arange(14) == 0, np.inf, _good(a))),
                    "finite"),
    "actions-one-row": (_npz(actions=np.zeros((1, 14))), "at least 2"),
    "actions-no-columns": (_npz(actions=np.zeros((5, 0))), "channel"),
    "actions-width-3": (_npz(actions=np.zeros((5, 3))), "14"),
    "actions-width-15": (_npz(actions=np.zeros((5, 15))), "14"),
    "fps-zero": (_npz(actions=_good, fps=0.0), "fps"),
    "fps-negative": (_npz(actions=_good, fps=-50.0), "fps"),
    "fps-nan": (_npz(actions=_good, fps=np.nan), "fps"),
    "fps-string": (_npz(actions=_good, fps=np.array("fast")), "fps"),
    "fps-vector": (_npz(actions=_good, fps=np.array([50.0, 50.0])), "scalar"),
    "time-decreasing": (_npz(actions=_good, time=np.arange(10)[::-1] / 50.0), "increasing"),
    "time-irregular": (_npz(actions=_good, time=np.array([0, 1, 2, 3, 5, 6, 7, 8, 9, 10]) / 50),
                       "uniform"),
    "time-short": (_npz(actions=_good, time=np.arange(4) / 50.0), "shape"),
    "time-fps-disagree": (_npz(actions=_good, fps=10.0, time=np.arange(10) / 50.0), "disagree"),
    "start-wrong-shape": (_npz(actions=_good, start=np.zeros(3)), "start"),
    "start-nan": (_npz(actions=_good, start=np.full(14, np.nan)), "finite"),
    "qpos0-empty": (_npz(actions=_good, qpos0=np.zeros(0)), "qpos0"),
    "qpos0-wrong-size": (_npz(actions=_good, qpos0=np.zeros(5)), ""),
    "pose-wrong-shape": (_npz(actions=_good, object_pose=np.zeros(6)), "object_pose"),
    "pose-zero-quat": (_npz(actions=_good, object_pose=np.zeros(7)), "quaternion"),
    "pose-nan": (_npz(actions=_good, object_pose=np.full(7, np.nan)), "finite"),
}

# D: HDF5 files ------------------------------------------------------------------
def _h5(build):
    def make(tmp: Path, a: dict) -> Path:
        path = tmp / "episode_0.hdf5"
        with h5py.File(path, "w") as f:
            build(f, a)
        return path
    return make


def _h5_corrupt_chunks(tmp: Path, a: dict) -> Path:
    path = tmp / "episode_0.hdf5"
    rng = np.random.default_rng(0)
    with h5py.File(path, "w") as f:
        f.create_dataset("action", data=rng.random((400, 14)), chunks=(50, 14),
                         compression="gzip")
    data = bytearray(path.read_bytes())
    for i in range(len(data) // 2, len(data) // 2 + 4000):
        data[i] ^= 0x5A
    path.write_bytes(bytes(data))
    return path


def _h5_truncated(tmp: Path, a: dict) -> Path:
    path = _h5(lambda f, a: f.create_dataset("action", data=a["actions"]))(tmp, a)
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 3])
    return path


def _set(name, value):
    def build(f, a):
        f[name] = value(a) if callable(value) else value
    return build


H5_FILES = {
    "corrupt-chunks": (_h5_corrupt_chunks, ""),
    "truncated": (_h5_truncated, ""),
    "not-hdf5": (_raw("episode_0.hdf5", b"not an HDF5 file at all\n"), "HDF5"),
    "dangling-external-action": (_h5(_set("action", h5py.ExternalLink("missing.h5", "/a"))),
                                 "external link"),
    "dangling-soft-qpos": (_h5(lambda f, a: (_set("action", _good)(f, a),
                                             _set("observations/qpos",
                                                  h5py.SoftLink("/nowhere"))(f, a))),
                           "soft link"),
    "no-action": (_h5(_set("observations/qpos", np.zeros((5, 14)))), "/action"),
    "action-group": (_h5(lambda f, a: f.create_group("action")), "/action"),
    "action-strings": (_h5(_set("action", np.array([b"x"] * 5))), "numeric"),
    "action-1d": (_h5(_set("action", np.zeros(14))), "2-D"),
    "action-nan": (_h5(_set("action", np.full((5, 14), np.nan))), "finite"),
    "action-declares-112GB": (_h5(lambda f, a: f.create_dataset(
        "action", shape=(10**9, 14), chunks=(1024, 14), dtype="f8")), "max_input_bytes"),
    "rows-1e7": (_h5(lambda f, a: f.create_dataset(
        "action", shape=(10**7, 14), chunks=(1024, 14), dtype="f8")), "max_input_bytes"),
}

# D/G: LeRobot data --------------------------------------------------------------
def _lerobot(columns: Callable[[dict], dict], *, info: bytes | None = b'{"fps": 50}',
             name="episode_000000.parquet"):
    def make(tmp: Path, a: dict) -> Path:
        root = tmp / "dataset"
        (root / "meta").mkdir(parents=True)
        if info is not None:
            (root / "meta" / "info.json").write_bytes(info)
        data = root / "data" / "chunk-000"
        data.mkdir(parents=True)
        pq.write_table(pa.table(columns(a)), data / name)
        return root
    return make


def _rows(a, n=10):
    return [list(map(float, r)) for r in a["actions"][:n]]


def _episodes(index):
    def columns(a):
        n = len(index)
        return {"action": _rows(a, n), "episode_index": index,
                "frame_index": list(range(n))}
    return columns


LEROBOT = {
    "episode-nan": (_lerobot(_episodes([0.0] * 5 + [math.nan] * 5)), "episode_index"),
    "episode-strings": (_lerobot(_episodes(["a"] * 10)), "episode_index"),
    "episode-fraction": (_lerobot(_episodes([0.5] * 10)), "integers"),
    "episode-null": (_lerobot(_episodes([0] * 9 + [None])), "null"),
    "frame-strings": (_lerobot(lambda a: {"action": _rows(a), "episode_index": [0] * 10,
                                          "frame_index": [str(i) for i in range(10)]}),
                      "frame_index"),
    "frame-nan": (_lerobot(lambda a: {"action": _rows(a), "episode_index": [0] * 10,
                                      "frame_index": [0.0] * 9 + [math.nan]}),
                  "frame_index"),
    "frame-duplicate": (_lerobot(lambda a: {"action": _rows(a), "episode_index": [0] * 10,
                                            "frame_index": [0] * 10}), "unique"),
    "action-null": (_lerobot(lambda a: {"action": _rows(a)[:9] + [None],
                                        "episode_index": [0] * 10}), "null"),
    "action-strings": (_lerobot(lambda a: {"action": [["x"] * 14] * 10,
                                           "episode_index": [0] * 10}), "numbers"),
    "action-ragged": (_lerobot(lambda a: {"action": _rows(a)[:9] + [[0.0] * 3],
                                          "episode_index": [0] * 10}), "fixed length"),
    "no-action": (_lerobot(lambda a: {"state": _rows(a), "episode_index": [0] * 10}),
                  "'action'"),
    "info-not-json": (_lerobot(_episodes([0] * 10), info=b"{fps: 50"), "info.json"),
    "info-bad-utf8": (_lerobot(_episodes([0] * 10), info=b'{"fps": 50, "x": "\xff"}'),
                      "info.json"),
    "info-list": (_lerobot(_episodes([0] * 10), info=b"[50]"), "JSON object"),
    "info-fps-negative": (_lerobot(_episodes([0] * 10), info=b'{"fps": -5}'), "fps"),
    "timestamp-irregular": (_lerobot(lambda a: {"action": _rows(a), "episode_index": [0] * 10,
                                                "timestamp": [0, .02, .04, .5, .52, .54, .56,
                                                              .58, .6, .62]}), "uniform"),
}

G_CASES = {
    "multi-episode-no-option": (_lerobot(_episodes([0] * 5 + [1] * 5)), [], "--episode"),
    "episode-missing": (_lerobot(_episodes([0] * 5 + [1] * 5)), ["--episode", "7"],
                        "not found"),
    "episode-negative": (_lerobot(_episodes([0] * 10)), ["--episode", "-1"], ">= 0"),
    "episode-word": (_lerobot(_episodes([0] * 10)), ["--episode", "first"], "integer"),
}


def _path_case(build_path: Callable[[Path, dict], Path], extra=()):
    def build(tmp, a, command):
        return [command, str(build_path(tmp, a)), *extra]
    return build


for command in ("rollout", "analyze"):
    for name, (make, match) in {**NPZ_FILES, **H5_FILES, **LEROBOT}.items():
        case("D", f"{name}-{command}", argv(command, make), match=match)
for command in ("moments", "validate"):
    for name in ("corrupt-deflate", "encrypted-member", "header-72TiB", "meta-bad-utf8"):
        make, match = NPZ_FILES[name]
        case("D", f"{name}-{command}", argv(command, make), match=match)
    for name in ("corrupt-chunks", "dangling-external-action"):
        make, match = H5_FILES[name]
        case("D", f"{name}-{command}", argv(command, make), match=match)
for command in TRAJ_COMMANDS:
    for name, (make, extra, match) in G_CASES.items():
        case("G", f"{name}-{command}", argv(command, make, *extra), match=match)
    case("G", f"episode-on-npz-{command}", argv(command, asset("tiny"), "--episode", "0"),
         match="episode")
case("G", "episodes-list-missing", argv("episodes", lambda tmp, a: tmp / "nope"), out=False,
     match="does not exist")
case("G", "episodes-list-nan", argv("episodes", LEROBOT["episode-nan"][0]), out=False,
     match="episode_index")

# D: paths -----------------------------------------------------------------------
PATHS = {
    "missing": (lambda tmp, a: str(tmp / "missing.npz"), "does not exist"),
    "long-name": (lambda tmp, a: str(tmp / ("x" * 300 + ".npz")), "cannot be used"),
    "nul-byte": (lambda tmp, a: str(tmp / "a\0b.npz"), ""),
    "unknown-suffix": (lambda tmp, a: str(_raw("traj.csv", b"1,2\n")(tmp, a)), "suffix"),
    "folder-named-npz": (lambda tmp, a: (os.makedirs(tmp / "d.npz"), str(tmp / "d.npz"))[1],
                         "meta/info.json"),
    "folder-without-info": (lambda tmp, a: (os.makedirs(tmp / "ds"), str(tmp / "ds"))[1],
                            "meta/info.json"),
    "dataset-without-data": (lambda tmp, a: (os.makedirs(tmp / "ds" / "meta"),
                                             (tmp / "ds" / "meta" / "info.json").write_text(
                                                 '{"fps": 50}'), str(tmp / "ds"))[2],
                             "parquet"),
    "corrupt-parquet": (lambda tmp, a: str(_raw("ep.parquet", b"PAR1 garbage PAR1")(tmp, a)),
                        "parquet"),
}
for command in TRAJ_COMMANDS:
    for name, (path, match) in PATHS.items():
        case("D", f"path-{name}-{command}", argv(command, path), match=match)

# A: options that used to be accepted silently -----------------------------------
OPTIONS = {
    "max-moments-negative": (["--max-moments", "-1"], ">= 1"),
    "max-moments-zero": (["--max-moments", "0"], ">= 1"),
    "max-moments-fraction": (["--max-moments", "2.5"], "integer"),
    "horizon-zero": (["--horizon", "0"], ">= 1"),
    "horizon-word": (["--horizon", "long"], "integer"),
    "verify-zero": (["--verify", "0"], "(0, 1]"),
    "verify-two": (["--verify", "2"], "(0, 1]"),
    "verify-nan": (["--verify", "nan"], "finite"),
    "verify-inf": (["--verify", "inf"], "finite"),
    "object-pose-short": (["--object-pose", "0", "0", "0"], "object-pose"),
    "object-pose-word": (["--object-pose", "0", "0", "0", "1", "0", "0", "x"], "number"),
    "object-pose-nan": (["--object-pose", "0", "0", "nan", "1", "0", "0", "0"], "finite"),
    "object-pose-zero-quat": (["--object-pose", "0", "0", "0", "0", "0", "0", "0"],
                              "unit quaternion"),
    "object-pose-unnormalised": (["--object-pose", "0", "0", "0", "1", "0", "0", "1"],
                                 "unit quaternion"),
    "max-steps-zero": (["--max-steps", "0"], ">= 1"),
    "max-input-bytes-word": (["--max-input-bytes", "lots"], "integer"),
    "unknown-option": (["--frobnicate"], "unrecognized"),
}
ANALYZE_ONLY = {
    "samples-zero": (["--samples", "0"], ">= 8"),
    "samples-negative": (["--samples", "-5"], ">= 8"),
    "samples-word": (["--samples", "many"], "integer"),
    "samples-nan": (["--samples", "nan"], "integer"),
    "min-success-negative": (["--min-success", "-0.1"], "[0, 1]"),
    "min-success-big": (["--min-success", "1.5"], "[0, 1]"),
    "min-success-nan": (["--min-success", "nan"], "finite"),
    "figures-bogus": (["--figures", "pretty"], "invalid choice"),
}
for command in ("analyze", "validate"):
    for name, (extra, match) in OPTIONS.items():
        case("A", f"{name}-{command}", argv(command, asset("tiny"), *extra), match=match)
for name, (extra, match) in ANALYZE_ONLY.items():
    case("A", f"{name}-analyze", argv("analyze", asset("tiny"), *extra), match=match)
for command in ("rollout", "moments"):
    for name in ("object-pose-zero-quat", "object-pose-nan", "max-steps-zero"):
        extra, match = OPTIONS[name]
        case("A", f"{name}-{command}", argv(command, asset("tiny"), *extra), match=match)
case("A", "max-moments-negative-moments", argv("moments", asset("tiny"), "--max-moments", "-1"),
     match=">= 1")
case("A", "no-command", argv(), out=False, match="required")
case("A", "unknown-command", argv("audit"), out=False, match="invalid choice")
case("A", "demo-unknown-family", argv("demo", "--family", "wobbly", "--out",
                                      lambda tmp, a: tmp / "t.npz"), out=False,
     match="invalid choice")

# F: seeds ------------------------------------------------------------------------
SEEDS = {"negative": "-1", "2**32": str(2**32), "2**40": str(2**40), "word": "abc",
         "fraction": "1.5", "nan": "nan"}
for command in ("analyze", "validate", "demo"):
    for name, seed in SEEDS.items():
        if command == "demo":
            case("F", f"seed-{name}-{command}", argv("demo", "--seed", seed, "--out",
                                                     lambda tmp, a: tmp / "t.npz"),
                 out=False, match="--seed")
        else:
            case("F", f"seed-{name}-{command}", argv(command, asset("tiny"), "--seed", seed),
                 match="--seed")

# C: memory and work bounds ---------------------------------------------------------
def _scene_with_timestep(tmp: Path, timestep: str) -> Path:
    folder = tmp / "model"
    shutil.copytree(MODELS, folder)
    scene = folder / "scene.xml"
    text = scene.read_text()
    assert 'timestep="0.002"' in text
    scene.write_text(text.replace('timestep="0.002"', f'timestep="{timestep}"'))
    return folder / "scenario.toml"


BOUNDS = {
    "fps-0.01": (lambda tmp, a: [str(_npz(actions=lambda a: a["actions"], fps=0.01)(tmp, a))],
                 "max_steps"),
    "fps-1e-6": (lambda tmp, a: [str(_npz(actions=_good, fps=1e-6)(tmp, a))], "max_steps"),
    "fps-1e9": (lambda tmp, a: [str(_npz(actions=_good, fps=1e9)(tmp, a))], "expected at most the physics rate"),
    "timestep-1e-6": (lambda tmp, a: [str(a["demo"]), "--scenario",
                                      str(_scene_with_timestep(tmp, "1e-6"))], "max_steps"),
    "max-steps-10": (lambda tmp, a: [str(a["demo"]), "--max-steps", "10"], "--max-steps"),
    "max-input-bytes-100": (lambda tmp, a: [str(a["demo"]), "--max-input-bytes", "100"],
                            "--max-input-bytes"),
    "max-input-bytes-parquet": (lambda tmp, a: [str(_lerobot(_episodes([0] * 10))(tmp, a)),
                                                "--max-input-bytes", "64"],
                                "--max-input-bytes"),
}
for command in TRAJ_COMMANDS:
    for name, (build_args, match) in BOUNDS.items():
        case("C", f"{name}-{command}", argv(command, build_args), match=match)
case("C", "samples-1e9-analyze", lambda tmp, a: ["analyze", str(a["demo"]), "--samples", "1e9"],
     match="max_batch_steps")
case("C", "samples-1e8-validate",
     lambda tmp, a: ["validate", str(a["demo"]), "--samples", "100000000"],
     match="max_batch_steps")
case("C", "max-batch-steps-1-analyze",
     lambda tmp, a: ["analyze", str(a["tiny"]), "--max-batch-steps", "1"], match="sparse sweep")
for value in ("abc", "0", "-3", "1.5"):
    case("C", f"env-max-steps-{value}", lambda tmp, a: ["rollout", str(a["tiny"])],
         env=(("CRITMOMENT_MAX_STEPS", value),), match="CRITMOMENT_MAX_STEPS")
case("C", "env-max-steps-10", lambda tmp, a: ["rollout", str(a["demo"])],
     env=(("CRITMOMENT_MAX_STEPS", "10"),), match="max_steps")

# B: output folders ----------------------------------------------------------------
def _file(tmp: Path) -> Path:
    (tmp / "a_file").write_text("x")
    return tmp / "a_file"


def _foreign(tmp: Path) -> Path:
    (tmp / "home").mkdir()
    (tmp / "home" / "thesis.tex").write_text("precious")
    return tmp / "home"


OUTS = {
    "is-a-file": (lambda tmp: _file(tmp), "existing file"),
    "under-a-file": (lambda tmp: _file(tmp) / "sub" / "report", "is a file"),
    "read-only-fs": (lambda tmp: Path("/proc/critmoment-fuzz-out"), "cannot write"),
    "foreign-folder": (lambda tmp: _foreign(tmp), "other files"),
    "long-name": (lambda tmp: tmp / ("r" * 300), "--out"),
    "nul-byte": (lambda tmp: tmp / "r\0x", "cannot be used"),
}
def _dest(make):
    return lambda tmp, a: make(tmp)


for command in TRAJ_COMMANDS:
    for name, (dest, match) in OUTS.items():
        case("B", f"out-{name}-{command}", argv(command, asset("demo"), "--out", _dest(dest)),
             out=False, match=match)
    case("B", f"out-empty-{command}", argv(command, asset("demo"), "--out", ""), out=False,
         match="empty")
DEMO_OUTS = {
    "folder": (lambda tmp: (os.makedirs(tmp / "d.npz"), tmp / "d.npz")[1], "existing folder"),
    "under-a-file": (lambda tmp: _file(tmp) / "t.npz", "is a file"),
    "read-only-fs": (lambda tmp: Path("/proc/critmoment-fuzz.npz"), "cannot write"),
    "wrong-suffix": (lambda tmp: tmp / "t.txt", ".npz"),
}
for name, (dest, match) in DEMO_OUTS.items():
    case("B", f"demo-out-{name}", argv("demo", "--out", _dest(dest)), out=False, match=match)

# E: scenario files (the strict schema is the lead's; failing ones are marked xfail) ---
def _toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v) if math.isfinite(v) else ("inf" if v > 0 else "-inf") if v == v else "nan"
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{json.dumps(k)} = {_toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(type(v))


def _toml(doc: dict, prefix: str = "") -> str:
    lines = [f"{json.dumps(k)} = {_toml_value(v)}" for k, v in doc.items()
             if not isinstance(v, dict)]
    for k, v in doc.items():
        if isinstance(v, dict):
            name = f"{prefix}.{json.dumps(k)}" if prefix else json.dumps(k)
            lines.append(f"\n[{name}]")
            lines.append(_toml(v, name))
    return "\n".join(lines)


BUNDLED = tomllib.loads((MODELS / "scenario.toml").read_text())


def _scenario(edit: Callable[[dict], None]):
    def make(tmp: Path) -> Path:
        import copy

        doc = copy.deepcopy(BUNDLED)
        doc["model"]["mjcf"] = str(MODELS / doc["model"]["mjcf"])
        edit(doc)
        path = tmp / "scenario.toml"
        path.write_text(_toml(doc) + "\n")
        return path
    return make


def _tables(doc: dict, prefix=()):
    for k, v in doc.items():
        if isinstance(v, dict):
            yield (*prefix, k)
            yield from _tables(v, (*prefix, k))


def _at(doc, path):
    for k in path:
        doc = doc[k]
    return doc


def _wrong_type(value):
    if isinstance(value, bool):
        return "yes"
    if isinstance(value, (int, float)):
        return "abc"
    if isinstance(value, str):
        return [1, 2]
    if isinstance(value, list):
        return "a list"
    return 3


E_CASES = {}
E_CASES["unknown-top-level-key"] = _scenario(lambda d: d.__setitem__("horizn", 1))
def _setter(table, key, value):
    return lambda d: _at(d, table).__setitem__(key, value)


for table in _tables(BUNDLED):
    E_CASES[f"unknown-key-in-{'.'.join(table)}"] = _scenario(
        _setter(table, "priors", "loguniform"))
for table in _tables(BUNDLED):
    for key, value in _at(BUNDLED, table).items():
        if isinstance(value, dict) or (table == ("model",) and key == "mjcf"):
            continue
        E_CASES[f"wrong-type-{'.'.join(table)}.{key}"] = _scenario(
            _setter(table, key, _wrong_type(value)))
    E_CASES[f"table-as-string-{'.'.join(table)}"] = _scenario(
        _setter(table[:-1], table[-1], "oops"))
E_CASES["limit-inf"] = _scenario(lambda d: d["limits"].__setitem__("waist", math.inf))
E_CASES["limit-zero"] = _scenario(lambda d: d["limits"].__setitem__("elbow", 0.0))
E_CASES["limit-negative"] = _scenario(lambda d: d["limits"].__setitem__("elbow", -1.0))
E_CASES["range-inf"] = _scenario(lambda d: d["uncertainty"]["mass"].__setitem__(
    "range", [0.05, math.inf]))
E_CASES["range-reversed"] = _scenario(lambda d: d["uncertainty"]["mass"].__setitem__(
    "range", [10.0, 0.05]))
E_CASES["threshold-nan"] = _scenario(lambda d: d["cost"].__setitem__("threshold", math.nan))
E_CASES["kind-as-list"] = _scenario(lambda d: d["task"].__setitem__("kind", ["handover"]))
E_CASES["prior-misspelt"] = _scenario(lambda d: d["uncertainty"]["mass"].__setitem__(
    "prior", "loguniform_"))
for name, make in E_CASES.items():
    case("E", name, argv("rollout", asset("tiny"), "--scenario", _dest(make)))
# A friction parameter on a gripper pad, below the cube's own friction: MuJoCo's max mixing
# makes every value in the range give the same contacts (the lead's parameter-effect check).
case("E", "friction-never-wins", argv("rollout", asset("tiny"), "--scenario", _dest(_scenario(
    lambda d: d["uncertainty"].__setitem__("friction", {
        "geom": "left/left_pad", "range": [0.01, 0.1], "nominal": 0.05,
        "prior": "uniform"})))))
case("E", "scenario-missing", argv("rollout", asset("tiny"), "--scenario",
                                   lambda tmp, a: tmp / "none.toml"))
case("E", "scenario-bad-toml", argv("rollout", asset("tiny"), "--scenario",
                                    _raw("s.toml", b"[model\nmjcf = 1")))
case("E", "scenario-bad-utf8", argv("rollout", asset("tiny"), "--scenario",
                                    _raw("s.toml", b'name = "\xff"')))


# -- the test ----------------------------------------------------------------------
def _params():
    return [pytest.param(c, id=c.id, marks=c.marks) for c in CASES]


def test_corpus_is_large_and_covers_every_class():
    assert len(CASES) >= 200
    assert {c.cls for c in CASES} >= set("ABCDEFG")
    assert len({c.id for c in CASES}) == len(CASES)


@pytest.mark.parametrize("c", _params())
def test_bad_input(c: Case, assets, tmp_path, capsys, monkeypatch):
    for name, value in c.env:
        monkeypatch.setenv(name, value)
    work = tmp_path / "in"
    work.mkdir()
    argv = c.build(work, assets)
    prev = tmp_path / "previous"
    if c.out:
        _previous_output(prev)
        argv = [*argv, "--out", str(prev)]
    before = _snapshot(prev)
    siblings = sorted(os.listdir(tmp_path))
    capsys.readouterr()
    code = main(argv)
    cap = capsys.readouterr()
    lines = cap.err.strip().splitlines()
    assert code == c.code, (code, cap.err)
    assert len(lines) == 1, cap.err
    assert "Traceback" not in cap.err
    command = argv[0] if argv and not argv[0].startswith("-") else ""
    if command in ("rollout", "moments", "analyze", "validate", "demo", "episodes"):
        assert lines[0].startswith(f"critmoment {command}: error: "), lines[0]
    else:
        assert lines[0].startswith("critmoment"), lines[0]
    assert c.match in lines[0], lines[0]
    assert _snapshot(prev) == before
    assert sorted(os.listdir(tmp_path)) == siblings  # no temporary folder left behind


# -- class A: a closed pipe keeps the verdict's code (real audits, kept few) ---------
class _ClosedPipe(io.TextIOBase):
    def write(self, s):
        raise BrokenPipeError(32, "Broken pipe")

    def flush(self):
        raise BrokenPipeError(32, "Broken pipe")


FAST_AUDIT = ["--samples", "16", "--max-moments", "2", "--no-verify"]


@pytest.mark.parametrize("json_flag", [["--json"], []], ids=["json", "text"])
def test_closed_pipe_keeps_the_verdict(json_flag, assets, tmp_path, capsys, monkeypatch):
    capsys.readouterr()
    monkeypatch.setattr(sys, "stdout", _ClosedPipe())
    code = main(["analyze", str(assets["demo"]), *FAST_AUDIT, *json_flag,
                 "--out", str(tmp_path / "r")])
    monkeypatch.undo()
    err = capsys.readouterr().err
    assert code == 1  # CONDITIONAL: the broken pipe does not turn it into 0
    assert "Traceback" not in err and "error" not in err
    doc = json.loads((tmp_path / "r" / "report.json").read_text())
    assert doc["verdict"] == "CONDITIONAL"  # the report was still written whole


def test_closed_pipe_demo_and_rollout_exit_0(assets, tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(sys, "stdout", _ClosedPipe())
    assert main(["rollout", str(assets["tiny"]), "--json"]) == 0
    assert main(["demo", "--out", str(tmp_path / "t.npz")]) == 0
    monkeypatch.undo()
    assert "Traceback" not in capsys.readouterr().err


def test_real_pipe_head_keeps_exit_1(assets, tmp_path):
    """The issue's reproduction: ``critmoment analyze ... --json | head -1`` exits 1."""
    script = (f"{sys.executable} -m critmoment.cli analyze {assets['demo']} "
              f"{' '.join(FAST_AUDIT)} --json | head -1; exit ${{PIPESTATUS[0]}}")
    proc = subprocess.run(["bash", "-c", script], capture_output=True, text=True,
                          timeout=600, env={**os.environ, "MPLBACKEND": "Agg"})
    assert proc.stdout.strip() == "{"
    assert proc.returncode == 1, proc.stderr
    assert "Traceback" not in proc.stderr and "BrokenPipe" not in proc.stderr


# -- class D: a $...$ in a file name is drawn, not parsed as mathtext ----------------
def test_dollar_in_file_name(assets, tmp_path, capsys):
    path = tmp_path / "run $\\frac{1$ of $x^.npz"
    shutil.copy(assets["tiny"], path)
    assert main(["rollout", str(path), "--out", str(tmp_path / "r")]) == 0
    assert (tmp_path / "r" / "signals.png").stat().st_size > 1000
    assert "error" not in capsys.readouterr().err


# -- class D: seeded byte mutations of valid files -----------------------------------
@pytest.fixture(scope="module")
def valid_files(assets, tmp_path_factory):
    root = tmp_path_factory.mktemp("valid")
    acts = assets["actions"][:40]
    np.savez_compressed(root / "v.npz", actions=acts, fps=50.0, object_pose=assets["pose"],
                        meta=np.array('{"robot": "aloha"}'))
    with h5py.File(root / "v.hdf5", "w") as f:
        f.create_dataset("action", data=acts, chunks=(10, 14), compression="gzip")
        f.create_dataset("observations/qpos", data=acts)
    pq.write_table(pa.table({"action": [list(map(float, r)) for r in acts],
                             "episode_index": [0] * 40, "frame_index": list(range(40))}),
                   root / "v.parquet")
    return {s: (root / f"v.{s}").read_bytes() for s in ("npz", "hdf5", "parquet")}


@pytest.mark.parametrize("suffix", ["npz", "hdf5", "parquet"])
@pytest.mark.parametrize("seed", range(40))
def test_mutated_file_loads_or_fails_cleanly(suffix, seed, valid_files, tmp_path):
    """Random byte changes or truncation: a Trajectory or a CritmomentError, nothing else."""
    import warnings

    from critmoment.exceptions import CritmomentError
    from critmoment.trajectory import Trajectory, load_trajectory

    rng = np.random.default_rng(seed)
    data = bytearray(valid_files[suffix])
    if seed % 4 == 0:
        data = data[: int(rng.integers(0, len(data)))]
    else:
        for i in rng.integers(0, len(data), size=int(rng.integers(1, 17))):
            data[int(i)] = int(rng.integers(0, 256))
    path = tmp_path / f"m.{suffix}"
    path.write_bytes(bytes(data))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            assert isinstance(load_trajectory(path), Trajectory)
        except CritmomentError as exc:
            assert str(exc).strip(), "an error without a message"
