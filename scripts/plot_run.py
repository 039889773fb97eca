#!/usr/bin/python3
"""PNG figures of one run, like paper 000's Figures 9-13.

  scripts/plot_run.py --group 1                 # runs the SystemC bench, then plots
  scripts/plot_run.py --group 1 --closed-loop   # also runs scurve sim --closed-loop for the
                                                # neuron weights and the closed-loop error
  scripts/plot_run.py --trace run.rtl.csv       # plots an existing kinematics trace
        [--weights weights.csv] [--out-dir DIR] [--require-phases rising,steady,falling,zero]

Figures (in --out-dir, default build/plots/<name>/):
  pulses.png        STEP pulse train with the phases shaded, duty cycle per pulse,
                    and a zoom into each phase (the paper's "PWM", Figure 9)
  velocity.png, acceleration.png, jerk.png   reference kinematics (Figures 10-12)
  error.png         tracking error: reference - stepper position from the STEP
                    pulses (open loop); with a weights CSV that has e_p (scurve sim
                    --closed-loop --weights-csv) also the closed-loop error P* - P
  weights.png       neuron weights w_* and normalised weights wn_* (closed loop),
                    when --weights names such a CSV
Uses Debian's python3-matplotlib (hence /usr/bin/python3).
"""
import argparse
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TREND = {1: "rising", 2: "rising", 3: "rising", 4: "steady", 5: "falling", 6: "falling", 7: "falling", 8: "zero"}
COLOUR = {"rising": "#cde8cd", "steady": "#cdd9f0", "falling": "#f4d6cc", "zero": "#e6e6e6"}


def read_trace(path):
    meta = {}
    rows = []
    with open(path) as f:
        header = None
        for line in f:
            if line.startswith("#"):
                for kv in line[1:].split():
                    if "=" in kv:
                        k, v = kv.split("=", 1)
                        meta[k] = v
                continue
            if header is None:
                header = line.strip().split(",")
                continue
            rows.append(line.strip().split(","))
    if header is None:
        sys.exit(f"{path}: no header line (not a kinematics trace)")
    cols = {name: [int(r[i]) for r in rows] for i, name in enumerate(header)}
    return meta, cols


def phase_runs(t, phase):
    """[(trend, t_start, t_end)] with repeats merged; idle rows skipped."""
    runs = []
    for i, p in enumerate(phase):
        trend = TREND.get(p)
        if trend is None:
            continue
        t_end = t[i + 1] if i + 1 < len(t) else t[i]
        if runs and runs[-1][0] == trend:
            runs[-1][2] = t_end
        else:
            runs.append([trend, t[i], t_end])
    return runs


def shade(ax, runs):
    for trend, a, b in runs:
        ax.axvspan(a, b, color=COLOUR[trend], zorder=0)


def legend_patches(ax, runs):
    import matplotlib.patches as mpatches

    seen = []
    for trend, _, _ in runs:
        if trend not in seen:
            seen.append(trend)
    ax.legend(handles=[mpatches.Patch(color=COLOUR[s], label=s) for s in seen], loc="upper right", fontsize=8)


def run_bench(args, trace):
    bench = os.path.join(args.build_dir, "bin", "sc_bench")
    if not os.access(bench, os.X_OK):
        sys.exit(f"{bench} not found: build first (cmake -S . -B build && cmake --build build -j2)")
    cmd = [bench, "--group", str(args.group), "--trace-rtl", trace, "--trace-decimate", str(args.decimate)]
    print(" ".join(cmd), flush=True)
    env = dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1")
    if subprocess.call(cmd, env=env) != 0:
        sys.exit("the bench run failed its checks")


def run_closed_loop(args, weights):
    scurve = os.path.join(args.build_dir, "bin", "scurve")
    cmd = [scurve, "sim", "--closed-loop", "--group", str(args.group), "--weights-csv", weights]
    print(" ".join(cmd), flush=True)
    if subprocess.call(cmd, stdout=subprocess.DEVNULL) != 0:
        sys.exit("the closed-loop run failed its checks")


