"""Prefix study: can the object-only part of a run before the first approach be simulated alone?

The audit runs parameter samples (the object's mass and friction) in full rollouts from step 0.
Before the robot first comes near the object, MuJoCo's constraint islands keep the robot's
motion apart from the object's. The idea measured here: run only the non-robot part of the
scene (a *reduced model*) for each sample up to a step P before the first approach, compose
the full state at P (robot part from the nominal recording, object part from the reduced run),
and run the full model only from P. Two reduced models are tried:

* ``plain``: the scene with the robot's kinematic trees deleted (and the actuators, sensors,
  keys, and the tendons, equalities, pairs, excludes, cameras and lights that reference the
  robot's trees);
* ``padded``: the same, but each robot tree is replaced by as many unconstrained, collision-free
  dummy slide joints (no gravity along them, the robot dofs' damping) as it had dofs, so that
  every remaining dof keeps its address and nv is unchanged, and ``stat.meaninertia`` is the
  full model's. This keeps MuJoCo's dense kernels summing in the same order and Euler's
  implicit-damping path the same as in the full model.

Per scenario it prints:

* which trees were deleted (the root bodies of the joints the actuators drive; tendon, site
  and body transmissions walked to their bodies), what had to go with them, whether the naive
  deletion (robot bodies, actuators, sensors, keys) compiles, and whether a parameter of the
  box writes into a robot element (then the idea does not apply);
* c. P: the nominal's first step (every 10th step checked) where a robot collision geom comes
  within D of a collision geom of a non-robot tree with dofs (``mj_geomDistance``), for
  D = 5 mm and 20 mm; P(D) is the checked step before it. The samples' largest displacement of
  the object from the nominal's over [0, P] (position, angle, a bound on any surface point),
  the steps before P where the nominal robot has active constraints, and the first step where
  a sample's robot leaves the nominal robot in its own full run (the real limit of the idea);
* a. whether the composed state at P equals the sample's own full run's state at P bit for bit
  (whole ``mjSTATE_INTEGRATION`` vectors, ``np.array_equal``), for 16 Sobol samples, the 4
  corners of the box and the nominal (21), at P(20 mm) and P(5 mm), per reduced model; where
  it fails, the same check with the solver's warmstart disabled in both models (a diagnosis,
  not the audit's physics);
* b. whether the full model run from the composed state at P(20 mm) to the end ends in the
  sample's full run's final state bit for bit (the 21 samples);
* d. timings, median of 3 interleaved runs, one MuJoCo thread (``mujoco.batch.Batch(...,
  nthread=1)``), 17 samples (16 Sobol + nominal): full model 0..P, each reduced model 0..P,
  full model 0..T and P..T; the saving (full 0..P - reduced 0..P - compose) / full 0..T.

Runs the bundled ALOHA demo (seeds 0, 3, 7; timings on seed 0) and the bundled Panda
pick-and-place (seed 0); with ``--real`` also robosuite's Panda + Robotiq 85 with an elliptic
cone (impratio 10) from the real-models cache (``benchmarks/real_models.py`` makes it; its
scenario and nominal trajectory are used as saved). About 3 minutes on 2 cores.

Usage::

    PYTHONPATH=. python benchmarks/prefix_study.py [--real] [--only NAME]
"""

from __future__ import annotations

import argparse
import copy
import os
import statistics
import sys
import time
import warnings
from pathlib import Path

import mujoco
import mujoco.batch
import numpy as np

import critmoment as cm
import critmoment.demos
import critmoment.panda_demo
from critmoment import recording as rec_mod
from critmoment.sparse import sweep_samples
from critmoment.trajectory import load_trajectory
from critmoment.twin import STATE_SPEC

REAL = Path(os.environ.get("CRITMOMENT_REAL_MODELS",
                           Path.home() / ".cache" / "critmoment-real-models"))
OBJ = mujoco.mjtObj
TIME_REC = (int(mujoco.mjtState.mjSTATE_TIME),)
CTRL = int(mujoco.mjtState.mjSTATE_CTRL)
WARMSTART = int(mujoco.mjtDisableBit.mjDSBL_WARMSTART)
EVERY = 10  # approach check stride [steps]
PAD = "critmoment_pad:"  # name prefix of the padded model's dummies
VARIANTS = ("plain", "padded")


# -- the robot's trees and the reduced models ------------------------------------------------
def robot_roots(m: mujoco.MjModel) -> list[int]:
    """Root bodies (children of the world) of everything the actuators drive."""
    bodies: set[int] = set()
    for a in range(m.nu):
        trn = mujoco.mjtTrn(int(m.actuator_trntype[a]))
        i0, i1 = (int(x) for x in m.actuator_trnid[a])
        if trn in (mujoco.mjtTrn.mjTRN_JOINT, mujoco.mjtTrn.mjTRN_JOINTINPARENT):
            bodies.add(int(m.jnt_bodyid[i0]))
        elif trn == mujoco.mjtTrn.mjTRN_TENDON:
            bodies |= _tendon_bodies(m, i0)
        elif trn == mujoco.mjtTrn.mjTRN_SITE:
            bodies.add(int(m.site_bodyid[i0]))  # moves the joints above its site: its tree
        elif trn == mujoco.mjtTrn.mjTRN_SLIDERCRANK:
            bodies |= {int(m.site_bodyid[i0]), int(m.site_bodyid[i1])}
        elif trn == mujoco.mjtTrn.mjTRN_BODY:
            bodies.add(i0)
        else:
            raise ValueError(f"actuator {a}: unhandled transmission {trn}")
    return sorted({int(m.body_rootid[b]) for b in bodies if b > 0})


