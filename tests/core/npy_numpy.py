#!/usr/bin/python3
"""`radview sample` with .npy arrays, against numpy on the other side.

  /usr/bin/python3 tests/core/npy_numpy.py RADVIEW WORK_DIR

Points written by numpy (float64 world points, float32 element-and-barycentric rows, a format
2.0 file) go in through --points FILE.npy; the samples come back through --out FILE.npy and
numpy.load must give exactly the numbers the text output prints (radview writes each as the
shortest text that reads back as the same double). Arrays radview cannot read (Fortran order,
integers, five columns, a NaN) must be refused with the file's name, a non-zero exit and no
output file. Exit 0 when all holds, 1 when something does not, 2 when something could not run.
"""
import os
import subprocess
import sys

import numpy as np

SOLUTION = os.path.join(os.path.dirname(__file__), "..", "..", "assets", "cornell_box_solved.glb")


def run(radview, *args):
    return subprocess.run([radview, "sample", SOLUTION, *args], capture_output=True, text=True)


def text_table(output):
    rows = [line.split() for line in output.splitlines() if line and not line.startswith("#")]
    return np.array([[float(v) for v in row] for row in rows])


def saved_with_output(work, name, array):
    """`array` saved as WORK/NAME.npy, and the path for its samples, no file there yet."""
    path, out = os.path.join(work, name + ".npy"), os.path.join(work, name + "_samples.npy")
    np.save(path, array)
    if os.path.exists(out):
        os.remove(out)
    return path, out


def check(condition, message, failures):
    print(("ok: " if condition else "FAILED: ") + message)
    if not condition:
        failures.append(message)


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    radview, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    failures = []
    rng = np.random.default_rng(3)
    # The floor of the Cornell box (y = 0, x and z in [0.01, 0.54]) and barycentric rows.
    world = np.stack([rng.uniform(0.01, 0.54, 500), np.zeros(500), rng.uniform(0.01, 0.54, 500)], axis=1)
    # Barycentric coordinates in 1/4096ths: their sum is exactly 1 in float32 and in text alike.
    b0 = rng.integers(0, 4097, 200)
    b1 = (rng.uniform(0, 1, 200) * (4096 - b0)).astype(int)
    by_element = np.stack([rng.integers(0, 1000, 200), b0 / 4096, b1 / 4096, (4096 - b0 - b1) / 4096],
                          axis=1).astype(np.float32)
    for name, points in {"world_f64": world, "element_f32": by_element}.items():
        path, out = saved_with_output(work, name, points)
        binary = run(radview, "--method", "clough-tocher", "--standard-error", "--points", path, "--out", out)
        if binary.returncode != 0:
            print(binary.stderr, file=sys.stderr)
            return 2
        text_points = "\n".join(" ".join(repr(float(v)) for v in row) for row in points.astype(np.float64))
        text = run(radview, "--method", "clough-tocher", "--standard-error", "--points", text_points)
        if text.returncode != 0:
            print(text.stderr, file=sys.stderr)
            return 2
        samples, expected = np.load(out), text_table(text.stdout)
        check(samples.dtype == np.float64 and samples.shape == (len(points), 20),
              f"{name}: {samples.dtype} {samples.shape} from --out", failures)
        check(samples.shape == expected.shape and np.array_equal(samples, expected),
              f"{name}: --out's numbers equal the text's exactly", failures)
    # float32 rows from float64 coordinates: the sums miss 1 by float32's rounding, and are read.
    rounded = os.path.join(work, "rounded_f32.npy")
    bary = rng.dirichlet([1, 1, 1], 50)
    np.save(rounded, np.concatenate([np.zeros((50, 1)), bary], axis=1).astype(np.float32))
    check(run(radview, "--points", rounded, "--out", os.path.join(work, "rounded_samples.npy")).returncode == 0,
          "float32 barycentric coordinates summing to 1 within float32's precision are read", failures)
    version2 = os.path.join(work, "version2.npy")
    with open(version2, "wb") as f:
        np.lib.format.write_array(f, world[:10], version=(2, 0))
    check(run(radview, "--points", version2, "--out", os.path.join(work, "v2_samples.npy")).returncode == 0,
          "a format 2.0 file is read", failures)

    bad = {
        "fortran": (np.asfortranarray(world[:4]), "Fortran order"),
        "integers": (np.zeros((4, 3), dtype=np.int32), "'<i4' numbers"),
        "five_columns": (np.zeros((4, 5)), "5 columns"),
        "nan": (np.array([[0.1, 0.0, 0.1], [np.nan, 0.0, 0.2]]), "row 1 holds a number that is not finite"),
    }
    for name, (array, fault) in bad.items():
        path, out = saved_with_output(work, name, array)
        result = run(radview, "--points", path, "--out", out)
        message = result.stderr.strip()
        check(result.returncode != 0 and path in message and fault in message and not os.path.exists(out),
              f"{name}: refused naming the file ({message})", failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
