#!/usr/bin/env bash
# Builds the XML and SVG parser fuzzers with clang (libFuzzer + AddressSanitizer + UBSan),
# outside catkin, and runs each for a bounded time. Usage: fuzz/run_fuzz.sh [seconds]
# Needs clang and libclang-rt-14-dev. Crash inputs are kept in the work directory.
set -euo pipefail

SECONDS_PER_TARGET="${1:-60}"
PACKAGE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORK_DIR="${FUZZ_WORK_DIR:-/tmp/vicc_glyphs_fuzz}"
mkdir -p "$WORK_DIR"

COMMON_SOURCES=(
  src/dci/diffusion_curve.cpp
  src/io/text_file.cpp src/io/xml_attributes.cpp
)
ORZAN_SOURCES=(src/io/orzan_reader.cpp src/io/orzan_writer.cpp)
SVG_SOURCES=(
  src/io/svg_number_scanner.cpp src/io/svg_color.cpp src/io/svg_transform.cpp
  src/io/svg_geometry.cpp src/io/svg_arc.cpp src/io/svg_path_data.cpp src/io/svg_shapes.cpp
  src/io/svg_style.cpp src/io/fill_regions.cpp src/io/side_colors.cpp src/io/svg_document.cpp
  src/io/svg_import.cpp
)
FLAGS=(-std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
       -I"$PACKAGE_DIR/include" -isystem /usr/include/eigen3)

build() {  # name, sources...
  local name="$1"; shift
  local sources=()
  for s in "$@"; do sources+=("$PACKAGE_DIR/$s"); done
  clang++ "${FLAGS[@]}" "${sources[@]}" -ltinyxml2 -o "$WORK_DIR/$name"
}

seed_corpus() {  # directory, files...
  local dir="$1"; shift
  mkdir -p "$dir"
  for f in "$@"; do cp "$f" "$dir/"; done
}

build fuzz_orzan_xml fuzz/fuzz_orzan_xml.cpp "${COMMON_SOURCES[@]}" "${ORZAN_SOURCES[@]}"
build fuzz_svg fuzz/fuzz_svg.cpp "${COMMON_SOURCES[@]}" "${SVG_SOURCES[@]}"

seed_corpus "$WORK_DIR/corpus_orzan" "$PACKAGE_DIR"/data/samples/*.xml
seed_corpus "$WORK_DIR/corpus_svg" "$PACKAGE_DIR"/data/icons/*.svg "$PACKAGE_DIR"/test/data/*.svg

status=0
for target in fuzz_orzan_xml fuzz_svg; do
  corpus="$WORK_DIR/corpus_${target#fuzz_}"
  [ "$target" = fuzz_orzan_xml ] && corpus="$WORK_DIR/corpus_orzan"
  echo "=== $target for ${SECONDS_PER_TARGET}s"
  (cd "$WORK_DIR" && "./$target" -max_total_time="$SECONDS_PER_TARGET" -max_len=16384 \
     -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 "$corpus") || status=1
done
exit $status