def _tendon_bodies(m: mujoco.MjModel, t: int) -> set[int]:
    out = set()
    for w in range(m.tendon_adr[t], m.tendon_adr[t] + m.tendon_num[t]):
        kind, obj = mujoco.mjtWrap(int(m.wrap_type[w])), int(m.wrap_objid[w])
        if kind == mujoco.mjtWrap.mjWRAP_JOINT:
            out.add(int(m.jnt_bodyid[obj]))
        elif kind == mujoco.mjtWrap.mjWRAP_SITE:
            out.add(int(m.site_bodyid[obj]))
        elif kind in (mujoco.mjtWrap.mjWRAP_SPHERE, mujoco.mjtWrap.mjWRAP_CYLINDER):
            out.add(int(m.geom_bodyid[obj]))
    return out


def _eq_bodies(m: mujoco.MjModel, e: int) -> set[int]:
    out = set()
    kind = OBJ(int(m.eq_objtype[e]))
    for obj in (int(m.eq_obj1id[e]), int(m.eq_obj2id[e])):
        if obj < 0:
            continue
        if kind in (OBJ.mjOBJ_BODY, OBJ.mjOBJ_XBODY):
            out.add(obj)
        elif kind == OBJ.mjOBJ_SITE:
            out.add(int(m.site_bodyid[obj]))
        elif kind == OBJ.mjOBJ_JOINT:
            out.add(int(m.jnt_bodyid[obj]))
        elif kind == OBJ.mjOBJ_GEOM:
            out.add(int(m.geom_bodyid[obj]))
        elif kind == OBJ.mjOBJ_TENDON:
            out |= _tendon_bodies(m, obj)
        else:
            out.add(-1)  # unknown kind: count it as the robot's
    return out


def _referencing(m: mujoco.MjModel, robot: np.ndarray) -> dict[str, list[int]]:
    """Ids of the elements outside the robot's bodies that reference them."""
    rb = lambda bodies: any(b < 0 or robot[b] for b in bodies)  # noqa: E731
    return {
        "tendons": [t for t in range(m.ntendon) if rb(_tendon_bodies(m, t))],
        "equalities": [e for e in range(m.neq) if rb(_eq_bodies(m, e))],
        "pairs": [p for p in range(m.npair) if rb(
            {int(m.geom_bodyid[m.pair_geom1[p]]), int(m.geom_bodyid[m.pair_geom2[p]])})],
        "excludes": [x for x in range(m.nexclude)
                     if rb({int(m.exclude_signature[x]) >> 16,
                            int(m.exclude_signature[x]) & 0xFFFF})],
        # cameras and lights on robot bodies go with them; these target a robot body
        "cameras": [c for c in range(m.ncam) if not robot[m.cam_bodyid[c]]
                    and m.cam_targetbodyid[c] > 0 and robot[m.cam_targetbodyid[c]]],
        "lights": [c for c in range(m.nlight) if not robot[m.light_bodyid[c]]
                   and m.light_targetbodyid[c] > 0 and robot[m.light_targetbodyid[c]]],
    }


_KINDS = {"tendons": ("ntendon", OBJ.mjOBJ_TENDON), "equalities": ("neq", OBJ.mjOBJ_EQUALITY),
          "pairs": ("npair", OBJ.mjOBJ_PAIR), "excludes": ("nexclude", OBJ.mjOBJ_EXCLUDE),
          "cameras": ("ncam", OBJ.mjOBJ_CAMERA), "lights": ("nlight", OBJ.mjOBJ_LIGHT)}


def _delete_all(spec, kinds=("actuators", "sensors", "keys")) -> None:
    for kind in kinds:
        for x in list(getattr(spec, kind)):
            spec.delete(x)


def _naive_compiles(twin: cm.Twin, roots: list[int]) -> str:
    """Whether deleting only the robot's root bodies, the actuators, sensors and keys compiles,
    and what deleting the bodies removed by itself."""
    m = twin.model
    spec = twin.scenario.load_spec()
    before = {k: len(list(getattr(spec, k))) for k in _KINDS}
    for r in roots:
        spec.delete(spec.body(m.body(r).name))
    auto = {k: before[k] - len(list(getattr(spec, k))) for k in _KINDS}
    auto = {k: v for k, v in auto.items() if v}
    _delete_all(spec)
    try:
        spec.compile()
        text = "yes"
    except Exception as exc:  # noqa: BLE001
        text = f"no: {str(exc).strip().splitlines()[0]}"
    return text + (f" (deleting the bodies removed by itself {auto})" if auto else "")


