"""Sample #24 of the sock_ship validation (socket 0.934 kg, friction 1.209): critmoment's own rollout at those
values (scenario sock_s24.toml, the nominal set to them): its task verdict and where the peg ends."""
import critmoment as cm
assert cm.__file__.startswith("/tmp/r37/src"), cm.__file__
from critmoment.trajectory import load_trajectory

twin = cm.Twin("sock_s24.toml")
rec = cm.rollout(load_trajectory("sock1.npz"), twin=twin)
s = rec.summary()
print("cm rollout:", {k: s.get(k) for k in ("completed", "max_stage", "final_stage", "shortfalls")})
m = twin.model
q = twin.qpos(rec.states[[-1]])[0]
for j in ("red_peg_joint", "blue_socket_joint"):
    a = m.jnt_qposadr[m.joint(j).id]
    print("cm final", j, q[a:a + 3].round(4))
