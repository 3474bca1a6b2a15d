"""Tests for critmoment.task: stages and success rules of each task kind on known runs."""

from __future__ import annotations

import numpy as np
import pytest

from critmoment.exceptions import ScenarioError
from critmoment.task import (
    TASK_KINDS,
    HandoverTask,
    PickHoldTask,
    PickPlaceTask,
    TaskEvidence,
    task_from_table,
)

DT = 0.002


def _run(z, touch, support, x=None, v_end=0.0):
    """Evidence of one run from per-step height [m], touch (T, G) and support flags (T,)."""
    t = len(z)
    pos = np.zeros((t, 3))
    pos[:, 2] = z
    if x is not None:
        pos[:, 0] = x
    vel = np.zeros((t, 3))
    vel[-1, 2] = v_end
    return TaskEvidence(contact_gripper=np.asarray(touch, bool),
                        contact_support=np.asarray(support, bool), object_pos=pos,
                        object_vel=vel, dt=DT)


def _pick_place_run(*, place_x=0.3, release=True, lift=0.1, v_end=0.0):
    """Cube starts at x = 0 on the table, lifted by `lift`, carried to place_x, put down."""
    n = 100
    z = np.concatenate([np.full(n, 0.02), np.full(n, 0.02 + lift), np.full(n, 0.02),
                        np.full(n, 0.02)])
    x = np.concatenate([np.zeros(n), np.linspace(0, place_x, n), np.full(2 * n, place_x)])
    touch = np.zeros((4 * n, 1), bool)
    touch[50:3 * n if release else 4 * n] = True
    support = np.ones(4 * n, bool)
    support[n:2 * n] = False
    return _run(z, touch, support, x=x, v_end=v_end)


PLACE = PickPlaceTask(grippers=("hand",), gripper="hand", goal=(0.3, 0.0, 0.02),
                      tolerance=0.03)


def test_pick_place_success_needs_lift_goal_release_and_rest():
    assert PLACE.success(_pick_place_run())
    # a release onto the table at the goal is the success, not a drop
    assert not PLACE.success(_pick_place_run(place_x=0.1))      # put down far from the goal
    assert not PLACE.success(_pick_place_run(release=False))    # still gripped at the end
    assert not PLACE.success(_pick_place_run(lift=0.005))       # pushed, never lifted
    assert not PLACE.success(_pick_place_run(v_end=0.5))        # still moving (tipping over)


def test_the_shortfalls_of_a_run_name_each_part_of_the_rule_it_misses():
    assert PLACE.shortfalls(_pick_place_run()) == []
    far = PLACE.shortfalls(_pick_place_run(place_x=0.1))
    assert far == ["the object ends 200 mm from the goal (tolerance 30 mm)"]
    assert PLACE.shortfalls(_pick_place_run(release=False)) == [
        "a gripper still touches the object at the end"]
    assert PLACE.shortfalls(_pick_place_run(lift=0.005)) == [
        "the object rose 5 mm at most (a lift is 20 mm)"]
    assert PLACE.shortfalls(_pick_place_run(v_end=0.5)) == [
        "the object still moves at 0.5 m/s at the end (at rest: 0.05 m/s)"]
    # placed, then dragged off the goal: when it left is said
    ev = _pick_place_run()
    pos = ev.object_pos.copy()
    pos[-50:, 0] = 0.4
    dragged = TaskEvidence(ev.contact_gripper, ev.contact_support, pos, ev.object_vel, DT)
    assert not PLACE.success(dragged)
    assert PLACE.shortfalls(dragged) == [
        "the object ends 100 mm from the goal (tolerance 30 mm; it was within it until "
        "t = 0.70 s)"]
    # hold and hand-over: who let go, and when; resting on the support
    hold = PickHoldTask(grippers=("hand",), gripper="hand")
    z = np.concatenate([np.full(100, 0.02), np.full(100, 0.1)])
    touch = np.ones((200, 1), bool)
    touch[150:] = False
    support = np.concatenate([np.ones(100, bool), np.zeros(100, bool)])
    assert hold.shortfalls(_run(z, touch, support)) == [
        "hand does not hold the object at the end (it last touched it at t = 0.30 s)"]
    support[-30:] = True
    touch[:] = True
    assert hold.shortfalls(_run(z, touch, support)) == [
        "the object rests on its support at the end"]
    swap = HandoverTask(grippers=("left", "right"), picker="right", receiver="left")
    never = np.zeros((200, 2), bool)
    never[:, 1] = True
    assert swap.shortfalls(_run(z, never, np.zeros(200, bool))) == [
        "left does not hold the object at the end (it never touched it)"]
    # a run lacks something exactly when it fails (Recording.shortfalls relies on it)
    runs = [(PLACE, _pick_place_run(**kw)) for kw in (
        {}, {"place_x": 0.1}, {"release": False}, {"lift": 0.005}, {"v_end": 0.5})]
    runs += [(PLACE, dragged), (hold, _run(z, np.ones((200, 1), bool),
                                           np.arange(200) < 100)),
             (hold, _run(z, touch, support)), (swap, _run(z, never, np.zeros(200, bool)))]
    for task, ev in runs:
        assert (task.shortfalls(ev) == []) == bool(task.success(ev))