def reduced_model(twin: cm.Twin, roots: list[int], variant: str) -> tuple[mujoco.MjModel, dict]:
    """The reduced model of ``variant`` (see the module docstring) and what was deleted."""
    m = twin.model
    robot = np.isin(m.body_rootid, roots)
    spec = twin.scenario.load_spec()
    info: dict = {"also_deleted": {}}
    for kind, ids in _referencing(m, robot).items():
        if not ids:
            continue
        count, objtype = getattr(m, _KINDS[kind][0]), _KINDS[kind][1]
        items = list(getattr(spec, kind))
        assert len(items) == count, (kind, len(items), count)
        names = [mujoco.mj_id2name(m, objtype, i) or "" for i in range(count)]
        by_name = {x.name: x for x in items if x.name}
        for i in ids:  # by name where named, else by position (the spec's order is the model's)
            spec.delete(by_name.get(names[i], items[i]))
        info["also_deleted"][kind] = [names[i] or f"#{i}" for i in ids]
        if kind == "equalities":
            coupling = [names[e] or f"#{e}" for e in ids
                        if any(b > 0 and not robot[b] for b in _eq_bodies(m, e))]
            if coupling:
                info["equalities coupling robot and rest (idea does not apply)"] = coupling
    if variant == "plain":
        for r in roots:
            spec.delete(spec.body(m.body(r).name))
    else:
        g = np.asarray(m.opt.gravity, dtype=float)
        axis = np.cross(g, [1.0, 0.0, 0.0]) if np.linalg.norm(np.cross(g, [1.0, 0, 0])) > 0 \
            else np.cross(g, [0.0, 1.0, 0.0])
        axis = axis / np.linalg.norm(axis) if np.linalg.norm(axis) > 0 else np.array([1.0, 0, 0])
        for r in roots:
            body = spec.body(m.body(r).name)
            for child in [c for c in body.bodies if c.parent.name == body.name]:
                spec.delete(child)
            for kind in ("geoms", "joints", "sites", "cameras", "lights"):
                for x in list(getattr(body, kind)):
                    spec.delete(x)
            body.name = f"{PAD}{body.name}"
            dofs = [v for v in range(m.nv) if m.body_rootid[m.dof_bodyid[v]] == r]
            for i, v in enumerate(dofs):
                c = body.add_body(name=f"{PAD}{r}:{i}")
                c.explicitinertial = True
                c.mass = 1.0
                c.inertia = [1.0, 1.0, 1.0]
                j = c.add_joint(name=f"{PAD}{r}:{i}", type=mujoco.mjtJoint.mjJNT_SLIDE, axis=axis)
                j.limited = mujoco.mjtLimited.mjLIMITED_FALSE
                j.damping = [float(m.dof_damping[v]), 0.0, 0.0]
                j.stiffness = [0.0, 0.0, 0.0]
                j.armature = float(m.dof_armature[v])
                j.frictionloss = 0.0
    _delete_all(spec)
    for kind in ("flexes", "skins"):
        if len(list(getattr(spec, kind))):
            info[f"{kind} present"] = "not handled"
    rm = spec.compile()
    if variant == "padded":
        rm.stat.meaninertia = m.stat.meaninertia  # the solver's tolerance scale
        assert rm.nv == m.nv
    info["sizes"] = f"nbody {rm.nbody}, nq {rm.nq}, nv {rm.nv}, ngeom {rm.ngeom}"
    return rm, info


class Maps:
    """The full model's non-robot elements with their ids in a reduced model."""

    def __init__(self, m: mujoco.MjModel, rm: mujoco.MjModel, roots: list[int]):
        robot = np.isin(m.body_rootid, roots)
        self.robot_body = robot

        def ours(objtype, n):  # reduced-model ids of the scene's own elements, in order
            return np.array([i for i in range(n)
                             if not (mujoco.mj_id2name(rm, objtype, i) or "").startswith(PAD)],
                            dtype=int)

        self.body, self.body_r = np.flatnonzero(~robot), ours(OBJ.mjOBJ_BODY, rm.nbody)
        self.geom, self.geom_r = np.flatnonzero(~robot[m.geom_bodyid]), ours(OBJ.mjOBJ_GEOM,
                                                                              rm.ngeom)
        self.jnt, jnt_r = np.flatnonzero(~robot[m.jnt_bodyid]), ours(OBJ.mjOBJ_JOINT, rm.njnt)
        for full, red, objtype in ((self.body, self.body_r, OBJ.mjOBJ_BODY),
                                   (self.geom, self.geom_r, OBJ.mjOBJ_GEOM),
                                   (self.jnt, jnt_r, OBJ.mjOBJ_JOINT)):
            assert len(full) == len(red), (objtype, len(full), len(red))
            for f, r in zip(full, red, strict=True):
                assert mujoco.mj_id2name(m, objtype, f) == mujoco.mj_id2name(rm, objtype, r)
        qf, qr, vf, vr = [], [], [], []
        for f, r in zip(self.jnt, jnt_r, strict=True):
            nq = {0: 7, 1: 4}.get(int(m.jnt_type[f]), 1)
            nv = {0: 6, 1: 3}.get(int(m.jnt_type[f]), 1)
            qf += range(m.jnt_qposadr[f], m.jnt_qposadr[f] + nq)
            qr += range(rm.jnt_qposadr[r], rm.jnt_qposadr[r] + nq)
            vf += range(m.jnt_dofadr[f], m.jnt_dofadr[f] + nv)
            vr += range(rm.jnt_dofadr[r], rm.jnt_dofadr[r] + nv)
        self.qpos, self.qpos_r = np.array(qf, int), np.array(qr, int)
        self.dof, self.dof_r = np.array(vf, int), np.array(vr, int)


