"""Figure and table of the dam break with a lifted gate (issue #35, session 51).

Reads the reduced series in studies/results/validation/gate/ (written by `reduce`, below, from `bowwave run` of
the cases make_cases.py writes: t*, the front, P1, P1c, P1g, P0) and the published P1 curves of the project's
reference data; draws P1 against t* and against the time since the front reached the wall, and prints the
table of the log (the first impact as `validate` reads it; window means).
Usage (from the repository root; needs numpy and matplotlib):
    python3 tools/dam-break-gate/plot.py reduce RUN_DIR/dam-break-gate_series.csv NAME.csv
    python3 tools/dam-break-gate/plot.py
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = "studies/results/validation/gate"
KEEP = ["t_star", "front_star", "pstar_P1", "pstar_P1c", "pstar_P1g", "pstar_P0"]
WALL = 5.36  # the front at the right wall (5.366 H), in H
RUNS = [
    ("none-h40.csv", "no gate (the built-in case), H/dx 40", "k"),
    ("v6.0-h40.csv", "gate lifted at 6 m/s, H/dx 40", "tab:blue"),
    ("v3.0-h40.csv", "gate lifted at 3 m/s, H/dx 40", "tab:green"),
    ("v1.5-h40.csv", "gate lifted at 1.5 m/s, H/dx 40", "tab:red"),
    ("none-h80.csv", "no gate, H/dx 80", "gray"),
    ("v3.0-h80.csv", "gate lifted at 3 m/s, H/dx 80", "tab:olive"),
]


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def reduce(src, name):
    s = read(src)
    with open(os.path.join(HERE, name), "w") as f:
        f.write(",".join(KEEP) + "\n")
        for i in range(len(s["t_star"])):
            f.write(",".join(f"{s[k][i]:.6g}" for k in KEEP) + "\n")


def impact(t, p):
    """The first time the 0.05 t*-mean of p, read every 0.005, reaches 0.1 (as `validate` reads it)."""
    g = np.arange(t[0], t[-1], 0.005)
    v = np.interp(g, t, p)
    m = np.array([v[np.abs(g - x) <= 0.025 + 1e-12].mean() for x in g])
    k = np.nonzero((m[1:] >= 0.1) & (m[:-1] < 0.1))[0]
    if len(k) == 0:
        return float("nan")
    k = k[0]
    return g[k] + (0.1 - m[k]) / (m[k + 1] - m[k]) * 0.005


def mean(t, p, a, b):
    x = a + 0.005 * (np.arange(round((b - a) / 0.005)) + 0.5)
    return float(np.interp(x, t, p).mean())


def arrival(s):
    return float(s["t_star"][np.nonzero(s["front_star"] >= WALL)[0][0]])


def main():
    ref = read("data/reference/marrone2011_deltaSPH_damBreak_P1_trixiparticles.csv")
    fig, axes = plt.subplots(2, 1, figsize=(8, 7))
    print("| run | wall arrival t* | P1 first impact | P1 2.5–3 | P1 3–3.5 | P1c 3–3.5 | P1g first impact | P0 2.5–3.5 "
          "| after arrival: P1 first impact | P1 +0.05–0.55 | P1 +0.55–1.05 | P1c +0.55–1.05 |")
    print("|" + "---|" * 12)
    for name, label, colour in RUNS:
        path = os.path.join(HERE, name)
        if not os.path.exists(path):
            continue
        s = read(path)
        t, a = s["t_star"], arrival(s)
        axes[0].plot(t, s["pstar_P1"], color=colour, lw=0.9, label=label)
        axes[1].plot(t - a, s["pstar_P1"], color=colour, lw=0.9, label=label)
        r = t - a
        print(f"| {label} | {a:.3f} | {impact(t, s['pstar_P1']):.3f} | {mean(t, s['pstar_P1'], 2.5, 3):.3f} "
              f"| {mean(t, s['pstar_P1'], 3, 3.5):.3f} | {mean(t, s['pstar_P1c'], 3, 3.5):.3f} "
              f"| {impact(t, s['pstar_P1g']):.3f} | {mean(t, s['pstar_P0'], 2.5, 3.5):.3f} "
              f"| +{impact(r, s['pstar_P1']):.3f} | {mean(r, s['pstar_P1'], 0.05, 0.55):.3f} "
              f"| {mean(r, s['pstar_P1'], 0.55, 1.05):.3f} | {mean(r, s['pstar_P1c'], 0.55, 1.05):.3f} |")
    t = ref["t_sqrt(g_over_H)"]
    for ax, shift in [(axes[0], 0.0), (axes[1], 2.45)]:
        ax.plot(t - shift, ref["p_over_rho_g_H_Buchner_exp_interp"], "k--", lw=1.2, label="Buchner (2002), experiment")
        ax.plot(t - shift, ref["p_over_rho_g_H_deltaSPH_H_over_dx_80"], ":", color="gray", lw=1.2,
                label="Marrone et al. (2011), H/dx 80")
        ax.set_ylabel("P1 (90 mm at 0.267 H)  p/ρgH")
        ax.set_ylim(-0.2, 1.2)
        ax.grid(alpha=0.3)
    axes[0].set_xlim(2.0, 5.0)
    axes[0].set_xlabel("t √(g/H)")
    axes[1].set_xlim(-0.4, 2.5)
    axes[1].set_xlabel("time since the front reached the wall, √(H/g) (the references: since t* 2.45)")
    axes[0].legend(fontsize=7, loc="upper left")
    fig.suptitle("Dam break: P1 with the column released by a lifted gate (issue #35)")
    fig.tight_layout()
    out = os.path.join(HERE, "p1_gate.png")
    fig.savefig(out, dpi=90)
    print("wrote", out)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "reduce":
        reduce(sys.argv[2], sys.argv[3])
    else:
        main()
