"""Pre-flight warnings of one code version on many (scenario, trajectory) pairs: the nominal
rollout, preflight (feasibility + fit, incl. the new pre-touch warning) and the contact-model
probe (incl. nominal_creep), as analyze runs them. One JSON line per case.
usage: PYTHONPATH=<src> python warn_scan.py CASES.tsv OUT.jsonl   (CASES: name<TAB>scenario<TAB>traj)"""
import json, sys, time, warnings
import critmoment as cm
from critmoment.recording import at_scenario_rate
from critmoment.trajectory import load_trajectory
from critmoment.recording import rollout
from critmoment.feasibility import preflight
from critmoment import contactmodel

print("critmoment", cm.__file__, file=sys.stderr)
out = open(sys.argv[2], "w")
for line in open(sys.argv[1]):
    if not line.strip() or line.startswith("#"):
        continue
    name, scen, tp = line.rstrip("\n").split("\t")
    row = {"case": name}
    t0 = time.time()
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        try:
            twin = cm.Twin(scen)
            traj = at_scenario_rate(load_trajectory(tp), twin)
            rec = rollout(traj, twin=twin)
            row["completed"] = bool(rec.completed)
            try:
                preflight(traj, rec, twin)
                row["preflight"] = "ok"
            except Exception as e:
                row["preflight"] = f"{type(e).__name__}: {e}"
            try:
                c = contactmodel.check_contact_model(twin, rec)
                row["nominal_creep_mm"] = round(getattr(c, "nominal_creep", float("nan")) * 1e3, 3)
                row["creep_rate_mm_s"] = round(c.creep_rate * 1e3, 3) if c.creep_rate == c.creep_rate else None
                row["soft"] = bool(c.soft)
                row["findings"] = [f.code for f in c.findings]
            except Exception as e:
                row["contact"] = f"{type(e).__name__}: {e}"
        except Exception as e:
            row["error"] = f"{type(e).__name__}: {e}"
    row["warnings"] = sorted({f"{x.category.__name__}: {x.message}" for x in w})
    row["s"] = round(time.time() - t0, 1)
    out.write(json.dumps(row) + "\n"); out.flush()
    print(name, row.get("preflight"), row.get("nominal_creep_mm"), row.get("findings"), len(row["warnings"]), row["s"], file=sys.stderr, flush=True)
