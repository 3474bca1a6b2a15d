"""ComOffset / ForceLimit parameters built in code (the TOML route refuses bad ones: same here?)."""
from common import *
from critmoment import params as P
traj = cm.load_trajectory(TRAJ); sc = cm.load_scenario()
m0, f0 = sc.box.parameters
def tw(name, *extra):
    t(name, lambda: cm.rollout(traj, twin=cm.Twin(sc.replace(box=P.UncertaintyBox((m0, f0) + extra)))).summary()["completed"])
tw("com_offset ±1 cm", P.ComOffsetParameter("com", "box", -0.01, 0.01, 0.0))
tw("com_offset ±1 m (outside the cube)", P.ComOffsetParameter("com", "box", -1.0, 1.0, 0.0))
tw("com_offset on a robot link", P.ComOffsetParameter("com", "left/gripper_link", -0.01, 0.01, 0.0))
tw("com_offset on world", P.ComOffsetParameter("com", "world", -0.01, 0.01, 0.0))
tw("force_limit unknown actuator", P.ForceLimitParameter("fl", "nosuch", 1.0, 10.0, 5.0))
tw("force_limit right/waist 1..10", P.ForceLimitParameter("fl", "right/waist", 1.0, 10.0, 5.0))
tw("force_limit short name 'waist'", P.ForceLimitParameter("fl", "waist", 1.0, 10.0, 5.0))
tw("mass on a robot link", P.MassParameter("m2", "left/gripper_link", 0.1, 1.0, 0.5))
tw("friction on a pad geom", P.FrictionParameter("f2", "left/left_pad", 0.5, 1.5, 1.0))
t("brute_force samples float16", lambda: cm.brute_force(traj, twin=cm.Twin(sc), samples=np.array([[0.05, 1.0]], np.float16), nthread=1) is not None)
t("brute_force samples (0,2)", lambda: cm.brute_force(traj, twin=cm.Twin(sc), samples=np.zeros((0, 2)), nthread=1))
