#!/usr/bin/env python3
"""Writes a synthetic but valid patient-records file (our JSON format) for the encode benchmark:
N examinations spread over patients, and one target patient whose latest examination has
exactly F findings. Valid against the shipped view: categories, structures, sides and values
come from the package's YAML configuration.

usage: make_dataset.py PACKAGE_DIR OUT.json [--examinations 10000] [--findings 50] [--seed 4]
"""
import argparse
import datetime
import json
import random

import yaml


def load(package_dir):
    encoding = yaml.safe_load(open(f"{package_dir}/config/encoding/neurological_status.yaml"))
    anatomy = yaml.safe_load(open(f"{package_dir}/config/anatomy/structures.yaml"))
    classes = {c["id"]: c for c in anatomy["structure_classes"]}
    view = next(v for v in encoding["views"] if v["id"] == "neurological_status_sdh")
    categories = {c["id"]: c for c in encoding["categories"]}
    # Every (category, structure, side) a finding of the view can name.
    slots = []
    for entry in view["categories"]:
        category = categories[entry["category"]]
        for structure in anatomy["structures"]:
            if structure["class"] not in category["spatial_ref"]:
                continue
            sides = ["none"] if classes[structure["class"]]["laterality"] == "midline" \
                else ["left", "right"]
            for side in sides:
                slots.append((category, structure["id"], side))
    return slots


def random_value(prop, rng):
    if "source" in prop:  # record the raw value, e.g. MRC muscle strength
        low, high = prop["source"]["domain"]
        return prop["source"]["prop_type"], rng.randint(low, high)
    domain = prop["domain"]
    if prop["data_type"] == "numerical":
        return prop["prop_type"], rng.randint(domain[0], domain[1])
    label = rng.choice(domain)
    if domain == [False, True] or domain == ["false", "true"]:
        return prop["prop_type"], bool(label) if isinstance(label, bool) else label == "true"
    return prop["prop_type"], str(label)


def findings(slots, count, rng):
    out = []
    for category, structure, side in rng.sample(slots, count):
        values = dict(random_value(prop, rng) for prop in category["props"])
        out.append({"category": category["id"], "structure": structure, "side": side,
                    "values": values})
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("package_dir")
    parser.add_argument("out")
    parser.add_argument("--examinations", type=int, default=10000)
    parser.add_argument("--findings", type=int, default=50)
    parser.add_argument("--per-patient", type=int, default=10)
    parser.add_argument("--seed", type=int, default=4)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    slots = load(args.package_dir)
    start = datetime.datetime(2020, 1, 1, tzinfo=datetime.timezone.utc)
    patients = []
    remaining = args.examinations
    index = 0
    while remaining > 0:
        count = min(args.per_patient, remaining)
        exams = []
        for e in range(count):
            when = start + datetime.timedelta(days=7 * e, hours=index % 24, minutes=index % 60)
            last = index == 0 and e == count - 1
            n = args.findings if last else rng.randint(5, args.findings)
            exams.append({"taken_at": when.strftime("%Y-%m-%dT%H:%M:%SZ"),
                          "findings": findings(slots, n, rng)})
        patients.append({"id": f"BENCH-{index:05d}", "examinations": exams})
        remaining -= count
        index += 1
    json.dump({"format": "vicc-patient-records", "version": 1, "patients": patients},
              open(args.out, "w"))


if __name__ == "__main__":
    main()
