#!/usr/bin/python3
"""The python package `centrec` (python/) read against real output folders.

The folders: those of the outputs fixture (tests/outputs: `centrec dem` of
tests/outputs/tiny_drum.yaml in FIXTURE/dem, `centrec run` of tests/coupling/small_coupled.yaml
in FIXTURE/run, its DEM in FIXTURE/cache), and, made here in WORK from the fixture's cached
DEM: a thermal-only transient run, a two-point sweep over the flux and a two-seed replicas
run (one new DEM: the second seed). Each check compares what the package returns with the files read independently
(json, h5py, csv), so a reader that dropped, renamed, reshaped or mislabelled something fails.

  /usr/bin/python3 tests/python/test_reader.py --centrec build/centrec --source . \
      --fixture build/tests/outputs/work --work /tmp/py_test   [unittest options]

PYTHONPATH must hold the source python/ folder (the CMake rule sets it). Exit 77 (ctest:
skipped) when numpy, h5py, pandas, xarray or yaml is missing, saying which.
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys
import unittest

SKIP = 77
for module in ("numpy", "h5py", "pandas", "xarray", "yaml"):
    try:
        __import__(module)
    except ImportError:
        print(f"SKIPPED: /usr/bin/python3 has no module '{module}' (Debian: python3-{module}; ./setup.sh installs it)")
        sys.exit(SKIP)

import h5py  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

import centrec  # noqa: E402

ARGS = None  # set by main()


def run_centrec(argv, log):
    """Runs the centrec binary; its output into `log`; fails the test on a non-zero exit."""
    cmd = [ARGS.centrec] + argv
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    with open(log, "w") as fh:
        fh.write(f"$ {' '.join(cmd)}\n--- stdout\n{p.stdout}--- stderr\n{p.stderr}")
    if p.returncode != 0:
        raise AssertionError(f"exit {p.returncode}: {' '.join(cmd)}\n{p.stderr[-2000:]}")
    return p.stdout


def read_json(path):
    with open(path) as fh:
        return json.load(fh)


def h5_datasets(path, under):
    """{path below `under`: (values, units)} of every dataset under the group, read with h5py."""
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                u = obj.attrs.get("units")
                out[name] = (obj[()], u.decode() if isinstance(u, bytes) else u)
        f[under].visititems(visit)
    return out


def work_cache():
    """WORK/cache holding a copy of the fixture's DEM of the small coupled case, so the runs
    made here reuse it and leave the fixture's folder as it is."""
    cache = os.path.join(ARGS.work, "cache")
    key = read_json(os.path.join(ARGS.fixture, "run", "summary.json"))["dem"]["cache_key"]
    if not os.path.isdir(os.path.join(cache, key)):
        shutil.copytree(os.path.join(ARGS.fixture, "cache", key), os.path.join(cache, key))
    return cache


