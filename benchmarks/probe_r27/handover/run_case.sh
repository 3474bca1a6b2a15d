#!/bin/sh
# One row: analyze then validate (64 samples, seed 0) of TRAJ under SCENARIO, niced.
# Writes $OUT/ROW.an.out (analyze stdout+stderr), $OUT/ROW.an.json (report.json copy),
# $OUT/ROW.json (validate --json), $OUT/ROW.log (rc and wall seconds of each).
# Usage (critmoment venv active): sh run_case.sh ROW TRAJ SCENARIO   [OUT default ./out]
set -u
ROW=$1; TRAJ=$2; SC=$3; OUT=${OUT:-out}
mkdir -p "$OUT"
t0=$(date +%s)
nice -n 10 critmoment analyze "$TRAJ" --scenario "$SC" --out "$OUT/rep_$ROW" --figures none \
    > "$OUT/$ROW.an.out" 2>&1
rc1=$?; t1=$(date +%s)
cp "$OUT/rep_$ROW/report.json" "$OUT/$ROW.an.json" 2>/dev/null
nice -n 10 critmoment validate "$TRAJ" --scenario "$SC" --samples 64 --seed 0 --json \
    > "$OUT/$ROW.json" 2> "$OUT/$ROW.val.err"
rc2=$?; t2=$(date +%s)
echo "analyze rc=$rc1 wall=$((t1 - t0))s; validate rc=$rc2 wall=$((t2 - t1))s" | tee "$OUT/$ROW.log"