def test_pick_place_stages():
    ev = _pick_place_run()
    stage = PLACE.stage(ev.contact_gripper, ev.contact_support, ev.object_pos)
    assert stage[0] == 0 and stage[60] == 1 and stage[150] == 2
    assert stage[250] == 3 and stage[-1] == 4
    assert PLACE.stage_names[stage[-1]] == "released"


def test_pick_place_success_is_batched_over_runs():
    runs = [_pick_place_run(), _pick_place_run(place_x=0.1)]
    ev = TaskEvidence(*(np.stack([getattr(r, f) for r in runs]) for f in
                        ("contact_gripper", "contact_support", "object_pos", "object_vel")),
                      dt=DT)
    np.testing.assert_array_equal(PLACE.success(ev), [True, False])


def test_contact_chatter_at_the_end_does_not_fail_a_hold():
    task = PickHoldTask(grippers=("hand",), gripper="hand")
    n = 200
    z = np.concatenate([np.full(n, 0.02), np.full(n, 0.1)])
    touch = np.ones((2 * n, 1), bool)
    touch[-1] = False  # the last step's contact flag flickers off
    support = np.concatenate([np.ones(n, bool), np.zeros(n, bool)])
    assert task.success(_run(z, touch, support))
    touch[-40:] = False  # 80 ms without contact: it was dropped
    assert not task.success(_run(z, touch, support))


def test_an_object_falling_out_of_the_grip_at_the_end_is_not_held():
    """Menagerie's PiPER (probe r34): the cube slid down the pads and left them 14 ms before
    the end, falling at 0.14 m/s; a touch anywhere in the final 50 ms had made it "held".
    A touch that ends more than 10 ms before the end now holds only an object that is not
    falling (a contact that flickers at rest, or a last step's flag off, still holds)."""
    n = 200
    z = np.concatenate([np.full(n, 0.02), np.full(n, 0.1)])
    support = np.concatenate([np.ones(n, bool), np.zeros(n, bool)])
    for task, touch in ((PickHoldTask(grippers=("hand",), gripper="hand"),
                         np.ones((2 * n, 1), bool)),
                        (HandoverTask(grippers=("hand", "other"), picker="other",
                                      receiver="hand"), np.ones((2 * n, 2), bool))):
        touch[-7:, 0] = False  # 14 ms without the holder's contact
        assert not task.success(_run(z, touch, support, v_end=-0.137))
        assert task.success(_run(z, touch, support, v_end=-0.01))  # at rest: a flicker
        assert "falls at 0.14 m/s at the end" in " ".join(
            task.shortfalls(_run(z, touch, support, v_end=-0.137)))
        touch[-7:-4, 0] = True  # 8 ms: within END_GAP, falling or not
        assert task.success(_run(z, touch, support, v_end=-0.137))


