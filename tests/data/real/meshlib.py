import numpy as np, struct, sys, os

def read_stl(path):
    data = open(path, 'rb').read()
    if len(data) >= 84:
        n = struct.unpack('<I', data[80:84])[0]
        if 84 + 50 * n == len(data):
            rec = np.frombuffer(data[84:], dtype=np.dtype([('n', '<f4', 3), ('v', '<f4', (3, 3)), ('a', '<u2')]), count=n)
            return rec['v'].astype(np.float64)
    tris = []
    cur = []
    for line in data.decode('latin1').splitlines():
        t = line.strip().split()
        if t and t[0] == 'vertex':
            cur.append([float(x) for x in t[1:4]])
            if len(cur) == 3:
                tris.append(cur); cur = []
    return np.array(tris, dtype=np.float64)

def read_off(path):
    toks = open(path).read().split()
    i = 0
    if toks[0].upper().endswith('OFF'): i = 1
    nv, nf = int(toks[i]), int(toks[i+1]); i += 3
    V = np.array(toks[i:i+3*nv], dtype=np.float64).reshape(nv, 3); i += 3*nv
    F = []
    for _ in range(nf):
        k = int(toks[i]); idx = [int(x) for x in toks[i+1:i+1+k]]; i += 1 + k
        for j in range(1, k-1): F.append([idx[0], idx[j], idx[j+1]])
    return V[np.array(F)]

def read_obj(path):
    V = []; F = []
    for line in open(path, errors='replace'):
        t = line.split()
        if not t: continue
        if t[0] == 'v': V.append([float(x) for x in t[1:4]])
        elif t[0] == 'f':
            idx = [int(x.split('/')[0]) for x in t[1:]]
            idx = [k - 1 if k > 0 else len(V) + k for k in idx]
            for j in range(1, len(idx)-1): F.append([idx[0], idx[j], idx[j+1]])
    V = np.array(V); return V[np.array(F)]

def read_ply(path):
    data = open(path, 'rb').read()
    end = data.index(b'end_header\n') + len(b'end_header\n')
    hdr = data[:end].decode()
    nv = int(hdr.split('element vertex ')[1].split()[0]); nf = int(hdr.split('element face ')[1].split()[0])
    V = np.frombuffer(data[end:end + 12 * nv], '<f4').reshape(nv, 3).astype(np.float64)
    rec = np.frombuffer(data[end + 12 * nv:], dtype=np.dtype([('n', 'u1'), ('i', '<i4', 3)]), count=nf)
    return V[rec['i']]

def read_any(path):
    e = os.path.splitext(path)[1].lower()
    return {'.stl': read_stl, '.off': read_off, '.obj': read_obj, '.ply': read_ply}[e](path)

def weld(T, tol=1e-6):
    P = T.reshape(-1, 3)
    scale = max(np.ptp(P, axis=0).max(), 1e-12)
    q = np.round(P / (tol * scale)).astype(np.int64)
    _, inv = np.unique(q, axis=0, return_inverse=True)
    F = inv.reshape(-1, 3)
    V = np.zeros((inv.max() + 1, 3)); V[inv] = P
    return V, F

def stats(T):
    V, F = weld(T)
    F = F[(F[:,0]!=F[:,1])&(F[:,1]!=F[:,2])&(F[:,0]!=F[:,2])]
    E = np.sort(np.concatenate([F[:,[0,1]],F[:,[1,2]],F[:,[2,0]]]), axis=1)
    u, c = np.unique(E, axis=0, return_counts=True)
    bnd = u[c == 1]; nm = (c > 2).sum()
    # boundary loops count via union find on boundary edges
    parent = {}
    def find(a):
        while parent.get(a, a) != a:
            parent[a] = parent.get(parent[a], parent[a]); a = parent[a]
        return a
    for a, b in bnd:
        ra, rb = find(a), find(b)
        if ra != rb: parent[ra] = rb
    loops = len({find(a) for a in np.unique(bnd)}) if len(bnd) else 0
    # components
    par = np.arange(len(V))
    def f2(a):
        r = a
        while par[r] != r: r = par[r]
        while par[a] != r: par[a], a = r, par[a]
        return r
    for a, b in u:
        ra, rb = f2(a), f2(b)
        if ra != rb: par[ra] = rb
    comps = len({f2(i) for i in np.unique(F)})
    area = 0.5 * np.linalg.norm(np.cross(T[:,1]-T[:,0], T[:,2]-T[:,0]), axis=1).sum()
    return dict(tris=len(T), verts=len(V), bbox_min=T.reshape(-1,3).min(0).round(3).tolist(),
                bbox_max=T.reshape(-1,3).max(0).round(3).tolist(), boundary_edges=len(bnd),
                boundary_loops=loops, nonmanifold_edges=int(nm), components=comps, area=round(area, 2))

def write_stl(path, T, name=b'spira corpus'):
    T = np.asarray(T, dtype=np.float64)
    n = np.cross(T[:,1]-T[:,0], T[:,2]-T[:,0])
    l = np.linalg.norm(n, axis=1, keepdims=True); l[l == 0] = 1; n = n / l
    rec = np.zeros(len(T), dtype=np.dtype([('n', '<f4', 3), ('v', '<f4', (3, 3)), ('a', '<u2')]))
    rec['n'] = n; rec['v'] = T
    with open(path, 'wb') as f:
        f.write(name.ljust(80, b' ')[:80]); f.write(struct.pack('<I', len(T))); f.write(rec.tobytes())

if __name__ == '__main__':
    for p in sys.argv[1:]:
        print(os.path.basename(p), stats(read_any(p)))

