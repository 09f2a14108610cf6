#!/usr/bin/env bash
# Checks that the benchmark's cases do not move with round-off: builds swn_bench_gen twice, as
# benchmark/run does and with other compiler flags (default -march=native: other SIMD kernels in Eigen,
# so other round-off), generates a suite with each build from the same mesh cache and compares every
# case file by checksum. Exit status 0 when all are identical.
#
#   benchmark/check_generator.sh [--suite paper] [--flags "-march=native"] [--work DIR] [--only handles]
#
# Needs the mesh cache and CGAL's data as benchmark/run leaves them in build-bench/ (run it once first).
# About 10 minutes for the paper suite on 2 cores (two builds of the generator, two generations).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(dirname "$HERE")"
suite=paper
flags="-march=native"
work="$ROOT/build-check-generator"
only=()
while [ $# -gt 0 ]; do
  case "$1" in
    --suite) suite="$2"; shift ;;
    --flags) flags="$2"; shift ;;
    --work) work="$2"; shift ;;
    --only) only=(--only "$2"); shift ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "check_generator.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done
cache="$ROOT/build-bench/mesh-cache"
data="$ROOT/build-bench/cgal-data"
[ -d "$cache" ] || { echo "check_generator.sh: no $cache (run benchmark/run once)" >&2; exit 2; }
rm -rf "$work/cases-a" "$work/cases-b"
mkdir -p "$work"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
for v in a b; do
  extra=()
  [ "$v" = b ] && extra=(-DCMAKE_CXX_FLAGS="$flags")
  cmake -S "$HERE" -B "$work/build-$v" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "${extra[@]}" \
    >"$work/configure-$v.log" 2>&1 || { cat "$work/configure-$v.log" >&2; exit 1; }
  cmake --build "$work/build-$v" -j1 --target swn_bench_gen >&2
  "$work/build-$v/swn_bench_gen" --suite "$suite" --out "$work/cases-$v" --mesh-cache "$cache" --cgal-data "$data" \
    "${only[@]}" 2>"$work/gen-$v.log"
done
(cd "$work/cases-a/cases" && find . -type f | sort | xargs sha256sum) >"$work/a.sha256"
(cd "$work/cases-b/cases" && find . -type f | sort | xargs sha256sum) >"$work/b.sha256"
n=$(wc -l <"$work/a.sha256")
if cmp -s "$work/a.sha256" "$work/b.sha256"; then
  echo "check_generator.sh: $n case files identical with and without '$flags' (suite $suite)"
else
  echo "check_generator.sh: case files differ with '$flags' (suite $suite):" >&2
  diff "$work/a.sha256" "$work/b.sha256" | grep '^[<>]' | awk '{print $3}' | sort -u | head -20 >&2
  exit 1
fi
