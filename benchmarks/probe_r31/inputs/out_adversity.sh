#!/bin/bash
# --out adversity: existing file, under a file, /proc, read-only fs, full fs, foreign folder, FIFO, long name.
CM=/work/main/benchmarks/probe_r31/inputs/cm.sh
W=/tmp/r31/inputs/outw; rm -rf $W; mkdir -p $W; cd $W
T=/tmp/r31/inputs/traj.npz; S=/tmp/r31/inputs/safe
A="analyze $T --scenario $S --samples 8 --figures none"
show() { echo "== $1: rc=$2"; head -c 400 err; echo; }
echo hello > afile; $CM $A --out afile >out 2>err; show "out=existing file" $?; cat afile
$CM $A --out afile/sub >out 2>err; show "out under a file" $?
$CM $A --out /proc/critm >out 2>err; show "out=/proc/critm" $?
$CM $A --out /proc/self >out 2>err; show "out=/proc/self" $?
$CM $A --out /dev/null >out 2>err; show "out=/dev/null" $?
mkfifo ff; $CM $A --out ff >out 2>err; show "out=fifo" $?
mkdir foreign; echo x > foreign/notes.txt; $CM $A --out foreign >out 2>err; show "out=foreign folder" $?; ls -A foreign
mkdir emptyd; $CM $A --out emptyd >out 2>err; show "out=empty existing folder" $?; ls -A emptyd
$CM $A --out "$(printf 'x%.0s' {1..300})" >out 2>err; show "out=name 300 chars" $?
mkdir -p /tmp/r31/inputs/ro; mountpoint -q /tmp/r31/inputs/ro || mount -t tmpfs -o size=1m tmpfs /tmp/r31/inputs/ro
mkdir -p /tmp/r31/inputs/ro/prev; $CM $A --out /tmp/r31/inputs/ro/prev >out 2>err; echo "(seed prev on ro before remount rc=$?)"
mount -o remount,ro /tmp/r31/inputs/ro
$CM $A --out /tmp/r31/inputs/ro/new >out 2>err; show "out on read-only fs (new)" $?
$CM $A --out /tmp/r31/inputs/ro/prev >out 2>err; show "out on read-only fs (replace earlier output)" $?; ls -A /tmp/r31/inputs/ro /tmp/r31/inputs/ro/prev
umount /tmp/r31/inputs/ro
# full fs: 200k tmpfs (report.json ~100 kB + html 7.6 kB; with figures much more)
M=/tmp/r31/inputs/mnt; mountpoint -q $M || mount -t tmpfs -o size=200k tmpfs $M; rm -rf $M/* $M/.[!.]* 2>/dev/null
$CM $A --out $M/o >out 2>err; show "full fs: first (fits?)" $?; ls -A $M; ls -A $M/o 2>/dev/null; df -k $M | tail -1
$CM $A --out $M/o >out 2>err; show "full fs: second into same (needs 2x)" $?; ls -A $M; ls -A $M/o; [ -f $M/o/report.json ] && python3 -c "import json;json.load(open('$M/o/report.json'));print('report.json parses')"
rm -rf $M/* $M/.[!.]* 2>/dev/null
$CM analyze $T --scenario $S --samples 8 --out $M/fig >out 2>err; show "full fs: with figures" $?; ls -A $M; ls -A $M/fig 2>/dev/null
# ulimit -f (EFBIG)
( ulimit -f 50; $CM $A --out $W/flimit >out 2>err ); show "ulimit -f 50" $?; ls -A $W | grep -i flimit
( ulimit -f 50; $CM $A --json > big.json 2>err ); show "ulimit -f 50, --json to file" $?
# stdout to full device
$CM $A --json > /dev/full 2>err; show "--json > /dev/full" $?
$CM $A > /dev/full 2>err; show "text > /dev/full" $?
# stdout closed
$CM $A --json >&- 2>err; show "stdout closed" $?
$CM $A --json 2>err | head -c 10 >/dev/null; show "pipe closed early (PIPESTATUS)" ${PIPESTATUS[0]}
ls -A $W
