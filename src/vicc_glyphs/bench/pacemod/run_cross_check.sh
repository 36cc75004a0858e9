#!/usr/bin/env bash
# PACEMOD on icons it was not tuned on: the bench's grid (frequencies x amplitudes, all curves)
# on fixed samples of three filled icon sets fetched from the npm registry at run time
# (pinned versions; nothing is committed), checks only (--no-render: counts, lobe amplitudes,
# polygon crossings, modify time). The MDI set the work was tuned on is the bench's own input.
#
#   src/vicc_glyphs/bench/pacemod/run_cross_check.sh [WAVEFORM...]   (default: all four)
#   VICC_CROSS_CHECK_SETS="bootstrap remix" ...   (some sets)
#   VICC_CROSS_CHECK_RESULTS=/some/dir ...        (where to write the tables)
#
# Samples (sorted file names, every k-th from the first, 24 icons each):
#   bootstrap  bootstrap-icons@1.13.2  icons/*-fill.svg        every 20th
#   remix      remixicon@4.9.1         icons/**/*-fill.svg     every 64th
#   tabler     @tabler/icons@3.52.0    icons/filled/*.svg      every 44th
# Writes RESULTS/SET_WAVEFORM.md (the bench's output with --verbose) and RESULTS/summary.md
# (one row per set and waveform). Needs npm and a built workspace
# (devel/lib/vicc_glyphs/vicc_glyphs_pacemod_bench; VICC_GLYPH_BIN_DIR overrides).
# Exit code 1 if a bench run failed or any glyph has a new polygon crossing.
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
workspace="$(cd "$here/../../../.." && pwd)"
bench="${VICC_GLYPH_BIN_DIR:-$workspace/devel/lib/vicc_glyphs}/vicc_glyphs_pacemod_bench"
[[ -x "$bench" ]] || { echo "missing $bench (build the workspace first)" >&2; exit 1; }
command -v npm >/dev/null || { echo "missing npm" >&2; exit 1; }
results="${VICC_CROSS_CHECK_RESULTS:-$here/results}"
mkdir -p "$results"
waveforms=("$@")
(( ${#waveforms[@]} > 0 )) || waveforms=(sine rectangle triangle sawtooth)

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# set | npm package@version | find arguments below the package root | step
sets=(
  "bootstrap|bootstrap-icons@1.13.2|icons -maxdepth 1 -name *-fill.svg|20"
  "remix|remixicon@4.9.1|icons -name *-fill.svg|64"
  "tabler|@tabler/icons@3.52.0|icons/filled -maxdepth 1 -name *.svg|44"
)
kPerSet=24

summary="$results/summary.md"
{
  echo "| set | waveform | glyphs | contours | count ok, unreduced | count ok, reduced (decidable) | undecidable | full lobes within 10 % | reduced knot points (by the polygon check) | new crossings | new sharp turns | modify ms median |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$summary"
status=0
for entry in "${sets[@]}"; do
  IFS='|' read -r name package finder step <<< "$entry"
  if [[ -n "${VICC_CROSS_CHECK_SETS:-}" && " $VICC_CROSS_CHECK_SETS " != *" $name "* ]]; then
    continue
  fi
  target="$work/pkg/$name"
  mkdir -p "$target" "$work/icons/$name"
  (cd "$target" && npm pack --silent "$package" >/dev/null && tar xzf ./*.tgz)
  read -r -a find_args <<< "$finder"
  # The first find argument is the directory; the rest are its tests (globs stay unexpanded).
  mapfile -t all < <(cd "$target/package" && set -f && find "${find_args[@]}" | LC_ALL=C sort)
  (( ${#all[@]} > 0 )) || { echo "$name: no icons in $package" >&2; status=1; continue; }
  for (( i = 0, n = 0; i < ${#all[@]} && n < kPerSet; i += step, ++n )); do
    cp "$target/package/${all[$i]}" "$work/icons/$name/"
  done
  echo "$name: $package, ${#all[@]} icons, every ${step}th: $n" >&2
  for waveform in "${waveforms[@]}"; do
    out="$results/${name}_${waveform}.md"
    if ! "$bench" "$work/icons/$name" --waveform "$waveform" --no-render --verbose > "$out" 2>&1; then
      echo "$name $waveform: the bench failed (see $out)" >&2
      status=1
      continue
    fi
    # The bench's per-waveform total row: | waveform | glyphs | ... (see its README).
    row="$(grep -E "^\| $waveform \|" "$out" | tail -1)"
    IFS='|' read -r -a cells <<< "$row"
    crossings="$(echo "${cells[13]}" | tr -d ' ')"
    # cells: 1 waveform ... 12 reduced knot points, 13 new crossings, 14 new sub-pixel loops,
    # 15 new sharp turns, 16 modify ms median.
    echo "| $name |${cells[1]}|${cells[2]}|${cells[3]}|${cells[4]}|${cells[5]}|${cells[6]}|${cells[7]}|${cells[12]}|${cells[13]}|${cells[15]}|${cells[16]}|" >> "$summary"
    [[ "$crossings" == "0" ]] || status=1
  done
done
cat "$summary"
exit "$status"
