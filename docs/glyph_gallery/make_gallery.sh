#!/usr/bin/env bash
# Renders the glyph gallery with the vicc_glyph tool: every vendored icon as imported (black
# on white) and our coloured DCI variants (*.xml here), all at 512 pixels wide.
# Usage: docs/glyph_gallery/make_gallery.sh [path/to/vicc_glyph]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
tool="${1:-$root/devel/lib/vicc_glyphs/vicc_glyph}"
if [[ ! -x "$tool" ]]; then
  echo "no vicc_glyph at $tool: build the workspace first (catkin_make) or pass its path" >&2
  exit 1
fi
for icon in "$root"/src/vicc_glyphs/data/icons/*.svg; do
  name="$(basename "$icon" .svg)"
  "$tool" render "$icon" --size 512 --out "$here/$name.png"
done
for dci in "$here"/*.xml; do
  name="$(basename "$dci" .xml)"
  "$tool" render "$dci" --size 512 --out "$here/$name.png"
done
echo "gallery written to $here"
