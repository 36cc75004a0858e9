#!/usr/bin/env python3
"""Writes bench/patient_status/results.json and results.md from run_bench.sh's measurements
and prints the Markdown. Both goals are judged separately: the in-process encode (what the
node answers, configuration loaded once) and the whole `vicc_patient encode --json` process
(what a CLI caller waits for).

usage: write_results.py HERE IN_PROCESS_JSON DATED_JSON PROCESS_JSON PATIENTS EXAMINATIONS
                        FINDINGS DB_BYTES IMPORT_START IMPORT_END
"""
import json
import os
import sys

GOAL_MS = 5.0


def cpu_model():
    try:
        with open("/proc/cpuinfo") as cpuinfo:
            for line in cpuinfo:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def row(name, figures, keys=("median", "p95", "min", "max"), digits=3):
    cells = [f"{figures[key]:.{digits}f}" if key in figures else "" for key in keys]
    return f"| {name} | " + " | ".join(cells) + " |"


def verdict(met):
    return "met" if met else "NOT met"


def markdown(result):
    db, bench, dated = result["database"], result["encode_latest"], result["encode_at_date"]
    process, machine = result["process_encode_json"], result["machine"]
    load = process["load_average_1min"]
    notes = []
    if max(load) >= machine["cores"]:
        notes.append("The machine was at least as busy as it has cores (it is shared with other jobs).")
    if process["wall_ms"]["p95"] > 1.25 * process["cpu_ms"]["p95"]:
        notes.append(f"Wall p95 {process['wall_ms']['p95']:.2f} ms against CPU-time p95 "
                     f"{process['cpu_ms']['p95']:.2f} ms: the slow runs waited for a CPU "
                     "rather than worked longer.")
    in_keys = ("median", "p95", "max")
    return f"""# Patient status: encode speed

Goal (issue 4): `encode` for a patient with 50 findings in a database of 10,000 examinations
answers in under {GOAL_MS:g} ms. Two figures, judged separately: the **whole process**
`vicc_patient encode --json` (what a command-line caller waits for: exec, dynamic linking,
configuration loading and validation, database open, query, encoding, JSON output) and the
**in-process** encode (what the `patient_status_server` node answers; it loads once).

Database: {db['patients']} patients, {db['examinations']} examinations, {db['findings']} findings
({db['bytes'] / 1e6:.1f} MB, imported with `vicc_patient import` in {db['import_seconds']:.1f} s).

## Whole process: `vicc_patient encode --json`, {process['runs']} runs

| measurement | median ms | p95 ms | min ms | max ms |
| --- | --- | --- | --- | --- |
{row("wall time, spawn to exit", process['wall_ms'])}
{row("CPU time of the process (user + system)", process['cpu_ms'])}
{row("spawn floor: `/bin/true` right after each run", process['spawn_floor_ms'])}

Whole-process goal (median wall time < {GOAL_MS:g} ms): **{verdict(result['process_goal_met'])}**
(median {process['wall_ms']['median']:.2f} ms; p95 {process['wall_ms']['p95']:.2f} ms, \
{'also under' if process['wall_ms']['p95'] < GOAL_MS else 'which is over'} {GOAL_MS:g} ms).

## In-process: `vicc_patient_bench`, 500 repetitions after 5 warm-up calls

| measurement | median ms | p95 ms | max ms |
| --- | --- | --- | --- |
{row(f"encode, latest examination ({bench['findings']} findings, {bench['encoded_structures']} shown)", bench['encode_ms'], in_keys)}
{row(f"encode, examination at or before 2020-02-01 ({dated['findings']} findings)", dated['encode_ms'], in_keys)}
{row("JSON serialization of the encoded status", bench['json_ms'], in_keys)}
{row("configuration loading: both YAML files parsed, view validated", bench['load_ms'], in_keys)}
{row("record database opened and closed (creates and removes the WAL index)", bench['store_open_ms'], in_keys)}

In-process goal (encode p95 < {GOAL_MS:g} ms): **{verdict(result['in_process_goal_met'])}**.

"encode" is `PatientStatusService::encodedStatus` (SQLite query of the examination at or before
the date through the (patient, time) index, its findings and values, validation screen, visual
encoding, alternations and legend).

## Machine

{machine['cpu']}, {machine['cores']} cores, shared. 1-minute load average
{load[0]:.2f} before and {load[1]:.2f} after the process runs. {' '.join(notes)}

Reproduce: `bench/patient_status/run_bench.sh [--runs N]`. Where the start-up time went and
what was changed: `bench/patient_status/startup_profile.md`.
"""


def main():
    (here, bench, dated, process, patients, exams, findings, size, t0, t1) = sys.argv[1:]
    bench, dated, process = json.loads(bench), json.loads(dated), json.loads(process)
    result = {
        "database": {"patients": int(patients), "examinations": int(exams),
                     "findings": int(findings), "bytes": int(size),
                     "import_seconds": round(float(t1) - float(t0), 2)},
        "encode_latest": bench, "encode_at_date": dated,
        "process_encode_json": process,
        "goal_ms": GOAL_MS,
        "machine": {"cpu": cpu_model(), "cores": os.cpu_count()},
    }
    result["in_process_goal_met"] = (bench["encode_ms"]["p95"] < GOAL_MS
                                     and dated["encode_ms"]["p95"] < GOAL_MS)
    result["process_goal_met"] = process["wall_ms"]["median"] < GOAL_MS
    with open(f"{here}/results.json", "w") as out:
        json.dump(result, out, indent=2)
    text = markdown(result)
    with open(f"{here}/results.md", "w") as out:
        out.write(text)
    print(text)


if __name__ == "__main__":
    main()
