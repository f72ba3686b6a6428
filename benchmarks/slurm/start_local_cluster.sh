#!/usr/bin/env bash
# Start a single-node SLURM cluster on this machine, with accounting, for running the workflow
# through profiles/slurm (snakemake-executor-plugin-slurm) for real.
#
#   sudo bash benchmarks/slurm/start_local_cluster.sh        # Debian/Ubuntu, as root
#
# It installs Debian's munge, slurm-wlm, slurmdbd and mariadb-server (apt-get), writes a minimal
# slurm.conf (no cgroups: proctrack/linuxproc, task/none; one node, this host, with its CPUs and
# memory; one partition `local`), a slurmdbd.conf backed by a local MariaDB database, registers
# the cluster, an account `local` and the current user in it, starts munged, mariadbd, slurmdbd,
# slurmctld and slurmd, and checks sinfo, srun and sacct. Running it again starts only what is
# not running. It is meant for a throw-away machine or container (the daemons run as root and
# the database user's password is fixed); it needs no systemd.
set -euo pipefail

CLUSTER=local
PARTITION=local
ACCOUNT=local
DBPASS=slurmdbpass
HOST=$(hostname -s)
CONF=/etc/slurm
LOG=/var/log/slurm
STATE=/var/lib/slurm
USER_NAME=${SUDO_USER:-$(id -un)}

log() { echo "[slurm-local] $*"; }
running() { pgrep -x "$1" >/dev/null 2>&1; }
wait_for() {  # wait_for <seconds> <command...>
    local n=$1; shift
    for _ in $(seq "$n"); do "$@" >/dev/null 2>&1 && return 0; sleep 1; done
    "$@"
}

if [ "$(id -u)" -ne 0 ]; then echo "run as root" >&2; exit 1; fi

# 1. packages
need=()
for p in munge slurm-wlm slurmdbd mariadb-server; do
    dpkg -s "$p" >/dev/null 2>&1 || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
    log "installing ${need[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${need[@]}"
fi

# 2. configuration (rewritten each time; the daemons are restarted only if not running)
CPUS=$(nproc)
MEM=$(free -m | awk '/^Mem:/ {print $2}')
MEM=$((MEM - 256))       # leave some memory to the daemons; slurmd rejects a RealMemory above what it sees
mkdir -p "$CONF" "$LOG" "$STATE/slurmctld" "$STATE/slurmd" /run/slurm /run/munge /run/mysqld
cat > "$CONF/slurm.conf" <<CONFEOF
ClusterName=$CLUSTER
SlurmctldHost=$HOST
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$STATE/slurmctld
SlurmdSpoolDir=$STATE/slurmd
SlurmctldPidFile=/run/slurm/slurmctld.pid
SlurmdPidFile=/run/slurm/slurmd.pid
SlurmctldLogFile=$LOG/slurmctld.log
SlurmdLogFile=$LOG/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/linux
AccountingStorageType=accounting_storage/slurmdbd
AccountingStorageHost=localhost
AccountingStorageEnforce=associations
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
MinJobAge=300
NodeName=$HOST CPUs=$CPUS RealMemory=$MEM State=UNKNOWN
PartitionName=$PARTITION Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
CONFEOF
cat > "$CONF/slurmdbd.conf" <<CONFEOF
AuthType=auth/munge
DbdHost=localhost
SlurmUser=root
PidFile=/run/slurm/slurmdbd.pid
LogFile=$LOG/slurmdbd.log
StorageType=accounting_storage/mysql
StorageHost=localhost
StorageUser=slurm
StoragePass=$DBPASS
StorageLoc=slurm_acct_db
CONFEOF
chmod 600 "$CONF/slurmdbd.conf"

# 3. munge
chown munge:munge /run/munge
if [ ! -s /etc/munge/munge.key ]; then
    log "creating the munge key"
    mungekey --create --keyfile=/etc/munge/munge.key
    chown munge:munge /etc/munge/munge.key; chmod 400 /etc/munge/munge.key
fi
if ! running munged; then
    log "starting munged"
    runuser -u munge -- /usr/sbin/munged </dev/null >/dev/null 2>&1
fi
wait_for 10 bash -c 'munge -n | unmunge'

# 4. MariaDB and the accounting database
chown mysql:mysql /run/mysqld
if ! running mariadbd && ! running mysqld; then
    log "starting mariadbd"
    # the subshell too lets go of this script's output, which a caller may be reading until it closes
    (cd / && setsid nohup mariadbd --user=mysql &) </dev/null >/var/log/mysql-local.log 2>&1
fi
wait_for 30 mariadb -e 'SELECT 1'
mariadb -e "CREATE DATABASE IF NOT EXISTS slurm_acct_db;
CREATE USER IF NOT EXISTS 'slurm'@'localhost' IDENTIFIED BY '$DBPASS';
GRANT ALL ON slurm_acct_db.* TO 'slurm'@'localhost';"

# 5. slurmdbd, the cluster and its account
if ! running slurmdbd; then
    log "starting slurmdbd"
    /usr/sbin/slurmdbd </dev/null >/dev/null 2>&1
fi
wait_for 30 sacctmgr -n list cluster
sacctmgr -n list cluster format=cluster | grep -qw "$CLUSTER" || sacctmgr -i add cluster "$CLUSTER"
sacctmgr -n list account format=account | grep -qw "$ACCOUNT" \
    || sacctmgr -i add account "$ACCOUNT" cluster="$CLUSTER" description="local test" organization=local
sacctmgr -n list assoc where user="$USER_NAME" account="$ACCOUNT" format=user | grep -qw "$USER_NAME" \
    || sacctmgr -i add user "$USER_NAME" account="$ACCOUNT" cluster="$CLUSTER" defaultaccount="$ACCOUNT"

# 6. slurmctld and slurmd
if ! running slurmctld; then
    log "starting slurmctld"
    /usr/sbin/slurmctld </dev/null >/dev/null 2>&1
fi
wait_for 30 scontrol ping
if ! running slurmd; then
    log "starting slurmd"
    /usr/sbin/slurmd </dev/null >/dev/null 2>&1
fi
for _ in $(seq 30); do
    st=$(sinfo -h -N -o %t 2>/dev/null | head -1)
    case "$st" in idle|mix|alloc) break;; esac
    sleep 1
done
scontrol update nodename="$HOST" state=resume >/dev/null 2>&1 || true

# 7. checks
log "sinfo:"; sinfo
log "srun hostname:"; timeout 60 srun -A "$ACCOUNT" -N1 -n1 -t 1 hostname
wait_for 20 bash -c 'sacct -X -n -o JobName | grep -qw hostname'   # the accounting record arrives a moment later
log "sacct (last jobs):"; sacct -X -n -o JobID,JobName,Account,State,ExitCode | tail -3
log "ready: partition '$PARTITION', account '$ACCOUNT'"
