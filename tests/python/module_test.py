#!/usr/bin/python3
"""The Python module (app/python) against the command line it shares its code with.

    module_test.py RADVIEW_EXECUTABLE WORK_DIR   (the module on PYTHONPATH)

Each answer the module gives is checked against the same request to the `radview` executable:
samples against `radview sample --out .npy`, pictures against `radview render`'s PNG, the trade
table against `bench.csv`, a solve against `radview info` on the file it wrote. Bad input must
raise a Python exception naming what is wrong, never crash the interpreter.
"""
import csv
import gc
import os
import pathlib
import subprocess
import sys
import unittest

import numpy as np
from OpenImageIO import ImageInput

import radview

REPO = pathlib.Path(__file__).resolve().parents[2]
SOLVED = REPO / "assets" / "cornell_box_solved.glb"
SCENE = REPO / "assets" / "cornell_box.gltf"
FIG98 = REPO / "assets" / "fig9_8_quad.gltf"
FIG914 = REPO / "assets" / "fig9_14.gltf"
EXECUTABLE = None
WORK = None


def cli(*args):
    # In the sanitizer build the interpreter runs with the sanitizers' shared runtime preloaded;
    # the executable links its own, and refuses a second.
    environment = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
    result = subprocess.run([EXECUTABLE, *map(str, args)], capture_output=True, text=True, env=environment)
    if result.returncode != 0:
        raise AssertionError(f"radview {' '.join(map(str, args))}: {result.stderr}")
    return result.stdout


def read_png(path):
    image = ImageInput.open(str(path))
    pixels = image.read_image(format="uint8")
    image.close()
    return pixels