class FieldChecks:
    """Checks of a Run against its own files, shared by the coupled and the thermal-only run."""

    def check_field_against_file(self, run, skip_groups=("film", "coupling", "xdmf")):
        with h5py.File(run.results_file, "r") as f:
            groups = [g for g in f if isinstance(f[g], h5py.Group) and g not in skip_groups]
        self.assertTrue(groups)
        n, names = 0, set()
        for g in groups:
            for rel, (values, units) in h5_datasets(run.results_file, g).items():
                name = rel.replace("/", "_")
                self.assertIn(name, run.field.variables, f"/{g}/{rel} missing from Run.field")
                var = run.field[name]
                self.assertIsNotNone(units, f"/{g}/{rel} has no units attribute")
                self.assertEqual(var.attrs.get("units"), units, f"units of /{g}/{rel}")
                self.assertEqual(var.shape, values.shape, f"shape of /{g}/{rel}")
                np.testing.assert_array_equal(var.values, values, err_msg=f"/{g}/{rel}")
                n += 1
                names.add(name)
        for extra in set(run.field.variables) - names:  # only labels of an axis without a scale
            self.assertIn(extra, run.field.dims, f"Run.field has {extra}, which is no dataset of the file")
        print(f"{run.path}: {n} datasets of {groups} in Run.field, each with the file's values and units")

    def check_grid_and_outlet(self, run):
        with h5py.File(run.results_file, "r") as f:
            resolved = yaml.safe_load(f.attrs["resolved_config"])
        nz, nxi = resolved["thermal"]["grid"]["nz"], resolved["thermal"]["grid"]["nxi"]
        T = run.field["T"]
        self.assertEqual(T.dims, ("z", "xi"))
        self.assertEqual(T.shape, (nz, nxi), "the field's shape is not the resolved case's grid nz x nxi")
        self.assertEqual(T.attrs["units"], "K")
        self.assertEqual(run.field["z"].attrs["units"], "m")
        summary = read_json(os.path.join(run.path, "summary.json"))
        self.assertEqual(run.T_out, summary["T_out_K"])
        self.assertEqual(run.efficiency, summary["efficiency"])
        self.assertEqual(run.k_eff, summary["k_eff"]["film_mean"]["k_eff"])
        # T_out is the last column's mixing-cup temperature (docs/outputs.md), in the field and
        # in along_z.csv (10 significant digits: 1e-6 K).
        self.assertEqual(float(run.field["T_mixing_cup"][-1]), run.T_out)
        self.assertEqual(run.field.attrs["T_out_K"], run.T_out)
        az = run.along_z
        self.assertEqual(len(az), nz, "along_z.csv has not one row per thermal column")
        self.assertAlmostEqual(float(az["T_mixing_cup_K"].iloc[-1]), run.T_out, delta=1e-6)
        np.testing.assert_allclose(az["z_m"], run.field["z"], rtol=1e-9)
        # The film-mean k_eff is the plain mean over the sections (thermal_output.cpp section_mean).
        self.assertAlmostEqual(float(run.field["keff_k_eff"].mean()), run.k_eff, delta=1e-12 * run.k_eff)
        with open(os.path.join(run.path, "along_z.csv")) as fh:
            header = next(csv.reader(fh))
        self.assertEqual(list(az.columns), header)
        units = az.attrs["units"]
        self.assertEqual(set(units), set(header), f"columns without a unit: {set(header) - set(units)}")
        for col, expect in (("T_mixing_cup_K", "K"), ("q_absorbed_W_m2", "W/m2"), ("keff_k_eff_W_mK", "W/(m K)"),
                            ("z_m", "m")):
            self.assertEqual(units[col], expect)
        print(f"{run.path}: T {T.shape} = resolved grid ({nz}, {nxi}); T_out {run.T_out:.6f} K = along_z "
              f"{az['T_mixing_cup_K'].iloc[-1]:.6f} K; k_eff {run.k_eff:.6f} W/(m K)")


class CoupledRun(unittest.TestCase, FieldChecks):
    @classmethod
    def setUpClass(cls):
        cls.out = centrec.load(os.path.join(ARGS.fixture, "run"))

    def test_kind(self):
        self.assertIsInstance(self.out, centrec.Run)
        self.assertEqual(self.out.kind, "run")

    def test_outlet_grid_and_along_z(self):
        self.check_grid_and_outlet(self.out)

    def test_field_is_the_file(self):
        self.check_field_against_file(self.out)

    def test_film_and_coupling_are_the_files(self):
        for ds, path, group in ((self.out.film, "film.h5", "film"), (self.out.coupling, "results.h5", "coupling")):
            self.assertIsNotNone(ds, group)
            for rel, (values, units) in h5_datasets(os.path.join(self.out.path, path), group).items():
                self.assertEqual(ds[rel].attrs.get("units"), units, f"{path}:/{group}/{rel}")
                np.testing.assert_array_equal(ds[rel].values, values)
        film = self.out.film
        self.assertEqual(film["u"].dims, ("z", "eta"))
        self.assertEqual(film.attrs["omega_units"], "rad/s")
        summary = read_json(os.path.join(self.out.path, "summary.json"))
        # The scaled film's thickness t [z] is the summary's film thickness.
        self.assertAlmostEqual(float(film["t"].mean()), summary["film"]["mean_thickness_m"],
                               delta=1e-9 * summary["film"]["mean_thickness_m"])
        self.assertEqual(self.out.coupling.attrs["imposed_mdot_kg_s"], summary["coupling"]["imposed_mdot_kg_s"])

    def test_its_dem(self):
        dem = self.out.dem
        self.assertIsInstance(dem, centrec.DemRun)
        self.assertEqual(dem.path.name, self.out.summary["dem"]["cache_key"])


