#!/bin/bash
# nominal rollout --json of each variant -> /tmp/r32/contact/rollouts.tsv
B=/work/main/benchmarks/probe_r32/contact; R=/tmp/r32/contact
for v in "$@"; do
  t=$R/aloha_s0.npz; [[ $v == p_* ]] && t=$R/panda_s0.npz; [ -f $R/v/$v/traj.npz ] && t=$R/v/$v/traj.npz
  s=$(date +%s.%N)
  $B/cm.sh rollout $t --scenario $R/v/$v --json > $R/v/$v/rollout.json 2> $R/v/$v/rollout.err; rc=$?
  e=$(date +%s.%N)
  line=$(/work/venv/bin/python -c "
import json,sys
try: j=json.load(open('$R/v/$v/rollout.json'))
except Exception as ex: print('NOJSON'); sys.exit()
print(j['completed'], j['max_stage'], round(j['min_fos_contact_sustained'] or -1,3), round(j['max_cost_sustained'] or -1,3), j['shortfalls'], len(j['feasibility_problems']), j['feasibility_problems'][:1])")
  err=$(grep -v '^$' $R/v/$v/rollout.err | head -3 | tr '\n' ' ' | cut -c1-400)
  printf "%s\t%s\t%.1f\t%s\t%s\n" $v $rc $(echo "$e - $s" | bc) "$line" "$err" | tee -a $R/rollouts.tsv
done
