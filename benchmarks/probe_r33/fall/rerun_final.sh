#!/bin/bash
# The main session's re-run of the probe's validations (verification on and off) on the
# round's final code: a git archive at /tmp/r33/src2. Run from /tmp/r33/fall (its scenes).
# usage: rerun_final.sh > /tmp/r33/rerun/table.txt
P=/work/main/benchmarks/probe_r33/fall
Q=${Q:-/tmp/r33/fall/scripts}   # the patched scripts, rebuilt there by make_scripts.sh (S=... of it)
export PYTHONPATH=/tmp/r33/src2
PY="taskset -c 0 /work/venv/bin/python"
while read -r tag scen traj n; do
  for mode in v nv; do
    extra=""; [ $mode = nv ] && extra="--no-verify"
    line=$($PY $Q/run_validate.py $scen $traj /tmp/r33/rerun/${mode}_$tag.json --samples $n $extra 2>/dev/null | tail -1)
    echo "$tag $mode ${line#* }"
  done
done <<'CASES'
act_catch act.toml act_catch.npz 32
act_setdown act.toml act_setdown.npz 32
act_drop8 act.toml act_drop8_open.npz 32
jaco_l8 jaco_tol.toml j_l8.npz 32
jaco_l4 jaco_tol.toml j_l4.npz 32
jaco_l2 jaco_tol.toml j_l2.npz 32
jaco_l8dy jaco_tol15.toml j_l8dy.npz 32
jshelf_l8 jaco_shelf.toml js_l8.npz 32
jaco_crate jaco_crate.toml j_l8dy.npz 32
o_cyl_lying act_cyl_lying.toml ao_cyl_lying.npz 32
o_sphere act_sphere.toml ao_sphere.npz 32
o_mesh act_mesh.toml ao_mesh.npz 32
o_compound act_compound.toml ao_compound.npz 32
o_shelf act_shelf.toml ao_shelf.npz 32
jo_cyl_stand jo_cyl_stand.toml jo_cyl_stand.npz 32
jo_tall jo_tall.toml jo_tall.npz 32
jo_cyl_lying jo_cyl_lying.toml jo_cyl_lying.npz 32
jo_sphere jo_sphere.toml jo_sphere.npz 32
jo_mesh jo_mesh.toml jo_mesh.npz 32
CASES
