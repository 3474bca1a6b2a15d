#!/bin/bash
# --out under adversity, run as root WITHOUT CAP_DAC_OVERRIDE (so chmod applies):
#   bash out_adversity.sh [SCRATCH]    (needs SCRATCH/traj.npz and SCRATCH/cm.sh)
S=${1:-/tmp/r29/api}; cd "$S" || exit 1
NP="setpriv --bounding-set -dac_override,-dac_read_search,-fowner"
A="--samples 32 --figures none"
W=$S/adv; rm -rf "$W"; mkdir -p "$W"; cd "$W"
cp ../traj.npz .
run() { local label=$1; shift; local t0=$(date +%s.%N)
  $NP ../cm.sh "$@" >out.txt 2>err.txt; local rc=$?
  printf '%-58s rc=%s %5.1fs | %s\n' "$label" "$rc" "$(echo "$(date +%s.%N) - $t0" | bc)" "$(grep -m1 'error' err.txt | cut -c1-230)"; }
state() { echo "    $(find "$1" -maxdepth 2 -printf '%p(%m) ' 2>/dev/null | cut -c1-300)"; ls -A "$(dirname "$1")" | grep critmoment-tmp && echo "    ^^ temp left"; }

# 1 parent folder read-only
mkdir ro; chmod 555 ro
run "1 --out ro/rep (parent 555)" analyze traj.npz $A --out ro/rep; state ro
# 2 an earlier output, parent made read-only afterwards
mkdir p2; ../cm.sh analyze traj.npz $A --out p2/rep >/dev/null 2>&1; chmod 555 p2
run "2 --out p2/rep (earlier output, parent 555)" analyze traj.npz $A --out p2/rep; state p2/rep
chmod 755 p2
# 3 an earlier output folder itself 555 (parent writable)
../cm.sh analyze traj.npz $A --out rep3 >/dev/null 2>&1; chmod 555 rep3
run "3 --out rep3 (earlier output folder 555)" analyze traj.npz $A --out rep3; state rep3
chmod 755 rep3 2>/dev/null
# 4 earlier output whose report.json is 444
../cm.sh analyze traj.npz $A --out rep4 >/dev/null 2>&1; chmod 444 rep4/report.json
run "4 --out rep4 (report.json 444)" analyze traj.npz $A --out rep4; state rep4
# 5 symlink --out to a folder in a read-only parent
mkdir ro5; ../cm.sh analyze traj.npz $A --out ro5/real >/dev/null 2>&1; chmod 555 ro5; ln -s ro5/real link5
run "5 --out link5 -> ro5/real (earlier output, 555 parent)" analyze traj.npz $A --out link5; state ro5/real
chmod 755 ro5
# 6 dangling symlink --out
ln -s nowhere/x link6
run "6 --out dangling symlink" analyze traj.npz $A --out link6
# 7 symlink --out pointing at a file
touch afile; ln -s afile link7
run "7 --out symlink to a file" analyze traj.npz $A --out link7
# 8 an output folder holding a subfolder named like a figure
../cm.sh analyze traj.npz $A --out rep8 >/dev/null 2>&1; mkdir rep8/signals.png
run "8 --out rep8 (holds a FOLDER named signals.png)" analyze traj.npz $A --out rep8; state rep8
# 9 an output folder that is a previous 'rollout' output (different command)
../cm.sh rollout traj.npz --out rep9 >/dev/null 2>&1
run "9 analyze --out <a rollout output>" analyze traj.npz $A --out rep9; state rep9
# 10 trajectory inside the output folder (the trajectory is a foreign file)
mkdir rep10; cp traj.npz rep10/
run "10 analyze rep10/traj.npz --out rep10" analyze rep10/traj.npz $A --out rep10
# 11 --out the current folder '.' inside a fresh empty folder
mkdir e11; (cd e11 && $NP ../../cm.sh analyze ../traj.npz $A --out . >../out.txt 2>../err.txt; echo "11 --out . (empty cwd) rc=$? | $(grep -m1 error ../err.txt | cut -c1-200)"; ls -A)
# 12 read-only trajectory folder and read-only cwd for analyze without --out
mkdir ro12; cp traj.npz ro12/; chmod 555 ro12
(cd ro12 && $NP ../../cm.sh analyze traj.npz $A >../out.txt 2>../err.txt; echo "12 analyze in a read-only cwd, no --out rc=$? | $(grep -m1 error ../err.txt | cut -c1-200)")
chmod 755 ro12
# 13 HOME and MPLCONFIGDIR unwritable (a locked-down CI runner)
mkdir -p rohome; chmod 555 rohome
HOME=$W/rohome MPLCONFIGDIR=$W/rohome/mpl run "13 HOME/MPLCONFIGDIR read-only, figures summary" analyze traj.npz --samples 32 --out rep13
echo "    $(grep -m2 -i 'warn\|matplotlib' err.txt | cut -c1-200)"
chmod 755 rohome
