#!/usr/bin/python3
"""Engine scaling: one case on centrec at 1 and 2 threads and on
LIGGGHTS 3.8 at 1 and 2 ranks, back to back in one run, so all four see the same machine
load. Prints and writes a Markdown table (wall time, particle-steps/s, LIGGGHTS' own loop
time) and the machine load average before and after each run.

usage: /usr/bin/python3 apps/bench/engine_scaling.py [--centrec build/centrec]
       [--case apps/bench/scaling_quickstart.yaml] [--out scaling-out] [--table FILE.md]
"""
import argparse
import json
import os
import re
import subprocess
import time

ap = argparse.ArgumentParser()
ap.add_argument("--centrec", default="build/centrec")
ap.add_argument("--case", default="apps/bench/scaling_quickstart.yaml")
ap.add_argument("--out", default="scaling-out")
ap.add_argument("--table", default="")
a = ap.parse_args()

runs = [("centrec", 1), ("centrec", 2), ("liggghts", 1), ("liggghts", 2)]
rows = []
for engine, n in runs:
    out = os.path.join(a.out, f"{engine}_{n}")
    cmd = [a.centrec, "dem", a.case, "--out", out]
    cmd += ["--threads", str(n)] if engine == "centrec" else ["--engine", "liggghts", "--ranks", str(n)]
    load0 = os.getloadavg()[0]
    t0 = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.time() - t0
    s = json.load(open(os.path.join(out, "summary.json")))
    loop = ""
    if engine == "liggghts":
        log = open(os.path.join(out, "liggghts", "log.liggghts")).read()
        loop = "%.1f" % sum(float(x) for x in re.findall(r"^Loop time of ([0-9.eE+-]+)", log, re.M))
    rows.append((engine, n, s["steps"], s["free_particles"] + s["glued_particles"], wall, s["wall_time_s"],
                 s["particle_steps_per_s"], loop, load0, os.getloadavg()[0]))
    print(rows[-1], flush=True)

head = ("| engine | threads/ranks | steps | particles at end | process wall s | run wall s | particle-steps/s "
        "| speed-up vs 1 | LIGGGHTS loop s | load avg before/after |\n|---|---|---|---|---|---|---|---|---|---|\n")
lines = []
for r in rows:
    base = next(x for x in rows if x[0] == r[0] and x[1] == 1)
    lines.append("| %s | %d | %d | %d | %.1f | %.1f | %.3g | %.2f | %s | %.2f / %.2f |" %
                 (r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[6] / base[6], r[7] or "-", r[8], r[9]))
table = head + "\n".join(lines) + "\n"
print(table)
if a.table:
    with open(a.table, "w") as f:
        f.write("# Engine scaling: %s\n\n%s UTC, %d hardware threads, `%s`.\n\n" %
                (a.case, time.strftime("%Y-%m-%d %H:%M", time.gmtime()), os.cpu_count(), " ".join(
                    ["engine_scaling.py"] + [f"--case {a.case}"])) + table)
