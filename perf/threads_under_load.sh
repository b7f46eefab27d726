#!/usr/bin/env bash
# Issue 37: `sph run --threads 2` against `--threads 1` on a machine that other work wants. The
# dam break at dx 0.01 and 0.005 runs on 1 and 2 threads, alternated (1 2, then 2 1, ...), on an
# idle machine, with a CPU-bound process of this script's own on the second core, then one on
# each core. sph and the busy loops are held to two CPUs (the first two this script may use), so
# that the experiment is the 2-core machine's on any machine. Prints the table of wall times and
# ratios, writes it with every run's figures to OUT/threads_under_load.{md,csv}.
#
#   perf/threads_under_load.sh [--sph PATH] [--out DIR] [--repeats N] [--scenes a.toml,b.toml]
#                              [--loads idle,one,both] [--env NAME=VALUE]... [--wait-quiet]
#
# --wait-quiet: before each run, wait (10 min at most) for a second in which work other than the
# busy loops took less than 0.05 cores: on a machine shared with other people's builds.
#
# The wait policy is the program's own unless --env sets one (OMP_WAIT_POLICY, GOMP_SPINCOUNT are
# removed from the environment otherwise): the benchmark measures what a user gets.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
sph="$root/build/release/solver/sph"
out="$root/build/release/perf-results"
repeats=5
scenes="$root/validation/scenes/dam_break.toml,$root/validation/scenes/dam_break_dx0.005.toml"
loads="idle,one,both"
extra_env=()
wait_quiet=0
while [ $# -gt 0 ]; do
  case "$1" in
    --sph) sph="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --repeats) repeats="$2"; shift 2 ;;
    --scenes) scenes="$2"; shift 2 ;;
    --loads) loads="$2"; shift 2 ;;
    --env) extra_env+=("$2"); shift 2 ;;
    --wait-quiet) wait_quiet=1; shift ;;
    *) echo "threads_under_load.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
work="$(mktemp -d)"
csv="$out/threads_under_load.csv"

# The first two CPUs this process may run on.
read -r -a cpus < <(/usr/bin/python3 -c 'import os; print(*sorted(os.sched_getaffinity(0))[:2])')
if [ "${#cpus[@]}" -lt 2 ]; then echo "threads_under_load.sh: needs two CPUs" >&2; exit 2; fi
pair="${cpus[0]},${cpus[1]}"

busy=()
stop_busy() {
  local pid
  for pid in "${busy[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${busy[@]}"; do wait "$pid" 2>/dev/null || true; done
  busy=()
}
trap 'stop_busy; rm -rf "$work"' EXIT
start_busy() {  # a CPU-bound loop on each CPU given
  for cpu in "$@"; do
    taskset -c "$cpu" bash -c 'while :; do :; done' &
    busy+=("$!")
  done
}

busy_jiffies() {  # all CPUs' busy time so far (user nice system irq softirq steal), 1/100 s
  local cpu user nice system idle iowait irq softirq steal rest
  read -r cpu user nice system idle iowait irq softirq steal rest </proc/stat
  echo $((user + nice + system + irq + softirq + steal))
}
loop_jiffies() {  # the busy loops' CPU time so far
  local sum=0 pid
  for pid in "${busy[@]}"; do
    sum=$((sum + $(awk '{print $14 + $15}' "/proc/$pid/stat")))
  done
  echo "$sum"
}

wait_for_quiet() {
  local deadline=$((SECONDS + 600)) b0 l0
  while [ "$SECONDS" -lt "$deadline" ]; do
    b0=$(busy_jiffies) l0=$(loop_jiffies)
    sleep 1
    [ $(($(busy_jiffies) - b0 - $(loop_jiffies) + l0)) -lt 5 ] && return 0
  done
}

# scene threads -> "wall_s share_on_2 other_cores": other_cores, the cores that work other than
# this run and the busy loops took on average while it ran (all busy time less theirs).
run_once() {
  local log="$work/log" cpu="$work/cpu"
  local b0 l0 b1 l1
  b0=$(busy_jiffies) l0=$(loop_jiffies)
  local TIMEFORMAT="%U %S"  # bash's time: the run's user and system CPU seconds
  { time env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "${extra_env[@]}" \
    taskset -c "$pair" "$sph" run "$1" --out "$work/run" --threads "$2" >"$log" 2>&1; } 2>"$cpu"
  b1=$(busy_jiffies) l1=$(loop_jiffies)
  local wall share user sys
  if ! wall=$(grep -oP 'wall time \K[0-9.]+' "$log"); then
    echo "threads_under_load.sh: sph run $1 --threads $2 failed:" >&2
    cat "$log" >&2
    return 1
  fi
  share=$(grep -oP "steps on 2 threads \K[0-9]+" "$log" || echo "-")
  read -r user sys <"$cpu"
  rm -rf "$work/run"
  local others
  others=$(/usr/bin/python3 -c "print(f'{max(0.0, (($b1 - $b0) - ($l1 - $l0)) / 100 - $user - $sys) / $wall:.2f}')")
  echo "$wall $share $others"
}

echo "load,scene,repeat,threads,wall_s,percent_steps_on_2,other_cores" >"$csv"
echo "threads_under_load: sph $sph on CPUs $pair; ${extra_env[*]:-the wait policy sph chooses}"
echo "  before: $(uptime)"
IFS=, read -r -a load_list <<<"$loads"
IFS=, read -r -a scene_list <<<"$scenes"
for load in "${load_list[@]}"; do
  case "$load" in
    idle) ;;
    one) start_busy "${cpus[1]}" ;;
    both) start_busy "${cpus[0]}" "${cpus[1]}" ;;
    *) echo "threads_under_load.sh: unknown load $load" >&2; exit 2 ;;
  esac
  for scene in "${scene_list[@]}"; do
    for r in $(seq 1 "$repeats"); do
      order="1 2"
      [ $((r % 2)) -eq 0 ] && order="2 1"
      for t in $order; do
        [ "$wait_quiet" = 1 ] && wait_for_quiet
        result=$(run_once "$scene" "$t")
        read -r wall share others <<<"$result"
        echo "$load,$(basename "$scene" .toml),$r,$t,$wall,$share,$others" >>"$csv"
        echo "  $load $(basename "$scene" .toml) run $r, $t thread(s): $wall s" \
          "(steps on 2: $share %; other work: $others cores)"
      done
    done
  done
  stop_busy
done
echo "  after: $(uptime)"
/usr/bin/python3 "$root/perf/threads_table.py" "$csv" | tee "$out/threads_under_load.md"
