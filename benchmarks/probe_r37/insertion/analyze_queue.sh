#!/bin/bash
# analyze (256 samples, seed 0, nthread=1) for each case, one after another, pinned to core 1 (in /tmp/r37/insertion)
export PYTHONPATH=/tmp/r37/src; P=/work/venv/bin/python; D=/work/main/benchmarks/probe_r37/insertion
# the peg audit whose left arm misses the socket (move_socket.py peg1.npz peg1_sockmissed.npz 0 0.06)
$D/queue.sh peg1_sockmissed peg_hold_init.toml peg1_sockmissed.npz peg x noanalyze
while read n s t; do
  taskset -c 1 $P $D/run_analyze.py $s $t res/an_$n.json > res/an_$n.txt 2>&1
  echo "an_$n done $(date -u +%T)" >> res/queue.log
done <<LIST
sock_ell_v0 sock_hold_ell.toml nom_socket.npz
sock_ship sock_hold_init.toml sock1.npz
peg1_ship peg_hold_init.toml peg1.npz
sock_ell sock_hold_ell.toml sock1.npz
peg_ell peg_hold_ell.toml peg1.npz
sock_ship_narrow sock_hold_init_narrow.toml sock1.npz
peg_ship_narrow peg_hold_init_narrow.toml peg1.npz
sock_ell_narrow sock_hold_ell_narrow.toml sock1.npz
peg_ell_narrow peg_hold_ell_narrow.toml peg1.npz
LIST
echo ANALYZE_DONE >> res/queue.log
