#!/usr/bin/env bash
# Reads catkin's JUnit results and ends with the plain line "N passed, N failed".
# catkin_make run_tests exits 0 even when tests fail, so the verdict comes from here.
set -uo pipefail
results_dir=${1:-build/test_results}
export PATH=/usr/bin:/bin:$PATH
if [ ! -d "$results_dir" ]; then
  echo "test_summary: no results under $results_dir (did the tests build?)"
  echo "0 passed, 1 failed"
  exit 1
fi
catkin_test_results --verbose "$results_dir" > build/test_results_summary.txt 2>&1
verdict=$?
grep -vE "^(Skipping|$)" build/test_results_summary.txt | tail -n 40
line=$(grep -E "^Summary:" build/test_results_summary.txt | tail -n 1)
# Summary: 12 tests, 0 errors, 1 failures, 0 skipped
total=$(sed -E 's/.* ([0-9]+) tests.*/\1/' <<<"$line")
errors=$(sed -E 's/.* ([0-9]+) errors.*/\1/' <<<"$line")
failures=$(sed -E 's/.* ([0-9]+) failures.*/\1/' <<<"$line")
skipped=$(sed -E 's/.* ([0-9]+) skipped.*/\1/' <<<"$line")
if ! [[ "$total" =~ ^[0-9]+$ ]]; then
  echo "test_summary: could not read catkin_test_results output"
  echo "0 passed, 1 failed"
  exit 1
fi
failed=$((errors + failures))
passed=$((total - failed - skipped))
if [ "$total" -eq 0 ]; then failed=1; echo "test_summary: no test ran"; fi
echo "${passed} passed, ${failed} failed, ${skipped} skipped"
if [ "$verdict" -ne 0 ] || [ "$failed" -ne 0 ]; then exit 1; fi
exit 0
