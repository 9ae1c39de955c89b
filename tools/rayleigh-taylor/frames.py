"""Rayleigh-Taylor frames side by side: the particles of `bowwave run cases/rayleigh-taylor.toml --res R` at
t = 1..5, coloured by phase, one row per resolution. A reading aid for studies/results/rayleigh-taylor/,
outside the product (needs matplotlib).

    python frames.py OUT_RES20 OUT_RES40 OUT_RES80 --out frames.png
"""
import argparse, re, xml.etree.ElementTree as ET
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def frames(folder):
    """(time, path) of every frame in FOLDER/vtk/rayleigh-taylor.pvd."""
    root = ET.parse(f"{folder}/vtk/rayleigh-taylor.pvd").getroot()
    return [(float(d.get("timestep")), f"{folder}/vtk/{d.get('file')}") for d in root.iter("DataSet")]


def particles(path):
    text = open(path).read()
    pts = re.search(r"<Points>\s*<DataArray[^>]*>(.*?)</DataArray>", text, re.S).group(1).split()
    phase = re.search(r'Name="phase"[^>]*>(.*?)</DataArray>', text, re.S).group(1).split()
    x = [float(v) for v in pts[0::3]]
    y = [float(v) for v in pts[1::3]]
    return x, y, [int(float(p)) for p in phase]


def main():
    a = argparse.ArgumentParser()
    a.add_argument("folders", nargs="+")
    a.add_argument("--times", default="1,2,3,4,5")
    a.add_argument("--out", default="frames.png")
    args = a.parse_args()
    times = [float(t) for t in args.times.split(",")]
    fig, axes = plt.subplots(len(args.folders), len(times), figsize=(2.0 * len(times), 3.8 * len(args.folders)))
    for row, folder in enumerate(args.folders):
        fr = frames(folder)
        for col, t in enumerate(times):
            ax = axes[row][col] if len(args.folders) > 1 else axes[col]
            tt, path = min(fr, key=lambda f: abs(f[0] - t))
            x, y, k = particles(path)
            n = len(x)
            s = max(0.2, 2000.0 / n)
            ax.scatter(x, y, c=["#1f3b73" if p == 0 else "#e8b04a" for p in k], s=s, linewidths=0)
            ax.set_xlim(0, 1); ax.set_ylim(0, 2); ax.set_aspect("equal"); ax.set_xticks([]); ax.set_yticks([])
            ax.set_title(f"{folder.rstrip('/').split('/')[-1]}, t = {tt:.2f}", fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=80)


if __name__ == "__main__":
    main()
