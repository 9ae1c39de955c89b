"""The right wall's pressure profile at fixed times, OpenFOAM beside bowwave (issue #35, session 42).

OpenFOAM: the face pressures OUTDIR/postProcessing/wallPressure/*/p (make_case.py); bowwave: a run of
profile.toml (the dam break with 60 faces of 7.5 mm from the floor to 0.45 m, W00–W59), its series CSV. Both
are read at the same times t√(g/H) (linear in time between samples) and written as one CSV (y/H, then one column
per code and time) and one figure.
Usage: python3 profile.py FOAM_OUTDIR BOWWAVE_SERIES.csv OUT_PREFIX [--times 2.5,2.6,...]
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from reduce import G, H, RHO, read_probes

TIMES = [2.45, 2.55, 2.65, 2.75, 3.0, 3.25, 3.5]


def bowwave_profile(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    names = sorted(k for k in rows[0] if k.startswith("pstar_W"))
    t = np.array([float(r["t_star"]) for r in rows])
    p = np.array([[float(r[n]) for n in names] for r in rows])
    ys = (np.arange(len(names)) + 0.5) * 0.0075
    return t, ys, p


def at(t, p, when):
    return np.array([np.interp(when, t, p[:, j]) for j in range(p.shape[1])])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("foam")
    ap.add_argument("bowwave")
    ap.add_argument("out")
    ap.add_argument("--times", default=",".join(map(str, TIMES)))
    a = ap.parse_args()
    times = [float(x) for x in a.times.split(",")]
    tf, yf, pf = read_probes(a.foam)
    tf = tf * np.sqrt(G / H)
    pf = pf / (RHO * G * H)
    tb, yb, pb = bowwave_profile(a.bowwave)
    n = min(len(yf), len(yb))
    cols = {"y_over_H": yf[:n] / H}
    fig, axes = plt.subplots(1, len(times), figsize=(2.2 * len(times), 5), sharey=True)
    for ax, when in zip(axes, times):
        f, b = at(tf, pf, when)[:n], at(tb, pb, when)[:n]
        cols[f"openfoam_t{when}"] = f
        cols[f"bowwave_t{when}"] = b
        ax.plot(f, yf[:n] / H, "b-", label="OpenFOAM")
        ax.plot(b, yb[:n] / H, "r-", label="bowwave")
        ax.axhspan(0.115 / H, 0.205 / H, color="0.9")
        ax.set_title(f"t√(g/H) = {when}", fontsize=9)
        ax.set_xlabel("p/(ρgH)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("y/H on the right wall (grey: P1's face)")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out + ".png", dpi=110)
    with open(a.out + ".csv", "w") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for k in range(n):
            w.writerow([f"{cols[c][k]:.5g}" for c in cols])
    print(a.out + ".png", a.out + ".csv")


if __name__ == "__main__":
    main()
