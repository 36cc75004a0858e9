#!/usr/bin/env python3
"""Summarises bench/fidelity results/icons.tsv as a Markdown table per icon set."""
import csv
import sys
from collections import OrderedDict

import numpy as np

SILENT_WRONG_IOU = 0.95


def main():
    path, size = sys.argv[1], sys.argv[2]
    rows = list(csv.DictReader(open(path), delimiter="\t"))
    sets = OrderedDict()
    for row in rows:
        sets.setdefault(row["set"], []).append(row)
    print(f"Icons rendered at {size} px wide by `vicc_glyph render` and `rsvg-convert`; IoU of the "
          "dark masks (gray < 0.5 over white), mean abs. gray difference (0..1), vicc_glyph wall "
          "time per icon (whole process), mean curves and Bezier control points of the imported DCI. "
          "Silent wrong = rendered with exit 0 but IoU < 0.95.\n")
    print("| set | icons | ok | failed | IoU min | IoU p5 | IoU median | MAE mean | silent wrong | "
          "s/icon | curves | control points |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    failures = []
    worst = []
    for name, items in sets.items():
        ok = [r for r in items if r["status"] == "ok"]
        failed = [r for r in items if r["status"] != "ok"]
        iou = np.array([float(r["iou"]) for r in ok]) if ok else np.array([np.nan])
        mae = np.array([float(r["mae"]) for r in ok]) if ok else np.array([np.nan])
        seconds = [float(r["seconds"]) for r in items if r["seconds"]]
        silent = [r for r in ok if float(r["iou"]) < SILENT_WRONG_IOU]
        curves = [float(r["curves"]) for r in ok if r.get("curves")]
        points = [float(r["control_points"]) for r in ok if r.get("control_points")]
        print(f"| {name} | {len(items)} | {len(ok)} | {len(failed)} | {np.nanmin(iou):.4f} | "
              f"{np.nanpercentile(iou, 5):.4f} | {np.nanmedian(iou):.4f} | {np.nanmean(mae):.4f} | "
              f"{len(silent)} | {np.mean(seconds) if seconds else float('nan'):.2f} | "
              f"{np.mean(curves) if curves else float('nan'):.1f} | "
              f"{np.mean(points) if points else float('nan'):.0f} |")
        failures += [(name, r["icon"], r["status"], r["message"]) for r in failed]
        worst += sorted(((float(r["iou"]), name, r["icon"]) for r in ok))[:3]
    print("\nFailures (with their messages):\n")
    for name, icon, status, message in failures:
        print(f"- {name}/{icon}: {status}: {message}")
    if not failures:
        print("- none")
    print("\nLowest IoU per set (3 each):\n")
    for iou, name, icon in worst:
        print(f"- {name}/{icon}: {iou:.4f}")


if __name__ == "__main__":
    main()
