#!/usr/bin/env python3
"""Compares two output folders of bowwave, file by file, as the before/after proof of a change that must
not move a result: every file byte for byte, except the cost of the run (CSV columns and JSON keys ending in
`_seconds`), the build (`git_commit`) and, with --config-format-changed, the recorded configuration (`spec`,
`study`) whose format a redesign changed on purpose. Prints one line per file and exits 1 on a difference.

    python3 tools/same-outputs/compare.py BEFORE AFTER [--config-format-changed]
"""
import csv
import io
import json
import os
import sys

IGNORED_KEYS = {"git_commit"}


def strip_json(v, drop_config):
    if isinstance(v, dict):
        return {
            k: strip_json(x, drop_config)
            for k, x in v.items()
            if not k.endswith("_seconds")
            and k not in IGNORED_KEYS
            and not (drop_config and k in ("spec", "study"))
        }
    if isinstance(v, list):
        return [strip_json(x, drop_config) for x in v]
    return v


def strip_csv(text):
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return rows
    keep = [k for k, h in enumerate(rows[0]) if not h.endswith("_seconds")]
    return [[r[k] for k in keep if k < len(r)] for r in rows]


def same(a, b, drop_config):
    if a.endswith(".json"):
        with open(a) as fa, open(b) as fb:
            return strip_json(json.load(fa), drop_config) == strip_json(json.load(fb), drop_config)
    if a.endswith(".csv"):
        with open(a) as fa, open(b) as fb:
            return strip_csv(fa.read()) == strip_csv(fb.read())
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def main():
    before, after = sys.argv[1], sys.argv[2]
    drop_config = "--config-format-changed" in sys.argv
    files = sorted(
        os.path.relpath(os.path.join(d, f), before) for d, _, fs in os.walk(before) for f in fs
    )
    bad = 0
    for f in files:
        b = os.path.join(after, f)
        if not os.path.exists(b):
            print(f"MISSING {f}")
            bad += 1
        elif same(os.path.join(before, f), b, drop_config):
            print(f"same    {f}")
        else:
            print(f"DIFFERS {f}")
            bad += 1
    extra = sorted(
        os.path.relpath(os.path.join(d, f), after) for d, _, fs in os.walk(after) for f in fs
    )
    for f in set(extra) - set(files):
        print(f"NEW     {f}")
    print(f"{len(files)} files, {bad} differ or are missing")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
