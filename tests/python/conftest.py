# conftest.py: what every Python test needs: the module (PYTHONPATH=build/python, set by ctest),
# the CLI binary it is compared with (SHADETOOL_BIN) and the source tree's data/ (SHADETOOL_SOURCE_DIR).
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

SOURCE_DIR = Path(os.environ.get("SHADETOOL_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BIN = os.environ.get("SHADETOOL_BIN", str(SOURCE_DIR / "build" / "shadetool"))
DATA = SOURCE_DIR / "data"


def run_cli(*args):
    """Runs the shadetool CLI quietly; fails the test with its stderr if it fails."""
    r = subprocess.run([BIN, *map(str, args), "-q"], capture_output=True, text=True)
    assert r.returncode == 0, f"shadetool {' '.join(map(str, args))}: {r.stderr}"
    return r


def same_bits(a, b):
    """Arrays equal bit for bit (NaN patterns and signed zeros included)."""
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


def uv_ellipsoid(radii, n_theta, n_phi):
    """Closed UV ellipsoid (poles shared), float64 V and int32 triangles wound outward, and the
    parameters (theta, phi) of every vertex."""
    a, b, c = radii
    V = [[0.0, 0.0, c]]
    params = [(0.0, 0.0)]
    for i in range(1, n_theta):
        t = np.pi * i / n_theta
        for j in range(n_phi):
            p = 2 * np.pi * j / n_phi
            V.append([a * np.sin(t) * np.cos(p), b * np.sin(t) * np.sin(p), c * np.cos(t)])
            params.append((t, p))
    V.append([0.0, 0.0, -c])
    params.append((np.pi, 0.0))
    south = len(V) - 1

    def ring(i, j):
        return 1 + (i - 1) * n_phi + (j % n_phi)

    F = []
    for j in range(n_phi):
        F.append([0, ring(1, j), ring(1, j + 1)])
        F.append([south, ring(n_theta - 1, j + 1), ring(n_theta - 1, j)])
    for i in range(1, n_theta - 1):
        for j in range(n_phi):
            F.append([ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)])
            F.append([ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)])
    return np.array(V), np.array(F, dtype=np.int32)


def angle_deg(N, M):
    """Angle in degrees between corresponding rows of two (n, 3) arrays of directions."""
    # atan2(|n x m|, n . m): accurate near 0, where arccos of the dot product loses half the digits.
    return np.degrees(np.arctan2(np.linalg.norm(np.cross(N, M), axis=1), np.sum(N * M, axis=1)))


@pytest.fixture
def tetra():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)
    return V, F
