"""Reduce an OpenFOAM dam-break run (make_case.py) to bowwave's wall sensors and P1's measures (issue #35).

Reads OUTDIR/postProcessing/wallPressure/*/p (the right wall's face pressures every step), forms each sensor as
bowwave's face sensors are formed (the wall pressure, linear between the face centres and constant below the
first, averaged over the sensor's face at 40 points), and prints, for P1 (90 mm at 0.16 m), P1c (8.4 mm there),
P1g (Greco's placement), P0 (90 mm from the floor) and L1–L3 (4.2 mm at 0.01, 0.05, 0.10 H): the first impact
(the 0.05 t*-mean first reaching 0.1 ρgH, as `bowwave validate dam-break` reads it) and the means over the
windows the project's logs use. Writes OUTDIR/sensors.csv (t*, every sensor in ρgH, every 0.005 t*).
Usage: python3 reduce.py OUTDIR [OUTDIR ...]
       python3 reduce.py --bowwave SERIES.csv [...]   (a bowwave run of profile.toml: its 60 faces W00–W59 of 7.5 mm
                                                      read the same way, so that both codes' sensors are formed
                                                      from the same 7.5 mm profile)
"""
import glob
import os
import sys

import numpy as np

H, G, RHO = 0.6, 9.81, 1000.0
SENSORS = [  # name, centre (m), size (m)
    ("P1", 0.16, 0.09),
    ("P1c", 0.16, 0.0084),
    ("P1g", 0.115, 0.09),
    ("P0", 0.045, 0.09),
    ("L1", 0.01 * H, 0.0042),
    ("L2", 0.05 * H, 0.0042),
    ("L3", 0.10 * H, 0.0042),
]
WINDOWS = [(2.5, 3.0), (3.0, 3.5), (3.5, 4.0), (4.0, 4.8), (3.0, 6.0)]


def read_probes(out):
    ys, rows = None, []
    files = sorted(glob.glob(os.path.join(out, "postProcessing/wallPressure/*/p")), key=lambda f: float(f.split("/")[-2]))
    for path in files:  # a restarted run writes one directory per start time
        locs = []
        with open(path) as f:
            for line in f:
                if line.startswith("# Probe"):
                    inside = line[line.index("(") + 1:line.index(")")].split()
                    locs.append(float(inside[1]))
                elif line.startswith("#"):
                    continue
                else:
                    vals = [float(v) for v in line.split()]
                    if rows and vals[0] <= rows[-1][0]:
                        rows = [r for r in rows if r[0] < vals[0]]
                    rows.append(vals)
        ys = np.array(locs) if ys is None else ys
    data = np.array(rows)
    return data[:, 0], ys, data[:, 1:]


def face(ys, p, centre, size):
    pts = centre + size * (np.arange(40) + 0.5) / 40 - 0.5 * size
    return np.array([np.interp(pts, ys, row).mean() for row in p])


def impact_time(t, p, level=0.1, width=0.05, step=0.005):
    grid = np.arange(t[0], t[-1], step)
    v = np.interp(grid, t, p)
    k = max(1, int(round(width / step)))
    smooth = np.convolve(v, np.ones(k + 1) / (k + 1), mode="same")
    above = np.nonzero((smooth[1:] >= level) & (smooth[:-1] < level))[0]
    if len(above) == 0:
        return float("nan")
    i = above[0]
    return grid[i] + (level - smooth[i]) / (smooth[i + 1] - smooth[i]) * step


def mean_over(t, p, a, b, step=0.005):
    if t[-1] < b:
        return float("nan")
    x = a + step * (np.arange(int(round((b - a) / step))) + 0.5)
    return float(np.interp(x, t, p).mean())


def read_bowwave_profile(path):
    import csv

    with open(path) as f:
        rows = list(csv.DictReader(f))
    names = sorted(k for k in rows[0] if k.startswith("pstar_W"))
    t = np.array([float(r["t"]) for r in rows])
    p = np.array([[float(r[n]) * RHO * G * H for n in names] for r in rows])
    return t, (np.arange(len(names)) + 0.5) * 0.0075, p


def main():
    args = sys.argv[1:]
    bowwave = args[:1] == ["--bowwave"]
    for out in args[1:] if bowwave else args:
        t, ys, p = read_bowwave_profile(out) if bowwave else read_probes(out)
        ts = t * np.sqrt(G / H)
        cols = {"t_star": ts}
        for name, c, s in SENSORS:
            cols[name] = face(ys, p, c, s) / (RHO * G * H)
        if not bowwave:  # written every 0.005 t* (linear between steps), the grid every reader resamples to
            grid = np.arange(0.0, ts[-1], 0.005)
            with open(os.path.join(out, "sensors.csv"), "w") as f:
                f.write(",".join(cols) + "\n")
                for x in grid:
                    f.write(",".join([f"{x:.3f}"] + [f"{np.interp(x, ts, cols[n]):.5g}" for n in cols if n != "t_star"]))
                    f.write("\n")
        print(f"{out}: {len(ts)} samples to t* {ts[-1]:.3f}")
        head = "sensor  impact t*  " + "  ".join(f"{a}-{b}" for a, b in WINDOWS)
        print(head)
        for name, _, _ in SENSORS:
            s = cols[name]
            means = "  ".join(f"{mean_over(ts, s, a, b):7.3f}" for a, b in WINDOWS)
            print(f"{name:5s}  {impact_time(ts, s):8.3f}  {means}")


if __name__ == "__main__":
    main()
