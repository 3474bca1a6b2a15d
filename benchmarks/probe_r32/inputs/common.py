import sys, warnings, io, contextlib, traceback
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r32/src"), cm.__file__
from critmoment.exceptions import CritmomentError
TRAJ = "/tmp/r32/inputs/traj.npz"
PANDA = "/tmp/r32/inputs/panda.npz"

def t(name, fn, show=True):
    """Run fn; classify: OK / CMERR / OTHER (not a CritmomentError). Captures stdout prints."""
    buf = io.StringIO()
    try:
        with warnings.catch_warnings(record=True) as w, contextlib.redirect_stdout(buf):
            warnings.simplefilter("always"); r = fn()
        ws = [f"{x.category.__name__}: {str(x.message)[:140]}" for x in w]
        out = buf.getvalue()
        print(f"OK    {name}: {type(r).__name__} {r if isinstance(r,(str,int,float,tuple)) and len(str(r))<200 else ''} warn={ws[:3]}" + (f" STDOUT={out[:200]!r}" if out else ""))
        return r
    except CritmomentError as e:
        print(f"CMERR {name}: {type(e).__name__}: {str(e)[:300]}")
    except Exception as e:
        tb = traceback.extract_tb(e.__traceback__)[-1]
        print(f"OTHER {name}: {type(e).__name__}: {str(e)[:300]}  @ {tb.filename.split('/')[-1]}:{tb.name}:{tb.lineno}  <-- not a CritmomentError")
    return None
