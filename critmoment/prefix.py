"""Shared prefixes: a sample's own run from a later step, to the bit.

Until the robot first comes near the object, nothing couples the two. MuJoCo solves each
constraint island on its own (``mjDSBL_ISLAND`` unset), so up to that step the robot moves
exactly as in the nominal run whatever the object's parameters, and the object rests (or
slides, or tips over) on its support exactly as it would in the scene without the robot.
A sample's own full run at such a step P is then the nominal run's robot with the object
of a run of the *reduced scene* (the scene with the robot's kinematic trees deleted: a few
degrees of freedom, a fraction of a full step's cost) under the sample's parameters. The
samples' own runs (the chained segments, the verification rollouts, the region check's
rollouts) start there instead of at step 0, and the readings of their first P steps are
composed the same way: the robot's sensors from the nominal run, the object's (its
position, velocity, acceleration, its contacts with its supports) from the reduced run,
its contacts with the grippers zero (nothing touches it yet).

Nothing here is assumed. :class:`SharedPrefix` checks, for each recording, that the reduced
scene's nominal run equals the recording's object part at every step of the prefix and
composes the recorded state at P to the bit, and that one sample far from the nominal (the
box's corner farthest from it) run in full to P equals its composed state to the bit; and,
for each call, that no sample's object came within :data:`PROXIMITY` of where the robot
passes (the nominal run's robot keeps that far from the object's geoms before P). Where any
check fails, or a parameter acts on the robot before P (a force limit the nominal force
reaches), or the model disables islands, the runs start at step 0 as before; ``reason``
says why.

Measured on the bundled ALOHA demo (seed 0, 256 samples; docs/benchmarks.md): P = 1433 of
4000 steps, and the audit's report is bit-identical with and without the shared prefix.
"""

from __future__ import annotations

import dataclasses
import threading
import types
import weakref

import mujoco
import mujoco.batch
import numpy as np

from critmoment.twin import STATE_SPEC, Twin, _sensor_name

__all__ = ["PROXIMITY", "PrefixStart", "SharedPrefix"]

#: how close [m] the nominal run's robot may come to a geom of the rest of the scene before
#: the shared prefix ends, and the largest a sample's object may stray from the nominal
#: object's place before it (so that no sample's robot touches what the nominal's does not)
PROXIMITY = 0.005

#: fewest steps worth sharing (below, the runs start at step 0)
MIN_STEPS = 50


def _offsets(model: mujoco.MjModel) -> dict[int, slice]:
    """Where each component of a ``STATE_SPEC`` row sits, by component bit."""
    out, at = {}, 0
    bit = 1
    while bit <= int(STATE_SPEC):
        if int(STATE_SPEC) & bit:
            size = mujoco.mj_stateSize(model, bit)
            out[bit] = slice(at, at + size)
            at += size
        bit <<= 1
    return out


_QPOS = int(mujoco.mjtState.mjSTATE_QPOS)
_QVEL = int(mujoco.mjtState.mjSTATE_QVEL)
_WARM = int(mujoco.mjtState.mjSTATE_WARMSTART)
_TIME = int(mujoco.mjtState.mjSTATE_TIME)
_QFRC = int(mujoco.mjtState.mjSTATE_QFRC_APPLIED)
_XFRC = int(mujoco.mjtState.mjSTATE_XFRC_APPLIED)


def _robot_trees(model: mujoco.MjModel) -> set[int]:
    """The root bodies of the kinematic trees the actuators move, with every tree an
    equality constraint or a tendon ties to them."""
    roots = set()
    for a in range(model.nu):
        trn, target = int(model.actuator_trntype[a]), int(model.actuator_trnid[a, 0])
        if trn in (mujoco.mjtTrn.mjTRN_JOINT, mujoco.mjtTrn.mjTRN_JOINTINPARENT):
            roots.add(int(model.body_rootid[model.jnt_bodyid[target]]))
        elif trn == mujoco.mjtTrn.mjTRN_SITE:
            roots.add(int(model.body_rootid[model.site_bodyid[target]]))
        elif trn == mujoco.mjtTrn.mjTRN_BODY:
            roots.add(int(model.body_rootid[target]))
        elif trn == mujoco.mjtTrn.mjTRN_TENDON:
            roots |= _tendon_trees(model, target)
        else:  # slider-crank and anything newer: its bodies are not known here
            return set()
    links = [_tendon_trees(model, t) for t in range(model.ntendon)]
    for e in range(model.neq):
        links.append({_root_of(model, int(model.eq_objtype[e]), int(i))
                      for i in (model.eq_obj1id[e], model.eq_obj2id[e]) if i >= 0})
    changed = True
    while changed:
        changed = False
        for tied in links:
            tied = tied - {0}
            if tied & roots and not tied <= roots:
                roots |= tied
                changed = True
    roots.discard(0)
    return roots


