"""The bow region of a PySPH 2D+t run (twodt.py) above bowwave's at the same x/L, as one PNG (matplotlib).

    python frames_side_by_side.py PYSPH_OUT BOWWAVE_RUN_DIR --hull HULL --x0 X --at 0.08,0.11,0.14 --out side.png

BOWWAVE_RUN_DIR: a `bowwave twodt --vtk` folder (series.pvd, frame_*.vtp, in units of L); --x0: where the PySPH run
started (twodt.py's --x0). Axes in D: y from the centre plane, z from the calm waterline; the hull's wall
particles of PySPH in black (bowwave's ghosts are not in its frames: its water ends at the hull).
"""
import glob
import re
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from crest_from_outputs import header, option, vtp_points


def main():
    out, case_dir = sys.argv[1], sys.argv[2]
    meta = header(option('--hull', 'hulls/athena.csv'))
    d = float(meta['draft_m']) / float(meta['length_m'])
    x0 = float(option('--x0', '0'))
    xs = [float(a) for a in option('--at', '0.1,0.15,0.2').split(',')]
    pvd = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(f'{case_dir}/series.pvd').read())
    files = sorted(glob.glob(f'{out}/*.npz'), key=lambda f: int(f.rsplit('_', 1)[1].split('.')[0]))
    import json
    fr = json.load(open(f'{case_dir}/metrics.json'))['fr']
    fig, axs = plt.subplots(2, len(xs), figsize=(4.5 * len(xs), 6), squeeze=False)
    for c, x in enumerate(xs):
        xb, fb = min(pvd, key=lambda p: abs(float(p[0]) - x))
        p = vtp_points(f'{case_dir}/{fb}')
        axs[0][c].scatter(p[:, 0] / d, p[:, 1] / d, s=1)
        axs[0][c].set_title(f'bowwave, x/L {float(xb):.3f}')
        best = min(files, key=lambda f: abs(x0 + fr * float(np.load(f, allow_pickle=True)['solver_data'][()]['t']) - x))
        data = np.load(best, allow_pickle=True)
        xp = x0 + fr * float(data['solver_data'][()]['t'])
        fl, hl = (data['particles'][()][k]['arrays'] for k in ('fluid', 'hull'))
        axs[1][c].scatter(fl['x'] / d, fl['y'] / d, s=1)
        axs[1][c].scatter(hl['x'] / d, hl['y'] / d, s=1, c='k')
        axs[1][c].set_title(f'PySPH, x/L {xp:.3f}')
        for a in axs[:, c]:
            a.set_xlim(0, 2.0)
            a.set_ylim(-0.6, 0.7)
            a.set_aspect('equal')
            a.set_xlabel('y / D')
        axs[0][c].set_ylabel('z / D')
        axs[1][c].set_ylabel('z / D')
    plt.tight_layout()
    plt.savefig(option('--out', 'side.png'), dpi=70)


if __name__ == '__main__':
    main()
