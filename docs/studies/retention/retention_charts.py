"""Charts of the retention study, PNGs under docs/retention/:

  holdup_vs_setting.png   held particles / paper's scaled holdup, per setting, with the +-10 % band
  thickness_along_z.png   eqs 4-7 thickness along z/L per setting against the paper's Fig 3 shape
  velocity_profiles.png   u(eta) at the nine arcs for the closest settings, with the line from 1 d
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from retention_metrics import NO_FILM_RATIO  # noqa: E402

GROUP_COLOURS = {"lip": "tab:blue", "rough": "tab:green", "spread": "tab:orange", "rolling": "tab:purple",
                 "combined": "tab:red"}


def closeness(r):
    """Distance from the paper's film, for ranking: holdup error (in units of the 10 % bar),
    flatness (units of 0.2 d), standing layer above 1 d (units of 0.5 d), no exit thinning."""
    if r["holdup_ratio"] < NO_FILM_RATIO:
        return float("inf")
    return (abs(r["holdup_ratio"] - 1.0) / 0.1 + r["flatness_d"] / 0.2
            + max(0.0, r["standing_height_max_d"] - 1.0) / 0.5 + (r["exit_drop_d"] <= 0.0))


def draw_holdup(rows, path):
    fig, ax = plt.subplots(figsize=(7, 0.35 * len(rows) + 1.5))
    y = np.arange(len(rows))
    ax.barh(y, [r["holdup_ratio"] for r in rows], color=[GROUP_COLOURS[r["group"]] for r in rows])
    for k, r in enumerate(rows):
        ax.text(r["holdup_ratio"] + 0.01, k, f"{r['holdup_ratio']:.2f} ({100 * r['holdup_drift_per_s']:+.0f} %/s)",
                va="center", fontsize=7)
    ax.axvspan(0.9, 1.1, color="grey", alpha=0.2, label="paper +-10 %")
    ax.axvline(1.0, color="k", lw=1)
    ax.set_yticks(y, [r["label"] for r in rows], fontsize=8)
    ax.invert_yaxis()
    ax.set_xlim(0, max(1.3, max(r["holdup_ratio"] for r in rows) + 0.3))
    ax.set_xlabel("held (free + glued) / paper's scaled holdup  (holdup drift, %/s)")
    ax.set_title("Retention study, D12 scaled to D/d = 25: holdup by setting")
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def paper_shape(ax, drum):
    """The paper's Fig 3 as the issue states it: flat within +-0.2 d over z/L 0.2-0.8 at the
    thickness its holdup implies, thinner at the exit (the figure's values are not in the
    text, so the level is the holdup's and the exit drop is only a direction)."""
    t = drum["thickness_d"]
    ax.fill_between([0.2, 0.8], t - 0.2, t + 0.2, color="grey", alpha=0.25,
                    label=f"paper Fig 3 shape: flat {t:.2f} +- 0.2 d")
    ax.annotate("", xy=(0.97, t - 0.6), xytext=(0.85, t), arrowprops={"arrowstyle": "->", "color": "grey"})
    ax.text(0.83, t - 0.9, "thinner at exit", color="grey", fontsize=7)


def draw_thickness(rows, drum, path):
    groups = [g for g in GROUP_COLOURS if any(r["group"] == g for r in rows)]
    fig, axes = plt.subplots(1, len(groups), figsize=(4 * len(groups), 3.6), sharey=True, squeeze=False)
    for ax, g in zip(axes[0], groups):
        paper_shape(ax, drum)
        for r in rows:
            if r["holdup_ratio"] < NO_FILM_RATIO:
                continue  # no film: eqs 4-7 would average a trickle
            if r["group"] == g or (g in ("spread", "rolling", "combined") and r["name"] in ("rough_sq1.0", "lip3")):
                ax.errorbar(r["z_over_length"], r["thickness_d"], yerr=r["thickness_std_d"], marker="o", ms=3,
                            capsize=2, lw=1, label=r["label"])
        ax.set_xlabel("z / L  (0 inlet, 1 outlet)")
        ax.set_ylim(0, 7)  # the feeder's region near z = 0 reads higher: not film
        ax.set_title(g)
        ax.legend(fontsize=6)
    axes[0][0].set_ylabel("eqs 4-7 film thickness [d]")
    fig.suptitle("Film thickness along the drum, mean +- std over the sampled turns (cf. paper Fig 3)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def draw_profiles(rows, path, count=4):
    """The closest settings and the closest lip, against the paper's line from 1 d."""
    ranked = sorted(rows, key=closeness)
    best_lip = next((r for r in ranked if r["group"] == "lip"), None)
    best = ranked[: count - 1] + ([best_lip] if best_lip and best_lip not in ranked[: count - 1] else ranked[count - 1:count])
    n = len(best[0]["arcs"])
    fig, axes = plt.subplots(3, (n + 2) // 3, figsize=(11, 9), squeeze=False, sharex=True)
    for k in range(n):
        ax = axes[k % 3][k // 3]
        for i, r in enumerate(best):
            a = r["arcs"][k]
            w = np.array(r["wall_distance_d"])
            u = np.array(a["u"])
            pop = np.array(a["turns"]) > 0
            ax.errorbar(w[pop], u[pop], yerr=np.array(a["u_std"])[pop], marker="o", ms=2.5, lw=1, capsize=1.5,
                        color=f"C{i}", label=r["label"])
            if np.isfinite(a["line_slope"]):
                x = np.array([1.0, a["thickness_d"] + 0.5])
                ax.plot(x, a["line_slope"] * (x - 1.0), color=f"C{i}", ls="--", lw=0.8)
        ax.axvline(1.0, color="grey", lw=0.5)
        ax.set_title(f"theta {best[0]['arcs'][k]['theta_deg']:.0f} deg, z/L {best[0]['arcs'][k]['z_over_length']:.1f}",
                     fontsize=9)
        if k % 3 == 2:
            ax.set_xlabel("wall distance of centres [d]")
        if k < 3:
            ax.set_ylabel("axial velocity [m/s]")
    axes[0][0].legend(fontsize=7)
    fig.suptitle("Axial velocity profiles (cf. paper Fig 6); dashed: the paper's line, 0 below 1 d, linear to the "
                 "surface (least squares)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def draw_all(rows, drum, docs):
    if not rows:
        return
    draw_holdup(rows, os.path.join(docs, "holdup_vs_setting.png"))
    draw_thickness(rows, drum, os.path.join(docs, "thickness_along_z.png"))
    draw_profiles(rows, os.path.join(docs, "velocity_profiles.png"))
    ranked = sorted(rows, key=closeness)
    print("closest to the paper's film: " + ", ".join(f"{r['name']} ({closeness(r):.1f})" for r in ranked))
