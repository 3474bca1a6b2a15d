"""Generate the twenty-fourth round's task/shape probe inputs (trajectories and scenario copies).

Run: ``python benchmarks/probe_r24/tasks/gen.py OUTDIR`` (default ``/tmp/r24t/gen``), with
critmoment installed. Writes ``OUTDIR/*.npz``, ``OUTDIR/*.toml`` (copies of the bundled
scenarios, their ``mjcf`` a relative path to the installed package's model) and
``OUTDIR/cases.tsv`` (case, trajectory, scenario, samples, note), which ``run.py`` reads.
"""

import dataclasses
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import mujoco
import numpy as np

from critmoment import demos, panda_demo
from critmoment.scenario import bundled_scenario_path, load_scenario
from critmoment.trajectory import Trajectory, save_trajectory
from critmoment.twin import Twin

OUT = Path(sys.argv[1] if len(sys.argv) > 1 else "/tmp/r24t/gen")
ALOHA_GRIP = np.zeros(14, bool)
ALOHA_GRIP[[6, 13]] = True
PANDA_GRIP = np.zeros(8, bool)
PANDA_GRIP[7] = True
CASES = []


def scenario_copy(name: str, bundled: str, edits: dict) -> str:
    """Writes OUT/name.toml: the bundled scenario with whole lines replaced (key -> new line)."""
    src = bundled_scenario_path(bundled)
    src = src if src.suffix == ".toml" else src / "scenario.toml"
    text = src.read_text().splitlines()
    mjcf = os.path.relpath(src.parent / "scene.xml", OUT)
    out = []
    section = ""
    for line in text:
        stripped = line.strip()
        if stripped.startswith("["):
            section = stripped
        key = (section, stripped.split("=")[0].strip()) if "=" in stripped else None
        if section == "[model]" and key and key[1] == "mjcf":
            line = f'mjcf = "{mjcf}"'
        elif key in edits:
            line = edits[key]
        out.append(line)
    path = OUT / f"{name}.toml"
    path.write_text("\n".join(out) + "\n")
    load_scenario(path)
    return path.name


def add(case: str, traj: Trajectory, scenario: str, samples: int = 32, note: str = "") -> None:
    save_trajectory(traj, OUT / f"{case}.npz")
    CASES.append((case, f"{case}.npz", scenario, str(samples), note))


def resample(traj: Trajectory, fps: float, grip: np.ndarray) -> Trajectory:
    """The twin's own 500 Hz control signal of ``traj``, sampled at ``fps`` (same duration)."""
    ctrl = traj.upsample(0.002, bounded=grip)
    t_ctrl = np.arange(len(ctrl)) * 0.002
    n = int(round(traj.duration * fps))
    t = np.arange(n) / fps
    acts = np.stack([np.interp(t, t_ctrl, ctrl[:, j]) for j in range(ctrl.shape[1])], axis=1)
    return dataclasses.replace(traj, actions=acts, fps=float(fps),
                               meta={**traj.meta, "resampled_to": fps})


def insert_pause(traj: Trajectory, at: int, seconds: float) -> Trajectory:
    rows = int(round(seconds * traj.fps))
    acts = np.concatenate([traj.actions[:at], np.repeat(traj.actions[at:at + 1], rows, 0),
                           traj.actions[at:]])
    return dataclasses.replace(traj, actions=acts)


def smooth_bump(n: int, t0: int, t1: int) -> np.ndarray:
    """0 before t0, 1 after t1, min-jerk in between."""
    s = np.clip((np.arange(n) - t0) / max(t1 - t0, 1), 0.0, 1.0)
    return s ** 3 * (10 - 15 * s + 6 * s ** 2)