def reduced_state(m, rm, maps: Maps, full_state: np.ndarray) -> np.ndarray:
    """The reduced model's integration state holding the non-robot part of ``full_state``
    (dummies at rest at their qpos0)."""
    d, rd = mujoco.MjData(m), mujoco.MjData(rm)
    mujoco.mj_setState(m, d, full_state, STATE_SPEC)
    rd.time = d.time
    rd.qpos[maps.qpos_r] = d.qpos[maps.qpos]
    rd.qvel[maps.dof_r] = d.qvel[maps.dof]
    rd.qacc_warmstart[maps.dof_r] = d.qacc_warmstart[maps.dof]
    rd.qfrc_applied[maps.dof_r] = d.qfrc_applied[maps.dof]
    rd.xfrc_applied[maps.body_r] = d.xfrc_applied[maps.body]
    for b_f, b_r in zip(maps.body, maps.body_r, strict=True):
        if m.body_mocapid[b_f] >= 0:
            rd.mocap_pos[rm.body_mocapid[b_r]] = d.mocap_pos[m.body_mocapid[b_f]]
            rd.mocap_quat[rm.body_mocapid[b_r]] = d.mocap_quat[m.body_mocapid[b_f]]
    out = np.empty(mujoco.mj_stateSize(rm, STATE_SPEC))
    mujoco.mj_getState(rm, rd, out, STATE_SPEC)
    return out


def compose(m, rm, maps: Maps, nominal_state: np.ndarray, red_states: np.ndarray) -> np.ndarray:
    """Full states: the nominal's, with the non-robot dofs from each reduced state, (n, ...)."""
    d, rd = mujoco.MjData(m), mujoco.MjData(rm)
    out = np.empty((len(red_states), mujoco.mj_stateSize(m, STATE_SPEC)))
    for i, rs in enumerate(red_states):
        mujoco.mj_setState(m, d, nominal_state, STATE_SPEC)
        mujoco.mj_setState(rm, rd, rs, STATE_SPEC)
        d.qpos[maps.qpos] = rd.qpos[maps.qpos_r]
        d.qvel[maps.dof] = rd.qvel[maps.dof_r]
        d.qacc_warmstart[maps.dof] = rd.qacc_warmstart[maps.dof_r]
        mujoco.mj_getState(m, d, out[i], STATE_SPEC)
    return out


def write_reduced(twin, full_batch, red_batch, maps: Maps) -> None:
    """The full batch's per-simulation parameter fields, onto the reduced batch's elements."""
    for f in twin.parameter_fields():
        vals = full_batch.expanded(f)
        if vals is None:
            continue
        if f.startswith("body_"):
            red_batch.expand(f)[:, maps.body_r] = vals[:, maps.body]
        elif f.startswith("geom_"):
            red_batch.expand(f)[:, maps.geom_r] = vals[:, maps.geom]
        else:
            raise ValueError(f"parameter field {f} has no reduced counterpart")
    red_batch.set_const()


def robot_params(twin, robot_body: np.ndarray) -> list[str]:
    """Parameters of the box that write into a robot element."""
    m, out = twin.model, []
    for p in twin.scenario.box.parameters:
        idx, f = p.resolve(m), p.fields[0]
        body = (idx if f.startswith("body_") else int(m.geom_bodyid[idx])
                if f.startswith("geom_") else None)
        if body is None or robot_body[body]:
            out.append(f"{p.name} ({f})")
    return out


# -- approach ----------------------------------------------------------------------------------
def approach(m, robot_body: np.ndarray, states: np.ndarray, distances=(0.005, 0.02)) -> dict:
    """First checked step where a robot collision geom is within D of a collision geom of a
    non-robot tree with dofs (a static table cannot join the robot's island); P(D) = the
    checked step before it."""
    robot_g = np.flatnonzero(robot_body[m.geom_bodyid])
    tree_dofs = np.zeros(m.nbody, int)
    for b in range(m.nbody):
        tree_dofs[m.body_rootid[b]] += m.body_dofnum[b]
    moving = np.flatnonzero(~robot_body[m.geom_bodyid]
                            & (tree_dofs[m.body_rootid[m.geom_bodyid]] > 0))
    explicit = {frozenset((int(m.pair_geom1[p]), int(m.pair_geom2[p]))) for p in range(m.npair)}
    pairs = [(int(a), int(b)) for a in robot_g for b in moving
             if (m.geom_contype[a] & m.geom_conaffinity[b])
             or (m.geom_contype[b] & m.geom_conaffinity[a]) or frozenset((a, b)) in explicit]
    d = mujoco.MjData(m)
    first = {D: None for D in distances}
    for k in range(0, len(states), EVERY):
        mujoco.mj_setState(m, d, states[k], STATE_SPEC)
        mujoco.mj_kinematics(m, d)
        dist = min((mujoco.mj_geomDistance(m, d, a, b, 2 * max(distances), None)
                    for a, b in pairs), default=np.inf)
        for D in distances:
            if first[D] is None and dist < D:
                first[D] = k
        if all(v is not None for v in first.values()):
            break
    margin = float(m.geom_margin[robot_g].max(initial=0) + m.geom_margin[moving].max(initial=0))
    return {"first": first, "pairs": len(pairs), "margin": margin,
            "P": {D: (None if v is None else max(v - EVERY, 0)) for D, v in first.items()}}


