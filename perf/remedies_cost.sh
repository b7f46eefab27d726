#!/usr/bin/env bash
# The cost of the numerics remedies against the paper's model (perf/README.md, "The remedies'
# cost"): the dam break at dx 0.005 (validation/scenes/dam_break_dx0.005.toml) to t = 0.3 s on 2
# threads, as the paper's scene, with Fourtakas et al.'s density diffusion (delta 0.1), and with
# that and Lind et al.'s shifting once a step and once in 5 steps (shifting_every), runs
# alternated:
#   perf/remedies_cost.sh [BUILD] [ROUNDS]     (default build/release, 5 rounds)
# Prints each run (round, case, wall seconds), then each case's median and its ratio to the
# paper scene's median. Timings move 10-30 % from minute to minute on a shared VM: compare the
# medians of one call only.
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$src/build/release} rounds=${2:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scene=$src/validation/scenes/dam_break_dx0.005.toml
# name, the lines added to [physics]
cases=(paper diffusion remedies remedies_every5)
extra=(""
  'density_diffusion = 0.1\ndensity_diffusion_form = "fourtakas"'
  'density_diffusion = 0.1\ndensity_diffusion_form = "fourtakas"\nshifting = "lind"'
  'density_diffusion = 0.1\ndensity_diffusion_form = "fourtakas"\nshifting = "lind"\nshifting_every = 5')
for k in "${!cases[@]}"; do
  sed -e "0,/^name = .*/s//name = \"${cases[k]}\"/" -e 's/^end_time = .*/end_time = 0.3/' \
    -e "s/^\[physics\]/[physics]\n${extra[k]}/" "$scene" >"$out/${cases[k]}.toml"
done
for round in $(seq "$rounds"); do
  for c in "${cases[@]}"; do
    "$build/solver/sph" run "$out/$c.toml" --out "$out/run" --threads 2 --fixed-threads --quiet
    /usr/bin/python3 -c "import h5py,sys; print(sys.argv[1], sys.argv[2], h5py.File(sys.argv[3])['metrics'].attrs['wall_time_s'])" \
      "$round" "$c" "$out/run/$c.h5"
  done
done | tee "$out/times"
/usr/bin/python3 - "$out/times" <<'EOF'
import statistics, sys
times = {}
for line in open(sys.argv[1]):
    _, case, s = line.split()
    times.setdefault(case, []).append(float(s))
paper = statistics.median(times["paper"])
for case, t in times.items():
    m = statistics.median(t)
    print(f"{case:18s} median {m:7.2f} s  ({min(t):.2f}-{max(t):.2f})  {m / paper:.2f}x the paper scene")
EOF
