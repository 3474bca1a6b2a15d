"""Scenario TOML variants of the bundled ALOHA scenario (aloha_transfer_cube), written to the
current folder (run it from scen/: `cd scen && python gen_sc.py`).

The variants point `mjcf` at the bundled model by absolute path, found at run time: the folder
named by $R24_MODELS_DIR if set, else the installed `critmoment.models` package folder.
The .toml files are generated (git-ignored); rerun this script to get them back."""
import os
from importlib import resources

MODELS = os.environ.get("R24_MODELS_DIR") or str(resources.files("critmoment.models"))
M = os.path.join(MODELS, "aloha_transfer_cube")
base=open(M+'/scenario.toml').read().replace('mjcf = "scene.xml"', f'mjcf = "{M}/scene.xml"')
def w(name, s): open(name+'.toml','w').write(s)
def sub(name, a, b, count=1):
    assert a in base, a
    w(name, base.replace(a,b,count))
w('ok', base)
sub('typo_key', 'horizon = 10', 'horizn = 10')
sub('typo_table', '[sparse]', '[spares]')
sub('mass_str', 'range = [0.05, 10.0]', 'range = ["0.05", "10"]')
sub('mass_reversed', 'range = [0.05, 10.0]', 'range = [10.0, 0.05]')
sub('mass_zero_width', 'range = [0.05, 10.0]', 'range = [0.05, 0.05]')
sub('mass_negative', 'range = [0.05, 10.0]', 'range = [-1.0, 10.0]')
sub('mass_zero_low', 'range = [0.05, 10.0]', 'range = [0.0, 10.0]')
sub('mass_huge', 'range = [0.05, 10.0]', 'range = [0.05, 1e12]')
sub('mass_inf', 'range = [0.05, 10.0]', 'range = [0.05, inf]')
sub('mass_nan', 'range = [0.05, 10.0]', 'range = [0.05, nan]')
sub('mass_3vals', 'range = [0.05, 10.0]', 'range = [0.05, 1.0, 10.0]')
sub('mass_units', 'range = [0.05, 10.0]', 'range = ["50 g", "10 kg"]')
sub('mass_nominal_out', 'nominal = 0.05', 'nominal = 20.0')
sub('mass_grams', 'range = [0.05, 10.0]     # [kg]\nnominal = 0.05', 'range = [50.0, 10000.0]\nnominal = 50.0')
sub('fric_negative', 'range = [0.2, 1.5]', 'range = [-0.5, 1.5]')
sub('fric_zero', 'range = [0.2, 1.5]', 'range = [0.0, 1.5]')
sub('fric_reversed', 'range = [0.2, 1.5]', 'range = [1.5, 0.2]')
sub('fric_huge', 'range = [0.2, 1.5]', 'range = [0.2, 1e6]')
sub('prior_bad', 'prior = "uniform"', 'prior = "normal"')
sub('prior_log_zero', 'range = [0.2, 1.5]       # sliding friction coefficient of the cube\'s contacts\nnominal = 1.0\nprior = "uniform"', 'range = [0.0, 1.5]\nnominal = 1.0\nprior = "loguniform"')
sub('unknown_kind', '[uncertainty.friction]', '[uncertainty.friction]\nkind = "stiffness"')
sub('unknown_param_name', '[uncertainty.friction]', '[uncertainty.slipperiness]')
sub('body_missing', 'body = "box"\nrange', 'body = "boxx"\nrange')
sub('mjcf_missing', f'mjcf = "{M}/scene.xml"', 'mjcf = "nonexistent.xml"')
sub('mjcf_dir', f'mjcf = "{M}/scene.xml"', f'mjcf = "{M}"')
sub('mjcf_int', f'mjcf = "{M}/scene.xml"', 'mjcf = 5')
sub('keyframe_missing', 'keyframe = "home"', 'keyframe = "nohome"')
sub('keyframe_idx', 'keyframe = "home"', 'keyframe = 7')
sub('keyframe_neg', 'keyframe = "home"', 'keyframe = -1')
sub('keyframe_bool', 'keyframe = "home"', 'keyframe = true')
sub('gripper_close_gt_open', 'gripper_close = 0.01844', 'gripper_close = 0.07')
sub('gripper_equal', 'gripper_close = 0.01844', 'gripper_close = 0.058')
sub('gripper_mm', 'gripper_close = 0.01844  # finger position [m] at normalised 0 (ACT\'s PUPPET_GRIPPER_POSITION_CLOSE)\ngripper_open = 0.05800', 'gripper_close = 18.44\ngripper_open = 58.0')
sub('fps_zero', 'fps = 50.0', 'fps = 0.0')
sub('fps_str', 'fps = 50.0', 'fps = "50"')
sub('range_policy_bad', 'range_policy = "error"', 'range_policy = "ignore"')
sub('task_missing', 'kind = "handover"', '# no kind')
sub('task_same', 'receiver = "left"', 'receiver = "right"')
sub('task_kind_typo', 'kind = "handover"', 'kind = "hand_over"')
sub('limit_zero', 'waist = 10.0', 'waist = 0.0')
sub('limit_neg', 'waist = 10.0', 'waist = -10.0')
sub('limit_unknown', 'waist = 10.0', 'waistt = 10.0')
sub('limit_str', 'waist = 10.0', 'waist = "10 Nm"')
sub('limit_inf', 'waist = 10.0', 'waist = inf')
sub('cost_threshold_zero', 'threshold = 0.9', 'threshold = 0.0')
sub('cost_threshold_neg', 'threshold = 0.9', 'threshold = -1.0')
sub('cost_alpha_neg', 'alpha = 0.7', 'alpha = -0.7')
sub('cost_A_zero_B_zero', 'A = 1.0\nB = 1.0', 'A = 0.0\nB = 0.0')
sub('cost_threshold_nan', 'threshold = 0.9', 'threshold = nan')
sub('horizon_zero', 'horizon = 10', 'horizon = 0')
sub('horizon_float', 'horizon = 10', 'horizon = 10.5')
sub('horizon_huge', 'horizon = 10', 'horizon = 100000')
sub('horizon_bool', 'horizon = 10', 'horizon = true')
sub('persistence_neg', 'horizon = 10', 'horizon = 10\npersistence = -0.01')
sub('slip_neg', 'horizon = 10', 'horizon = 10\nslip_tolerance = -1')
sub('dup_key', 'horizon = 10', 'horizon = 10\nhorizon = 11')
sub('support_missing', 'geoms = ["table"]', 'geoms = ["tabel"]')
sub('support_empty', 'geoms = ["table"]', 'geoms = []')
sub('grippers_same', 'geoms = ["right/left_pad", "right/right_pad"]', 'geoms = ["left/left_pad", "left/right_pad"]')
sub('grip_geom_obj', 'geoms = ["right/left_pad", "right/right_pad"]', 'geoms = ["box"]')
sub('name_int', 'name = "aloha_transfer_cube"', 'name = 5')
sub('settle_huge', 'receiver = "left"', 'receiver = "left"\nsettle_time = 100.0')
sub('lift_neg', 'receiver = "left"', 'receiver = "left"\nlift_height = -1.0')
sub('feas_bad', '[sparse]', '[feasibility]\nlag_tolerance = -1\n[sparse]')
sub('feas_unknown', '[sparse]', '[feasibility]\nlag_tol = 1\n[sparse]')
sub('com_offset', '[cost]', '[uncertainty.com]\nkind = "com_offset"\nbody = "box"\nrange = [-0.5, 0.5]\nnominal = 0.0\n[cost]')
sub('force_limit_noforcerange', '[cost]', '[uncertainty.fl]\nkind = "force_limit"\nactuator = "left/waist"\nrange = [1.0, 10.0]\nnominal = 5.0\n[cost]')
sub('two_masses', '[cost]', '[uncertainty.mass2]\nkind = "mass"\nbody = "box"\nrange = [0.05, 1.0]\nnominal = 0.05\n[cost]')
sub('mass_target_table', 'body = "box"\nrange', 'body = "world"\nrange')
w('empty', '')
w('notoml', 'this is = not [ toml')
w('bom', '\ufeff'+base)
w('only_name', 'name="x"\n')
open('latin1.toml','wb').write(base.replace('description = "', 'description = "caf\xe9 ').encode('latin-1'))

