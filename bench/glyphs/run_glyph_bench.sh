#!/usr/bin/env bash
# Glyph bench (issues 5, 16): renders every vendored icon, the gallery's coloured DCIs and the
# ladybug sample at 512 x 512 on one core and writes the tables of bench/glyphs/results.md
# (the hand-written sections below them stay): one-shot render
# time (the first render, with a fresh renderer), median render time (renderer reused, first
# render excluded), CG iterations with the default stopping criterion, its error estimate,
# the mean and largest absolute error against a direct sparse solve of the same discrete
# problem, and the median wall time of a whole `vicc_glyph render` process.
# Usage: bench/glyphs/run_glyph_bench.sh [path/to/vicc_glyph_bench]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
bench="${1:-$root/devel/lib/vicc_glyphs/vicc_glyph_bench}"
tool="$(dirname "$bench")/vicc_glyph"
if [[ ! -x "$bench" ]]; then
  echo "no vicc_glyph_bench at $bench: build the workspace (catkin_make) or pass its path" >&2
  exit 1
fi
inputs=("$root"/src/vicc_glyphs/data/icons/*.svg "$root"/docs/glyph_gallery/*.xml
  "$root"/src/vicc_glyphs/data/samples/ladybug_usvg.xml)
# One thread (the bench itself sets OpenCV and Eigen to one thread; no OpenMP/TBB helpers).
# VICC_BENCH_CPU=N pins it to core N; by default the scheduler picks the least busy core,
# which on a machine shared with other jobs gives steadier numbers than a fixed core.
pin=()
if [[ -n "${VICC_BENCH_CPU:-}" ]]; then pin=(taskset -c "$VICC_BENCH_CPU"); fi
export OMP_NUM_THREADS=1 OPENCV_FOR_THREADS_NUM=1
table="$("${pin[@]}" "$bench" --size 512 --repeats 31 "${inputs[@]}")"
# Whole processes (start, import, render, PNG), median of 7 runs each.
process_table="| input | process wall ms (median of 7) |
|---|---:|"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
for input in "${inputs[@]}"; do
  times=()
  for _ in 1 2 3 4 5 6 7; do
    start=$(date +%s%N)
    "${pin[@]}" "$tool" render "$input" --size 512 --out "$scratch/out.png"
    times+=($((($(date +%s%N) - start) / 1000000)))
  done
  median="$(printf '%s\n' "${times[@]}" | sort -n | sed -n 4p)"
  process_table+="
| $(basename "$input") | $median |"
done
cpu="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
# The hand-written sections after the generated tables (from the first "## " heading on: the
# history of earlier measurements) are kept; only the tables above them are replaced.
history=""
if [[ -f "$here/results.md" ]]; then history="$(sed -n '/^## /,$p' "$here/results.md")"; fi
{
  echo "# Glyph bench results"
  echo
  echo "Produced by \`bench/glyphs/run_glyph_bench.sh\` on $(date -u +%Y-%m-%d) ($cpu, $(grep -c ^processor /proc/cpuinfo) cores"
  echo "shared with other jobs; one thread). Release build, 512 x 512 RGB, default options"
  echo "(FMG on Galerkin coarse levels, then CG preconditioned by a V(1,1)-cycle on the finest"
  echo "grid until the error estimate is at most 0.002, anti-aliasing on; the blur pass runs only for"
  echo "DCIs with blur points: heart_glow; since session 43 an input whose every region sees one"
  echo "colour, as the flat icons and virus_green, takes those colours without the multigrid:"
  echo "0 levels, 0 iterations, error below 1e-5 against the direct solve, \"solve ms\" that check; see"
  echo "src/vicc_glyphs/docs/rendering.md, \"Regions of one colour\"). \"one-shot ms\" is the first render of each input"
  echo "with a fresh \`DiffusionCurveRenderer\` (as \`renderDiffusionCurves()\` or a CLI run), which"
  echo "also pays for first-touch page faults of its buffers (huge pages where the kernel grants"
  echo "them, see src/vicc_glyphs/docs/rendering.md); later inputs may reuse memory the process"
  echo "already has, so a CLI run is the colder case. The other times are medians of 31 renders"
  echo "with a reused renderer, first render excluded. MAE is the mean absolute"
  echo "difference (colours in 0..1) between the multigrid solution and Eigen's SimplicialLDLT"
  echo "solve of the identical discrete problem (before anti-aliasing and blur), \"max error\" the"
  echo "largest; \"error estimate\" is what the stopping criterion saw. \"median ms\" is"
  echo "wall time of the whole render (assembly of all levels, multigrid, anti-aliasing, blur),"
  echo "\"median CPU ms\" the thread's CPU time for it (not counting other jobs on the core),"
  echo "\"solve ms\" the multigrid part alone. On this shared machine the times depend on what"
  echo "other jobs run at the same time: while it was busy, runs measured up to twice these (CPU"
  echo "time too, as the virtual cores share caches)."
  echo
  echo "$table"
  echo
  echo "Load average when it finished: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo
  echo "$process_table"
  if [[ -n "$history" ]]; then
    echo
    echo "$history"
  fi
} >"$here/results.md"
cat "$here/results.md"
