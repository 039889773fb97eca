#!/usr/bin/python3
"""PNG figures of a path run from its decimated trace (scurve path --plot DIR).

  scurve path FILE --plot DIR                       # runs the path, writes the trace, then this
  scripts/plot_path.py DIR/path_trace.csv [--out-dir DIR]   # replots an existing trace

Figures (in --out-dir, default: the trace's directory):
  path_xy.png    X-Y path (axes 0 and 1, mm): the planned polyline, the sampled
                 reference and (closed loop) the measured position, and a zoom around
                 each corner (up to 12; of more, the 12 with the largest contour error
                 near them): a few pulses, or wide enough for the measured path
  path_axes.png  velocity of every axis (mm/s) and the contour error (pulses) over time;
                 closed loop: each axis's tracking error (reference - measured, pulses)

The trace: "# key=value" lines (clk_hz, every_clocks, pulses_per_mm, vertex per polyline
vertex in pulses, move_end_s, contour_max_pulses, ...), a header line, then one row per
sample: t_s, pos<a>_pulses, vel<a>_pulses_per_s per axis, contour_error_pulses, and in
closed loop meas<a>_pulses per axis (the encoder plus 1/2 pulse: the reference's coordinates).
Uses Debian's python3-matplotlib (hence /usr/bin/python3). Each PNG is written as
"<name>.part" and renamed when whole.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MAX_CORNERS = 12
ZOOM_PULSES = 4.0  # half-width of a corner's window


def read_trace(path):
    meta = {"vertex": []}
    header = None
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                kv = line[1:].strip()
                if "=" in kv:
                    k, v = kv.split("=", 1)
                    if k == "vertex":
                        meta["vertex"].append([float(x) for x in v.split(",")])
                    else:
                        meta[k] = v
                continue
            header = line.strip().split(",")
            break
        if header is None:
            sys.exit(f"{path}: no header line (not a path trace)")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    if data.shape[0] == 0 or data.shape[1] != len(header):
        sys.exit(f"{path}: no samples, or rows of another width than the header's {len(header)} columns")
    cols = {name: data[:, i] for i, name in enumerate(header)}
    return meta, cols


def floats(meta, key):
    v = meta.get(key, "")
    return [float(x) for x in v.split(",")] if v else []


def save(fig, out, name):
    path = os.path.join(out, name)
    fig.savefig(path + ".part", dpi=110, format="png")
    plt.close(fig)
    os.replace(path + ".part", path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("trace", help="path trace CSV (scurve path --plot DIR writes DIR/path_trace.csv)")
    ap.add_argument("--out-dir", help="where the PNGs go (default: the trace's directory)")
    args = ap.parse_args()
    out = args.out_dir or os.path.dirname(os.path.abspath(args.trace))
    os.makedirs(out, exist_ok=True)

    meta, c = read_trace(args.trace)
    axes = int(meta.get("axes", "1"))
    ppm = floats(meta, "pulses_per_mm") or [100.0] * axes
    name = meta.get("file", os.path.basename(args.trace))
    every = meta.get("every_clocks", "?")
    t = c["t_s"]
    pos = [c[f"pos{a}_pulses"] for a in range(axes)]
    vel = [c[f"vel{a}_pulses_per_s"] for a in range(axes)]
    contour = c["contour_error_pulses"]
    meas = [c[f"meas{a}_pulses"] for a in range(axes)] if "meas0_pulses" in c else None
    vertices = np.array(meta["vertex"]) if meta["vertex"] else np.zeros((0, axes))
    ends = floats(meta, "move_end_s")
    letters = "XYZA"

    # ---- X-Y path and its corners ------------------------------------------------------
    # One axis: the path lies on X (Y = 0); three or four: the X-Y projection.
    def xy(p_list, v):
        x = p_list[0] / ppm[0]
        y = p_list[1] / ppm[1] if axes > 1 else np.zeros_like(x)
        vx = v[:, 0] / ppm[0] if len(v) else np.zeros(0)
        vy = v[:, 1] / ppm[1] if len(v) and axes > 1 else np.zeros_like(vx)
        return x, y, vx, vy

    x, y, px, py = xy(pos, vertices)
    if meas is not None:
        mx, my, _, _ = xy(meas, vertices)
    corners = list(range(1, len(vertices) - 1))  # every vertex between two moves
    half = [ZOOM_PULSES / ppm[0], ZOOM_PULSES / (ppm[1] if axes > 1 else ppm[0])]
    near = {}
    zoom = {}  # per corner: half-width in mm per axis
    for k in corners:
        box = (np.abs(x - px[k]) <= half[0]) & (np.abs(y - py[k]) <= half[1])
        near[k] = box
        zoom[k] = half
        if meas is not None and np.any(box):
            # wide enough for where the measured position is while the reference passes
            reach = max(float(np.max(np.abs(mx[box] - px[k]))), float(np.max(np.abs(my[box] - py[k]))))
            w = max(half[0], half[1], 1.2 * reach)
            zoom[k] = [w, w]
    shown = corners
    if len(corners) > MAX_CORNERS:
        worst = sorted(corners, key=lambda k: -float(np.max(contour[near[k]], initial=0.0)))
        shown = sorted(worst[:MAX_CORNERS])
    # The path on the left, the corners' zooms in a grid on its right.
    ncol = 0 if not shown else 1 if len(shown) <= 3 else 2 if len(shown) <= 8 else 3
    nrow = (len(shown) + ncol - 1) // ncol if shown else 1
    cell = 3.6
    side = max(6.5, cell * nrow)
    fig = plt.figure(figsize=(side + cell * ncol, side + 0.6), layout="constrained")
    grid = fig.add_gridspec(nrow, 1 + ncol, width_ratios=[side] + [cell] * ncol)
    ax = fig.add_subplot(grid[:, 0])
    ax.plot(px, py, "-", lw=5, color="0.8", label="planned polyline")
    ax.plot(x, y, "-", lw=0.9, color="C0", label="reference (sampled)")
    if meas is not None:
        ax.plot(mx, my, "-", lw=0.9, color="C2", label="measured (encoder)")
    for k in shown:
        ax.plot(px[k], py[k], "o", ms=7, mfc="none", color="C3")
        ax.annotate(str(k), (px[k], py[k]), textcoords="offset points", xytext=(6, 6), fontsize=8, color="C3")
    ax.set_aspect("equal", adjustable="datalim")
    proj = "" if axes == 2 else (" (one axis: on X)" if axes == 1 else " (X-Y projection)")
    ax.set_title(f"{name}: path{proj}, {len(vertices) - 1} moves,\nsampled every {every} clocks", fontsize=10)
    ax.set_xlabel("X, mm")
    ax.set_ylabel("Y, mm")
    ax.legend(loc="best", fontsize=8)
    if len(corners) > len(shown):
        ax.text(0.01, 0.01, f"corners zoomed: {len(shown)} of {len(corners)} (the largest contour error)",
                transform=ax.transAxes, fontsize=8)
    for i, k in enumerate(shown):
        ax = fig.add_subplot(grid[i // ncol, 1 + i % ncol])
        # The samples in the window and one on each side, the rest cut out
        # (NaN), so passes through the window are not joined.
        keep = near[k] | np.roll(near[k], 1) | np.roll(near[k], -1)
        ax.plot(px, py, "-", lw=5, color="0.8", label="planned")
        ax.plot(np.where(keep, x, np.nan), np.where(keep, y, np.nan), ".-", ms=1.5, lw=0.6, color="C0",
                label="reference")
        if meas is not None:
            ax.plot(mx, my, "-", lw=0.6, color="C2", label="measured")
        ax.set_xlim(px[k] - zoom[k][0], px[k] + zoom[k][0])
        ax.set_ylim(py[k] - zoom[k][1], py[k] + zoom[k][1])
        ax.set_aspect("equal", adjustable="box")
        worst = float(np.max(contour[near[k]], initial=0.0))
        width = f"+-{ZOOM_PULSES:g} pulses" if zoom[k] is half else f"+-{zoom[k][0]:.3g} mm"
        ax.set_title(f"corner {k} at ({px[k]:.3f}, {py[k]:.3f}) mm, {width}\n"
                     f"contour error here: max {worst:.2g} pulses (sampled)", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.locator_params(nbins=4)
        if i == 0:
            ax.legend(fontsize=7, loc="best")
    save(fig, out, "path_xy.png")

    # ---- velocities and contour error over time -------------------------------------------
    if meas is None:
        fig, (av, ac) = plt.subplots(2, 1, figsize=(11, 7), sharex=True)
    else:
        fig, (av, ac, at) = plt.subplots(3, 1, figsize=(11, 10), sharex=True)
        for a in range(axes):
            at.plot(t, pos[a] - meas[a], lw=0.8, label=f"axis {a} ({letters[a]})")
        at.set_ylabel("tracking error, pulses")
        at.set_title("tracking error per axis: reference - measured (the loop follows P* - 1/2)")
        at.legend(fontsize=8, loc="best")
    for a in range(axes):
        av.plot(t, vel[a] / ppm[a], lw=1.0, label=f"axis {a} ({letters[a]})")
    av.set_ylabel("velocity, mm/s")
    av.set_title(f"{name}: reference velocity per axis")
    ac.plot(t, contour, lw=0.8, color="C3", label="sampled")
    cmax = meta.get("contour_max_pulses")
    if cmax is not None:
        ac.axhline(float(cmax), ls="--", lw=0.8, color="k", label=f"max over every clock: {float(cmax):.3g}")
    ac.set_ylabel("contour error, pulses")
    (ac if meas is None else at).set_xlabel("time, s")
    ac.set_title("contour error: the reference's distance from the planned polyline")
    for i, e in enumerate(ends):
        for a in (av, ac) if meas is None else (av, ac, at):
            a.axvline(e, ls=":", lw=0.7, color="0.5", label="move end" if i == 0 else None)
    av.legend(fontsize=8, loc="best")
    ac.legend(fontsize=8, loc="best")
    fig.tight_layout()
    save(fig, out, "path_axes.png")


if __name__ == "__main__":
    main()
