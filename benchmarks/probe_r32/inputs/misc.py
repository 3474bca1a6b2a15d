"""Remaining: goal/up values, grippers reordered in Scenario.replace, options that should be
refused before work, warn_once across calls, two scenarios in threads."""
import dataclasses, time, threading, json
from common import *
from critmoment.analysis import AnalyzeOptions
traj = cm.load_trajectory(TRAJ); sc = cm.load_scenario()
ps = cm.load_scenario("panda_pick_place"); ptr = cm.load_trajectory(PANDA)
def roll(s, tr):
    r = cm.rollout(tr, twin=cm.Twin(s)).summary(); return (r["completed"], r["final_stage"], r["shortfalls"][:1])
print("panda nominal", roll(ps, ptr))
for name, task in (("goal nan", dataclasses.replace(ps.task, goal=(float("nan"), 0.15, 0.02))),
                   ("tolerance 1e9", dataclasses.replace(ps.task, tolerance=1e9)),
                   ("up (0,0,0)", dataclasses.replace(ps.task, up=(0., 0., 0.))),
                   ("up (0,0,-1)", dataclasses.replace(ps.task, up=(0., 0., -1.))),
                   ("lift_height 0", dataclasses.replace(ps.task, lift_height=0.0)),
                   ("settle_time 0", dataclasses.replace(ps.task, settle_time=0.0))):
    t(name, lambda: roll(ps.replace(task=task), ptr))
print("-- ALOHA grippers reordered by Scenario.replace (task unchanged)")
t("grippers reversed", lambda: roll(sc.replace(grippers=sc.grippers[::-1]), traj))
t("grippers reversed + task rebuilt from names", lambda: roll(sc.replace(grippers=sc.grippers[::-1], task=dataclasses.replace(sc.task, grippers=tuple(g.name for g in sc.grippers[::-1]))), traj))
print("-- options refused before work?")
for kw in (dict(n_samples=2**40), dict(max_moments=10**9), dict(horizon=10**9), dict(search_trials=10**9)):
    t0 = time.time(); t(str(kw), lambda: cm.analyze(traj, sc, options=AnalyzeOptions(nthread=1, **kw)).verdict); print(f"      {time.time()-t0:.1f}s")
t("analyze seed=True", lambda: cm.analyze(traj, sc, seed=True, options=AnalyzeOptions(n_samples=8, nthread=1)))
t("analyze options=dict", lambda: cm.analyze(traj, sc, options={"n_samples": 8}))
t("analyze progress='yes'", lambda: cm.analyze(traj, sc, progress="yes"))
t("analyze trajectory=None", lambda: cm.analyze(None, sc))
t("analyze twin=scenario", lambda: cm.analyze(traj, twin=sc))
print("-- warn_once across two calls (30 Hz trajectory vs 50 Hz scenario)")
tr30 = cm.Trajectory(traj.actions[::5][:80], fps=10.0, start=traj.start, object_pose=traj.object_pose)
for i in range(2):
    t(f"rollout call {i}", lambda: cm.rollout(tr30, sc).steps if hasattr(cm.rollout(tr30, sc), 'steps') else 'ok')
print("-- two different scenarios in threads vs sequential")
O = AnalyzeOptions(n_samples=16, nthread=1)
J = lambda r: json.loads(json.dumps(r.to_json(timings=False), default=str))
seq = {"aloha": J(cm.analyze(traj, sc, options=O)), "panda": J(cm.analyze(ptr, ps, options=O))}
res = {}
def run(k, tr, s):
    try: res[k] = J(cm.analyze(tr, s, options=O))
    except BaseException as e: res[k] = repr(e)
th = [threading.Thread(target=run, args=("aloha", traj, sc)), threading.Thread(target=run, args=("panda", ptr, ps))]
[x.start() for x in th]; [x.join() for x in th]
for k in seq: print(k, "thread == sequential:", res[k] == seq[k], seq[k]["verdict"], seq[k]["p_success"])
