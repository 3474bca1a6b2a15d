import critmoment as cm
from critmoment import demos

scenario = cm.load_scenario()                    # bundled ALOHA transfer-cube twin
print(scenario.task.describe())                  # what the trajectory must achieve
traj = demos.scripted_transfer(seed=0)
rec = cm.rollout(traj, scenario)
print(rec.summary()["stage_first_step"])

report = cm.analyze(traj, scenario, seed=0)      # the audit
print(report.verdict, report.p_success, report.safe_region_text)
check = cm.validate(traj, twin=cm.Twin(scenario), n_samples=64)   # against brute force
print(check.confusion, check.false_safe_rate)
