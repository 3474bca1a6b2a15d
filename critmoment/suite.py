"""A suite of trajectory families for validation and tests, each a seeded function.

Beyond the nominal scripted transfer, the families stress what sparse evaluation must
catch: higher accelerations, a shallower grasp, a weakened grip in transport, policy-like
jitter, and a trajectory that never grasps.

======================  ===================================================================
family                  what changes (see :class:`critmoment.demos.DemoOptions`)
======================  ===================================================================
``nominal``             the scripted pick-and-transfer
``fast``                every waypoint time × 0.6: higher accelerations and speeds
``shallow_grasp``       the TCP stops 3.0 cm above the cube centre instead of 1.7 cm: the
                        pads reach less of the cube (the "lower grasp, less pad contact")
``early_open``          the picker opens its gripper to 0.35 while carrying (partial
                        opening during transport: grip force drops from 5 N to ~3 N)
``jitter``              white noise of 0.003 rad on every arm joint target
``no_grasp``            the cube lies 12 cm away from where the arms go: never touched
======================  ===================================================================

The bundled Panda scenario (``panda_pick_place``) has its own families
(:data:`SCENARIO_FAMILIES`, from :data:`critmoment.panda_demo.FAMILIES`): the scripted pick
and place and its variants (``fast``, ``faster``, ``slow``, ``shallow_grasp``, ``no_grasp``).
"""

from __future__ import annotations

from collections.abc import Callable

from critmoment.demos import DemoOptions, sample_box_pose, scripted_transfer
from critmoment.exceptions import ParameterError
from critmoment.trajectory import Trajectory
from critmoment.twin import Twin

__all__ = ["FAMILIES", "SCENARIO_FAMILIES", "make"]


def _with(options: DemoOptions) -> Callable[..., Trajectory]:
    def build(seed: int, twin: Twin | None = None) -> Trajectory:
        return scripted_transfer(seed, options=options, twin=twin)

    return build


def _no_grasp(seed: int, twin: Twin | None = None) -> Trajectory:
    traj = scripted_transfer(seed, twin=twin)
    pose = sample_box_pose(seed).copy()
    pose[1] += 0.12 if pose[1] < 0.5 else -0.12  # the arms plan for the sampled pose
    return Trajectory(actions=traj.actions, fps=traj.fps, start=traj.start, object_pose=pose,
                      meta={**traj.meta, "family": "no_grasp"}, source=traj.source + " no_grasp")


#: family name -> function(seed, twin=None) -> Trajectory
FAMILIES: dict[str, Callable[..., Trajectory]] = {
    "nominal": _with(DemoOptions()),
    "fast": _with(DemoOptions(time_scale=0.6)),
    "shallow_grasp": _with(DemoOptions(grasp_height=0.030)),
    "early_open": _with(DemoOptions(carry_opening=0.35)),
    "jitter": _with(DemoOptions(jitter=0.003)),
    "no_grasp": _no_grasp,
}


def _panda(family: str) -> Callable[..., Trajectory]:
    def build(seed: int, twin: Twin | None = None) -> Trajectory:
        from critmoment import panda_demo

        return panda_demo.make(family, seed=seed, model=None if twin is None else twin.model)

    return build


def _panda_families() -> dict[str, Callable[..., Trajectory]]:
    from critmoment import panda_demo

    return {name: _panda(name) for name in panda_demo.FAMILIES}


#: bundled scenario -> its families (family name -> function(seed, twin=None) -> Trajectory)
SCENARIO_FAMILIES: dict[str, dict[str, Callable[..., Trajectory]]] = {
    "aloha_transfer_cube": FAMILIES,
    "panda_pick_place": _panda_families(),
}


def make(family: str, *, seed: int = 0, twin: Twin | None = None,
         scenario: str = "aloha_transfer_cube") -> Trajectory:
    """A trajectory of ``family`` with ``seed`` (cube spawn, and noise where there is any) for
    the bundled ``scenario``; its ``meta`` names the scenario, so that the CLI audits it
    against that scenario when ``--scenario`` is not given."""
    if scenario not in SCENARIO_FAMILIES:
        raise ParameterError(f"unknown bundled scenario {scenario!r}; known: "
                             f"{', '.join(SCENARIO_FAMILIES)}")
    families = SCENARIO_FAMILIES[scenario]
    if family not in families:
        raise ParameterError(f"unknown trajectory family {family!r} for {scenario}; known: "
                             f"{', '.join(families)}")
    from critmoment.budget import check_seed

    traj = families[family](check_seed(seed), twin=twin)
    meta = dict(traj.meta)
    meta["family"] = family
    meta["scenario"] = scenario
    return Trajectory(actions=traj.actions, fps=traj.fps, start=traj.start, qpos0=traj.qpos0,
                      object_pose=traj.object_pose, meta=meta, source=f"{family}(seed={seed})")
