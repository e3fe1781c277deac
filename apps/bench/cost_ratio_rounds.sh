#!/bin/bash
# Cost per particle of the 2e5 film relative to the 1e4 film, measured in rounds that
# alternate the two sizes (centrec only), so that a slow spell of this shared machine hits
# both sizes of a round instead of one size of a whole benchmark run.
#   apps/bench/cost_ratio_rounds.sh [ROUNDS] [THREADS]      (defaults 3 rounds, 1 thread)
# Each round: 1e4, then 2e5, each settle 1500 steps, then the same film window of 3 x 500
# steps (equal film state at both sizes); the 1e4 film replays that window from its settled
# state 19 times (--replay-particle-steps 3e8), so both sizes time about 3e8 particle-steps.
# About 3 min per round on one core. Prints one line per round and the median ratio.
set -euo pipefail
rounds=${1:-3}
threads=${2:-1}
here=$(cd "$(dirname "$0")/../.." && pwd)
bench=${BENCH:-$here/${BUILD_DIR:-build}/apps/bench/centrec_bench_film}
[ -x "$bench" ] || { echo "no benchmark at $bench (run ./setup.sh, or set BENCH)" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

speed() {  # particle-steps/s of the centrec row of a results.csv
  awk -F, '$1 == "centrec" { print $6 }' "$1/results.csv"
}

ratios=()
for r in $(seq "$rounds"); do
  "$bench" --no-liggghts --sizes 10000 --threads "$threads" --steps 500 --repeats 3 --replay-particle-steps 3e8 --settle 1500 --out "$out/small" >/dev/null
  "$bench" --no-liggghts --sizes 200000 --threads "$threads" --steps 500 --repeats 3 --replay-particle-steps 3e8 --settle 1500 --out "$out/large" >/dev/null
  small=$(speed "$out/small")
  large=$(speed "$out/large")
  ratio=$(awk -v a="$small" -v b="$large" 'BEGIN { printf "%.3f", a / b }')
  ratios+=("$ratio")
  echo "round $r: 1e4 $small, 2e5 $large particle-steps/s, cost per particle 2e5 / 1e4 = $ratio"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{ a[NR] = $1 } END {
  m = NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2
  printf "median cost ratio over %d rounds: %.3f\n", NR, m }'