def displacement(m, maps: Maps, rm, nominal_states, red_qpos, P) -> tuple[float, float, float]:
    """Largest |dp| [m], angle [rad] and surface-point bound [m] of the non-robot free bodies
    from the nominal's over steps 1..P (other joints count |dq| * (rbound + 1 m))."""
    off = mujoco.mj_stateSize(m, mujoco.mjtState.mjSTATE_TIME)
    nom = nominal_states[1:P + 1, off:off + m.nq]
    dp_max = ang_max = bound = 0.0
    for f in maps.jnt:
        a = m.jnt_qposadr[f]
        ar = maps.qpos_r[list(maps.qpos).index(a)]
        rb = float(m.geom_rbound[m.geom_bodyid == m.jnt_bodyid[f]].max(initial=0))
        red = red_qpos[:, :P]
        if int(m.jnt_type[f]) == int(mujoco.mjtJoint.mjJNT_FREE):
            dp = np.linalg.norm(red[..., ar:ar + 3] - nom[None, :, a:a + 3], axis=-1)
            dot = np.abs(np.sum(red[..., ar + 3:ar + 7] * nom[None, :, a + 3:a + 7], axis=-1))
            ang = 2 * np.arccos(np.clip(dot, 0, 1))
            dp_max, ang_max = max(dp_max, dp.max()), max(ang_max, ang.max())
            bound = max(bound, (dp + ang * rb).max())
        else:
            bound = max(bound, np.abs(red[..., ar] - nom[None, :, a]).max() * (rb + 1.0))
    return dp_max, ang_max, bound


def robot_constrained(m, robot_body: np.ndarray, states: np.ndarray, P: int) -> tuple[int, int]:
    """Steps in [0, P) where the nominal robot has active constraints (self-contacts, joint
    limits, ...), and the first of them (-1: none)."""
    d = mujoco.MjData(m)
    robot_dofs = np.flatnonzero(robot_body[m.dof_bodyid])
    count, first = 0, -1
    for k in range(P):
        mujoco.mj_setState(m, d, states[k], STATE_SPEC)
        mujoco.mj_forward(m, d)
        if d.nefc and (d.dof_island[robot_dofs] >= 0).any():
            count += 1
            first = k if first < 0 else first
    return count, first


# -- runs --------------------------------------------------------------------------------------
def run_full(batch, state0, controls, k0, k1, record=TIME_REC):
    n = batch.nsim
    batch.state[:] = state0
    batch.warning[...] = 0
    ctrl = np.ascontiguousarray(np.broadcast_to(controls[k0:k1], (n, k1 - k0, controls.shape[1])))
    out = batch.rollout(k1 - k0, control=ctrl, control_spec=CTRL, record=record)
    out["diverged"] = batch.warning[:, :, 1].any(axis=1).copy()
    return out


def run_reduced(batch, state0, nstep, record=TIME_REC):
    batch.state[:] = state0
    batch.warning[...] = 0
    out = batch.rollout(nstep, control=None, record=record)
    out["diverged"] = batch.warning[:, :, 1].any(axis=1).copy()
    return out


def check_at(twin, m, rm, maps, samples, state0, controls, P, nominal_at_P=None) -> int:
    """Samples whose composed state at P is bit-exact, with the models given (used for the
    warmstart diagnosis: the nominal is rerun on ``m`` when ``nominal_at_P`` is None)."""
    box = twin.scenario.box
    if nominal_at_P is None:
        nb = mujoco.batch.Batch(m, 1, nthread=0)
        twin.write_parameters(nb, box.nominal[None])
        run_full(nb, state0, controls, 0, P)
        nominal_at_P = nb.state[0].copy()
    fb = mujoco.batch.Batch(m, len(samples), nthread=0)
    twin.write_parameters(fb, samples)
    run_full(fb, state0, controls, 0, P)
    rb = mujoco.batch.Batch(rm, len(samples), nthread=0)
    write_reduced(twin, fb, rb, maps)
    run_reduced(rb, reduced_state(m, rm, maps, state0), P)
    comp = compose(m, rm, maps, nominal_at_P, rb.state)
    return int(sum(np.array_equal(comp[i], fb.state[i]) for i in range(len(samples))))


