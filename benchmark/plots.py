#!/usr/bin/env python3
"""Error distributions of a benchmark run, per class and factor, as PNG (matplotlib, Debian's
python3-matplotlib; bench.py calls this after every run when matplotlib is installed).

  plots.py DIR                         DIR/error_factors.png, DIR/confidence.png (from DIR/cases.csv)
  plots.py --suites OUT.png LABEL=DIR...   error distributions of several runs (suites) side by side

error_factors.png: the mislabeled area per case (symmetric log scale) against each factor: gap level
(both classes), and for the surfaces with handles whether the planted loops share edges with region
curves, the number of planted loops, the genus and the mesh size; broken inputs only (gap > 0).
confidence.png: the cheapest flip's Eq. 11 cost against the error (cases with handles), and the share
of cases under 0.5 % for SWN, the second-best labeling and each simulated user hint.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(d):
    rows = []
    for r in csv.DictReader(open(os.path.join(d, "cases.csv"))):
        if r["ok"] != "1":
            continue
        for k, v in list(r.items()):
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
        rows.append(r)
    return rows


def strip(ax, groups, title):
    """One column of points per group (jittered), the median as a bar, share < 0.5 % on top."""
    for i, (name, vals) in enumerate(groups):
        if not vals:
            continue
        xs = [i + 0.25 * ((j * 0.618) % 1 - 0.5) for j in range(len(vals))]
        ax.scatter(xs, vals, s=6, alpha=0.5, color="#d62728" if "handles" in title else "#1f77b4")
        med = sorted(vals)[len(vals) // 2]
        ax.plot([i - 0.3, i + 0.3], [med, med], color="black", lw=1.5)
        ax.text(i, 80, "%d%%\nn=%d" % (round(100 * sum(1 for v in vals if v < 0.5) / len(vals)), len(vals)),
                ha="center", va="top", fontsize=7)
    ax.set_xticks(range(len(groups)))
    ax.set_xticklabels([g[0] for g in groups], fontsize=8)
    ax.set_yscale("symlog", linthresh=0.1)
    ax.set_ylim(0, 100)
    ax.axhline(0.5, color="gray", ls=":", lw=1)
    ax.set_title(title, fontsize=9)


def factor_plot(rows, out):
    broken = [r for r in rows if r["gap_level"] > 0]
    g0 = [r for r in broken if r["simply_connected"] == 1]
    gh = [r for r in broken if r["simply_connected"] == 0]
    err = lambda rs: [r["error_percent"] for r in rs]
    gaps = sorted(set(r["gap_level"] for r in broken))
    fig, axes = plt.subplots(2, 3, figsize=(13, 7.5))
    strip(axes[0][0], [("%d%%" % round(100 * g), err([r for r in g0 if r["gap_level"] == g])) for g in gaps],
          "simply connected: gap level")
    strip(axes[0][1], [("%d%%" % round(100 * g), err([r for r in gh if r["gap_level"] == g])) for g in gaps],
          "with handles: gap level")
    strip(axes[0][2], [("shared edges", err([r for r in gh if r["planted_shared_edges"] > 0])),
                       ("no shared edge", err([r for r in gh if r["planted_shared_edges"] == 0]))],
          "with handles: planted loops on region curves")
    nl = lambda r: r["planted_loops"] + r["planted_arcs"]
    strip(axes[1][0], [("1", err([r for r in gh if nl(r) == 1])), ("2", err([r for r in gh if nl(r) == 2])),
                       ("3+", err([r for r in gh if nl(r) >= 3]))], "with handles: planted loops and arcs")
    bins = ((0, 0, "0"), (1, 1, "1"), (2, 2, "2"), (3, 3, "3"), (4, 6, "4-6"), (7, 99, "11"))
    strip(axes[1][1], [(n, err([r for r in gh if lo <= r["genus"] <= hi])) for lo, hi, n in bins],
          "with handles: genus")
    sizes = ((0, 3e4, "<30k"), (3e4, 6e4, "30-60k"), (6e4, 1.2e5, "60-120k"), (1.2e5, 1e9, ">=120k"))
    strip(axes[1][2], [(n, err([r for r in gh if lo <= r["faces"] < hi])) for lo, hi, n in sizes],
          "with handles: faces")
    for ax in axes[:, 0]:
        ax.set_ylabel("mislabeled area (%)")
    fig.suptitle("error per case, broken inputs (median bar; share under 0.5 % above each column)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_factors.png"), dpi=90)
    plt.close(fig)


def confidence_plot(rows, out):
    gh = [r for r in rows if r["simply_connected"] == 0 and r["gap_level"] > 0 and
          isinstance(r.get("error_hint_missing_run"), float)]
    if not gh:
        return
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    for failing, color, name in ((False, "#2ca02c", "error < 0.5 %"), (True, "#d62728", "error >= 0.5 %")):
        sel = [r for r in gh if (r["error_percent"] >= 0.5) == failing and isinstance(r.get("min_flip_cost"), float)]
        a.scatter([max(r["min_flip_cost"], 1e-3) for r in sel], [r["error_percent"] for r in sel], s=8, alpha=0.6,
                  color=color, label=name)
    a.set_xscale("log")
    a.set_yscale("symlog", linthresh=0.1)
    a.set_ylim(0, 100)
    a.set_xlabel("cheapest flip of a region: Eq. 11 cost increase (mean edge lengths; <= 0 drawn at 0.001)")
    a.set_ylabel("mislabeled area (%)")
    a.legend(fontsize=8)
    a.set_title("confidence against error (with handles, broken inputs)", fontsize=9)
    keys = (("SWN", "error_percent"), ("second best", "error_second_best"),
            ("hint: least\nconfident region", "error_hint_least_confident"),
            ("hint: largest\nmislabeled region", "error_hint_largest_mislabeled"),
            ("hint: one missing\npiece redrawn", "error_hint_missing_run"))
    shares = []
    for _, k in keys:
        vals = [r[k] if isinstance(r.get(k), float) else r["error_percent"] for r in gh]
        shares.append(100 * sum(1 for v in vals if v < 0.5) / len(vals))
    b.bar(range(len(keys)), shares, color=["#1f77b4"] + ["#9467bd"] + ["#ff7f0e"] * 3)
    for i, v in enumerate(shares):
        b.text(i, v + 1, "%.1f%%" % v, ha="center", fontsize=8)
    b.set_xticks(range(len(keys)))
    b.set_xticklabels([k[0] for k in keys], fontsize=8)
    b.set_ylim(0, 100)
    b.set_ylabel("cases under 0.5 % (%)")
    b.set_title("one simulated user hint (%d cases)" % len(gh), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "confidence.png"), dpi=90)
    plt.close(fig)


def suites_plot(out_png, items):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    for item in items:
        label, d = item.split("=", 1)
        rows = [r for r in load(d) if r["gap_level"] > 0]
        for ax, cls, name in ((axes[0], 1, "simply connected"), (axes[1], 0, "with handles")):
            v = sorted(r["error_percent"] for r in rows if r["simply_connected"] == cls)
            if v:
                ax.step(v, [(i + 1) / len(v) for i in range(len(v))], where="post", label="%s (%d cases)" % (label, len(v)))
            ax.set_title("%s, broken inputs: cumulative share of cases" % name, fontsize=9)
    for ax in axes:
        ax.set_xscale("symlog", linthresh=0.01)
        ax.set_xlim(0, 100)
        ax.axvline(0.5, color="gray", ls=":", lw=1)
        ax.set_xlabel("mislabeled area (%)")
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out_png, dpi=90)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir", nargs="?")
    ap.add_argument("--suites", nargs="+", metavar="OUT.png LABEL=DIR")
    a = ap.parse_args()
    if a.suites:
        suites_plot(a.suites[0], a.suites[1:])
        return 0
    rows = load(a.dir)
    if rows:
        factor_plot(rows, a.dir)
        confidence_plot(rows, a.dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
