"""An independent ground truth for critmoment (copied from benchmarks/probe_r26/truth/truth.py; 29th-round physics probe: only BUNDLED changed).

Each parameter sample's whole rollout runs in plain MuJoCo (``mujoco.MjModel.from_xml_path``
on the scenario's MJCF, stepped with ``mj_step`` one step at a time), and is classified here
from physics alone, without critmoment's recording, task or ground-truth code.

What is taken from critmoment (and only this):
  * the per-physics-step controls: ``critmoment.recording.prepare_controls`` (the scenario's
    channel mapping ``Twin.controls`` + its upsampling), and ``Twin.controls`` of the
    trajectory's ``start`` for the initial ctrl;
  * the scenario.toml is parsed here with ``tomllib`` (own code).

Everything else is own code: the model edits for the parameters (body mass with the inertia
scaled, sliding friction of the object's geom with the object's geom priority raised above
every other geom when the friction varies, as scenario.py's docstring says critmoment does
when the object's contact parameters already govern; ``mj_setConst`` after a mass change),
the initial state (keyframe, qpos0 / start joint targets, object pose, settling onto the
support), the contact bookkeeping and the classification.

Classification (thresholds are this probe's, fixed before comparing):
  * SUCCESS rule per task kind (own reading of docs/method + task.py's docstring):
      - handover: at the end (last 50 ms) the receiver touches the object in >= 50 % of the
        steps, no support touches it in the last 50 ms, and its height is >= 1 cm above start;
      - pick_place: lifted >= lift_height above start at some step; at the last step within
        tolerance of the goal; no gripper contact in the last 50 ms; speed <= 0.05 m/s at the
        last step;
      - pick_hold: lifted >= lift_height; the gripper touches it in >= 50 % of the last 50 ms
        and no support touches it in the last 50 ms.
  * SLIP: a "firm hold" of a gripper is a stretch where both its pads touch the object and
    the gripper's own actuator controls have not changed for >= 50 ms (the grasp has settled,
    the release has not begun). The object's position in the gripper body's frame (the
    lowest common ancestor body of its pads) is taken at the start of the hold; slip is its
    displacement perpendicular to the pads' closing axis exceeding 1 cm for >= 50 ms within
    the hold (contact losses of <= 20 ms do not end a hold).
  * DROP: the object was lifted (>= lift_height above start, touched by a gripper), later
    touched by no gripper for > 20 ms, and the task is not completed.
  * TRACK: an arm joint (driven by a position-like actuator that is not a gripper's) lags
    its servo target (gain*ctrl + biasprm0)/(-biasprm1)/gear by more than 0.1 rad *more
    than in this probe's own nominal run at the same step* for >= 100 ms.
  * SAT: an arm actuator's force at >= 0.99 of its limit (min of forcerange and the joint's
    actuatorfrcrange / gear) for >= 50 ms.
  * Outcome: SUCCESS if completed and no SLIP/TRACK/SAT; otherwise the *earliest* event
    among SLIP, TRACK, SAT, DROP names it (MOTOR for TRACK/SAT); NOT_COMPLETED if none.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import mujoco
import numpy as np
import tomllib

BUNDLED = Path("/tmp/r29/src/models")


def scenario_path(name: str) -> Path:
    p = Path(name)
    if p.is_dir():
        p = p / "scenario.toml"
    if p.exists():
        return p
    return BUNDLED / name / "scenario.toml"


class Setup:
    def __init__(self, scen: str, traj_path: str, controls: str = "critmoment"):
        self.scen_path = scenario_path(scen)
        self.cfg = tomllib.loads(self.scen_path.read_text())
        xml = self.scen_path.parent / self.cfg["model"]["mjcf"]
        self.model = mujoco.MjModel.from_xml_path(str(xml))
        m = self.model
        self.traj = np.load(traj_path, allow_pickle=True)
        self.obj_body = m.body(self.cfg["object"]["body"]).id
        self.obj_geom = m.geom(self.cfg["object"]["geom"]).id
        self.obj_geoms = {g for g in range(m.ngeom) if m.geom_bodyid[g] == self.obj_body}
        self.support = {m.geom(g).id for g in self.cfg.get("support", {}).get("geoms", [])}
        self.grippers = {}
        for gname, t in self.cfg["grippers"].items():
            pads = [m.geom(g).id for g in t["geoms"]]
            self.grippers[gname] = dict(pads=pads, base=self._lca([m.geom_bodyid[p] for p in pads]))
        for g in self.grippers.values():
            g["act"] = self._gripper_actuators(g)
        self.unc = {k: v for k, v in self.cfg.get("uncertainty", {}).items()}
        self.names = list(self.unc.keys())
        # friction varies -> object's geom(s) get a priority above every other geom
        self.base_mass = m.body_mass.copy()
        self.base_inertia = m.body_inertia.copy()
        self.base_friction = m.geom_friction.copy()
        if any("geom" in v for v in self.unc.values()):
            top = int(m.geom_priority.max())
            for g in self.obj_geoms:
                m.geom_priority[g] = top + 1
        task = self.cfg["task"]
        self.kind = task["kind"]
        self.task = task
        self.lift = float(task.get("lift_height", 0.02))
        # controls from critmoment (documented dependency)
        import critmoment
        from critmoment.recording import prepare_controls
        from critmoment.trajectory import load_trajectory
        self.twin = critmoment.Twin(str(self.scen_path))
        tw_names = [self.twin.model.actuator(i).name for i in range(self.twin.model.nu)]
        my_names = [m.actuator(i).name for i in range(m.nu)]
        if tw_names != my_names:
            raise SystemExit(f"actuator order differs: {tw_names} vs {my_names}")
        self.ctraj = load_trajectory(traj_path)
        self.controls = np.asarray(prepare_controls(self.twin, self.ctraj))
        if controls == "zoh":
            # own re-derivation: each action row held for its whole control period (a
            # zero-order hold, as a gym env's step() applies it), mapped by Twin.controls
            dt = m.opt.timestep
            n = self.controls.shape[0]
            rows = np.minimum(np.floor(np.arange(n) * dt * float(self.ctraj.fps) + 1e-9).astype(int),
                              self.ctraj.actions.shape[0] - 1)
            self.controls = np.asarray(self.twin.controls(np.asarray(self.ctraj.actions)[rows]))
        start = self.ctraj.start if self.ctraj.start is not None else self.ctraj.actions[0]
        self.ctrl0 = np.asarray(self.twin.controls(np.asarray(start)[None])[0])
        self.arm_act = [a for a in range(m.nu) if not any(a in g["act"] for g in self.grippers.values())
                        and m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT]
        self.limits = np.array([self._limit(a) for a in range(m.nu)])

    # ------------------------------------------------------------------ model helpers
    def _ancestors(self, b):
        out = [b]
        while b != 0:
            b = self.model.body_parentid[b]
            out.append(b)
        return out

    def _lca(self, bodies):
        common = set(self._ancestors(bodies[0]))
        for b in bodies[1:]:
            common &= set(self._ancestors(b))
        for b in self._ancestors(bodies[0]):
            if b in common:
                return b
        return 0

    def _gripper_actuators(self, g):
        m = self.model
        path = set()
        for p in g["pads"]:
            for b in self._ancestors(m.geom_bodyid[p]):
                if b == g["base"]:
                    break
                path.add(b)
        out = []
        for a in range(m.nu):
            if m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT:
                j = m.actuator_trnid[a, 0]
                if m.jnt_bodyid[j] in path:
                    out.append(a)
            elif m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_TENDON:
                pass
        return out

    def _limit(self, a):
        m = self.model
        lim = np.inf
        if m.actuator_forcelimited[a]:
            lim = min(lim, max(abs(m.actuator_forcerange[a, 0]), abs(m.actuator_forcerange[a, 1])))
        if m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT:
            j = m.actuator_trnid[a, 0]
            if m.jnt_actfrclimited[j]:
                lim = min(lim, max(abs(m.jnt_actfrcrange[j])) / abs(m.actuator_gear[a, 0]))
        return lim

    def joint_target(self, a, ctrl):
        """Joint angle a position-like servo holds at ctrl (None if not position-like)."""
        m = self.model
        b1 = m.actuator_biasprm[a, 1]
        if b1 >= 0:
            return None
        return (m.actuator_gainprm[a, 0] * ctrl + m.actuator_biasprm[a, 0]) / (-b1) / m.actuator_gear[a, 0]

    # ------------------------------------------------------------------ parameters
    def apply(self, values):
        m = self.model
        m.body_mass[:] = self.base_mass
        m.body_inertia[:] = self.base_inertia
        m.geom_friction[:] = self.base_friction
        for name, v in zip(self.names, values, strict=True):
            t = self.unc[name]
            if "body" in t:
                b = m.body(t["body"]).id
                m.body_inertia[b] = self.base_inertia[b] * (v / self.base_mass[b])
                m.body_mass[b] = v
            elif "geom" in t:
                m.geom_friction[m.geom(t["geom"]).id, 0] = v
            else:
                raise SystemExit(f"unsupported parameter {name}: {t}")

    # ------------------------------------------------------------------ initial state
    def initial(self, data):
        m = self.model
        mujoco.mj_resetData(m, data)
        key = self.cfg["model"].get("keyframe")
        if key:
            mujoco.mj_resetDataKeyframe(m, data, m.key(key).id)
        jadr = m.jnt_qposadr[m.body_jntadr[self.obj_body]]
        if "qpos0" in self.traj.files:
            data.qpos[:] = self.traj["qpos0"]
        else:
            for a in range(m.nu):
                if m.actuator_trntype[a] != mujoco.mjtTrn.mjTRN_JOINT:
                    continue
                q = self.joint_target(a, self.ctrl0[a])
                if q is not None:
                    data.qpos[m.jnt_qposadr[m.actuator_trnid[a, 0]]] = q
        if "object_pose" in self.traj.files:
            data.qpos[jadr:jadr + 7] = self.traj["object_pose"]
        data.qvel[:] = 0
        data.ctrl[:] = self.ctrl0
        mujoco.mj_forward(m, data)
        # settle an object that touches nothing, robot held
        if not self._obj_contacts(data):
            q = data.qpos.copy()
            dof = m.jnt_dofadr[m.body_jntadr[self.obj_body]]
            still = 0
            for _ in range(1000):
                mujoco.mj_step(m, data)
                keep = np.ones(m.nq, bool)
                keep[jadr:jadr + 7] = False
                data.qpos[keep] = q[keep]
                kv = np.ones(m.nv, bool)
                kv[dof:dof + 6] = False
                data.qvel[kv] = 0
                data.ctrl[:] = self.ctrl0
                moving = np.linalg.norm(data.qvel[dof:dof + 3]) > 1e-3
                still = 0 if (moving or not self._obj_contacts(data)) else still + 1
                if still >= 25:
                    break
            data.time = 0.0
            mujoco.mj_forward(m, data)

    def _obj_contacts(self, data):
        out = set()
        m = self.model
        for i in range(data.ncon):
            c = data.contact[i]
            g1, g2 = c.geom1, c.geom2
            if m.geom_bodyid[g1] == self.obj_body:
                out.add(g2)
            elif m.geom_bodyid[g2] == self.obj_body:
                out.add(g1)
        return out

    # ------------------------------------------------------------------ rollout
    def rollout(self, values):
        m = self.model
        self.apply(values)
        data = mujoco.MjData(m)
        mujoco.mj_setConst(m, data)
        self.initial(data)
        T = self.controls.shape[0]
        G = list(self.grippers)
        rec = dict(pos=np.zeros((T, 3)), vel=np.zeros((T, 3)), sup=np.zeros(T, bool),
                   touch=np.zeros((T, len(G)), bool), both=np.zeros((T, len(G)), bool),
                   rel=np.zeros((T, len(G), 3)), axis=np.zeros((T, len(G), 3)),
                   lag=np.zeros((T, m.nu)), frac=np.zeros((T, m.nu)), diverged=-1)
        dof = m.jnt_dofadr[m.body_jntadr[self.obj_body]]
        for t in range(T):
            data.ctrl[:] = self.controls[t]
            mujoco.mj_step(m, data)
            if not np.isfinite(data.qpos).all() or data.warning[mujoco.mjtWarning.mjWARN_BADQACC].number:
                rec["diverged"] = t
                break
            rec["pos"][t] = data.xpos[self.obj_body]
            rec["vel"][t] = data.qvel[dof:dof + 3]
            con = self._obj_contacts(data)
            rec["sup"][t] = bool(con & self.support)
            for k, gname in enumerate(G):
                g = self.grippers[gname]
                pads = g["pads"]
                rec["touch"][t, k] = bool(con & set(pads))
                rec["both"][t, k] = all(p in con for p in pads)
                R = data.xmat[g["base"]].reshape(3, 3)
                rec["rel"][t, k] = R.T @ (data.xpos[self.obj_body] - data.xpos[g["base"]])
                if len(pads) >= 2:
                    ax = data.geom_xpos[pads[0]] - data.geom_xpos[pads[1]]
                    rec["axis"][t, k] = R.T @ ax / (np.linalg.norm(ax) + 1e-12)
            for a in range(m.nu):
                if m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT:
                    j = m.actuator_trnid[a, 0]
                    tgt = self.joint_target(a, data.ctrl[a])
                    if tgt is not None:
                        rec["lag"][t, a] = abs(data.qpos[m.jnt_qposadr[j]] - tgt)
                rec["frac"][t, a] = abs(data.actuator_force[a]) / self.limits[a]
        rec["z0"] = float(self.traj["object_pose"][2]) if "object_pose" in self.traj.files else float(rec["pos"][0, 2])
        return rec


def runs_of(mask, n):
    """Start index of the first run of >= n consecutive True, or -1."""
    c = 0
    for i, v in enumerate(mask):
        c = c + 1 if v else 0
        if c >= n:
            return i - n + 1
    return -1


def fill_gaps(mask, n):
    """False gaps of <= n steps between True stretches become True."""
    out = mask.copy()
    idx = np.flatnonzero(mask)
    for a, b in zip(idx[:-1], idx[1:], strict=True):
        if 1 < b - a <= n + 1:
            out[a:b] = True
    return out


def classify(s: Setup, rec, nominal=None):
    m = s.model
    dt = m.opt.timestep
    w = max(1, int(round(0.05 / dt)))
    n20, n50, n100 = int(round(0.02 / dt)), w, int(round(0.1 / dt))
    G = list(s.grippers)
    info = {}
    if rec["diverged"] >= 0:
        return "DIVERGED", info
    pos, touch = rec["pos"], rec["touch"]
    z0 = rec["z0"]
    lifted_mask = (pos[:, 2] >= z0 + s.lift) & touch.any(axis=1)
    lifted = bool(lifted_mask.any())
    kind = s.kind
    if kind == "handover":
        r = G.index(s.task["receiver"])
        ok = (touch[-w:, r].mean() >= 0.5) and not rec["sup"][-w:].any() and pos[-1, 2] >= z0 + 0.01
        pk = G.index(s.task["picker"])
        info.update(receiver_both_end=float(rec["both"][-w:, r].mean()),
                    picker_touch_end=float(touch[-w:, pk].mean()))
    elif kind == "pick_place":
        goal = np.asarray(s.task["goal"], float)
        tol = float(s.task.get("tolerance", 0.03))
        dist = float(np.linalg.norm(pos[-1] - goal))
        speed = float(np.linalg.norm(rec["vel"][-1]))
        ok = lifted and dist <= tol and not touch[-w:].any() and speed <= float(s.task.get("rest_speed", 0.05))
        info.update(goal_dist=round(dist, 4), end_speed=round(speed, 4))
    elif kind == "pick_hold":
        gi = G.index(s.task.get("gripper", G[0]))
        ok = lifted and touch[-w:, gi].mean() >= 0.5 and not rec["sup"][-w:].any()
    else:
        raise SystemExit(kind)
    info["completed"] = bool(ok)
    info["lifted"] = lifted
    info["end_pos"] = [round(float(x), 4) for x in pos[-1]]
    events = {}
    # slip
    max_slip = 0.0
    for k, gname in enumerate(G):
        acts = s.grippers[gname]["act"]
        ctrl = s.controls[:, acts] if acts else np.zeros((len(pos), 1))
        steady = np.zeros(len(pos), bool)
        for t in range(n50, len(pos)):
            steady[t] = np.ptp(ctrl[t - n50:t + 1], axis=0).max() < 1e-9
        hold = fill_gaps(rec["both"][:, k], n20) & steady
        t = 0
        T = len(pos)
        while t < T:
            if not hold[t]:
                t += 1
                continue
            e = t
            while e < T and hold[e]:
                e += 1
            ref = rec["rel"][t, k]
            ax = rec["axis"][t, k]
            d = rec["rel"][t:e, k] - ref
            perp = d - np.outer(d @ ax, ax)
            dn = np.linalg.norm(perp, axis=1)
            max_slip = max(max_slip, float(dn.max()))
            i = runs_of(dn > 0.01, n50)
            if i >= 0 and "SLIP" not in events:
                events["SLIP"] = t + i
            t = e
    info["max_slip_mm"] = round(1000 * max_slip, 2)
    # drop
    if lifted and not ok:
        first_lift = int(np.flatnonzero(lifted_mask)[0])
        lost = ~touch.any(axis=1)
        lost[:first_lift] = False
        i = runs_of(lost, n20 + 1)
        if i >= 0:
            events["DROP"] = i
    # motor
    arm = s.arm_act
    if arm:
        frac = rec["frac"][:, arm]
        i = runs_of((frac >= 0.99).any(axis=1), n50)
        info["max_frac"] = round(float(frac.max()), 4)
        if i >= 0:
            events["SAT"] = i
        absl = rec["lag"][:, arm]
        info["max_abs_lag"] = round(float(absl.max()), 4)
        info["abs_lag_joint"] = m.actuator(arm[int(np.argmax(absl.max(axis=0)))]).name
        if nominal is not None:
            excess = rec["lag"][:, arm] - nominal["lag"][:, arm]
            info["max_lag_excess"] = round(float(excess.max()), 4)
            info["lag_joint"] = m.actuator(arm[int(np.argmax(excess.max(axis=0)))]).name
            i = runs_of((excess > 0.1).any(axis=1), n100)
            if i >= 0:
                events["TRACK"] = i
    info["events"] = {k: int(v) for k, v in events.items()}
    if ok and not any(k in events for k in ("SLIP", "TRACK", "SAT")):
        return "SUCCESS", info
    if not events:
        return "NOT_COMPLETED", info
    first = min(events, key=events.get)
    return {"SLIP": "SLIPPED", "TRACK": "MOTOR", "SAT": "MOTOR", "DROP": "DROPPED"}[first], info


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenario", required=True)
    ap.add_argument("traj")
    ap.add_argument("--validate-json", help="validate --json output: its per_sample values are run")
    ap.add_argument("--out", help="write JSON results here")
    ap.add_argument("--brute", action="store_true", help="also run critmoment.groundtruth.brute_force")
    ap.add_argument("--only", type=int, nargs="*", help="sample indices to run")
    ap.add_argument("--controls", default="critmoment", choices=["critmoment", "zoh"],
                    help="per-step ctrl: critmoment's prepare_controls (spline) or own zero-order hold")
    args = ap.parse_args()
    s = Setup(args.scenario, args.traj, controls=args.controls)
    val = json.load(open(args.validate_json))
    samples = np.array([[p["values"][n] for n in s.names] for p in val["per_sample"]])
    nominal_vals = [s.unc[n]["nominal"] for n in s.names]
    nom = s.rollout(nominal_vals)
    nom_out, nom_info = classify(s, nom)
    print("nominal", nom_out, nom_info, flush=True)
    bf = None
    if args.brute and args.controls == "critmoment":
        import critmoment.groundtruth as gt
        bf = gt.brute_force(s.ctraj, twin=s.twin, samples=samples, nthread=1)
    rows = []
    idx = args.only if args.only else range(len(samples))
    for i in idx:
        rec = s.rollout(samples[i])
        out, info = classify(s, rec, nom)
        p = val["per_sample"][i]
        row = dict(i=i, values=dict(zip(s.names, samples[i].tolist(), strict=True)), mine=out,
                   cm_outcome=p["outcome"], cm_predicted_failed=p["predicted_failed"], info=info)
        if bf is not None:
            c = bf.classification
            row["bf"] = dict(outcome=str(c.outcome[i].name if hasattr(c.outcome[i], "name") else c.outcome[i]),
                             completed=bool(c.completed[i]), first_failure_step=int(c.first_failure_step[i]),
                             slip_step=int(c.slip_step[i]), drop_step=int(c.drop_step[i]),
                             motor_step=int(c.motor_step[i]), max_slip_mm=round(1000 * float(c.max_slip[i]), 2),
                             sat_time=float(c.saturation_time[i]), motor_tracking=bool(c.motor_tracking[i]))
        mine_fail = out != "SUCCESS"
        cm_fail = p["real_failed"]
        row["agree_fail"] = mine_fail == cm_fail
        row["agree_label"] = out.lower() == p["outcome"].lower()
        rows.append(row)
        flag = "" if row["agree_label"] else ("  <-- LABEL" if row["agree_fail"] else "  <== FAIL/PASS DIFFERS")
        print(f"{i:2d} {row['values']} mine={out:13s} cm={p['outcome']:13s} pred_fail={p['predicted_failed']}"
              f" {json.dumps(info)}{flag}" + (f"\n      bf={row['bf']}" if bf is not None else ""), flush=True)
    from collections import Counter
    print("mine", dict(Counter(r["mine"] for r in rows)))
    print("cm  ", dict(Counter(r["cm_outcome"].upper() for r in rows)))
    print("fail/pass disagreements", sum(not r["agree_fail"] for r in rows),
          "label disagreements", sum(not r["agree_label"] for r in rows))
    if args.out:
        json.dump(dict(nominal=[nom_out, nom_info], rows=rows), open(args.out, "w"), indent=1, default=str)


if __name__ == "__main__":
    sys.exit(main())
