"""Writes DualSPHysics dam-break case files at other spacings and end times from the peer's case definition
(../shared/peers/dualsphysics/DB50_Def.xml, not copied into the project):

    python dualsphysics_case.py DB50_Def.xml OUT_DIR --res 25,50,100 [--t-end 7] [--every 0.02]

Sets dp = H/res (H = 1 m), TimeMax = t_end sqrt(H/g) and TimeOut = every sqrt(H/g), nothing else, and writes
OUT_DIR/DB{res}_Def.xml.
"""
import math
import os
import re
import sys


def option(name, default):
    if name in sys.argv:
        k = sys.argv.index(name)
        value = sys.argv[k + 1]
        del sys.argv[k:k + 2]
        return value
    return default


def main():
    res = [float(r) for r in option('--res', '25,50,100').split(',')]
    t_end = float(option('--t-end', '7'))
    every = float(option('--every', '0.02'))
    src, out = sys.argv[1], sys.argv[2]
    text = open(src).read()
    scale = math.sqrt(1.0 / 9.81)
    os.makedirs(out, exist_ok=True)
    for r in res:
        t = text
        for pattern, value in [(r'(<definition dp=")[^"]*(")', f'{1.0 / r:.6g}'),
                               (r'(<parameter key="TimeMax" value=")[^"]*(")', f'{t_end * scale:.6f}'),
                               (r'(<parameter key="TimeOut" value=")[^"]*(")', f'{every * scale:.6f}')]:
            t, n = re.subn(pattern, lambda m: m.group(1) + value + m.group(2), t)
            if n != 1:
                sys.exit(f'{src}: expected one match of {pattern}, found {n}')
        path = os.path.join(out, f'DB{r:g}_Def.xml')
        open(path, 'w').write(t)
        print(f'wrote {path}')


if __name__ == '__main__':
    main()
