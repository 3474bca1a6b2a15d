"""Actions as numpy arrays of odd dtypes/layouts: accepted or refused, and if accepted, is the
audited content (content_sha256, the rollout) what the caller meant?"""
from common import *
z = np.load(TRAJ); A = z["actions"]; S = z["start"]; P = z["object_pose"]
sc = cm.load_scenario(); twin = cm.Twin(sc)
ref = cm.Trajectory(A, fps=50.0, start=S, object_pose=P)
H = ref.content_sha256()
def same(name, actions, **kw):
    kw = {"fps": 50.0, "start": S, "object_pose": P, **kw}
    tr = t(name, lambda: cm.Trajectory(actions, **kw))
    if tr is not None:
        d = float(np.max(np.abs(tr.actions - A))) if tr.actions.shape == A.shape else None
        print(f"      -> same content: {tr.content_sha256() == H}, max|diff| {d}, shape {tr.actions.shape}, writeable {tr.actions.flags.writeable}")
    return tr
same("float32", A.astype(np.float32))
same("float16", A.astype(np.float16))
same("int64 (rounded)", np.round(A).astype(np.int64))
same("uint8", np.clip(np.round(A), 0, None).astype(np.uint8))
same("big-endian >f8", A.astype(">f8"))
same("big-endian >f4", A.astype(">f4"))
same("longdouble", A.astype(np.longdouble))
same("object of floats", A.astype(object))
same("object with None", np.where(np.arange(A.size).reshape(A.shape)==5, None, A.astype(object)))
same("bool", A > 0)
same("complex (imag 0)", A.astype(complex))
same("str array", A.astype(str))
same("masked, no mask", np.ma.masked_array(A))
mA = A.copy(); mA[100, 3] = np.nan
same("masked, NaN masked out", np.ma.masked_invalid(mA))
mB = A.copy(); mB[100, 3] = 1e6
same("masked, 1e6 masked out", np.ma.masked_greater(mB, 100))
same("Fortran order", np.asfortranarray(A))
big = np.zeros((800, 28)); big[::2, ::2] = A
same("non-contiguous view [::2, ::2]", big[::2, ::2])
ro = A.copy(); ro.flags.writeable = False
same("read-only", ro)
same("broadcast (stride 0) rows", np.broadcast_to(A[0], (400, 14)))
same("0-d", np.array(1.0))
same("1-d (14,)", A[0])
same("1-d (5600,)", A.reshape(-1))
same("3-d (1,400,14)", A[None])
same("3-d (400,14,1)", A[..., None])
same("2-d (14,400) transposed", A.T)
same("list of lists", A.tolist())
same("tuple of tuples", tuple(map(tuple, A)))
same("list of np arrays", list(A))
same("matrix", np.asmatrix(A))
same("memoryview", memoryview(np.ascontiguousarray(A)))
try:
    import torch
    same("torch tensor", torch.tensor(A))
except ImportError:
    print("(no torch)")
same("structured array", np.zeros(400, dtype=[("a", "f8", (14,))]))
same("datetime64", np.zeros((400, 14), dtype="datetime64[s]"))
same("one inf", np.where(np.arange(A.size).reshape(A.shape)==77, np.inf, A))
same("one -0.0 / subnormal", np.where(np.arange(A.size).reshape(A.shape)==77, 5e-324, A))
# aliasing: mutate the source after construction
src = A.copy(); tr = cm.Trajectory(src, fps=50.0, start=S, object_pose=P); src[:] = 0
print("mutate source after construct -> traj unchanged:", tr.content_sha256() == H)
# start / pose / fps dtypes
same("start float16", A, start=S.astype(np.float16))
same("start (1,14)", A, start=S[None])
same("object_pose float32", A, object_pose=P.astype(np.float32))
same("object_pose list", A, object_pose=list(P))
same("object_pose (7,1)", A, object_pose=P[:, None])
same("object_pose xyzw-ish unnormalised 2x", A, object_pose=np.r_[P[:3], 2*P[3:]])
same("fps np.float32(50)", A, fps=np.float32(50))
same("fps np.float16(50)", A, fps=np.float16(50))
same("fps Fraction(50)", A, fps=__import__('fractions').Fraction(50))
same("fps Decimal('50')", A, fps=__import__('decimal').Decimal('50'))
same("fps np.array(50.)", A, fps=np.array(50.0))
same("fps np.array([50.])", A, fps=np.array([50.0]))
same("fps 50+0j", A, fps=50+0j)
same("fps 10**400", A, fps=10**400)
same("fps True", A, fps=True)
