"""Crest and plunge of one code at several spacings, read from `bowwave frames` outputs (issue #30: does the
difference between two codes shrink as the spacing does, and towards which value?).

    python convergence.py LABEL DX DIR [DX DIR ...] [--at 0.08,0.10,0.12,0.14] [--first-crest-to 0.16]

Each DIR is a `bowwave frames` output (crest.csv, plunge.json if a plunge was found), the DX its spacing dx/L,
listed from the coarsest to the finest in ratio 2. Prints, per spacing, the crest height/D at the --at x/L
(linear between frames), the first crest (the largest crest up to --first-crest-to) and the plunge point; with
three spacings, the observed order p = log2((f1 - f2)/(f2 - f3)) and the Richardson value f3 + (f3 - f2)/(2^p - 1)
of each (thesis appendix C), or why there is none (the differences change sign: no monotone convergence).
"""
import json
import math
import os
import sys

import numpy as np


def option(name, default):
    if name in sys.argv:
        k = sys.argv.index(name)
        value = sys.argv[k + 1]
        del sys.argv[k:k + 2]
        return value
    return default


def read(dir_, at, first_to):
    a = np.loadtxt(os.path.join(dir_, 'crest.csv'), delimiter=',', skiprows=1, ndmin=2)
    x, c = a[:, 0], a[:, 1]
    row = {f'crest@{v:g}': float(np.interp(v, x, c)) if x[0] <= v <= x[-1] else math.nan for v in at}
    m = x <= first_to
    k = int(np.argmax(np.where(m, c, -np.inf)))
    row['first crest'] = float(c[k])
    row['its x/L'] = float(x[k])
    path = os.path.join(dir_, 'plunge.json')
    p = (json.load(open(path)) if os.path.exists(path) else None) or {}
    for key, name in [('x_plunge_over_l', 'x_plunge/L'), ('y_plunge_over_l', 'y_plunge/L'),
                      ('h_pj_over_d', 'H_pj/D'), ('gamma_over_ud', 'Gamma/(UD)'), ('jet_particles', 'jet particles')]:
        row[name] = float(p[key]) if key in p else math.nan
    return row


def richardson(f1, f2, f3):
    d12, d23 = f1 - f2, f2 - f3
    if not all(map(math.isfinite, (f1, f2, f3))) or d23 == 0 or d12 * d23 <= 0:
        return 'not monotone'
    p = math.log2(d12 / d23)
    if p <= 0:
        return f'diverging (p {p:.2f})'
    return f'p {p:.2f}, limit {f3 - d23 / (2 ** p - 1):.4f}'


def main():
    at = [float(v) for v in option('--at', '0.08,0.10,0.12,0.14').split(',')]
    first_to = float(option('--first-crest-to', '0.16'))
    label, rest = sys.argv[1], sys.argv[2:]
    if len(rest) < 2 or len(rest) % 2:
        sys.exit(__doc__)
    runs = [(float(rest[k]), read(rest[k + 1], at, first_to)) for k in range(0, len(rest), 2)]
    keys = list(runs[0][1])
    print(f'{label}: ' + ', '.join(f'dx/L {dx:g}' for dx, _ in runs))
    for key in keys:
        values = [r[key] for _, r in runs]
        line = f'  {key:>14}: ' + '  '.join(f'{v:8.4f}' for v in values)
        if len(values) >= 3 and key not in ('its x/L', 'jet particles'):
            line += '   ' + richardson(*values[-3:])
        print(line)


if __name__ == '__main__':
    main()