def study(label: str, twin: cm.Twin, traj, *, do_timing: bool = True) -> dict:
    t_start = time.perf_counter()
    m = twin.model
    print(f"\n=== {label}", flush=True)
    rec = rec_mod.rollout(traj, twin=twin)
    controls = rec_mod.prepare_controls(twin, traj)
    state0 = rec_mod.initial_state(twin, traj)
    assert np.array_equal(state0, rec.states[0])
    T = len(controls)
    roots = robot_roots(m)
    robot_body = np.isin(m.body_rootid, roots)
    models, maps, info = {}, {}, {}
    for v in VARIANTS:
        t0 = time.perf_counter()
        models[v], info[v] = reduced_model(twin, roots, v)
        info[v]["built"] = time.perf_counter() - t0
        maps[v] = Maps(m, models[v], roots)
    print(f"integrator {mujoco.mjtIntegrator(m.opt.integrator).name[6:]}, cone "
          f"{mujoco.mjtCone(m.opt.cone).name[7:]}, solver {mujoco.mjtSolver(m.opt.solver).name[6:]}"
          f"; deleted trees: {[m.body(r).name for r in roots]}; naive deletion compiles: "
          f"{_naive_compiles(twin, roots)}; also deleted: "
          f"{info['plain']['also_deleted'] or 'nothing'}"
          + "".join(f"; {k}: {v}" for k, v in info["plain"].items()
                    if k not in ("also_deleted", "sizes", "built")))
    print(f"full: nbody {m.nbody}, nq {m.nq}, nv {m.nv}, ngeom {m.ngeom}; "
          + "; ".join(f"{v}: {info[v]['sizes']} (built in {info[v]['built'] * 1e3:.0f} ms)"
                      for v in VARIANTS) + f"; T = {T} steps")
    bad = robot_params(twin, robot_body)
    if bad:
        print(f"parameters writing robot elements: {bad}: the idea does not apply")
        return {"label": label}

    ap = approach(m, robot_body, rec.states)
    P5, P20 = ap["P"][0.005], ap["P"][0.02]
    print(f"c. approach ({ap['pairs']} robot/non-robot collision geom pairs, summed margins "
          f"{ap['margin'] * 1e3:.1f} mm): first checked step within 20 mm: {ap['first'][0.02]}, "
          f"within 5 mm: {ap['first'][0.005]} -> P(20 mm) = {P20}, P(5 mm) = {P5}")
    if not P20 or not P5:
        print("no usable P")
        return {"label": label}
    Pmax = max(P5, P20)
    nrc, frc = robot_constrained(m, robot_body, rec.states, Pmax)
    print(f"   nominal robot has active constraints at {nrc} of the {Pmax} steps before P(5 mm)"
          + (f" (first at step {frc})" if nrc else ""))

    box = twin.scenario.box
    lows = np.array([p.low for p in box.parameters])
    highs = np.array([p.high for p in box.parameters])
    sobol = sweep_samples(box, n=16, seed=0)
    corners = np.array(np.meshgrid(*zip(lows, highs, strict=True), indexing="ij")
                       ).reshape(len(lows), -1).T
    samples = np.concatenate([sobol, corners, box.nominal[None]])
    n = len(samples)

    # each sample's full run from step 0 (every state recorded, a chunk of samples at a time)
    nst = rec.states.shape[1]
    full_at = {P: np.empty((n, nst)) for P in (P5, P20)}
    full_end = np.empty((n, nst))
    first_dev = np.full(n, -1)
    full_div = np.zeros(n, bool)
    full_obj = np.empty((n, Pmax, len(maps["plain"].qpos)))
    robot_q = np.setdiff1d(np.arange(m.nq), maps["plain"].qpos)
    off = mujoco.mj_stateSize(m, mujoco.mjtState.mjSTATE_TIME)
    nom_robot_q = rec.states[1:, off:off + m.nq][:, robot_q]
    for s in range(0, n, 7):
        rows = samples[s:s + 7]
        fb = mujoco.batch.Batch(m, len(rows), nthread=0)
        twin.write_parameters(fb, rows)
        out = run_full(fb, state0, controls, 0, T, record=(int(STATE_SPEC),))
        st = out[int(STATE_SPEC)]
        full_div[s:s + 7] = out["diverged"]
        for P in (P5, P20):
            full_at[P][s:s + 7] = st[:, P - 1]
        full_end[s:s + 7] = fb.state
        q = st[:, :, off:off + m.nq]
        full_obj[s:s + 7] = q[:, :Pmax][:, :, maps["plain"].qpos]
        dev = (q[:, :, robot_q] != nom_robot_q[None]).any(axis=-1)
        first_dev[s:s + 7] = np.where(dev.any(axis=1), dev.argmax(axis=1) + 1, -1)
        del st, out, q
    left = first_dev[first_dev >= 0]
    print("   full runs: first step where a sample's robot leaves the nominal robot: "
          + (f"min {left.min()}, median {int(np.median(left))} ({left.size}/{n} samples leave it)"
             if left.size else "never"))
    if full_div.any():
        print(f"   diverged in the full run from step 0 (MuJoCo warning; the batch stops the run):"
              f" samples {np.flatnonzero(full_div).tolist()} = {samples[full_div].round(3).tolist()}")

    row = {"label": label, "P5": P5, "P20": P20, "T": T, "n": n, "a": {}, "b": {}}
    red = {}
    for v in VARIANTS:
        rm, mp = models[v], maps[v]
        fb = mujoco.batch.Batch(m, n, nthread=0)
        twin.write_parameters(fb, samples)
        rb = mujoco.batch.Batch(rm, n, nthread=0)
        write_reduced(twin, fb, rb, mp)
        rstate0 = reduced_state(m, rm, mp, state0)
        out = run_reduced(rb, rstate0, Pmax, record=(int(STATE_SPEC), "qpos"))
        states, qpos = out[int(STATE_SPEC)], out["qpos"]
        red[v] = (rstate0, states)
        same = [(qpos[i][:, mp.qpos_r] == full_obj[i]).all(axis=1) for i in range(n)]
        bad_first = [int(np.argmin(x)) + 1 for x in same if not x.all()]
        print(f"[{v}] reduced vs full object qpos over steps 1..{Pmax}: bit-identical in "
              f"{sum(x.all() for x in same)}/{n} samples"
              + (f" (first difference at step {min(bad_first)})" if bad_first else ""))
        if v == "plain":
            dp, ang, bound = displacement(m, mp, rm, rec.states, qpos, P20)
            dp5, ang5, bound5 = displacement(m, mp, rm, rec.states, qpos, P5)
            print(f"   object's largest displacement from the nominal object, {n} samples: over "
                  f"[0, P(20 mm)] {dp * 1e3:.3g} mm, {np.degrees(ang):.3g} deg, any surface "
                  f"point <= {bound * 1e3:.3g} mm; over [0, P(5 mm)] {dp5 * 1e3:.3g} mm, "
                  f"{np.degrees(ang5):.3g} deg, surface <= {bound5 * 1e3:.3g} mm")
        for P in (P20, P5):
            comp = compose(m, rm, mp, rec.states[P], states[:, P - 1])
            ok = np.array([np.array_equal(comp[i], full_at[P][i]) for i in range(n)])
            row["a"][(v, P)] = int(ok.sum())
            print(f"a. [{v}] composed state at P = {P} == the sample's full-run state (whole "
                  f"mjSTATE_INTEGRATION): {ok.sum()}/{n} bit-exact "
                  f"({'yes' if ok.all() else 'NO'}; 16 Sobol + 4 corners + nominal)"
                  + ("" if ok.all() else
                     f"; differing entries per sample {(comp != full_at[P]).sum(axis=1).tolist()}"))
        if row["a"][(v, P20)] < n:
            mw, rw = twin.copy_model(), copy.copy(rm)
            mw.opt.disableflags |= WARMSTART
            rw.opt.disableflags |= WARMSTART
            ok = check_at(twin, mw, rw, mp, samples, state0, controls, P20)
            row["a"][(v, "nows")] = ok
            print(f"   diagnosis [{v}]: with the solver's warmstart disabled in both models "
                  f"(mjDSBL_WARMSTART; not the audit's physics): {ok}/{n} bit-exact at P = {P20}")
        comp = compose(m, rm, mp, rec.states[P20], states[:, P20 - 1])
        fb = mujoco.batch.Batch(m, n, nthread=0)
        twin.write_parameters(fb, samples)
        post_div = run_full(fb, comp, controls, P20, T)["diverged"]
        ok = np.array([np.array_equal(fb.state[i], full_end[i]) for i in range(n)])
        row["b"][v] = int(ok.sum())
        print(f"b. [{v}] full model from the composed state at P = {P20} to T = {T}: final state "
              f"== the full run from 0: {ok.sum()}/{n} bit-exact ({'yes' if ok.all() else 'NO'})"
              + (f"; diverged: {np.flatnonzero(post_div).tolist()}" if post_div.any() else ""))

    if do_timing:
        row.update(timing(twin, m, models, maps, red, rec, controls, state0, sobol, P20, P5, T))
    print(f"   ({time.perf_counter() - t_start:.0f} s)", flush=True)
    return row


