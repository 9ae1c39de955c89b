#!/bin/sh
# The peers of the dam-break speed-accuracy chart, and bowwave read the same way (issue #34). One thread each,
# CPU seconds from /usr/bin/time. Usage, from an empty scratch folder (see README.md for DSPH and the venv):
#   BOWWAVE=.../bowwave DSPH=.../dsph/bin/linux PYSPH_PY=.../venv/bin/python TOOLS=.../tools sh run_all.sh
# Writes peers.csv in the scratch folder; copy it to studies/results/speed-accuracy/dam-break/.
set -e
: "${BOWWAVE:?}" "${DSPH:?}" "${PYSPH_PY:?}" "${TOOLS:?}"
P=$TOOLS/dam-break-peers
cpu() { awk '{print $1 + $2}' "$1"; }
export LD_LIBRARY_PATH=$DSPH OMP_NUM_THREADS=1

# DualSPHysics 5.0 CPU: the peer's case at H/dx 25, 50, 100, to t* 7, snapshots every 0.02 t*.
python3 $P/dualsphysics_case.py "${DSPH_CASE:-../shared/peers/dualsphysics/DB50_Def.xml}" dsph --res 25,50,100
for r in 25 50 100; do
  $DSPH/GenCase_linux64 dsph/DB${r}_Def dsph/DB$r/DB$r -save:all > dsph/gencase$r.log
  /usr/bin/time -f '%U %S' -o dsph/time$r $DSPH/DualSPHysics5.0CPU_linux64 dsph/DB$r/DB$r dsph/run$r \
      -dirdataout data -svres -ompthreads:1 > dsph/run$r.log
  $DSPH/PartVTK_linux64 -dirin dsph/run$r/data -savecsv dsph/csv$r/PartFluid -onlytype:-all,+fluid \
      -vars:-all,+press,+mass,+rhop > dsph/partvtk$r.log
  steps=$(grep 'Steps of simulation' dsph/run$r.log | grep -o '[0-9]*$')
  python3 $P/p1c_error.py dualsphysics dsph/csv$r --res $r --cpu $(cpu dsph/time$r) \
      --label 'DualSPHysics 5.0' --variant 'Wendland, Verlet, DDT 0.1' --steps "${steps:-0}" --peers peers.csv
done

# PySPH 1.0b2, EDAC with Adami's walls, at H/dx 20, 40, 60, to t 1.7312 s (t* 7), snapshots every 0.005 s.
for r in 20 40 60; do
  /usr/bin/time -f '%U %S' -o pysph-time$r $PYSPH_PY $TOOLS/pysph-dam-break/dam_break.py --scheme edac --res $r \
      --tf 1.7312 -d pysph-edac$r > pysph-edac$r.log 2>&1
  "$PYSPH_PY" $P/p1c_error.py pysph pysph-edac$r --res $r --cpu $(cpu pysph-time$r) --label 'PySPH 1.0b2' \
      --variant 'EDAC, Adami walls' --peers peers.csv
done

# bowwave itself, read from its snapshots the same way (the reading's own part in the difference).
for r in 20 40 60; do
  $BOWWAVE cases dam-break | sed 's/^vtk_every = .*/vtk_every = 0.005/' > bowwave-dam-break.toml
  /usr/bin/time -f '%U %S' -o bowwave-time$r $BOWWAVE run bowwave-dam-break.toml --threads 1 --res $r \
      --out bowwave$r > bowwave$r.log 2>&1
  python3 $P/p1c_error.py bowwave bowwave$r/vtk --res $r --cpu $(cpu bowwave-time$r) \
      --label 'bowwave, read as the peers' --variant 'delta-sph' --peers peers.csv
done
