#!/usr/bin/env bash
# Builds the fuzz targets of the patient-record importers and the validator with clang
# (libFuzzer + AddressSanitizer + UBSan), outside catkin, and runs each for a bounded time,
# one after the other on one core. Usage: fuzz/run_fuzz.sh [seconds] [target...]
# (To run targets side by side, give each run its own FUZZ_WORK_DIR.)
# Targets: json_import fhir_import validator (default: all). Needs clang and
# libclang-rt-14-dev. Corpora and crash inputs are kept in the work directory.
set -euo pipefail

SECONDS_PER_TARGET="${1:-60}"
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -eq 0 ] && TARGETS=(json_import fhir_import validator)
PACKAGE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORK_DIR="${FUZZ_WORK_DIR:-/tmp/vicc_anatomy_viz_fuzz}"
# The core finds its configuration through vicc_paths (a sibling package in this workspace).
VICC_PATHS_DIR="$PACKAGE_DIR/../vicc_paths"
mkdir -p "$WORK_DIR"

# The core library's sources exactly as CMakeLists.txt lists them, so the fuzzers test what
# the package builds.
mapfile -t CORE_SOURCES < <(sed -n '/^add_library(vicc_anatomy_viz_core/,/)/p' \
  "$PACKAGE_DIR/CMakeLists.txt" | grep -o 'src/core/[a-z_]*\.cpp' | sed 's|src/core/||; s|\.cpp$||')
FUZZ_SOURCES=(fuzz_model fuzz_json_import fuzz_fhir_import fuzzed_examinations fuzz_validator)
FLAGS=(-std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
       -I"$PACKAGE_DIR/include" -I"$VICC_PATHS_DIR/include"
       -DVICC_ANATOMY_VIZ_SOURCE_DIR="\"$PACKAGE_DIR\"")

# The core and the harnesses once, as objects; then one entry point per target.
build_objects() {
  mkdir -p "$WORK_DIR/obj"
  local name
  for name in "${CORE_SOURCES[@]}"; do
    clang++ "${FLAGS[@]}" -c "$PACKAGE_DIR/src/core/$name.cpp" -o "$WORK_DIR/obj/$name.o"
  done
  clang++ "${FLAGS[@]}" -c "$VICC_PATHS_DIR/src/package_share.cpp" -o "$WORK_DIR/obj/package_share.o"
  for name in "${FUZZ_SOURCES[@]}"; do
    clang++ "${FLAGS[@]}" -c "$PACKAGE_DIR/fuzz/$name.cpp" -o "$WORK_DIR/obj/$name.o"
  done
}

harness_of() {  # target -> harness function
  case "$1" in
    json_import) echo fuzzJsonImport ;;
    fhir_import) echo fuzzFhirImport ;;
    validator) echo fuzzValidator ;;
    *) echo "unknown target $1" >&2; return 1 ;;
  esac
}

seed_corpus() {  # target: seeds from fuzz/seeds.txt and the regression inputs
  local target="$1" corpus="$WORK_DIR/corpus_$1" seed_target path
  mkdir -p "$corpus"
  while read -r seed_target path; do
    [ "$seed_target" = "$target" ] && cp "$PACKAGE_DIR/$path" "$corpus/"
  done < <(grep -v '^#' "$PACKAGE_DIR/fuzz/seeds.txt")
  find "$PACKAGE_DIR/fuzz/regressions/$target" -type f -exec cp {} "$corpus/" \;
}

build_objects
status=0
for target in "${TARGETS[@]}"; do
  clang++ "${FLAGS[@]}" -DVICC_FUZZ_TARGET="$(harness_of "$target")" \
    "$PACKAGE_DIR/fuzz/libfuzzer_entry.cpp" "$WORK_DIR"/obj/*.o -lyaml -lsqlite3 -o "$WORK_DIR/fuzz_$target"
  seed_corpus "$target"
  echo "=== $target for ${SECONDS_PER_TARGET}s"
  # -jobs=1 runs one worker process that logs to run_<target>/fuzz-0.log (echoed at its end).
  mkdir -p "$WORK_DIR/run_$target"
  (cd "$WORK_DIR/run_$target" && nice -n 10 "../fuzz_$target" -jobs=1 \
     -max_total_time="$SECONDS_PER_TARGET" -max_len=16384 -timeout=10 -rss_limit_mb=2048 \
     -print_final_stats=1 -artifact_prefix="$WORK_DIR/${target}_" "../corpus_$target") || status=1
  grep -E '^#[0-9]+ +DONE' "$WORK_DIR/run_$target/fuzz-0.log" || true
  if grep -q 'ERROR\|deadly signal\|runtime error' "$WORK_DIR/run_$target/fuzz-0.log"; then
    status=1
  fi
done
exit $status
