#!/usr/bin/env bash
# Encode speed of the patient status (issue: "encode for a patient with 50 findings in a
# database of 10,000 examinations answers in under 5 ms"). Builds the database with
# `vicc_patient import`, then times
#   - in-process: vicc_patient_bench (query of the examination at or before the date + visual
#     encoding, and separately the JSON serialization), 500 repetitions after warm-up;
#   - end to end: `vicc_patient encode --json` as a process (start-up, configuration loading,
#     database open, query, encoding, output), 20 runs.
# Writes bench/patient_status/results.json and results.md.
#   usage: bench/patient_status/run_bench.sh [--ws CATKIN_WS] [--work DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
ws="$repo"
work="${TMPDIR:-/tmp}/vicc_patient_bench"
while [ $# -gt 0 ]; do
  case "$1" in
    --ws) ws="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    *) echo "usage: $0 [--ws CATKIN_WS] [--work DIR]" >&2; exit 2 ;;
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

cli_ms=$(/usr/bin/python3 - "$bin/vicc_patient" "$db" <<'PY'
import statistics, subprocess, sys, time
times = []
for _ in range(20):
    start = time.perf_counter()
    subprocess.run([sys.argv[1], "encode", "--patient", "BENCH-00000", "--json",
                    "--db", sys.argv[2]], check=True, stdout=subprocess.DEVNULL)
    times.append((time.perf_counter() - start) * 1000.0)
print(f"{statistics.median(times):.2f} {max(times):.2f}")
PY
)

/usr/bin/python3 - "$here" "$in_process" "$in_process_dated" "$cli_ms" "$patients" \
  "$examinations" "$findings" "$db_bytes" "$import_start" "$import_end" <<'PY'
import json, platform, sys, os
here, bench, dated, cli, patients, exams, findings, size, t0, t1 = sys.argv[1:]
bench, dated = json.loads(bench), json.loads(dated)
cli_median, cli_max = map(float, cli.split())
result = {
    "database": {"patients": int(patients), "examinations": int(exams),
                 "findings": int(findings), "bytes": int(size),
                 "import_seconds": round(float(t1) - float(t0), 2)},
    "encode_latest": bench, "encode_at_date": dated,
    "cli_encode_json_ms": {"median": cli_median, "max": cli_max, "runs": 20},
    "goal_ms": 5.0,
    "machine": {"cpu": platform.processor() or platform.machine(), "cores": os.cpu_count()},
}
result["goal_met"] = bench["encode_ms"]["p95"] < 5.0 and dated["encode_ms"]["p95"] < 5.0
json.dump(result, open(f"{here}/results.json", "w"), indent=2)
md = f"""# Patient status: encode speed

Goal (issue 4): `encode` for a patient with 50 findings in a database of 10,000 examinations
answers in under 5 ms.

Database: {patients} patients, {exams} examinations, {findings} findings
({int(size) / 1e6:.1f} MB, imported with `vicc_patient import` in {float(t1) - float(t0):.1f} s).

| measurement | median ms | p95 ms | max ms |
| --- | --- | --- | --- |
| encode, latest examination ({bench['findings']} findings, {bench['encoded_structures']} shown) | {bench['encode_ms']['median']:.3f} | {bench['encode_ms']['p95']:.3f} | {bench['encode_ms']['max']:.3f} |
| encode, examination at or before 2020-02-01 ({dated['findings']} findings) | {dated['encode_ms']['median']:.3f} | {dated['encode_ms']['p95']:.3f} | {dated['encode_ms']['max']:.3f} |
| JSON serialization of the encoded status | {bench['json_ms']['median']:.3f} | {bench['json_ms']['p95']:.3f} | |
| `vicc_patient encode --json` process, end to end (20 runs) | {cli_median:.1f} | | {cli_max:.1f} |

"encode" is the in-process call the CLI and the node make (`PatientStatusService::encodedStatus`:
SQLite query of the examination at or before the date through the (patient, time) index, its
findings and values, validation screen, visual encoding, alternations and legend), timed over
500 repetitions after 5 warm-up calls by `vicc_patient_bench`. The process figure adds start-up,
loading and validating the YAML configuration and opening the database.

Goal met: **{'yes' if result['goal_met'] else 'no'}**. Reproduce: `bench/patient_status/run_bench.sh`.
"""
open(f"{here}/results.md", "w").write(md)
print(md)
PY
