"""Independent insertion truth in plain MuJoCo (no critmoment decision code).

Each run: gym-aloha's insertion MJCF loaded with mujoco.MjModel.from_xml_path (optionally the
contact model changed: --cone elliptic --impratio 10), the sample's parameters written here
(body mass with inertia scaled; the audited object's sliding friction on all its geoms with
their priority raised above every other geom, as critmoment documents), qpos0 from the
trajectory, the actions upsampled here (not-a-knot cubic spline for joints, PCHIP for the two
normalised gripper channels, one control per 2 ms step; ACT's channel layout), mj_step.

Decision, ACT's InsertionTask reward read at the end: success when over the last 50 ms the
peg touches the pin in >= 50 % of steps and, in the same window, neither the peg nor any socket
geom touches the table. Also reported: the ACT reward stage at the end and its max over the run.

usage: truth.py TRAJ.npz [--samples validation.json | --values m,f ...] --object peg|socket
                [--cone elliptic --impratio 10] [--out truth.json]
"""
import argparse
import json
import sys

sys.path.insert(0, "/tmp/r37/src")
import critmoment  # noqa: E402  (imported only for the snapshot check; nothing of it is used)
assert critmoment.__file__.startswith("/tmp/r37/src"), critmoment.__file__
import mujoco  # noqa: E402
import numpy as np  # noqa: E402
from scipy.interpolate import CubicSpline, PchipInterpolator  # noqa: E402

XML = "/tmp/r37/insertion/gym_aloha/assets/bimanual_viperx_insertion.xml"
SOCKET = ("socket-1", "socket-2", "socket-3", "socket-4")


def controls(actions, fps, dt, start):
    T, na = actions.shape
    n = int(round((T - 1) / fps / dt)) + 1
    t = np.arange(n) * dt
    ts = np.arange(T) / fps
    out = np.zeros((n, 16))
    for side, col, ucol in ((0, 0, 0), (1, 7, 8)):
        q = CubicSpline(ts, actions[:, col:col + 6], bc_type="not-a-knot")(np.minimum(t, ts[-1]))
        g = np.clip(PchipInterpolator(ts, actions[:, col + 6])(np.minimum(t, ts[-1])), 0, 1)
        out[:, ucol:ucol + 6] = q
        out[:, ucol + 6] = 0.021 + g * 0.036
        out[:, ucol + 7] = -(0.021 + g * 0.036)
    return out