def timing(twin, m, models, maps, red, rec, controls, state0, sobol, P20, P5, T) -> dict:
    box = twin.scenario.box
    ts = np.concatenate([sobol, box.nominal[None]])  # 17 samples
    k = len(ts)
    fb = mujoco.batch.Batch(m, k, nthread=1)
    twin.write_parameters(fb, ts)
    rbs = {}
    for v in VARIANTS:
        rbs[v] = mujoco.batch.Batch(models[v], k, nthread=1)
        write_reduced(twin, fb, rbs[v], maps[v])
    ctrl_all = np.ascontiguousarray(np.broadcast_to(controls, (k, T, m.nu)))
    ctrl = {P: np.ascontiguousarray(ctrl_all[:, :P]) for P in (P20, P5)}
    ctrl_post = np.ascontiguousarray(ctrl_all[:, P20:])
    rstate0 = {v: red[v][0] for v in VARIANTS}
    at_p = {v: red[v][1][:k, P20 - 1] for v in VARIANTS}
    comp = compose(m, models["plain"], maps["plain"], rec.states[P20], at_p["plain"])

    def full(s0, c):
        fb.state[:] = s0
        fb.warning[...] = 0
        fb.rollout(c.shape[1], control=c, control_spec=CTRL, record=TIME_REC)

    def reduced(v, P):
        rbs[v].state[:] = rstate0[v]
        rbs[v].warning[...] = 0
        rbs[v].rollout(P, control=None, record=TIME_REC)

    jobs = {("full", P20): lambda: full(state0, ctrl[P20]),
            ("full", P5): lambda: full(state0, ctrl[P5]),
            ("full", T): lambda: full(state0, ctrl_all),
            ("post", P20): lambda: full(comp, ctrl_post),
            ("compose", P20): lambda: compose(m, models["plain"], maps["plain"],
                                              rec.states[P20], at_p["plain"])}
    for v in VARIANTS:
        for P in (P20, P5):
            jobs[(v, P)] = lambda v=v, P=P: reduced(v, P)
    times = {key: [] for key in jobs}
    for _ in range(3):  # interleaved: a slow spell of the machine hits every job alike
        for key, job in jobs.items():
            t1 = time.perf_counter()
            job()
            times[key].append(time.perf_counter() - t1)
    med = {key: statistics.median(v) for key, v in times.items()}
    t_all, t_comp = med[("full", T)], med[("compose", P20)]
    print(f"d. timings, {k} samples (16 Sobol + nominal), nthread=1, median of 3 interleaved: "
          f"full 0..T = {t_all:.3f} s ({', '.join(f'{x:.3f}' for x in times[('full', T)])}), "
          f"compose {t_comp * 1e3:.1f} ms")
    row = {}
    for P, D in ((P20, 20), (P5, 5)):
        parts = [f"P(D = {D} mm) = {P} (P/T = {P / T:.3f}): full 0..P {med[('full', P)]:.3f} s"]
        for v in VARIANTS:
            saved = (med[("full", P)] - med[(v, P)] - t_comp) / t_all
            row[(v, D)] = saved
            parts.append(f"{v} reduced 0..P {med[(v, P)]:.3f} s "
                         f"({med[(v, P)] / med[('full', P)]:.0%} of full 0..P), saving "
                         f"{saved:.3f}")
        print("   " + " | ".join(parts))
    check = 1 - (med[("plain", P20)] + t_comp + med[("post", P20)]) / t_all
    print(f"   saving = (full 0..P - reduced 0..P - compose) / full 0..T. Check at P(20 mm): "
          f"full P..T {med[('post', P20)]:.3f} s, 1 - (plain 0..P + compose + full P..T) / "
          f"full 0..T = {check:.3f} (a difference of noisy totals)")
    return {"saved": row}


