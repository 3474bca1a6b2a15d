"""per validate json: samples decided failed by sparse evaluation alone (predicted_failed, not verified by an own run), and how
many of those really succeed; the same for passes. usage: sparse_alone.py DIR"""
import json, pathlib, sys
for f in sorted(pathlib.Path(sys.argv[1]).glob("val_*.json")):
    d = json.load(open(f)); ps = d["per_sample"]
    fa = [p for p in ps if p["predicted_failed"] and not p["verified"]]
    wrong = [p for p in fa if not p["real_failed"]]
    print(f"{f.stem[4:]:16s} nominal_completed={d['nominal_completed']!s:5s} own_runs={d['own_runs']['rollouts']:3d} chained={d['own_runs'].get('chained',0):3d} "
          f"inherited={d['own_runs'].get('inherited',0):3d} sparse-alone fails {len(fa):2d}, wrong {len(wrong)}")
