"""Objects accepted by the API whose effect may be silently different from what was asked."""
import dataclasses
from common import *
from critmoment import task as TK, params as P
from critmoment.analysis import AnalyzeOptions
traj = cm.load_trajectory(TRAJ); sc = cm.load_scenario()
def roll(s, tr=traj):
    r = cm.rollout(tr, twin=cm.Twin(s)).summary(); return {k: r[k] for k in ("completed", "final_stage", "min_fos_motor", "limiting_actuator")}
print("bundled task:", sc.task.describe()); print("  ", roll(sc))
g = sc.gripper_names
wrong = TK.HandoverTask(grippers=g, picker="left", receiver="right")
print("roles swapped, scenario's gripper order:", wrong.describe()); print("  ", roll(sc.replace(task=wrong)))
wrong_rev = TK.HandoverTask(grippers=g[::-1], picker="left", receiver="right")
print("roles swapped, task grippers in reverse order:", wrong_rev.describe()); print("  ", t("rollout", lambda: roll(sc.replace(task=wrong_rev))))
foreign = TK.HandoverTask(grippers=("right", "left", "third"), picker="third", receiver="left")
print("task names a gripper the scenario lacks:"); t("rollout", lambda: roll(sc.replace(task=foreign)))
print("-- limits built in code")
print("limits keys:", list(sc.limits.items())[:4], "... sources", list(sc.limit_sources.items())[:2])
full = {k: 0.5 for k in sc.limits}
short = {k.split("/")[-1]: 0.5 for k in sc.limits}
print("all limits 0.5 by full name:", t("rollout", lambda: roll(sc.replace(limits=full))))
print("all limits 0.5 by short name (TOML accepts these):", t("rollout", lambda: roll(sc.replace(limits=short))))
print("one typo key 'left/waistt':", t("rollout", lambda: roll(sc.replace(limits={**sc.limits, "left/waistt": 0.5}))))
print("limits {} (empty):", t("rollout", lambda: roll(sc.replace(limits={}))))
print("-- goals built in code (panda)")
ps = cm.load_scenario("panda_pick_place"); ptr = cm.load_trajectory(PANDA)
print("panda task", ps.task); print("  ", roll(ps, ptr))
for name, goal in (("goal nan", (float("nan"), 0, 0)), ("goal len 2", tuple(ps.task.goal[:2])), ("goal str", "0 0 0"), ("goal len 4", tuple(ps.task.goal) + (0.0,)), ("goal np array", np.asarray(ps.task.goal))):
    t(name, lambda: roll(ps.replace(task=dataclasses.replace(ps.task, goal=goal)), ptr))
t("tolerance 1e9 (any place)", lambda: roll(ps.replace(task=dataclasses.replace(ps.task, tolerance=1e9)), ptr))
t("up (0,0,0)", lambda: roll(ps.replace(task=dataclasses.replace(ps.task, up=(0., 0., 0.))), ptr))
t("up 'z'", lambda: roll(ps.replace(task=dataclasses.replace(ps.task, up="z")), ptr))
print("-- huge / tiny parameter ranges (analyze n_samples=8, search off)")
O = AnalyzeOptions(n_samples=8, nthread=1, search=False)
def aud(s, label):
    r = t(label, lambda: cm.analyze(traj, s, options=O))
    if r is not None: print(f"      verdict {r.verdict.value} p={r.p_success} region={r.safe_region_text[:90]!r} causes={[c[:80] for c in r.failure_causes][:2]}")
aud(sc.replace(box=sc.box.with_range("mass", 0.05, 1e300)), "mass up to 1e300 kg")
aud(sc.replace(box=sc.box.with_range("mass", 1e-300, 0.1, nominal=0.05)), "mass from 1e-300 kg")
aud(sc.replace(box=sc.box.with_range("friction", 0.5, 1e300)), "friction up to 1e300")
aud(sc.replace(box=sc.box.with_range("friction", 1e-300, 1.5)), "friction from 1e-300")
aud(sc.replace(box=sc.box.with_range("mass", 0.05, 0.05 * (1 + 1e-15))), "mass range 1e-15 relative width")
