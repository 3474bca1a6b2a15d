"""Contact-model copies of a shipped MJCF via MjSpec (mesh paths made absolute; nothing else changed).

Usage: python make_variants.py SCENE.xml OUT_DIR NAME [pyramidal1|elliptic10 ...]
"""
import sys
from pathlib import Path

import mujoco

MODELS = {"pyramidal1": (mujoco.mjtCone.mjCONE_PYRAMIDAL, 1.0),
          "elliptic10": (mujoco.mjtCone.mjCONE_ELLIPTIC, 10.0)}


def main():
    src, out, name, *kinds = sys.argv[1:]
    src, out = Path(src).absolute(), Path(out)
    out.mkdir(parents=True, exist_ok=True)
    for kind in kinds:
        spec = mujoco.MjSpec.from_file(str(src))
        meshdir = src.parent / spec.meshdir if spec.meshdir else src.parent
        for mesh in spec.meshes:
            if mesh.file and not Path(mesh.file).is_absolute():
                mesh.file = str((meshdir / mesh.file).resolve())
        spec.meshdir = ""
        spec.option.cone, spec.option.impratio = MODELS[kind]
        spec.compile()
        path = out / f"{name}_{kind}.xml"
        path.write_text(spec.to_xml())
        m = mujoco.MjModel.from_xml_path(str(path))
        print("wrote", path, "cone", m.opt.cone, "impratio", m.opt.impratio)


if __name__ == "__main__":
    main()
