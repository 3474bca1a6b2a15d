#!/bin/bash
# Rebuilds the scripts this probe took from earlier probes into $S (default /tmp/r34/unseen/scripts):
#   truth.py   = probe_r31/tasks/truth.py + probe_r33/fall/truth.patch (the independent plain-MuJoCo
#                truth with r33's fall rule), snapshot path -> /tmp/r34/src, and the snapshot assert
#                moved out of the docstring (in r33's patch it sits inside it and never runs)
#   run_validate.py         = probe_r32/robots/run_validate.py, snapshot path -> /tmp/r34/src
set -e
P=$(cd "$(dirname "$0")" && pwd); B=/tmp/r34/src/benchmarks; S=${S:-/tmp/r34/unseen/scripts}
mkdir -p "$S"
patch -s -o "$S/truth.py" "$B/probe_r31/tasks/truth.py" "$B/probe_r33/fall/truth.patch"
sed -i 's#/tmp/r33/src#/tmp/r34/src#g' "$S/truth.py"
python3 - "$S/truth.py" <<'PY'
import sys
p = sys.argv[1]; s = open(p).read()
s = s.replace('import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r34/src"), _cm_check.__file__  # r33 snapshot\n', '', 1)
s = s.replace('import mujoco\nimport numpy as np\n', 'import mujoco\nimport numpy as np\nimport critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r34/src"), _cm_check.__file__  # r34 snapshot\n', 1)
open(p, 'w').write(s)
PY
sed 's#/tmp/r32/src#/tmp/r34/src#g' "$B/probe_r32/robots/run_validate.py" > "$S/run_validate.py"
echo "rebuilt into $S"
