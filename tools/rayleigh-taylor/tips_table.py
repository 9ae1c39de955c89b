"""The interface tips of three Rayleigh-Taylor runs (`bowwave run cases/rayleigh-taylor.toml --res R`, R = 20, 40,
80) at t = 1..5, with the order (C.2) and Richardson estimate of `bowwave converge` (the same formulas, read from
finished runs' series instead of running them again). Outside the product.

    python tips_table.py DIR    # DIR/res20, DIR/res40, DIR/res80 hold the runs' outputs
"""
import sys
import csv, math
def series(r):
    rows = list(csv.DictReader(open(f'{sys.argv[1]}/res{r}/rayleigh-taylor_series.csv')))
    t = [float(x['t']) for x in rows]
    return t, {c: [float(x[c]) for x in rows] for c in ('spike_y', 'bubble_y')}
def at(t, v, T):
    for i in range(1, len(t)):
        if t[i] >= T:
            w = (T - t[i-1]) / (t[i] - t[i-1]); return v[i-1] + w * (v[i] - v[i-1])
    return v[-1]
S = {r: series(r) for r in (20, 40, 80)}
print('| quantity | t√(g/H′) | H′/dx 20 | 40 | 80 | order (C.2) | Richardson |')
print('|---|---|---|---|---|---|---|')
for c in ('spike_y', 'bubble_y'):
    for T in (1, 2, 3, 4, 5):
        f = [at(S[r][0], S[r][1][c], T) for r in (20, 40, 80)]
        d1, d2 = f[1] - f[0], f[2] - f[1]
        if d1 * d2 > 0 and abs(d2) < abs(d1):
            C = math.log(abs(d1) / abs(d2)) / math.log(2); ext = f[2] + d2 / (2**C - 1)
            o, e = f'{C:.2f}', f'{ext:.4f} ± {1.25*abs(ext-f[2]):.4f}'
        else:
            o, e = 'none (differences %.4f, %.4f)' % (d1, d2), '–'
        print(f'| {c} | {T} | {f[0]:.4f} | {f[1]:.4f} | {f[2]:.4f} | {o} | {e} |')
