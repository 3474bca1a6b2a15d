"""Panda and ALOHA demo trajectories that press into the table (option validation bypassed):
python make_press.py"""
from critmoment import panda_demo, demos
from critmoment.trajectory import save_trajectory
def force(opt, **kw):
    for k, v in kw.items():
        object.__setattr__(opt, k, v)
    return opt
for pc in (-0.01, -0.02, -0.04):
    o = force(panda_demo.PickPlaceOptions(), place_clearance=pc)
    t = panda_demo.make_pick_place(0, options=o)
    save_trajectory(t, f"p_press{int(-pc*1000)}.npz"); print("p_press", pc)
for go in (-0.005, -0.01):
    o = force(panda_demo.PickPlaceOptions(), grasp_offset=go)
    t = panda_demo.make_pick_place(0, options=o)
    save_trajectory(t, f"p_lowgrasp{int(-go*1000)}.npz"); print("p_lowgrasp", go)
for gh in (0.005, 0.0, -0.01):
    o = force(demos.DemoOptions(), grasp_height=gh)
    t = demos.scripted_transfer(0, options=o)
    save_trajectory(t, f"a_lowgrasp{int(gh*1000)}.npz"); print("a_lowgrasp", gh)
