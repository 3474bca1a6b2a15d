#!/bin/bash
cd /tmp/r36/hands/shadow
../queue.sh nom.npz sh_pyr_init:ph.toml 
../queue.sh nom.npz sh_ell_init:ph_ell.toml
for s in ph ph_ell; do ( time ../cm.sh analyze nom.npz --scenario $s.toml --out an_$s --figures none ) > ../res/analyze_$s.txt 2>&1; cp an_$s/report.json ../res/an_${s}_report.json; done
../queue.sh nom.npz sh_pyr_narrow:ph_narrow.toml sh_ell_narrow:ph_ell_narrow.toml
echo ALLDONE
