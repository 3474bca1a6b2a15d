#!/bin/bash
# After the first analyze: the independent truth again with --pairs (MuJoCo's own contact mixing, as critmoment's
# twin has it here), then two more analyzes and region checks. Pinned to core 1, one at a time (in /tmp/r37/insertion).
export PYTHONPATH=/tmp/r37/src; P=/work/venv/bin/python; D=/work/main/benchmarks/probe_r37/insertion
while [ ! -f res/an_sock_ell_v0.json ]; do sleep 5; done
while read n t o c; do
  cc=""; [ "$c" = elliptic ] && cc="--cone elliptic --impratio 10"
  taskset -c 1 $P $D/truth.py $t --object $o $cc --pairs --samples res/val_$n.json --out res/truthpairs_$n.json > res/truthpairs_$n.txt 2>&1
  echo "truthpairs_$n done $(date -u +%T)" >> res/queue.log
done <<LIST
peg1_sockmissed peg1_sockmissed.npz peg x
sock_ship sock1.npz socket x
sock_ell_v0 nom_socket.npz socket elliptic
peg1_ship peg1.npz peg x
LIST
taskset -c 1 $P $D/run_analyze.py sock_hold_init.toml sock1.npz res/an_sock_ship.json > res/an_sock_ship.txt 2>&1
echo "an_sock_ship done $(date -u +%T)" >> res/queue.log
taskset -c 1 $P $D/run_analyze.py peg_hold_init_narrow.toml peg1.npz res/an_peg_ship_narrow.json > res/an_peg_ship_narrow.txt 2>&1
echo "an_peg_ship_narrow done $(date -u +%T)" >> res/queue.log
