#!/bin/bash
# Rebuilds the independent truth (truth.py) into $S (default /tmp/r34/floating/scripts): probe_r33/fall's
# rebuild (probe_r31/tasks/truth.py + truth.patch, and r32's run_validate/run_samples/...), its snapshot
# path changed to /tmp/r34/src, then this probe's truth_r34.patch (records the robot base's tilt and shift,
# information only; the classification is unchanged).
set -e
P=$(cd "$(dirname "$0")" && pwd); S=${S:-/tmp/r34/floating/scripts}
S="$S" /tmp/r34/src/benchmarks/probe_r33/fall/make_scripts.sh
sed -i 's#/tmp/r33/src#/tmp/r34/src#g' "$S"/*.py
patch -s "$S/truth.py" "$P/truth_r34.patch"
echo "truth.py with the r34 base-pose record in $S"