def _root_of(model: mujoco.MjModel, objtype: int, i: int) -> int:
    body = {int(mujoco.mjtObj.mjOBJ_BODY): lambda: i,
            int(mujoco.mjtObj.mjOBJ_XBODY): lambda: i,
            int(mujoco.mjtObj.mjOBJ_JOINT): lambda: int(model.jnt_bodyid[i]),
            int(mujoco.mjtObj.mjOBJ_GEOM): lambda: int(model.geom_bodyid[i]),
            int(mujoco.mjtObj.mjOBJ_SITE): lambda: int(model.site_bodyid[i])}.get(objtype)
    return int(model.body_rootid[body()]) if body is not None else 0


def _tendon_trees(model: mujoco.MjModel, t: int) -> set[int]:
    out = set()
    for w in range(int(model.tendon_adr[t]), int(model.tendon_adr[t] + model.tendon_num[t])):
        kind, obj = int(model.wrap_type[w]), int(model.wrap_objid[w])
        if kind == mujoco.mjtWrap.mjWRAP_JOINT:
            out.add(int(model.body_rootid[model.jnt_bodyid[obj]]))
        elif kind == mujoco.mjtWrap.mjWRAP_SITE:
            out.add(int(model.body_rootid[model.site_bodyid[obj]]))
        elif kind in (mujoco.mjtWrap.mjWRAP_SPHERE, mujoco.mjtWrap.mjWRAP_CYLINDER):
            out.add(int(model.body_rootid[model.geom_bodyid[obj]]))
    return out


@dataclasses.dataclass(frozen=True)
class _Scene:
    """The reduced scene of a twin and how its elements map to the twin's model."""

    model: mujoco.MjModel  # the reduced model, nominal parameters written
    bodies: np.ndarray  # the twin's body id of each reduced body
    qpos: np.ndarray  # the twin's qpos address of each reduced qpos entry
    dofs: np.ndarray  # the twin's dof address of each reduced dof
    sensors: tuple[np.ndarray, np.ndarray]  # (twin columns, reduced columns) read from it
    robot_geoms: np.ndarray  # the twin's geom ids of the robot's trees
    targets: tuple[tuple[int, ...] | None, ...]  # per parameter: reduced ids, None: robot
    original: types.SimpleNamespace  # the reduced model's own values of the fields written
    reach: np.ndarray  # per reduced body, the radius about its frame that holds its geoms
    proximity: mujoco.MjModel  # the twin's model, robot geoms' margins raised by PROXIMITY
    offsets: dict[int, slice]  # STATE_SPEC components in the twin's state rows
    reduced_offsets: dict[int, slice]  # and in the reduced model's


_SCENES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_SCENES_LOCK = threading.Lock()


def _scene_of(twin: Twin) -> _Scene | str:
    """The twin's reduced scene (built once per twin), or why there is none."""
    with _SCENES_LOCK:
        scene = _SCENES.get(twin)
        if scene is None:
            try:
                scene = _build_scene(twin)
            except ValueError as exc:  # a model the deletion leaves uncompilable
                scene = f"the scene without the robot does not compile ({exc})"
            _SCENES[twin] = scene
        return scene


