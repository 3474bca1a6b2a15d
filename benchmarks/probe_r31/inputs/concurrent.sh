#!/bin/bash
# two analyses (different verdicts) into one --out at once; then same seed twice -> identical report.json but timings
CM=/work/main/benchmarks/probe_r31/inputs/cm.sh
W=/tmp/r31/inputs/conc; rm -rf $W; mkdir -p $W; cd $W
T=/tmp/r31/inputs/traj.npz
$CM analyze $T --scenario /tmp/r31/inputs/safe --samples 8 --figures summary --out shared > a.out 2> a.err & pa=$!
$CM analyze $T --samples 8 --figures none --out shared > b.out 2> b.err & pb=$!
wait $pa; ra=$?; wait $pb; rb=$?
echo "safe run rc=$ra, unsafe run rc=$rb"; tail -1 a.err b.err
ls -A; ls -A shared; cat shared/.critmoment-output.json; echo
python3 - <<'P'
import json, os
d = "/tmp/r31/inputs/conc/shared"; r = json.load(open(f"{d}/report.json")); m = json.load(open(f"{d}/.critmoment-output.json"))
print("verdict in report.json:", r.get("verdict"), "| files listed in marker:", m, "| files present:", sorted(os.listdir(d)))
html = open(f"{d}/report.html").read(); print("html mentions SAFE/UNSAFE/CONDITIONAL:", [w for w in ("UNSAFE", "CONDITIONAL", ">SAFE") if w in html])
P
