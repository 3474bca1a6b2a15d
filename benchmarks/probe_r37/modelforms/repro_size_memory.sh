#!/bin/bash
# D7: a model whose <size memory="42K"/> arena suffices for the nominal run but not for one sample:
# analyze exits 2 blaming the process ("too little memory or too few threads ... ulimit -v or a
# container's?; lower --samples") though the cause is the MJCF's own arena; at 16K-25K the nominal
# rollout is "simulation diverged ... [mjWARN_CNSTRFULL]" with no word on <size memory>.
set -u
C=/work/main/benchmarks/probe_r37/modelforms/cm.sh
S=/tmp/r37/src/models/panda_pick_place
R=/tmp/r37/modelforms/repro_mem; rm -rf $R; mkdir -p $R; cp $S/panda.xml $R/; cd $R
$C demo --scenario panda_pick_place --seed 0 --out traj.npz > /dev/null
for mem in 20K 42K; do
  sed "s|<visual>|<size memory=\"$mem\"/>\n  <visual>|" $S/scene.xml > scene.xml
  $C init scene.xml --object cube --task pick_place --goal 0.5 0.15 0.02 --out scenario.toml --force > /dev/null 2>&1
  echo "== memory $mem"
  $C analyze traj.npz --scenario scenario.toml --samples 32 --figures none > /dev/null; echo "rc=$?"
done