def cases(real: bool):
    aloha = cm.Twin(cm.load_scenario())
    for seed in (0, 3, 7):
        yield (f"aloha_transfer_cube, scripted_transfer seed {seed}", aloha,
               lambda s=seed: critmoment.demos.scripted_transfer(s, twin=aloha), seed == 0)
    panda = cm.Twin(cm.load_scenario("panda_pick_place"))
    yield ("panda_pick_place, make_pick_place seed 0", panda,
           lambda: critmoment.panda_demo.make_pick_place(0, model=panda.model), True)
    if real:
        run = REAL / "runs" / "panda_robotiq85_elliptic10"
        if not (run / "scenario.toml").is_file():
            print(f"\n(--real: {run} not found: run benchmarks/real_models.py first)")
            return
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            twin = cm.Twin(cm.load_scenario(run / "scenario.toml"))
        yield ("real: robosuite panda_robotiq85, elliptic cone impratio 10 "
               "(runs/panda_robotiq85_elliptic10)", twin,
               lambda: load_trajectory(run / "nominal.npz"), True)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--real", action="store_true",
                        help="also robosuite's Panda + Robotiq 85 (elliptic) from the cache")
    parser.add_argument("--only", default=None, help="only cases whose label contains this")
    args = parser.parse_args(argv)
    print(f"MuJoCo {mujoco.__version__}")
    t0 = time.perf_counter()
    rows = []
    for label, twin, make, do_timing in cases(args.real):
        if args.only and args.only not in label:
            continue
        if twin.model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_ISLAND:
            print(f"\n=== {label}: islands disabled in this model (mjDSBL_ISLAND): skipped")
            continue
        rows.append(study(label, twin, make(), do_timing=do_timing))
    print("\n=== summary (bit-exact samples of 21; saving = fraction of the full runs' time)")
    for r in rows:
        if "P20" not in r:
            print(f"{r['label']}: does not apply")
            continue
        line = f"{r['label']}: P(20 mm) = {r['P20']}, P(5 mm) = {r['P5']} of T = {r['T']}"
        for v in VARIANTS:
            line += (f"; [{v}] a. {r['a'][(v, r['P20'])]} at P(20 mm), {r['a'][(v, r['P5'])]} "
                     f"at P(5 mm)" + (f" ({r['a'][(v, 'nows')]} without warmstart)"
                                      if (v, "nows") in r["a"] else "")
                     + f", b. {r['b'][v]}")
            if "saved" in r:
                line += (f", saving {r['saved'][(v, 20)]:.3f} at P(20 mm), "
                         f"{r['saved'][(v, 5)]:.3f} at P(5 mm)")
        print(line)
    print(f"total {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
