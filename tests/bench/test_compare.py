#!/usr/bin/env python3
"""The speed check's comparison (bench/check/compare.py) on small CSVs written here: which
rows pass, which fail and why, and the exit status scripts/bench-check.sh relies on. No GL,
no timing: the CSVs are fixtures."""
import os
import subprocess
import sys
import tempfile
import unittest

COMPARE = os.path.join(os.path.dirname(__file__), "..", "..", "bench", "check", "compare.py")
HEADER = "method,case,triangles,width,height,param,gl_path,frame_ms,fps,surface_ms\n"
# (method, case, triangles, param, gl_path) -> baseline ms at 512x512
BASE = {
    ("isa", "static", 9800, "R=256", "fragment"): 20.0,
    ("isa", "dynamic", 9800, "R=256", "fragment"): 60.0,
    ("hybrid", "static", 9800, "L=31", "fragment"): 40.0,
    ("hybrid", "dynamic", 9800, "L=31", "fragment"): 45.0,
    ("hybrid", "dynamic", 9800, "L=31", "compute"): 30.0,
}


class CompareTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def csv(self, name, times, comment="", calib=None):
        """Writes rows {key: ms} as `flowsurf bench --csv` would, with the calibration row
        when `calib` (ms) is given; returns the path."""
        path = os.path.join(self.dir.name, name)
        with open(path, "w") as f:
            f.write(comment + HEADER)
            for (method, case, tris, param, path_), ms in times.items():
                f.write(f"{method},{case},{tris},512,512,{param},{path_},{ms},{1000 / ms},1.5\n")
            if calib is not None:
                f.write(f"calib,-,80000,512,512,-,-,{calib},{1000 / calib},\n")
        return path

    def run_compare(self, *args):
        p = subprocess.run([sys.executable, COMPARE, *args], capture_output=True, text=True)
        return p.returncode, p.stdout, p.stderr

    def scaled(self, factors):
        return {k: ms * factors.get(k[0:2] + (k[4],), 1.0) for k, ms in BASE.items()}

    def test_same_times_pass_and_every_ratio_is_printed(self):
        base = self.csv("base.csv", BASE, comment="# machine: test\n# commit: abc\n")
        rc, out, _ = self.run_compare(base, self.csv("now.csv", BASE))
        self.assertEqual(rc, 0, out)
        rows = [line for line in out.splitlines() if not line.startswith("method ")]
        self.assertEqual(sum(line.endswith(" 1.00  ok") for line in rows), len(BASE), out)

    def test_noise_of_30_percent_passes(self):
        now = {k: ms * f for (k, ms), f in zip(BASE.items(), [1.3, 0.7, 1.25, 0.8, 1.3])}
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE), self.csv("now.csv", now))
        self.assertEqual(rc, 0, out)

    def test_a_row_over_the_threshold_fails_and_is_named(self):
        now = self.scaled({("hybrid", "dynamic", "compute"): 2.1})
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE), self.csv("now.csv", now))
        self.assertEqual(rc, 1, out)
        failing = [line for line in out.splitlines() if "FAIL" in line]
        self.assertEqual(len(failing), 1, out)
        self.assertIn("hybrid", failing[0])
        self.assertIn("compute", failing[0])
        self.assertIn("2.10", failing[0])

    def test_threshold_option(self):
        now = self.scaled({("isa", "static", "fragment"): 1.7})
        base = self.csv("base.csv", BASE)
        self.assertEqual(self.run_compare(base, self.csv("now.csv", now))[0], 0)
        self.assertEqual(self.run_compare(base, self.csv("now.csv", now), "--threshold", "1.6")[0], 1)

    def test_median_of_repeats_outvotes_one_slow_measurement(self):
        slow = self.scaled({("isa", "dynamic", "fragment"): 3.0})
        base = self.csv("base.csv", BASE)
        rc, out, _ = self.run_compare(base, self.csv("a.csv", slow), self.csv("b.csv", BASE), self.csv("c.csv", BASE))
        self.assertEqual(rc, 0, out)
        self.assertIn(" 3 ", [l for l in out.splitlines() if l.startswith("isa    dynamic")][0])

    def test_slow_in_most_repeats_fails(self):
        slow = self.scaled({("isa", "dynamic", "fragment"): 2.5})
        base = self.csv("base.csv", BASE)
        rc, out, _ = self.run_compare(base, self.csv("a.csv", slow), self.csv("b.csv", slow), self.csv("c.csv", BASE))
        self.assertEqual(rc, 1, out)

    def test_failing_methods_lists_each_method_once(self):
        now = self.scaled({("hybrid", "dynamic", "compute"): 4.0, ("hybrid", "static", "fragment"): 4.0})
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE), self.csv("now.csv", now), "--failing-methods")
        self.assertEqual((rc, out.strip()), (1, "hybrid"))

    def test_a_method_slower_in_every_row_fails_on_its_mean(self):
        # 1.7x in each hybrid row: no row over 2.0, the method's mean over 1.5.
        now = self.scaled({("hybrid", c, p): 1.7 for c in ("static", "dynamic") for p in ("fragment", "compute")})
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE), self.csv("now.csv", now))
        self.assertEqual(rc, 1, out)
        self.assertFalse([line for line in out.splitlines() if "FAIL" in line and not line.startswith("method")], out)
        self.assertIn("method hybrid: geometric mean of ratio / machine 1.70  FAIL", out)
        self.assertIn("method isa: geometric mean of ratio / machine 1.00  ok", out)
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE), self.csv("now.csv", now), "--failing-methods")
        self.assertEqual((rc, out.strip()), (1, "hybrid"))

    def test_a_row_not_measured_fails(self):
        now = dict(BASE)
        del now[("isa", "static", 9800, "R=256", "fragment")]
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE), self.csv("now.csv", now))
        self.assertEqual(rc, 1)
        self.assertIn("FAIL: not measured", out)

    def test_a_row_missing_from_the_baseline_fails(self):
        base = dict(BASE)
        del base[("hybrid", "dynamic", 9800, "L=31", "compute")]
        rc, out, _ = self.run_compare(self.csv("base.csv", base), self.csv("now.csv", BASE))
        self.assertEqual(rc, 1)
        self.assertIn("FAIL: not in the baseline", out)

    def test_a_machine_twice_as_slow_is_not_a_regression(self):
        slow = {k: 1.9 * ms for k, ms in BASE.items()}
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE, calib=50.0), self.csv("now.csv", slow, calib=100.0),
                                      "--threshold", "1.5")
        self.assertEqual(rc, 0, out)
        self.assertIn("= 2.00", out.splitlines()[0])

    def test_a_slowdown_on_a_faster_machine_fails(self):
        # The rows took as long as in the baseline on a machine twice as fast: 2x slower code.
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE, calib=50.0), self.csv("now.csv", BASE, calib=25.0),
                                      "--threshold", "1.5")
        self.assertEqual(rc, 1, out)
        rows = [line for line in out.splitlines() if not line.startswith("method ")]
        self.assertEqual(sum("FAIL" in line for line in rows), len(BASE), out)

    def test_without_calibration_in_both_files_the_machine_is_1(self):
        slow = {k: 1.9 * ms for k, ms in BASE.items()}
        rc, out, _ = self.run_compare(self.csv("base.csv", BASE), self.csv("now.csv", slow, calib=100.0),
                                      "--threshold", "1.5")
        self.assertEqual(rc, 1, out)
        self.assertIn("= 1.00", out.splitlines()[0])

    def test_median_writes_a_baseline_of_the_per_row_medians(self):
        runs = [self.csv(f"{k}.csv", {kk: f * ms for kk, ms in BASE.items()}, calib=50.0 * f)
                for k, f in enumerate([1.0, 3.0, 1.2])]
        rc, out, _ = self.run_compare("--median", *runs)
        self.assertEqual(rc, 0)
        median = os.path.join(self.dir.name, "median.csv")
        with open(median, "w") as f:
            f.write(out)
        self.assertIn("calib,-,80000,512,512,-,-,60.000,3", out)
        rc, out, _ = self.run_compare(median, self.csv("now.csv", {k: 1.2 * ms for k, ms in BASE.items()}, calib=60.0))
        self.assertEqual(rc, 0, out)
        self.assertEqual(out.count(" 1.00 ") >= len(BASE), True, out)

    def test_a_file_without_frame_ms_is_an_input_error(self):
        bad = os.path.join(self.dir.name, "bad.csv")
        with open(bad, "w") as f:
            f.write("method,case\nisa,static\n")
        rc, out, err = self.run_compare(self.csv("base.csv", BASE), bad)
        self.assertEqual(rc, 2)
        self.assertIn("bad.csv", err)
        self.assertIn("frame_ms", err)
        self.assertEqual(out, "")

    def test_a_missing_file_is_an_input_error(self):
        rc, _, err = self.run_compare(self.csv("base.csv", BASE), os.path.join(self.dir.name, "none.csv"))
        self.assertEqual(rc, 2)
        self.assertIn("none.csv", err)


if __name__ == "__main__":
    unittest.main()
