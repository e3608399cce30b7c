"""Derives the corpus files of tests/data/real from their public sources (see SOURCES.md).

Each function documents the one change it makes. Inputs are the upstream files, read from
the folder given as the first argument; outputs go to the folder given as the second.
Needs only numpy.
"""
import heapq, os, struct, sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from meshlib import read_any, weld, write_stl, stats


def strip_end_caps(T, ends, tol=0.02):
    """Removes the flat end faces of a thin-walled solid: for each (axis, side) of `ends`, the
    faces whose three vertices lie on the bounding box's face there (a vase's floor and rim, a
    tube's end annuli, slivers included). What is left is the outer and inner skin (or one skin
    for a solid vase body)."""
    lo, hi = T.reshape(-1, 3).min(0), T.reshape(-1, 3).max(0)
    keep = np.ones(len(T), bool)
    for a, side in ends:
        plane = lo[a] if side < 0 else hi[a]
        keep &= ~(np.abs(T[:, :, a] - plane) < tol).all(axis=1)
    return T[keep]


def drop_degenerate(T, eps=1e-9):
    """Drops zero-area faces (repeated vertices or collinear), which the source exports carry."""
    return T[np.linalg.norm(np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0]), axis=1) > eps]


def components(T):
    V, F = weld(T)
    parent = np.arange(len(V))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for f in F:
        r = [find(v) for v in f]
        for x in r[1:]:
            parent[find(x)] = find(r[0])
    roots = np.array([find(f[0]) for f in F])
    return [T[roots == r] for r in np.unique(roots)]


def area(T):
    return 0.5 * np.linalg.norm(np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0]), axis=1).sum()


Z_ENDS = ((2, -1), (2, 1))


def outer_skin(T, ends=Z_ENDS):
    """The widest piece once the end caps are gone (largest bounding box): the outer skin."""
    parts = components(drop_degenerate(strip_end_caps(T, ends)))
    return max(parts, key=lambda p: (np.ptp(p.reshape(-1, 3), axis=0).sum(), area(p)))


def y_up_to_z_up(T):
    """Turns a Y-up model (the usual export of mesh tools) by +90 degrees about X: y -> z, z -> -y."""
    R = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], float)
    return T @ R.T


def cut_below(T, z):
    """Drops every triangle with a vertex below z (the open base of a shell)."""
    return T[(T[:, :, 2] >= z).all(axis=1)]


def waam_scale(T, factor=100.0):
    """A vessel scan made a WAAM part: lowest point moved to the origin, then scaled (a 4.2 cm
    junction becomes 420 mm tall)."""
    return (T - T.reshape(-1, 3).min(axis=0)) * factor


def collapse_to(T, target):
    """Re-tessellates a surface coarser by shortest-edge collapses to the edge midpoint, never
    touching a boundary vertex (the free edges keep their vertices) and refusing collapses that
    break the link condition or flip a triangle."""
    V, F = weld(T)
    V = V.copy()
    F = [list(f) for f in F]
    alive = [True] * len(F)
    vf = [set() for _ in V]
    for i, f in enumerate(F):
        for v in f:
            vf[v].add(i)
    E = {}
    for f in F:
        for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            k = (min(a, b), max(a, b))
            E[k] = E.get(k, 0) + 1
    boundary = set()
    for (a, b), c in E.items():
        if c == 1:
            boundary.update((a, b))
    heap = [(np.linalg.norm(V[a] - V[b]), a, b) for (a, b) in E]
    heapq.heapify(heap)
    nface = len(F)
    removed_v = set()

    def nbrs(v):
        return {u for fi in vf[v] for u in F[fi]} - {v}

    while nface > target and heap:
        _, a, b = heapq.heappop(heap)
        if a in removed_v or b in removed_v or a in boundary or b in boundary:
            continue
        shared = vf[a] & vf[b]
        if len(shared) != 2:
            continue
        if len(nbrs(a) & nbrs(b)) != 2:  # link condition
            continue
        m = 0.5 * (V[a] + V[b])
        ok = True
        for fi in (vf[a] | vf[b]) - shared:
            f = F[fi]
            p = [V[v] for v in f]
            q = [m if v in (a, b) else V[v] for v in f]
            n0 = np.cross(p[1] - p[0], p[2] - p[0])
            n1 = np.cross(q[1] - q[0], q[2] - q[0])
            if np.dot(n0, n1) <= 0.2 * np.linalg.norm(n0) * np.linalg.norm(n1):
                ok = False
                break
        if not ok:
            continue
        V[a] = m
        for fi in shared:
            alive[fi] = False
            for v in F[fi]:
                vf[v].discard(fi)
            nface -= 1
        for fi in list(vf[b]):
            F[fi] = [a if v == b else v for v in F[fi]]
            vf[a].add(fi)
        vf[b] = set()
        removed_v.add(b)
        for u in nbrs(a):
            heapq.heappush(heap, (np.linalg.norm(V[a] - V[u]), min(a, u), max(a, u)))
    F = np.array([f for f, al in zip(F, alive) if al])
    return V[F]


