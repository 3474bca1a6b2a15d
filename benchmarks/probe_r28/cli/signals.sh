#!/bin/bash
# SIGINT/SIGTERM an analyze at several delays; check exit code and --out state.
export PATH=/tmp/r28/cli/venv/bin:$PATH; T=/tmp/r28/cli/readme/traj.npz
W=/tmp/r28/cli/sig; rm -rf $W; mkdir -p $W; cd $W
for sig in INT TERM; do for d in 1 3 6 10; do
  rm -rf o .o.*; critmoment analyze $T --out o > so.txt 2> se.txt & pid=$!
  sleep $d; kill -$sig $pid; wait $pid; rc=$?
  state=$(ls -A . | grep -v '^s[oe].txt$' | tr '\n' ' ')
  files=$( [ -d o ] && ls -A o | tr '\n' ' ')
  echo "SIG$sig after ${d}s: rc=$rc dir: [$state] o: [$files] stderr: $(tail -c 300 se.txt | tr '\n' '|')"
done; done
# with an earlier output present: it must stay as it was
rm -rf o; critmoment rollout $T --out o >/dev/null 2>&1; before=$(cd o && sha256sum * | sha256sum)
critmoment analyze $T --out o > so.txt 2> se.txt & pid=$!; sleep 8; kill -INT $pid; wait $pid; rc=$?
after=$(cd o && sha256sum * | sha256sum); echo "prev output kept: rc=$rc same=$([ "$before" = "$after" ] && echo yes || echo NO) files: $(ls -A o | tr '\n' ' ') leftovers: $(ls -A | grep critmoment-tmp)"