def _build_scene(twin: Twin) -> _Scene | str:
    model, sc = twin.model, twin.scenario
    if model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_ISLAND:
        return "the model disables constraint islands"
    if model.opt.enableflags & mujoco.mjtEnableBit.mjENBL_SLEEP:
        return "the model lets bodies sleep"
    if model.nmocap or model.npluginstate or model.nflex:
        return "the model has mocap bodies, plugins or flexes"
    roots = _robot_trees(model)
    if not roots:
        return "no kinematic tree is moved by the actuators alone"
    robot_body = np.isin(model.body_rootid, sorted(roots))
    if robot_body[twin.object_body_id]:
        return "the object is part of the robot's trees"
    support = [model.geom(g).id for g in sc.support_geoms]
    if robot_body[model.geom_bodyid[support]].any():
        return "a support of the object is part of the robot"
    names = [model.body(int(r)).name for r in sorted(roots)]
    if not all(names):
        return "a root body of the robot has no name"
    spec = sc.load_spec()
    twin.add_sensors(spec)
    for name in names:
        spec.delete(spec.body(name))
    kept_sensors = {_sensor_name("support", g) for g in sc.support_geoms} | {
        _sensor_name(k) for k in ("object_acc", "object_pos", "object_vel")}
    for s in list(spec.sensors):
        if s.name not in kept_sensors:
            spec.delete(s)
    for group in (spec.actuators, spec.keys, spec.tendons, spec.equalities):
        for item in list(group):
            spec.delete(item)
    if model.ntendon and any(not _tendon_trees(model, t) <= roots
                             for t in range(model.ntendon)):
        return "a tendon spans the rest of the scene"
    if any(not {_root_of(model, int(model.eq_objtype[e]), int(i))
                for i in (model.eq_obj1id[e], model.eq_obj2id[e]) if i >= 0} - {0} <= roots
           for e in range(model.neq)):
        return "an equality constraint acts on the rest of the scene"
    robot_geom_names = {model.geom(g).name for g in np.flatnonzero(robot_body[model.geom_bodyid])}
    for pair in list(spec.pairs):
        if pair.geomname1 in robot_geom_names or pair.geomname2 in robot_geom_names:
            spec.delete(pair)
    deleted = {model.body(b).name for b in np.flatnonzero(robot_body)}
    for ex in list(spec.excludes):
        if ex.bodyname1 in deleted or ex.bodyname2 in deleted:
            spec.delete(ex)
    for group in (spec.cameras, spec.lights):
        for item in list(group):
            if getattr(item, "targetbody", "") in deleted:
                spec.delete(item)
    reduced = spec.compile()
    kept = np.flatnonzero(~robot_body)
    if reduced.nbody != kept.size or reduced.nu or reduced.nmocap:
        return "the scene without the robot does not keep the other bodies one for one"
    for i, b in enumerate(kept):  # the same bodies, in the same order
        if reduced.body(i).name != model.body(int(b)).name or (
                reduced.body_jntnum[i] != model.body_jntnum[b]):
            return "the scene without the robot reorders its bodies"
    qpos, dofs = [], []
    for b in kept:
        for j in range(int(model.body_jntadr[b]), int(model.body_jntadr[b] + model.body_jntnum[b])):
            size = {0: 7, 1: 4, 2: 1, 3: 1}[int(model.jnt_type[j])]
            qpos.extend(range(int(model.jnt_qposadr[j]), int(model.jnt_qposadr[j]) + size))
        dofs.extend(range(int(model.body_dofadr[b]),
                          int(model.body_dofadr[b] + model.body_dofnum[b])))
    qpos, dofs = np.array(qpos, np.int64), np.array(dofs, np.int64)
    if qpos.size != reduced.nq or dofs.size != reduced.nv:
        return "the scene without the robot has other degrees of freedom"
    cols_twin, cols_red = [], []
    for name in kept_sensors:
        try:
            sid_r, sid = reduced.sensor(name).id, model.sensor(name).id
        except KeyError:
            continue
        dim = int(model.sensor_dim[sid])
        cols_twin.extend(range(int(model.sensor_adr[sid]), int(model.sensor_adr[sid]) + dim))
        cols_red.extend(range(int(reduced.sensor_adr[sid_r]),
                              int(reduced.sensor_adr[sid_r]) + dim))
    index_of = {int(b): i for i, b in enumerate(kept)}
    geom_index = {int(g): i for i, g in enumerate(np.flatnonzero(~robot_body[model.geom_bodyid]))}
    targets = []
    for p, ids in zip(sc.box.parameters, twin._param_targets, strict=True):
        kind = p.fields[0].split("_")[0]
        table = {"body": index_of, "geom": geom_index}.get(kind)
        if table is None or any(int(i) not in table for i in ids):
            targets.append(None)
        else:
            targets.append(tuple(table[int(i)] for i in ids))
    fields = twin.parameter_fields()
    original = types.SimpleNamespace(**{f: getattr(reduced, f).copy() for f in fields})
    reach = np.zeros(reduced.nbody)
    for g in range(reduced.ngeom):
        b = int(reduced.geom_bodyid[g])
        reach[b] = max(reach[b], float(np.linalg.norm(reduced.geom_pos[g])
                                       + reduced.geom_rbound[g]))
    proximity = copy_model(model)
    robot_geoms = np.flatnonzero(robot_body[model.geom_bodyid])
    # MuJoCo takes the larger margin of a pair: raise every geom's (and every explicit
    # pair's) so that each pair's is raised; only the robot's pairs with the rest count
    proximity.geom_margin[:] += PROXIMITY
    proximity.pair_margin[:] += PROXIMITY
    scene = _Scene(model=reduced, bodies=kept, qpos=qpos, dofs=dofs,
                   sensors=(np.array(cols_twin, np.int64), np.array(cols_red, np.int64)),
                   robot_geoms=robot_geoms, targets=tuple(targets), original=original,
                   reach=reach, proximity=proximity, offsets=_offsets(model),
                   reduced_offsets=_offsets(reduced))
    _write(twin, scene, reduced, sc.box.nominal[None, :])
    return scene


