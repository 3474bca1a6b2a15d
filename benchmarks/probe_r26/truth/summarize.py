"""Per-case table from /tmp/r26/truth/res_*.json and val_*.json (run after rerun_all.sh)."""
import json
import sys
from collections import Counter
from pathlib import Path

D = Path("/tmp/r26/truth")
CASES = ["aloha15_s0", "aloha15_s7", "panda_s0", "panda_gear20", "panda_offset",
         "panda_offg20_noq", "panda_hold", "aloha15_pyr_s0", "aloha15_pyr_s7", "panda_pyr"]


def fmt(c):
    return ", ".join(f"{k.lower()} {v}" for k, v in sorted(c.items()))


def fam(o):
    return {"SLIPPED": "GRIP", "DROPPED": "GRIP"}.get(o.upper(), o.upper())


def main():
    for name in CASES:
        for suffix in ("", "_zoh"):
            p = D / f"res_{name}{suffix}.json"
            if not p.exists():
                continue
            r = json.load(open(p))
            v = json.load(open(D / f"val_{name}.json"))
            rows = r["rows"]
            mine = Counter(x["mine"] for x in rows)
            cm = Counter(x["cm_outcome"].upper() for x in rows)
            pf = [x for x in rows if not x["agree_fail"]]
            # grip loss family: SLIPPED and DROPPED are both "the grip lost the object"
            lab = [x for x in rows if x["agree_fail"] and fam(x["mine"]) != fam(x["cm_outcome"])]
            print(f"| {name}{' (own zero-order hold)' if suffix else ''} | {len(rows)} | "
                  f"{r['nominal'][0].lower()} | {fmt(mine)} | {fmt(cm)} | "
                  f"{v['confusion']['false_safe']}/{v['confusion']['false_unsafe']} | "
                  f"{len(pf)} {[x['i'] for x in pf]} | {len(lab)} {[x['i'] for x in lab]} |")


if __name__ == "__main__":
    sys.exit(main())
