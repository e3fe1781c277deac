#!/usr/bin/python3
"""Chart of the thermal solver's speed vs accuracy.

Usage: /usr/bin/python3 plot_bench_thermal.py bench.csv out.png
Reads the CSV of bench_thermal_accuracy and plots |T_out - T_ref| against wall time, one
panel per operating point, one marker series per method.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    cases = sorted({r["case"] for r in rows}, reverse=True)
    fig, axes = plt.subplots(1, len(cases), figsize=(6.5 * len(cases), 5), squeeze=False)
    styles = {"2D upwind": "o-", "2D van Leer": "s-", "1D upwind": "^--", "1D van Leer": "v--",
              "2D upwind 200x40 newton-first": "x", "2D upwind 200x40 marching-only": "+"}
    for ax, case in zip(axes[0], cases):
        for method, style in styles.items():
            pts = [r for r in rows if r["case"] == case and r["method"] == method]
            if not pts:
                continue
            t = [float(r["wall_s"]) for r in pts]
            e = [max(float(r["error_K"]), 1e-6) for r in pts]
            label = method + (" (steady tol 1e-2..1e-10)" if "200x40" in method else "")
            ax.loglog(t, e, style, label=label, ms=9 if "200x40" in method else 6)
            if method.startswith("2D") and "200x40" not in method:
                for r, ti, ei in zip(pts, t, e):
                    ax.annotate(f'{r["nz"]}x{r["nxi"]}', (ti, ei), fontsize=6, alpha=0.7)
        ax.axhline(0.1, color="grey", lw=0.8, ls="--")
        ax.text(ax.get_xlim()[0], 0.11, " 0.1 K", fontsize=7, color="grey")
        ax.set_title(case.replace("_", " ") + " (CentRec film, 1 MW/m2)")
        ax.set_xlabel("wall time of a steady solve (s, one core)")
        ax.set_ylabel("|T_out - T_out,ref| (K)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
