"""One audit vs one frequent rollout vs brute-force full rollouts, side by side in one run.

    python benchmarks/bench_analyze.py [--samples 256] [--seed 0] [--threads 0] [--repeat 3]
                                       [--pause 5] [--render-only]

Prints the wall time of (a) one audit's computation (``analysis.analyze``) and, side by side,
the rendering of its report (report.json, figures, report.html; ``report.write_report``) for
each figure set (none, summary: the default, all), (b) one nominal frequent rollout, (c)
brute-force full rollouts of the whole trajectory for the same parameter samples the verdict
uses (batched through ``mujoco.batch``, all threads), and the ratios. The audit and the
brute force run ``--repeat`` times, alternating, and the figures are medians (on a shared
machine one run of either can be 30 % off), each timed run after ``--pause`` seconds of rest
(so that neither starts on cores the other has just loaded for seconds); the per-repeat
ratios are printed too. The
stages of the audit overlap (``analysis.STAGES``). Ends with ``ratio audit/brute-force: R``
(median audit over median brute force). ``--render-only`` stops after the audit/render
table.
"""

import argparse
import statistics
import tempfile
import time
import warnings

import critmoment as cm
from critmoment import analysis, demos, report, sparse
from critmoment.recording import batched_rollouts, initial_state, prepare_controls


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--samples", type=int, default=256)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--chunk", type=int, default=32, help="simulations per brute-force batch")
    parser.add_argument("--repeat", type=int, default=3,
                        help="audit and brute-force runs, alternating (medians are reported)")
    parser.add_argument("--pause", type=float, default=5.0,
                        help="seconds of rest before each timed run")
    parser.add_argument("--render-only", action="store_true",
                        help="only the audit and report rendering times")
    args = parser.parse_args()
    if args.repeat < 1:
        parser.error(f"--repeat: expected >= 1, got {args.repeat}")
    warnings.simplefilter("ignore")

    twin = cm.Twin(cm.load_scenario())
    traj = demos.scripted_transfer(args.seed, twin=twin)
    opts = analysis.AnalyzeOptions(seed=args.seed, n_samples=args.samples, nthread=args.threads)
    analysis.analyze(traj, twin=twin, options=opts)  # warm-up (imports, first batch)

    time.sleep(args.pause)
    t0 = time.perf_counter()
    audit = analysis.analyze(traj, twin=twin, options=opts)
    t_audit = time.perf_counter() - t0
    t_render = {}
    with tempfile.TemporaryDirectory() as tmp:
        for figures in report.Figures:
            t0 = time.perf_counter()
            report.write_report(audit, f"{tmp}/{figures.value}", figures=figures)
            t_render[figures.value] = time.perf_counter() - t0
    print(f"{'audit (analyze) [s]':>24s} {'render ' + ' / '.join(t_render) + ' [s]':>34s} "
          f"{'default render / audit':>24s}")
    print(f"{t_audit:24.3f} {' / '.join(f'{v:.3f}' for v in t_render.values()):>34s} "
          f"{t_render['summary'] / t_audit:24.2f}")
    if args.render_only:
        return

    reps = 5
    t0 = time.perf_counter()
    for _ in range(reps):
        cm.rollout(traj, twin=twin)
    t_rollout = (time.perf_counter() - t0) / reps

    samples = sparse.sweep_samples(twin.scenario.box, n=args.samples, seed=args.seed)
    controls = prepare_controls(twin, traj)
    state0 = initial_state(twin, traj)

    def brute():
        time.sleep(args.pause)
        t0 = time.perf_counter()
        for _ in batched_rollouts(twin, state0, controls, samples, chunk=args.chunk,
                                  nthread=args.threads):
            pass
        return time.perf_counter() - t0

    audits, brutes, stage_runs = [t_audit], [brute()], [audit.timings]
    for _ in range(args.repeat - 1):
        time.sleep(args.pause)
        t0 = time.perf_counter()
        again = analysis.analyze(traj, twin=twin, options=opts)
        audits.append(time.perf_counter() - t0)
        stage_runs.append(again.timings)
        brutes.append(brute())
    t_audit, t_brute = statistics.median(audits), statistics.median(brutes)

    print(f"trajectory: {traj.source}, {controls.shape[0]} physics steps; "
          f"{args.samples} parameter samples; audit verdict {audit.verdict.value}, "
          f"P(success) {audit.p_success:.3f}, {len(audit.moments)} moments, "
          f"horizon {audit.sweep.horizon}; verification: "
          f"{(audit.verification or {}).get('rollouts', 0)} full rollouts")
    print(f"{'what':44s} {'seconds':>10s}")
    print(f"{f'audit computation (analyze), median of {len(audits)}':44s} {t_audit:10.3f}")
    for stage in audit.timings:
        sec = statistics.median(run.get(stage, 0.0) for run in stage_runs)
        print(f"{'  ' + stage:44s} {sec:10.3f}")
    for figures, sec in t_render.items():
        print(f"{f'report rendering, figures {figures}':44s} {sec:10.3f}")
    print(f"{'one frequent rollout (nominal)':44s} {t_rollout:10.3f}")
    print(f"{f'brute force: {args.samples} full rollouts, median':44s} {t_brute:10.3f}")
    print(f"audit / frequent rollout: {t_audit / t_rollout:.2f} rollouts")
    print(f"brute force / audit: {t_brute / t_audit:.1f}x")
    print("per repeat (audit s / brute force s = ratio): " + "; ".join(
        f"{a:.2f} / {b:.2f} = {a / b:.3f}" for a, b in zip(audits, brutes, strict=True)))
    print(f"ratio audit/brute-force: {t_audit / t_brute:.4f}")


if __name__ == "__main__":
    main()