def copy_model(model: mujoco.MjModel) -> mujoco.MjModel:
    """A copy of ``model`` to modify."""
    import copy

    return copy.copy(model)


def _write(twin: Twin, scene: _Scene, target, samples: np.ndarray) -> None:
    """Write parameter samples into the reduced model (n = 1) or a batch of it, as
    :meth:`Twin.write_parameters` writes them into the twin's."""
    box = twin.scenario.box
    if isinstance(target, mujoco.MjModel):
        arrays = {f: getattr(target, f)[None] for f in twin.parameter_fields()}
    else:
        arrays = {f: target.expand(f) for f in twin.parameter_fields()}
    for j, p in enumerate(box.parameters):
        for index in scene.targets[j] or ():
            p.write(index, scene.original, arrays, samples[:, j])
    if any(p.needs_set_const for p in box.parameters):
        if isinstance(target, mujoco.MjModel):
            mujoco.mj_setConst(target, mujoco.MjData(target))
        else:
            target.set_const()


@dataclasses.dataclass(frozen=True)
class PrefixStart:
    """The samples' own states at the shared prefix's end, and their readings before it.

    Attributes:
        step: P, the step the runs go on from.
        states: each sample's own ``STATE_SPEC`` row at P, (n, nstate).
        sensor_columns: the twin's sensor columns the reduced scene gives, (c,).
        readings: those columns' readings of steps 0 .. P−1 per sample, (n, P, c).
        qpos: each sample's own positions after steps 0 .. P−1, (n, P, nq).
    """

    step: int
    states: np.ndarray
    sensor_columns: np.ndarray
    readings: np.ndarray
    qpos: np.ndarray

    def sensordata(self, nominal: np.ndarray, rows: np.ndarray | slice = slice(None)
                   ) -> np.ndarray:
        """The readings of the first P steps of samples ``rows``, (r, P, nsd): the nominal
        run's ``nominal`` (P, nsd) (the twin's sensors first, as a model with sensors
        appended by :meth:`Twin.add_sensors` has them) with the columns the reduced scene
        gives replaced."""
        readings = self.readings[rows]
        out = np.repeat(np.asarray(nominal)[None, :self.step], readings.shape[0], axis=0)
        out[..., self.sensor_columns] = readings
        return out


