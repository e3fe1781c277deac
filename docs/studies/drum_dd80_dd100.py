#!/usr/bin/python3
"""The scale-down's threshold on fed drums (docs/validity_threshold.md "Rechecked on fed
drums"): the D12 receiver's drum at D/d 100 against its eqs 1-3 copy at D/d 80, both fed from
the same settled start, compared in drum turns (the scale-down keeps omega^2 R, so a turn is
the common clock).

usage (from the repository root):
  /usr/bin/python3 docs/studies/drum_dd80_dd100.py OUT.png LABEL=DEM_DIR[@TURN] [LABEL=DEM_DIR[@TURN] ...]

Each DEM_DIR is a `centrec dem` folder: its dem.h5 when the run has ended, else its
checkpoint.h5 (a run still going: the mass-flow record so far, no film yet). Prints, per
drum turn, the outflow as a share of the feed and the holdup against the start's; for ended
runs the film thickness along z (eqs 4-7, per axial section, in d) and its mean over z/L
0.5-0.8. With @TURN, the film's volume per wall area along z (in d: thickness times the
mean solid fraction, from the free particles' positions) averaged over the snapshots from
that drum turn on (the particle tracks when the run kept them, else dem.h5's snapshots): a
steady stretch of a run whose sampling began before it settled. Draws the filling (outflow /
feed and holdup / start against turns) and the film along z / L.
"""
import sys

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import yaml  # noqa: E402


def load(run):
    """Mass-flow record (t, fed, out, holdup), the drum's turn period, length, feed and d;
    the film along z when the run has ended."""
    try:
        h = h5py.File(run + "/dem.h5", "r")
        cfg = yaml.safe_load(h.attrs["resolved_config"]) if "resolved_config" in h.attrs else None
        m = h["mass_flow"]
        rec = np.column_stack([m["time"][()], m["fed"][()], m["out"][()], m["holdup"][()]])
        film = dict(z=h["film/section_z"][()], t=h["film/thickness_mean"][()])
        ended = True
    except OSError:
        h = h5py.File(run + "/checkpoint.h5", "r")
        cfg = yaml.safe_load(h.attrs["resolved_config"])
        log = h["scene/mass_flow_log"][()]
        rec = log[:, [0, 1, 2, 4]]
        film, ended = None, False
    if cfg is None:  # dem.h5 without the configuration: the summary's
        import json
        with open(run + "/summary.json") as f:
            cfg = yaml.safe_load(json.load(f)["resolved_config"])
    dem = cfg["dem"]
    period = 60.0 / dem["drum"]["speed_rpm"]
    return dict(rec=rec, period=period, L=dem["drum"]["length"], D=dem["drum"]["diameter"],
                feed=dem["feeder"]["mass_flow"], d=dem["particles"]["diameter"], film=film, ended=ended)


def volume_per_area(run, r, from_turn, sections=20):
    """The free particles' volume per wall area along z, in d, averaged over the snapshots from
    `from_turn` drum turns on: (z / L section centres, values, snapshots used)."""
    import glob
    import os
    D, L, d = r["D"], r["L"], r["d"]
    edges = np.linspace(0.0, L, sections + 1)
    vp = np.pi / 6.0 * d ** 3
    acc, used = np.zeros(sections), 0
    t0 = from_turn * r["period"]
    parts = sorted(glob.glob(os.path.join(run, "tracks", "part_*.h5")))
    if parts:  # every snapshot's free particles (r, z)
        for p in parts:
            with h5py.File(p, "r") as h:
                off, t, z = h["offset"][()].astype(int), h["time"][()], h["z"][()]
                for k in range(len(t)):
                    if t[k] >= t0:
                        acc += np.histogram(z[off[k]:off[k + 1]], edges)[0]
                        used += 1
    else:
        with h5py.File(run + "/dem.h5", "r") as h:
            for name, g in h["snapshots"].items():
                if g.attrs["time"] >= t0:
                    free = g["glued"][()] == 0
                    acc += np.histogram(g["position"][()][free, 2], edges)[0]
                    used += 1
    area = np.pi * D * np.diff(edges)
    return 0.5 * (edges[1:] + edges[:-1]) / L, acc / max(used, 1) * vp / area / d, used


def per_turn(r):
    """Outflow / feed and holdup / start over each whole turn of the record."""
    t, out, hold = r["rec"][:, 0], r["rec"][:, 2], r["rec"][:, 3]
    rows = []
    for k in range(int(t[-1] / r["period"])):
        i, j = np.searchsorted(t, k * r["period"]), np.searchsorted(t, (k + 1) * r["period"])
        j = min(j, len(t) - 1)
        rows.append((k + 1, (out[j] - out[i]) / (t[j] - t[i]) / r["feed"], hold[j] / hold[0]))
    return rows


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    runs = []
    for a in argv[2:]:
        label, rest = a.split("=", 1)
        run, _, turn = rest.partition("@")
        runs.append((label, run, float(turn) if turn else None, load(run)))
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    for n, (label, run, from_turn, r) in enumerate(runs):
        color = "C%d" % n
        rows = per_turn(r)
        print(f"{label}: turn {r['period']:.4f} s, feed {r['feed'] * 1e3:.2f} g/s, start holdup "
              f"{r['rec'][0, 3] * 1e3:.1f} g, {r['rec'][-1, 0]:.3f} s recorded ({'ended' if r['ended'] else 'running'})")
        print("  turn  out/feed  holdup/start")
        for k, f, h in rows:
            print(f"  {k:4d}  {f:8.3f}  {h:12.3f}")
        k = [x[0] for x in rows]
        ax[0].plot(k, [x[1] for x in rows], "o-", ms=3, color=color, label=label)
        ax[1].plot(k, [x[2] for x in rows], "o-", ms=3, color=color, label=label)
        if r["film"] is not None:
            zl = r["film"]["z"] / r["L"]
            td = r["film"]["t"] / r["d"]
            mid = (zl >= 0.5) & (zl <= 0.8)
            print("  thickness along z (d): " + " ".join(f"{x:.2f}" for x in td))
            print(f"  mean over z/L 0.5-0.8: {np.nanmean(td[mid]):.3f} d")
            ax[2].plot(zl, td, "o-", ms=3, color=color, label=label + ", eqs 4-7 (all sampled turns)")
        if from_turn is not None:
            zl, vpa, used = volume_per_area(run, r, from_turn)
            mid = (zl >= 0.5) & (zl <= 0.8)
            print(f"  film volume per wall area (d), {used} snapshots from turn {from_turn:g}: " +
                  " ".join(f"{x:.3f}" for x in vpa))
            print(f"  mean over z/L 0.5-0.8: {np.mean(vpa[mid]):.3f} d")
            ax[2].plot(zl, vpa, "s--", ms=3, color=color, label=f"{label}, volume per wall area (from turn {from_turn:g})")
    ax[0].axhline(1.0, color="k", lw=0.8)
    ax[0].set(xlabel="drum turns since the start", ylabel="outflow / feed", title="filling from the settled start")
    ax[1].set(xlabel="drum turns since the start", ylabel="holdup / start's")
    ax[2].set(xlabel="z / L", ylabel="d", title="film along the drum")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend()
    fig.tight_layout()
    fig.savefig(argv[1], dpi=130)
    print("wrote", argv[1])


if __name__ == "__main__":
    main(sys.argv)
