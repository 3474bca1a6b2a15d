"""ACT's bimanual peg insertion as a joint-space trajectory for gym-aloha's own insertion scene.

Reuses the project's scripted-demo tools (benchmarks/real_models/scripted.py: Arm, joint_path,
_frame, ACT_START, ACT_TCP; DLS IK of the pads' centre + inverse-dynamics feed-forward).
Waypoints follow ACT's InsertionPolicy timeline (400 steps at 50 Hz; facts from
/work/shared/reference/aloha_facts.md): the left arm picks the socket, the right arm the peg,
both pitched 60 deg down; both lift and meet at (0, 0.5, 0.15): socket at meet - 0.1 x,
peg at meet + 0.1 x (+ a right-arm lift), then each moves 0.05 toward the other.

usage: gen_insertion.py OUT.npz [--object peg|socket] [--peg X Y] [--socket X Y] [--lift DZ]
                        [--grasp-dz DZ] [--push D]
The npz carries qpos0 (arms at ACT's start, both objects resting on the table) and the
object_pose of the audited object (--object).
"""
import argparse
import sys

sys.path.insert(0, "/tmp/r37/src")
import critmoment  # noqa: E402
assert critmoment.__file__.startswith("/tmp/r37/src"), critmoment.__file__
import mujoco  # noqa: E402
import numpy as np  # noqa: E402
import importlib.util  # noqa: E402
_spec = importlib.util.spec_from_file_location("scripted", "/tmp/r37/src/benchmarks/real_models/scripted.py")
_scripted = importlib.util.module_from_spec(_spec)
sys.modules["scripted"] = _scripted
_spec.loader.exec_module(_scripted)
ACT_START, ACT_TCP, Arm, _frame, joint_path = (_scripted.ACT_START, _scripted.ACT_TCP, _scripted.Arm,
                                               _scripted._frame, _scripted.joint_path)

XML = "/tmp/r37/insertion/gym_aloha/assets/bimanual_viperx_insertion.xml"
JOINTS = ("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate")
#: resting heights on the table (peg half height 0.01; socket bottom wall at -0.022)
PEG_Z, SOCKET_Z = 0.01, 0.022


def build(peg_xy=(0.15, 0.5), socket_xy=(-0.15, 0.5), lift=0.00715, grasp_dz=0.0, push=0.05,
          meet=(0.0, 0.5, 0.15), right_approach_seed=None):
    model = mujoco.MjModel.from_xml_path(XML)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    qpos0 = data.qpos.copy()
    peg = np.array([peg_xy[0], peg_xy[1], PEG_Z, 1, 0, 0, 0])
    sock = np.array([socket_xy[0], socket_xy[1], SOCKET_Z, 1, 0, 0, 0])
    for name, pose in (("red_peg_joint", peg), ("blue_socket_joint", sock)):
        a = model.jnt_qposadr[model.joint(name).id]
        qpos0[a:a + 7] = pose
    arms = {side: Arm(model, tuple(f"vx300s_{side}/{j}" for j in JOINTS),
                      f"vx300s_{side}/gripper_link",
                      (f"vx300s_{side}/10_left_gripper_finger",
                       f"vx300s_{side}/10_right_gripper_finger"), qpos0, ACT_TCP)
            for side in ("left", "right")}
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    pitch = np.deg2rad(60.0)
    right_pick = _frame([-np.cos(pitch), 0, -np.sin(pitch)], [0, -1, 0])
    left_pick = _frame([np.cos(pitch), 0, -np.sin(pitch)], [0, 1, 0])
    meet = np.asarray(meet, float)
    pg = peg[:3] + [0, 0, grasp_dz]
    sg = sock[:3] + [0, 0, grasp_dz]
    rs, ls = arms["right"].tcp(data), arms["left"].tcp(data)
    # ACT's InsertionPolicy timeline (steps at 50 Hz)
    right = [(0, rs[0], rs[1], 0.0), (120, pg + [0, 0, 0.08], right_pick, 1.0),
             (170, pg, right_pick, 1.0), (220, pg, right_pick, 0.0),
             (285, meet + [0.1, 0, lift], right_pick, 0.0),
             (340, meet + [0.1 - push, 0, lift], right_pick, 0.0),
             (400, meet + [0.1 - push, 0, lift], right_pick, 0.0)]
    left = [(0, ls[0], ls[1], 0.0), (120, sg + [0, 0, 0.08], left_pick, 1.0),
            (170, sg, left_pick, 1.0), (220, sg, left_pick, 0.0),
            (285, meet + [-0.1, 0, 0], left_pick, 0.0),
            (340, meet + [-0.1 + push, 0, 0], left_pick, 0.0),
            (400, meet + [-0.1 + push, 0, 0], left_pick, 0.0)]
    n, dt = 400, 0.02
    actions = np.zeros((n, 14))
    seeds = {"left": np.array([0.0, -0.5, 1.0, 0.0, 0.6, 0.0]),
             "right": np.array([0.0, -0.5, 1.0, 0.0, 0.6, 0.0])}
    for side, points, col in (("left", left, 0), ("right", right, 7)):
        arm = arms[side]
        data.qpos[:] = qpos0
        q, grip = joint_path(arm, data, points, n, start=ACT_START, seed=seeds[side])
        actions[:, col:col + 6] = arm.feed_forward(q, dt, qpos0)
        actions[:, col + 6] = grip
    start = np.concatenate([ACT_START, [0.0], ACT_START, [0.0]])
    actions[0] = start
    # arms' qpos0 at ACT's start with the fingers closed (as the keyframe's 0.024)
    return actions, start, qpos0, peg, sock


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--object", default="peg", choices=("peg", "socket"))
    ap.add_argument("--peg", type=float, nargs=2, default=(0.15, 0.5))
    ap.add_argument("--socket", type=float, nargs=2, default=(-0.15, 0.5))
    ap.add_argument("--lift", type=float, default=0.00715)
    ap.add_argument("--grasp-dz", type=float, default=0.0)
    ap.add_argument("--push", type=float, default=0.05)
    a = ap.parse_args()
    actions, start, qpos0, peg, sock = build(a.peg, a.socket, a.lift, a.grasp_dz, a.push)
    pose = peg if a.object == "peg" else sock
    np.savez(a.out, actions=actions, fps=50.0, start=start, qpos0=qpos0, object_pose=pose,
             meta=np.array('{"generator": "probe_r37 gen_insertion", "object": "%s", "peg": %s, '
                           '"socket": %s, "lift": %g, "grasp_dz": %g, "push": %g}'
                           % (a.object, list(a.peg), list(a.socket), a.lift, a.grasp_dz, a.push)))
    print("wrote", a.out)


if __name__ == "__main__":
    main()
