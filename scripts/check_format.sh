#!/usr/bin/env bash
# Formatting gate: clang-format --dry-run -Werror (root .clang-format) on the C/C++ files this
# change touches, so the tree only ever becomes more formatted.
#   Which files: those that differ (committed or not) from the base of the change:
#   - on a branch other than main: the merge base with `main` (or origin/main);
#   - on main itself (CI on a fresh clone): HEAD's first parent, i.e. what the last commit or
#     merge brought in;
#   - without history (a single commit, an export): every tracked C/C++ file.
#   `scripts/check_format.sh --all` checks every tracked C/C++ file; `--base REV` sets the base.
set -euo pipefail
cd "$(dirname "$0")/.."

clang_format=""
for candidate in clang-format-14 clang-format; do
  if command -v "$candidate" >/dev/null 2>&1; then clang_format=$candidate; break; fi
done
if [ -z "$clang_format" ]; then
  echo "check_format: clang-format-14 not found (scripts/install_deps.sh installs it)" >&2
  exit 2
fi

patterns=('*.cpp' '*.hpp' '*.h' '*.cc' '*.cxx')
mode=auto
base=""
case "${1:-}" in
  --all) mode=all ;;
  --base) base=${2:?"--base needs a revision"}; mode=base ;;
  "") ;;
  *) echo "usage: scripts/check_format.sh [--all | --base REV]" >&2; exit 2 ;;
esac

first_existing_ref() {
  for ref in "$@"; do
    if git rev-parse --verify -q "$ref^{commit}" >/dev/null; then echo "$ref"; return 0; fi
  done
  return 1
}

if [ "$mode" = auto ]; then
  head=$(git rev-parse HEAD)
  main_ref=$(first_existing_ref main origin/main || true)
  if [ -n "$main_ref" ] && [ "$(git rev-parse "$main_ref")" != "$head" ]; then
    base=$(git merge-base HEAD "$main_ref")
    echo "check_format: files changed since the merge base with $main_ref (${base:0:10})"
  elif git rev-parse --verify -q "HEAD^1" >/dev/null; then
    base=$(git rev-parse "HEAD^1")
    echo "check_format: files changed by HEAD against its first parent (${base:0:10})"
  else
    mode=all
  fi
fi

files=()
if [ "$mode" = all ]; then
  echo "check_format: every tracked C/C++ file"
  mapfile -t files < <(git ls-files -- "${patterns[@]}")
else
  mapfile -t files < <(git diff --name-only --diff-filter=ACMR "$base" -- "${patterns[@]}")
fi

existing=()
for f in "${files[@]}"; do
  if [ -f "$f" ]; then existing+=("$f"); fi
done
if [ ${#existing[@]} -eq 0 ]; then
  echo "check_format: no C/C++ files to check"
  exit 0
fi

if "$clang_format" --dry-run -Werror --style=file "${existing[@]}"; then
  echo "check_format: ${#existing[@]} file(s) formatted ($clang_format)"
else
  echo "check_format: FAILED - run: $clang_format -i <file> on the files above" >&2
  exit 1
fi
