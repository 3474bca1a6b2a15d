#!/bin/bash
# usage: run_analyze_cli.sh SCEN TRAJ TAG [SAMPLES]  -> ana_TAG.json / anaNV_TAG.json (+ rc)   (run from /tmp/r33/fall)
S=$1; T=$2; TAG=$3; N=${4:-64}; P=/work/main/benchmarks/probe_r33/fall
for mode in "" "--no-verify"; do
  o=ana${mode:+NV}_$TAG
  /usr/bin/time -f "%e s" taskset -c 1 $P/cm.sh analyze $T --scenario $S --samples $N --seed 0 --figures none --json $mode > $o.json 2> $o.err
  echo "$o rc=$? $(tail -1 $o.err)"
done
