#!/bin/bash
# Rebuilds this probe's scripts that are earlier probes' with small changes (kept here as
# patches: truth.py on probe_r31/tasks/truth.py, trace.py on ../fall/trace.py,
# run_validate.py on probe_r32/robots/run_validate.py) into $S (default
# /tmp/r33/clutter/scripts); run_case.sh takes them from there ($Q).
set -e
P=$(cd "$(dirname "$0")" && pwd); B=$P/../..; S=${S:-/tmp/r33/clutter/scripts}
mkdir -p "$S"
patch -s -o "$S/truth.py" "$B/probe_r31/tasks/truth.py" "$P/truth.patch"
patch -s -o "$S/trace.py" "$P/../fall/trace.py" "$P/trace.patch"
patch -s -o "$S/run_validate.py" "$B/probe_r32/robots/run_validate.py" "$P/run_validate.patch"
echo "rebuilt into $S"
