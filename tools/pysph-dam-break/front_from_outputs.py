"""The Martin-Moyce front from PySPH's snapshots of `dam_break.py --case mm`, read as bowwave reads its own:
the largest x over the fluid plus dx/2 (`diagnostics::front`), against Martin & Moyce's Table 2 (n^2 = 2).

Usage: python front_from_outputs.py OUTDIR RES [BOWWAVE_SERIES_CSV]
Prints Z = x/a at each experimental time T = n t sqrt(g/a) <= 2.5 (linear between snapshots), its relative
error, and the largest and mean error; with bowwave's series CSV (`run dam-break-mm`), bowwave's Z beside it.
"""
import csv
import os
import sys

import numpy as np

from snapshots import pysph_snapshots

A, G = 0.05715, 9.81
T_SCALE = 1.0 / (np.sqrt(2.0) * np.sqrt(G / A))  # t = T * T_SCALE
# Martin & Moyce (1952) Table 2, n^2 = 2, a = 2.25 in: the file bowwave's validation reads
TABLE2_CSV = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'data', 'reference',
                          'martin_moyce_1952_n2_2_a2.25in_front_table2_ocellaris.csv')


def table2():
    with open(TABLE2_CSV) as f:
        return [(float(r[0]), float(r[1])) for r in list(csv.reader(f))[1:]]


def pysph_front(folder, dx):
    return np.array([(t, (np.max(fl.x) + 0.5 * dx) / A) for t, fl in pysph_snapshots(folder)])


def bowwave_front(path):
    rows = list(csv.DictReader(open(path)))
    return np.array([(float(r['t']), float(r['front']) / A) for r in rows])


def main():
    folder, res = sys.argv[1], float(sys.argv[2])
    ours = pysph_front(folder, A / res)
    other = bowwave_front(sys.argv[3]) if len(sys.argv) > 3 else None
    errs, errs_b = [], []
    print('T      exp.   PySPH  error' + ('   bowwave  error' if other is not None else ''))
    for T, z in table2():
        if T > 2.5:
            continue
        zp = np.interp(T * T_SCALE, ours[:, 0], ours[:, 1])
        errs.append(abs(zp - z) / z)
        line = '%.2f   %.2f   %.3f  %5.1f %%' % (T, z, zp, 100 * errs[-1])
        if other is not None:
            zb = np.interp(T * T_SCALE, other[:, 0], other[:, 1])
            errs_b.append(abs(zb - z) / z)
            line += '   %.3f    %5.1f %%' % (zb, 100 * errs_b[-1])
        print(line)
    print('PySPH: max %.1f %%, mean %.1f %%' % (100 * max(errs), 100 * np.mean(errs)))
    if errs_b:
        print('bowwave: max %.1f %%, mean %.1f %%' % (100 * max(errs_b), 100 * np.mean(errs_b)))


if __name__ == '__main__':
    main()
