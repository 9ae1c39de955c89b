"""Figure of the dam break's wall sensors with free-slip and no-slip floors (issue #35, session 35).

Reads the reduced series in studies/results/validation/no-slip/ (written by `bowwave run` of
dam-break-low-sensors.toml, columns kept: t*, front, P1, P1c, P2, P0, L1-L3) and the published P1 curves of
the project's reference data, and draws P1, P0 and the lowest sensor L1 against t* for H/dx 80.
Usage: python3 tools/dam-break-friction/plot.py   (from the repository root; needs numpy and matplotlib)
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = "studies/results/validation/no-slip"
RUNS = [
    ("default80.csv", "free slip, α 0.02 (default)", "k"),
    ("free-slip-re1e4-80.csv", "free slip, ν for Re 1e4", "tab:blue"),
    ("no-slip-re1e5-80.csv", "no slip, Re 1e5", "tab:green"),
    ("no-slip-re1e4-80.csv", "no slip, Re 1e4", "tab:red"),
    ("no-slip-re3e3-80.csv", "no slip, Re 3.3e3", "tab:orange"),
]


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def main():
    ref = read("data/reference/marrone2011_deltaSPH_damBreak_P1_trixiparticles.csv")
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    for name, label, colour in RUNS:
        path = os.path.join(HERE, name)
        if not os.path.exists(path):
            continue
        s = read(path)
        for ax, key in zip(axes, ["pstar_P1", "pstar_P0", "pstar_L1"]):
            ax.plot(s["t_star"], s[key], color=colour, lw=0.9, label=label)
    t = ref["t_sqrt(g_over_H)"]
    axes[0].plot(t, ref["p_over_rho_g_H_Buchner_exp_interp"], "k--", lw=1.2, label="Buchner (2002), experiment")
    axes[0].plot(t, ref["p_over_rho_g_H_deltaSPH_H_over_dx_80"], ":", color="gray", lw=1.2, label="Marrone et al. (2011), H/dx 80")
    axes[0].set_ylabel("P1 (90 mm at 0.267 H)  p/ρgH")
    axes[1].set_ylabel("P0 (90 mm at the floor)  p/ρgH")
    axes[2].set_ylabel("L1 (4.2 mm at 0.01 H)  p/ρgH")
    axes[0].set_ylim(-0.2, 1.2)
    axes[1].set_ylim(-0.2, 3.0)
    axes[2].set_ylim(-0.2, 3.0)
    axes[2].set_xlabel("t √(g/H)")
    axes[2].set_xlim(2.0, 6.0)
    axes[0].legend(fontsize=7, loc="upper left")
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle("Dam break, H/dx 80: free-slip and no-slip floors (issue #35)")
    fig.tight_layout()
    out = os.path.join(HERE, "sensors_h80.png")
    fig.savefig(out, dpi=90)
    print("wrote", out)


if __name__ == "__main__":
    main()
