#!/usr/bin/python3
"""How firmly the drum wall holds the film's bottom layer, from `centrec dem` outputs of
either engine (native or --engine liggghts): for every particle whose sphere touches the
cylinder (rho + r > R - 0.05 r), away from the back plate and the outlet (3 d), its slip
against the wall, v - omega x x, in every snapshot; then the mean axial-velocity profile
over the nine arcs near the wall and the film thickness along z.

usage: /usr/bin/python3 docs/studies/wall_layer_slip.py RUN_DIR [RUN_DIR ...]
"""
import sys

import h5py
import numpy as np

for run in sys.argv[1:]:
    f = h5py.File(run + "/dem.h5", "r")
    R = f.attrs["drum_radius_m"]
    d = f.attrs["particle_diameter_m"]
    om = 2 * np.pi / f.attrs["turn_period_s"]
    L = float([ln for ln in f.attrs["resolved_config"].splitlines() if ln.strip().startswith("length:")][0].split()[1])
    rows = []
    for name in sorted(f["snapshots"].keys()):
        g = f["snapshots"][name]
        x, v, r = g["position"][()], g["velocity"][()], g["radius"][()]
        rho = np.hypot(x[:, 0], x[:, 1])
        touch = (rho + r > R - 0.05 * r) & (x[:, 2] > 3 * d) & (x[:, 2] < L - 3 * d)
        slip = v - np.stack([-om * x[:, 1], om * x[:, 0], 0 * x[:, 0]], 1)
        if not touch.any():
            continue
        th = np.arctan2(x[:, 1], x[:, 0])
        s_th = -np.sin(th) * slip[:, 0] + np.cos(th) * slip[:, 1]
        rows.append((touch.sum(), np.mean(np.abs(s_th[touch])), np.mean(slip[touch, 2]), np.mean(np.abs(slip[touch, 2])),
                     np.percentile(np.linalg.norm(slip[touch], axis=1), 90)))
    if not rows:
        print(f"{run}: no free particle touches the cylinder (a glued layer covers it)")
        continue
    a = np.array(rows).mean(0)
    print(f"{run}: {a[0]:.0f} particles on the wall per snapshot; slip |azimuthal| {a[1] * 1e3:.2f} mm/s, "
          f"axial mean {a[2] * 1e3:.2f} mm/s, |axial| {a[3] * 1e3:.2f} mm/s, 90th percentile |slip| {a[4] * 1e3:.2f} mm/s "
          f"(omega R = {om * R:.3f} m/s)")
    wd = f["film/wall_distance_d"][()]
    vm = np.nanmean(f["film/axial_velocity_mean"][()], 0)
    print("  axial velocity, mean of the nine arcs, m/s, at wall distance " +
          ", ".join(f"{w:.2f} d: {u:.4f}" for w, u in zip(wd[:6], vm[:6])))
    print("  thickness along z [d]: " + " ".join(f"{t:.2f}" for t in f["film/thickness_mean"][()] / d))
