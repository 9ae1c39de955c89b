"""PySPH's snapshot files of a run folder, in time order (shared by the two readers)."""
import glob
import re


def pysph_snapshots(folder):
    """Yield (t, fluid particle array) for each .npz output of `folder`, in the order PySPH wrote them."""
    from pysph.solver.utils import load
    files = sorted(glob.glob(folder + '/*_[0-9]*.npz'), key=lambda f: int(re.findall(r'_(\d+)\.npz', f)[-1]))
    for f in files:
        data = load(f)
        yield data['solver_data']['t'], data['arrays']['fluid']
