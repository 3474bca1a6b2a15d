"""From own_runs.py logs (own_CASE.txt): the physics steps a stop at the first failure of each
failing full rollout would save (failure step + the rule's duration), by stage and outcome."""
import ast, sys
T = {"aloha0": 4000, "aloha3": 4000, "panda0": 5000}
dur = {"tracking": 26, "motor": 26, "dropped": 11, "slipped": 26, "diverged": 0}
for c in T:
    lines = [ast.literal_eval(l) for l in open(f"own_{c}.txt") if l.startswith("{")]
    agg = {}
    for d in lines:
        if d["kind"] != "rollout" or not d["failed"]: continue
        step = int(round(d["t"] / 0.002)); save = T[c] - step - dur[d["outcome"]]
        k = (d["who"], d["outcome"]); a = agg.setdefault(k, [0, 0]); a[0] += 1; a[1] += save
    tot_own = sum(T[c] for d in lines)
    print(c, "own runs", len(lines), "own-run steps", tot_own, {f"{k[0]}/{k[1]}": (n, s) for k, (n, s) in agg.items()},
          "| failed-bool-exact (region, not drops):", sum(s for k, (n, s) in agg.items() if k[0]=="region" and k[1] != "dropped"),
          "| all:", sum(s for n, s in agg.values()))
