#!/bin/sh
# Every shell command of README.md, docs/tutorial.md, docs/byo_robot.md and docs/cli.md, run as written
# in a fresh scratch folder ($1, default /tmp/r25/docs_api/a_cli). Only machine-specific paths are
# replaced: path/to/scene.xml, scene.xml, act_scene.xml -> the bundled models' scene.xml.
# Each command's stdout/stderr go to NN.out / NN.err, its exit code to rc.tsv.
D=${1:-/tmp/r25/docs_api/a_cli}
rm -rf "$D"; mkdir -p "$D"; cd "$D" || exit 1
M=$(python -c "import critmoment.models, os; print(os.path.dirname(critmoment.models.__file__))")
cp "$M/panda_pick_place/"*.xml . ; mkdir act; cp "$M/aloha_transfer_cube/"*.xml act/; mv act/scene.xml act/act_scene.xml
n=0
run() { n=$((n+1)); nn=$(printf %02d $n); sh -c "$1" > $nn.out 2> $nn.err; rc=$?; printf '%s\t%s\t%s\n' "$nn" "$rc" "$1" >> rc.tsv; }
# README
run 'critmoment demo --seed 0 --out traj.npz && critmoment analyze traj.npz --out report; echo "exit code $? (0 safe, 1 not safe over the whole box, 2 error)"'
run 'critmoment demo --scenario panda_pick_place --out panda.npz && critmoment analyze panda.npz'
run 'critmoment inspect scene.xml'
run 'critmoment init scene.xml --object cube --task pick_place --goal 0.5 0.2 0.02 --out scenario.toml'
# tutorial 1
run 'critmoment rollout traj.npz'
run 'critmoment analyze traj.npz --min-success 0.9 || echo "do not run this on the robot"'
# byo_robot
run 'critmoment inspect scene.xml --json'
run 'cd act && critmoment init act_scene.xml --object box --task handover --out scenario.toml'
run 'critmoment demo --scenario panda_pick_place --seed 0 --out ptraj.npz && critmoment rollout ptraj.npz --scenario scenario.toml'
run 'critmoment analyze ptraj.npz --scenario scenario.toml --out preport'
run 'critmoment validate ptraj.npz --scenario scenario.toml --samples 32'
run 'cd act && critmoment rollout ../traj.npz --scenario scenario.toml'
# cli.md
run 'critmoment analyze traj.npz --json | head -1; echo "PIPESTATUS-like: see rc"'
run 'set -o pipefail 2>/dev/null; bash -c "critmoment analyze traj.npz --json | head -1; echo \${PIPESTATUS[0]}"'
run 'critmoment moments traj.npz --json'
run 'critmoment rollout traj.npz --json'
run 'critmoment validate traj.npz --samples 32 --json'
run 'critmoment episodes traj.npz --json'
run 'critmoment analyze traj.npz --seed -1'
run 'critmoment validate traj.npz --samples 1e1 --json'
run 'critmoment analyze traj.npz --samples 1e9'
run 'critmoment init scene.xml --object cube --task pick_place --goal 0.5 0.2 0.02 --out scenario.toml'
run 'mkdir -p nodir_test; critmoment init scene.xml --object cube --task pick_place --goal 0.5 0.2 0.02 --out nodir/'
run 'critmoment rollout traj.npz --out rol && ls -A rol'
run 'critmoment moments traj.npz --out mom && ls -A mom'
run 'critmoment validate traj.npz --samples 16 --out val && ls -A val'
run 'critmoment analyze traj.npz --figures all --samples 32 --out repall && ls -A repall'
run 'critmoment analyze traj.npz --figures none --samples 32 --out repnone && ls -A repnone'
cat rc.tsv
