"""Bad-input cases: each writes a scenario and runs `critmoment rollout` on it (the scenario loads first)."""
import subprocess
import sys
from pathlib import Path

from make_scenarios import base

HERE = Path(__file__).parent
PANDA = base("panda_pick_place")
MOD = PANDA.replace('/tmp/r28/src/models/panda_pick_place/scene.xml', str(HERE / "mod_panda/scene.xml"))
ALOHA = base("aloha_transfer_cube")
def T(name, kind, key, target, rng, nom, prior="uniform", extra=""):
    return f"[uncertainty.{name}]\nkind = \"{kind}\"\n{key} = \"{target}\"\nrange = {rng}\nnominal = {nom}\nprior = \"{prior}\"\n{extra}\n"
CASES = {
 # com_offset
 "com_outside_cube": (PANDA, T("com", "com_offset", "body", "cube", "[-0.03, 0.03]", 0.0)),
 "com_far_outside": (PANDA, T("com", "com_offset", "body", "cube", "[0.05, 0.06]", 0.055)),
 "com_mm": (PANDA, T("com", "com_offset", "body", "cube", "[-5.0, 5.0]", 0.0)),
 "com_nan": (PANDA, T("com", "com_offset", "body", "cube", "[nan, 0.01]", 0.0)),
 "com_inf": (PANDA, T("com", "com_offset", "body", "cube", "[-inf, 0.01]", 0.0)),
 "com_zero_width": (PANDA, T("com", "com_offset", "body", "cube", "[0.0, 0.0]", 0.0)),
 "com_reversed": (PANDA, T("com", "com_offset", "body", "cube", "[0.01, -0.01]", 0.0)),
 "com_negative_only": (PANDA, T("com", "com_offset", "body", "cube", "[-0.01, -0.005]", -0.007)),
 "com_nominal_outside": (PANDA, T("com", "com_offset", "body", "cube", "[-0.01, 0.01]", 0.02)),
 "com_unknown_body": (PANDA, T("com", "com_offset", "body", "cubee", "[-0.01, 0.01]", 0.0)),
 "com_geom_key": (PANDA, T("com", "com_offset", "geom", "cube", "[-0.01, 0.01]", 0.0)),
 "com_world_body": (PANDA, T("com", "com_offset", "body", "table", "[-0.01, 0.01]", 0.0)),
 "com_loguniform_neg": (PANDA, T("com", "com_offset", "body", "cube", "[-0.01, 0.01]", 0.0, "loguniform")),
 "com_axis_key": (PANDA, T("com", "com_offset", "body", "cube", "[-0.01, 0.01]", 0.0, extra='axis = "y"\n')),
 "com_massless_nogeom": (MOD, T("com", "com_offset", "body", "marker", "[-0.5, 0.5]", 0.0)),
 "com_massless_geom": (MOD, T("com", "com_offset", "body", "massless_geom", "[-0.001, 0.001]", 0.0)),
 "com_arm_link_huge": (PANDA, T("com", "com_offset", "body", "link4", "[-0.3, 0.3]", 0.0)),
 "com_string_range": (PANDA, T("com", "com_offset", "body", "cube", '["a", 0.01]', 0.0)),
 "com_twice": (PANDA, T("com", "com_offset", "body", "cube", "[-0.01, 0.01]", 0.0) + T("com2", "com_offset", "body", "cube", "[-0.01, 0.01]", 0.0)),
 "com_kind_typo": (PANDA, T("com", "com-offset", "body", "cube", "[-0.01, 0.01]", 0.0)),
 "com_name_as_kind": (PANDA, "[uncertainty.com_offset]\nbody = \"cube\"\nrange = [-0.01, 0.01]\nnominal = 0.0\n"),
 "com_no_target": (PANDA, "[uncertainty.com]\nkind = \"com_offset\"\nrange = [-0.01, 0.01]\nnominal = 0.0\n"),
 # force_limit
 "fl_unknown_act": (PANDA, T("fl", "force_limit", "actuator", "finger_lft", "[1, 35]", 35)),
 "fl_body_key": (PANDA, T("fl", "force_limit", "body", "finger_left", "[1, 35]", 35)),
 "fl_no_forcerange": (MOD, T("fl", "force_limit", "actuator", "joint7", "[1, 12]", 12)),
 "fl_zero_low": (PANDA, T("fl", "force_limit", "actuator", "finger_left", "[0, 35]", 35)),
 "fl_negative": (PANDA, T("fl", "force_limit", "actuator", "finger_left", "[-35, -1]", -10)),
 "fl_above_mjcf": (PANDA, T("fl", "force_limit", "actuator", "finger_left", "[10, 500]", 35)),
 "fl_joint_name": (PANDA, T("fl", "force_limit", "actuator", "finger_joint1", "[1, 35]", 35)),
 "fl_nan": (PANDA, T("fl", "force_limit", "actuator", "finger_left", "[nan, 35]", 35)),
 "fl_tiny": (PANDA, T("fl", "force_limit", "actuator", "joint1", "[1e-9, 1e-6]", 1e-6)),
 "fl_loguniform": (PANDA, T("fl", "force_limit", "actuator", "finger_left", "[1, 35]", 35, "loguniform")),
 "fl_aloha_short": (ALOHA, T("fl", "force_limit", "actuator", "shoulder", "[5, 20]", 20)),
 "fl_aloha_joint": (ALOHA, T("fl", "force_limit", "actuator", "right/right_finger_joint", "[1, 5]", 5)),
 "fl_twice_same": (PANDA, T("fl", "force_limit", "actuator", "finger_left", "[1, 35]", 35) + T("fl2", "force_limit", "actuator", "finger_left", "[1, 35]", 35)),
 "fl_nominal_outside": (PANDA, T("fl", "force_limit", "actuator", "finger_left", "[1, 20]", 35)),
}
def cli(args):
    return subprocess.run([str(HERE / "cm.sh")] + args, capture_output=True, text=True)
if __name__ == "__main__":
    only = sys.argv[1:]
    for name, (b, tables) in CASES.items():
        if only and name not in only: continue
        text = b.replace("# Cost", tables + "# Cost", 1)
        p = HERE / "bad" / f"{name}.toml"; p.write_text(text)
        traj = "/tmp/r28/params/aloha0.npz" if b is ALOHA else "/tmp/r28/params/panda0.npz"
        r = cli(["rollout", traj, "--scenario", str(p), "--json"])
        err = (r.stderr.strip().splitlines() or [""])
        tb = "Traceback" in r.stderr
        msg = [l for l in err if "error" in l or "warning" in l] or err[-1:]
        print(f"[{name}] rc={r.returncode}{' TRACEBACK' if tb else ''}: " + " | ".join(msg)[:700])
