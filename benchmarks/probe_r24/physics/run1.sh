#!/bin/bash
# usage: run1.sh VARIANT_DIR TRAJ [extra validate args]
# runs analyze and validate -n 64 on the scenario in VARIANT_DIR; appends to results.tsv
# critmoment must be on PATH; set R24_VENV=/path/to/venv to activate that venv first
if [ -n "${R24_VENV:-}" ]; then . "$R24_VENV/bin/activate"; fi
V=$1; T=$2; shift 2
cd "$(dirname "$0")"   # V and TRAJ are relative to this folder
t0=$(date +%s.%N)
critmoment analyze $T --scenario $V --out $V/report --json --figures none > $V/analyze.json 2> $V/analyze.err
ra=$?
t1=$(date +%s.%N)
critmoment validate $T --scenario $V --samples 64 --json "$@" > $V/validate.json 2> $V/validate.err
rv=$?
t2=$(date +%s.%N)
python - "$V" "$T" $ra $rv $t0 $t1 $t2 <<'PY' >> results.tsv
import json,sys
V,T,ra,rv,t0,t1,t2=sys.argv[1:]
def load(p):
    try: return json.load(open(p))
    except Exception: return None
a=load(f"{V}/analyze.json") or {}
v=load(f"{V}/validate.json") or {}
c=v.get("confusion",{})
sr=a.get("safe_region_text","")
print("\t".join(map(str,[V,T,a.get("verdict"),a.get("p_success"),ra,round(float(t1)-float(t0),1),
  c.get("false_safe"),c.get("false_unsafe"),c.get("true_safe"),c.get("true_unsafe"),v.get("agreement"),v.get("vacuous"),rv,round(float(t2)-float(t1),1),sr])))
PY
tail -1 results.tsv
