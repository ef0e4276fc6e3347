#!/bin/bash
# A one-node SLURM on this machine for the pipeline's SLURM test (tests/slurm/slurm_test.sh):
# munged, slurmctld and slurmd from Debian's packages, talking over loopback only, with their
# configuration, keys, sockets, logs and state in one folder. No systemd, no cgroups
# (proctrack/linuxproc, task/none), no accounting database. Installs the packages if missing.
#
#   tests/slurm/start_cluster.sh [STATE_DIR]      (default /tmp/dem-slurm)
#   . STATE_DIR/env                               sets SLURM_CONF for sbatch, squeue, scancel
#   tests/slurm/stop_cluster.sh [STATE_DIR]
set -eu
state=${1:-/tmp/dem-slurm}
ctld_port=${DEM_SLURMCTLD_PORT:-16817} d_port=${DEM_SLURMD_PORT:-16818}

# Install only what is missing; Debian's postinst does not start the daemons where services
# cannot start (no systemd): this script starts them itself. Exit 77 (a skip for CTest) where they
# cannot be installed.
missing=""
for p in slurmctld slurmd slurm-client munge; do dpkg -s "$p" > /dev/null 2>&1 || missing="$missing $p"; done
if [ -n "$missing" ]; then
  sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo -n"
  if ! apt-cache policy slurmctld 2> /dev/null | grep -q 'Candidate: [0-9]'; then
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq > /dev/null 2>&1
  fi
  echo "start_cluster: installing:$missing"
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing > /dev/null ||
    { echo "start_cluster: cannot install$missing (needs root or sudo, and Debian's packages)"; exit 77; }
fi

if [ -f "$state/slurmctld.pid" ] && kill -0 "$(cat "$state/slurmctld.pid")" 2> /dev/null; then
  echo "start_cluster: already running in $state"; exit 0
fi
rm -rf "$state"
mkdir -p "$state/munge" "$state/ctld" "$state/spool" "$state/log"
chmod 700 "$state/munge"
user=$(id -un)
node=$(hostname -s)

# munged with a key of its own (not /etc/munge's): only this cluster's daemons can talk to it.
dd if=/dev/urandom of="$state/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$state/munge/munge.key"
munged --force --key-file="$state/munge/munge.key" --socket="$state/munge/munge.socket" \
  --pid-file="$state/munge/munged.pid" --log-file="$state/log/munged.log" --seed-file="$state/munge/seed"

# The node as slurmd sees it (its real CPUs and memory), at 127.0.0.1.
hw=$(slurmd -C | head -1 | sed "s/^NodeName=[^ ]*//")
cat > "$state/slurm.conf" <<CONF
ClusterName=demtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$d_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$state/munge/munge.socket
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SchedulerParameters=sched_interval=2
MessageTimeout=10
KillWait=5
MinJobAge=60
NodeName=$node NodeAddr=127.0.0.1 $hw State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
echo "export SLURM_CONF=$state/slurm.conf" > "$state/env"
export SLURM_CONF=$state/slurm.conf

slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
# Ready when the node takes jobs.
for _ in $(seq 60); do
  if sinfo --noheader --format=%T 2> /dev/null | grep -qE '^(idle|mixed|allocated)'; then
    echo "start_cluster: SLURM running in $state (node $node: $(sinfo --noheader --format='%c CPUs, %m MB'))"
    exit 0
  fi
  sleep 0.5
done
echo "start_cluster: the node did not come up; logs in $state/log:"
tail -5 "$state"/log/*.log
exit 1
