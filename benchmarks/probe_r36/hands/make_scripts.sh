#!/bin/bash
# Rebuilds the scripts this probe takes from earlier probes into $S (default /tmp/r36/hands/scripts):
#   truth.py        = probe_r31/tasks/truth.py + probe_r33/fall/truth.patch (the independent plain-MuJoCo
#                     truth with r33's fall rule), snapshot path -> /tmp/r36/src, snapshot assert at import
#                     (as probe_r35/robots/make_scripts.sh does)
#   run_validate.py = probe_r32/robots/run_validate.py (validate as the CLI does it, nthread=1), path -> /tmp/r36/src
set -e
B=/tmp/r36/src/benchmarks; S=${S:-/tmp/r36/hands/scripts}
mkdir -p "$S"
patch -s -o "$S/truth.py" "$B/probe_r31/tasks/truth.py" "$B/probe_r33/fall/truth.patch"
sed -i 's#/tmp/r33/src#/tmp/r36/src#g' "$S/truth.py"
python3 - "$S/truth.py" <<'PY'
import sys
p = sys.argv[1]; s = open(p).read()
s = s.replace('import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r36/src"), _cm_check.__file__  # r33 snapshot\n', '', 1)
s = s.replace('import mujoco\nimport numpy as np\n', 'import mujoco\nimport numpy as np\nimport critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r36/src"), _cm_check.__file__  # r36 snapshot\n', 1)
open(p, 'w').write(s)
PY
grep -c '/tmp/r36/src' "$S/truth.py"
sed 's#/tmp/r32/src#/tmp/r36/src#g' "$B/probe_r32/robots/run_validate.py" > "$S/run_validate.py"
grep -c '/tmp/r36/src' "$S/run_validate.py"
echo "rebuilt into $S"
