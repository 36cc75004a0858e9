#!/usr/bin/env bash
# Renders the glyph gallery with the vicc_glyph tool, all at 512 pixels wide with the default
# stopping criterion: five vendored MDI icons as imported (black on white), the stroke and
# multi-shape icons in icons/ (Feather, Bootstrap Icons; MIT), our coloured DCI variants
# (*.xml here) and the ladybug sample DCI.
# Usage: docs/glyph_gallery/make_gallery.sh [path/to/vicc_glyph]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
tool="${1:-$root/devel/lib/vicc_glyphs/vicc_glyph}"
if [[ ! -x "$tool" ]]; then
  echo "no vicc_glyph at $tool: build the workspace first (catkin_make) or pass its path" >&2
  exit 1
fi
inputs=()
for name in brain heart lungs virus weather-pouring; do
  inputs+=("$root/src/vicc_glyphs/data/icons/$name.svg")
done
inputs+=("$here"/icons/*.svg "$here"/*.xml "$root/src/vicc_glyphs/data/samples/ladybug_usvg.xml")
for input in "${inputs[@]}"; do
  name="$(basename "$input")"
  name="${name%.*}"
  name="${name%_usvg}"  # ladybug_usvg.xml -> ladybug.png
  "$tool" render "$input" --size 512 --out "$here/$name.png"
done
echo "gallery written to $here"
