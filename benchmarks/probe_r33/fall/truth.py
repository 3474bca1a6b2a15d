"""An independent ground truth for critmoment on real robot models (r30 copy: the relative slip
rule made one-sided, as docs/method.md now defines it; twenty-eighth round probe;
adapted from benchmarks/probe_r26/truth/truth.py). Changes from r26: grippers given as a
`body` subtree (pads = collision geoms grouped by finger body), the friction parameter applied
by own code that reproduces MuJoCo's contact-parameter mixing and writes explicit <pair>s where
the object's own parameters do not govern its contacts (checked at run time against the
unedited model's contacts), the closing axis taken from the two sides' contact points.

Each parameter sample's whole rollout runs in plain MuJoCo (``mujoco.MjModel.from_xml_path``
on the scenario's MJCF, stepped with ``mj_step`` one step at a time), and is classified here
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
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

BUNDLED = Path("/tmp/r33/src/models")
MINVAL = 1e-15


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
        self.xml = xml
        self.orig = mujoco.MjModel.from_xml_path(str(xml))   # unedited, for the contact check
        o = self.orig
        self.traj = np.load(traj_path, allow_pickle=True)
        obj = o.body(self.cfg["object"]["body"]).id
        self.unc = {k: v for k, v in self.cfg.get("uncertainty", {}).items()}
        self.names = list(self.unc.keys())
        obj_geoms = [g for g in range(o.ngeom) if o.geom_bodyid[g] == obj
                     and (o.geom_contype[g] or o.geom_conaffinity[g])]
        self.friction_mode = "none"
        self.pair_ids = []
        if any("geom" in v for v in self.unc.values()):
            partners = self._partners(o, obj, obj_geoms)
            same = all(self._mixed(o, g, x)[:4] == self._own(o, g) for g, x in partners)
            if same:
                self.friction_mode = "priority"
                self.model = mujoco.MjModel.from_xml_path(str(xml))
                top = int(self.model.geom_priority.max())
                for g in obj_geoms:
                    self.model.geom_priority[g] = top + 1
            else:
                self.friction_mode = "pairs"
                spec = mujoco.MjSpec.from_file(str(xml))
                for k, g in enumerate(spec.geoms):
                    if not g.name:
                        g.name = f"probe28_g{k}"
                tmp = spec.compile()
                assert tmp.ngeom == o.ngeom and np.array_equal(tmp.geom_bodyid, o.geom_bodyid)
                names = [tmp.geom(i).name for i in range(tmp.ngeom)]
                for g, x in partners:
                    condim, fr, solref, solimp, margin, gap = self._mixed(o, g, x)
                    spec.add_pair(name=f"probe28_pair_{g}_{x}", geomname1=names[g], geomname2=names[x],
                                  condim=condim, friction=list(fr), solref=list(solref),
                                  solimp=list(solimp), margin=margin, gap=gap)
                self.model = spec.compile()
                self.pair_ids = list(range(o.npair, self.model.npair))
                self.pair_obj = {p: None for p in self.pair_ids}
            self.n_partners = len(partners)
        else:
            self.model = mujoco.MjModel.from_xml_path(str(xml))
        m = self.model
        assert m.ngeom == o.ngeom and m.nbody == o.nbody and m.nq == o.nq
        self._apply_servos(m)  # r29: [servos] (torque motors driven as joint-position servos)
        self.obj_body = obj
        self.obj_geom = m.geom(self.cfg["object"]["geom"]).id
        self.obj_geoms = set(obj_geoms)
        self.support = {m.geom(g).id for g in self.cfg.get("support", {}).get("geoms", [])}
        self.grippers = {}
        for gname, t in self.cfg["grippers"].items():
            if "geoms" in t:
                sides = [{m.geom(g).id} for g in t["geoms"]]
                base = self._lca([m.geom_bodyid[next(iter(sd))] for sd in sides])
                allg = set().union(*sides)
            else:
                base = m.body(t["body"]).id
                sides, allg = self._sides(base)
            # closing axis: a finger's slide joint axis where the fingers slide (the
            # direction they move in); hinge fingers: from the two sides' contact points
            slide_j = []
            for sd in sides:
                for gg in sd:
                    b = m.geom_bodyid[gg]
                    while b not in (base, 0):
                        for j in range(m.body_jntadr[b], m.body_jntadr[b] + m.body_jntnum[b]):
                            if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE and j not in slide_j:
                                slide_j.append(j)
                        b = m.body_parentid[b]
            self.grippers[gname] = dict(sides=sides, all=allg, base=base, slide=slide_j)
        for g in self.grippers.values():
            g["act"] = self._gripper_actuators(g)
        self.base_mass = m.body_mass.copy()
        self.base_inertia = m.body_inertia.copy()
        self.base_friction = m.geom_friction.copy()
        self.base_pair_friction = m.pair_friction.copy()
        self.base_ipos = m.body_ipos.copy()                 # r31: com_offset
        self.base_forcerange = m.actuator_forcerange.copy()  # r31: force_limit
        self.base_forcelimited = m.actuator_forcelimited.copy()
        self.rated = set((self.cfg.get("limits") or {}).keys())
        task = self.cfg["task"]
        self.kind = task["kind"]
        self.task = task
        self.lift = float(task.get("lift_height", 0.02))
        # controls from critmoment (documented dependency)
        import critmoment
        from critmoment.recording import prepare_controls
        from critmoment.trajectory import load_trajectory
        self.twin = critmoment.Twin(str(self.scen_path))
        def _trn(mod):   # actuators compared by type and target joint (ACT's are unnamed)
            return [(int(mod.actuator_trntype[i]), mod.joint(mod.actuator_trnid[i, 0]).name
                     if mod.actuator_trntype[i] == mujoco.mjtTrn.mjTRN_JOINT else int(mod.actuator_trnid[i, 0]))
                    for i in range(mod.nu)]
        tw_names, my_names = _trn(self.twin.model), _trn(m)
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


    # ------------------------------------------------------------------ contact mixing (own)
    @staticmethod
    def _own(m, g):
        f = m.geom_friction[g]
        return (int(m.geom_condim[g]), (f[0], f[0], f[1], f[2], f[2]),
                tuple(m.geom_solref[g]), tuple(m.geom_solimp[g]))

    @staticmethod
    def _mixed(m, g1, g2):
        """MuJoCo's parameters of a dynamic contact between g1 and g2 (docs: Contact
        parameters): the higher priority geom's condim/friction/solref/solimp; equal
        priorities: max condim, max friction, solmix-weighted solref (min if either is
        direct) and solimp; margin and gap the max."""
        p1, p2 = m.geom_priority[g1], m.geom_priority[g2]
        if p1 != p2:
            h = g1 if p1 > p2 else g2
            condim = int(m.geom_condim[h]); f = m.geom_friction[h]
            solref = tuple(m.geom_solref[h]); solimp = tuple(m.geom_solimp[h])
        else:
            condim = int(max(m.geom_condim[g1], m.geom_condim[g2]))
            f = np.maximum(m.geom_friction[g1], m.geom_friction[g2])
            s1, s2 = m.geom_solmix[g1], m.geom_solmix[g2]
            if s1 < MINVAL and s2 < MINVAL:
                mix = 0.5
            elif s1 < MINVAL:
                mix = 0.0
            elif s2 < MINVAL:
                mix = 1.0
            else:
                mix = s1 / (s1 + s2)
            r1, r2 = m.geom_solref[g1], m.geom_solref[g2]
            if r1[0] > 0 and r2[0] > 0:
                solref = tuple(mix * r1 + (1 - mix) * r2)
            else:
                solref = tuple(np.minimum(r1, r2))
            solimp = tuple(mix * m.geom_solimp[g1] + (1 - mix) * m.geom_solimp[g2])
        fr = (f[0], f[0], f[1], f[2], f[2])
        margin = float(max(m.geom_margin[g1], m.geom_margin[g2]))
        gap = float(max(m.geom_gap[g1], m.geom_gap[g2]))
        return condim, fr, solref, solimp, margin, gap

    @staticmethod
    def _partners(m, obj, obj_geoms):
        """(object geom, other geom) pairs MuJoCo may collide dynamically: contype/conaffinity
        compatible, other body, not excluded, not already an explicit pair."""
        excl = set(int(x) for x in m.exclude_signature)
        paired = {(int(a), int(b)) for a, b in zip(m.pair_geom1, m.pair_geom2)}
        out = []
        for g in obj_geoms:
            for x in range(m.ngeom):
                bx = m.geom_bodyid[x]
                if bx == obj:
                    continue
                if not ((m.geom_contype[g] & m.geom_conaffinity[x]) or (m.geom_contype[x] & m.geom_conaffinity[g])):
                    continue
                b1, b2 = sorted((int(obj), int(bx)))
                if ((b1 + 1) << 16) + b2 + 1 in excl:
                    continue
                if (g, x) in paired or (x, g) in paired:
                    continue
                out.append((g, x))
        return out

    def _sides(self, base):
        """Collision geoms of base's subtree grouped by finger: the top-most body with a
        joint on the path from the geom's body up to base."""
        m = self.model
        groups, allg = {}, set()
        for g in range(m.ngeom):
            if not (m.geom_contype[g] or m.geom_conaffinity[g]):
                continue
            b = m.geom_bodyid[g]
            anc = self._ancestors(b)
            if base not in anc:
                continue
            allg.add(g)
            finger = None
            for bb in anc:
                if bb == base:
                    break
                if m.body_jntnum[bb] > 0:
                    finger = bb
            if finger is not None:
                groups.setdefault(finger, set()).add(g)
        sides = [groups[k] for k in sorted(groups)]
        return sides, allg

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
        for p in g["all"]:
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
        m.pair_friction[:] = self.base_pair_friction
        m.body_ipos[:] = self.base_ipos
        m.actuator_forcerange[:] = self.base_forcerange
        m.actuator_forcelimited[:] = self.base_forcelimited
        self.limits_now = self.limits.copy()
        for name, v in zip(self.names, values, strict=True):
            t = self.unc[name]
            kind = t.get("kind", name)
            if kind == "com_offset":      # r31: along the body's own x axis, inertia unchanged
                b = m.body(t["body"]).id
                m.body_ipos[b, 0] = self.base_ipos[b, 0] + v
                m.body_sameframe[b] = 0   # the inertial frame no longer coincides with the body frame
                m.body_simple[b] = 0
            elif kind == "force_limit":   # r31: the actuator's symmetric forcerange
                a = m.actuator(t["actuator"]).id
                m.actuator_forcerange[a] = [-v, v]
                m.actuator_forcelimited[a] = 1
                if t["actuator"] not in self.rated:
                    self.limits_now[a] = v
            elif "body" in t:
                b = m.body(t["body"]).id
                m.body_inertia[b] = self.base_inertia[b] * (v / self.base_mass[b])
                m.body_mass[b] = v
            elif "geom" in t:
                if self.friction_mode == "priority":
                    for g in self.obj_geoms:
                        m.geom_friction[g, 0] = v
                else:
                    for p in self.pair_ids:
                        m.pair_friction[p, 0:2] = v
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
        if not self._obj_contacts(data, all_=True):
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
                still = 0 if (moving or not self._obj_contacts(data, all_=True)) else still + 1
                if still >= 25:
                    break
            data.time = 0.0
            mujoco.mj_forward(m, data)

    def _obj_contacts(self, data, model=None, all_=False):
        """{partner geom: [contact positions]} of the object's active contacts (dist <= 0)."""
        out = {}
        m = model or self.model
        for i in range(data.ncon):
            c = data.contact[i]
            if c.dist > 0 and not all_:
                continue
            g1, g2 = c.geom1, c.geom2
            if m.geom_bodyid[g1] == self.obj_body:
                out.setdefault(g2, []).append(c.pos.copy())
            elif m.geom_bodyid[g2] == self.obj_body:
                out.setdefault(g1, []).append(c.pos.copy())
        return out

    def contact_check(self, states, mu):
        """Own check of the friction edit: at each qpos in states, the object's contacts in the
        edited model (friction mu) vs the unedited model: same geom pairs, condim, solref,
        solimp, torsional/rolling friction; sliding friction = mu. Returns mismatch lines."""
        m, o = self.model, self.orig
        d1, d2 = mujoco.MjData(m), mujoco.MjData(o)
        bad, n = [], 0
        for q in states:
            d1.qpos[:] = q; d2.qpos[:] = q
            mujoco.mj_forward(m, d1); mujoco.mj_forward(o, d2)
            def table(d, mod):
                t = {}
                for i in range(d.ncon):
                    c = d.contact[i]
                    if self.obj_body in (mod.geom_bodyid[c.geom1], mod.geom_bodyid[c.geom2]):
                        t.setdefault(tuple(sorted((c.geom1, c.geom2))), []).append(
                            (c.dim, tuple(np.round(c.solref, 9)), tuple(np.round(c.solimp, 9)),
                             tuple(np.round(c.friction, 9)), round(float(c.dist), 9)))
                return t
            t1, t2 = table(d1, m), table(d2, o)
            if set(t1) != set(t2):
                bad.append(f"geom pairs differ: {sorted(t1)} vs {sorted(t2)}")
                continue
            for k in t1:
                for a, b in zip(sorted(t1[k], key=lambda r: r[4]), sorted(t2[k], key=lambda r: r[4])):
                    n += 1
                    if a[0] != b[0] or a[1] != b[1] or a[2] != b[2] or a[3][2:] != b[3][2:] \
                            or abs(a[3][0] - mu) > 1e-9 or abs(a[3][1] - mu) > 1e-9:
                        bad.append(f"{k}: edited {a} vs unedited {b}")
        return n, bad

    # ------------------------------------------------------------------ rollout
    def _apply_servos(self, m):
        """r29: own implementation of formats.md's [servos]: the motor becomes a joint servo
        torque = kp (target - q) - kv q' (acting on the joint whatever the gear), control = the
        joint's target (its range), force range = the motor's bound (|ctrlrange| x gain, within
        its own forcerange)."""
        sv = self.cfg.get("servos", {})
        tables = {k: v for k, v in sv.items() if isinstance(v, dict)}
        glob = {k: v for k, v in sv.items() if not isinstance(v, dict)}
        self.servo_acts = []
        for a in range(m.nu):
            name = m.actuator(a).name
            if m.actuator_trntype[a] != mujoco.mjtTrn.mjTRN_JOINT:
                continue
            if m.actuator_gaintype[a] != mujoco.mjtGain.mjGAIN_FIXED or m.actuator_biastype[a] != mujoco.mjtBias.mjBIAS_NONE:
                continue
            t = tables.get(name, glob if glob else None)
            if t is None:
                continue
            kp, kv = float(t["kp"]), float(t.get("kv", 0.0))
            gear = float(m.actuator_gear[a, 0])
            gain = float(m.actuator_gainprm[a, 0])
            bound = max(abs(m.actuator_ctrlrange[a, 0]), abs(m.actuator_ctrlrange[a, 1])) * abs(gain)
            if m.actuator_forcelimited[a]:
                bound = min(bound, max(abs(m.actuator_forcerange[a, 0]), abs(m.actuator_forcerange[a, 1])))
            j = m.actuator_trnid[a, 0]
            m.actuator_gainprm[a, :] = 0.0
            m.actuator_biasprm[a, :] = 0.0
            m.actuator_gainprm[a, 0] = kp / gear
            m.actuator_biastype[a] = mujoco.mjtBias.mjBIAS_AFFINE
            m.actuator_biasprm[a, 1] = -kp / gear
            m.actuator_biasprm[a, 2] = -kv / gear
            m.actuator_forcelimited[a] = 1
            m.actuator_forcerange[a] = [-bound, bound]
            if m.jnt_limited[j]:
                m.actuator_ctrlrange[a] = m.jnt_range[j]
            else:
                m.actuator_ctrllimited[a] = 0
            self.servo_acts.append(a)

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
            rec["sup"][t] = bool(set(con) & self.support)
            rec.setdefault("other", np.zeros(T, bool))[t] = bool(set(con) - self.support - set().union(*(g["all"] for g in self.grippers.values())))  # r33
            if t % 50 == 0:
                rec.setdefault("qpos_s", []).append(data.qpos.copy())
            for k, gname in enumerate(G):
                g = self.grippers[gname]
                sides = g["sides"]
                rec["touch"][t, k] = bool(set(con) & g["all"])
                hit = [[p for gg in sd if gg in con for p in con[gg]] for sd in sides]
                rec["both"][t, k] = len(sides) >= 2 and sum(bool(h) for h in hit) >= 2
                R = data.xmat[g["base"]].reshape(3, 3)
                rec["rel"][t, k] = R.T @ (data.xpos[self.obj_body] - data.xpos[g["base"]])
                hh = [h for h in hit if h]
                if g["slide"]:
                    ax = data.xaxis[g["slide"][0]]
                    rec["axis"][t, k] = R.T @ ax / (np.linalg.norm(ax) + 1e-12)
                elif len(hh) >= 2:
                    ax = np.mean(hh[0], axis=0) - np.mean(hh[1], axis=0)
                    rec["axis"][t, k] = R.T @ ax / (np.linalg.norm(ax) + 1e-12)
                elif t > 0:
                    rec["axis"][t, k] = rec["axis"][t - 1, k]
            for a in range(m.nu):
                if m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT:
                    j = m.actuator_trnid[a, 0]
                    tgt = self.joint_target(a, data.ctrl[a])
                    if tgt is not None:
                        rec["lag"][t, a] = abs(data.qpos[m.jnt_qposadr[j]] - tgt)
                rec["frac"][t, a] = abs(data.actuator_force[a]) / getattr(self, 'limits_now', self.limits)[a]
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
        goal = (np.asarray(s.task["goal"], float) if "goal" in s.task
                else s.model.site_pos[s.model.site(s.task["goal_site"]).id].copy())  # r29: goal_site (a world site)
        tol = float(s.task.get("tolerance", 0.03))
        dist = float(np.linalg.norm(pos[-w:] - goal, axis=1).max())  # r31: whole final window
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
    max_rel = 0.0
    rel_events = {}
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
            if nominal is not None:
                # secondary rule (critmoment's documented reference, own code): the
                # displacement relative to the nominal run's, counted from when both hold
                nb = fill_gaps(nominal["both"][:, k], n20) & steady
                both_h = np.zeros(T, bool); both_h[t:e] = True; both_h &= nb
                if both_h.any():
                    s0 = int(np.flatnonzero(both_h)[0])
                    idx = np.flatnonzero(both_h)
                    # r30: one-sided, as docs/method.md now defines it (own code): the sample's
                    # displacement's distance to the segment from 0 to the nominal's, both with
                    # the closing axis projected out
                    ax0 = rec["axis"][s0, k]
                    ds = rec["rel"][idx, k] - rec["rel"][s0, k]
                    dn = nominal["rel"][idx, k] - nominal["rel"][s0, k]
                    ds = ds - np.outer(ds @ ax0, ax0)
                    dn = dn - np.outer(dn @ ax0, ax0)
                    L2 = (dn * dn).sum(1)
                    u = np.where(L2 > 0, (ds * dn).sum(1) / np.where(L2 > 0, L2, 1.0), 0.0).clip(0.0, 1.0)
                    pr = np.linalg.norm(ds - u[:, None] * dn, axis=1)
                    max_rel = max(max_rel, float(pr.max()))
                    over = np.zeros(T, bool); over[idx] = pr > 0.01
                    over &= ~rec["sup"]   # r33: not while the object rests on a support (set down early, hand moving around it)
                    i = runs_of(over, n50)
                    if i >= 0 and "SLIP_REL" not in rel_events:
                        rel_events["SLIP_REL"] = i
            t = e
    info["max_slip_mm"] = round(1000 * max_slip, 2)
    info["max_slip_rel_mm"] = round(1000 * max_rel, 2)
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
    # r33 FALL (own code): a stretch where the object lies on a declared support touched by no
    # gripper, starting more than 3 cm below its height at the last gripper touch, after it was
    # first lifted. FALL counts (even in a completed run) where the probe's own nominal run
    # carries the object (gripper touch, no support) at the stretch's first step; FALL_RAW
    # regardless of the nominal (informational); FALL_ANY: also onto a non-support geom.
    anyt = touch.any(axis=1)
    if lifted:
        first_lift = int(np.flatnonzero(lifted_mask)[0])
        for key, land in (("FALL_RAW", rec["sup"]), ("FALL_ANY", rec["sup"] | rec.get("other", rec["sup"]))):
            lying = land & ~anyt
            st = [i for i in range(first_lift + 1, len(pos)) if lying[i] and not lying[i - 1]]
            for s0 in st:
                L = np.flatnonzero(anyt[:s0])
                if L.size and pos[L[-1], 2] - pos[s0, 2] > 0.03:
                    info.setdefault(key.lower() + "_at", [int(L[-1]) + 1, int(s0), round(float(pos[L[-1], 2] - pos[s0, 2]), 4)])
                    if key == "FALL_RAW" and nominal is not None:
                        nc = nominal["touch"].any(axis=1) & ~nominal["sup"]
                        if nc[s0] and "FALL" not in events:
                            events["FALL"] = int(L[-1]) + 1
                    break
    info["events"] = {k: int(v) for k, v in events.items()}
    # secondary outcome: the same rules with the relative slip instead of the absolute one
    ev2 = {k: v for k, v in events.items() if k != "SLIP"}
    ev2.update({"SLIP": v for v in rel_events.values()})
    if ok and not any(k in ev2 for k in ("SLIP", "TRACK", "SAT", "FALL")):
        info["outcome_rel"] = "SUCCESS"
    elif not ev2:
        info["outcome_rel"] = "NOT_COMPLETED"
    else:
        f2 = min(ev2, key=ev2.get)
        info["outcome_rel"] = {"SLIP": "SLIPPED", "TRACK": "MOTOR", "SAT": "MOTOR", "DROP": "DROPPED", "FALL": "DROPPED"}[f2]
    if ok and not any(k in events for k in ("SLIP", "TRACK", "SAT", "FALL")):
        return "SUCCESS", info
    if not events:
        return "NOT_COMPLETED", info
    first = min(events, key=events.get)
    return {"SLIP": "SLIPPED", "TRACK": "MOTOR", "SAT": "MOTOR", "DROP": "DROPPED", "FALL": "DROPPED"}[first], info


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenario", required=True)
    ap.add_argument("traj")
    ap.add_argument("--validate-json", help="validate --json output: its per_sample values are run")
    ap.add_argument("--out", help="write JSON results here")
    ap.add_argument("--brute", action="store_true", help="also run critmoment.groundtruth.brute_force")
    ap.add_argument("--only", type=int, nargs="*", help="sample indices to run")
    ap.add_argument("--compare-cm", action="store_true", help="compare the nominal object path with critmoment's rollout")
    ap.add_argument("--points", help="JSON list of parameter dicts to run instead of validate's samples (region check)")
    ap.add_argument("--controls", default="critmoment", choices=["critmoment", "zoh"],
                    help="per-step ctrl: critmoment's prepare_controls (spline) or own zero-order hold")
    args = ap.parse_args()
    s = Setup(args.scenario, args.traj, controls=args.controls)
    if args.points:
        pts = json.load(open(args.points))
        val = {"per_sample": [dict(values=p, outcome="n/a", predicted_failed=None, real_failed=None) for p in pts]}
    else:
        val = json.load(open(args.validate_json))
    samples = np.array([[p["values"][n] for n in s.names] for p in val["per_sample"]])
    nominal_vals = [s.unc[n]["nominal"] for n in s.names]
    nom = s.rollout(nominal_vals)
    nom_out, nom_info = classify(s, nom)
    print("nominal", nom_out, nom_info, flush=True)
    print("friction mode", s.friction_mode, "pairs added", len(s.pair_ids), "partners", getattr(s, "n_partners", 0),
          "grippers", {k: dict(sides=[sorted(int(x) for x in sd) for sd in g["sides"]], act=g["act"], base=int(g["base"]))
                       for k, g in s.grippers.items()})
    fi = s.names.index("friction") if "friction" in s.names else None
    if fi is not None:
        ncon, bad = s.contact_check(nom["qpos_s"], nominal_vals[fi])
        print(f"contact check: {ncon} object contacts compared, {len(bad)} mismatches", bad[:3], flush=True)
    if args.compare_cm:
        import critmoment as cm
        crec = cm.rollout(s.ctraj, twin=s.twin) if "twin" in cm.rollout.__code__.co_varnames else cm.rollout(s.ctraj, s.twin.scenario)
        cpos = np.asarray(crec.signals.object_pos)
        n = min(len(cpos), len(nom["pos"]))
        dd = np.linalg.norm(cpos[:n] - nom["pos"][:n], axis=1)
        print(f"nominal object path vs critmoment's rollout: max diff {dd.max():.3g} m (first > 1 mm at step "
              f"{int(np.argmax(dd > 1e-3)) if (dd > 1e-3).any() else -1}), lengths {len(cpos)} {len(nom['pos'])}", flush=True)
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
        cm_fail = p["real_failed"] if p["real_failed"] is not None else (bf.failed[i] if bf is not None else None)
        row["agree_fail"] = mine_fail == cm_fail
        row["agree_fail_rel"] = (info.get("outcome_rel", out) != "SUCCESS") == cm_fail
        row["agree_label"] = out.lower() == p["outcome"].lower()
        rows.append(row)
        flag = "" if row["agree_label"] else ("  <-- LABEL" if row["agree_fail"] else "  <== FAIL/PASS DIFFERS")
        print(f"{i:2d} {row['values']} mine={out:13s} cm={p['outcome']:13s} pred_fail={p['predicted_failed']}"
              f" {json.dumps(info)}{flag}" + (f"\n      bf={row['bf']}" if bf is not None else ""), flush=True)
    from collections import Counter
    print("mine", dict(Counter(r["mine"] for r in rows)))
    print("cm  ", dict(Counter(r["cm_outcome"].upper() for r in rows)))
    print("fail/pass disagreements (rel rule)", sum(not r["agree_fail_rel"] for r in rows))
    print("fail/pass disagreements", sum(not r["agree_fail"] for r in rows),
          "label disagreements", sum(not r["agree_label"] for r in rows))
    if args.out:
        json.dump(dict(nominal=[nom_out, nom_info], rows=rows), open(args.out, "w"), indent=1, default=str)


if __name__ == "__main__":
    sys.exit(main())
