"""The crest history and the first overturning of a PySPH 2D+t run (twodt.py) beside bowwave's (eta.csv).

    python crest_from_outputs.py PYSPH_OUT BOWWAVE_RUN_DIR [--hull hulls/athena.csv] [--x0 X]

BOWWAVE_RUN_DIR: a `bowwave twodt` output folder or a study's case folder (eta.csv, series.csv, metrics.json).
--x0: where the PySPH run started (twodt.py's --x0), if not at the bowwave run's first x/L. If the bowwave run
wrote VTK frames (`twodt --vtk`: BOWWAVE_RUN_DIR/series.pvd and its frame_*.vtp), the same overturning test is applied to its frames
too, so that the two codes' first overturning is read by one criterion (bowwave's own plunge, a closed cavity
with a circulation threshold, is printed beside it).

Crest: the highest fluid particle, z/D, at each output x/L (bowwave: the largest eta/D of eta.csv at that x,
its free-surface height profile). Overturning (PySPH only; bowwave's plunge criteria are in its metrics.json):
the first output where, seaward of the crest, a column of width 2 dx holds at least 5 fluid particles above
an empty gap of at least 3 dx over other fluid (a jet over air). Prints both histories and the differences at common x.
"""
import glob
import json
import os
import sys
import numpy as np


def header(path):
    meta = {}
    for line in open(path):
        if not line.startswith('#'):
            break
        k, _, v = line[1:].partition(':')
        meta[k.strip()] = v.strip()
    return meta


def overturned(y, z, dx):
    """Seaward of the crest, a column of width 2 dx holding at least 5 fluid particles above a vertical gap of
    3 dx over fluid: a jet over air, not a stray drop or the sheet on the hull."""
    if len(z) == 0:
        return False
    y_crest = y[np.argmax(z)]
    sea = y > y_crest
    y, z = y[sea], z[sea]
    cols = np.floor(y / (2 * dx)).astype(int)
    for c in np.unique(cols):
        zz = np.sort(z[cols == c])
        if len(zz) < 7:
            continue
        gaps = np.diff(zz)
        k = int(np.argmax(gaps))
        if gaps[k] > 3 * dx and len(zz) - (k + 1) >= 5:
            return True
    return False


def option(name, default):
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv else default


def vtp_points(path):
    """Points (x, y) of a bowwave 2D+t .vtp frame (ASCII; across the tank, up; units of L)."""
    text = open(path).read()
    start = text.index('<Points>')
    body = text[text.index('>', text.index('<DataArray', start)) + 1:text.index('</DataArray>', start)]
    return np.array(body.split(), dtype=float).reshape(-1, 3)[:, :2]


def bowwave_overturn(case_dir, dx):
    """First bowwave frame (`series.pvd`, whose times are x/L) where the same test finds a jet over air."""
    pvd = os.path.join(case_dir, 'series.pvd')
    if not os.path.exists(pvd):
        return None
    import re
    for x, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(pvd).read()):
        p = vtp_points(os.path.join(case_dir, f))
        y, z = p[:, 0], p[:, 1]
        if overturned(y[z > 0], z[z > 0], dx):
            return float(x)
    return None


def main():
    out, case_dir = sys.argv[1], sys.argv[2]
    hull = option('--hull', 'hulls/athena.csv')
    meta = header(hull)
    d = float(meta['draft_m']) / float(meta['length_m'])
    fr = json.load(open(os.path.join(case_dir, 'metrics.json')))['fr']
    x0 = float(np.loadtxt(os.path.join(case_dir, 'series.csv'), delimiter=',', skiprows=1, max_rows=1)[0])
    x0 = float(option('--x0', x0))
    files = sorted(glob.glob(os.path.join(out, '*.npz')), key=lambda f: int(f.rsplit('_', 1)[1].split('.')[0]))
    ours = []
    first_overturn = None
    for f in files:
        data = np.load(f, allow_pickle=True)
        t = float(data['solver_data'][()]['t'])
        fl = data['particles'][()]['fluid']['arrays']
        y, z = fl['x'], fl['y']
        dx = np.sqrt(fl['m'][0])
        x = x0 + fr * t
        ours.append((x, z.max() / d))
        if first_overturn is None and overturned(y[z > 0], z[z > 0], dx):
            first_overturn = x
    eta = np.loadtxt(os.path.join(case_dir, 'eta.csv'), delimiter=',', skiprows=1)
    xs = np.unique(eta[:, 0])
    theirs = [(x, eta[eta[:, 0] == x, 2].max()) for x in xs]
    # The same measure as PySPH's where bowwave wrote frames: its highest particle.
    top = []
    pvd = os.path.join(case_dir, 'series.pvd')
    if os.path.exists(pvd):
        import re
        for xf, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(pvd).read()):
            top.append((float(xf), vtp_points(os.path.join(case_dir, f))[:, 1].max() / d))
    interp = lambda pts, x: np.interp(x, [p[0] for p in pts], [p[1] for p in pts], left=np.nan, right=np.nan) if pts else np.nan
    print('x/L      PySPH highest particle z/D   bowwave highest particle z/D   bowwave crest eta/D (eta.csv)')
    for x, c in ours:
        print(f'{x:.4f}   {c:.4f}                       {interp(top, x):.4f}                         {interp(theirs, x):.4f}')
    print(f'PySPH: first overturning (jet over a gap of 3 dx) at x/L = {first_overturn}')
    m = json.load(open(os.path.join(case_dir, 'metrics.json')))
    print(f"bowwave: first overturning, same test on its VTK frames, at x/L = "
          f"{bowwave_overturn(case_dir, m.get('dx_over_l', dx))}")
    p = m.get('plunge') or {}
    print(f"bowwave: plunge (its own criteria) at x/L = {p.get('x_plunge_over_l')}")


if __name__ == '__main__':
    main()
