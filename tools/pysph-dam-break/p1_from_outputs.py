"""P1 and the tongue's depth from particle snapshots, the same reading for PySPH and bowwave.

P1: at 5 points on the right wall (x = L, y = 0.115 ... 0.205 m, Buchner's 90 mm sensor centred at 0.16 m),
the Shepard average of the fluid particles' pressure with a Gaussian of width 1.33 dx cut at 3 of it; a point
whose weight sum (sum W V) is below 0.1 reads 0. Only fluid particles count, so the wall model of either
code does not enter the reading.

Usage: python p1_from_outputs.py pysph OUTDIR RES     (PySPH .npz outputs)
       python p1_from_outputs.py bowwave VTKDIR RES   (bowwave's vtk/ folder, `vtk_every` = 0.005 s)
Prints a line per snapshot from t* = 1.8 (P1, the front, and the free-surface height over x = 2.4 ... 3.2 m)
and the mean P1 over quarter windows of t* from 2.5 to 4.0.
"""
import glob
import re
import sys

import numpy as np

from snapshots import pysph_snapshots

H, L, G, RHO = 0.6, 3.2196, 9.81, 1000.0
T_SCALE = np.sqrt(H / G)
PROFILE_X = np.array([2.4, 2.7, 3.0, 3.1, 3.2])


def p1(x, y, p, vol, hs):
    vals = []
    for yk in np.linspace(0.115, 0.205, 5):
        r2 = ((x - L) ** 2 + (y - yk) ** 2) / hs ** 2
        m = r2 < 9.0
        w = np.exp(-r2[m]) / (np.pi * hs * hs)
        sw = np.sum(w * vol[m])
        vals.append(np.sum(p[m] * w * vol[m]) / sw if sw > 0.1 else 0.0)
    return np.mean(vals) / (RHO * G * H)


def surface(x, y, dx):
    return [np.max(y[np.abs(x - xc) < dx]) / H if np.any(np.abs(x - xc) < dx) else 0.0 for xc in PROFILE_X]


def read_vtp(fn):
    text = open(fn).read()
    arrays = {}
    for m in re.finditer(r'<DataArray([^>]*)>(.*?)</DataArray>', text, re.S):
        name = re.search(r'Name="([^"]*)"', m.group(1))
        arrays[name.group(1) if name else 'Points'] = np.array(m.group(2).split(), dtype=float)
    return arrays


def pysph_frames(folder):
    for t, fl in pysph_snapshots(folder):
        yield t, fl.x, fl.y, fl.p, fl.m / fl.rho


def bowwave_frames(folder, dx):
    pvd = open(glob.glob(folder + '/*.pvd')[0]).read()
    for t, f in re.findall(r'timestep="([^"]*)"[^>]*file="([^"]*)"', pvd):
        a = read_vtp(folder + '/' + f)
        pts = a['Points'].reshape(-1, 3)
        yield float(t), pts[:, 0], pts[:, 1], a['pressure'], np.full(len(pts), dx * dx)


def main():
    code, folder, res = sys.argv[1], sys.argv[2], float(sys.argv[3])
    dx = H / res
    frames = pysph_frames(folder) if code == 'pysph' else bowwave_frames(folder, dx)
    rows = []
    print('t*      P1     front/H   surface y/H at x =', PROFILE_X, 'm')
    for t, x, y, p, vol in frames:
        ts = t / T_SCALE
        if ts < 1.8:
            continue
        v = p1(x, y, p, vol, 1.33 * dx)
        rows.append((ts, v))
        front = np.max(x[y < 0.1]) / H if np.any(y < 0.1) else 0.0
        print('%.3f  %6.3f  %6.3f   ' % (ts, v, front) + ' '.join('%.3f' % q for q in surface(x, y, dx)))
    rows = np.array(rows)
    for a in np.arange(2.5, 4.0, 0.25):
        m = (rows[:, 0] >= a) & (rows[:, 0] < a + 0.25)
        print('window t* %.2f-%.2f: mean P1 %.3f' % (a, a + 0.25, rows[m, 1].mean()))


if __name__ == '__main__':
    main()
