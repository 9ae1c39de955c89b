"""P1's centre read from particle snapshots, one reading for every code, and its error against TrixiParticles'
converged run: the measure of the dam-break speed-accuracy chart (issue #34), for the peers drawn on it.

    python p1c_error.py CODE FOLDER --res N --cpu S [--steps K] [--variant NAME] [--label CODE_NAME] [--peers FILE]

CODE is the format of FOLDER:
  bowwave       a `bowwave run` vtk/ folder (its .pvd and frames; H = 0.6 m, tank 5.366 H)
  pysph         a PySPH output folder of ../pysph-dam-break/dam_break.py (.npz; H = 0.6 m)
  dualsphysics  the CSV files of DualSPHysics' PartVTK (`-savecsv DIR/PartFluid -onlytype:-all,+fluid
                -vars:-all,+press,+mass,+rhop`; H = 1 m, tank 5.366 H; each file carries its time)

The reading, the same for every code and independent of its wall model: at three points on the right wall
spanning TrixiParticles' 8.4 mm sensor (y = 0.2597-0.2737 H, centred on Buchner's P1 at 0.2667 H), the Shepard
average of the fluid particles' pressure with a Gaussian of width 1.33 dx cut at 3 of it (dx = H/N, the run's
spacing), a point with fewer than 3 fluid particles within that cut reading 0; P1c is the mean of the three, in
rho0 g H. Codes keep their water at different distances from the wall line (bowwave and PySPH about dx/2,
DualSPHysics' boundary particles about 2 dx), and the Shepard average reads what is nearest. The error
is the mean over the snapshots with t sqrt(g/H) in [2, 7] of |P1c - TrixiParticles' H/dx 400 run|, interpolated
linearly in time (data/reference/trixiparticles_wcsph_damBreak_P4_H600_80_400.csv), as bowwave's own check
computes it from its sensor (src/validation/dam_break.rs, `p1c_converged_label`).

Prints the error; with --peers, replaces or adds the row (CODE_NAME, VARIANT, N) of FILE, a speed_accuracy.csv
that `bowwave chart speed-accuracy --peers FILE` draws beside bowwave's runs. --cpu is the run's user + system
CPU seconds (e.g. from /usr/bin/time -f '%U %S'), as the chart counts bowwave's.
"""
import csv
import glob
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
# The dam break's PySPH cross-check reads bowwave's VTK frames and PySPH's outputs; its readers are used here.
sys.path.insert(0, os.path.join(HERE, '..', 'pysph-dam-break'))
from p1_from_outputs import read_vtp  # noqa: E402
from snapshots import pysph_snapshots  # noqa: E402
REFERENCE = os.path.join(HERE, '..', '..', 'data', 'reference', 'trixiparticles_wcsph_damBreak_P4_H600_80_400.csv')
# The label bowwave's check carries (src/validation/dam_break.rs, p1c_converged_label): the chart refuses peers
# whose label differs.
QUANTITY = ('P1c (8.4 mm) mean |p-p_ref|/(rho g H), t* in [2,7], vs TrixiParticles H/dx=400 (converged)')
TANK = 5.366            # tank length / H
SENSOR = (0.1558 / 0.6, 0.1642 / 0.6)  # TrixiParticles' P4, in H
G = 9.81
# A point reads 0 with fewer fluid particles than this within its 3 widths (4 dx): a drop is not the wall's water.
# No threshold on the weight sum: DualSPHysics' boundary particles keep the fluid about 2 dx off the wall line
# (H/dx 25: the nearest particle at the sensor's height 0.08 H from it), where a Gaussian of width 1.33 dx sums to
# about 0.02, so such a threshold would read that code's wall as dry.
MIN_PARTICLES = 3
HEADER = ['case', 'code', 'variant', 'res', 'particles', 'steps', 'cpu_seconds', 'error', 'pareto', 'stopped',
          'quantity']


def option(name, default=None, kind=str):
    if name in sys.argv:
        k = sys.argv.index(name)
        value = kind(sys.argv[k + 1])
        del sys.argv[k:k + 2]
        return value
    return default


def bowwave_snapshots(folder, dx):
    """(t in s, x, y, p, volume) of a bowwave vtk/ folder; H = 0.6 m, rho0 = 1000."""
    pvd = open(glob.glob(os.path.join(folder, '*.pvd'))[0]).read()
    for t, name in re.findall(r'timestep="([^"]*)"[^>]*file="([^"]*)"', pvd):
        a = read_vtp(os.path.join(folder, name))
        pts = a['Points'].reshape(-1, 3)
        yield float(t), pts[:, 0], pts[:, 1], a['pressure'], np.full(len(pts), dx * dx)


def pysph_frames(folder):
    """(t in s, x, y, p, volume) of a PySPH output folder."""
    for t, fl in pysph_snapshots(folder):
        yield float(t), fl.x, fl.y, fl.p, fl.m / fl.rho