def test_handover_success_is_the_receiver_holding_it_off_the_support():
    task = HandoverTask(grippers=("left", "right"), picker="right", receiver="left")
    n = 100
    touch = np.zeros((3 * n, 2), bool)
    touch[:2 * n, 1] = True      # the picker holds it
    touch[n:, 0] = True          # the receiver takes it
    support = np.zeros(3 * n, bool)
    support[:10] = True
    z = np.full(3 * n, 0.1)
    ev = _run(z, touch, support)
    assert task.success(ev)
    stage = task.stage(ev.contact_gripper, ev.contact_support, ev.object_pos)
    assert stage[5] == 1 and stage[50] == 2 and stage[-1] == 4
    support[-50:] = True         # it ends on the table
    assert not task.success(_run(z, touch, support))


@pytest.mark.parametrize("table, message", [
    ({}, r"\[task\]: missing kind; expected kind = one of handover, pick_place, pick_hold"),
    ({"kind": "stack"}, r"\[task\] kind: expected one of handover, pick_place, pick_hold, got"),
    ({"kind": "pick_place", "gripper": "hand"}, r"expected exactly one of goal"),
    ({"kind": "pick_place", "goal": [0, 0]}, r"\[task\] goal: expected \[x, y, z\]"),
    ({"kind": "pick_place", "goal": [0, 0, 0], "tolerence": 0.01},
     r"unknown key 'tolerence' \(did you mean 'tolerance'\?\)"),
    ({"kind": "pick_hold", "gripper": "claw"}, r"\[task\] gripper: expected one of"),
    ({"kind": "handover", "picker": "hand", "receiver": "hand"},
     r"two different grippers for picker and receiver"),
    ({"kind": "pick_place", "goal": [0, 0, 0], "tolerance": -1.0},
     r"\[task\] tolerance: expected a finite number > 0"),
])
def test_bad_task_tables(table, message):
    with pytest.raises(ScenarioError, match=message):
        task_from_table(table, ["hand"])


def test_several_grippers_need_the_gripper_named():
    with pytest.raises(ScenarioError, match=r"several grippers needs gripper = one of"):
        task_from_table({"kind": "pick_hold"}, ["left", "right"])
    assert task_from_table({"kind": "pick_hold"}, ["hand"]).gripper == "hand"


def test_registry_and_json():
    assert set(TASK_KINDS) == {"handover", "pick_place", "pick_hold"}
    doc = PLACE.to_json()
    assert doc["kind"] == "pick_place" and doc["goal"] == [0.3, 0.0, 0.02]
    assert doc["stages"][-1] == "released" and "place" in doc["description"]


def test_evidence_shapes_are_checked():
    with pytest.raises(ScenarioError, match="task evidence: expected"):
        TaskEvidence(contact_gripper=np.zeros((5, 1), bool), contact_support=np.zeros(4, bool),
                     object_pos=np.zeros((5, 3)), object_vel=np.zeros((5, 3)), dt=DT)


def test_a_lift_height_for_a_handover_is_warned_unused():
    """Nothing in a hand-over's success reads lift_height (100 m gave the same verdict)."""
    from critmoment.exceptions import CritmomentWarning

    table = {"kind": "handover", "picker": "left", "receiver": "right", "lift_height": 100.0}
    with pytest.warns(CritmomentWarning, match=r"\[task\] lift_height: a hand-over's success "
                      r".*the value is not used"):
        task = task_from_table(table, ["left", "right"])
    assert isinstance(task, HandoverTask)


def test_a_lift_is_measured_against_gravity():
    """A model whose gravity points along −y lifts along +y: a rise in z is no lift there
    (the rule read z whatever the model's gravity)."""
    n = 50
    rise = np.concatenate([np.zeros(n), np.full(n, 0.1)])
    touch = np.ones((2 * n, 1), bool)
    support = np.r_[np.ones(n, bool), np.zeros(n, bool)]
    along_z = _run(rise, touch, support)
    along_y = TaskEvidence(contact_gripper=touch, contact_support=support,
                           object_pos=np.c_[np.zeros(2 * n), rise, np.zeros(2 * n)],
                           object_vel=np.zeros((2 * n, 3)), dt=DT)
    hold = PickHoldTask(grippers=("hand",), gripper="hand")
    y_up = PickHoldTask(grippers=("hand",), gripper="hand", up=(0.0, 1.0, 0.0))
    assert hold.lifted(along_z) and not hold.lifted(along_y)
    assert y_up.lifted(along_y) and not y_up.lifted(along_z)
    assert "up" not in y_up.to_json()  # the model's, not a task setting


