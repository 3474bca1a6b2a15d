#!/bin/bash
# batch_gt.sh: old vs new ground truth on every earlier-round trajectory (n random + corners + nominal)
F=/work/main/benchmarks/probe_r30/followup; S=/tmp/r30/followup/gt; mkdir -p $S
N=${N:-16}
scen() { # gen dir, case -> scenario
  local g=$1 c=$2
  case $c in
    P_shelf6*) echo $g/shelf6;; P_shelf10*) echo $g/shelf10;; P_bin*) echo $g/bin;; P_hold*) echo $g/hold;;
    P_stack*) echo $g/stack;; P_*) echo /tmp/r30b/src/models/panda_pick_place;; A_*) echo $g/aloha_m15;;
  esac; }
for g in /tmp/r29c/gen /tmp/r30/tasks/gen; do
  tag=$(basename $(dirname $g))
  for f in $g/*.npz; do c=$(basename $f .npz); sc=$(scen $g $c)
    for v in old:r30 new:r30b; do n=${v%%:*}; d=${v##*:}
      out=$S/${tag}_${c}_$n.json; [ -s $out ] && continue
      (cd $g && PYTHONPATH=/tmp/$d/src timeout 600 /work/venv/bin/python $F/gt.py /tmp/$d/src $sc $f $out --n $N > $S/${tag}_${c}_$n.log 2>&1) || echo "FAIL $c $n"
    done
    /work/venv/bin/python $F/cmpgt.py $S/${tag}_${c}_old.json $S/${tag}_${c}_new.json
  done
done
