#!/usr/bin/python3
"""The retention study: which retention setting reproduces the paper's film.

usage (from the repository root, after ./setup.sh):
  /usr/bin/python3 docs/studies/retention/retention_study.py [--jobs 2] [--only NAME,...]
        [--cases-only] [--analyse-only] [--out out/retention] [--docs docs/retention]

Writes cases/retention/<setting>.yaml (one drum scaled from D12 to D/d = 25 by eqs 1-3,
pre-filled with the paper's scaled holdup), runs each with `centrec dem --threads 1`,
--jobs at a time (a finished run of the same case text is reused), then
measures every run (docs/studies/retention/retention_metrics.py) and writes
docs/retention/results.{md,json} and the charts (docs/studies/retention/retention_charts.py).
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import retention_cases as rc  # noqa: E402


def run_case(centrec, case, out):
    """Runs one case unless OUT holds a finished run of the same case text (OUT/case.yaml)."""
    text = open(case).read()
    copy = os.path.join(out, "case.yaml")
    if os.path.exists(os.path.join(out, "summary.json")) and (not os.path.exists(copy) or open(copy).read() == text):
        return f"{case}: reusing {out}"
    os.makedirs(out, exist_ok=True)
    t0 = time.time()
    with open(os.path.join(out, "run.log"), "w") as log:
        subprocess.run([centrec, "dem", case, "--out", out, "--threads", "1"], check=True, stdout=log,
                       stderr=subprocess.STDOUT)
    with open(copy, "w") as f:
        f.write(text)
    return f"{case}: {time.time() - t0:.0f} s"


def write_cases(drum, case_dir, settings):
    os.makedirs(case_dir, exist_ok=True)
    paths = {}
    for name, _group, label, overrides in settings:
        dem = rc.setting_dem(drum, overrides)
        comment = (f"Retention study (docs/studies/retention/retention_study.py writes this file): {label}.\n"
                   f"D12 scaled to D/d = {rc.D_OVER_D} by eqs 1-3; pre-filled so free + glued particles hold the\n"
                   f"paper's film ({drum['thickness_d']:.2f} d at f_s 0.5 = {drum['particles']:.0f} particles here), "
                   f"settled {rc.SETTLE_S} s,\nthen {rc.SAMPLE_TURNS} turns sampled. "
                   "A few minutes on one core.")
        path = os.path.join(case_dir, f"{name}.yaml")
        text = rc.case_yaml(f"retention_{name}", comment, dem)
        if not os.path.exists(path) or open(path).read() != text:
            with open(path, "w") as f:
                f.write(text)
        paths[name] = path
    return paths


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--centrec", default="build/centrec")
    ap.add_argument("--cases", default="cases/retention")
    ap.add_argument("--out", default="out/retention")
    ap.add_argument("--docs", default="docs/retention")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default="", help="comma-separated setting names")
    ap.add_argument("--cases-only", action="store_true", help="write the case files and stop")
    ap.add_argument("--analyse-only", action="store_true", help="measure existing runs, run nothing")
    a = ap.parse_args()

    drum = rc.scaled_drum(a.centrec)
    only = set(filter(None, a.only.split(",")))
    settings = [s for s in rc.SETTINGS if not only or s[0] in only]
    paths = write_cases(drum, a.cases, settings)
    print(f"study drum: D = {drum['diameter']} m, L = {drum['length']} m, {drum['speed_rpm']} rpm, "
          f"{drum['mdot'] * 1e3:.3f} g/s; paper's film {drum['thickness_d']:.2f} d = {drum['particles']:.0f} "
          f"particles (naive (D/d)^2 scaling: {drum['naive_particles']:.0f})")
    if a.cases_only:
        return
    if not a.analyse_only:
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
            jobs = [pool.submit(run_case, a.centrec, paths[n], os.path.join(a.out, n)) for n, *_ in settings]
            for j in concurrent.futures.as_completed(jobs):
                print(j.result(), flush=True)

    import retention_charts
    import retention_metrics
    rows = []
    for name, group, label, overrides in settings:
        out = os.path.join(a.out, name)
        if not os.path.exists(os.path.join(out, "dem.h5")):
            print(f"{name}: no run in {out}, skipped")
            continue
        dem = rc.setting_dem(drum, overrides)
        m = retention_metrics.measure(out, drum, dem)
        m.update({"name": name, "group": group, "label": label})
        rows.append(m)
    os.makedirs(a.docs, exist_ok=True)
    with open(os.path.join(a.docs, "results.json"), "w") as f:
        json.dump({"drum": drum, "settings": rows}, f, indent=1)
    table = retention_metrics.markdown_table(rows, drum)
    with open(os.path.join(a.docs, "results.md"), "w") as f:
        f.write(table)
    print(table)
    retention_charts.draw_all(rows, drum, a.docs)


if __name__ == "__main__":
    main()