def write_obj(path, T, header):
    V, F = weld(T)
    with open(path, "w") as f:
        f.write("# " + header + "\n")
        for v in V:
            f.write("v %.9g %.9g %.9g\n" % tuple(v))
        for t in F:
            f.write("f %d %d %d\n" % tuple(t + 1))


def write_ply(path, T, header):
    V, F = weld(T)
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\ncomment %s\nelement vertex %d\n"
                 "property float x\nproperty float y\nproperty float z\nelement face %d\n"
                 "property list uchar int vertex_indices\nend_header\n" % (header, len(V), len(F))).encode())
        f.write(V.astype("<f4").tobytes())
        rec = np.zeros(len(F), dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]))
        rec["n"] = 3
        rec["i"] = F
        f.write(rec.tobytes())


def main(src, out):
    os.makedirs(out, exist_ok=True)
    s = lambda name: os.path.join(src, name)
    o = lambda name: os.path.join(out, name)
    vase = read_any(s("sotvl_Spiral-Vase.stl"))
    write_stl(o("vase_honeycomb_wall.stl"), outer_skin(vase), b"vase wall (eggnot, CC BY-SA 3.0)")
    pot = y_up_to_z_up(read_any(s("XMAS_Pot_9.stl")))
    write_stl(o("pot_twisted_wall.stl"), outer_skin(pot), b"twisted pot wall (shanouk, CC BY 3.0)")
    tube = read_any(s("dyson-hoover.stl"))
    write_stl(o("tube_straight_wall.stl"), outer_skin(tube), b"tube wall (guyc, CC BY 3.0)")
    elbow = read_any(s("Exhaust_Tube.stl"))
    write_stl(o("elbow_tube_wall.stl"), outer_skin(elbow, ((2, -1), (0, 1))), b"elbow wall (jmillerfo, CC BY 3.0)")
    artery = read_any(s("gmsh_artery.stl"))
    write_stl(o("y_branch_artery_m.stl"), artery, b"gmsh benchmarks/stl/artery.stl (GPL-2.0-or-later)")
    fine = read_any(s("gmsh_bifurcation.stl"))
    write_stl(o("junction_coarse_cm.stl"), collapse_to(fine, 4000), b"gmsh bifurcation.stl coarsened (GPL-2.0+)")
    # From the file as written, so the float32 rounding is the coarse file's own.
    write_stl(o("junction_waam_mm.stl"), waam_scale(read_any(o("junction_coarse_cm.stl"))),
              b"gmsh bifurcation.stl coarsened, WAAM scale (GPL-2.0+)")
    dome = read_any(s("pmp_hemisphere.off"))
    write_obj(o("dome_cap_in.obj"), dome, "pmp-library data/off/hemisphere.off (MIT), as OBJ")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
    for f in sorted(os.listdir(sys.argv[2])):
        if f.endswith((".stl", ".obj")):
            print(f, stats(read_any(os.path.join(sys.argv[2], f))))
