import sys
import numpy as np
from scipy.io import netcdf_file
path, pid = sys.argv[1], int(sys.argv[2])
t0, t1 = float(sys.argv[3]), float(sys.argv[4])
f = netcdf_file(path, 'r', mmap=False)
names = [b''.join(q).decode().strip() for q in f.variables['name_nod_var'][:]]
V = {n: f.variables['vals_nod_var%d' % (i + 1)][:] for i, n in enumerate(names)}
T = f.variables['time_whole'][:]
x0 = f.variables['coordx'][:]; y0 = f.variables['coordy'][:]
for k in range(len(T)):
    if T[k] < t0 or T[k] > t1: continue
    p = int(np.where(V['point_id'][k] == pid)[0][0])
    print('t=%5.1f x=%.4f y=%.4f V=%.6f n=%.4f pL=%7.2f ps=%d s=(%6.2f %6.2f %6.2f %6.2f) vS=(%.2e %.2e) eps_dev=%.4f eps_p=%.4f' % (T[k], x0[p] + V['displ_x'][k][p], y0[p] + V['displ_y'][k][p], V['volume'][k][p], V['porosity'][k][p], V['pressure_liquid'][k][p] / 1e3, V['plastic_state'][k][p], V['stress_eff_xx'][k][p]/1e3, V['stress_eff_yy'][k][p]/1e3, V['stress_eff_zz'][k][p]/1e3, V['stress_eff_xy'][k][p]/1e3, V['velocity_solid_x'][k][p], V['velocity_solid_y'][k][p], V['deviatoric_strain'][k][p], V['plastic_strain'][k][p]))