def chunk(traj: Trajectory, scenario, k: int) -> Trajectory:
    """Actions k.. of ``traj`` with qpos0/qvel0 from its nominal rollout's recorded state."""
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "t.npz"
        save_trajectory(traj, src)
        subprocess.run(["critmoment", "rollout", str(src), "--scenario", str(scenario),
                        "--out", str(Path(tmp) / "r")], check=True, capture_output=True)
        states = np.load(Path(tmp) / "r" / "recording.npz")["states"]
    twin = Twin(load_scenario(scenario))
    model = twin.model
    data = mujoco.MjData(model)
    per = int(round(1.0 / traj.fps / model.opt.timestep))
    mujoco.mj_setState(model, data, states[k * per], mujoco.mjtState.mjSTATE_INTEGRATION)
    body = model.body(twin.scenario.object_body)
    adr = model.jnt_qposadr[model.body_jntadr[body.id]]
    return dataclasses.replace(traj, actions=traj.actions[k:].copy(), start=None,
                               qpos0=data.qpos.copy(), qvel0=data.qvel.copy(),
                               object_pose=data.qpos[adr:adr + 7].copy(),
                               meta={**traj.meta, "chunk_from": k})


def aloha_waypoints(right_open, left_close):
    """A demos._waypoints variant: picker opens over right_open, receiver closes over left_close.

    Both are (start, end) action steps; right_open inside (220, 370), left_close ending
    before 340.
    """
    orig = demos._waypoints

    def wp(box, opt, start_right, start_left):
        right, left = orig(box, opt, start_right, start_left)
        by_r = {p[0]: p for p in right}
        by_l = {p[0]: p for p in left}
        meet = by_r[220][1]
        right = [by_r[t] for t in (0, 90, 130, 170, 195, 220)]
        right += [(right_open[0], meet, demos.RIGHT_PICK, 0.0),
                  (right_open[1], meet, demos.RIGHT_PICK, opt.release_opening),
                  by_r[370], by_r[400]]
        take = by_l[260][1]
        approach = min(220, left_close[0] - 35)
        left = [by_l[0], by_l[100], (approach, by_l[220][1], demos.LEFT_MEET, 1.0),
                (left_close[0], take, demos.LEFT_MEET, 1.0),
                (left_close[1], take, demos.LEFT_MEET, 0.0),
                (340, take, demos.LEFT_MEET, 0.0), by_l[370], by_l[400]]
        return right, left

    return wp


def aloha(seed: int = 0, **opts) -> Trajectory:
    return demos.scripted_transfer(seed, options=demos.DemoOptions(**opts))


def aloha_at(pose_xy, **opts) -> Trajectory:
    orig = demos.sample_box_pose
    demos.sample_box_pose = lambda seed: np.array([*pose_xy, demos.BOX_REST_Z, 1, 0, 0, 0.0])
    try:
        return aloha(0, **opts)
    finally:
        demos.sample_box_pose = orig


def panda(seed: int = 0, **opts) -> Trajectory:
    return panda_demo.make_pick_place(seed, options=panda_demo.PickPlaceOptions(**opts))


