"""The 59-62 rpm lock of receiver_1m's slice (docs/operating.md, "The 59-62 rpm verdict").

From a slice's dem.h5 (either engine), with the particle snapshots:
  flow     m sum(v_z) / L over the free particles per snapshot (mean, halves, coefficient of
           variation), the native record over the same window when it has one, the film's depth
  sectors  per 30 deg around the drum in the lab frame (0 = bottom, 180 = top, where gravity
           lightens the load): share of the holdup and of the axial flow

  /usr/bin/python3 docs/studies/slice_lock.py table runs/lock/native_59/dem.h5 ...
  /usr/bin/python3 docs/studies/slice_lock.py figure docs/operating/lock_59rpm.png "label|dem.h5|style" ...
     (labels with "held" also go to the flow-against-time panel)
"""
import sys

import h5py
import numpy as np
import yaml


def read(path):
    """Per snapshot: time, slice flow (kg/s); summed over snapshots: flow and holdup per sector."""
    f = h5py.File(path, "r")
    cfg = yaml.safe_load(f.attrs["resolved_config"])
    d = f.attrs["particle_diameter_m"]
    R = f.attrs["drum_radius_m"]
    L = cfg["dem"]["slice"]["length_d"] * d
    m = cfg["dem"]["particles"]["density"] * np.pi * d**3 / 6
    names = sorted(f["snapshots"], key=lambda s: float(s[1:]))
    t, q, depth = [], [], []
    hold, flow = np.zeros(12), np.zeros(12)
    for s in names:
        g = f["snapshots"][s]
        free = g["glued"][()] == 0
        x, v = g["position"][()][free], g["velocity"][()][free]
        ang = (np.degrees(np.arctan2(x[:, 0], -x[:, 1])) + 360) % 360
        k = (ang // 30).astype(int)
        hold += np.bincount(k, minlength=12)
        flow += np.bincount(k, weights=v[:, 2], minlength=12)
        t.append(float(s[1:]))
        q.append(m * v[:, 2].sum() / L)
        depth.append((R - np.hypot(x[:, 0], x[:, 1])) / d)
    mf = f["mass_flow"]
    tm, rec = mf["time"][()], mf["slice_axial_flow"][()]
    w = (tm >= t[0]) & (tm <= t[-1])
    return dict(cfg=cfg, engine=f.attrs.get("engine", "centrec"), free=int(free.sum()), t=np.array(t),
                q=np.array(q), record=rec[w].mean(), depth=np.concatenate(depth), hold=hold, flow=flow)


def table(paths):
    for p in paths:
        r = read(p)
        q = r["q"] * 1e3
        h = len(q) // 2
        print(f"{p} ({r['engine']}, {r['free']} free): flow {q.mean():.2f} g/s (halves {q[:h].mean():.2f}, "
              f"{q[h:].mean():.2f}; CV {q.std() / q.mean():.2f}), record {r['record'] * 1e3:.2f} g/s; depth 50/99 % "
              f"{np.percentile(r['depth'], 50):.2f}/{np.percentile(r['depth'], 99):.2f} d, beyond 8 d "
              f"{100 * np.mean(r['depth'] > 8):.1f} %")
        print("  sector deg " + " ".join(f"{30 * i:>5d}" for i in range(12)))
        print("  holdup %   " + " ".join(f"{100 * x / r['hold'].sum():5.1f}" for x in r["hold"]))
        print("  flow %     " + " ".join(f"{100 * x / r['flow'].sum():5.1f}" for x in r["flow"]))


def figure(out, specs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for label, path, style in (s.split("|") for s in specs):
        r = read(path)
        ax[0].plot(np.arange(12) * 30 + 15, 100 * r["flow"] / r["flow"].sum(), style,
                   label=f"{label}: {r['q'].mean() * 1e3:.1f} g/s")
        if "held" in label:
            ax[1].plot(r["t"] - r["t"][0], r["q"] * 1e3, style, label=label)
    ax[0].set_xlabel("angle from the bottom of the drum (deg; 180 = top)")
    ax[0].set_ylabel("share of the axial flow per 30 deg (%)")
    ax[0].set_xticks(range(0, 361, 60))
    ax[0].legend(fontsize=7)
    ax[0].grid(alpha=0.3)
    ax[1].axhline(28.56, color="k", lw=0.8, ls=":")
    ax[1].text(0.02, 29.5, "target 28.56 g/s", fontsize=7)
    ax[1].set_xlabel("time in the sampled window (s)")
    ax[1].set_ylabel("slice axial flow (g/s), per snapshot")
    ax[1].legend(fontsize=7)
    ax[1].grid(alpha=0.3)
    fig.suptitle("receiver_1m slice at D/d 80: where the film flows, and what it carries with its holdup held",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("table", "figure"):
        sys.exit(__doc__)
    table(sys.argv[2:]) if sys.argv[1] == "table" else figure(sys.argv[2], sys.argv[3:])
