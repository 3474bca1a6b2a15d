"""A user's edit of init's ORCA scenario (the model untouched): the hand's one normalised
channel (16 finger servos between the measured extremes, abduction and thumb rotation
included) is split into a flexion gripper channel (thumb pip/dip, mcp/pip of each finger;
init's measured closed/open ends kept) and six joint channels (thumb mcp and abd, four
abductions) that the trajectory holds at a grasp posture.
usage: split_orca_scenario.py IN.toml OUT.toml"""
import re
import sys
import tomllib

src = open(sys.argv[1]).read()
cfg = tomllib.loads(src)
ch = [c for c in cfg["actions"]["channel"] if c.get("normalised")][0]
fixed = [n for n in ch["actuators"] if "abd" in n or "thumb_mcp" in n]
keep = [(n, c, o) for n, c, o in zip(ch["actuators"], ch["closed"], ch["open"]) if n not in fixed]
block_re = re.compile(r"\[\[actions\.channel\]\]\nactuators = \[\"h_right_thumb_mcp_actuator\".*?label = \"h_right_palm/gripper\"\n", re.S)
new = "".join(f'[[actions.channel]]\nactuators = ["{n}"]   # held at a grasp posture (split from the hand channel)\n\n' for n in fixed)
new += ("[[actions.channel]]\nactuators = [" + ", ".join(f'"{n}"' for n, _, _ in keep) + "]\nnormalised = true\n"
        f"closed = [{', '.join(str(c) for _, c, _ in keep)}]\nopen = [{', '.join(str(o) for _, _, o in keep)}]\n"
        'label = "h_right_palm/gripper"\n')
out, n = block_re.subn(new, src)
assert n == 1, n
open(sys.argv[2], "w").write(out)
print("split:", fixed)
