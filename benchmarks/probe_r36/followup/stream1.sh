#!/bin/bash
# new code, validate only (the independent truths are the probes' recorded JSONs: plain MuJoCo, same samples)
export NOTRUTH=1
cd /tmp/r34/unseen/piper && /tmp/r36f/followup/queue.sh nom.npz piper_ell_edge:ph_edge.toml piper_pyr_edge:ph_pyr_edge.toml
cd /tmp/r34/unseen/aloha2 && /tmp/r36f/followup/queue.sh nom_s2.npz ell_init:ho.toml pyr_init:ho_pyr.toml ell_narrow:ho_narrow.toml pyr_narrow:ho_pyr_narrow.toml
/tmp/r36f/followup/queue.sh v_proper.npz prop_ell_init:ho.toml prop_ell_heavy:ho_heavy.toml prop_pyr_heavy:ho_pyr_heavy.toml
/tmp/r36f/followup/queue_r30.sh orca:s_init:scenario_pcsplit_s.toml:traj_pc.npz orca:e_narrow:scenario_pcsplit_e_narrow.toml:traj_pc.npz orca:s_narrow:scenario_pcsplit_s_narrow.toml:traj_pc.npz gen3:s_init:scenario_s.toml:traj.npz gen3:s_narrow:scenario_s_narrow.toml:traj.npz gen3:e_init:scenario_e.toml:traj.npz gen3:e_narrow:scenario_e_narrow.toml:traj.npz
