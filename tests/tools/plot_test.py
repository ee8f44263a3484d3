#!/usr/bin/python3
"""Tests of tools/coldspray_plot.py on a small synthetic run folder.

The folder is written here the way `coldspray run` writes its output (src/io/vtu.cpp for the
appended raw VTU files, snapshots.pvd, history.csv, case.resolved.yaml). The tool's path comes
from COLDSPRAY_PLOT (set by ctest), else tools/coldspray_plot.py next to this tests/ folder.
"""

import importlib.util
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest

import numpy as np

PLOT = os.environ.get("COLDSPRAY_PLOT") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "coldspray_plot.py")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
SPACING = 1.0e-6  # m, both bodies


def load_tool():
    spec = importlib.util.spec_from_file_location("coldspray_plot", PLOT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# ------------------------------------------------------------------------------------------
# Writing a synthetic run folder
# ------------------------------------------------------------------------------------------

def write_vtu(path, points, arrays):
    """An appended raw VTU like src/io/vtu.cpp: arrays is [(name, vtk type, values)]."""
    n = len(points)
    cells = [("connectivity", "Int64", np.arange(n, dtype="<i8")),
             ("offsets", "Int64", np.arange(1, n + 1, dtype="<i8")),
             ("types", "UInt8", np.ones(n, dtype="<u1"))]
    offset, blocks = 0, []

    def declare(name, vtk_type, values):
        nonlocal offset
        components = 1 if values.ndim == 1 else values.shape[1]
        named = f' Name="{name}"' if name else ""
        line = (f'        <DataArray type="{vtk_type}"{named} NumberOfComponents="{components}" '
                f'format="appended" offset="{offset}"/>\n')
        data = np.ascontiguousarray(values).tobytes()
        blocks.append(struct.pack("<Q", len(data)) + data)
        offset += 8 + len(data)
        return line

    xml = ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" '
           'byte_order="LittleEndian" header_type="UInt64">\n  <UnstructuredGrid>\n'
           f'    <Piece NumberOfPoints="{n}" NumberOfCells="{n}">\n      <PointData>\n')
    xml += "".join(declare(*a) for a in arrays)
    xml += "      </PointData>\n      <Points>\n"
    xml += declare(None, "Float64", np.asarray(points, dtype="<f8"))
    xml += "      </Points>\n      <Cells>\n"
    xml += "".join(declare(*c) for c in cells)
    xml += ('      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n'
            '  <AppendedData encoding="raw">\n   _')
    with open(path, "wb") as f:
        f.write(xml.encode() + b"".join(blocks) + b"\n  </AppendedData>\n</VTKFile>\n")


def lattice(geometry):
    """Points of a 'particle' (a 4 x 4 square above z = 0) and a 'substrate' (8 x 3 below);
    in 3D three layers at y = -1, 0, 1 um; in r-z the x coordinate is the radius r > 0."""
    h = SPACING
    layers = [0.0] if geometry == "axisymmetric" else [-h, 0.0, h]
    axisymmetric = geometry == "axisymmetric"
    x0 = 0.5 * h if axisymmetric else -3.5 * h
    x0_substrate = x0 if axisymmetric else x0 - 2 * h
    points, body = [], []
    for y in layers:
        for i in range(4):
            for k in range(4):
                points.append((x0 + i * h, y, (k + 0.5) * h))
                body.append(0)
        for i in range(8):
            for k in range(3):
                points.append((x0_substrate + i * h, y, -(k + 0.5) * h))
                body.append(1)
    return np.array(points), np.array(body, dtype="<i4")


def snapshot_arrays(points, body, time):
    n = len(points)
    velocity = np.zeros((n, 3))
    velocity[:, 2] = np.where(body == 0, -100.0 + 1e9 * time, 0.0)
    eqps = np.where(body == 0, 1e8 * time * points[:, 2] / SPACING, 0.0)
    return [("body", "Int32", body),
            ("velocity", "Float64", velocity),
            ("eqps", "Float64", eqps),
            ("temperature", "Float64", 298.0 + 10.0 * eqps),
            ("surface", "UInt8", (np.arange(n) % 2).astype("<u1"))]


