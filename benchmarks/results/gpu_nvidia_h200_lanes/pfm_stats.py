import sys, hashlib, numpy as np
def pfm(path):
    with open(path, 'rb') as f:
        kind = f.readline().strip(); w, h = map(int, f.readline().split()); scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype='<f4' if scale < 0 else '>f4')
    return data.reshape(h, w, 3 if kind == b'PF' else 1), hashlib.md5(data.tobytes()).hexdigest()[:8]
try:
    a, h = pfm(sys.argv[1])
except Exception as e:
    print('no image'); sys.exit()
bad = ~np.isfinite(a)
lum = a.mean(axis=2)
fin = np.isfinite(lum)
print('mean %.5f nonfinite %d md5 %s' % (lum[fin].mean() if fin.any() else float('nan'), int(bad.any(axis=2).sum()), h), end='')
if len(sys.argv) > 2:
    b, _ = pfm(sys.argv[2]); lb = b.mean(axis=2); m = fin & np.isfinite(lb)
    d = np.abs(lum - lb); print(' vs %s: ratio %.4f maxdiff %.4g pixels differing %d' % (sys.argv[2].split('/')[-1], lum[m].mean() / max(lb[m].mean(), 1e-12), d[m].max(), int((d[m] > 0).sum())), end='')
print()
