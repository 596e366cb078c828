#!/usr/bin/env bash
# The cluster workflow of docs/cluster.md on a real Slurm: starts munge, slurmctld and slurmd from
# Debian's packages (one node, no cgroups) in a temporary folder, creates an ordinary user, and
# has that user run the page's blocks marked "test-slurm" word for word, with a small sweep in
# place of the page's example:
#   A. `parpe` on the PATH: the merge job must complete and equal a one-machine sweep, byte for byte;
#   B. PARPE set: one task is cancelled while it runs; the merge must name that shard, and the
#      page's rerun block must then reach the same CSV;
#   C. a stepped array and a bare --array=2 must be refused;
#   D. a class graded as an array (sweep.slurm --grade): the merged report equals one machine's.
# Needs root (daemons) and a built parpe-cli/target/parpe.jar. The daemons are stopped by their
# PIDs at the end, also when a check fails. KEEP=1 keeps the temporary folder.
set -euo pipefail
root=$(cd "$(dirname "$(readlink -f "$0")")/.." && pwd)
started=$(date +%s)
if [ "$(id -u)" != 0 ]; then
    exec sudo -E bash "$0" "$@"
fi
jar=$root/parpe-cli/target/parpe.jar
[ -f "$jar" ] || { echo "test-slurm: $jar is missing; build first (mvn -B package)" >&2; exit 2; }
for cmd in munged slurmctld slurmd sbatch squeue scancel; do
    command -v "$cmd" >/dev/null || { echo "test-slurm: $cmd is missing (apt-get install munge slurm-wlm)" >&2; exit 2; }
done

user=parpe-slurm-test
id "$user" >/dev/null 2>&1 || useradd --create-home --shell /bin/bash "$user"
work=$(mktemp -d /tmp/parpe-slurm.XXXXXX)
chmod 755 "$work"
pids=()
log() { echo "test-slurm: $*" >&2; }
fail() {
    log "FAILED: $*"
    exit 1
}

stop() {
    local code=$? p
    # Our user's jobs first, so that no job step outlives slurmd; then the daemons, by PID.
    SLURM_CONF=$work/slurm.conf scancel -u "$user" >/dev/null 2>&1 || true
    for p in "${pids[@]}"; do
        kill "$p" 2>/dev/null || true
    done
    for p in "${pids[@]}"; do
        for _ in $(seq 50); do
            kill -0 "$p" 2>/dev/null || break
            sleep 0.2
        done
        kill -KILL "$p" 2>/dev/null || true
    done
    if [ "$code" != 0 ]; then
        for f in "$work"/log/*.log "$work"/site/results/*/*.log; do
            [ -f "$f" ] && { echo "== $f"; tail -n 20 "$f"; } >&2
        done
    fi
    [ "${KEEP:-}" = 1 ] && log "kept $work" || rm -rf "$work"
    log "took $(($(date +%s) - started)) s"
    exit "$code"
}
trap stop EXIT

# --- Slurm on this machine -------------------------------------------------------------------
mkdir -p "$work"/{munge,spool,state,log}
install -m 600 /etc/munge/munge.key "$work/munge/munge.key" 2>/dev/null \
    || dd if=/dev/urandom of="$work/munge/munge.key" bs=1 count=1024 status=none
chmod 600 "$work/munge/munge.key"
chmod 700 "$work/munge"
munged --foreground --force --socket="$work/munge/munge.socket" --key-file="$work/munge/munge.key" \
    --pid-file="$work/munge/munged.pid" --log-file="$work/log/munged.log" --seed-file="$work/munge/seed" >>"$work/log/munged.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$work/munge/munge.socket" ] && break; sleep 0.1; done
chmod 755 "$work/munge" # the socket must be reachable by the job's user
host=$(hostname -s)
cat >"$work/slurm.conf" <<EOF
ClusterName=parpetest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
DefMemPerCPU=700
KillWait=20
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=2 RealMemory=3000 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$work/slurm.conf
slurmctld -D -i >>"$work/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D >>"$work/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 100); do
    sinfo -h -o %t 2>/dev/null | grep -qx idle && break
    sleep 0.2
