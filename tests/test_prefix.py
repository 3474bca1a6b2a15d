"""The shared prefix (critmoment.prefix): a sample's own run from a later step, to the bit.

Each composed state, reading and position is compared with the sample's own full run from
step 0, bit for bit, on the bundled demo under its elliptic cone and under MuJoCo's default
pyramidal one; the chain and the brute force give the same results with and without it;
and where the prefix cannot be trusted, the runs start at step 0.
"""

import dataclasses
import shutil
import warnings

import mujoco
import mujoco.batch
import numpy as np
import pytest

import critmoment.prefix as prefix_mod
from critmoment import history, sparse
from critmoment.groundtruth import brute_force, reference_from_recording
from critmoment.recording import rollout
from critmoment.scenario import load_scenario
from critmoment.twin import STATE_SPEC, Twin
from scenarios import soft_copy


def _samples(box, n=3):
    """Sobol samples and the box's two extreme corners."""
    return np.vstack([sparse.sweep_samples(box, n=n, seed=0), box.low[None], box.high[None]])


def _full_prefix(twin, rec, samples, step):
    """The samples' own full runs over steps 0 .. step−1 (final state, readings, positions)."""
    batch = mujoco.batch.Batch(twin.model, samples.shape[0], nthread=1)
    twin.write_parameters(batch, samples)
    batch.state[:] = rec.states[0]
    out = batch.rollout(step, control=np.asarray(rec.controls)[:step][None],
                        control_spec=int(mujoco.mjtState.mjSTATE_CTRL),
                        record=(int(STATE_SPEC), "sensordata", "qpos"))
    return out[int(STATE_SPEC)][:, -1], out["sensordata"], out["qpos"]


@pytest.fixture(scope="module")
def soft(tmp_path_factory, scenario):
    twin = Twin(load_scenario(soft_copy(scenario, tmp_path_factory.mktemp("soft") / "s")))
    from critmoment import demos

    traj = demos.scripted_transfer(0, twin=twin)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return twin, traj, rollout(traj, twin=twin)


@pytest.mark.parametrize("which", ["elliptic", "pyramidal"])
def test_composed_prefix_is_each_samples_own_run(which, twin, demo_recording, soft):
    tw, rec = (twin, demo_recording) if which == "elliptic" else (soft[0], soft[2])
    ev = sparse.SparseEvaluator(rec, tw)
    step = ev.prefix.plan()
    assert step > 1000, ev.prefix.reason  # the arms approach the cube for over 2 s
    touched = np.flatnonzero(rec.signals.contact_gripper.any(axis=-1))
    assert step < touched[0]
    samples = _samples(tw.scenario.box)
    start = ev.prefix.start(samples)
    assert start is not None and start.step == step
    state, sensordata, qpos = _full_prefix(tw, rec, samples, step)
    assert np.array_equal(start.states, state)
    assert np.array_equal(start.sensordata(rec.sensordata), sensordata)
    assert np.array_equal(start.qpos, qpos)
    # the samples' objects really rest differently (the heavy one sinks deeper)
    z = state[:, 1 + tw.object_qposadr + 2]
    assert np.ptp(z) > 0


def test_brute_force_with_the_prefix_classifies_each_run_as_from_step_0(twin, demo_traj,
                                                                         demo_recording):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    assert ev.prefix.plan() > 0
    samples = _samples(twin.scenario.box, n=2)
    ref = reference_from_recording(demo_recording, twin)
    plain = brute_force(demo_traj, twin=twin, samples=samples, reference=ref, nthread=1)
    shared = brute_force(demo_traj, twin=twin, samples=samples, reference=ref, nthread=1,
                         shared=ev.prefix)
    for f in dataclasses.fields(plain.classification):
        a, b = (getattr(x.classification, f.name) for x in (plain, shared))
        assert (a == b if not isinstance(a, np.ndarray) else np.array_equal(a, b)), f.name
    assert np.array_equal(plain.diverged, shared.diverged)


def _chain(ev, steps, samples):
    result = history.chained_failures(ev, steps, samples)
    return {f.name: getattr(result, f.name) for f in dataclasses.fields(result)}


def _same(a, b):
    # the same results; only the steps stepped in the full model differ
    assert a["stepped"] >= b["stepped"]
    for name in set(a) - {"stepped"}:
        x, y = a[name], b[name]
        assert (np.array_equal(x, y) if isinstance(x, np.ndarray) else x == y), name


def test_chain_with_the_prefix_is_the_chain_from_step_0(twin, demo_recording):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    step = ev.prefix.plan()
    steps = np.array([1466, 1707, 2290, 3406])
    samples = _samples(twin.scenario.box, n=3)
    plain = ev.fork()
    plain.prefix = None
    a, b = _chain(plain, steps, samples), _chain(ev, steps, samples)
    _same(a, b)
    assert step > 0 and a["stepped"] - b["stepped"] == step


def test_a_sample_that_strays_starts_at_step_0(twin, demo_recording, monkeypatch):
    # with no room at all, every sample's resting cube differs from the nominal one's
    ev = sparse.SparseEvaluator(demo_recording, twin)
    assert ev.prefix.plan() > 0
    monkeypatch.setattr(prefix_mod, "PROXIMITY", 0.0)
    samples = _samples(twin.scenario.box, n=2)
    assert ev.prefix.start(samples) is None
    steps = np.array([1466, 1707])
    plain = ev.fork()
    plain.prefix = None
    _same(_chain(plain, steps, samples), _chain(ev, steps, samples))


def test_no_prefix_without_islands(tmp_path, scenario):
    folder = tmp_path / "s"
    shutil.copytree(scenario.path.parent, folder)
    xml = (folder / "scene.xml").read_text()
    xml = xml.replace('impratio="10"/>', 'impratio="10"><flag island="disable"/></option>')
    (folder / "scene.xml").write_text(xml)
    tw = Twin(load_scenario(folder))
    from critmoment import demos

    traj = demos.scripted_transfer(0, twin=tw)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout(traj, twin=tw)
    ev = sparse.SparseEvaluator(rec, tw)
    assert ev.prefix.plan() == 0
    assert "islands" in ev.prefix.reason
    assert ev.prefix.start(_samples(tw.scenario.box, n=1)) is None


def test_the_first_moment_bounds_the_chains_prefix(twin, demo_recording):
    # a moment before the prefix's end: the chain starts at step 0 (and is still the same)
    ev = sparse.SparseEvaluator(demo_recording, twin)
    step = ev.prefix.plan()
    steps = np.array([step - 200, 1707])
    samples = _samples(twin.scenario.box, n=1)
    assert history._shared_start(ev, samples, 0, [int(steps[0]), 1707]) is None
    plain = ev.fork()
    plain.prefix = None
    _same(_chain(plain, steps, samples), _chain(ev, steps, samples))
