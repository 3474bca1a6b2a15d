"""The safe region's check on a motion whose outcome turns between the checked points."""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

from critmoment import analysis, panda_demo
from critmoment.groundtruth import brute_force
from critmoment.modelinfo import init_scenario
from critmoment.params import FrictionParameter, MassParameter, UncertaintyBox
from critmoment.recording import rollout
from critmoment.scenario import bundled_scenario_path, load_scenario
from critmoment.trajectory import Trajectory
from critmoment.twin import Twin

_FRIC = ('contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001" '
         'solref="0.01 1"')
_LEVER = f'''<body name="cube" pos="0.5 -0.15 0.02">
      <freejoint name="cube_joint"/>
      <geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.05" {_FRIC}/>
      <geom name="bar" type="box" size="0.05 0.008 0.008" pos="0.07 0 -0.012" mass="0.02" {_FRIC}/>
      <geom name="weight" type="box" size="0.02 0.02 0.02" pos="0.14 0 0" mass="0.15" {_FRIC}/>
    </body>'''


@pytest.fixture(scope="module")
def lever(tmp_path_factory):
    """The bundled Panda carrying a lever (a cube gripped, a 0.15 kg weight 14 cm out on a
    bar): at friction 0.2 it slips in the grip by 9.7 mm at 0.14 kg and by 10.5-11 mm from
    0.145 kg (the ground truth's rule: 1 cm for 50 ms), a strip along the friction range's
    low edge that a coarse edge point does not see."""
    source = bundled_scenario_path("panda_pick_place").parent
    folder = tmp_path_factory.mktemp("lever")
    (folder / "panda.xml").write_text((source / "panda.xml").read_text())
    xml = re.sub(r'<body name="cube".*?</body>', lambda m: _LEVER,
                 (source / "scene.xml").read_text(), count=1, flags=re.S)
    (folder / "scene.xml").write_text(xml)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        init_scenario(folder / "scene.xml", object_body="cube", task="pick_place",
                      goal=(0.5, 0.15, 0.02), out=folder / "scenario.toml")
        scenario = load_scenario(folder / "scenario.toml")
    box = UncertaintyBox((MassParameter("mass", "cube", 0.1, 1.0, 0.22),
                          FrictionParameter("friction", "weight", 0.2, 1.5, 1.0)))
    twin = Twin(scenario.replace(box=box))
    model = twin.model
    cube = panda_demo.sample_cube_pose(0)
    cube[2] = 0.02
    options = panda_demo.PickPlaceOptions(goal=(0.5, 0.15, 0.02))
    q, _, grip = panda_demo.pick_place_plan(model, cube, options)
    targets = panda_demo._feed_forward(model, q, grip, 1.0 / options.fps)
    traj = Trajectory(actions=np.concatenate([targets, grip[:, None]], axis=1),
                      fps=options.fps, start=np.concatenate([panda_demo.READY_POSE, [1.0]]),
                      object_pose=cube)
    return twin, traj


def test_an_edge_whose_own_runs_come_near_a_rule_is_checked_densely(lever):
    """A region stated as "safe for mass <= 0.181 kg" at any friction held on its 17
    checked points (corners, coarse edge points, inside), while 7 of 40 points inside it
    slip out of the grip (helper probe of 2026-12-06). An edge point whose own run comes
    within the verification fraction of a rule's limit (a 9.7 mm slip against 1 cm) now
    densifies its edge as a cost near the threshold does."""
    twin, traj = lever
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout(traj, twin=twin)
        evaluator, _ = analysis.audit_evaluator(rec, twin)
        _, steps = analysis.audit_moments(rec, twin, evaluator, 8)
        opts = analysis.decision_options(analysis.AnalyzeOptions(), twin.scenario.cost.threshold)
        check = analysis.check_region({"mass": (0.1, 0.181), "friction": (0.2, 1.5)},
                                      trajectory=traj, twin=twin, evaluator=evaluator,
                                      steps=steps, sides=["above", "below"], options=opts,
                                      nominal_completed=rec.completed, every_point=False)
    assert check.region is not None
    # the stated region excludes the slipping strip: no point of it fails in full
    lo, hi = (np.array([check.region[n][i] for n in ("mass", "friction")]) for i in (0, 1))
    strip = np.array([[m, f] for m in (0.145, 0.163, 0.181) for f in (0.2, 0.22)])
    inside = strip[((strip >= lo) & (strip <= hi)).all(axis=1)]
    if inside.shape[0]:
        assert not brute_force(traj, twin=twin, samples=inside).failed.any()
    assert check.shrunk and not ((strip >= lo) & (strip <= hi)).all(axis=1)[2:].any()


def test_a_pyramidal_cone_grip_that_does_not_move_is_for_its_own_run():
    """The bundled Panda with a pyramidal cone (impratio 100), mass 1-2.6 kg: grips at a
    force ratio FOS 1.05-1.2 moving 10-100 µm over the window failed the sweep and really
    hold (4 false unsafes of 32 here, 33 of 256 on the demo of seed 3). On a pyramidal cone
    the ratio proves nothing; a contact failure whose object moved under a tenth of the
    slip tolerance is decided by its own rollout."""
    import critmoment as cm

    scenario = load_scenario("panda_pick_place")
    box = UncertaintyBox((MassParameter("mass", "cube", 1.0, 2.6, 1.0),
                          FrictionParameter("friction", "cube", 0.6, 1.5, 1.0)))
    twin = Twin(scenario.replace(box=box))
    twin.model.opt.cone = 0  # mjCONE_PYRAMIDAL (the twin's model changed in memory)
    twin.model.opt.impratio = 100.0
    traj = panda_demo.make_pick_place(3)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = cm.validate(traj, twin=twin, n_samples=32, seed=0)
    assert result.confusion["false_safe"] == 0
    assert result.confusion["false_unsafe"] == 0
