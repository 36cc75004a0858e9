#!/usr/bin/env bash
# Fidelity benchmark of the SVG import + renderer against librsvg (rsvg-convert) on real icon
# sets fetched from the npm registry at run time (nothing is committed). Per icon: both
# renders at SIZE px, dark-mask IoU and mean absolute gray difference
# (vicc_glyph_fidelity_compare), vicc_glyph's wall time, the size of the imported DCI
# (curves and Bezier control points: what the stroke outlining and refit produce), or the
# error message.
#
#   bench/fidelity/run_fidelity.sh [PER_SET] [SIZE]     (defaults 30 icons per set, 256 px)
#   VICC_FIDELITY_SETS="feather tabler-outline" bench/fidelity/run_fidelity.sh   (some sets)
#   VICC_FIDELITY_RENDER_ARGS="--stroke-outliner curves" ...   (extra vicc_glyph render flags)
#   VICC_FIDELITY_RESULTS=/some/dir ...   (where to write icons.tsv / summary.md)
#
# Needs: npm, rsvg-convert, a built workspace (devel/lib/vicc_glyphs/vicc_glyph and
# vicc_glyph_fidelity_compare; set VICC_GLYPH_BIN_DIR to override). Writes
# results/icons.tsv and results/summary.md next to this script (results/ is not committed;
# VICC_FIDELITY_RESULTS overrides the directory).
set -euo pipefail

per_set="${1:-30}"
size="${2:-256}"
here="$(cd "$(dirname "$0")" && pwd)"
workspace="$(cd "$here/../../../.." && pwd)"
bin="${VICC_GLYPH_BIN_DIR:-$workspace/devel/lib/vicc_glyphs}"
for tool in "$bin/vicc_glyph" "$bin/vicc_glyph_fidelity_compare"; do
  [[ -x "$tool" ]] || { echo "missing $tool (build the workspace first)" >&2; exit 1; }
done
command -v rsvg-convert >/dev/null || { echo "missing rsvg-convert (librsvg2-bin)" >&2; exit 1; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
results="${VICC_FIDELITY_RESULTS:-$here/results}"
read -r -a render_args <<< "${VICC_FIDELITY_RENDER_ARGS:-}"
mkdir -p "$results"

# set name | npm package | directory inside the package
sets=(
  "mdi|@mdi/svg|svg"
  "bootstrap|bootstrap-icons|icons"
  "fontawesome-solid|@fortawesome/fontawesome-free|svgs/solid"
  "fontawesome-regular|@fortawesome/fontawesome-free|svgs/regular"
  "simple-icons|simple-icons|icons"
  "octicons|@primer/octicons|build/svg"
  "remix|remixicon|icons/System"
  "tabler-filled|@tabler/icons|icons/filled"
  "heroicons-solid|heroicons|24/solid"
  "feather|feather-icons|dist/icons"
  "tabler-outline|@tabler/icons|icons/outline"
  "heroicons-outline|heroicons|24/outline"
)

fetch() {  # npm package -> extracted directory
  local package="$1" target="$work/pkg/${1//\//_}"
  if [[ ! -d "$target" ]]; then
    mkdir -p "$target"
    (cd "$target" && npm pack --silent "$package" >/dev/null 2>&1 && tar xzf ./*.tgz)
  fi
  echo "$target/package"
}

tsv="$results/icons.tsv"
printf 'set\ticon\tstatus\tiou\tmae\tseconds\tmessage\tcurves\tcontrol_points\n' > "$tsv"
for entry in "${sets[@]}"; do
  IFS='|' read -r name package directory <<< "$entry"
  if [[ -n "${VICC_FIDELITY_SETS:-}" && " $VICC_FIDELITY_SETS " != *" $name "* ]]; then continue; fi
  root="$(fetch "$package")/$directory"
  mapfile -t all < <(find "$root" -maxdepth 1 -name '*.svg' | LC_ALL=C sort)
  count=${#all[@]}
  (( count > 0 )) || { echo "$name: no icons found in $package/$directory" >&2; continue; }
  step=$(( count > per_set ? count / per_set : 1 ))
  echo "$name: $package $(basename "$(dirname "$root")")/$(basename "$root"), $count icons, every ${step}th" >&2
  for (( i = 0; i < count && i / step < per_set; i += step )); do
    svg="${all[$i]}"
    icon="$(basename "$svg" .svg)"
    ours="$work/ours.png" reference="$work/ref.png" dci="$work/ours.xml"
    rm -f "$ours" "$reference" "$dci"
    if ! rsvg-convert -w "$size" "$svg" -o "$reference" 2>/dev/null; then
      printf '%s\t%s\treference-failed\t\t\t\t\n' "$name" "$icon" >> "$tsv"
      continue
    fi
    start=$(date +%s.%N)
    if message="$("$bin/vicc_glyph" render "$svg" --size "$size" --out "$ours" --dci "$dci" \
        "${render_args[@]}" 2>&1 >/dev/null)"; then
      seconds=$(echo "$(date +%s.%N) - $start" | bc)
      curves="$(grep -c '<curve[ >]' "$dci" || true)"
      points="$(grep -o '<control_point' "$dci" | wc -l)"
      if line="$("$bin/vicc_glyph_fidelity_compare" "$ours" "$reference" 2>&1)"; then
        read -r _ iou _ mae _ <<< "$line"
        printf '%s\t%s\tok\t%s\t%s\t%s\t\t%s\t%s\n' "$name" "$icon" "$iou" "$mae" "$seconds" \
          "$curves" "$points" >> "$tsv"
      else
        printf '%s\t%s\tcompare-failed\t\t\t%s\t%s\n' "$name" "$icon" "$seconds" "$line" >> "$tsv"
      fi
    else
      seconds=$(echo "$(date +%s.%N) - $start" | bc)
      message="$(echo "$message" | head -1 | tr '\t' ' ' | sed "s|$root/||")"
      printf '%s\t%s\tfailed\t\t\t%s\t%s\n' "$name" "$icon" "$seconds" "$message" >> "$tsv"
    fi
  done
done

/usr/bin/python3 "$here/summarize.py" "$tsv" "$size" > "$results/summary.md"
cat "$results/summary.md"
