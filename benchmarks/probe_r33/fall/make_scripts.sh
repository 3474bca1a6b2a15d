#!/bin/bash
# Rebuilds this probe's five scripts that are earlier probes' scripts with small changes
# (kept here as patches: truth.py = probe_r31/tasks/truth.py + a fall rule; make_jaco.py,
# robot_traj.py (+ --loosen), run_validate.py, run_samples.py = probe_r32/robots/'s) into
# $S (default /tmp/r33/fall/scripts). Every command of this README that names
# $P/truth.py, $P/make_jaco.py, $P/robot_traj.py, $P/run_validate.py or $P/run_samples.py
# runs the rebuilt copy: set P=$S for those (or copy them next to the others).
set -e
P=$(cd "$(dirname "$0")" && pwd); B=$P/../..; S=${S:-/tmp/r33/fall/scripts}
mkdir -p "$S"
patch -s -o "$S/truth.py" "$B/probe_r31/tasks/truth.py" "$P/truth.patch"
for f in make_jaco robot_traj run_validate run_samples; do
  patch -s -o "$S/$f.py" "$B/probe_r32/robots/$f.py" "$P/$f.patch"
done
echo "rebuilt into $S"
