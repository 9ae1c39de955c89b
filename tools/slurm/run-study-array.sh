#!/usr/bin/env bash
# The README's job-array recipe, run for real under SLURM on this one machine: installs SLURM and munge from
# Debian's packages, starts a one-node controller (slurmctld) and node daemon (slurmd) on localhost, submits a
# coarse study as a job array (one `bowwave study FILE --case N` per task, into one output folder), collects
# it, runs the same study serially into another folder, and compares the tables (jets.csv without its timing
# columns, comparison.csv, report.md) byte for byte. Needs root and apt; not part of CI.
#
#   sudo tools/slurm/run-study-array.sh            # from the project's root; prints the comparison
#
# Leaves the daemons running (stop them with `pkill slurmctld; pkill slurmd; pkill munged`).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
work=${WORK:-/tmp/bowwave-slurm}
rm -rf "$work" && mkdir -p "$work"

# 1. SLURM and munge from Debian's packages.
if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurmctld slurmd slurm-client munge >/dev/null
fi

# 2. munge (the cluster's authentication) and a one-node cluster on localhost.
if [ ! -s /etc/munge/munge.key ]; then
    dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key 2>/dev/null
fi
chown munge:munge /etc/munge/munge.key && chmod 400 /etc/munge/munge.key
mkdir -p /run/munge && chown munge:munge /run/munge
pgrep -x munged >/dev/null || su -s /bin/sh munge -c /usr/sbin/munged
node=$(hostname -s)
cpus=$(nproc)
mkdir -p /etc/slurm /var/spool/slurmctld /var/spool/slurmd /var/log/slurm
cat > /etc/slurm/slurm.conf <<CONF
ClusterName=bowwave
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
pkill -x slurmctld || true
pkill -x slurmd || true
sleep 1
slurmctld
slurmd
for _ in $(seq 30); do
    sinfo -h -o %T 2>/dev/null | grep -q idle && break
    sleep 1
done
sinfo

# 3. The binary and a coarse study of three cases.
cargo build --release -q
bin="$root/target/release/bowwave"
cat > "$work/array.toml" <<TOML
name = "array"
description = "three short coarse cases for the job-array check"
hull = "$root/hulls/athena.csv"
froude = [0.55, 0.6, 0.64]
[resolution]
dx = [3e-3, 3e-3, 3e-3]
[config]
until = 0.1
TOML

# 4. The job array: one task per case, one thread each, all into one folder; then the collection.
cat > "$work/array.sbatch" <<SBATCH
#!/bin/bash
#SBATCH --job-name=bowwave-array
#SBATCH --array=1-3
#SBATCH --cpus-per-task=1
#SBATCH --output=$work/log-%a.txt
"$bin" --threads 1 study "$work/array.toml" --out "$work/array" --case \$SLURM_ARRAY_TASK_ID
SBATCH
start=$(date +%s)
job=$(sbatch --parsable "$work/array.sbatch")
echo "submitted job array $job"
while squeue -h -j "$job" 2>/dev/null | grep -q .; do sleep 2; done
echo "array finished in $(( $(date +%s) - start )) s"
sacct -j "$job" 2>/dev/null || true
"$bin" study "$work/array.toml" --out "$work/array" --collect -q > "$work/collect.txt"

# 5. The same study serially, and the comparison.
"$bin" --threads 1 study "$work/array.toml" --out "$work/serial" -q > "$work/serial.txt"
python3 - "$work" <<'PY'
import csv, io, sys
work = sys.argv[1]
def jets(folder):
    rows = list(csv.reader(open(f"{work}/{folder}/jets.csv")))
    keep = [k for k, h in enumerate(rows[0]) if not h.endswith("_seconds")]
    return [[r[k] for k in keep] for r in rows]
ok = jets("array") == jets("serial")
print("jets.csv (timing columns aside):", "same" if ok else "DIFFERENT")
for f in ["comparison.csv", "report.md"]:
    same = open(f"{work}/array/{f}", "rb").read() == open(f"{work}/serial/{f}", "rb").read()
    print(f"{f}:", "same" if same else "DIFFERENT")
    ok &= same
print("logs:", *(open(f"{work}/log-{k}.txt").read().strip().splitlines()[:1] for k in (1, 2, 3)))
sys.exit(0 if ok else 1)
PY
