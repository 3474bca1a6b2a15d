"""One line per row from run_case.sh's outputs: verdict, P, region, real outcomes, false safes
and unsafes, agreement, timings; then each disagreeing sample.

Usage: python summarize.py ROW [ROW ...]   (reads out/ROW.json and out/ROW.an.json)
"""
import json
import sys

for row in sys.argv[1:]:
    with open(f"out/{row}.json") as f:
        v = json.load(f)
    with open(f"out/{row}.an.json") as f:
        r = json.load(f)
    c = v["confusion"]
    o = v["outcomes"]
    succ = o["success"]
    fail = sum(o.values()) - succ
    print(f"{row}: verdict {r['verdict']} P {r['p_success']:.3f} "
          f"region {r['safe_region_text']!r} | real {succ}/{fail} {o} | "
          f"FS {c['false_safe']} FU {c['false_unsafe']} agreement {v['agreement']:.3f} "
          f"vacuous {v['vacuous']} | validate {v['timings']} | "
          f"analyze stages {sum(r['timings'].values()):.0f} s")
    for s in v["per_sample"]:
        if s["real_failed"] != s["predicted_failed"]:
            print("   ", "FS" if s["real_failed"] else "FU", s)
