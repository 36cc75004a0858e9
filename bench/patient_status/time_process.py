#!/usr/bin/env python3
"""Times a command as whole processes (what a caller of `vicc_patient` waits for): wall time
from spawn to exit, and the CPU time (user + system) the child used, which a busy machine
inflates less. Each run is followed by a run of a trivial process (--floor), so that the
spawn cost under the same load is known. Prints one JSON object.

usage: time_process.py [--runs 100] [--floor /bin/true] -- COMMAND...
"""
import argparse
import json
import os
import subprocess
import sys
import time


def run_once(command, devnull):
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=devnull)
    _, status, usage = os.wait4(child.pid, 0)
    wall = (time.perf_counter() - start) * 1000.0
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"time_process: {command[0]} failed")
    return wall, (usage.ru_utime + usage.ru_stime) * 1000.0


def summary(values):
    ordered = sorted(values)
    at = lambda fraction: ordered[int(fraction * (len(ordered) - 1))]
    return {"median": round(at(0.5), 3), "p95": round(at(0.95), 3),
            "min": round(ordered[0], 3), "max": round(ordered[-1], 3)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=100)
    parser.add_argument("--floor", default="/bin/true")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command or args.runs < 1:
        parser.error("a command and --runs >= 1 are needed")
    walls, cpus, floors = [], [], []
    load_before = os.getloadavg()
    with open(os.devnull, "w") as devnull:
        run_once(command, devnull)  # warm the page cache once, like any repeated use
        for _ in range(args.runs):
            wall, cpu = run_once(command, devnull)
            walls.append(wall)
            cpus.append(cpu)
            floors.append(run_once([args.floor], devnull)[0])
    load_after = os.getloadavg()
    print(json.dumps({"runs": args.runs, "wall_ms": summary(walls), "cpu_ms": summary(cpus),
                      "spawn_floor_ms": summary(floors),
                      "load_average_1min": [round(load_before[0], 2), round(load_after[0], 2)]}))


if __name__ == "__main__":
    main()