CASE_YAML = """\
# The resolved case 'tiny' (synthetic, for the plotting tool's tests): every value in SI units.
name: tiny
description: "two blocks # not a comment"
materials:
  al:
    density: 2700  # kg/m^3
bodies:
  - name: particle
    material: al
    shape:
      type: box
      min: [0, 0, 0]  # m
      max: [4e-06, 1e-06, 4e-06]  # m
    spacing: {spacing}  # m
    velocity: [0, 0, -100]  # m/s
    absorbing: []
  - name: substrate
    material: al
    shape: {{type: box, min: [-2e-06, 0, -3e-06], max: [6e-06, 1e-06, 0]}}
    spacing: {spacing}  # m
    absorbing: [bottom, side]
grid:
  cell_size: 2e-06  # m
solver:
  method: mpm
  geometry: {geometry}
  end_time: 2e-08  # s
output:
  history_interval: 1e-09  # s
  probes: []
"""

HISTORY_COLUMNS = ["time", "kinetic", "total", "particle.vz", "particle.cor", "particle.mean_eqps",
                   "substrate.vz", "substrate.mean_eqps"]


def write_history(path, end_time):
    rows = [",".join(HISTORY_COLUMNS)]
    for t in np.linspace(0.0, end_time, 21):
        cor = "nan" if t < 0.5 * end_time else f"{0.1 + t * 1e6:.6g}"
        rows.append(",".join([f"{t:.10g}", f"{1e-9 * (1 - t / end_time):.10g}", "1e-09",
                              f"{-100 + 1e9 * t:.10g}", cor, f"{1e8 * t:.6g}", "0",
                              f"{1e7 * t:.6g}"]))
    with open(path, "w") as f:
        f.write("\n".join(rows) + "\n")


def moved(points, body, time):
    """The particle's points moved down by 1 mm/s x time (a tiny, exactly known offset)."""
    return points + np.where(body == 0, -1e-3 * time, 0.0)[:, None] * [0, 0, 1]


