#!/usr/bin/python3
"""What a user opens after a run (docs/outputs.md), checked on small runs.

  run      `centrec dem` (tests/outputs/tiny_drum.yaml) and `centrec run`
           (tests/coupling/small_coupled.yaml) into WORK; console: named phases, one
           time-step line, the steady-state verdict
  figures  the PNGs both commands drew exist and are not blank; the plot scripts' --help
           and their error on a missing folder
  xdmf     dem.xmf (every snapshot, free and glued, integer ids), drum.xmf and results.xmf
           read by meshio (Debian python3-meshio)
  files    HDF5 provenance, dimension scales, one spelling of units; mass_flow.csv readable
           by a plain CSV reader (no comment line, cumulative columns named so)

A check whose python module is missing exits 77 (ctest: skipped) and says which.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

SKIP = 77


def need(module):
    try:
        return __import__(module)
    except ImportError:
        print(f"SKIPPED: /usr/bin/python3 has no module '{module}' (Debian: python3-{module}; ./setup.sh installs it)")
        sys.exit(SKIP)


def fail(msg):
    print(f"FAILED: {msg}")
    sys.exit(1)


def check(cond, msg):
    if not cond:
        fail(msg)


def run_cmd(argv, log):
    print("$ " + " ".join(argv), flush=True)
    p = subprocess.run(argv, capture_output=True, text=True)
    with open(log, "w") as fh:
        fh.write(f"$ {' '.join(argv)}\n--- stdout\n{p.stdout}--- stderr\n{p.stderr}")
    print(p.stdout[-1500:])
    if p.returncode != 0:
        print(p.stderr[-3000:])
        fail(f"exit {p.returncode}: {' '.join(argv)} (log {log})")
    return p.stdout, p.stderr


def do_run(a):
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    out, err = run_cmd([a.centrec, "dem", os.path.join(a.source, "tests/outputs/tiny_drum.yaml"), "--out",
                        os.path.join(a.work, "dem")], os.path.join(a.work, "dem.log"))
    both = out + err
    for phase in ("spin-up:", "sampling:"):
        check(phase in err, f"`centrec dem` names no phase '{phase}' on stderr")
    check(both.count("recommended dt") == 1, "the time-step advice is printed %d times, not once" % both.count("recommended dt"))
    check("steady state: outlet" in out, "`centrec dem` prints no steady-state verdict")
    out, err = run_cmd([a.centrec, "run", os.path.join(a.source, "tests/coupling/small_coupled.yaml"), "--out",
                        os.path.join(a.work, "run"), "--cache", os.path.join(a.work, "cache"), "--allow-small-drum", "--allow-unsteady"],
                       os.path.join(a.work, "run.log"))
    check("thermal:" in err, "`centrec run` names no thermal phase")
    check("DEM steady state:" in out, "`centrec run` prints no DEM steady-state verdict")
    # Without python, or without its plotting packages, the run says so and still succeeds
    # (the DEM comes from the cache: seconds).
    for python, says in (("/nonexistent/python3", "not found"), ("/bin/false", "lacks matplotlib")):
        env = dict(os.environ, CENTREC_PYTHON=python)
        folder = os.path.join(a.work, "run_without_python_" + os.path.basename(python))
        p = subprocess.run([a.centrec, "run", os.path.join(a.source, "tests/coupling/small_coupled.yaml"), "--out", folder,
                            "--cache", os.path.join(a.work, "cache"), "--allow-small-drum", "--allow-unsteady"],
                           capture_output=True, text=True, env=env)
        print(f"CENTREC_PYTHON={python}: exit {p.returncode}; " + p.stderr.strip().splitlines()[-1])
        check(p.returncode == 0, f"`centrec run` with CENTREC_PYTHON={python} failed: {p.stderr[-1000:]}")
        check("no figures: " in p.stderr and says in p.stderr, f"`centrec run` without plotting says: {p.stderr[-500:]}")
        check(os.path.isfile(os.path.join(folder, "results.h5")), "`centrec run` without plotting wrote no results.h5")


DEM_PNGS = ["fig2_mass_flow.png", "fig3_film_thickness.png", "fig6_velocity_profiles.png", "solid_fraction.png"]
RUN_PNGS = DEM_PNGS + ["thermal_T_map.png", "losses.png", "thermal_keff.png", "run_film.png", "run_velocity.png"]


def do_figures(a):
    need("matplotlib")
    import matplotlib.image as mpimg
    import numpy as np
    for folder, names in (("dem", DEM_PNGS), ("run", RUN_PNGS)):
        for name in names:
            path = os.path.join(a.work, folder, name)
            check(os.path.isfile(path), f"{path} was not drawn")
            img = mpimg.imread(path)
            h, w = img.shape[:2]
            # Not blank: a drawn figure has lines and text, so its pixels vary.
            spread = float(np.std(img[..., :3]))
            print(f"{path}: {w} x {h} px, {os.path.getsize(path)} bytes, pixel std {spread:.3f}")
            check(w >= 600 and h >= 300, f"{path} is only {w} x {h} px")
            check(os.path.getsize(path) > 15000 and spread > 0.05, f"{path} looks blank")
    apps = os.path.join(a.source, "apps")
    for script in ("plot_dem.py", "plot_run.py", "plot_thermal.py", "plot_sweep.py"):
        p = subprocess.run([sys.executable, os.path.join(apps, script), "--help"], capture_output=True, text=True)
        check(p.returncode == 0 and "usage:" in p.stdout, f"{script} --help fails: {p.stderr[-500:]}")
        missing = os.path.join(a.work, "no_such_folder")
        p = subprocess.run([sys.executable, os.path.join(apps, script), missing], capture_output=True, text=True)
        check(p.returncode == 2 and "no such folder" in p.stderr and "Traceback" not in p.stderr,
              f"{script} on a missing folder: exit {p.returncode}, {p.stderr[-500:]}")


def do_xdmf(a):
    meshio = need("meshio")
    import numpy as np
    dem = os.path.join(a.work, "dem")
    with meshio.xdmf.TimeSeriesReader(os.path.join(dem, "dem.xmf")) as r:
        points, cells = r.read_points_cells()
        print(f"dem.xmf: {r.num_steps} snapshots, first with {len(points)} particles")
        check(r.num_steps == 2 * 4 + 1, f"dem.xmf has {r.num_steps} snapshots, expected the start + 2 turns x 4")
        check(cells[0].type == "vertex" and len(cells[0].data) == len(points), "dem.xmf: not one vertex per particle")
        t0, data, _ = r.read_data(0)
        for name in ("velocity", "radius", "id", "glued"):
            check(name in data and len(data[name]) == len(points), f"dem.xmf: attribute {name} missing or wrong length")
        check(np.issubdtype(data["id"].dtype, np.integer), f"dem.xmf: ids are {data['id'].dtype}, not integers")
        check(set(np.unique(data["glued"])) == {0, 1}, "dem.xmf: the glued flag does not mark both free and glued")
        check(len(np.unique(data["id"])) == len(points), "dem.xmf: particle ids repeat")
        times = [r.read_data(k)[0] for k in range(r.num_steps)]
        check(all(b > a_ for a_, b in zip(times, times[1:])), f"dem.xmf: times not increasing {times}")
    drum = meshio.read(os.path.join(dem, "drum.xmf"))
    tri = drum.cells_dict.get("triangle")
    check(tri is not None and len(tri) > 100, "drum.xmf: no triangles")
    r_max = float(np.max(np.hypot(drum.points[:, 0], drum.points[:, 1])))
    check(abs(r_max - 0.015) < 1e-9, f"drum.xmf: drum radius {r_max} m, expected 0.015 m")
    film = meshio.read(os.path.join(a.work, "run", "results.xmf"))
    quads = film.cells_dict.get("quad")
    T = np.asarray(film.point_data["T"]).ravel()
    print(f"results.xmf: {len(film.points)} points, {len(quads)} quads, T {T.min():.1f}-{T.max():.1f} K")
    check(quads is not None and len(quads) > 0, "results.xmf: no quadrilaterals")
    check(T.size == len(film.points), "results.xmf: T is not one value per point")
    check(T.min() > 800.0 and T.max() < 2500.0, "results.xmf: implausible temperatures")


def do_files(a):
    h5py = need("h5py")
    import numpy as np
    files = {"dem": os.path.join(a.work, "dem", "dem.h5"), "results": os.path.join(a.work, "run", "results.h5"),
             "film": os.path.join(a.work, "run", "film.h5")}
    units = set()
    for key, path in files.items():
        with h5py.File(path, "r") as f:
            for attr in ("code_version", "case", "resolved_config", "input_hashes", "written_utc"):
                check(attr in f.attrs and len(str(f.attrs[attr])) > 0, f"{path}: provenance attribute {attr} missing or empty")
            check("fnv1a64:" in f.attrs["input_hashes"], f"{path}: no input hash")

            def visit(name, obj):
                if isinstance(obj, h5py.Dataset) and "units" in obj.attrs:
                    units.add(str(obj.attrs["units"]))
            f.visititems(visit)
    print("units used:", sorted(units))
    check(not any("^" in u for u in units), f"units spelled with '^': {sorted(u for u in units if '^' in u)}")
    with h5py.File(files["dem"], "r") as f:
        check(f["film/thickness_mean"].dims[0][0].name == "/film/section_z", "dem.h5: thickness has no z scale")
        check(f["mass_flow/out"].dims[0][0].name == "/mass_flow/time", "dem.h5: mass flow has no time scale")
        snaps = list(f["snapshots"].values())
        check(len(snaps) == 9, f"dem.h5 holds {len(snaps)} snapshots, expected 9")
        check(f["snapshots"][sorted(f["snapshots"])[0]]["id"].dtype == np.int64, "dem.h5: ids are not int64")
    with h5py.File(files["results"], "r") as f:
        check(f["steady/T"].dims[0][0].name == "/grid/z", "results.h5: T has no z scale")
        check("thermal:" in f.attrs["resolved_config"], "results.h5: resolved_config lacks the thermal section")
    with h5py.File(files["film"], "r") as f:
        check(f["film/u"].dims[1][0].name == "/film/eta", "film.h5: u has no eta scale")
    path = os.path.join(a.work, "dem", "mass_flow.csv")
    with open(path) as fh:
        first = fh.readline()
        check(not first.startswith("#"), f"{path}: header is a comment line")
        fh.seek(0)
        rows = list(csv.DictReader(fh))
    for col in ("time_s", "fed_cumulative_kg", "out_cumulative_kg", "holdup_kg"):
        check(col in rows[0], f"{path}: no column {col}")
    out = [float(r["out_cumulative_kg"]) for r in rows]
    check(all(b >= a_ for a_, b in zip(out, out[1:])), f"{path}: out_cumulative_kg decreases")
    print(f"{path}: {len(rows)} rows, columns {list(rows[0])}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("check", choices=["run", "figures", "xdmf", "files"])
    p.add_argument("--centrec", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--work", required=True)
    a = p.parse_args()
    {"run": do_run, "figures": do_figures, "xdmf": do_xdmf, "files": do_files}[a.check](a)
    print("PASSED")


if __name__ == "__main__":
    main()
