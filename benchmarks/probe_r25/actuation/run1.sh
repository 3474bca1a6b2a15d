#!/bin/bash
# usage: run1.sh NAME [TRAJ]   (from this folder; critmoment on PATH or R25_VENV set)
# analyze (--json --figures none) and validate --samples 32 --json on v/NAME; outputs under
# $R25_OUT (default /tmp/r25/actuation/out/NAME); one row appended to results.tsv:
# variant model verdict exit P real_succ real_fail FS FU agreement validate_exit analyze_s validate_s
if [ -n "${R25_VENV:-}" ]; then . "$R25_VENV/bin/activate"; fi
cd "$(dirname "$0")"
N=$1; V=v/$N
case $N in a_*|base_aloha) T=${2:-/tmp/r25/actuation/aloha_s0.npz}; MODEL=aloha;; *) T=${2:-/tmp/r25/actuation/panda_s0.npz}; MODEL=panda;; esac
O=${R25_OUT:-/tmp/r25/actuation/out}/$N; mkdir -p "$O"
t0=$(date +%s.%N)
nice -n 5 critmoment analyze "$T" --scenario $V --out "$O/report" --json --figures none > "$O/analyze.json" 2> "$O/analyze.err"
ra=$?
t1=$(date +%s.%N)
nice -n 5 critmoment validate "$T" --scenario $V --samples 32 --json > "$O/validate.json" 2> "$O/validate.err"
rv=$?
t2=$(date +%s.%N)
python - "$N" "$MODEL" "$O" $ra $rv $t0 $t1 $t2 <<'PY' >> results.tsv
import json, sys
N, MODEL, O, ra, rv, t0, t1, t2 = sys.argv[1:]
def load(p):
    try:
        return json.load(open(p))
    except Exception:
        return None
a = load(f"{O}/analyze.json") or {}
v = load(f"{O}/validate.json") or {}
c = v.get("confusion", {})
ts, tu, fs, fu = (c.get(k) for k in ("true_safe", "true_unsafe", "false_safe", "false_unsafe"))
succ = None if ts is None else ts + fu
fail = None if ts is None else tu + fs
print("\t".join(map(str, [N, MODEL, a.get("verdict"), ra, a.get("p_success"), succ, fail, fs, fu,
                          v.get("agreement"), rv, round(float(t1) - float(t0), 1), round(float(t2) - float(t1), 1)])))
PY
tail -1 results.tsv
