#!/bin/sh
# Usage (from a robot folder, critmoment venv active): sh ../common/run_validate.sh ROW TRAJ SCENARIO
# writes $OUT/ROW.json (validate --json) and $OUT/ROW.log (stderr + "rc=... wall=...").
OUT=${OUT:-/tmp/r25/robots/out}
mkdir -p "$OUT"
s=$(date +%s)
nice -n 5 critmoment validate "$2" --scenario "$3" --samples 64 --seed 0 --json > "$OUT/$1.json" 2> "$OUT/$1.log"
echo "rc=$? wall=$(( $(date +%s) - s ))" >> "$OUT/$1.log"