class Arrays(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.solution = radview.load(SOLVED)

    def test_nodal_arrays_are_read_only_views(self):
        s = self.solution
        self.assertEqual(s.positions.shape, (s.node_count, 3))
        self.assertEqual(s.B.shape, (s.node_count, 3))
        self.assertFalse(s.positions.flags.writeable)
        self.assertFalse(s.B.flags.writeable)
        self.assertFalse(s.positions.flags.owndata)  # a view of radview's nodes, not a copy
        self.assertTrue(np.shares_memory(s.positions, s.positions))
        self.assertEqual(s.positions.strides[0], s.B.strides[0])  # strided over the same records
        with self.assertRaises(ValueError):
            s.B[0, 0] = 1.0

    def test_views_keep_the_solution_alive(self):
        B = radview.load(SOLVED).B  # the Solution itself is gone at once
        gc.collect()
        self.assertEqual(B.shape[1], 3)
        self.assertTrue(np.all(np.isfinite(B)))

    def test_elements_and_their_corner_lists_agree(self):
        s = self.solution
        elements, corners, offsets = s.elements, s.element_corners, s.element_offsets
        self.assertEqual(elements.shape, (s.element_count, 3))
        self.assertEqual(offsets.size, s.element_count + 1)
        np.testing.assert_array_equal(corners, elements.ravel())
        self.assertLess(int(elements.max()), s.node_count)

    def test_discontinuity_edges_are_the_files_records(self):
        s = self.solution
        edges = s.discontinuity_edges
        self.assertEqual(edges.dtype.names, ("a", "b", "order"))
        self.assertFalse(edges.flags.writeable)
        self.assertTrue(np.all(edges["a"] < s.node_count) and np.all(edges["b"] < s.node_count))
        self.assertTrue(np.all(edges["a"] != edges["b"]))
        # Records name one side's end nodes, so an edge with a value jump may appear once per
        # side; info counts each edge once.
        info = cli("info", SOLVED)
        c_minus_1 = int(info.split("discontinuity edges: C-1 ")[1].split(",")[0])
        self.assertGreater(c_minus_1, 0)
        self.assertLessEqual(c_minus_1, int(np.sum(edges["order"] == -1)))

    def test_standard_errors_and_gradients_are_none_when_absent(self):
        quad = radview.load(FIG98)  # a scene lit by its direct light alone: no solver errors
        self.assertIsNone(radview.load(FIG98, direct_only=True).standard_errors)
        self.assertEqual(quad.positions.shape[1], 3)


class Sampling(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.solution = radview.load(SOLVED)
        rng = np.random.default_rng(7)
        cls.elements = rng.integers(0, cls.solution.element_count, 300)
        cls.barycentric = rng.dirichlet([1.0, 1.0, 1.0], 300)
        cls.world = cls.solution.sample(element=cls.elements, barycentric=cls.barycentric)["x"]

    def cli_samples(self, name, points, *options):
        path_in, path_out = WORK / f"{name}_in.npy", WORK / f"{name}_out.npy"
        np.save(path_in, points)
        cli("sample", SOLVED, "--points", path_in, "--out", path_out, *options)
        return np.load(path_out)

    def test_world_points_equal_the_command_line(self):
        for method in ("gouraud", "clough-tocher", "c1-quadratic"):
            ours = self.solution.sample(self.world, method=method)
            theirs = self.cli_samples(f"world_{method}", self.world, "--method", method)
            np.testing.assert_array_equal(ours["element"], theirs[:, 0])
            np.testing.assert_array_equal(ours["x"], theirs[:, 1:4])
            np.testing.assert_array_equal(ours["distance"], theirs[:, 4])
            np.testing.assert_array_equal(ours["B"], theirs[:, 5:8])
            np.testing.assert_array_equal(ours["gradient"].reshape(-1, 9), theirs[:, 8:17])

    def test_barycentric_points_equal_the_command_line(self):
        ours = self.solution.sample(element=self.elements, barycentric=self.barycentric, method="clough-tocher")
        theirs = self.cli_samples("bary", np.column_stack([self.elements, self.barycentric]))
        np.testing.assert_array_equal(ours["B"], theirs[:, 5:8])

    def test_kept_set_up_gives_the_same_samples(self):
        fresh = radview.load(SOLVED)
        first = fresh.sample(self.world, method="clough-tocher")["B"]
        np.testing.assert_array_equal(fresh.sample(self.world, method="clough-tocher")["B"], first)
        fresh.sample(self.world, method="gouraud")  # another method's set-up replaces it
        np.testing.assert_array_equal(fresh.sample(self.world, method="clough-tocher")["B"], first)
        fresh.clear_cache()
        np.testing.assert_array_equal(fresh.sample(self.world, method="clough-tocher")["B"], first)

    def test_one_point_and_float32_are_taken(self):
        one = self.solution.sample(self.world[0])
        self.assertEqual(one["B"].shape, (1, 3))
        single = self.solution.sample(self.world.astype(np.float32))
        self.assertEqual(single["B"].shape, (300, 3))

    def test_standard_errors_when_the_solver_estimated_them(self):
        scene = radview.load(FIG98)
        if scene.standard_errors is None:
            with self.assertRaisesRegex(radview.Error, "no standard errors"):
                scene.sample(scene.positions[:1], standard_error=True)
        else:
            out = scene.sample(scene.positions[:4], standard_error=True)
            self.assertEqual(out["standard_error"].shape, (4, 3))


class Pictures(unittest.TestCase):
    def test_render_equals_the_command_lines_png(self):
        solution = radview.load(SOLVED)
        for method in ("gouraud", "clough-tocher"):
            png = WORK / f"render_{method}.png"
            cli("render", SOLVED, "--method", method, "--size", "96x64", "--out", png)
            ours = solution.render(method=method, size=(96, 64))
            self.assertEqual(ours.shape, (64, 96, 3))
            np.testing.assert_array_equal(ours, read_png(png)[:, :, :3])

    def test_linear_render_is_nan_off_the_surfaces(self):
        linear = radview.load(SOLVED).render(method="gouraud", size=(64, 64), linear=True, camera="0.27,0.27,3/0.27,0.27,0")
        self.assertEqual(linear.dtype, np.float32)
        self.assertTrue(np.isnan(linear).any())  # the box seen from far away leaves a background
        self.assertTrue((linear[np.isfinite(linear)] >= 0).all())

    def test_final_gather_is_seeded(self):
        solution = radview.load(SOLVED)
        a = solution.render(method="final-gather", size=(24, 24), spp=2, seed=3, linear=True)
        b = solution.render(method="final-gather", size=(24, 24), spp=2, seed=3, linear=True)
        np.testing.assert_array_equal(a, b)


class Commands(unittest.TestCase):
    def test_bench_returns_the_csv_table(self):
        out = WORK / "bench"
        # Small and quick, as the command line's bench tests (a sanitizer build tessellates slowly).
        table = radview.bench(FIG914, size=(48, 48), spp=8, runs=4, node_spp=0, frames=1, levels="1",
                              tolerances="1", out_dir=str(out))
        with open(out / "bench.csv") as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(table["method"]), len(rows))
        self.assertEqual(list(table["method"]), [r["method"] for r in rows])
        lengths = {len(v) for v in table.values()}
        self.assertEqual(lengths, {len(rows)})
        self.assertTrue(np.all(table["display_error_low"] <= table["display_error_high"]))

    def test_solve_writes_the_file_and_loads_it(self):
        out = WORK / "solved.glb"
        solution = radview.solve(SCENE, out, max_elements=1500, no_discontinuity_meshing=True)
        self.assertTrue(out.exists())
        self.assertIn(f"elements: {solution.element_count}", cli("info", out))
        temporary = radview.solve(SCENE, max_elements=1500, discontinuity_meshing=False)
        self.assertEqual(temporary.element_count, solution.element_count)


class BadInput(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.solution = radview.load(SOLVED)

    def test_missing_and_malformed_files_name_the_file(self):
        with self.assertRaisesRegex(radview.Error, "no_such_file.glb"):
            radview.load(WORK / "no_such_file.glb")
        with self.assertRaisesRegex(radview.Error, "truncated.glb"):
            radview.load(REPO / "tests" / "data" / "truncated.glb")
        with self.assertRaises(TypeError):
            radview.load(42)

    def test_a_closed_file(self):
        with open(SOLVED, "rb") as f:
            pass
        with self.assertRaisesRegex(ValueError, "closed"):
            radview.load(f)
        with open(SOLVED, "rb") as f:
            self.assertEqual(radview.load(f).node_count, self.solution.node_count)

    def test_unknown_options_and_bad_values(self):
        with self.assertRaisesRegex(radview.Error, "no option sampels"):
            radview.load(SCENE, sampels=4)
        with self.assertRaisesRegex(radview.Error, "--samples"):
            radview.load(SCENE, samples=-3)
        with self.assertRaisesRegex(radview.Error, "--method"):
            self.solution.render(method="phong")
        with self.assertRaisesRegex(radview.Error, "--spp needs method"):
            self.solution.render(method="gouraud", spp=4)
        with self.assertRaisesRegex(radview.Error, "--size"):
            self.solution.render(size="wide")

    def test_wrong_shapes_and_dtypes(self):
        s = self.solution
        with self.assertRaisesRegex(ValueError, r"shape \(5, 2\)"):
            s.sample(np.zeros((5, 2)))
        with self.assertRaisesRegex(ValueError, "shape"):
            s.sample(np.zeros((2, 3, 3)))
        with self.assertRaisesRegex(TypeError, "dtype"):
            s.sample(np.array([["a", "b", "c"]]))
        with self.assertRaisesRegex(TypeError, "dtype"):
            s.sample(np.zeros((4, 3), dtype=complex))
        with self.assertRaises(TypeError):
            s.sample(object())
        with self.assertRaisesRegex(TypeError, "not both"):
            s.sample(np.zeros((1, 3)), element=[0], barycentric=[[1.0, 0.0, 0.0]])
        with self.assertRaisesRegex(TypeError, "integers"):
            s.sample(element=[0.5], barycentric=[[1.0, 0.0, 0.0]])
        with self.assertRaisesRegex(ValueError, "entries"):
            s.sample(element=[0, 1], barycentric=[[1.0, 0.0, 0.0]])

    def test_nan_and_out_of_range_points(self):
        s = self.solution
        points = s.positions[:4].copy()
        points[2, 1] = np.nan
        with self.assertRaisesRegex(ValueError, "row 2 holds a number that is not finite"):
            s.sample(points)
        with self.assertRaisesRegex(radview.Error, "off every surface"):
            s.sample([[10.0, 10.0, 10.0]])
        with self.assertRaisesRegex(ValueError, "no element 99999999"):
            s.sample(element=[99999999], barycentric=[[1.0, 0.0, 0.0]])
        with self.assertRaisesRegex(ValueError, "sum to 1"):
            s.sample(element=[0], barycentric=[[0.5, 0.0, 0.0]])
        with self.assertRaisesRegex(ValueError, "max_distance"):
            s.sample(s.positions[:1], max_distance=-1.0)


if __name__ == "__main__":
    EXECUTABLE, WORK = sys.argv[1], pathlib.Path(sys.argv[2])
    WORK.mkdir(parents=True, exist_ok=True)
    unittest.main(argv=[sys.argv[0], "-v"])
