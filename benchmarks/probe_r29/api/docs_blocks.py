"""Every ```python block of README.md and docs/tutorial.md (concatenated per file, in order),
the ```bash blocks of README.md / docs/tutorial.md with `critmoment` = the snapshot's CLI and
`pip install` skipped, and examples/*.py, each in a fresh temp folder.

    PYTHONPATH=/tmp/r29/src python docs_blocks.py [DOCS_ROOT]   (default /tmp/r29/src)
"""
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import PY, SRC, env  # noqa: E402

argv = [a for a in sys.argv[1:] if not a.startswith("--")]
root = Path(argv[0] if argv else SRC)
CM = f"{PY} -c \"import sys; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())\""


def blocks(md, lang):
    return re.findall(rf"```{lang}\n(.*?)```", (root / md).read_text(), re.S)


def show(label, p, t):
    tail = (p.stdout + p.stderr).strip().splitlines()
    print(f"== {label}: rc {p.returncode}, {t:.1f} s")
    for line in tail[:6] + (["..."] + tail[-6:] if len(tail) > 12 else tail[6:]):
        print("   ", line[:230])


ONLY_BASH = "--bash-only" in sys.argv
for md in ("README.md", "docs/tutorial.md"):
    code = "\n".join(blocks(md, "python"))
    if code and not ONLY_BASH:
        d = tempfile.mkdtemp(prefix="r29doc_", dir="/tmp/r29/api")
        (Path(d) / "block.py").write_text(code)
        t = time.perf_counter()
        p = subprocess.run([PY, "block.py"], cwd=d, env=env(), capture_output=True, text=True)
        show(f"{md} python blocks ({d})", p, time.perf_counter() - t)
    for i, sh in enumerate(blocks(md, "bash")):
        lines = [re.sub(r"pip install \S+ && ", "", ln) for ln in sh.splitlines()
                 if ln.strip() and "pytest" not in ln]
        script = "\n".join(ln for ln in lines if not ln.strip().startswith("pip install"))
        if not script.strip():
            continue
        d = tempfile.mkdtemp(prefix="r29doc_", dir="/tmp/r29/api")
        t = time.perf_counter()
        p = subprocess.run(["bash", "-c", f"critmoment() {{ {CM} \"$@\"; }}\n{script}"], cwd=d,
                           env=env(), capture_output=True, text=True)
        show(f"{md} bash block {i}: {script!r}"[:200], p, time.perf_counter() - t)

for ex in [] if ONLY_BASH else sorted((root / "examples").glob("*.py")):
    d = tempfile.mkdtemp(prefix="r29doc_", dir="/tmp/r29/api")
    args = []  # as written
    t = time.perf_counter()
    p = subprocess.run([PY, str(ex), *args], cwd=d, env=env(), capture_output=True, text=True)
    show(f"examples/{ex.name} {' '.join(args)} ({d})", p, time.perf_counter() - t)
