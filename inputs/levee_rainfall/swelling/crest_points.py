import sys
import numpy as np
from scipy.io import netcdf_file
path = sys.argv[1]
t0 = float(sys.argv[2]) if len(sys.argv) > 2 else 3.0
f = netcdf_file(path, 'r', mmap=False)
names = [b''.join(r).decode().strip() for r in f.variables['name_nod_var'][:]]
V = {n: f.variables['vals_nod_var%d' % (i + 1)][:] for i, n in enumerate(names)}
T = f.variables['time_whole'][:]
x0 = f.variables['coordx'][:]; y0 = f.variables['coordy'][:]
k0 = int(np.argmin(abs(T - t0)))
ids = V['point_id']
# positions at rain start
x = x0 + V['displ_x'][k0]; y = y0 + V['displ_y'][k0]
ytop = y[x < 0.3].max()
sel = np.where((x < 0.3) & (y > ytop - 0.3))[0]
print('t0', T[k0], 'ytop', ytop, 'n', len(sel))
for k in range(0, len(T), max(1, len(T)//25)):
    if T[k] < t0 - 1: continue
    xx = x0 + V['displ_x'][k]; yy = y0 + V['displ_y'][k]
    print('%6.1f n=%.3f [%.3f..%.3f] pL=%.2f..%.2f kPa S=%.4f dy=%.3f ps=%s sxx=%.2f syy=%.2f szz=%.2f vol=%.5f' % (
        T[k], V['porosity'][k][sel].mean(), V['porosity'][k][sel].min(), V['porosity'][k][sel].max(),
        V['pressure_liquid'][k][sel].min()/1e3, V['pressure_liquid'][k][sel].max()/1e3,
        V['saturation'][k][sel].mean(), (yy[sel]-y[sel]).mean(),
        ''.join(str(int(s)) for s in V['plastic_state'][k][sel]),
        V['stress_eff_xx'][k][sel].mean()/1e3, V['stress_eff_yy'][k][sel].mean()/1e3, V['stress_eff_zz'][k][sel].mean()/1e3,
        V['volume'][k][sel].sum()))