# hand-edited variants of the probe, generated here too
def subs(name, *pairs):
    s = base
    for a, b in pairs:
        assert a in s, a
        s = s.replace(a, b, 1)
    w(name, s)
sub('mass_log', 'prior = "uniform"', 'prior = "loguniform"')
sub('fl_wrist', '[cost]', '[uncertainty.wrist_limit]\nkind = "force_limit"\nactuator = "right/wrist_angle"\nrange = [0.3, 5.0]\nnominal = 5.0\n[cost]')
subs('fl_wrist_narrow', ('range = [0.05, 10.0]     # [kg]', 'range = [0.05, 0.3]'),
     ("range = [0.2, 1.5]       # sliding friction coefficient of the cube's contacts", 'range = [0.8, 1.5]'),
     ('[cost]', '[uncertainty.wrist_limit]\nkind = "force_limit"\nactuator = "right/wrist_angle"\nrange = [0.3, 5.0]\nnominal = 5.0\n[cost]'))
subs('html_inject', ('name = "aloha_transfer_cube"', 'name = "<script>alert(1)</script>"'),
     ('description = "Right ViperX 300s picks a 4 cm, 0.05 kg cube and hands it to the left arm (ACT sim transfer cube)."',
      'description = "<img src=x onerror=alert(2)> &amp; <b>bold</b>"'),
     ('[uncertainty.friction]', '[uncertainty."fr<i>ic"]\nkind = "friction"'))
