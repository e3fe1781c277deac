#!/usr/bin/python3
"""The README quotes the main job's closing lines: run the main job as the README says and
compare. Every quoted line must be the run's own line, word for word, except the DEM
cache's key (KEY in the README). Label `slow` (the main job's DEM takes about 3 minutes on 2
cores); the DEM is bitwise reproducible on the same build and thread count (2 here, as the
README's run), not across machines with another floating-point path, so a mismatch after a
change that should not move results is a finding, and after one that should, the README's
block is re-quoted from this run's output (printed below).

  /usr/bin/python3 tests/readme/check_readme_main_job.py --centrec build/centrec --source . --work /tmp/readme
"""
import argparse
import os
import re
import shutil
import subprocess
import sys


def quoted_block(readme):
    """The README's fenced block that starts with `centrec run cases/quickstart.yaml`."""
    block, inside = [], False
    for line in open(readme).read().split("\n"):
        if line.startswith("```"):
            if inside and block and block[0].strip() == "centrec run cases/quickstart.yaml":
                return block
            block, inside = [], not inside
        elif inside:
            block.append(line)
    sys.exit("README.md quotes no block starting with `centrec run cases/quickstart.yaml`")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--centrec", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--work", required=True)
    a = p.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    out = os.path.join(a.work, "quickstart")
    cmd = [a.centrec, "run", "cases/quickstart.yaml", "--out", out, "--cache", os.path.join(a.work, "dem-cache"),
           "--threads", "2", "--no-plots"]
    run = subprocess.run(cmd, cwd=a.source, capture_output=True, text=True)
    print(run.stdout)
    if run.returncode != 0:
        print(run.stderr[-3000:])
        sys.exit("the main job failed (exit %d)" % run.returncode)
    got = [re.sub(r"\(%s/dem-cache/[0-9a-f]+\)" % re.escape(a.work), "(out/dem-cache/KEY)", line)
           for line in run.stdout.split("\n")]
    got = [line.replace(out, "out/quickstart") for line in got]
    quoted = quoted_block(os.path.join(a.source, "README.md"))
    missing = [line for line in quoted if line not in got]
    for line in quoted:
        print(("  ok      " if line in got else "  DIFFERS ") + line)
    if missing:
        sys.exit("%d of the README's %d quoted lines are not the main job's output (above)" % (len(missing), len(quoted)))
    print("all %d quoted lines are the main job's own" % len(quoted))


if __name__ == "__main__":
    main()
