#!/usr/bin/env bash
# Whole-run and residual-solver timings at several mesh sizes:
# LEMON multilevel (the default) vs LEMON network simplex vs GLPK, CHOLMOD vs Eigen's LDLT, exact vs
# reduced residual. Not a test; writes one log per instance to benchmark/results/scaling/, cited in
# benchmark/SPEED.md ("Speed in detail") and benchmark/residual_solvers.md.
#
#   benchmark/scaling.sh [BENCH_BINARY [NAME]]
#
# BENCH_BINARY: benchmark/residual_solvers.cpp built as in benchmark/residual_solvers.md
# (default build-lemon/bench/residual_solvers). The chain6 instance needs the benchmark's mesh
# cache (benchmark/run --full builds it in build-bench/mesh-cache), the chain10 one (1.15M faces,
# genus 10) the "large" suite of the generator (about 1 min):
#   build-bench/swn_bench_gen --suite large --out build-bench/cases-large --mesh-cache "$PWD/build-bench/mesh-cache"
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build-lemon/bench/residual_solvers}
OUT=benchmark/results/scaling
mkdir -p "$OUT"
D=data/swn-demo
ONLY=${2:-}   # optional: run only the instances whose name contains this string
run() {
  local name=$1; shift
  [ -z "$ONLY" ] || [[ "$name" == *"$ONLY"* ]] || return 0
  echo "== $name: $B $*" | tee "$OUT/$name.log"
  /usr/bin/time -v "$B" "$@" 2>&1 | grep -v "^\[swn\]" | grep -v -E "^\s(Average|Major|Minor|Voluntary|Involuntary|Swaps|File system|Socket|Signals|Page size|Percent)" | tee -a "$OUT/$name.log" || true
}
run torus-phi      $D/torus.obj --curve $D/torus-phi.txt --scaling 0 --table 1 --glpk 1 --repeat 3
run dtwl-35k       $D/DoubleTorusWithLoops.obj --scaling 0 --table 1 --glpk 0 --repeat 3
run dtwl-140k      $D/DoubleTorusWithLoops.obj --subdivide 1 --scaling 0 --table 1 --glpk 0 --repeat 1
CH=build-bench/mesh-cache/chain6_80k_80000.off
if [ -f "$CH" ]; then
  run chain6-188k  $CH --curve $OUT/chain6_80k_r0_g05.curve.txt --scaling 0 --table 1 --glpk 0 --repeat 1
fi
run dtwl-560k      $D/DoubleTorusWithLoops.obj --subdivide 2 --scaling 0 --simplex 0 --table 1 --glpk 0 --repeat 1
if [ -f "$CH" ]; then
  run chain6-752k  $CH --curve $OUT/chain6_80k_r0_g05.curve.txt --subdivide 1 --scaling 0 --simplex 0 --table 1 --glpk 0 --repeat 1
fi
C10=build-bench/mesh-cache/chain10_500k_500000.off
if [ -f "$C10" ]; then
  run chain10-1154k $C10 --curve $OUT/chain10_500k_r0_g05.curve.txt --scaling 0 --simplex 0 --table 1 --glpk 0 --repeat 1
fi
