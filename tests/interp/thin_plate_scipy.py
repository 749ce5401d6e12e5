#!/usr/bin/python3
"""radview's thin-plate smoothing spline against scipy's on one region of scattered points.

  /usr/bin/python3 tests/interp/thin_plate_scipy.py RADVIEW WORK_DIR

scipy.interpolate.RBFInterpolator(kernel="thin_plate_spline", smoothing=s) minimises
sum_i (y_i - f(x_i))^2 + lambda J(f) over the whole plane, J the integral of |Hess f|^2 and
s = 8 pi lambda (the kernel r^2 log r is 8 pi times the Green's function of the biharmonic
operator). radview minimises the same sum with its discrete J over the mesh (interp/thin_plate.h):
piecewise linear f, which tends to J where the mesh is an equilateral lattice, and a plate that
ends at the region's edge (free), where scipy's goes on past the points. So the two are
compared where they match: an equilateral lattice of 1,203 points in the unit square, noisy
samples of a smooth function, at the points at least 0.25 from the edge. The test fails when
radview's fitted values there differ from scipy's by more than 15 % of what scipy's smoothing
took off (RMS), or when the two smooth by amounts differing by more than 15 %.
Exit 0 on agreement, 1 on disagreement, 2 when something could not run.
"""
import math
import os
import subprocess
import sys

import numpy as np
from scipy.interpolate import RBFInterpolator

LAMBDA = 2e-4


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    radview, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    h = 1.0 / 32
    rows = int(1.0 / (h * math.sqrt(3) / 2)) + 1
    points, index = [], {}
    for j in range(rows):
        offset = 0.5 * h if j % 2 else 0.0
        for i in range(33):
            x = i * h + offset
            if x <= 1.0 + 1e-9:
                index[(i, j)] = len(points)
                points.append((x, j * h * math.sqrt(3) / 2))
    faces = []
    for j in range(rows - 1):
        for i in range(33):
            a, b = index.get((i, j)), index.get((i + 1, j))
            c, d = index.get((i, j + 1)), index.get((i + 1, j + 1))
            if j % 2 == 0:  # this row is shifted left of the next
                if a is not None and b is not None and c is not None:
                    faces.append((a, b, c))
                if b is not None and d is not None and c is not None:
                    faces.append((b, d, c))
            else:
                if a is not None and d is not None and c is not None:
                    faces.append((a, d, c))
                if a is not None and b is not None and d is not None:
                    faces.append((a, b, d))
    points = np.array(points)
    rng = np.random.default_rng(5)
    truth = 0.5 + 0.2 * np.sin(3 * points[:, 0]) * np.cos(2 * points[:, 1])
    y = truth + rng.normal(0.0, 0.02, len(points))
    ply = os.path.join(work, "lattice.ply")
    with open(ply, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                "property float red\nproperty float green\nproperty float blue\nelement face %d\n"
                "property list uchar int vertex_indices\nend_header\n" % (len(points), len(faces)))
        for (px, py), v in zip(points, y):
            f.write("%.9g %.9g 0 %.9g %.9g %.9g\n" % (px, py, v, v, v))
        for t in faces:
            f.write("3 %d %d %d\n" % t)
    inner = np.all((points > 0.25) & (points < np.array([0.75, points[:, 1].max() - 0.25])), axis=1)
    query = "; ".join("%.9g %.9g 0" % tuple(p) for p in points[inner])
    done = subprocess.run([radview, "sample", ply, "--method", "thin-plate", "--smoothing", repr(LAMBDA),
                           "--colours", "linear", "--points", query], capture_output=True, text=True)
    if done.returncode != 0:
        print("radview sample failed:\n" + done.stderr, file=sys.stderr)
        return 2
    ours = np.array([float(line.split()[5]) for line in done.stdout.splitlines() if not line.startswith("#")])
    theirs = RBFInterpolator(points, y, kernel="thin_plate_spline", smoothing=8 * math.pi * LAMBDA)(points[inner])
    taken = y[inner] - theirs
    difference = ours - theirs
    relative = math.sqrt(np.mean(difference ** 2) / np.mean(taken ** 2))
    amount = math.sqrt(np.mean((y[inner] - ours) ** 2) / np.mean(taken ** 2))
    print("%d points, %d inner; lambda %g (scipy smoothing %.3g): scipy took off RMS %.4g, radview %.4g "
          "(ratio %.3f); radview - scipy RMS %.4g = %.3f of it; noise 0.02, radview's error %.4g, scipy's %.4g" % (
              len(points), inner.sum(), LAMBDA, 8 * math.pi * LAMBDA, math.sqrt(np.mean(taken ** 2)),
              math.sqrt(np.mean((y[inner] - ours) ** 2)), amount, math.sqrt(np.mean(difference ** 2)), relative,
              math.sqrt(np.mean((ours - truth[inner]) ** 2)), math.sqrt(np.mean((theirs - truth[inner]) ** 2))))
    return 0 if relative <= 0.15 and abs(amount - 1.0) <= 0.15 else 1


if __name__ == "__main__":
    sys.exit(main())
