#!/bin/bash
# Stops the daemons tests/slurm/start_cluster.sh started (by their pid files) and removes its folder.
#   tests/slurm/stop_cluster.sh [STATE_DIR]      (default /tmp/dem-slurm)
set -u
state=${1:-/tmp/dem-slurm}
[ -d "$state" ] || exit 0
[ -f "$state/slurm.conf" ] && SLURM_CONF=$state/slurm.conf scancel --user="$(id -un)" 2> /dev/null
for daemon in slurmd slurmctld munge/munged; do
  pidfile=$state/$daemon.pid
  [ -f "$pidfile" ] || continue
  pid=$(cat "$pidfile")
  kill "$pid" 2> /dev/null || continue
  for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
  kill -9 "$pid" 2> /dev/null
done
rm -rf "$state"
echo "stop_cluster: stopped"
