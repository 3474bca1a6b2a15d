#!/bin/bash
# usage: determinism.sh NAME TRAJ — analyze twice (second via another path spelling), diff report.json without timings
# critmoment must be on PATH; set R24_VENV=/path/to/venv to activate that venv first
if [ -n "${R24_VENV:-}" ]; then . "$R24_VENV/bin/activate"; fi
cd "$(dirname "$0")"
# scratch copies of the two report.json (default: a fresh folder under $TMPDIR or /tmp)
D=$(mktemp -d)
n=$1; t=$2
critmoment analyze $t --scenario v/$n --json --figures none > "$D/det_$n.1.json" 2>/dev/null
critmoment analyze ./$t --scenario ./v/../v/$n/scenario.toml --json --figures none > "$D/det_$n.2.json" 2>/dev/null
python3 - $n "$D" <<'PY'
import json,sys
n,D=sys.argv[1:3]
a,b=[json.load(open(f"{D}/det_{n}.{i}.json")) for i in (1,2)]
for r in (a,b): r.pop("timings",None)
def diff(x,y,p=""):
    if type(x)!=type(y): print("DIFF",p,str(x)[:100],str(y)[:100]); return
    if isinstance(x,dict):
        for k in set(x)|set(y): diff(x.get(k),y.get(k),p+"/"+k)
    elif isinstance(x,list):
        if len(x)!=len(y): print("DIFF len",p); return
        for i,(u,v) in enumerate(zip(x,y)): diff(u,v,f"{p}[{i}]")
    elif x!=y: print("DIFF",p,str(x)[:100],str(y)[:100])
diff(a,b); print(n,"determinism compared; identical" if a==b else "DIFFERENT")
PY