def dualsphysics_snapshots(folder):
    """PartVTK's CSV files: a line of names starting `TimeStep`, its values (the time in s first), then the
    particles under a line of names starting `Pos.x` (semicolon or comma separated)."""
    files = [f for f in glob.glob(os.path.join(folder, '*.csv')) if re.search(r'_(\d+)\.csv$', f)]
    for f in sorted(files, key=lambda f: int(re.search(r'_(\d+)\.csv$', f).group(1))):
        lines = open(f).read().splitlines()
        sep = ';' if ';' in lines[0] else ','
        if not lines[0].startswith('TimeStep'):
            sys.exit(f'{f}: expected a first line starting `TimeStep` (PartVTK -savecsv)')
        t = float(lines[1].split(sep)[0])
        start = next(i for i, line in enumerate(lines) if line.startswith('Pos.x'))
        names = [n.strip().split(' ')[0] for n in lines[start].split(sep)]
        a = np.array([[float(v) for v in line.split(sep) if v.strip()] for line in lines[start + 1:] if line.strip()])
        col = {n: i for i, n in enumerate(names)}
        for need in ('Pos.x', 'Pos.z', 'Press', 'Mass', 'Rhop'):
            if need not in col:
                sys.exit(f'{f}: no column `{need}`; run PartVTK with -vars:-all,+press,+mass,+rhop')
        yield t, a[:, col['Pos.x']], a[:, col['Pos.z']], a[:, col['Press']], a[:, col['Mass']] / a[:, col['Rhop']]


def p1c(x, y, p, vol, height, dx, rho0):
    hs = 1.33 * dx
    wall = TANK * height
    vals = []
    for yk in np.linspace(SENSOR[0] * height, SENSOR[1] * height, 3):
        r2 = ((x - wall) ** 2 + (y - yk) ** 2) / hs ** 2
        m = r2 < 9.0
        w = np.exp(-r2[m]) / (np.pi * hs * hs)
        sw = np.sum(w * vol[m])
        vals.append(np.sum(p[m] * w * vol[m]) / sw if np.count_nonzero(m) >= MIN_PARTICLES else 0.0)
    return np.mean(vals) / (rho0 * G * height)


def reference():
    lines = [line for line in open(REFERENCE) if not line.startswith('#')]
    assert lines[0].strip() == 't_s,p_Pa_H_over_dx_80,p_Pa_H_over_dx_400', REFERENCE
    a = np.array([[float(v) for v in line.split(',')] for line in lines[1:] if line.strip()])
    return a[:, 0] * np.sqrt(G / 0.6), a[:, 2] / (1000.0 * G * 0.6)


def main():
    res = option('--res', kind=float)
    cpu = option('--cpu', kind=float)
    steps = option('--steps', 0, int)
    variant = option('--variant', 'default')
    peers = option('--peers')
    code, folder = sys.argv[1], sys.argv[2]
    label = option('--label', code)
    if res is None or cpu is None:
        sys.exit(__doc__)
    if code == 'bowwave':
        height, rho0 = 0.6, 1000.0
        snaps = bowwave_snapshots(folder, height / res)
    elif code == 'pysph':
        height, rho0 = 0.6, 1000.0
        snaps = pysph_frames(folder)
    elif code == 'dualsphysics':
        height, rho0 = 1.0, 1000.0
        snaps = dualsphysics_snapshots(folder)
    else:
        sys.exit(f'{code}: expected bowwave, pysph or dualsphysics')
    dx = height / res
    tr, pr = reference()
    t_scale = np.sqrt(height / G)
    errors, particles = [], 0
    for t, x, y, p, vol in snaps:
        ts = t / t_scale
        particles = len(x)
        if 2.0 <= ts <= 7.0 and tr[0] <= ts <= tr[-1]:
            errors.append(abs(p1c(x, y, p, vol, height, dx, rho0) - np.interp(ts, tr, pr)))
    if not errors:
        sys.exit(f'{folder}: no snapshot with t sqrt(g/H) in [2, 7]')
    error = float(np.mean(errors))
    print(f'{label} {variant} H/dx {res:g}: {len(errors)} snapshots in t* [2, 7], mean |P1c - TrixiParticles 400| '
          f'= {error:.4f} rho g H, {particles} fluid particles, {cpu:.1f} CPU s')
    if peers:
        rows = []
        if os.path.exists(peers):
            with open(peers) as f:
                rows = [r for r in csv.DictReader(f)
                        if not (r['code'] == label and r['variant'] == variant and float(r['res']) == res)]
        rows.append(dict(case='dam-break', code=label, variant=variant, res=f'{res:g}', particles=particles,
                         steps=steps, cpu_seconds=f'{cpu:.3f}', error=repr(error), pareto='false', stopped='',
                         quantity=QUANTITY))
        rows.sort(key=lambda r: (r['code'], r['variant'], float(r['res'])))
        tmp = peers + '.tmp'
        with open(tmp, 'w', newline='') as f:
            w = csv.DictWriter(f, fieldnames=HEADER)
            w.writeheader()
            w.writerows(rows)
        os.replace(tmp, peers)
        print(f'wrote {peers}')


if __name__ == '__main__':
    main()
