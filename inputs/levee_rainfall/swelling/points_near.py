import sys
import numpy as np
from scipy.io import netcdf_file
path, t, px, py, r = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
f = netcdf_file(path, 'r', mmap=False)
names = [b''.join(q).decode().strip() for q in f.variables['name_nod_var'][:]]
V = {n: f.variables['vals_nod_var%d' % (i + 1)][:] for i, n in enumerate(names)}
T = f.variables['time_whole'][:]
k = int(np.argmin(abs(T - t)))
x = f.variables['coordx'][:] + V['displ_x'][k]; y = f.variables['coordy'][:] + V['displ_y'][k]
sel = np.where(np.hypot(x - px, y - py) < r)[0]
sel = sel[np.lexsort((x[sel], -np.round(y[sel], 2)))]
print('t', T[k])
for p in sel:
    print('id=%4d x=%.3f y=%.3f n=%.3f pL=%7.2f S=%.5f ps=%d sxx=%6.2f syy=%6.2f sxy=%6.2f vLy=%.2e vSy=%.2e k=%.2e' % (V['point_id'][k][p], x[p], y[p], V['porosity'][k][p], V['pressure_liquid'][k][p]/1e3, V['saturation'][k][p], V['plastic_state'][k][p], V['stress_eff_xx'][k][p]/1e3, V['stress_eff_yy'][k][p]/1e3, V['stress_eff_xy'][k][p]/1e3, V['velocity_liquid_y'][k][p], V['velocity_solid_y'][k][p], V['conductivity'][k][p]))
