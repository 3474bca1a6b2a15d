"""ACT transfer-cube variants on gym-aloha's shipped scene (fall-rule probe, r33).
usage: gen_act.py SCENARIO.toml OUTDIR   -> OUTDIR/act_<variant>.npz
Right arm timeline = real_models' act_transfer (grasp_height 0.015), with a detour inserted
after the grasp: lift to H above the grasp, set the gripper to G (0 closed..1 open) for a while,
close again, go down to the grasp pose, open (set down), re-close (re-grasp), then the rest
of ACT's timeline, shifted by the detour's length."""
import dataclasses, sys, tomllib
from pathlib import Path
import mujoco, numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r33/src"), cm.__file__
sys.path.insert(0, "/tmp/r33/src/benchmarks")
from real_models import scripted as S
from critmoment.trajectory import Trajectory, save_trajectory


Z = None   # r33: the object's start height (centre), for objects other than the 4 cm box


def act(model, seed=0, *, detour=None, early_open=None, left_close=(260, 300), gh=0.015):
    box = S.act_box_pose(seed)
    if Z is not None:
        box[2] = Z
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    qpos0 = data.qpos.copy()
    fj = model.joint("red_box_joint").id
    qpos0[model.jnt_qposadr[fj]:model.jnt_qposadr[fj] + 7] = box
    arms = {side: S.Arm(model, tuple(f"vx300s_{side}/{j}" for j in S.ACT_JOINTS),
                        f"vx300s_{side}/gripper_link",
                        (f"vx300s_{side}/10_left_gripper_finger", f"vx300s_{side}/10_right_gripper_finger"),
                        qpos0, S.ACT_TCP) for side in ("left", "right")}
    data.qpos[:] = qpos0; mujoco.mj_kinematics(model, data)
    pitch = np.deg2rad(60.0)
    rp = S._frame([-np.cos(pitch), 0, -np.sin(pitch)], [0, -1, 0])
    lm = S._frame([1, 0, 0], [0, 0, 1]); lr = S._frame([1, 0, 0], [0, 1, 0])
    meet = np.array([0.0, 0.5, 0.25]); cube = box[:3]
    grasp = cube + [0, 0, gh]; held = meet - [0, 0, gh]
    rs, ls = arms["right"].tcp(data), arms["left"].tcp(data)
    right = [(0, rs[0], rs[1], 0.0), (90, cube + [0, 0, 0.08], rp, 1.0),
             (130, grasp, rp, 1.0), (170, grasp, rp, 0.0)]
    D = 0
    if detour is not None:
        H, G = detour   # lift H, gripper G for 0.3 s, re-close, set down, open, re-grasp
        up = grasp + [0, 0, H]
        if G >= 1.0:   # (a) a real drop: open, stay open, come down open, re-grasp
            right += [(200, up, rp, 0.0), (210, up, rp, 0.0), (214, up, rp, 1.0), (229, up, rp, 1.0),
                      (235, up, rp, 1.0), (245, up, rp, 1.0), (275, grasp, rp, 1.0), (285, grasp, rp, 1.0),
                      (295, grasp, rp, 1.0), (305, grasp, rp, 1.0), (325, grasp, rp, 0.0), (335, grasp, rp, 0.0)]
        else:
            right += [(200, up, rp, 0.0), (210, up, rp, 0.0), (214, up, rp, G), (229, up, rp, G),
                      (235, up, rp, 0.0), (245, up, rp, 0.0), (275, grasp, rp, 0.0), (285, grasp, rp, 0.0),
                      (295, grasp, rp, 1.0), (305, grasp, rp, 1.0), (325, grasp, rp, 0.0), (335, grasp, rp, 0.0)]
        D = 165
    ro = 310 if early_open is None else early_open
    right += [(200 + D, meet + [0.05, 0, 0], rp, 0.0), (220 + D, meet, rp, 0.0),
              (ro + D, meet, rp, 0.0), (ro + 10 + D, meet, rp, 1.0),
              (360 + D, meet + [0.1, 0, 0], rp, 1.0), (400 + D, meet + [0.1, 0, 0], rp, 1.0)]
    c0, c1 = left_close
    left = [(0, ls[0], ls[1], 0.0), (100, held + [-0.1, 0, 0], lm, 1.0),
            (min(c0, 260) + D, held + [-0.01, 0, 0], lm, 1.0)]
    if c0 > 260:
        left.append((c0 + D, held + [-0.01, 0, 0], lm, 1.0))
    left += [(c1 + D, held + [-0.01, 0, 0], lm, 0.0),
             (max(c1, 310) + 10 * (c1 >= 310) + D, held + [-0.01, 0, 0], lm, 0.0),
             (360 + D, held + [-0.1, 0, -0.02], lr, 0.0), (400 + D, held + [-0.1, 0, -0.02], lr, 0.0)]
    n = 400 + D
    actions = np.zeros((n, 14))
    for side, pts, col in (("left", left, 0), ("right", right, 7)):
        data.qpos[:] = qpos0
        q, grip = S.joint_path(arms[side], data, pts, n, start=S.ACT_START,
                               seed=S._APPROACH_SEED if side == "right" else S.ACT_START)
        actions[:, col:col + 6] = arms[side].feed_forward(q, 0.02, qpos0)
        actions[:, col + 6] = grip
    start = np.concatenate([S.ACT_START, [0.0], S.ACT_START, [0.0]])
    actions[0] = start
    return Trajectory(actions=actions, fps=50.0, start=start, object_pose=box,
                      meta={"generator": "probe_r33 gen_act", "detour": detour, "early_open": early_open,
                            "left_close": left_close}, source="probe_r33 gen_act")


VARIANTS = {
    "nominal": {},
    # (a) full open 0.3 s at 8 cm: the object falls (in the nominal run too), set-down, re-grasp
    "drop8_open": dict(detour=(0.08, 1.0)),
    # (b) set-down early and re-grasp, no loosening (G = 0)
    "setdown": dict(detour=(0.08, 0.0)),
}

if __name__ == "__main__":
    argv = sys.argv[1:]
    if "--z" in argv:
        i = argv.index("--z"); Z = float(argv[i + 1]); argv = argv[:i] + argv[i + 2:]
    scen, out = argv[0], Path(argv[1])
    extra = argv[2:]   # more variants as name=H,G  or  name=early:STEP  or name=left:C0,C1
    for e in extra:
        name, spec = e.split("=")
        if spec.startswith("early:"):
            VARIANTS[name] = dict(early_open=int(spec[6:]))
        elif spec.startswith("left:"):
            a, b = spec[5:].split(","); VARIANTS[name] = dict(left_close=(int(a), int(b)))
        elif spec.startswith("catch:"):
            a, b, c = spec[6:].split(","); VARIANTS[name] = dict(early_open=int(a), left_close=(int(b), int(c)))
        else:
            h, g = spec.split(","); VARIANTS[name] = dict(detour=(float(h), float(g)))
    raw = tomllib.loads(Path(scen).read_text())
    model = mujoco.MjModel.from_xml_path(str(Path(scen).parent / raw["model"]["mjcf"]))
    only = [e.split("=")[0] for e in extra] or list(VARIANTS)
    for name in only:
        t = act(model, **VARIANTS[name])
        save_trajectory(t, out / f"act_{name}.npz"); print("wrote", out / f"act_{name}.npz", t.actions.shape)
