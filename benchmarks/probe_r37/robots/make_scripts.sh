#!/bin/bash
# Rebuilds the scripts this probe takes from earlier probes of this project into $S (default /tmp/r37/robots/scripts):
#   truth.py        = probe_r31/tasks/truth.py + probe_r33/fall/truth.patch (the independent plain-MuJoCo truth with
#                     r33's fall rule; as probe_r36/hands/make_scripts.sh builds it), snapshot path -> /tmp/r37/src,
#                     snapshot assert at import
#   run_validate.py = probe_r32/robots/run_validate.py (validate as the CLI does it, nthread=1), path -> /tmp/r37/src
set -e
B=/tmp/r37/src/benchmarks; S=${S:-/tmp/r37/robots/scripts}
mkdir -p "$S"
patch -s -o "$S/truth.py" "$B/probe_r31/tasks/truth.py" "$B/probe_r33/fall/truth.patch"
sed -i 's#/tmp/r33/src#/tmp/r37/src#g; s#/tmp/r31/src#/tmp/r37/src#g' "$S/truth.py"
python3 - "$S/truth.py" <<'PY'
import sys
p = sys.argv[1]; s = open(p).read()
s = s.replace('import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r37/src"), _cm_check.__file__  # r33 snapshot\n', '', 1)
s = s.replace('import mujoco\nimport numpy as np\n', 'import mujoco\nimport numpy as np\nimport critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r37/src"), _cm_check.__file__  # r37 snapshot\n', 1)
open(p, 'w').write(s)
PY
grep -c '/tmp/r37/src' "$S/truth.py"
sed 's#/tmp/r32/src#/tmp/r37/src#g' "$B/probe_r32/robots/run_validate.py" > "$S/run_validate.py"
grep -c '/tmp/r37/src' "$S/run_validate.py"
echo "rebuilt into $S"
