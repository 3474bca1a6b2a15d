"""manifest.model_sha256 (recording.model_hash): what it covers.
(a) an unrelated *.xml beside the scene changes it (the same audit, a different report.json);
(b) a model file included from a subfolder (Menagerie style: robots/, assets/ meshes) is not covered:
    its change alters the physics but not the hash; (c) it is computed when the report is built,
    from the files then on disk, not from what was loaded."""
import os, shutil, json
from common import SCRATCH, log
import mujoco
from critmoment.scenario import load_scenario
from critmoment.recording import model_hash
from critmoment.twin import Twin
R = "model_hash.txt"
root = os.path.join(SCRATCH, "mh"); shutil.rmtree(root, ignore_errors=True)
# (a)
a = os.path.join(root, "a"); shutil.copytree("/tmp/r33/src/models/panda_pick_place", a)
h1 = model_hash(load_scenario(a))
open(os.path.join(a, "notes.xml"), "w").write("<!-- an unrelated file -->\n")
h2 = model_hash(load_scenario(a))
log(R, f"(a) unrelated notes.xml added beside scene.xml: model_sha256 {h1[:12]} -> {h2[:12]} (changed: {h1 != h2})")
# (b) the robot included from a subfolder
b = os.path.join(root, "b"); shutil.copytree("/tmp/r33/src/models/panda_pick_place", b)
os.makedirs(os.path.join(b, "robots")); shutil.move(os.path.join(b, "panda.xml"), os.path.join(b, "robots", "panda.xml"))
scene = open(os.path.join(b, "scene.xml")).read().replace('<include file="panda.xml"/>', '<include file="robots/panda.xml"/>')
open(os.path.join(b, "scene.xml"), "w").write(scene)
s = load_scenario(b); m1 = Twin(s).model; hb1 = model_hash(s)
p = os.path.join(b, "robots", "panda.xml"); txt = open(p).read()
import re
n = len(re.findall(r'mass="', txt))
txt2 = re.sub(r'mass="([0-9.]+)"', lambda mo: f'mass="{float(mo.group(1)) * 3:g}"', txt)
open(p, "w").write(txt2)
s2 = load_scenario(b); m2 = Twin(s2).model; hb2 = model_hash(s2)
log(R, f"(b) robots/panda.xml: {n} link masses tripled: total robot mass {m1.body_subtreemass[1]:.3f} -> {m2.body_subtreemass[1]:.3f} kg; "
       f"model_sha256 {hb1[:12]} -> {hb2[:12]} (changed: {hb1 != hb2})")
