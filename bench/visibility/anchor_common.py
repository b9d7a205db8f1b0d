"""anchor_common.py: what the anchor scripts share: reading bench_visibility --export's file and
shadetool's time-against-error table (ao.csv), and the time shadetool needs for a given error.

Equal error: shadetool's rows (N = 4..1024) give RMS error e(N) and time t(N); for an anchor's error
e, t is interpolated linearly in log(e)-log(t) between the two rows whose errors bracket it (the
curve is monotone: error falls, time grows with N). An error above the N = 4 row's gets the N = 4
row's time (an upper bound on shadetool's time, so the anchor's ratio is a lower bound: marked
"<="); below the N = 1024 row's: None (not extrapolated).
"""
import csv
import math

import numpy as np


def read_export(path):
    """The file bench_visibility --export writes (layout in bench_visibility.cpp, item 4)."""
    with open(path, "rb") as f:
        V, T, K = (int(x) for x in np.fromfile(f, dtype="<u8", count=3))
        vertices = np.fromfile(f, dtype="<f4", count=3 * V).reshape(V, 3)
        triangles = np.fromfile(f, dtype="<u4", count=3 * T).reshape(T, 3)
        ids = np.fromfile(f, dtype="<u8", count=K)
        normals = np.fromfile(f, dtype="<f8", count=3 * K).reshape(K, 3)
        reference = np.fromfile(f, dtype="<f4", count=K).astype(np.float64)
    if reference.size != K:
        raise SystemExit(f"{path}: truncated export")
    return vertices, triangles, ids, normals, reference


def read_shadetool(csv_path):
    """Rows of ao.csv: samples, rms_error, shadetool_ms, ..., us_per_vertex."""
    with open(csv_path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def shadetool_us_per_vertex_at(rows, error):
    """(shadetool's time per vertex in us at this RMS error, is_upper_bound), or (None, False)."""
    if error > rows[0]["rms_error"]:
        return rows[0]["us_per_vertex"], True
    for a, b in zip(rows, rows[1:]):
        if b["rms_error"] <= error <= a["rms_error"]:
            la, lb = math.log(a["rms_error"]), math.log(b["rms_error"])
            s = (math.log(error) - la) / (lb - la) if lb != la else 0.0  # divisor checked
            return math.exp(math.log(a["us_per_vertex"]) + s * (math.log(b["us_per_vertex"]) - math.log(a["us_per_vertex"]))), False
    return None, False


def equal_error_cells(anchor_us, ours_us, bound):
    """The table's two cells: shadetool's time at equal error, and anchor / shadetool."""
    if ours_us is None:
        return "- (below shadetool's N = 1024 error)", "-"
    mark = "<= " if bound else ""
    ratio_mark = ">= " if bound else ""
    return f"{mark}{ours_us:.2f}", f"{ratio_mark}{anchor_us / ours_us:.1f}"


def rms(a, b):
    return float(np.sqrt(np.mean((np.asarray(a, np.float64) - b) ** 2)))