class SharedPrefix:
    """The shared prefix of one recording's samples (see the module's doc).

    Built on first use, once, from whichever thread asks first; safe to share between
    threads.

    Args:
        twin: the twin.
        states: the recording's ``STATE_SPEC`` rows (T + 1, nstate).
        controls: the recording's controls (T, nu).
        sensordata: the recording's readings (T, nsd).
        limit: the last step the prefix may reach (e.g. the first audited moment).
        onsets: ``onsets(parameters, limit)``, the first step (up to ``limit``) at which
            one of the box's parameters (indices) that act on the robot (a force limit, a
            finger pad's friction) can change the motion; None: from the start.
    """

    def __init__(self, twin: Twin, states: np.ndarray, controls: np.ndarray,
                 sensordata: np.ndarray, limit: int, onsets=None):
        self.twin = twin
        self._states, self._controls, self._sensordata = states, controls, sensordata
        self._limit, self._onsets = int(limit), onsets
        self._lock = threading.Lock()
        self._ready = False
        self.step = 0
        self.reason = "not built yet"
        self._trace: dict[str, np.ndarray] | None = None

    def plan(self) -> int:
        """P (0: nothing shared; ``reason`` says why), found and checked on first use."""
        with self._lock:
            if not self._ready:
                self.step, self.reason = self._plan()
                self._ready = True
            return self.step

    def start(self, samples: np.ndarray, nthread: int = 1) -> PrefixStart | None:
        """The samples' own states at P and their readings before it, or None where the
        runs must start at step 0 (no prefix, or a sample's object strayed)."""
        if self.plan() == 0:
            return None
        return self._start(samples, nthread)

    # -- internals ------------------------------------------------------------
    def _start(self, samples: np.ndarray, nthread: int) -> PrefixStart | None:
        scene = self._scene()
        out = self._reduced_run(scene, samples, nthread)
        if out is None or _strayed(scene, out, self._trace) >= PROXIMITY:
            return None
        return PrefixStart(step=self.step, states=self._compose(scene, out["final"]),
                           sensor_columns=scene.sensors[0],
                           readings=out["sensordata"][..., scene.sensors[1]],
                           qpos=self._qpos(scene, out["qpos"]))

    def _scene(self) -> _Scene:
        return _SCENES[self.twin]

    def _plan(self) -> tuple[int, str]:
        twin = self.twin
        scene = _scene_of(twin)
        if isinstance(scene, str):
            return 0, scene
        box = twin.scenario.box
        limit = min(self._limit, self._states.shape[0] - 1)
        step = self._proximity(scene, limit)
        robot_params = [j for j, t in enumerate(scene.targets) if t is None]
        if robot_params:  # the state at a parameter's onset is still the nominal one
            step = min(step, self._onsets(robot_params, step) if self._onsets else 0)
        if step < MIN_STEPS:
            return 0, f"the robot nears the rest of the scene at step {step}"
        self.step = step
        trace = self._reduced_run(scene, box.nominal[None, :], 1)
        if trace is None:
            return 0, "the reduced scene's nominal run warned"
        full = self._states
        if not (np.array_equal(trace["qpos"][0], full[1:step + 1][:, scene.offsets[_QPOS]]
                               [:, scene.qpos])
                and np.array_equal(self._compose(scene, trace["final"])[0], full[step])):
            return 0, "the reduced scene's nominal run differs from the recording"
        self._trace = trace
        # one sample far from the nominal, run in full: the robot's part must not move
        corner = np.where(np.abs(box.high - box.nominal) >= np.abs(box.nominal - box.low),
                          box.high, box.low)[None, :]
        composed = self._start(corner, 1)
        if composed is None:
            return 0, "the box's far corner strays near the robot"
        batch = mujoco.batch.Batch(twin.model, 1, nthread=1)
        twin.write_parameters(batch, corner)
        batch.state[:] = full[0]
        batch.warning[...] = 0
        out = batch.rollout(step, control=self._controls[:step][None],
                            control_spec=int(mujoco.mjtState.mjSTATE_CTRL),
                            record=(int(STATE_SPEC),))
        if not np.array_equal(out[int(STATE_SPEC)][0, -1], composed.states[0]):
            return 0, "the box's far corner, run in full, differs from its composed state"
        return step, f"shared to step {step}"

    def _proximity(self, scene: _Scene, limit: int) -> int:
        """The first step (up to ``limit``) at which the nominal run's robot comes within
        PROXIMITY of a geom of the rest of the scene (collision detection with the robot's
        margins raised)."""
        model = scene.proximity
        data = mujoco.MjData(model)
        robot = np.zeros(model.ngeom, bool)
        robot[scene.robot_geoms] = True
        world = model.geom_bodyid == 0
        for k in range(limit + 1):
            mujoco.mj_setState(model, data, self._states[k], STATE_SPEC)
            mujoco.mj_kinematics(model, data)
            mujoco.mj_collision(model, data)
            n = data.ncon
            if n:
                g = data.contact.geom[:n]
                a, b = robot[g[:, 0]], robot[g[:, 1]]
                other = (a & ~robot[g[:, 1]] & ~world[g[:, 1]]) | (
                    b & ~robot[g[:, 0]] & ~world[g[:, 0]])
                if other.any():
                    return k
        return limit

    def _reduced_run(self, scene: _Scene, samples: np.ndarray, nthread: int
                     ) -> dict[str, np.ndarray] | None:
        """The reduced scene from the recording's initial state over steps 0 .. P−1."""
        step, red = self.step, scene.model
        n = samples.shape[0]
        batch = mujoco.batch.Batch(red, n, nthread=nthread)
        _write(self.twin, scene, batch, samples)
        row = np.zeros(mujoco.mj_stateSize(red, STATE_SPEC))
        full, off, roff = self._states[0], scene.offsets, scene.reduced_offsets
        row[roff[_TIME]] = full[off[_TIME]]
        row[roff[_QPOS]] = full[off[_QPOS]][scene.qpos]
        row[roff[_QVEL]] = full[off[_QVEL]][scene.dofs]
        row[roff[_WARM]] = full[off[_WARM]][scene.dofs]
        row[roff[_QFRC]] = full[off[_QFRC]][scene.dofs]
        row[roff[_XFRC]] = full[off[_XFRC]].reshape(-1, 6)[scene.bodies].reshape(-1)
        batch.state[:] = row
        batch.warning[...] = 0
        out = batch.rollout(step, record=("sensordata", "qpos", "xpos", "xmat",
                                          int(STATE_SPEC)))
        if (batch.warning[:, :, 1] > 0).any():
            return None
        return {"sensordata": out["sensordata"], "qpos": out["qpos"], "xpos": out["xpos"],
                "xmat": out["xmat"], "final": out[int(STATE_SPEC)][:, -1]}

    def _compose(self, scene: _Scene, reduced: np.ndarray) -> np.ndarray:
        """The twin's state rows at P: the recording's, with the reduced scene's part of
        each sample's (n, nstate_reduced) written in."""
        off, roff = scene.offsets, scene.reduced_offsets
        rows = np.repeat(self._states[self.step][None], reduced.shape[0], axis=0)
        for comp, index in ((_QPOS, scene.qpos), (_QVEL, scene.dofs), (_WARM, scene.dofs)):
            part = rows[:, off[comp]]
            part[:, index] = reduced[:, roff[comp]]
            rows[:, off[comp]] = part
        return rows

    def _qpos(self, scene: _Scene, reduced: np.ndarray) -> np.ndarray:
        """Positions after steps 0 .. P−1 (n, P, nq): the recording's robot, the samples'
        own rest of the scene."""
        off = scene.offsets[_QPOS]
        out = np.repeat(self._states[1:self.step + 1][None, :, off], reduced.shape[0], axis=0)
        out[..., scene.qpos] = reduced
        return out


def _strayed(scene: _Scene, run: dict[str, np.ndarray], nominal: dict[str, np.ndarray]) -> float:
    """How far [m] any point of the rest of the scene's geoms strayed from the nominal
    run's over the prefix (a bound: the body's move plus its rotation times its reach)."""
    dx = np.linalg.norm(run["xpos"] - nominal["xpos"], axis=-1)  # (n, P, nbody)
    dr = np.linalg.norm(run["xmat"] - nominal["xmat"], axis=-1)
    return float((dx + dr * scene.reach).max(initial=0.0))