def test_a_chunk_that_starts_mid_carry_starts_lifted():
    """An action chunk audited mid-carry starts with the object held off its support; it
    only goes down (to the goal): its lift happened before the chunk. Held on the table at
    the start, or touched only later, the rule still asks for the rise."""
    n = 100
    z = np.linspace(0.08, 0.02, 2 * n)  # carried down from 8 cm, set on the table
    x = np.full(2 * n, 0.3)
    touch = np.r_[np.ones(n, bool), np.zeros(n, bool)][:, None]  # released at step n
    support = np.r_[np.zeros(n, bool), np.ones(n, bool)]
    chunk = _run(z, touch, support, x=x)
    assert PLACE.carried_at_start(chunk) and PLACE.lifted(chunk) and PLACE.success(chunk)
    assert PLACE.shortfalls(chunk) == []
    # the same path with the object on its support at the start: no lift, no success
    on_table = _run(z, touch, np.ones(2 * n, bool), x=x)
    assert not PLACE.carried_at_start(on_table) and not PLACE.success(on_table)
    assert any("rose" in s for s in PLACE.shortfalls(on_table))
    # untouched at the start (a gripper only reaches it later): no head start either
    late = _run(z, np.r_[np.zeros(10, bool), np.ones(n - 10, bool), np.zeros(n, bool)][:, None],
                support, x=x)
    assert not PLACE.carried_at_start(late) and not PLACE.lifted(late)


@pytest.mark.parametrize("build, message", [
    (lambda: PickPlaceTask(grippers=("hand",), gripper="hand", goal=(0.3, 0.0)),
     r"\[task\] goal: expected \(x, y, z\)"),
    (lambda: PickPlaceTask(grippers=("hand",), gripper="hand", goal="0.3 0 0"),
     r"\[task\] goal: expected \(x, y, z\)"),
    (lambda: PickPlaceTask(grippers=("hand",), gripper="hand", goal=(0.3, np.nan, 0.0)),
     r"\[task\] goal: expected \(x, y, z\)"),
    (lambda: PickPlaceTask(grippers=("hand",), gripper="hand", tolerance="0.03"),
     r"\[task\] tolerance: expected a finite number > 0, got '0.03'"),
    (lambda: PickHoldTask(grippers=("hand",), gripper="hand", settle_time=None),
     r"\[task\] settle_time: expected a finite number >= 0, got None"),
    (lambda: PickHoldTask(grippers=("hand",), gripper="hand", lift_height=10**400),
     r"\[task\] lift_height: expected a finite number"),
    (lambda: PickHoldTask(grippers=("hand",), gripper="hand", up="z"),
     r"\[task\] up: expected \(x, y, z\)"),
    (lambda: PickHoldTask(grippers=("hand",), gripper="hand", up=(0, 0, 0)),
     r"\[task\] up: expected a non-zero direction"),
    (lambda: PickHoldTask(grippers="hand", gripper="hand"), r"\[task\] grippers: expected"),
    (lambda: HandoverTask(grippers=("l", "l"), picker="l", receiver="r"),
     r"\[task\] grippers: expected"),
    (lambda: HandoverTask(grippers=("l", "r"), picker=0, receiver="r"),
     r"\[task\] picker: expected one of the grippers \['l', 'r'\], got 0"),
])
def test_tasks_built_in_code_refuse_bad_fields(build, message):
    """A task built in code is checked as a [task] table is (these raised ValueError,
    TypeError or OverflowError from inside a rollout, or passed: a NaN goal, up = 0)."""
    with pytest.raises(ScenarioError, match=message):
        build()


def test_fields_built_in_code_are_stored_as_floats():
    task = PickPlaceTask(grippers=["hand"], gripper="hand", goal=np.array([1, 2, 3]),
                         tolerance=np.float32(0.5), up=(0, 0, 2))
    assert task.grippers == ("hand",) and task.goal == (1.0, 2.0, 3.0)
    assert type(task.tolerance) is float and task.up == (0.0, 0.0, 1.0)
