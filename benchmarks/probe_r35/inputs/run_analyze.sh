#!/bin/bash
# analyze --json of the same actions from npz, LeRobot (float64 list, v3.0 float32, v2.1) and ACT HDF5
# run from /tmp/r35/inputs; outputs in results/an_*.json
C=/work/main/benchmarks/probe_r35/inputs/cm.sh
POSE=$(/work/venv/bin/python -c "import numpy as np; print(' '.join(repr(float(x)) for x in np.load('traj.npz')['object_pose']))")
run() { name=$1; shift; /usr/bin/time -f "%e s" $C analyze "$@" --samples 16 --figures none --json > results/an_$name.json 2> results/an_$name.err; echo "$name rc=$?"; }
run npz traj.npz
run lr_f64 lr_f64_list --object-pose $POSE
run act act.hdf5 --object-pose $POSE
run lr_v30 lr_v30 --episode 1 --object-pose $POSE
run npz_pose traj.npz --object-pose $POSE
