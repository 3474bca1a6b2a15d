#!/bin/bash
# builds summ.py, run_analyze.py and run_validate.py beside this script from probe_r37/robots's
# (the same scripts; only the snapshot and scratch paths differ)
D=$(cd "$(dirname "$0")" && pwd); B=$(cd "$D/../.." && pwd)
for f in summ.py run_analyze.py run_validate.py; do
  sed 's#/tmp/r37/robots/res#/tmp/r38/robots/res#g; s#/tmp/r37/src#/tmp/r38/robots/src#g; s#probe_r37:#probe_r38:#' \
    "$B/probe_r37/robots/$f" > "$D/$f"
done
