"""Benchmark: critmoment's sparse evaluation against raw ``mujoco.batch`` stepping.

Both sides evaluate the same Sobol samples of the uncertainty box at the same moments of the
scripted demo's recording, with the parameters written once beforehand:

* raw: for each moment, write the state rows (``batch.state[:] = row``) and ``batch.step()``
  (``nstep = horizon``), nothing else;
* critmoment: ``SparseEvaluator.evaluate``: state load, stepping with the recorded controls,
  divergence checks, signal extraction and horizon reduction into a ``SparseResult``.

An evaluation is one (moment, sample) pair of ``horizon`` physics steps. The script also
compares STEP with SOLVE (one forward solve) at horizon 1: speed and largest difference.

    PYTHONPATH=. python benchmarks/bench_sparse.py --samples 2048 --repeats 3
"""

from __future__ import annotations

import argparse
import os
import platform
import time
import warnings

import mujoco
import mujoco.batch
import numpy as np

from critmoment import demos
from critmoment import recording as rollout
from critmoment.scenario import load_scenario
from critmoment.sparse import SparseEvaluator, SparseMode, sweep_samples
from critmoment.twin import Twin


def demo_moments(recording) -> list[int]:
    """Five moments of the demo: grasp, lift-off, carry, hand-over, after the release."""
    stage = recording.stage
    t = recording.n_steps
    grasp = int(np.flatnonzero(stage >= 1)[0])
    # the first step of the last run into stage 2 (contact chatter precedes the lift-off)
    two = stage == 2
    starts = np.flatnonzero(two & ~np.concatenate([[False], two[:-1]]))
    lift = int(starts[-1])
    handover = int(np.flatnonzero(stage == 4)[0])
    return [grasp + 50, lift + 100, (lift + handover) // 2, handover + 300,
            min(t - 10, handover + 800)]


class RawStepper:
    """Raw ``mujoco.batch`` stepping: state rows in, ``step()``, nothing else."""

    def __init__(self, twin: Twin, recording, steps, samples, *, nthread: int, horizon: int):
        self.batch = mujoco.batch.Batch(twin.model, samples.shape[0], nthread=nthread)
        twin.write_parameters(self.batch, samples)
        self.horizon = horizon
        ctrl = slice(*_ctrl_span(twin))
        self.rows = []
        for k in steps:
            row = recording.states[k].copy()
            row[ctrl] = recording.controls[k]  # the controls step k applies
            self.rows.append(row)

    def __call__(self) -> None:
        for row in self.rows:
            self.batch.state[:] = row
            self.batch.step(nstep=self.horizon)


def _ctrl_span(twin: Twin) -> tuple[int, int]:
    offset = 0
    for bit in range(mujoco.mjtState.mjNSTATE):
        part = 1 << bit
        if not int(mujoco.mjtState.mjSTATE_INTEGRATION) & part:
            continue
        size = mujoco.mj_stateSize(twin.model, part)
        if part == int(mujoco.mjtState.mjSTATE_CTRL):
            return offset, offset + size
        offset += size
    raise RuntimeError("no ctrl in the integration state")


def best_times(runs: dict, repeats: int) -> dict:
    """Best wall time [s] of each callable, timed interleaved so that drifts hit all alike."""
    best = dict.fromkeys(runs, np.inf)
    for _ in range(repeats):
        for name, run in runs.items():
            start = time.perf_counter()
            run()
            best[name] = min(best[name], time.perf_counter() - start)
    return best


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=2048, help="parameter samples per moment")
    parser.add_argument("--repeats", type=int, default=3, help="timed repeats (best is kept)")
    parser.add_argument("--seed", type=int, default=0, help="demo and Sobol seed")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--horizons", type=int, nargs="+", default=[1, 5])
    args = parser.parse_args(argv)

    scenario = load_scenario()
    twin = Twin(scenario)
    traj = demos.scripted_transfer(args.seed, twin=twin)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        recording = rollout.rollout(traj, twin=twin)
    steps = demo_moments(recording)
    samples = sweep_samples(scenario.box, n=args.samples, seed=args.seed)
    print(f"machine: {platform.machine()}, {os.cpu_count()} CPUs, mujoco {mujoco.__version__}")
    print(f"demo seed {args.seed}: moments {steps}; {args.samples} Sobol samples of "
          f"{', '.join(scenario.box.names)}; best of {args.repeats}")
    print()
    header = (f"{'threads':>7} {'horizon':>7} {'raw eval/s':>12} {'critmoment eval/s':>18} "
              f"{'ratio':>7}")
    print(header)
    print("-" * len(header))
    n_eval = len(steps) * args.samples
    ratios = {}
    for nthread in args.threads:
        for horizon in args.horizons:
            raw = RawStepper(twin, recording, steps, samples, nthread=nthread, horizon=horizon)
            engine = SparseEvaluator(recording, twin, horizon=horizon, nthread=nthread)
            engine.evaluate(steps[:1], samples)  # writes the parameters once, as raw does
            best = best_times({"raw": raw, "critmoment": lambda engine=engine: engine.evaluate(steps, samples)},
                              args.repeats)
            ratio = best["raw"] / best["critmoment"]
            ratios[nthread, horizon] = ratio
            print(f"{nthread:>7} {horizon:>7} {n_eval / best['raw']:>12,.0f} "
                  f"{n_eval / best['critmoment']:>18,.0f} {ratio:>7.3f}")
    nthread = max(args.threads)
    nominal = np.tile(scenario.box.nominal, (args.samples, 1))
    raw = RawStepper(twin, recording, steps, nominal, nthread=nthread, horizon=1)
    engine = SparseEvaluator(recording, twin, horizon=1, nthread=nthread)
    engine.evaluate(steps[:1], nominal)
    best = best_times({"raw": raw, "critmoment": lambda: engine.evaluate(steps, nominal)},
                      args.repeats)
    print(f"{nthread:>7} {1:>7} {n_eval / best['raw']:>12,.0f} "
          f"{n_eval / best['critmoment']:>18,.0f} {best['raw'] / best['critmoment']:>7.3f}"
          "   (all samples at nominal parameters)")
    print()
    engines = {mode: SparseEvaluator(recording, twin, horizon=1, mode=mode, nthread=nthread)
               for mode in SparseMode}
    results = {}

    def run(mode):
        results[mode] = engines[mode].evaluate(steps, samples)

    for mode in SparseMode:
        run(mode)
    best = best_times({mode: (lambda m=mode: run(m)) for mode in SparseMode}, args.repeats)
    r_step, r_solve = results[SparseMode.STEP], results[SparseMode.SOLVE]
    same = all(np.array_equal(getattr(r_step, f), getattr(r_solve, f), equal_nan=True)
               for f in ("cost", "fos_contact", "fos_grasp", "fos_motor", "object_acc",
                         "actuator_norm", "contact_gripper", "contact_support"))
    t_step, t_solve = best[SparseMode.STEP], best[SparseMode.SOLVE]
    print(f"STEP  (mj_step),    {nthread} threads, horizon 1: {n_eval / t_step:>9,.0f} eval/s")
    print(f"SOLVE (mj_forward), {nthread} threads, horizon 1: {n_eval / t_solve:>9,.0f} eval/s "
          f"({t_step / t_solve:.3f}x STEP's speed); identical results: {same}")
    print()
    key = (2, 1) if (2, 1) in ratios else max(ratios, key=lambda nh: (nh[1] == 1, nh[0]))
    print(f"ratio critmoment/raw: {ratios[key]:.3f}")


if __name__ == "__main__":
    main()
