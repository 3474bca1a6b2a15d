#!/bin/bash
# nominal rollout of every variant: rollouts.tsv (variant, rc, completed, final_stage, max_cost_sustained, secs, stderr tail)
cd /tmp/r29/physics
CM=/work/main/benchmarks/probe_r29/physics/cm.sh
for v in ${@:-$(ls v)}; do
  case $v in a_*) tr=aloha_s0.npz;; *) tr=panda_s0.npz;; esac
  [ -f v/$v/traj.npz ] && tr=v/$v/traj.npz
  s=$(date +%s.%N)
  $CM rollout $tr --scenario v/$v --json > v/$v/rollout.json 2> v/$v/rollout.err; rc=$?
  e=$(echo "$(date +%s.%N) - $s" | bc)
  /work/venv/bin/python - "$v" "$rc" "$e" <<'PY'
import json,sys
v,rc,e=sys.argv[1:]
try: d=json.load(open(f"v/{v}/rollout.json"))
except Exception: d={}
err=open(f"v/{v}/rollout.err").read().strip().replace("\n"," | ")[:300]
print(v,rc,d.get("completed"),d.get("final_stage"),d.get("max_cost_sustained"),d.get("min_fos_contact_sustained"),f"{float(e):.1f}s",err,sep="\t",flush=True)
PY
done