class Truth:
    def __init__(self, traj, obj, cone=None, impratio=None, pairs=False):
        self.m = mujoco.MjModel.from_xml_path(XML)
        self.pairs = pairs
        if pairs:
            self.m = self._pair_model(obj)
        m = self.m
        if cone:
            m.opt.cone = {"elliptic": mujoco.mjtCone.mjCONE_ELLIPTIC,
                          "pyramidal": mujoco.mjtCone.mjCONE_PYRAMIDAL}[cone]
        if impratio:
            m.opt.impratio = impratio
        self.tr = np.load(traj, allow_pickle=True)
        self.obj = m.body(obj).id
        self.obj_geoms = [g for g in range(m.ngeom) if m.geom_bodyid[g] == self.obj]
        self.base = (m.body_mass.copy(), m.body_inertia.copy(), m.geom_friction.copy(),
                     m.geom_priority.copy())
        self.ctrl = controls(self.tr["actions"], float(self.tr["fps"]), m.opt.timestep, None)
        g = lambda n: m.geom(n).id  # noqa: E731
        self.peg, self.pin, self.table = g("red_peg"), g("pin"), g("table")
        self.sock = {g(n) for n in SOCKET} | {self.pin}
        self.fingers = {side: {gg for gg in range(m.ngeom)
                               if m.body(m.geom_bodyid[gg]).name.startswith(f"vx300s_{side}/")
                               and "finger" in m.body(m.geom_bodyid[gg]).name}
                        for side in ("left", "right")}

    @staticmethod
    def _pair_model(obj):
        """The object's contacts as explicit pairs carrying MuJoCo's own mixing of the two geoms'
        parameters (condim, friction: max; solref, solimp: solmix-weighted mean; margin, gap: max),
        written here from MuJoCo's documented rules, so that the friction parameter can set the
        sliding friction alone and leave solref/solimp as the unedited model mixes them (--pairs)."""
        o = mujoco.MjModel.from_xml_path(XML)
        spec = mujoco.MjSpec.from_file(XML)
        for k, g in enumerate(spec.geoms):
            if not g.name:
                g.name = f"probe37_g{k}"
        names = [spec.geoms[i].name for i in range(len(spec.geoms))]
        ob = o.body(obj).id
        mine = [g for g in range(o.ngeom) if o.geom_bodyid[g] == ob]
        for g in mine:
            for x in range(o.ngeom):
                if o.geom_bodyid[x] == ob:
                    continue
                if not ((o.geom_contype[g] & o.geom_conaffinity[x]) or (o.geom_contype[x] & o.geom_conaffinity[g])):
                    continue
                if o.body_weldid[o.geom_bodyid[x]] == o.body_weldid[ob]:
                    continue
                w1, w2 = o.geom_solmix[g], o.geom_solmix[x]
                a = 0.5 if w1 + w2 < mujoco.mjMINVAL else w1 / (w1 + w2)
                fr = np.maximum(o.geom_friction[g], o.geom_friction[x])
                spec.add_pair(name=f"probe37_pair_{g}_{x}", geomname1=names[g], geomname2=names[x],
                              condim=int(max(o.geom_condim[g], o.geom_condim[x])),
                              friction=[fr[0], fr[0], fr[1], fr[2], fr[2]],
                              solref=list(a * o.geom_solref[g] + (1 - a) * o.geom_solref[x]),
                              solimp=list(a * o.geom_solimp[g] + (1 - a) * o.geom_solimp[x]),
                              margin=max(o.geom_margin[g], o.geom_margin[x]), gap=max(o.geom_gap[g], o.geom_gap[x]))
        return spec.compile()

    def apply(self, mass, friction):
        m = self.m
        m.body_mass[:], m.body_inertia[:], m.geom_friction[:], m.geom_priority[:] = (
            x.copy() for x in self.base)
        if mass is not None:
            m.body_inertia[self.obj] = self.base[1][self.obj] * mass / self.base[0][self.obj]
            m.body_mass[self.obj] = mass
        if friction is not None and self.pairs:
            if not hasattr(self, "base_pf"):
                self.base_pf = m.pair_friction.copy()
            m.pair_friction[:] = self.base_pf
            m.pair_friction[:, 0:2] = friction
        elif friction is not None:
            top = int(self.base[3].max())
            for gg in self.obj_geoms:
                m.geom_priority[gg] = top + 1
                m.geom_friction[gg, 0] = friction

    def run(self, mass=None, friction=None):
        m = self.m
        self.apply(mass, friction)
        d = mujoco.MjData(m)
        mujoco.mj_setConst(m, d)
        d.qpos[:] = self.tr["qpos0"]
        d.ctrl[:] = self.ctrl[0]
        mujoco.mj_forward(m, d)
        T = len(self.ctrl)
        win = int(round(0.05 / m.opt.timestep))
        flags = np.zeros((T, 6), bool)  # pin, peg-table, socket-table, peg-socketwall, L-socket, R-peg
        zpeg, zsock = np.zeros(T), np.zeros(T)
        for t in range(T):
            d.ctrl[:] = self.ctrl[t]
            mujoco.mj_step(m, d)
            if not np.isfinite(d.qpos).all():
                return {"diverged": t}
            for c in d.contact[:d.ncon]:
                pr = {int(c.geom1), int(c.geom2)}
                if pr == {self.peg, self.pin}:
                    flags[t, 0] = True
                if pr == {self.peg, self.table}:
                    flags[t, 1] = True
                if self.table in pr and pr & (self.sock - {self.pin} | {self.pin}) and self.peg not in pr:
                    flags[t, 2] = True
                if self.peg in pr and pr & (self.sock - {self.pin}):
                    flags[t, 3] = True
                if pr & self.fingers["left"] and pr & self.sock:
                    flags[t, 4] = True
                if pr & self.fingers["right"] and self.peg in pr:
                    flags[t, 5] = True
            zpeg[t] = d.xpos[m.body("peg").id][2]
            zsock[t] = d.xpos[m.body("socket").id][2]
        # ACT's reward per step (order-insensitive pairs)
        touch = flags[:, 4] & flags[:, 5]
        off = ~flags[:, 1] & ~flags[:, 2]
        r = np.where(touch, 1, 0)
        r = np.where(touch & off, 2, r)
        r = np.where(flags[:, 3] & off, 3, r)
        r = np.where(flags[:, 0], 4, r)
        end = flags[-win:]
        success = bool(end[:, 0].mean() >= 0.5 and not end[:, 1].any() and not end[:, 2].any())
        pl = d.xpos[m.body("peg").id] - d.xpos[m.body("socket").id]
        return {"success": success, "reward_end": int(r[-1]), "reward_max": int(r.max()),
                "pin_end_frac": float(end[:, 0].mean()), "peg_table_end": bool(end[:, 1].any()),
                "socket_table_end": bool(end[:, 2].any()),
                "left_holds_end": bool(end[:, 4].mean() >= 0.5), "right_holds_end": bool(end[:, 5].mean() >= 0.5),
                "peg_z_end": float(zpeg[-1]), "socket_z_end": float(zsock[-1]),
                "peg_minus_socket_end": [round(float(x), 4) for x in pl],
                "first_pin_step": int(np.argmax(flags[:, 0])) if flags[:, 0].any() else None}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("traj")
    ap.add_argument("--object", required=True)
    ap.add_argument("--samples")
    ap.add_argument("--values", nargs="*", default=[])
    ap.add_argument("--cone")
    ap.add_argument("--impratio", type=float)
    ap.add_argument("--out")
    ap.add_argument("--pairs", action="store_true", help="friction through explicit pairs with MuJoCo's mixing "
                    "(default: the object's geoms' priority raised, which also gives its contacts the object's solref/solimp)")
    a = ap.parse_args()
    tr = Truth(a.traj, a.object, a.cone, a.impratio, a.pairs)
    rows = []
    if a.samples:
        v = json.load(open(a.samples))
        names = v["parameters"] if isinstance(v["parameters"], list) else list(v["parameters"])
        for i, s in enumerate(v["per_sample"]):
            vals = s["values"] if isinstance(s["values"], dict) else dict(zip(names, s["values"]))
            res = tr.run(vals.get("mass"), vals.get("friction"))
            res.update(i=i, values=vals, cm_outcome=s.get("outcome"), cm_real_ok=not s.get("real_failed"),
                       cm_pred_ok=not s.get("predicted_failed"))
            rows.append(res)
            print(i, {k: res[k] for k in ("values", "success", "reward_end", "cm_outcome", "cm_pred_ok")},
                  flush=True)
    else:
        for spec in a.values or ["nominal"]:
            mass, fr = (None, None) if spec == "nominal" else map(float, spec.split(","))
            res = tr.run(mass, fr)
            res["values"] = spec
            rows.append(res)
            print(json.dumps(res), flush=True)
    if a.out:
        json.dump(rows, open(a.out, "w"), indent=1)


if __name__ == "__main__":
    main()
