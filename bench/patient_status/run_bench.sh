#!/usr/bin/env bash
# Encode speed of the patient status (issue: "encode for a patient with 50 findings in a
# database of 10,000 examinations answers in under 5 ms"). Builds the database with
# `vicc_patient import`, then times
#   - in-process: vicc_patient_bench (query of the examination at or before the date + visual
#     encoding, and separately the JSON serialization), 500 repetitions after warm-up;
#     and loading the configuration (YAML parsing + validation of the view);
#   - whole process: `vicc_patient encode --json` as a process (exec, dynamic linking,
#     configuration loading, database open, query, encoding, output), --runs runs (default
#     100), wall time and the child's CPU time, each run followed by a trivial process to show
#     the spawn cost under the same machine load (time_process.py).
# Writes bench/patient_status/results.json and results.md, with the machine load.
#   usage: bench/patient_status/run_bench.sh [--ws CATKIN_WS] [--work DIR] [--runs N]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
ws="$repo"
work="${TMPDIR:-/tmp}/vicc_patient_bench"
runs=100
while [ $# -gt 0 ]; do
  case "$1" in
    --ws) ws="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    *) echo "usage: $0 [--ws CATKIN_WS] [--work DIR] [--runs N]" >&2; exit 2 ;;
  esac
done
export PATH=/usr/bin:/bin:$PATH
set +u; source "$ws/devel/setup.bash"; set -u
bin="$ws/devel/lib/vicc_anatomy_viz"
package="$repo/src/vicc_anatomy_viz"
mkdir -p "$work"
db="$work/patients.db"
data="$work/records.json"
rm -f "$db" "$db-wal" "$db-shm"

/usr/bin/python3 "$here/make_dataset.py" "$package" "$data" --examinations 10000 --findings 50
import_start=$(date +%s.%N)
"$bin/vicc_patient" import "$data" --db "$db" >&2
import_end=$(date +%s.%N)
patients=$("$bin/vicc_patient" list --db "$db" | tail -n +2 | wc -l)
count() { /usr/bin/python3 -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('SELECT count(*) FROM ' + sys.argv[2]).fetchone()[0])" "$db" "$1"; }
examinations=$(count examinations)
findings=$(count findings)
db_bytes=$(stat -c %s "$db")

in_process=$("$bin/vicc_patient_bench" --db "$db" --patient BENCH-00000 --repeat 500)
# Also a query by date that lands on an earlier examination.
in_process_dated=$("$bin/vicc_patient_bench" --db "$db" --patient BENCH-00000 \
  --date 2020-02-01 --repeat 500)

process=$(/usr/bin/python3 "$here/time_process.py" --runs "$runs" -- \
  "$bin/vicc_patient" encode --patient BENCH-00000 --json --db "$db")

/usr/bin/python3 "$here/write_results.py" "$here" "$in_process" "$in_process_dated" "$process" \
  "$patients" "$examinations" "$findings" "$db_bytes" "$import_start" "$import_end"
