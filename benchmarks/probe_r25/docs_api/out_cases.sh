#!/bin/bash
# --out behaviour, exit codes, concurrency, --json on stdout, determinism. $1: scratch dir, $2: traj.npz
D=$1; T=$(realpath "$2"); rm -rf "$D"; mkdir -p "$D"; cd "$D" || exit 1
A="critmoment analyze $T --samples 32 --figures none"
r() { echo "### $1"; shift; "$@" > o.txt 2> e.txt; echo "rc=$?"; head -c 300 e.txt; echo; }
mkdir old; echo x > old/report.json; echo y > old/notes.txt
r "out dir with foreign file" $A --out old; ls -A old
mkdir old2; echo x > old2/report.json
r "out dir holding only an old (corrupt) report.json" $A --out old2; ls -A old2; python -c "import json;json.load(open('old2/report.json'));print('parses')"
echo f > afile; r "out is a file" $A --out afile
r "out under a file" $A --out afile/sub
mkdir ro; chmod 555 ro; r "read-only parent (root ignores modes?)" $A --out ro/rep; id -u
r "path with spaces+unicode" $A --out "dir with spaces/ré port ü"; ls -A "dir with spaces/ré port ü"
cp "$T" "t r ä.npz"; r "traj path with spaces/unicode" critmoment analyze "t r ä.npz" --samples 32 --figures none --json
python -c "import json;d=json.load(open('o.txt'));print('stdout json ok, trajectory=',d['manifest']['trajectory'])"
# SAFE exit 0: narrow box scenario copy
M=$(python -c "import critmoment.models,os;print(os.path.dirname(critmoment.models.__file__))")
cp -r "$M/aloha_transfer_cube" sc; python - <<'P'
import re
t=open('sc/scenario.toml').read()
i=t.index('[uncertainty.mass]'); j=t.index('range',i); k=t.index('\n',j)
t=t[:j]+'range = [0.05, 0.2]'+t[k:]
i=t.index('[uncertainty.friction]'); j=t.index('range',i); k=t.index('\n',j)
t=t[:j]+'range = [0.5, 1.5]'+t[k:]
open('sc/scenario.toml','w').write(t)
P
r "SAFE (narrow box) exit 0?" $A --scenario sc; head -1 o.txt
r "CONDITIONAL with --min-success 0.01 exit 0?" $A --min-success 0.01; head -1 o.txt
r "CONDITIONAL with --min-success 1 exit 1?" $A --min-success 1
r "UNSAFE (no_grasp) exit 1?" bash -c "critmoment demo --seed 0 --family no_grasp --out ng.npz >/dev/null && critmoment analyze ng.npz --samples 32 --figures none"; head -1 o.txt
r "missing traj exit 2" critmoment analyze nope.npz
# --json with warnings: npz without object_pose
python -c "
import numpy as np; d=dict(np.load('$T')); d.pop('object_pose',None); d['bogus']=np.zeros(1); np.savez('nopose.npz',**d)"
r "--json + warnings (no object_pose, unknown key)" critmoment analyze nopose.npz --samples 32 --figures none --json
python -c "import json;json.load(open('o.txt'));print('stdout is one JSON document')"; grep -c warning e.txt
# determinism
$A --seed 5 --json > d1.json 2>/dev/null; (cd /tmp && $A --seed 5 --json > "$D/d2.json" 2>/dev/null)
python -c "
import json;a,b=[json.load(open(f)) for f in ('d1.json','d2.json')]
[x.pop('timings') for x in (a,b)];print('determinism: identical apart from timings:',a==b)"
# concurrent writers to one --out
( $A --seed 1 --out same > c1.txt 2>&1; echo "w1 rc=$?" ) & ( $A --seed 2 --out same > c2.txt 2>&1; echo "w2 rc=$?" ) & wait
python -c "
import json;d=json.load(open('same/report.json'));h=open('same/report.html').read();print('concurrent: seed in report', d['manifest']['seed'], 'html complete', h.rstrip().endswith('</html>'))"; ls -A same; ls -A | grep tmp
