"""Writes the dam break with a lifted gate (issue #35, session 51): for each gate speed V (m/s, at Buchner's
scale H = 0.6 m) a motion table (the gate accelerated uniformly to V over 0.02 s, then at V) and a case file,
cases/dam-break.toml with a zero-thickness gate at the column's face (x = 2H) lifted by that table.
The speeds are ours: the experiments' gate laws are not in the project's sources.
Usage: python3 tools/dam-break-gate/make_cases.py OUT_DIR [V ...]   (from the repository root; default 1.5 3 6)
then:  bowwave run OUT_DIR/dam-break-gate-v3.0.toml --res 40 --no-vtk --out RUN_DIR
"""
import os
import sys

RAMP = 0.02  # s to reach V
STEP = 0.0025  # s between the table's rows
END = 2.0  # s, past the case's end time (1.81 s)


def table(v):
    rows, k = [], 0
    while k * STEP <= END + 1e-9:
        t = k * STEP
        heave = v * t * t / (2 * RAMP) if t < RAMP else v * (t - RAMP / 2)
        rows.append(f"{t:.4f},0.0,{heave:.6f},0.0")
        k += 1
    return "\n".join(rows) + "\n"


def case(v):
    base = open("cases/dam-break.toml").read()
    s = base.replace('name = "dam-break"', 'name = "dam-break-gate"', 1)
    gate = f"""[[walls]]
name = "gate"          # a gate of zero thickness at the column's face, lifted from t = 0 at {v} m/s (ours)
points = [[1.2, 0.0], [1.2, 0.8]]
fluid_side = "left"
motion = {{ table = "gate_v{v}.csv" }}

[[blocks]]"""
    return s.replace("[[blocks]]", gate, 1)


def main():
    out = sys.argv[1]
    speeds = [float(x) for x in sys.argv[2:]] or [1.5, 3.0, 6.0]
    os.makedirs(out, exist_ok=True)
    for v in speeds:
        with open(os.path.join(out, f"gate_v{v}.csv"), "w") as f:
            f.write(table(v))
        with open(os.path.join(out, f"dam-break-gate-v{v}.toml"), "w") as f:
            f.write(case(v))


if __name__ == "__main__":
    main()