def write_run(folder, geometry):
    """A run folder with snapshots at 0, 10 and 20 ns."""
    os.makedirs(os.path.join(folder, "snapshots"))
    with open(os.path.join(folder, "case.resolved.yaml"), "w") as f:
        f.write(CASE_YAML.format(spacing=f"{SPACING:g}", geometry=geometry))
    points, body = lattice(geometry)
    entries = []
    for step, time in ((0, 0.0), (5, 1e-8), (10, 2e-8)):
        name = f"snapshots/step_{step:08d}.vtu"
        now = moved(points, body, time)
        write_vtu(os.path.join(folder, name), now, snapshot_arrays(now, body, time))
        entries.append(f'    <DataSet timestep="{time:.10g}" file="{name}"/>')
    with open(os.path.join(folder, "snapshots.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                "  <Collection>\n" + "\n".join(entries) + "\n  </Collection>\n</VTKFile>\n")
    write_history(os.path.join(folder, "history.csv"), 2e-8)
    return points, body


# ------------------------------------------------------------------------------------------
# Tests
# ------------------------------------------------------------------------------------------

class PlotToolTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tool = load_tool()
        cls.temp = tempfile.TemporaryDirectory(prefix="coldspray-plot-test-")
        cls.rz = os.path.join(cls.temp.name, "rz")
        cls.rz_points, cls.rz_body = write_run(cls.rz, "axisymmetric")
        cls.xyz = os.path.join(cls.temp.name, "xyz")
        write_run(cls.xyz, "3d")

    @classmethod
    def tearDownClass(cls):
        cls.temp.cleanup()

    def run_tool(self, *args):
        return subprocess.run([sys.executable, PLOT, *args], capture_output=True, text=True,
                              timeout=120)

    def out(self, name):
        return os.path.join(self.temp.name, name)

    def assert_png(self, result, path):
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(path, "rb") as f:
            data = f.read()
        self.assertTrue(data.startswith(PNG_SIGNATURE), path)
        self.assertGreater(len(data), 1000)

    def assert_failed_without_png(self, result, path, *words):
        self.assertEqual(result.returncode, 2, result.stderr)
        for word in words:
            self.assertIn(word, result.stderr)
        self.assertFalse(os.path.exists(path))
        self.assertEqual([f for f in os.listdir(os.path.dirname(path)) if "coldspray_plot" in f],
                         [], "a temporary file was left behind")

    # --- readers ------------------------------------------------------------------------

    def test_vtu_reader_returns_the_written_arrays(self):
        data = self.tool.read_vtu(os.path.join(self.rz, "snapshots", "step_00000005.vtu"))
        expected_points = moved(self.rz_points, self.rz_body, 1e-8)
        expected = dict((name, values) for name, _, values in
                        snapshot_arrays(expected_points, self.rz_body, 1e-8))
        self.assertEqual(sorted(data.arrays), sorted(expected))
        np.testing.assert_array_equal(data.points, expected_points)
        for name, values in expected.items():
            np.testing.assert_array_equal(data.arrays[name], values, err_msg=name)
        self.assertEqual(data.arrays["body"].dtype, np.int32)
        self.assertEqual(data.arrays["surface"].dtype, np.uint8)
        self.assertEqual(data.arrays["velocity"].shape, (len(self.rz_points), 3))
        self.assertEqual(data.arrays["velocity"][0, 2], -90.0)

    def test_pvd_reader_lists_times_and_files(self):
        entries = self.tool.read_pvd(os.path.join(self.rz, "snapshots.pvd"))
        self.assertEqual([t for t, _ in entries], [0.0, 1e-8, 2e-8])
        self.assertTrue(all(os.path.isfile(path) for _, path in entries))

    def test_case_reader_finds_geometry_bodies_and_spacings(self):
        case = self.tool.CaseInfo(os.path.join(self.rz, "case.resolved.yaml"))
        self.assertTrue(case.axisymmetric)
        self.assertEqual(case.body_names, ["particle", "substrate"])
        self.assertEqual(case.spacings, [SPACING, SPACING])
        self.assertFalse(self.tool.CaseInfo(os.path.join(self.xyz, "case.resolved.yaml")).axisymmetric)

    def test_times_accept_units(self):
        for text in ("80ns", "80 ns", "8e-8", "0.08us", "8e-8 s", "80000ps"):
            self.assertAlmostEqual(self.tool.parse_time(text), 8e-8, delta=1e-20, msg=text)
        for text in ("80 parsecs", "ns", ""):
            with self.assertRaises(self.tool.PlotError):
                self.tool.parse_time(text)

    def test_axisymmetric_section_is_mirrored(self):
        case = self.tool.CaseInfo(os.path.join(self.rz, "case.resolved.yaml"))
        data = self.tool.read_vtu(os.path.join(self.rz, "snapshots", "step_00000000.vtu"))
        section = self.tool.make_section(data, case, [0], ["eqps"], "test")
        self.assertEqual(len(section.h), 2 * 16)
        np.testing.assert_array_equal(section.h[16:], -section.h[:16])

    def test_3d_section_takes_the_middle_layer(self):
        case = self.tool.CaseInfo(os.path.join(self.xyz, "case.resolved.yaml"))
        data = self.tool.read_vtu(os.path.join(self.xyz, "snapshots", "step_00000000.vtu"))
        section = self.tool.make_section(data, case, [0, 1], ["velocity.z"], "test")
        self.assertEqual(len(section.h), 16 + 24)  # one layer of three
        self.assertEqual(set(section.values["velocity.z"]), {-100.0, 0.0})

    def test_3d_section_cuts_and_draws_each_point_by_its_half_widths(self):
        case = self.tool.CaseInfo(os.path.join(self.xyz, "case.resolved.yaml"))
        s = 0.175e-6
        points = np.array([[0.0, 0.5 * s, 0.0], [0.0, 1.5 * s, 0.0], [1e-6, 2 * s, 0.0]])
        half = np.array([[0.5 * s] * 3, [0.5 * s] * 3, [2 * s] * 3])  # the last: a 4 s block
        data = self.tool.VtuData(points, {"body": np.array([1, 1, 1]), "half_width": half,
                                          "eqps": np.zeros(3)})
        section = self.tool.make_section(data, case, [1], ["eqps"], "test")
        self.assertEqual(list(section.h), [0.0, 1e-6])  # the plane y = 0 crosses these two
        self.assertEqual(list(section.size), [s, 4 * s])

    def test_3d_material_cut_follows_the_points_that_started_in_the_layer(self):
        case = self.tool.CaseInfo(os.path.join(self.xyz, "case.resolved.yaml"))
        first = self.tool.read_vtu(os.path.join(self.xyz, "snapshots", "step_00000000.vtu"))
        later = self.tool.read_vtu(os.path.join(self.xyz, "snapshots", "step_00000000.vtu"))
        middle = np.abs(first.points[:, 1]) < 0.01 * SPACING
        later.points = later.points.copy()
        later.points[middle, 1] += 0.7 * SPACING  # the middle layer has moved off y = 0
        plane = self.tool.make_section(later, case, [0, 1], ["eqps"], "test")
        material = self.tool.make_section(later, case, [0, 1], ["eqps"], "test", first)
        reference = self.tool.make_section(first, case, [0, 1], ["eqps"], "test")
        self.assertEqual(len(plane.h), 0)  # no point lies within 0.6 spacing of y = 0 now
        self.assertEqual(len(material.h), 16 + 24)
        np.testing.assert_array_equal(material.h, reference.h)
        first.points = first.points[:-1]
        with self.assertRaises(self.tool.PlotError):
            self.tool.make_section(later, case, [0, 1], ["eqps"], "test", first)

    # --- the command line ---------------------------------------------------------------

    def test_section_writes_a_png(self):
        path = self.out("section.png")
        result = self.run_tool("section", self.rz, "--times", "0ns,10 ns,0.02us", "--field", "eqps",
                               "--field", "temperature", "--range", "0:1", "--out", path)
        self.assert_png(result, path)

    def test_section_of_a_3d_run_writes_a_png(self):
        path = self.out("section3d.png")
        result = self.run_tool("section", self.xyz, "--times", "2e-8", "--field", "velocity",
                               "--bodies", "particle", "--out", path)
        self.assert_png(result, path)

    def test_sections_of_two_runs_stand_side_by_side(self):
        options = self.tool.build_parser().parse_args(
            ["section", self.rz, self.xyz, "--times", "10ns,20ns", "--labels", "MPM,PD",
             "--out", self.out("unused.png")])
        figures = []
        original = self.tool.save_figure
        self.tool.save_figure = lambda fig, out, dpi: figures.append(fig)
        try:
            options.run(options)
        finally:
            self.tool.save_figure = original
        panels = [ax for ax in figures[0].axes if ax.get_title()]
        self.assertEqual([ax.get_title() for ax in panels],
                         ["MPM, t = 10 ns", "MPM, t = 20 ns", "PD, t = 10 ns", "PD, t = 20 ns"])
        self.assertEqual([ax.get_xlabel()[0] for ax in panels], ["r", "r", "x", "x"])

    def test_sections_with_too_few_labels_fail_without_a_png(self):
        path = self.out("labels.png")
        result = self.run_tool("section", self.rz, self.xyz, "--times", "10ns", "--labels", "MPM",
                               "--out", path)
        self.assert_failed_without_png(result, path, "--labels")

    def test_history_overlays_runs(self):
        path = self.out("history.png")
        result = self.run_tool("history", self.rz, self.xyz, "--columns", "cor,mean_eqps,kinetic",
                               "--body", "particle", "--labels", "r-z,3D", "--out", path)
        self.assert_png(result, path)

    def test_missing_column_fails_without_a_png(self):
        path = self.out("missing-column.png")
        result = self.run_tool("history", self.rz, "--columns", "mean_eqps,no_such_column",
                               "--body", "particle", "--out", path)
        self.assert_failed_without_png(result, path, "no_such_column", "particle.mean_eqps")

    def test_unknown_field_fails_without_a_png(self):
        path = self.out("unknown-field.png")
        result = self.run_tool("section", self.rz, "--times", "10ns", "--field", "bond",
                               "--out", path)
        self.assert_failed_without_png(result, path, "bond", "eqps")

    def test_time_outside_the_run_fails_without_a_png(self):
        path = self.out("late.png")
        result = self.run_tool("section", self.rz, "--times", "10ns,50ns", "--out", path)
        self.assert_failed_without_png(result, path, "50ns")

    def test_missing_folder_fails_without_a_png(self):
        path = self.out("nothing.png")
        missing = os.path.join(self.temp.name, "no-such-run")
        result = self.run_tool("history", missing, "--columns", "kinetic", "--out", path)
        self.assert_failed_without_png(result, path, missing)

    def test_sweep_plots_a_column_against_the_varied_key(self):
        folder = write_sweep(self.out("sweep"))
        path = self.out("sweep.png")
        self.assert_png(self.run_tool("sweep", folder, folder, "--x", "contact.beta", "--y",
                                      "particle.cor", "--labels", "500 m/s,again",
                                      "--out", path), path)
        missing = self.out("sweep-missing.png")
        self.assert_failed_without_png(
            self.run_tool("sweep", folder, "--x", "contact.beta", "--y", "particle.v_rest",
                          "--out", missing), missing, "particle.v_rest")

    def test_sweep_draws_a_line_per_value_of_another_key(self):
        folder = self.out("sweep-two-keys")
        os.makedirs(folder)
        with open(os.path.join(folder, "sweep.csv"), "w") as f:
            f.write('case,status,bodies.particle.velocity,contact.beta,particle.cor\n'
                    'case_0001,ok,"[0,0,-400 m/s]",0.002,0.07\n'
                    'case_0002,ok,"[0,0,-400 m/s]",0.004,0.0\n'
                    'case_0003,ok,"[0,0,-500 m/s]",0.002,0.08\n'
                    'case_0004,failed,"[0,0,-500 m/s]",0.004,nan\n')
        lines = []  # what the tool draws: (label, x, y) per line
        axes, draw = self.tool.plt.Axes, self.tool.plt.Axes.plot
        axes.plot = lambda ax, x, y, *a, **k: lines.append((k["label"], list(x), list(y)))
        try:
            self.tool.command_sweep(self.tool.build_parser().parse_args(
                ["sweep", folder, "--x", "contact.beta", "--y", "particle.cor", "--by",
                 "bodies.particle.velocity", "--out", self.out("by.png")]))
        finally:
            axes.plot = draw
        self.assertEqual(lines, [
            ("bodies.particle.velocity = [0,0,-400 m/s]", [0.002, 0.004], [0.07, 0.0]),
            ("bodies.particle.velocity = [0,0,-500 m/s]", [0.002], [0.08])])
        missing = self.out("by-missing.png")
        self.assert_failed_without_png(
            self.run_tool("sweep", folder, "--x", "contact.beta", "--y", "particle.cor", "--by",
                          "contact.r0", "--out", missing), missing, "contact.r0")

    def test_bulk_fracture_draws_the_bulk_curve_and_its_fit(self):
        folder = write_bulk_fracture(self.out("bulk-fracture"))
        path = self.out("bulk-fracture.png")
        self.assert_png(self.run_tool("bulk-fracture", folder, "--out", path), path)
        os.remove(os.path.join(folder, "fit.json"))
        missing = self.out("bulk-fracture-missing.png")
        self.assert_failed_without_png(self.run_tool("bulk-fracture", folder, "--out", missing),
                                       missing, "fit.json")

    def test_material_test_draws_curves_beside_the_johnson_cook_formula(self):
        path_csv = write_material_test(self.out("material-test.csv"))
        path = self.out("material-test.png")
        self.assert_png(self.run_tool("material-test", path_csv, "--labels", "1e3 1/s",
                                      "--johnson-cook", "90,292,0.31,0.025,1.09,1356",
                                      "--source", "Johnson & Cook 1983", "--out", path), path)
        wrong = self.out("material-test-jc.png")
        self.assert_failed_without_png(self.run_tool("material-test", path_csv, "--johnson-cook",
                                                     "90,292,0.31", "--out", wrong),
                                       wrong, "--johnson-cook")

    def test_johnson_cook_formula_matches_the_hand_calculation(self):
        # OFHC Cu (Johnson & Cook 1983) at eqps 0.2, 1e3 1/s, 500 K: 261.89673983504822 MPa
        # (the hand calculation of tests/materials/johnson_cook_test.cpp).
        constants = self.tool.parse_johnson_cook("90,292,0.31,0.025,1.09,1356")
        self.assertAlmostEqual(self.tool.johnson_cook_stress(constants, 0.2, 1e3, 500.0) / 1e6,
                               261.89673983504822, places=9)
        # Below the reference rate and temperature: no softening, A + B eqps^n.
        self.assertAlmostEqual(self.tool.johnson_cook_stress(constants, 0.2, 1e-3, 200.0) / 1e6,
                               90 + 292 * 0.2 ** 0.31, places=9)

    def test_pull_off_draws_force_against_displacement(self):
        folder = write_pull_off(self.out("pull-off"))
        path = self.out("pull-off.png")
        self.assert_png(self.run_tool("pull-off", folder, folder, "--labels", "a,b",
                                      "--out", path), path)
        wrong = self.out("pull-off-labels.png")
        self.assert_failed_without_png(self.run_tool("pull-off", folder, "--labels", "a,b",
                                                     "--out", wrong), wrong, "--labels")

    def test_bond_strength_draws_strength_against_speed_and_a_radial_profile(self):
        folder = self.out("bond-strength")
        for case, strength in (("case_0001", 80e6), ("case_0002", 120e6)):
            os.makedirs(os.path.join(folder, case, "pull-off"))
            with open(os.path.join(folder, case, "pull-off", "interface.csv"), "w") as f:
                f.write("x,y,z,radius,area,bond,damage,strength,critical_opening\n"
                        f"1e-6,0,0,1e-6,1e-12,0.4,0,{strength / 2},1e-6\n"
                        f"5e-6,0,0,5e-6,1e-12,2.0,0.1,{strength},1e-6\n")
        with open(os.path.join(folder, "sweep.csv"), "w") as f:
            f.write("case,status,bodies.particle.velocity,pull_off.strength_bonded,"
                    "pull_off.strength_projected\n"
                    'case_0001,ok,"[0,0,-900 m/s]",80e6,30e6\n'
                    'case_0002,ok,"[0,0,-800 m/s]",120e6,50e6\n'
                    'case_0003,failed,"[0,0,-1000 m/s]",nan,nan\n')
        drawn = []  # what the tool draws: (x, y) of the lines, then the scatter's
        axes = self.tool.plt.Axes
        plot, scatter = axes.plot, axes.scatter
        axes.plot = lambda ax, x, y, *a, **k: drawn.append((list(x), list(y)))
        axes.scatter = lambda ax, x, y, *a, **k: drawn.append((list(x), list(y)))
        try:
            self.tool.command_bond_strength(self.tool.build_parser().parse_args(
                ["bond-strength", folder, "--out", self.out("bond-strength.png")]))
        finally:
            axes.plot, axes.scatter = plot, scatter
        # Sorted by speed, in MPa; the profile of the strongest case (case_0002), in um and MPa.
        self.assertEqual(drawn, [([800.0, 900.0], [120.0, 80.0]), ([800.0, 900.0], [50.0, 30.0]),
                                 ([1.0, 5.0], [60.0, 120.0])])
        missing = self.out("bond-strength-missing.png")
        self.assert_failed_without_png(self.run_tool("bond-strength", folder, "--key",
                                                     "bodies.other.velocity", "--out", missing),
                                       missing, "bodies.other.velocity")

    def test_deposit_draws_the_thickness_map_and_a_section(self):
        folder = self.out("deposit")
        shutil.copytree(self.xyz, folder)
        with open(os.path.join(folder, "deposit.json"), "w") as f:
            json.dump({"patch": [2e-6, 2e-6], "deposition_efficiency": 1.0, "porosity": 0.25,
                       "mean_thickness": 1.5e-6,
                       "particles": [{"name": "p1", "centre": [0, 0, 1e-6], "diameter": 1e-6,
                                      "verdict": "bonded"}],
                       "thickness_map": {"columns_x": 2, "columns_y": 2,
                                         "values": [1e-6, 2e-6, 0.0, 3e-6]}}, f)
        drawn = []  # the map the tool draws, in um
        axes = self.tool.plt.Axes
        imshow = axes.imshow
        axes.imshow = lambda ax, image, *a, **k: drawn.append(image.tolist()) or imshow(
            ax, image, *a, **k)
        try:
            self.tool.command_deposit(self.tool.build_parser().parse_args(
                ["deposit", folder, "--out", self.out("deposit.png")]))
        finally:
            axes.imshow = imshow
        self.assertEqual(drawn, [[[1.0, 2.0], [0.0, 3.0]]])  # rows along y, x fastest
        missing = self.out("deposit-missing.png")
        self.assert_failed_without_png(self.run_tool("deposit", self.rz, "--out", missing),
                                       missing, "deposit.json")

    def test_calibration_draws_verdicts_or_tolerances(self):
        for by in ("verdict", "cor-pbcp"):
            folder = write_calibration(self.out("calibration-" + by), by)
            path = self.out(f"calibration-{by}.png")
            self.assert_png(self.run_tool("calibration", folder, "--out", path), path)


def write_sweep(folder):
    """A sweep folder as src/studies/sweep.cpp writes it: three cases, one failed."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "sweep.csv"), "w") as f:
        f.write("case,status,contact.beta,particle.cor\n"
                "case_0001,ok,0.002,0.08\ncase_0002,failed,0.004,nan\ncase_0003,ok,0.005,0.0\n")
    return folder


def write_material_test(path):
    """A material-test CSV as src/material_test/loading.cpp writes it: OFHC Cu in uniaxial stress
    at 1e3 1/s, isothermal at 298 K, von Mises on the Johnson-Cook curve once it flows."""
    import math
    with open(path, "w") as f:
        f.write("time,strain,eqps,eqps_rate,temperature,melt_temperature,shear_modulus,"
                "flow_stress,von_mises,pressure,density\n")
        for i in range(21):
            eqps = 0.025 * i
            stress = (90e6 + 292e6 * eqps ** 0.31) * (1 + 0.025 * math.log(1e3))
            f.write(f"{i * 1e-5},{-eqps},{eqps},{1e3 if i else 0},298,1356,4.6e10,{stress},"
                    f"{stress},{-stress / 3},8930\n")
    return path


def write_bulk_fracture(folder):
    """A bulk-fracture folder as src/cli/bulk_fracture.cpp writes it: s_c = 0.002, c = 1e33."""
    import json
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "bulk_fracture.csv"), "w") as f:
        f.write("stretch,bulk_force_density,fitted_force_density\n"
                "0,0,0\n0.002,2e30,2e30\n0.004,5e29,8e29\n0.008,0,1e29\n")
    with open(os.path.join(folder, "fit.json"), "w") as f:
        json.dump({"material": "cu-jc", "micromodulus": 1e33, "critical_stretch": 0.002,
                   "yield_stretch": 0.002, "softening": 300.0}, f)
    return folder


def write_pull_off(folder):
    """A pull-off folder as src/studies/pull_off.cpp writes it."""
    import json
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "pull_off.csv"), "w") as f:
        f.write("displacement,force\n0,0\n1e-9,0.5e-3\n2e-9,0.7e-3\n3e-9,0.1e-3\n4e-9,0\n")
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump({"peak_force": 0.7e-3, "peak_displacement": 2e-9,
                   "strength_projected": 1.4e7}, f)
    return folder


def write_calibration(folder, by):
    """A calibration folder as src/studies/calibration.cpp writes it: one grid, one size, four
    runs (one of each outcome and one more bonded), and a straight boundary."""
    import json
    os.makedirs(folder, exist_ok=True)
    rule = {"by": by} if by == "verdict" else {"by": by, "cor_max": 0.01, "pbcp_min": 5.0}
    axis = {"key": "critical_energy", "unit": "J/m^2", "from": 10.0, "to": 1000.0, "count": 2,
            "spacing": "log"}
    result = {"name": "test",
              "parameters": {"x1": axis, "x2": dict(axis, key="critical_energy_rate")},
              "grids": [{"grid": "1um/0.25um", "calibrated": {"critical_energy": 100.0,
                                                              "critical_energy_rate": 100.0},
                         "sizes": [{"size": "14um", "diameter_um": 14, "velocity_ms": 810,
                                    "classify": rule, "boundary_csv": "boundary_14um.csv"}]}]}
    with open(os.path.join(folder, "calibration.json"), "w") as f:
        json.dump(result, f)
    with open(os.path.join(folder, "runs.csv"), "w") as f:
        f.write("grid,size,diameter_um,velocity_ms,critical_energy,critical_energy_rate,status,"
                "outcome,separation_speed,margin,cor,abp,pbcp,v_rest,y\n")
        for x1, x2, outcome, speed, cor, pbcp, y in (
                (10, 10, "bonded", 0.3, 0.001, 50, "1"), (10, 1000, "bonded", -0.2, 0.0, 45, "1"),
                (1000, 10, "rebounded", 28.0, 0.04, 41, "0"),
                (1000, 1000, "undecided", 1.0, 0.002, 48, "" if by == "verdict" else "1")):
            f.write(f"1um/0.25um,14um,14,810,{x1},{x2},ok,{outcome},{speed},{2 - speed},{cor},1,"
                    f"{pbcp},{speed},{y}\n")
    with open(os.path.join(folder, "boundary_14um.csv"), "w") as f:
        f.write("x1,x2,curve\n10,1000,0\n1000,10,0\n")
    return folder


if __name__ == "__main__":
    unittest.main(verbosity=2)
