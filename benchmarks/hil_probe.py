"""gym-hil's Franka Panda + Robotiq 2F-85 (LeRobot's human-in-the-loop env, torque motors on the
arm): init, a scripted pick-and-place, analyze and validate under two contact models.

Not run in CI: it downloads the gym-hil wheel (``pip download gym-hil --no-deps``, never
installed) into ``$CRITMOMENT_REAL_MODELS`` (default ``~/.cache/critmoment-real-models``).

1. ``critmoment init scene.xml --object block --task pick_place --goal 0.5 0.15 0.02`` on the
   shipped scene (torque motors -> ``[servos]`` with guessed 5 Hz gains).
2. A scripted pick-and-place from gym-hil's ``PandaPickCube`` home pose (DLS IK of the
   ``pinch`` site, feed-forward of the unloaded arm's inverse dynamics through the servos'
   own gains): the block at (0.5, 0, 0.02) lifted 10 cm and put down 15 cm away in y.
   ``rollout`` must say completed.
3. ``analyze`` and ``validate --samples 64`` on init's box and on a narrow box per contact
   model (:data:`NARROW`, where about half the samples fail), under the shipped contact model
   (pyramidal, impratio 1, noslip 5) and an elliptic cone, impratio 10, noslip 0 copy.

Usage::

    python benchmarks/hil_probe.py [--seed 0] [--samples 64] [--gain-scale 1]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent / "real_models"))
import scenes  # noqa: E402
import scripted  # noqa: E402

import critmoment as cm  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

scenes.WHEELS["gym-hil"] = ("gym_hil", ("gym_hil/assets/",))

#: gym-hil's PandaPickCube home pose (panda_pick_gym_env.py ``_PANDA_HOME``) [rad]
HOME = np.array([0.0, 0.195, 0.0, -2.43, 0.0, 2.62, 0.785])
JOINTS = tuple(f"joint{i}" for i in range(1, 8))
BLOCK = np.array([0.5, 0.0, 0.02, 1, 0, 0, 0])
GOAL = np.array([0.5, 0.15, 0.02])


def _cli(*args: str) -> tuple[int, str, float]:
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "critmoment.cli", *args], capture_output=True,
                          text=True, env={**os.environ, "PYTHONWARNINGS": ""})
    return proc.returncode, proc.stdout + proc.stderr, time.perf_counter() - t0


def _json(out: str) -> dict:
    return json.loads(out[out.index("{"):out.rindex("}") + 1])


def shipped_scene() -> Path:
    return scenes.fetch("gym-hil") / "gym_hil" / "assets" / "scene.xml"


def contact_copy(mjcf: Path) -> Path:
    """A copy with an elliptic cone, impratio 10 and noslip_iterations 0 (MjSpec)."""
    spec = mujoco.MjSpec.from_file(str(mjcf))
    scenes._absolute_assets(spec, mjcf.parent)
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.option.impratio = 10.0
    spec.option.noslip_iterations = 0
    return scenes._write(spec, "gym_hil_elliptic10_noslip0")


def scale_gains(toml: Path, factor: float, out: Path) -> Path:
    """A copy of ``toml`` with every ``[servos.*]`` kp scaled by ``factor`` and kv by
    sqrt(factor) (still critically damped)."""
    def kp(m):
        return f"kp = {float(m.group(1)) * factor:.4g}"

    def kv(m):
        return f"kv = {float(m.group(1)) * np.sqrt(factor):.4g}"
    text = re.sub(r"^kp = ([0-9.e+-]+)", kp, toml.read_text(), flags=re.M)
    text = re.sub(r"^kv = ([0-9.e+-]+)", kv, text, flags=re.M)
    out.write_text(text)
    return out


#: per contact model, a box where about half the samples really fail: (mass range, mass
#: nominal, friction range, friction nominal), from a brute-force grid of the nominal motion
NARROW = {"shipped": ((0.5, 2.0), 0.6, (0.25, 0.6), 0.55),
          "elliptic10": ((1.0, 3.0), 1.05, (0.1, 0.3), 0.28)}


def narrow(toml: Path, out: Path, contact: str) -> Path:
    """init's box narrowed to :data:`NARROW`'s box of ``contact``."""
    (m0, m1), mn, (f0, f1), fn = NARROW[contact]
    text = toml.read_text()
    for old, new in (("range = [0.05, 2.0]   # [kg]\nnominal = 0.1",
                      f"range = [{m0}, {m1}]   # [kg]\nnominal = {mn}"),
                     ("range = [0.2, 1.5]", f"range = [{f0}, {f1}]"),
                     ("nominal = 0.6\n\n[cost]", f"nominal = {fn}\n\n[cost]")):
        if old not in text:
            raise RuntimeError(f"{toml}: init's box changed; expected {old!r}")
        text = text.replace(old, new)
    out.write_text(text)
    return out


def pick_place(model: mujoco.MjModel, *, goal=GOAL, grasp_z: float = 0.02,
               transport: float = 0.12, n: int = 500, feed_forward: bool = True) -> Trajectory:
    """Home -> above the block -> down -> close -> lift -> over the goal -> down -> open ->
    up; actions [7 joint targets, gripper 0 closed .. 1 open] at 50 Hz, targets through
    the converted servos' own kp, kv (``model`` is the twin's model)."""
    data = mujoco.MjData(model)
    qpos0 = data.qpos.copy()
    qpos0[model.jnt_qposadr[[model.joint(j).id for j in JOINTS]]] = HOME
    bj = model.jnt_qposadr[model.joint("block").id]
    qpos0[bj:bj + 7] = BLOCK
    offset = model.site_pos[model.site("pinch").id].copy()
    arm = scripted.Arm(model, JOINTS, "base", ("right_pad1", "left_pad1"), qpos0, offset)
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    down = r0.copy()  # the home pose points down, fingers closing along world y
    down[:, 0] = [1, 0, 0]
    down[:, 1] = [0, -1, 0]
    down[:, 2] = [0, 0, -1]
    goal = np.asarray(goal, float)
    grasp = np.array([BLOCK[0], BLOCK[1], grasp_z])
    above = np.array([BLOCK[0], BLOCK[1], transport])
    place = np.array([goal[0], goal[1], grasp_z + 0.002])
    over = np.array([goal[0], goal[1], transport])
    points = [(0, p0, r0, 1.0), (60, above, down, 1.0), (110, grasp, down, 1.0),
              (125, grasp, down, 1.0), (150, grasp, down, 0.0), (170, grasp, down, 0.0),
              (220, above, down, 0.0), (295, over, down, 0.0), (345, place, down, 0.0),
              (360, place, down, 0.0), (385, place, down, 1.0), (435, over, down, 1.0),
              (n, over, down, 1.0)]
    q, grip = scripted.joint_path(arm, data, points, n, start=HOME, rest=HOME)
    targets = arm.feed_forward(q, 0.02, qpos0) if feed_forward else q
    actions = np.concatenate([targets, grip[:, None]], axis=1)
    start = np.concatenate([HOME, [1.0]])
    return Trajectory(actions=actions, fps=50.0, start=start, qpos0=qpos0,
                      object_pose=BLOCK.copy(),
                      meta={"generator": "benchmarks/hil_probe.py pick_place"},
                      source="gym-hil panda pick_place")


def init(mjcf: Path, toml: Path) -> str:
    rc, out, _ = _cli("init", str(mjcf), "--object", "block", "--task", "pick_place",
                      "--goal", *(str(v) for v in GOAL), "--out", str(toml), "--force")
    if rc:
        raise RuntimeError(f"init failed on {mjcf}:\n{out}")
    return out


def audit(traj: Path, toml: Path, work: Path, args, label: str) -> dict:
    row = {"case": label}
    rc, out, wall = _cli("analyze", str(traj), "--scenario", str(toml), "--seed",
                         str(args.seed), "--out", str(work / f"{label}_report"))
    row["analyze"] = {"exit": rc, "wall_s": round(wall, 1)}
    rep = work / f"{label}_report" / "report.json"
    if rep.is_file():
        report = json.loads(rep.read_text())
        row["analyze"].update(verdict=report.get("verdict"),
                              p_success=report.get("p_success"),
                              safe_region=report.get("safe_region"))
        if report.get("safe_region"):
            row["region_rollouts"] = region_check(traj, toml, report["safe_region"])
    else:
        row["analyze"]["output"] = out[-1500:]
    rc, out, wall = _cli("validate", str(traj), "--scenario", str(toml), "--samples",
                         str(args.samples), "--seed", str(args.seed), "--json")
    try:
        res = _json(out)
        row["validate"] = {"exit": rc, "wall_s": round(wall, 1),
                           **{k: res.get(k) for k in ("verdict", "p_success", "outcomes",
                                                      "confusion", "false_safe_rate",
                                                      "agreement", "safe_region")}}
    except ValueError:
        row["validate"] = {"exit": rc, "wall_s": round(wall, 1), "output": out[-1500:]}
    print(json.dumps(row), flush=True)
    return row


def region_check(traj: Path, toml: Path, region: dict) -> dict:
    """Full rollouts at 32 Sobol points inside the stated safe region and its corners."""
    from scipy.stats import qmc

    from critmoment.groundtruth import brute_force
    twin = cm.Twin(cm.load_scenario(toml))
    names = twin.scenario.box.names
    lo = np.array([region[n][0] for n in names])
    hi = np.array([region[n][1] for n in names])
    u = qmc.Sobol(len(names), scramble=True, seed=1).random_base2(5)
    corners = np.array([[a, b] for a in (lo[0], hi[0]) for b in (lo[1], hi[1])])
    points = np.vstack([lo + u * (hi - lo), corners])
    bf = brute_force(cm.load_trajectory(traj), twin=twin, samples=points)
    bad = [dict(zip(names, map(float, p), strict=True), outcome=o.value)
           for p, o, f in zip(points, bf.outcome, bf.failed, strict=True) if f]
    return {"points": len(points), "failed": int(bf.failed.sum()), "failures": bad}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--gain-scale", type=float, default=1.0,
                        help="scale init's guessed servo kp (kv by its square root)")
    parser.add_argument("--work", type=Path, default=None)
    parser.add_argument("--stage", choices=("rollout", "all"), default="all")
    args = parser.parse_args()
    work = args.work or Path(tempfile.mkdtemp(prefix="hil_"))
    work.mkdir(parents=True, exist_ok=True)
    shipped = shipped_scene()
    rows = []
    for contact, mjcf in (("shipped", shipped), ("elliptic10", None)):
        if mjcf is None:
            mjcf = contact_copy(shipped)
        toml = work / f"{contact}_init.toml"
        out = init(mjcf, toml)
        print(out if contact == "shipped" else f"init ({contact}) ok", flush=True)
        if args.gain_scale != 1.0:
            toml = scale_gains(toml, args.gain_scale, work / f"{contact}_gains.toml")
        twin = cm.Twin(cm.load_scenario(toml))
        traj = pick_place(twin.model)
        path = work / f"pick_place_{contact}.npz"
        save_trajectory(traj, path)
        rc, out, wall = _cli("rollout", str(path), "--scenario", str(toml), "--json")
        print(f"rollout ({contact}): exit {rc}, {wall:.1f} s\n{out[-3000:]}", flush=True)
        if args.stage == "rollout":
            continue
        rows.append(audit(path, toml, work, args, f"{contact}_init"))
        rows.append(audit(path, narrow(toml, work / f"{contact}_narrow.toml", contact), work, args,
                          f"{contact}_narrow"))
        if contact == "shipped":
            # the same motion as plain joint targets (what a dataset records), no feed-forward
            raw = work / "pick_place_shipped_raw.npz"
            save_trajectory(pick_place(twin.model, feed_forward=False), raw)
            rows.append(audit(raw, toml, work, args, "shipped_init_raw"))
    (work / "results.json").write_text(json.dumps(rows, indent=1))
    print(f"results: {work / 'results.json'}")


if __name__ == "__main__":
    main()
