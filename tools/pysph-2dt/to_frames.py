"""Writes a 2D+t run's particle outputs as the frames `bowwave frames` measures (issue #30's cross-check: the
plunge and the jet of both codes by bowwave's one set of criteria).

    python to_frames.py pysph PYSPH_OUT OUT --x0 X --fr F [--from-x A] [--to-x B]
    python to_frames.py bowwave BOWWAVE_RUN_DIR OUT --dx D --c0 C [--from-x A] [--to-x B]
    bowwave frames OUT --hull H --fr F --dx D --width W --depth Z

pysph: twodt.py's outputs (twodt_*.npz; the section at x/L = x0 + Fr t, twodt.py's --x0). bowwave: a
`bowwave twodt --vtk` folder (series.pvd and its frame_*.vtp); a VTK frame has no volumes, so each particle's
is dx^2 rho0/rho with rho/rho0 = 1 + p/c0^2 (the linear state equation; exact for uniform spacing,
`--ratio 1`, only). OUT gets frames.csv (x_over_l,file) and one CSV per frame (y,z,u,v,volume in units of L and
sqrt(gL)), as docs/reference/twodt.md ("Another code's frames") defines them.
"""
import glob
import os
import re
import sys

import numpy as np


def option(name, default=None, kind=float):
    if name in sys.argv:
        return kind(sys.argv[sys.argv.index(name) + 1])
    return default


def pysph_frames(src, x0, fr):
    from pysph.solver.utils import load
    for path in sorted(glob.glob(os.path.join(src, 'twodt_*.npz'))):
        data = load(path)
        f = data['arrays']['fluid']
        x = x0 + fr * float(data['solver_data']['t'])
        yield x, np.column_stack([f.x, f.y, f.u, f.v, f.m / f.rho])


def vtp_arrays(path):
    text = open(path).read()
    pts = re.search(r'<Points>.*?<DataArray[^>]*>(.*?)</DataArray>', text, re.S).group(1)
    pts = np.array(pts.split(), float).reshape(-1, 3)

    def named(name, comps):
        m = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
        return np.array(m.group(1).split(), float).reshape(-1, comps)
    return pts, named('velocity', 3), named('pressure', 1)[:, 0]


def bowwave_frames(src, dx, c0):
    pvd = open(os.path.join(src, 'series.pvd')).read()
    for t, name in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd):
        pts, vel, p = vtp_arrays(os.path.join(src, name))
        vol = dx * dx / (1.0 + p / (c0 * c0))
        yield float(t), np.column_stack([pts[:, 0], pts[:, 1], vel[:, 0], vel[:, 1], vol])


def main():
    kind, src, out = sys.argv[1:4]
    lo, hi = option('--from-x', -np.inf), option('--to-x', np.inf)
    if kind == 'pysph':
        frames = pysph_frames(src, option('--x0'), option('--fr'))
    elif kind == 'bowwave':
        frames = bowwave_frames(src, option('--dx'), option('--c0'))
    else:
        sys.exit(f'{kind}: expected pysph or bowwave')
    os.makedirs(out, exist_ok=True)
    rows = []
    for k, (x, a) in enumerate(frames):
        if not lo <= x <= hi:
            continue
        name = f'frame_{k:05d}.csv'
        if not os.path.exists(os.path.join(out, name)):  # a frame already written is kept (an added run's tail)
            np.savetxt(os.path.join(out, name), a, delimiter=',', header='y,z,u,v,volume', comments='',
                       fmt='%.9e')
        rows.append((x, name))
    with open(os.path.join(out, 'frames.csv'), 'w') as f:
        f.write('x_over_l,file\n')
        for x, name in rows:
            f.write(f'{x:.9f},{name}\n')
    print(f'wrote {len(rows)} frames to {out}')


if __name__ == '__main__':
    main()
