import sys
import numpy as np
from scipy.io import netcdf_file
path = sys.argv[1]; t0 = float(sys.argv[2]); t1 = float(sys.argv[3])
f = netcdf_file(path, 'r', mmap=False)
names = [b''.join(r).decode().strip() for r in f.variables['name_nod_var'][:]]
V = {n: f.variables['vals_nod_var%d' % (i + 1)][:] for i, n in enumerate(names)}
T = f.variables['time_whole'][:]
x0 = f.variables['coordx'][:]; y0 = f.variables['coordy'][:]
k0 = int(np.argmin(abs(T - t0))); k1 = int(np.argmin(abs(T - t1)))
def liq(k):
    return V['porosity'][k] * V['saturation'][k] * V['volume'][k]
dl = liq(k1) - liq(k0)
dn = V['porosity'][k1] - V['porosity'][k0]
print('total liquid volume change', dl.sum(), 'n points', len(dl))
x = x0 + V['displ_x'][k0]; y = y0 + V['displ_y'][k0]
for thr in [0.005, 0.01, 0.02, 0.05]:
    s = dn > thr
    print('dn>%g: %d points, liquid change %.5f, volume change %.5f' % (thr, s.sum(), dl[s].sum(), (V['volume'][k1]-V['volume'][k0])[s].sum()))
s = dn > 0.01
order = np.argsort(-dn)
for p in order[:40]:
    print('x=%.2f y=%.2f dn=%.3f n=%.3f pL=%.2f ps=%d' % (x[p], y[p], dn[p], V['porosity'][k1][p], V['pressure_liquid'][k1][p]/1e3, V['plastic_state'][k1][p]))
