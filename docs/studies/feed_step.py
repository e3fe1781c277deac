#!/usr/bin/python3
"""The fed drum's response to a step in its feed (docs/operating.md "The film's response
time"): a settled drum whose feed changes at t = 0 (cases/drum_dd80/feed_step_down.yaml).

usage (from the repository root):
  /usr/bin/python3 docs/studies/feed_step.py RUN_DIR OLD_FEED_KG_S [OUT.png]

RUN_DIR is the step's `centrec dem` folder (its dem.h5 when ended, else its checkpoint.h5: the
record so far). The holdup H(t) is fitted by a first-order lag with dead time of the outflow,
out(t) = new + (old - new) g(t), g = 1 before the dead time theta and exp(-(t - theta)/tau)
after, which makes dH/dt = new - out(t):

    H(t) = H0 - (old - new) [min(t, theta) + tau (1 - exp(-max(t - theta, 0) / tau))]

The holdup is the integral of the flows, so it is fitted rather than the outflow, whose
one-turn scatter is +-10 %. Prints theta, tau, the 63 % time theta + tau (the response time),
the holdup the step moved (its steady change (old - new)(theta + tau)), the same against the
mean residence time before the step, and the outflow's 63 % crossing read directly from the
one-turn smoothed outflow as a check; the fit again without the first half second (the
drum's own swing at the step) as its uncertainty; draws both.
"""
import sys

import h5py
import numpy as np
import yaml


def record(run):
    for name in ("dem.h5", "checkpoint.h5"):
        try:
            h = h5py.File(f"{run}/{name}", "r")
        except OSError:
            continue
        cfg = yaml.safe_load(h.attrs["resolved_config"])
        if "mass_flow" in h:
            m = h["mass_flow"]
            return cfg, m["time"][()], m["fed"][()], m["out"][()], m["holdup"][()]
        log = h["scene/mass_flow_log"][()]  # a checkpoint: time fed out lost holdup particles axial_flow
        return cfg, log[:, 0], log[:, 1], log[:, 2], log[:, 4]
    sys.exit(f"{run}: neither dem.h5 nor checkpoint.h5")


def model(t, H0, dm, theta, tau):
    lagged = np.maximum(t - theta, 0.0)
    return H0 - dm * (np.minimum(t, theta) + tau * (1.0 - np.exp(-lagged / tau)))


def fit(t, H, dm):
    """Least squares over (theta, tau) on a grid refined twice, H0 free (linear)."""
    best = None
    th_lo, th_hi, ta_lo, ta_hi = 0.0, min(t[-1], 20.0), 0.05, 30.0
    for _ in range(3):
        for theta in np.linspace(th_lo, th_hi, 61):
            for tau in np.geomspace(ta_lo, ta_hi, 61):
                shape = model(t, 0.0, dm, theta, tau)
                H0 = np.mean(H - shape)
                r = np.sqrt(np.mean((H - H0 - shape) ** 2))
                if best is None or r < best[0]:
                    best = (r, H0, theta, tau)
        _, _, th, ta = best
        span = (th_hi - th_lo) / 10
        th_lo, th_hi = max(0.0, th - span), th + span
        ta_lo, ta_hi = ta / 1.5, ta * 1.5
    return best


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    run, old = sys.argv[1], float(sys.argv[2])
    cfg, t, fed, out, H = record(run)
    new = cfg["dem"]["feeder"]["mass_flow"]
    dm = old - new
    turn = 60.0 / cfg["dem"]["drum"]["speed_rpm"]
    r, H0, theta, tau = fit(t, H, dm)
    print(f"{run}: feed {old * 1e3:.3f} -> {new * 1e3:.3f} g/s at t = 0, {t[-1]:.3f} s recorded ({t[-1] / turn:.1f} turns)")
    print(f"  holdup {H[0] * 1e3:.1f} g at the step, {H[-1] * 1e3:.1f} g at the end")
    print(f"  first-order lag with dead time fitted to the holdup: theta {theta:.3f} s, tau {tau:.3f} s, "
          f"response (63 %) theta + tau = {theta + tau:.3f} s = {(theta + tau) / turn:.2f} turns; rms {r * 1e3:.3f} g")
    # The same fit without the first half second (the settled drum's own outflow swing at the
    # step, +-10 % per turn, is in it): the difference is the fit's uncertainty.
    late = t >= 0.5
    r2, _, theta2, tau2 = fit(t[late], H[late], dm)
    print(f"  fitted from t = 0.5 s: theta {theta2:.3f} s, tau {tau2:.3f} s, response {theta2 + tau2:.3f} s; rms {r2 * 1e3:.3f} g")
    res_before = H[0] / old
    print(f"  mean residence before the step (holdup / feed) {res_before:.3f} s: response = {(theta + tau) / res_before:.3f} of it")
    print(f"  steady holdup change the fit implies {-dm * (theta + tau) * 1e3:.2f} g "
          f"({-dm * (theta + tau) / H[0] * 100:.1f} % for a {-dm / old * 100:.1f} % feed change: "
          f"d ln H / d ln m = {(dm * (theta + tau) / H[0]) / (dm / old):.3f})")
    n = max(1, int(round(turn / np.median(np.diff(t)))))
    rate = (out[n:] - out[:-n]) / (t[n:] - t[:-n])
    tm = 0.5 * (t[n:] + t[:-n])
    target = old - 0.632 * dm
    cross = tm[np.argmax(rate <= target)] if np.any(rate <= target) else float("nan")
    print(f"  one-turn outflow first at 63 % of its change ({target * 1e3:.2f} g/s) at t = {cross:.3f} s (a check; scatter +-10 %)")
    if len(sys.argv) > 3:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4))
        ax[0].plot(t, H * 1e3, label="DEM")
        ax[0].plot(t, model(t, H0, dm, theta, tau) * 1e3, "--", label=f"fit: theta {theta:.2f} s, tau {tau:.2f} s")
        ax[0].set_xlabel("t since the step (s)")
        ax[0].set_ylabel("holdup (g)")
        ax[0].legend()
        ax[1].plot(tm, rate * 1e3, lw=0.8, label="outflow, one-turn mean")
        g = np.where(tm < theta, 1.0, np.exp(-np.maximum(tm - theta, 0) / tau))
        ax[1].plot(tm, (new + dm * g) * 1e3, "--", label="fit")
        ax[1].axhline(new * 1e3, color="k", lw=0.8, label="new feed")
        ax[1].set_xlabel("t since the step (s)")
        ax[1].set_ylabel("g/s")
        ax[1].legend()
        for a in ax:
            a.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(sys.argv[3], dpi=110)
        print("wrote", sys.argv[3])


if __name__ == "__main__":
    main()