def read_weights(path):
    with open(path) as f:
        rdr = csv.reader(line for line in f if not line.startswith("#"))
        head = next(rdr)
        data = [list(map(float, r)) for r in rdr if r]
    return head, data


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--group", type=int, choices=[1, 2, 3, 4], help="run paper group N through sc_bench first")
    src.add_argument("--trace", help="kinematics trace CSV (sc_bench --trace-rtl/--trace-model)")
    ap.add_argument("--weights", help="neuron weight trajectories CSV (closed loop), optional")
    ap.add_argument("--closed-loop", action="store_true",
                    help="with --group: also run the group in closed loop for the weights and its error")
    ap.add_argument("--out-dir", help="where the PNGs go (default build/plots/<name>)")
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build"), help="build with bin/sc_bench")
    ap.add_argument("--decimate", type=int, default=20000, help="reference sample period, clocks (with --group)")
    ap.add_argument("--require-phases", help="comma list: fail unless the duty phases appear in this order")
    args = ap.parse_args()

    name = f"group{args.group}" if args.group else os.path.splitext(os.path.basename(args.trace))[0]
    out = args.out_dir or os.path.join(ROOT, "build", "plots", name)
    os.makedirs(out, exist_ok=True)
    trace = args.trace
    if args.group:
        trace = os.path.join(out, f"{name}.rtl.csv")
        run_bench(args, trace)
        if args.closed_loop:
            args.weights = os.path.join(out, f"{name}.weights.csv")
            run_closed_loop(args, args.weights)
    weights = read_weights(args.weights) if args.weights else None
    closed = bool(weights and "e_p" in weights[0])  # the closed loop's position error is in the CSV

    meta, c = read_trace(trace)
    clk_hz = float(meta.get("clk_hz", 20e6))
    one = float(2 ** int(meta.get("frac_bits", 80)))
    t = [k / clk_hz for k in c["clock"]]
    runs = phase_runs(t, c["phase"])
    order = [r[0] for r in runs]
    # The bench's quiet tail after done is short (~0.1 ms); nothing moves in
    # it (checked by the bench), so the zero phase is drawn to the axis end.
    t_axis_end = t[-1] + 0.03 * (t[-1] - t[0]) if t else 1.0
    if runs and runs[-1][0] == "zero":
        runs[-1][2] = t_axis_end
    print("duty phases: " + ", ".join(f"{tr} {a:.3f}-{b:.3f} s" for tr, a, b in runs))

    # ---- pulse train, duty, zooms (Figure 9) --------------------------------------
    rises = [t[i] for i in range(1, len(t)) if c["step"][i] and not c["step"][i - 1]]
    falls = [t[i] for i in range(1, len(t)) if not c["step"][i] and c["step"][i - 1]]
    high = (falls[0] - rises[0]) if rises and falls and falls[0] > rises[0] else 0.0
    duty_t = rises[:-1]
    duty = [high / (b - a) if b > a else 0 for a, b in zip(rises, rises[1:])]
    zoom_phases = [r for r in runs if r[0] != "zero"] + [r for r in runs if r[0] == "zero"][:1]
    fig = plt.figure(figsize=(12, 8))
    grid = fig.add_gridspec(3, max(1, len(zoom_phases)))
    ax = fig.add_subplot(grid[0, :])
    shade(ax, runs)
    ax.step(t, c["step"], where="post", lw=0.3, color="k")
    ax.set_ylabel("STEP")
    ax.set_title(f"{name}: step pulse train ({len(rises)} pulses) with the profile phases")
    legend_patches(ax, runs)
    ax = fig.add_subplot(grid[1, :], sharex=fig.axes[0])
    shade(ax, runs)
    ax.plot(duty_t, [100 * d for d in duty], lw=0.8, color="C3")
    ax.set_ylabel("duty %")
    ax.set_xlabel("time, s")
    for k, (trend, a, b) in enumerate(zoom_phases):
        ax = fig.add_subplot(grid[2, k])
        span = 2e-3  # 2 ms window
        mid = (a + b) / 2 if trend != "zero" else a + span / 2
        sel = [i for i in range(len(t)) if mid - span / 2 <= t[i] <= mid + span / 2]
        if sel:
            i0 = max(0, sel[0] - 1)
            xs = [(t[i] - mid) * 1e3 for i in range(i0, sel[-1] + 1)]
            ys = [c["step"][i] for i in range(i0, sel[-1] + 1)]
            xs = [-span / 2 * 1e3] + xs + [span / 2 * 1e3]
            ys = [ys[0]] + ys + [ys[-1]]
            ax.step(xs, ys, where="post", lw=0.8, color="k")
        ax.set_ylim(-0.1, 1.1)
        ax.set_facecolor(COLOUR[trend])
        ax.set_title(f"{trend} @ {mid:.2f} s", fontsize=9)
        ax.set_xlabel("ms")
        ax.set_yticks([])
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pulses.png"), dpi=110)
    plt.close(fig)

    # ---- kinematics (Figures 10-12) ------------------------------------------------
    scales = {
        "velocity": ("ref_vel", clk_hz / one, "pulses/s"),
        "acceleration": ("ref_acc", clk_hz**2 / one, "pulses/s^2"),
        "jerk": ("ref_jerk", clk_hz**3 / one, "pulses/s^3"),
    }
    for fig_name, (col, k, unit) in scales.items():
        fig, ax = plt.subplots(figsize=(10, 4))
        shade(ax, runs)
        ax.step(t, [v * k for v in c[col]], where="post", lw=1.0, color="C0")
        ax.set_title(f"{name}: reference {fig_name}")
        ax.set_xlabel("time, s")
        ax.set_ylabel(unit)
        legend_patches(ax, runs)
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"{fig_name}.png"), dpi=110)
        plt.close(fig)

    # ---- tracking error (Figure 13) --------------------------------------------------
    ref = [pi + pf / one for pi, pf in zip(c["ref_pos_int"], c["ref_pos_frac"])]
    origin = next((c["ref_pos_int"][i] for i in range(len(t)) if c["busy"][i]), 0)
    what = "stepper position from the STEP pulses (open loop)"
    err = [r - origin - p for r, p in zip(ref, c["pulse_count"])]
    # Binned envelope: a per-pulse sawtooth over 30,000 pulses would fill the
    # plot solid; min/max/mean per bin keep its extent and trend readable.
    nbins = 400
    t0, t1 = (t[0], t[-1]) if t else (0.0, 1.0)
    bins = [[] for _ in range(nbins)]
    for ti, e in zip(t, err):
        bins[min(nbins - 1, int((ti - t0) / max(t1 - t0, 1e-12) * nbins))].append(e)
    centre = [t0 + (k + 0.5) * (t1 - t0) / nbins for k in range(nbins) if bins[k]]
    full = [b for b in bins if b]
    fig, ax = plt.subplots(figsize=(10, 4))
    shade(ax, runs)
    ax.fill_between(centre, [min(b) for b in full], [max(b) for b in full], color="C2", alpha=0.35,
                    label="min..max per bin")
    ax.plot(centre, [sum(b) / len(b) for b in full], lw=1.0, color="C2", label="open loop: mean")
    if closed:
        k = weights[0].index("e_p")
        ax.plot([r[0] for r in weights[1]], [r[k] for r in weights[1]], lw=0.8, color="C3",
                label="closed loop: P* - P (encoder)")
    ax.legend(loc="lower left", fontsize=8)
    print(f"tracking error: max |e| {max(abs(e) for e in err):.3f} pulses, final {err[-1]:.3f}")
    ax.set_title(f"{name}: tracking error, reference - {what}" + (" and closed loop" if closed else ""), fontsize=10)
    ax.set_xlabel("time, s")
    ax.set_ylabel("pulses")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error.png"), dpi=110)
    plt.close(fig)

    # ---- neuron weights (closed loop, optional) -----------------------------------------
    if weights:
        head, data = weights
        x = [r[0] for r in data]
        panels = [("weights w", [j for j, h in enumerate(head) if h.startswith("w_")]),
                  ("normalised weights w' = w / sum|w|", [j for j, h in enumerate(head) if h.startswith("wn_")])]
        panels = [p for p in panels if p[1]] or [("columns", list(range(1, len(head))))]
        fig, axes = plt.subplots(len(panels), 1, figsize=(10, 3.2 * len(panels)), sharex=True, squeeze=False)
        for ax, (title, cols) in zip(axes[:, 0], panels):
            for j in cols:
                ax.plot(x, [r[j] for r in data], lw=1.0, label=head[j])
            ax.set_title(f"{name}: neuron {title}")
            ax.legend(fontsize=8, loc="right")
        axes[-1, 0].set_xlabel(head[0])
        fig.tight_layout()
        fig.savefig(os.path.join(out, "weights.png"), dpi=110)
        plt.close(fig)
    else:
        print("no weights CSV: weights.png not drawn (open loop has no neuron weights; see --closed-loop)")

    print(f"figures in {out}")
    if args.require_phases:
        want = args.require_phases.split(",")
        if order != want:
            sys.exit(f"duty phases {order} != required {want}")


if __name__ == "__main__":
    main()
