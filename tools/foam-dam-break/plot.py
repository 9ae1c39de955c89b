"""Figure: P1 and the lowest wall sensor of the dam break, OpenFOAM (VOF) beside bowwave (issue #35, session 42).

Reads the reduced OpenFOAM series in studies/results/validation/openfoam/ (written by reduce.py, copied there),
bowwave's default runs in studies/results/validation/no-slip/ (session 35) and the published P1 curves of the
project's reference data; draws P1 (90 mm at 0.16 m) and L1 (4.2 mm at 0.01 H) against t√(g/H).
Usage: python3 tools/foam-dam-break/plot.py   (from the repository root; needs numpy and matplotlib)
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

OURS = "studies/results/validation/no-slip"
FOAM = "studies/results/validation/openfoam"
REF = "data/reference"


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(row for row in f if not row.startswith("#")))
    return {k: np.array([float(r[k]) if r[k] else np.nan for r in rows]) for k in rows[0]}


def main():
    fig, axes = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    shades = {40: 0.75, 80: 0.45, 160: 0.0}
    for res, shade in shades.items():
        path = os.path.join(OURS, f"default{res}.csv")
        if os.path.exists(path):
            d = read(path)
            colour = (1.0, shade, shade)
            axes[0].plot(d["t_star"], d["pstar_P1"], color=colour, lw=1, label=f"bowwave H/dx {res}")
            axes[1].plot(d["t_star"], d["pstar_L1"], color=colour, lw=1, label=f"bowwave H/dx {res}")
        for kind, style in (("slip", "-"), ("sst", "--")):
            path = os.path.join(FOAM, f"{kind}{res}.csv")
            if os.path.exists(path):
                d = read(path)
                colour = (shade, shade, 1.0)
                label = f"OpenFOAM {'free slip' if kind == 'slip' else 'no slip, k-ω SST'} H/dx {res}"
                axes[0].plot(d["t_star"], d["P1"], style, color=colour, lw=1, label=label)
                axes[1].plot(d["t_star"], d["L1"], style, color=colour, lw=1, label=label)
    marrone = read(os.path.join(REF, "marrone2011_deltaSPH_damBreak_P1_trixiparticles.csv"))
    buchner = read(os.path.join(REF, "buchner2002_damBreak_H600_P1_trixiparticles.csv"))
    axes[0].plot(marrone["t_sqrt(g_over_H)"], marrone["p_over_rho_g_H_deltaSPH_H_over_dx_80"], color="g", lw=1.5,
                 label="Marrone et al. δ-SPH H/dx 80")
    axes[0].plot(buchner["t_sqrt(g_over_H)"], buchner["p_over_rho_g_H"], "ko", ms=3, label="Buchner (experiment)")
    axes[0].set_ylabel("P1 (90 mm at 0.16 m), p/(ρgH)")
    axes[0].set_ylim(-0.2, 1.2)
    axes[1].set_ylabel("L1 (4.2 mm at 0.01 H), p/(ρgH)")
    axes[1].set_ylim(-0.5, 4.0)
    axes[1].set_xlabel("t√(g/H)")
    axes[1].set_xlim(2.0, 6.0)
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Dam break: wall pressure, bowwave (δ-SPH) and OpenFOAM interFoam (VOF, with air)")
    fig.tight_layout()
    out = os.path.join(FOAM, "p1_l1.png")
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