def panda_at(pose_xy, **opts) -> Trajectory:
    orig = panda_demo.sample_cube_pose
    panda_demo.sample_cube_pose = lambda seed: np.array(
        [*pose_xy, panda_demo.CUBE_HALF, 1, 0, 0, 0.0])
    try:
        return panda(0, **opts)
    finally:
        panda_demo.sample_cube_pose = orig


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    a15 = scenario_copy("aloha_m15", "aloha_transfer_cube",
                        {("[uncertainty.mass]", "range"): "range = [0.05, 1.5]"})
    pan = scenario_copy("panda", "panda_pick_place", {})
    a0 = aloha(0)
    p0 = panda(0)
    add("A_nominal", a0, a15)
    add("P_nominal", p0, pan)
    # 1. rates
    for fps in (10, 15, 30, 100, 250, 500):
        add(f"A_fps{fps}", resample(a0, fps, ALOHA_GRIP), a15, note="twin control resampled")
        add(f"P_fps{fps}", panda(0, fps=float(fps)), pan, note="generator fps option")
    for fps in (10, 500):
        add(f"P_rs{fps}", resample(p0, fps, PANDA_GRIP), pan, note="twin control resampled")
    # 2. pauses while carrying (ALOHA: held at the meeting point; Panda: at transport height)
    add("A_pause3s", insert_pause(a0, 240, 3.0), a15)
    add("P_pause3s", insert_pause(p0, 300, 3.0), pan)
    add("P_pause3s_lifted", insert_pause(p0, 232, 3.0), pan, note="pause right after lift")
    # 3. regrasp mid-carry (Panda at transport height, steps 250..290)
    n = p0.n_steps
    for name, peak in (("P_regrasp_partial", 0.45), ("P_regrasp_full", 1.0)):
        acts = p0.actions.copy()
        bump = smooth_bump(n, 250, 265) - smooth_bump(n, 275, 290)
        acts[:, 7] = np.maximum(acts[:, 7], peak * bump)
        add(name, dataclasses.replace(p0, actions=acts), pan, note=f"opens to {peak} mid-carry")
    acts = a0.actions.copy()
    bump = smooth_bump(a0.n_steps, 225, 235) - smooth_bump(a0.n_steps, 240, 250)
    acts[:, 13] = np.maximum(acts[:, 13], 0.45 * bump)
    add("A_regrasp_partial", dataclasses.replace(a0, actions=acts), a15)
    # 4. time scale
    add("A_ts0.4", aloha(0, time_scale=0.4), a15)
    add("A_ts3", aloha(0, time_scale=3.0), a15)
    add("P_ts0.4", panda(0, time_scale=0.4), pan)
    add("P_ts3", panda(0, time_scale=3.0), pan)
    # 5. wrist rotation of 90 deg while carrying (Panda joint7, steps 230..305)
    acts = p0.actions.copy()
    acts[:, 6] += np.pi / 2 * smooth_bump(n, 235, 300)
    add("P_wrist90", dataclasses.replace(p0, actions=acts), pan, note="joint7 +90 deg in carry")
    acts = a0.actions.copy()
    rot = np.pi / 2 * (smooth_bump(a0.n_steps, 196, 215) - smooth_bump(a0.n_steps, 225, 245))
    acts[:, 12] += rot
    add("A_wrist90_back", dataclasses.replace(a0, actions=acts), a15,
        note="right wrist_rotate +90 and back before hand-over")
    # 6. lift higher
    add("P_high0.4", panda(0, transport_height=0.4), pan)
    add("A_meet_high", aloha(0, meet=(0.0, 0.5, 0.40)), a15, note="meet at z 0.40")
    # 7. release above the goal
    for clr in (0.01, 0.02):
        add(f"P_release{int(clr * 100)}cm", panda(0, place_clearance=clr), pan)
    opt = panda_demo.PickPlaceOptions()
    object.__setattr__(opt, "place_clearance", 0.03)
    add("P_release3cm", panda_demo.make_pick_place(0, options=opt), pan)
    # 8. action chunks from mid-carry
    add("P_chunk280", chunk(p0, OUT / pan, 280), pan, note="from carry at transport height")
    add("P_chunk240", chunk(p0, OUT / pan, 240), pan, note="from just after lift")
    add("A_chunk210", chunk(a0, OUT / a15, 210), a15, note="from picker carrying")
    add("A_chunk310", chunk(a0, OUT / a15, 310), a15, note="from hand-over overlap")
    # 9. policy-like noise
    for amp in (0.005, 0.01, 0.03):
        for seed in (1, 2):
            rng = np.random.default_rng(seed)
            acts = p0.actions.copy()
            acts[1:, :7] += rng.normal(0.0, amp, size=(n - 1, 7))
            add(f"P_noise{amp}_s{seed}", dataclasses.replace(p0, actions=acts), pan)
    for amp in (0.005, 0.03):
        add(f"A_jitter{amp}", aloha(3, jitter=amp), a15)
    # 10. ends right after the release
    add("P_end396", dataclasses.replace(p0, actions=p0.actions[:396].copy()), pan)
    add("P_end400", dataclasses.replace(p0, actions=p0.actions[:400].copy()), pan)
    add("A_end345", dataclasses.replace(a0, actions=a0.actions[:345].copy()), a15)
    # 11. hand-over overlaps (picker open, receiver close windows, steps)
    for name, r_open, l_close in (("A_overlap_long", (330, 360), (255, 270)),
                                  ("A_overlap_tiny", (300, 305), (290, 300)),
                                  ("A_overlap_none", (300, 315), (320, 335))):
        orig = demos._waypoints
        demos._waypoints = aloha_waypoints(r_open, l_close)
        try:
            add(name, aloha(0), a15, note=f"picker opens {r_open}, receiver closes {l_close}")
        finally:
            demos._waypoints = orig
    # 12. spawn corners
    for cx, cy in ((0.0, 0.4), (0.0, 0.6), (0.2, 0.4), (0.2, 0.6)):
        add(f"A_corner_{cx}_{cy}", aloha_at((cx, cy)), a15)
    for cx, cy in ((0.45, -0.2), (0.45, -0.1), (0.55, -0.2), (0.55, -0.1)):
        add(f"P_corner_{cx}_{cy}", panda_at((cx, cy)), pan)
    # 13. task copies
    hold = scenario_copy("panda_hold", "panda_pick_place",
                         {("[task]", "kind"): 'kind = "pick_hold"',
                          ("[task]", "goal"): "", ("[task]", "tolerance"): ""})
    add("P_hold", dataclasses.replace(p0, actions=p0.actions[:320].copy()), hold,
        note="pick_hold, ends holding at transport height")
    tight = scenario_copy("panda_goal_tight", "panda_pick_place",
                          {("[task]", "goal"): "goal = [0.5, 0.15, 0.02]",
                           ("[task]", "tolerance"): "tolerance = 0.005"})
    add("P_tol5mm", p0, tight, note="tolerance 5 mm")
    add("P_tol5mm_rel2cm", panda(0, place_clearance=0.02), tight, note="tolerance 5 mm")
    other = scenario_copy("panda_goal_other", "panda_pick_place",
                          {("[task]", "goal"): "goal = [0.4, 0.25, 0.02]"})
    add("P_goal_other", panda(0, goal=(0.4, 0.25, 0.02)), other, note="goal (0.4, 0.25)")
    add("P_goal_mismatch", p0, other, note="placed at (0.5,0.15), goal (0.4,0.25): must fail")
    ahold = scenario_copy("aloha_hold", "aloha_transfer_cube",
                          {("[uncertainty.mass]", "range"): "range = [0.05, 1.5]",
                           ("[task]", "kind"): 'kind = "pick_hold"',
                           ("[task]", "picker"): 'gripper = "right"',
                           ("[task]", "receiver"): ""})
    add("A_hold", dataclasses.replace(a0, actions=a0.actions[:255].copy()), ahold,
        note="pick_hold by the picker, ends at the meeting point")
    swap = scenario_copy("aloha_swapped", "aloha_transfer_cube",
                         {("[uncertainty.mass]", "range"): "range = [0.05, 1.5]",
                          ("[task]", "picker"): 'picker = "left"',
                          ("[task]", "receiver"): 'receiver = "right"'})
    add("A_swapped_roles", a0, swap, note="roles swapped on the right->left motion: must fail")
    # mirrored motion: left arm picks at -x, right receives
    m = a0.actions.copy()
    mirrored = np.concatenate([m[:, 7:14], m[:, 0:7]], axis=1)
    for col in (0, 3, 5, 7, 10, 12):
        mirrored[:, col] *= -1
    pose = a0.object_pose.copy()
    pose[0] *= -1
    start = mirrored[0].copy()
    add("A_mirrored_swapped", dataclasses.replace(a0, actions=mirrored, start=start,
                                                  object_pose=pose), swap,
        note="mirrored motion, left picks")
    with open(OUT / "cases.tsv", "w") as fh:
        fh.write("case\ttrajectory\tscenario\tsamples\tnote\n")
        for row in CASES:
            fh.write("\t".join(row) + "\n")
    print(json.dumps({"cases": len(CASES), "out": str(OUT)}))


if __name__ == "__main__":
    main()
