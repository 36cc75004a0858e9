#!/usr/bin/env python3
"""Which slots of the resolution target (thesis Fig. 5.3) does a reconstruction resolve?

usage: resolution_target.py SCENARIO.yaml CLOUD.ply ESTIMATE.tum TRUTH.tum

The stable surfels (vicc_reconstruct --cloud) are moved into the simulator's frame with the
pose of the first tracked frame (as vicc_reconstruct --gt aligns trajectories). In the
scenario's height band, each slot is cut into 2 mm rows along its centre line: a row is open
when no surfel disc (centre within the plate's depth, radius as fused) reaches the centre line
there, i.e. the splatted model shows a hole. A slot is "open" when >= 90 % of its rows are open,
"partly open" above 10 %, else a "groove" when the surfels bridging it sit >= 1 mm behind the
front face, else "closed". Prints a markdown table.
"""
import sys

import numpy as np
import yaml

PLY_TYPES = {"float": "<f4", "float32": "<f4", "double": "<f8", "uchar": "u1", "uint8": "u1",
             "int": "<i4", "int32": "<i4", "uint": "<u4", "short": "<i2", "ushort": "<u2"}


def read_ply_vertices(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii", errors="replace").splitlines()
    if "format binary_little_endian 1.0" not in header:
        sys.exit(f"{path}: only binary little-endian PLY is supported")
    fields, count, in_vertex = [], 0, False
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            in_vertex = words[1] == "vertex"
            if in_vertex:
                count = int(words[2])
        elif words[:1] == ["property"] and in_vertex:
            fields.append((words[2], PLY_TYPES[words[1]]))
    dtype = np.dtype(fields)
    return np.frombuffer(data[end:end + count * dtype.itemsize], dtype=dtype)


def read_tum(path):
    poses = {}
    for line in open(path):
        if not line.strip() or line.startswith("#"):
            continue
        t, x, y, z, qx, qy, qz, qw = map(float, line.split())
        rotation = np.array([
            [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
            [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
            [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]])
        pose = np.eye(4)
        pose[:3, :3], pose[:3, 3] = rotation, (x, y, z)
        poses[round(t, 4)] = pose
    return poses


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    scenario = yaml.safe_load(open(sys.argv[1]))
    target = scenario.get("resolution_target")
    if not target:
        sys.exit(f"{sys.argv[1]} has no resolution_target section")
    cloud = read_ply_vertices(sys.argv[2])
    estimate, truth = read_tum(sys.argv[3]), read_tum(sys.argv[4])
    first = min(estimate)
    if first not in truth:
        sys.exit("no ground-truth pose at the first tracked stamp")
    alignment = truth[first] @ np.linalg.inv(estimate[first])
    points = np.stack([cloud["x"], cloud["y"], cloud["z"]], axis=1).astype(float)
    points = points @ alignment[:3, :3].T + alignment[:3, 3]

    front = target["front_x"]
    z_low, z_high = target["band_z"]
    plate_depth = (points[:, 0] > front - 0.012) & (points[:, 0] < front + 0.004)
    band = (points[:, 2] >= z_low) & (points[:, 2] <= z_high)
    rows = np.arange(z_low, z_high, 0.002)
    print("| slot (mm) | open rows | mean depth behind front (mm) | verdict |")
    print("|---:|---:|---:|---|")
    for slot in target["slots"]:
        centre, width = slot["center_y"], slot["width"]
        inside = plate_depth & band & (np.abs(points[:, 1] - centre) <= cloud["radius"])
        z = points[inside, 2]
        open_rows = sum(1 for r in rows if not np.any((z >= r) & (z < r + 0.002)))
        share = open_rows / len(rows)
        behind = (front - points[inside, 0].mean()) * 1000 if inside.any() else float("nan")
        if share >= 0.9:
            verdict = "open"
        elif share > 0.1:
            verdict = "partly open"
        elif behind >= 1.0:
            verdict = "groove"
        else:
            verdict = "closed"
        print(f"| {width * 1000:g} | {share * 100:.0f} % | {behind:.1f} | {verdict} |")


if __name__ == "__main__":
    main()
