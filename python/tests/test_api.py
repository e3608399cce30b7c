"""The Python API against spira-cli: the same plan, program, joints and error messages.

Run by ctest (python.api) with PYTHONPATH at the built module, SPIRA_CLI the spira-cli program and
SPIRA_SOURCE_DIR the source tree.
"""
import csv
import json
import os
import pathlib
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import numpy as np

import spira

CLI = os.environ["SPIRA_CLI"]
SOURCE = pathlib.Path(os.environ["SPIRA_SOURCE_DIR"])
DOME = str(SOURCE / "resources" / "samples" / "dome.stl")
CELL = str(SOURCE / "resources" / "cells" / "kuka_kr16_2_positioner.cell")
# The program header carries the date: both writers read it from here.
os.environ["SOURCE_DATE_EPOCH"] = "0"


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, env=os.environ)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:]])


def cli_error(*args):
    """The line spira-cli prints on stderr, without its 'spira-cli: ' prefix."""
    done = cli(*args)
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("spira-cli: "), done.stderr
    return done.returncode, line[len("spira-cli: "):]


class PlanLikeTheCli(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out = pathlib.Path(cls.tmp.name) / "cli"
        done = cli("plan", DOME, "-o", str(cls.out), "--export", "krl")
        assert done.returncode == 0, done.stderr
        cls.header, cls.rows = read_csv(cls.out / "trajectory.csv")
        cls.plan = spira.plan(spira.load_part(DOME))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def column(self, name):
        return self.rows[:, self.header.index(name)]

    def test_trajectory_is_the_cli_one_bit_for_bit(self):
        # trajectory.csv writes each number in the shortest text that reads back to the same double
        # (std::to_chars), so float() of it is the planned double: the arrays must match exactly.
        plan = self.plan
        self.assertEqual(len(plan), len(self.rows))
        self.assertEqual(plan.positions.shape, (len(self.rows), 3))
        diff = np.abs(plan.positions - self.rows[:, 1:4]).max()
        self.assertEqual(diff, 0.0)
        for name, cols in (("normals", "nx ny nz"), ("tangents", "tx ty tz"), ("builds", "bx by bz")):
            expected = np.stack([self.column(c) for c in cols.split()], axis=1)
            np.testing.assert_array_equal(getattr(plan, name), expected, err_msg=name)
        for name, col in (("revolution", "rev"), ("generatrix", "gen"), ("height", "height"),
                          ("travel_speed", "ts"), ("wire_feed", "wfs"), ("path_index", "path")):
            np.testing.assert_array_equal(getattr(plan, name), self.column(col), err_msg=name)
        np.testing.assert_array_equal(plan.arc, self.column("arc") == 1)

    def test_report_is_report_json_but_the_timings(self):
        with open(self.out / "report.json") as f:
            expected = json.load(f)
        report = self.plan.report
        for r in (report, expected):
            r.pop("timings_s")
        self.assertEqual(report, expected)
        self.assertTrue(self.plan.feasible)

    def test_export_writes_the_cli_program(self):
        with tempfile.TemporaryDirectory() as out:
            done = self.plan.export(out, "krl")
            names = sorted(pathlib.Path(f).name for f in done["files"])
            self.assertEqual(names, ["spira_part.dat", "spira_part.src"])
            for name in names:
                self.assertEqual((pathlib.Path(out) / name).read_bytes(), (self.out / name).read_bytes(), name)


class Settings(unittest.TestCase):
    def test_settings_by_key_and_by_section_plan_as_the_cli_flags(self):
        with tempfile.TemporaryDirectory() as out:
            done = cli("plan", DOME, "-o", out, "--h", "2.1", "--points-per-rev", "180")
            self.assertEqual(done.returncode, 0, done.stderr)
            _, rows = read_csv(pathlib.Path(out) / "trajectory.csv")
        flat = spira.plan(DOME, h=2.1, points_per_rev=180)
        nested = spira.plan(DOME, settings={"decomposer.isovalue": {"points_per_rev": 180}, "h": 2.1})
        np.testing.assert_array_equal(flat.positions, rows[:, 1:4])
        np.testing.assert_array_equal(nested.positions, rows[:, 1:4])

    def test_a_value_out_of_range_is_the_cli_usage_error(self):
        code, message = cli_error("plan", DOME, "-o", tempfile.gettempdir() + "/spira-unused", "--h", "-1")
        with self.assertRaises(spira.UsageError) as raised:
            spira.plan(DOME, h=-1)
        self.assertEqual(str(raised.exception), message)
        self.assertEqual(raised.exception.exit_code, code)
        self.assertIsInstance(raised.exception, ValueError)


class Placement(unittest.TestCase):
    def test_drop_moves_the_part_onto_the_substrate_as_the_cli(self):
        as_read = spira.load_part(DOME)
        dropped = spira.load_part(DOME, drop=True, substrate_z=5.0)
        lowest = as_read.vertices[:, 2].min()
        self.assertEqual((as_read.part_class, as_read.warnings, as_read.importer), ("closed", [], "import.stl"))
        self.assertEqual(as_read.faces.shape, (as_read.report["face_count"], 3))
        self.assertEqual(dropped.vertices[:, 2].min(), 5.0)
        self.assertEqual(dropped.dropped_mm, 5.0 - lowest)
        np.testing.assert_array_equal(dropped.vertices[:, :2], as_read.vertices[:, :2])
        with tempfile.TemporaryDirectory() as out:
            done = cli("plan", DOME, "-o", out, "--drop", "--substrate-z", "5")
            self.assertEqual(done.returncode, 0, done.stderr)
            _, rows = read_csv(pathlib.Path(out) / "trajectory.csv")
        np.testing.assert_array_equal(spira.plan(DOME, drop=True, substrate_z=5.0).positions, rows[:, 1:4])
        np.testing.assert_array_equal(spira.plan(dropped).positions, rows[:, 1:4])

    def test_lower_loop_counts_from_one_as_the_cli(self):
        code, message = cli_error("plan", DOME, "-o", tempfile.gettempdir() + "/spira-unused", "--lower-loop", "0")
        with self.assertRaises(spira.UsageError) as raised:
            spira.load_part(DOME, lower_loop=0)
        self.assertEqual(raised.exception.exit_code, code)
        self.assertIn("lower_loop: '0' is out of range (1 to 999999)", str(raised.exception))
        self.assertIn("--lower-loop: '0' is out of range (1 to 999999)", message)


class Errors(unittest.TestCase):
    def test_a_missing_file_raises_the_cli_message(self):
        missing = "/nonexistent-folder/part.stl"
        code, message = cli_error("plan", missing, "-o", tempfile.gettempdir() + "/spira-unused")
        with self.assertRaises(spira.Error) as raised:
            spira.load_part(missing)
        e = raised.exception
        self.assertEqual(str(e), message)
        self.assertEqual(e.exit_code, code)
        self.assertEqual(e.exit_code, 3)
        self.assertEqual(str(e), e.message + " (" + e.hint + ")")
        # A file that is not there is an I/O error, which is also Python's OSError.
        self.assertIsInstance(e, spira.IoError)
        self.assertIsInstance(e, OSError)

    def test_an_unsupported_file_is_an_input_error(self):
        code, message = cli_error("plan", __file__, "-o", tempfile.gettempdir() + "/spira-unused")
        with self.assertRaises(spira.InputError) as raised:
            spira.load_part(__file__)
        self.assertEqual(str(raised.exception), message)
        self.assertIsInstance(raised.exception, ValueError)

    def test_wrong_types_name_the_argument(self):
        cases = [
            (lambda: spira.load_part(42), "load_part(): argument 'path' must be a path (str or os.PathLike), not int"),
            (lambda: spira.load_part(DOME, drop="yes"), "load_part(): argument 'drop' must be bool, not str"),
            (lambda: spira.plan(3.5), "plan(): argument 'part' must be a spira.Part or a path (str or os.PathLike), not float"),
            (lambda: spira.plan(DOME, h="2"), "plan(): argument 'h' must be a number, not str"),
            (lambda: spira.plan(DOME, points_per_rev=360.0), "plan(): argument 'points_per_rev' must be int, not float"),
            (lambda: spira.plan(DOME, strategy=1), "plan(): argument 'strategy' must be str, not int"),
            (lambda: spira.plan(DOME, progress=1), "plan(): argument 'progress' must be a callable(fraction, stage) or None, not int"),
            (lambda: spira.plan(DOME, hh=2), "plan() got an unexpected keyword argument 'hh'"),
            (lambda: spira.plan(DOME, settings={"spiral": {"hh": 2}}),
             "plan() got an unexpected keyword argument 'hh' in settings['spiral']"),
            (lambda: spira.plan(DOME, settings=[1]), "plan(): argument 'settings' must be a dict, not list"),
        ]
        for call, message in cases:
            with self.assertRaises(TypeError) as raised:
                call()
            self.assertEqual(str(raised.exception), message)


class ProgressAndCancel(unittest.TestCase):
    def test_progress_reports_stages_up_to_the_end(self):
        seen = []
        spira.plan(DOME, progress=lambda f, stage: seen.append((f, stage)))
        self.assertGreater(len(seen), 3)
        self.assertTrue(all(0.0 <= f <= 1.0 for f, _ in seen))
        self.assertTrue(all(isinstance(s, str) for _, s in seen))

    def test_returning_false_cancels(self):
        calls = []

        def stop(fraction, stage):
            calls.append(fraction)
            return False

        with self.assertRaises(spira.Cancelled):
            spira.plan(DOME, progress=stop)
        self.assertEqual(len(calls), 1)  # no call after the answer

    def test_raising_cancels_with_the_cause(self):
        def fail(fraction, stage):
            if fraction > 0.3:
                raise KeyError("stop here")

        with self.assertRaises(spira.Cancelled) as raised:
            spira.plan(DOME, progress=fail)
        self.assertIsInstance(raised.exception.__cause__, KeyError)


class Interrupt(unittest.TestCase):
    def test_ctrl_c_stops_a_long_plan_with_keyboard_interrupt(self):
        # The thermal stage of the open cylinder takes about 20 s; the interrupt comes after 0.3 s.
        cylinder = str(SOURCE / "resources" / "samples" / "open_cylinder.stl")
        timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        with self.assertRaises(KeyboardInterrupt):
            spira.plan(cylinder, settings={"thermal": {"enabled": True}})
        self.assertLess(time.monotonic() - start, 5.0)


class Thermal(unittest.TestCase):
    def test_the_thermal_stage_is_spira_cli_thermal_of_the_plan(self):
        with tempfile.TemporaryDirectory() as out:
            planned, heat = pathlib.Path(out) / "plan", pathlib.Path(out) / "thermal"
            done = cli("plan", DOME, "-o", str(planned), "--points-per-rev", "90")
            self.assertEqual(done.returncode, 0, done.stderr)
            done = cli("thermal", str(planned), "-o", str(heat))
            self.assertEqual(done.returncode, 0, done.stderr)
            header, rows = read_csv(heat / "thermal_points.csv")
        plan = spira.plan(DOME, points_per_rev=90, settings={"thermal": {"enabled": True}})
        self.assertEqual(len(plan.thermal["peak_c"]), len(rows))
        np.testing.assert_array_equal(plan.thermal["peak_c"], rows[:, header.index("peak_C")])
        np.testing.assert_array_equal(plan.thermal["interpass_c"], rows[:, header.index("interpass_C")])
        self.assertEqual(plan.report["thermal"]["max_peak_C"], plan.thermal["peak_c"].max())
        self.assertIsNone(spira.plan(DOME, points_per_rev=90).thermal)


class Cell(unittest.TestCase):
    def test_joints_are_joints_csv(self):
        with tempfile.TemporaryDirectory() as out:
            done = cli("plan", DOME, "-o", out, "--cell", CELL)
            self.assertEqual(done.returncode, 0, done.stderr)
            header, _ = read_csv(pathlib.Path(out) / "trajectory.csv")
            with open(pathlib.Path(out) / "joints.csv", newline="") as f:
                rows = list(csv.reader(f))
        plan = spira.plan(DOME, cell=spira.read_cell(CELL))
        q = np.array([[float(x) for x in r[1:7]] for r in rows[1:]])
        self.assertEqual(plan.joints.shape, q.shape)
        np.testing.assert_array_equal(plan.joints, q)
        e = np.array([[float(x) for x in r[7:9]] for r in rows[1:]])
        np.testing.assert_array_equal(plan.external_joints, e)
        self.assertTrue(plan.reachable.all())
        self.assertTrue(plan.motion_ok)


    def test_an_export_the_cell_cannot_execute_is_refused_as_by_the_cli(self):
        table = str(SOURCE / "resources" / "cells" / "kuka_kr16_2_table.cell")
        with tempfile.TemporaryDirectory() as out:
            code, message = cli_error("plan", DOME, "-o", out, "--cell", table, "--export", "krl")
            plan = spira.plan(DOME, cell=table)
            self.assertFalse(plan.motion_ok)
            with self.assertRaises(spira.InfeasibleError) as raised:
                plan.export(pathlib.Path(out) / "api", "krl")
        self.assertEqual(str(raised.exception), message)
        self.assertEqual((raised.exception.exit_code, code), (4, 4))

    def test_solving_a_plan_is_planning_on_the_cell(self):
        fanuc = str(SOURCE / "resources" / "cells" / "fanuc_m20ia_positioner.cell")
        planned = spira.plan(DOME)
        self.assertIsNone(planned.joints)
        for cell in (CELL, fanuc):
            on_cell = spira.plan(DOME, cell=cell)
            solved = planned.solve(cell)
            np.testing.assert_array_equal(solved.joints, on_cell.joints)
            np.testing.assert_array_equal(solved.positions, on_cell.positions)
            reports = [solved.report, on_cell.report]
            for r in reports:
                r.pop("timings_s")
                r.pop("kinematics_timings_s", None)
            self.assertEqual(reports[0], reports[1])
            planned = solved  # the next cell replaces this one's motion
        with self.assertRaises(TypeError) as raised:
            planned.solve(CELL, keep_collisions=1)
        self.assertEqual(str(raised.exception), "solve(): argument 'keep_collisions' must be bool, not int")


class Project(unittest.TestCase):
    def test_a_project_plans_and_exports_as_the_cli(self):
        project = SOURCE / "resources" / "samples" / "dome.spira"
        with tempfile.TemporaryDirectory() as out:
            out = pathlib.Path(out)
            (out / "copy").mkdir()
            saved = out / "copy" / "dome.spira"
            saved.write_bytes(project.read_bytes())
            done = cli("plan", str(saved), "-o", str(out / "plan"), "--save")
            self.assertEqual(done.returncode, 0, done.stderr)
            done = cli("export", str(saved), "--format", "fanuc_tp", "-o", str(out / "cli"))
            self.assertEqual(done.returncode, 0, done.stderr)
            _, rows = read_csv(out / "plan" / "trajectory.csv")
            with open(out / "plan" / "joints.csv", newline="") as f:
                q = np.array([[float(x) for x in r[1:7]] for r in list(csv.reader(f))[1:]])

            plan = spira.plan(saved)
            np.testing.assert_array_equal(plan.positions, rows[:, 1:4])
            np.testing.assert_array_equal(plan.joints, q)
            self.assertEqual(plan.report["project"], str(saved))
            plan.export(out / "api", "fanuc_tp")
            for name in sorted(p.name for p in (out / "cli").iterdir()):
                self.assertEqual((out / "api" / name).read_bytes(), (out / "cli" / name).read_bytes(), name)

    def test_a_project_takes_no_settings(self):
        with self.assertRaises(spira.UsageError) as raised:
            spira.plan(SOURCE / "resources" / "samples" / "dome.spira", settings={"h": 2.0})
        self.assertIn("a project is planned with everything it holds, not with 'settings'", str(raised.exception))


if __name__ == "__main__":
    unittest.main(verbosity=2)
