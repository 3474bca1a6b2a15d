"""The model as shipped (no friction parameter written), with critmoment's controls, classified by the independent
truth (truth.py's Setup/classify; its pair model keeps MuJoCo's mixed parameters of the unedited model, i.e. the
shipped frictions 1/5/6), next to the same run at a given friction for every object contact.
usage: asis.py SCENARIO TRAJ [MU ...]"""
import sys
sys.path.insert(0, "/tmp/r37/robots/scripts")
import truth  # noqa: E402  (asserts the r37 snapshot)
import critmoment
assert critmoment.__file__.startswith("/tmp/r37/src"), critmoment.__file__
scen, traj = sys.argv[1:3]
s = truth.Setup(scen, traj)
mass = s.unc["mass"]["nominal"]
names = s.names
s.names = ["mass"]                     # only the mass is written: the pairs keep the shipped (mixed) friction
rec = s.rollout([mass]); out, info = truth.classify(s, rec)
print("as shipped:", out, {k: info[k] for k in ("goal_dist", "end_pos", "completed", "events")})
s.names = names
for mu in sys.argv[3:]:
    vals = [float(mu) if n == "friction" else s.unc[n]["nominal"] for n in names]
    rec = s.rollout(vals); out, info = truth.classify(s, rec)
    print(f"friction {mu} on every object contact:", out, {k: info[k] for k in ("goal_dist", "end_pos", "completed", "events")})
