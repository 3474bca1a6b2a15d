import critmoment as cm
from critmoment import analysis, demos, report

twin = cm.Twin(cm.load_scenario())
traj = demos.scripted_transfer(seed=0, twin=twin)
audit = analysis.analyze(traj, twin=twin)
print(audit.verdict, audit.p_success, audit.safe_region)
for mr in audit.moments:
    print(mr.moment.label, mr.moment.time, mr.critical, mr.dominant)
report.write_report(audit, "report")

sc = cm.load_scenario()
box = sc.box.with_range("mass", 0.05, 0.2).with_range("friction", 0.5, 1.5)
audit = analysis.analyze(traj, twin=cm.Twin(sc.replace(box=box)))   # -> SAFE
print(audit.verdict)
