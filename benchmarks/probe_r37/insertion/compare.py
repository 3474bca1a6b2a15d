"""Compare critmoment's validate (its brute force `cm_real_ok`, its prediction `cm_pred_ok`) with the
independent insertion truth (truth.py), sample by sample. usage: compare.py truth_NAME.json ..."""
import json
import sys
from collections import Counter

for p in sys.argv[1:]:
    r = json.load(open(p))
    n = len(r)
    ts = sum(x["success"] for x in r)
    c = Counter()
    for x in r:
        t, pr, re = x["success"], x["cm_pred_ok"], x["cm_real_ok"]
        c["pred_safe_truth_fail"] += pr and not t      # false safe against the insertion truth
        c["pred_fail_truth_ok"] += (not pr) and t      # false unsafe against the insertion truth
        c["cmreal_ok_truth_fail"] += re and not t
        c["cmreal_fail_truth_ok"] += (not re) and t
    agree = sum(x["success"] == x["cm_pred_ok"] for x in r) / n
    print(f"{p}: n={n} truth successes {ts} failures {n - ts}; cm brute-force successes "
          f"{sum(x['cm_real_ok'] for x in r)}; vs truth: {dict(c)}; agreement(pred vs truth) {agree:.3f}")
    for x in r:
        if x["success"] != x["cm_pred_ok"] or x["success"] != x["cm_real_ok"]:
            v = {k: round(val, 3) for k, val in x["values"].items()}
            print(f"   #{x['i']} {v} cm: {x['cm_outcome']} pred_ok={x['cm_pred_ok']} | truth ok={x['success']} "
                  f"reward end/max {x['reward_end']}/{x['reward_max']} L holds {x['left_holds_end']} "
                  f"R holds {x['right_holds_end']} peg-table {x['peg_table_end']} sock-table {x['socket_table_end']} "
                  f"peg-socket {x['peg_minus_socket_end']}")
