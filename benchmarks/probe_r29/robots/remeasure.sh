#!/bin/bash
# Re-measure this probe's validate rows on the current code (after the one-sided slip rule),
# 32 samples, seed 0, nthread 1. Needs setup.sh's scenes under /tmp/r29/robots.
# usage: bash remeasure.sh OUTDIR   (then: python summarize.py OUTDIR/*.json)
out=${1:-/tmp/r29/robots/remeasure}; mkdir -p "$out"
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../../.." && pwd)
run() { (cd "/tmp/r29/robots/$1" && PYTHONPATH="$root" /work/venv/bin/python "$here/run_validate.py" "$2" "$3" "$out/$1_${2%.toml}.json" --samples 32 2>/dev/null | tail -1); }
run vs050 scenario_shipped.toml traj.npz
run vs050 scenario_s_narrow.toml traj.npz
run vs050 scenario_p1_init.toml traj.npz
run vs050 scenario_p1_narrow.toml traj.npz
run ur5e scenario_shipped.toml traj.npz
run ur5e scenario_shipped_narrow.toml traj.npz
run ur5e scenario_e10.toml traj.npz
run ur5e scenario_e10_narrow.toml traj.npz
run ur5e scenario_lownom.toml traj.npz
run xarm scenario_box.toml traj_box.npz
run xarm scenario_box_narrow.toml traj_box.npz
run xarm scenario_box_e10.toml traj_box.npz
run xarm scenario_box_e10_heavy.toml traj_box.npz