class DemFolder(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dem = centrec.load(os.path.join(ARGS.fixture, "dem"))
        cls.summary = read_json(os.path.join(ARGS.fixture, "dem", "summary.json"))

    def test_kind(self):
        self.assertIsInstance(self.dem, centrec.DemRun)

    def test_film_is_the_file(self):
        film = self.dem.film
        data = h5_datasets(self.dem.dem_file, "film")
        # The variables are the file's datasets, plus at most the labels of an axis without a
        # scale (the solid fraction's zones).
        self.assertLessEqual(set(data), set(film.variables), "DemRun.film lacks datasets of dem.h5's /film")
        for extra in set(film.variables) - set(data):
            self.assertIn(extra, film.dims, f"DemRun.film has {extra}, which dem.h5's /film has not")
        for rel, (values, units) in data.items():
            self.assertIsNotNone(units, f"/film/{rel} has no units attribute")
            self.assertEqual(film[rel].attrs["units"], units, rel)
            np.testing.assert_array_equal(film[rel].values, values)
        self.assertEqual(film["axial_velocity_mean"].dims, ("arc_theta", "wall_distance_d"))
        self.assertEqual(film["arc_z_over_length"].dims, ("arc_theta",))
        self.assertEqual(film["thickness_mean"].dims, ("section_z",))
        self.assertEqual(film["wall_distance_d"].attrs["units"], "d")
        zones = list(film[film["solid_fraction_mean"].dims[0]].values)
        self.assertEqual(zones, ["stationary zone", "moving zone"])

    def test_film_matches_summary(self):
        d = self.dem.particle_diameter
        mean_d = self.summary["mean_film_thickness_d"]
        self.assertAlmostEqual(float(self.dem.film["thickness_mean"].mean()) / d, mean_d, delta=1e-9 * mean_d)
        self.assertAlmostEqual(self.dem.film.attrs["mean_thickness_m"] / d, mean_d, delta=1e-9 * mean_d)
        self.assertEqual(self.dem.film.attrs["sampled_turns"], self.summary["sampled_turns"])
        print(f"{self.dem.path}: film {mean_d:.4f} d = mean of {self.dem.film.sizes['section_z']} sections / d")

    def test_mass_flow(self):
        mf = self.dem.mass_flow
        series = self.dem.group("mass_flow")
        self.assertEqual(len(mf), series.sizes["time"])
        np.testing.assert_allclose(mf["out_cumulative_kg"], series["out"], rtol=1e-5, atol=1e-12)
        self.assertEqual(series["out"].attrs["units"], "kg")
        holdup = self.summary["holdup_kg"]  # mass_flow.csv: 6 significant digits
        self.assertAlmostEqual(mf["holdup_kg"].iloc[-1], holdup, delta=1e-5 * holdup)
        self.assertEqual(int(mf["free_particles"].iloc[-1]), self.summary["free_particles"])
        self.assertEqual(mf.attrs["units"]["slice_axial_flow_kg_s"], "kg/s")
        self.assertEqual(mf.attrs["units"]["time_s"], "s")

    def test_snapshots(self):
        times = self.dem.snapshot_times
        # The start of sampling, then every sampled snapshot.
        self.assertEqual(len(times), self.dem.film.attrs["snapshots"] + 1)
        self.assertEqual(times, sorted(times))
        last = self.dem.snapshot(-1)
        self.assertEqual(len(last), last.attrs["free_particles"] + last.attrs["glued_particles"])
        self.assertEqual(last.attrs["units"]["position_z"], "m")
        self.assertEqual(last.attrs["time"], times[-1])


class ThermalRun(unittest.TestCase, FieldChecks):
    """`centrec thermal` of the cloud-passage case, on a small grid and a short transient."""

    @classmethod
    def setUpClass(cls):
        out = os.path.join(ARGS.work, "thermal")
        run_centrec(["thermal", os.path.join(ARGS.source, "cases", "thermal_cloud_transient.yaml"), "--out", out,
                     "--set", "thermal.grid.nz=20", "--set", "thermal.grid.nxi=8",
                     "--set", "thermal.transient.t_end=6"], out + ".log")
        cls.out = centrec.load(out)

    def test_kind(self):
        self.assertIsInstance(self.out, centrec.Run)
        self.assertEqual(self.out.kind, "thermal")
        self.assertIsNone(self.out.coupling)
        self.assertIsNone(self.out.dem)
        self.assertTrue(self.out.film.attrs["source_file"].endswith("thermal.h5"))

    def test_outlet_grid_and_along_z(self):
        self.check_grid_and_outlet(self.out)

    def test_field_is_the_file(self):
        self.check_field_against_file(self.out)

    def test_transient(self):
        tr = self.out.summary["transient"]
        T_out = self.out.field["T_out"]
        self.assertEqual(T_out.dims, ("t",))
        self.assertEqual(self.out.field["t"].attrs["units"], "s")
        self.assertAlmostEqual(float(self.out.field["t"][-1]), tr["t_end_s"], delta=1e-9)
        self.assertEqual(float(T_out[-1]), tr["T_out_end_K"])
        self.assertEqual(float(T_out.max()), tr["T_out_max_K"])


class SweepFolder(unittest.TestCase):
    """A two-point sweep of the small coupled case over the flux on the film (`--grid`): both
    points from the cached DEM."""

    @classmethod
    def setUpClass(cls):
        cache = work_cache()
        out = os.path.join(ARGS.work, "sweep")
        case = os.path.join(ARGS.source, "tests", "coupling", "small_coupled.yaml")
        cls.swept, cls.values = "thermal.flux.q_film", [1.5e5, 2.5e5]
        grid = ["--grid", "thermal.flux.q_film=1.5e5,2.5e5"]
        run_centrec(["sweep", case, "--out", out, "--cache", cache, "--allow-small-drum"] + grid, out + ".log")
        cls.sweep = centrec.load(out)

    def test_kind(self):
        self.assertIsInstance(self.sweep, centrec.Sweep)

    def test_one_row_per_point_folder(self):
        folders = sorted(e.name for e in os.scandir(self.sweep.path)
                         if e.is_dir() and os.path.isfile(os.path.join(e.path, "summary.json")))
        self.assertEqual(len(self.sweep.table), len(folders))
        self.assertEqual(len(self.sweep.points), len(folders))
        self.assertEqual(sorted(p.name for p in self.sweep.dirs), folders)

    def test_rows_are_their_points(self):
        table = self.sweep.table
        self.assertIn(self.swept, self.sweep.swept)
        self.assertEqual(sorted(table[self.swept]), sorted(self.values))
        for k, point in enumerate(self.sweep.points):
            self.assertIsInstance(point, centrec.Run)
            # sweep.csv writes at least 6 significant digits.
            self.assertAlmostEqual(table["T_out_K"][k], point.T_out, delta=1e-5 * point.T_out)
            self.assertAlmostEqual(table["efficiency"][k], point.efficiency, delta=1e-5)
            self.assertAlmostEqual(table["k_eff_W_mK"][k], point.k_eff, delta=1e-5 * point.k_eff)
            own = point.summary["point"]["flux_film_mean_W_m2"]
            self.assertAlmostEqual(table[self.swept][k], own, delta=1e-6 * own)
            print(f"{point.path.name}: {self.swept} {table[self.swept][k]:g}, T_out {point.T_out:.2f} K, "
                  f"efficiency {point.efficiency:.4f}")
        self.assertNotEqual(self.sweep.points[0].T_out, self.sweep.points[1].T_out)
        self.assertEqual(table.attrs["units"]["T_out_K"], "K")
        self.assertEqual(table.attrs["units"]["k_eff_W_mK"], "W/(m K)")


class ReplicasFolder(unittest.TestCase):
    """`centrec run --replicas 2` of the small coupled case (seed 0's DEM from the cache)."""

    @classmethod
    def setUpClass(cls):
        out = os.path.join(ARGS.work, "replicas")
        run_centrec(["run", os.path.join(ARGS.source, "tests", "coupling", "small_coupled.yaml"), "--out", out,
                     "--cache", work_cache(), "--replicas", "2", "--allow-small-drum", "--allow-unsteady",
                     "--no-plots"], out + ".log")
        cls.rep = centrec.load(out)

    def test_replicas(self):
        rep = self.rep
        self.assertIsInstance(rep, centrec.Replicas)
        folders = sorted(e.name for e in os.scandir(rep.path) if e.is_dir() and e.name.startswith("replica_"))
        self.assertEqual(len(rep.points), len(folders))
        self.assertEqual(len(rep.table), 2)
        for k, point in enumerate(rep.points):
            self.assertIsInstance(point, centrec.Run)
            self.assertEqual(rep.table["/T_out_K"][k], point.T_out)
            self.assertEqual(rep.table["/k_eff/film_mean/k_eff"][k], point.k_eff)
            self.assertEqual(rep.table["seed"][k], rep.seeds[k])
        for ptr in rep.spread.index:  # centrec's mean and sample standard deviation of the values
            scale = abs(rep.table[ptr].mean())
            self.assertAlmostEqual(rep.spread["mean"][ptr], rep.table[ptr].mean(), delta=1e-12 * scale)
            self.assertAlmostEqual(rep.spread["std"][ptr], rep.table[ptr].std(ddof=1), delta=1e-9 * scale)
        self.assertEqual(rep.T_out, rep.spread["mean"]["/T_out_K"])
        print(f"{rep.path}: T_out {rep.T_out:.3f} +- {rep.spread['std']['/T_out_K']:.3f} K over seeds {rep.seeds}")


class OperateFolder(unittest.TestCase):
    """`centrec operate` of the small coupled case on a map made of the fixture run's film at
    2 speeds x 3 mass flows: one film everywhere, its inlet section repeated along z (a slice's
    film; the fixture's is a fed drum's), so the surrogate is that film, and the target, the
    fixture's own T_out, lies inside the map's T_out range."""

    @classmethod
    def setUpClass(cls):
        fixture = os.path.join(ARGS.fixture, "run")
        cls.fixture_T_out = read_json(os.path.join(fixture, "summary.json"))["T_out_K"]
        m = os.path.join(ARGS.work, "operate_map")
        points = []
        for rpm in (150.0, 170.0):
            for mdot in (0.03, 0.0357, 0.042):
                d = os.path.join(m, f"p{rpm:g}_{mdot:g}")
                os.makedirs(d)
                shutil.copy(os.path.join(fixture, "film.h5"), d)
                with h5py.File(os.path.join(d, "film.h5"), "r+") as f:
                    for name in ("t", "u", "phi", "D", "u_std", "phi_std", "D_std"):
                        if name in f["film"]:
                            f["film"][name][...] = f["film"][name][0]
                points.append({"dir": d, "status": 0, "speed_rpm": rpm, "mass_flow_kg_s": mdot,
                               "dem_flow_steady": True, "flow_closure": 1.0})
        axes = [{"key": "speed_rpm", "column": "speed_rpm"}, {"key": "mass_flow", "column": "mass_flow_kg_s"}]
        # The points hold films only (no summary.json), so operate learns the map's receiver
        # from the case file sweep.json names, as centrec sweep writes it.
        case = os.path.join(ARGS.source, "tests", "coupling", "small_coupled.yaml")
        with open(os.path.join(m, "sweep.json"), "w") as fh:
            json.dump({"case": case, "axes": axes, "points": points}, fh)
        out = os.path.join(ARGS.work, "operate")
        run_centrec(["operate", case, "--map", m, "--target-outlet", repr(cls.fixture_T_out), "--speeds", "2",
                     "--out", out, "--no-plots"], out + ".log")
        cls.op = centrec.load(out)

    def test_kind(self):
        self.assertIsInstance(self.op, centrec.Operate)

    def test_answer_is_the_fixture_point(self):
        b = self.op.operating_point
        print(f"target {self.op.target_T_out:.4f} K: {b['speed_rpm']:g} rpm, {b['mass_flow_kg_s']:.6f} kg/s, "
              f"T_out {b['T_out_K']:.4f} K")
        self.assertAlmostEqual(self.op.target_T_out, self.fixture_T_out, delta=1e-9)
        self.assertAlmostEqual(b["T_out_K"], self.fixture_T_out, delta=0.02)
        self.assertTrue(0.03 <= b["mass_flow_kg_s"] <= 0.042)
        self.assertEqual(len(self.op.candidates), 2)
        self.assertTrue(self.op.candidates["found"].all())

    def test_tables(self):
        self.assertEqual(len(self.op.map_points), 6)
        self.assertTrue(self.op.map_points["usable"].all())
        self.assertEqual(list(self.op.surrogate_errors["quantity"])[0], "film thickness")
        self.assertEqual(len(self.op.map), 81)
        self.assertEqual(self.op.map.attrs["units"]["T_out_K"], "K")
        self.assertIsNone(self.op.transient)


class NotAnOutputFolder(unittest.TestCase):
    def folder(self, name, files=()):
        path = os.path.join(ARGS.work, "not_outputs", name)
        shutil.rmtree(path, ignore_errors=True)
        os.makedirs(path)
        for f in files:
            shutil.copy(f, path)
        return path

    def assertRefused(self, path, *words, call=centrec.load):
        with self.assertRaises(ValueError) as ctx:
            call(path)
        msg = str(ctx.exception)
        print(f"ValueError: {msg}")
        self.assertIn(path, msg)
        for w in words:
            self.assertIn(w, msg)

    def test_empty_folder(self):
        self.assertRefused(self.folder("empty"), "summary.json", "sweep.csv")

    def test_summary_without_results(self):
        path = self.folder("summary_only", [os.path.join(ARGS.fixture, "run", "summary.json")])
        self.assertRefused(path, "results.h5", "thermal.h5", "dem.h5")
        self.assertRefused(path, "results.h5", call=centrec.Run)

    def test_interrupted_dem(self):
        path = self.folder("interrupted")
        open(os.path.join(path, "checkpoint.h5"), "w").close()
        self.assertRefused(path, "--resume")

    def test_missing_folder(self):
        self.assertRefused(os.path.join(ARGS.work, "not_outputs", "no_such_folder"), "no such folder")

    def test_dem_folder_as_run(self):
        self.assertRefused(os.path.join(ARGS.fixture, "dem"), "results.h5", call=centrec.Run)

    def test_sweep_without_json(self):
        path = self.folder("sweep_without_json")
        with open(os.path.join(path, "sweep.csv"), "w") as fh:
            fh.write("speed_rpm,mass_flow_kg_s,T_out_K\n160.08,0.0357,1000\n")
        sweep = centrec.load(path)
        self.assertEqual(len(sweep.table), 1)
        self.assertRefused(path, "sweep.json", call=lambda p: sweep.points)


def main():
    global ARGS
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--centrec", required=True, help="the centrec binary")
    p.add_argument("--source", required=True, help="the source tree (cases/, tests/)")
    p.add_argument("--fixture", required=True, help="the outputs fixture's folder (tests/outputs: WORK)")
    p.add_argument("--work", required=True, help="a folder for this test's own runs (emptied first)")
    ARGS, rest = p.parse_known_args()
    for d in ("dem", "run", "cache"):
        if not os.path.isdir(os.path.join(ARGS.fixture, d)):
            print(f"FAILED: the outputs fixture's {os.path.join(ARGS.fixture, d)} is missing (test outputs.run)")
            sys.exit(1)
    shutil.rmtree(ARGS.work, ignore_errors=True)
    os.makedirs(ARGS.work)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)


if __name__ == "__main__":
    main()
