#!/usr/bin/python3
"""Reads a .mat written by ImuDesk with scipy.io.loadmat (Debian's python3-scipy) and compares one
struct with the tidy CSV export of the same capture, column by column.

usage: compare_mat.py FILE.mat VARIABLE FILE.csv

Prints one JSON object: {"variables": [...], "fields": [...], "rows": n, "units": {...},
"columns": {...}, "info": {...}, "max_rel_error": {field: e} (the time fields': absolute, s),
"nan_mismatch": {field: n}} or
{"error": "..."} (exit 1).
"""
import csv
import json
import math
import sys

import numpy as np
import scipy.io as sio

G = 9.8
DEG = math.pi / 180.0


def text(v):
    a = np.asarray(v)
    return "" if a.size == 0 else str(a.reshape(-1)[0]) if a.dtype.kind in "US" else str(a)


def main():
    mat_path, name, csv_path = sys.argv[1:4]
    m = sio.loadmat(mat_path, squeeze_me=False, struct_as_record=False, uint16_codec="utf-16-le")
    variables = sorted(k for k in m if not k.startswith("__"))
    if name not in m:
        print(json.dumps({"error": f"no variable {name} in {variables}"}))
        return 1
    s = m[name][0, 0]
    units = {f: text(getattr(s.units[0, 0], f)) for f in s.units[0, 0]._fieldnames}
    columns = {f: text(getattr(s.columns[0, 0], f)) for f in s.columns[0, 0]._fieldnames}
    info = {f: text(getattr(s.info[0, 0], f)) for f in s.info[0, 0]._fieldnames}
    rows = list(csv.DictReader(open(csv_path, newline="")))
    attitude = "_nwu" if any(k.startswith("roll_nwu") for k in (rows[0].keys() if rows else [])) else ""

    def col(key, k=1.0):
        return np.array([float(r[key]) * k if r[key] != "" else np.nan for r in rows])

    expected = {
        "time_device": [col("time_s")],
        "time_arrival": [col("host_time_s")],
        "time_common": [col("common_time_s")],
        "main_status": [col("main_status")],
        "acc": [col(f"acc_{a}_mps2") for a in "xyz"],
        "gyr": [col(f"gyr_{a}_radps") for a in "xyz"],
        "mag": [col(f"mag_{a}_uT", 1e-6) for a in "xyz"],
        "euler": [col(f"{a}{attitude}_deg", DEG) for a in ("roll", "pitch", "yaw")],
        "quat": [col(f"quat{attitude}_{a}") for a in "wxyz"],
        "pressure": [col("pressure_Pa")],
        "temperature": [col("temperature_degC")],
        "position": [col("lat_deg"), col("lon_deg"), col("alt_m")],
        "vel": [col(f"vel_{a}_mps") for a in ("e", "n", "u")],
    }
    max_rel, nan_mismatch, shapes = {}, {}, {}
    for field, cols in expected.items():
        got = np.asarray(getattr(s, field), dtype=float)
        shapes[field] = list(got.shape)
        want = np.stack(cols, axis=1) if cols and len(rows) else np.zeros((0, len(cols)))
        if got.shape != want.shape:
            max_rel[field] = None
            continue
        nan_mismatch[field] = int(np.sum(np.isnan(got) != np.isnan(want)))
        both = ~np.isnan(got) & ~np.isnan(want)
        if not both.any():
            max_rel[field] = 0.0
            continue
        # The CSV prints times with 6 decimals (an absolute error, s) and float values with their 9
        # significant digits (a relative one).
        scale = 1.0 if field.startswith("time") else np.maximum(np.abs(want[both]), 1e-9)
        max_rel[field] = float(np.max(np.abs(got[both] - want[both]) / scale))
    print(json.dumps({"variables": variables, "fields": list(s._fieldnames), "rows": len(rows), "shapes": shapes,
                      "units": units, "columns": columns, "info": info, "max_rel_error": max_rel,
                      "nan_mismatch": nan_mismatch}))
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception as e:  # an unreadable file is the finding, said as such
        print(json.dumps({"error": f"{type(e).__name__}: {e}"}))
        sys.exit(1)
