#!/usr/bin/env python3
"""Receiver efficiency and outlet temperature over the aperture flux and the mass flow,
cavity model against the open-surface model (docs/cavity_model.md).

Runs `centrec thermal` on an analytic CentRec film (1.0 m drum, 1.0 m long, 6 mm film of
1.2 mm bauxite, inlet 600 C) for aperture fluxes 0.3-1.2 MW/m2 through a 0.7 m aperture
(the same power spread uniformly over the film for the open-surface model) and three mass
flows; writes docs/cavity_chart.csv and docs/cavity_chart.png.

Usage: /usr/bin/python3 docs/cavity_chart.py [build/centrec]
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
BINARY = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "build", "centrec")
DRUM, LENGTH, APERTURE = 1.0, 1.0, 0.7  # m
FLUXES = [0.3e6, 0.45e6, 0.6e6, 0.75e6, 0.9e6, 1.05e6, 1.2e6]  # W/m2 at the aperture
U_SURFACE = {0.04: "low flow", 0.065: "nominal flow", 0.1: "high flow"}  # m/s -> mdot
MODELS = {
    "cavity": "  radiation: {model: cavity, aperture_diameter: %g, tilt_deg: 45}\n" % APERTURE,
    "open F=1": "  radiation: {model: open_surface}\n  surface: {loss_factor: 1.0, h_conv: 10}\n",
    "open F=0.3": "  radiation: {model: open_surface}\n  surface: {loss_factor: 0.3, h_conv: 10}\n",
}


def case_text(q_aperture, u, model):
    q_film = q_aperture * math.pi * APERTURE**2 / 4 / (math.pi * DRUM * LENGTH)
    absorption = "" if model == "cavity" else ", absorption: surface"
    return (
        "title: cavity chart\n"
        "film:\n  analytic: {thickness: 6.0e-3, u_surface: %g, phi: 0.55, D_shear_coeff: 0.05, "
        "drum_diameter: %g, length: %g}\n"
        "thermal:\n  model: 2d\n  grid: {nz: 200, nxi: 40}\n  T_in: 873.15\n"
        "  flux: {profile: uniform, q_film: %.6g%s}\n%s  wall: {U_w: 1.0}\n"
        % (u, DRUM, LENGTH, q_film, absorption, MODELS[model])
    )


def run(q, u, model, tmp):
    path = os.path.join(tmp, "case.yaml")
    with open(path, "w") as f:
        f.write(case_text(q, u, model))
    out = os.path.join(tmp, "out")
    subprocess.run([BINARY, "thermal", path, "--out", out], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    r = s["receiver"]
    return {
        "model": model, "q_aperture_W_m2": q, "u_surface_m_s": u, "mdot_kg_s": s["mass_flow_kg_s"],
        "T_out_C": s["T_out_C"], "efficiency": r["efficiency"], "aperture_power_W": r["aperture_power_W"],
        "reflected_loss_W": r["reflected_loss_W"], "emitted_loss_W": r["emitted_loss_W"],
        "convective_loss_W": r["convective_loss_W"], "wall_loss_W": r["wall_loss_W"],
        "steady_wall_time_s": s["solver"]["steady"]["wall_time_s"],
    }


def main():
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for model in MODELS:
            for u in U_SURFACE:
                for q in FLUXES:
                    rows.append(run(q, u, model, tmp))
    with open(os.path.join(HERE, "cavity_chart.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.8))
    styles = {"cavity": "-", "open F=1": ":", "open F=0.3": "--"}
    colors = dict(zip(U_SURFACE, ["tab:red", "tab:blue", "tab:green"]))
    for model in MODELS:
        for u, label in U_SURFACE.items():
            sel = [r for r in rows if r["model"] == model and r["u_surface_m_s"] == u]
            x = [r["q_aperture_W_m2"] / 1e6 for r in sel]
            lab = "%s, %s (%.2f kg/s)" % (model, label, sel[0]["mdot_kg_s"])
            a1.plot(x, [100 * r["efficiency"] for r in sel], styles[model], color=colors[u], marker="o", ms=3, label=lab)
            a2.plot(x, [r["T_out_C"] for r in sel], styles[model], color=colors[u], marker="o", ms=3, label=lab)
    a1.plot([1.0], [85.0], "k*", ms=14, label="CentRec lab model: >85 % at 900 C, 1 MW/m2 (Wu 2014)")
    a2.plot([1.0], [900.0], "k*", ms=14, label="900 C at 1 MW/m2 (Wu 2014)")
    a1.set_xlabel("aperture flux, MW/m2")
    a1.set_ylabel("receiver efficiency = carried / aperture power, %")
    a2.set_xlabel("aperture flux, MW/m2")
    a2.set_ylabel("outlet temperature, C")
    a1.set_title("1.0 m drum, 1.0 m long, 0.7 m aperture, inlet 600 C")
    a2.set_title("cavity (solid) vs open surface F = 1 (dotted), F = 0.3 (dashed)")
    for a in (a1, a2):
        a.grid(alpha=0.3)
    a1.legend(fontsize=6.5, loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "cavity_chart.png"), dpi=120)
    print("wrote docs/cavity_chart.csv and docs/cavity_chart.png (%d runs)" % len(rows))


if __name__ == "__main__":
    main()