done
sinfo -h -o %t | grep -qx idle || fail "the node did not come up: $(sinfo 2>&1)"
log "Slurm is up ($(sinfo -h -o '%P %D %t'))"

# --- a shared installation and the user's folder ----------------------------------------------
site=$work/site
mkdir -p "$site/app/parpe-cli/target" "$site/bin"
cp "$root/parpe" "$site/app/parpe"
cp "$jar" "$site/app/parpe-cli/target/parpe.jar"
ln -s "$site/app/parpe" "$site/bin/parpe"
cp -r "$root/scripts" "$root/examples" "$site/"
chown -R "$user" "$site"

# block TAG: the fenced block after <!-- test-slurm: TAG --> in docs/cluster.md
block() {
    awk -v tag="<!-- test-slurm: $1 -->" '
        $0 == tag { found = 1; next }
        found && /^```/ { if (inside) exit; inside = 1; next }
        inside { print }' "$root/docs/cluster.md"
}
for tag in sweep submit rerun grade grade-submit; do
    [ -n "$(block $tag)" ] || fail "docs/cluster.md has no block marked test-slurm: $tag"
done
# The page's sweep, small: 18 runs in 3 shards of 6.
small='sweep=(examples/tutorial/10-race-snake.xml --sim snake:n=6 --duration 4 --vary bend=10..80:6 --vary period=1,2,3)'

# as_user NAME SETUP BLOCKS...: runs SETUP, then the page's BLOCKS, as the user in the site folder
as_user() {
    local name=$1 setup=$2 driver=$work/$1.sh
    shift 2
    {
        echo "set -euo pipefail"
        echo "export SLURM_CONF=$SLURM_CONF"
        echo "export PATH=/usr/local/bin:/usr/bin:/bin"
        echo "cd $site"
        echo "$setup"
        for b in "$@"; do block "$b" | grep -v -e '^k=' -e '^out=' -e '^n='; done
        echo "echo \$jid >$site/$name.jid"
    } >"$driver"
    su "$user" -s /bin/bash -c "bash $driver" || fail "$name: the page's commands failed"
}

# settle: waits until the user has no job left (at most 5 minutes)
settle() {
    for _ in $(seq 1500); do
        [ -z "$(squeue -h -u "$user" 2>/dev/null)" ] && return 0
        sleep 0.2
    done
    squeue -u "$user" >&2
    fail "jobs still queued after 5 minutes"
}

# The same sweep on one machine, as the page promises the merge will equal.
(cd "$site" && eval "$small" && su "$user" -s /bin/bash -c \
    "cd $site && app/parpe sweep $(printf '%q ' "${sweep[@]}") --out $site/one.csv" 2>"$site/one.log") \
    || { cat "$site/one.log" >&2; fail "the one-machine sweep failed"; }
[ "$(wc -l <"$site/one.csv")" = 19 ] || fail "the one-machine sweep has $(wc -l <"$site/one.csv") lines, not 19"

# --- A: parpe on the PATH ---------------------------------------------------------------------
as_user a "export PATH=$site/bin:\$PATH; out=results/a; n=3; $small" submit
settle
cmp "$site/one.csv" "$site/results/a/race.csv" || fail "A: the merged CSV differs from the one-machine sweep"
head -c 8 "$site/results/a/race.png" | grep -q PNG || fail "A: merge --plot drew no PNG"
log "A (parpe on PATH): merged CSV equals the one-machine sweep"

# --- B: PARPE set, one task cancelled while it runs, then the documented rerun -----------------
as_user b "export PARPE=$site/app/parpe; command -v parpe && exit 3; out=results/b; n=3; $small" submit
jid=$(cat "$site/b.jid")
partial=$site/results/b/shard-2-of-3.csv.partial
for _ in $(seq 3000); do
    [ -f "$partial" ] && [ "$(wc -l <"$partial")" -ge 2 ] && break
    sleep 0.02
done
[ -f "$partial" ] || fail "B: task 2 wrote no $partial"
# Held still until the cancel arrives: on a quiet machine its six runs end within 0.3 s of the
# first row, and a cancel that came after them found nothing to stop (Slurm sends SIGCONT with
# the SIGTERM, so the held task wakes to be stopped).
pkill -STOP -f -- "--shard 2/3" || true
su "$user" -s /bin/bash -c "SLURM_CONF=$SLURM_CONF scancel ${jid}_2"
settle
merge_log=$site/results/b/merge.log
[ ! -e "$site/results/b/race.csv" ] || fail "B: merge wrote race.csv although shard 2 was cancelled"
[ ! -e "$site/results/b/shard-2-of-3.csv" ] || fail "B: the cancelled shard looks whole"
grep -q "shard 2/3 is missing" "$merge_log" || fail "B: the merge log does not name shard 2: $(cat "$merge_log")"
grep -q "PARPE_SHARDS=3 sbatch --array=2 " "$merge_log" || fail "B: the merge log shows no rerun: $(cat "$merge_log")"
grep -q "stopped by SIGTERM" "$site/results/b/task-2.log" \
    || fail "B: task 2's log does not say SIGTERM: $(cat "$site/results/b/task-2.log")"
grep -q "runs, .* runs/s" "$site/results/b/task-1.log" || fail "B: task 1's log shows no progress"
rows=$(($(wc -l <"$partial") - 2))
log "B (PARPE set): cancelled task 2 kept $rows rows in its .partial file; the merge named shard 2"
as_user b2 "export PARPE=$site/app/parpe; out=results/b; n=3; k=2; $small" rerun
settle
cmp "$site/one.csv" "$site/results/b/race.csv" || fail "B: after the rerun the merged CSV differs from the one-machine sweep"
[ ! -e "$partial" ] || fail "B: the rerun left $partial"
log "B: the documented rerun reached the one-machine CSV"

# --- C: arrays the script refuses --------------------------------------------------------------
as_user c "export PARPE=$site/app/parpe; $small
jid=\$(sbatch --parsable --array=1-5:2 --output=results/c-step-%a.log scripts/sweep.slurm results/c \"\${sweep[@]}\")
sbatch --array=2 --output=results/c-one-%a.log scripts/sweep.slurm results/c \"\${sweep[@]}\" >/dev/null"
settle
grep -q "must be a step-1 range" "$site/results/c-step-1.log" || fail "C: a stepped array was not refused"
grep -q "would run the whole sweep as shard 1/1" "$site/results/c-one-2.log" || fail "C: --array=2 was not refused"
[ ! -e "$site/results/c" ] || [ -z "$(ls -A "$site/results/c")" ] || fail "C: a refused array wrote shards"
log "C: a stepped array and a bare --array=2 are refused"
# --- D: a class graded as an array (the page's grade-submit block) -----------------------------
mkdir -p "$site/class"
for bend in 20 35 50; do
    cat >"$site/class/s$bend.xml" <<XML
<program>
  <robot><structure><body elements="0..7"/></structure></robot>
  <main><race/></main>
  <behaviors><race><wave group="body" phase="0.2" period="1.5"/></race></behaviors>
  <automata><wave states="up, down"/></automata>
  <states><up angles="$bend" interp="smooth"/><down angles="-$bend" interp="smooth"/></states>
</program>
XML
done
printf '<program>\n  <robot>\n</program>\n' >"$site/class/broken.xml"
echo '<challenge world="examples/worlds/race-track.xml" robot="snake:n=8" duration="2" max-modules="8"/>' \
    >"$site/class.xml"
chown -R "$user" "$site/class" "$site/class.xml"
su "$user" -s /bin/bash -c "cd $site && app/parpe grade class.xml class --out one-grade >/dev/null 2>&1" \
    || fail "D: the one-machine grading failed"
as_user d "export PARPE=$site/app/parpe; out=results/d; n=3; grade=(class.xml class)" grade-submit
settle
for f in report.csv report.html; do
    cmp "$site/one-grade/$f" "$site/results/d/$f" || fail "D: the merged $f differs from the one-machine grading"
done
log "D (grading): the merged report equals the one-machine grading"
log "all checks passed"
