#!/usr/bin/env python3
"""Markdown tables for RESULTS.md from a benchmark result directory (standard library only).

  analyze.py DIR [--label NAME]
  analyze.py --factors DIR               every factor separately (gap level, shared edges, planted loops,
                                         genus, size), on broken inputs (gap > 0) only
  analyze.py --confidence DIR            confidence of the cases with handles: low confidence against
                                         failure (precision, recall), second-best labeling, simulated hints
  analyze.py --compare LABEL=DIR...      one line per result directory (ablations)
  analyze.py --speed BEFORE AFTER        whole solve / first jump-Laplace solve on the cases with handles
                                         of two runs of the same cases (issue 5's "<= 3x" target); BEFORE and
                                         AFTER may each list several runs of one code, comma-separated
                                         (DIR1,DIR2): a case's ratio is then its mean over those runs, which
                                         damps the machine's drift between runs

Prints: headline numbers, errors by gap level, a classification of the cases with handles whose error
is >= 0.5 %, the effect of planted loops sharing edges with region boundaries, per-mesh numbers and
timings by size.
"""
import argparse
import csv
import json
import os
import statistics


def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return None


def pct(x):
    return "%.1f %%" % (100 * x)


def f3(x):
    return "-" if x is None else ("%.3f" % x)


def compare(items):
    print("| setting | cases | simply conn. mean / max (%) | handles mean / median (%) | handles < 0.5 % | handles gap 0 < 0.5 % | handles: G ~ planted | naive handles mean (%) |")
    print("|---|---|---|---|---|---|---|---|")
    for item in items:
        label, d = item.split("=", 1)
        rows = [r for r in csv.DictReader(open(os.path.join(d, "cases.csv"))) if r["ok"] == "1"]
        g0 = [r for r in rows if r["simply_connected"] == "1"]
        gh = [r for r in rows if r["simply_connected"] == "0"]
        e = lambda rs, k="error_percent": [float(r[k]) for r in rs]
        h0 = [r for r in gh if float(r["gap_level"]) == 0]
        print("| %s | %d | %.3f / %.2f | %.3f / %.3f | %s | %s | %s | %.3f |" % (
            label, len(rows), statistics.fmean(e(g0)), max(e(g0)), statistics.fmean(e(gh)), statistics.median(e(gh)),
            pct(sum(1 for x in e(gh) if x < 0.5) / len(gh)), pct(sum(1 for x in e(h0) if x < 0.5) / len(h0)),
            pct(sum(1 for r in gh if r["loops_recovered"] == "1") / len(gh)), statistics.fmean(e(gh, "naive_error_percent"))))


def speed(before_dirs, after_dirs):
    def load(d):
        return {r["case"]: r for r in csv.DictReader(open(os.path.join(d, "cases.csv"))) if r["ok"] == "1"}
    runs = [[load(d) for d in ds.split(",")] for ds in (before_dirs, after_dirs)]
    keys = [k for k in runs[0][0] if all(k in R for rs in runs for R in rs) and runs[0][0][k]["simply_connected"] == "0"]
    # one row per case and code: the ratio and the residual as means over that code's runs
    def merged(rs):
        out = {}
        for k in keys:
            r = dict(rs[0][k])
            r["ratio"] = statistics.fmean(float(R[k]["time_total"]) / float(R[k]["time_jump_laplace"]) for R in rs)
            r["time_residual"] = statistics.fmean(float(R[k]["time_residual"]) for R in rs)
            out[k] = r
        return out
    A, B = merged(runs[0]), merged(runs[1])
    ratio = lambda r: r["ratio"]
    same = sum(1 for k in keys if all(R[k]["error_percent"] == runs[0][0][k]["error_percent"] and
                                      R[k]["G_edges"] == runs[0][0][k]["G_edges"] for rs in runs for R in rs))
    print("cases with handles in every run: %d; same error and G in all: %d; runs per code: %d, %d" % (
        len(keys), same, len(runs[0]), len(runs[1])))
    print("| faces | cases | whole / first solve <= 3x: before, after | median ratio: before, after | residual total (s): before, after |")
    print("|---|---|---|---|---|")
    for lo, hi in ((0, 40000), (40000, 100000), (100000, 10 ** 9), (0, 10 ** 9)):
        ks = [k for k in keys if lo <= int(A[k]["faces"]) < hi]
        if not ks:
            continue
        row = []
        for D in (A, B):
            r = [ratio(D[k]) for k in ks]
            row.append((sum(1 for x in r if x <= 3), statistics.median(r), sum(float(D[k]["time_residual"]) for k in ks)))
        label = "all" if (lo, hi) == (0, 10 ** 9) else ("%dk-%s" % (lo // 1000, "" if hi == 10 ** 9 else "%dk" % (hi // 1000)))
        print("| %s | %d | %d, %d | %.2f, %.2f | %.1f, %.1f |" % (label, len(ks), row[0][0], row[1][0], row[0][1], row[1][1],
                                                               row[0][2], row[1][2]))


def load_ok(d):
    rows = [r for r in csv.DictReader(open(os.path.join(d, "cases.csv"))) if r["ok"] == "1"]
    for r in rows:
        for k, v in list(r.items()):
            if k not in ("case", "mesh", "source", "labels_hash", "G_hash"):
                x = num(v)
                r[k] = x if x is not None or v == "" else v
    return rows


def line(name, rs, recovered=True):
    v = [r["error_percent"] for r in rs]
    if not v:
        return "| %s | 0 | - | - | - | - |" % name
    rec = pct(sum(1 for r in rs if r.get("loops_recovered") == 1) / len(rs)) if recovered else "-"
    return "| %s | %d | %.3f / %.3f / %.2f | %s | %s |" % (name, len(v), statistics.fmean(v), statistics.median(v), max(v),
                                                     pct(sum(1 for x in v if x < 0.5) / len(v)), rec)


def factors(d):
    ok = load_ok(d)
    broken = [r for r in ok if r["gap_level"] > 0]
    g0 = [r for r in broken if r["simply_connected"] == 1]
    gh = [r for r in broken if r["simply_connected"] == 0]
    print("Broken inputs only (gap level > 0): %d simply connected, %d with handles.\n" % (len(g0), len(gh)))
    head = "| %s | cases | mean / median / max error (%%) | share < 0.5 %% | G ~ planted |\n|---|---|---|---|---|"
    print(head % "simply connected, gap level")
    for gap in sorted(set(r["gap_level"] for r in g0)):
        print(line("%d %%" % round(100 * gap), [r for r in g0 if r["gap_level"] == gap], False))
    print(line("all", g0, False))
    print()
    sizes = ((0, 30000, "< 30k faces"), (30000, 60000, "30k-60k"), (60000, 120000, "60k-120k"), (120000, 10 ** 9, ">= 120k"))
    genus = ((0, 0, "0 (several border loops)"), (1, 1, "1"), (2, 2, "2"), (3, 3, "3"), (4, 6, "4-6"), (7, 99, "11"))
    tables = (
        ("gap level", [("%d %%" % round(100 * g), lambda r, g=g: r["gap_level"] == g) for g in sorted(set(r["gap_level"] for r in gh))]),
        ("planted loops share edges with region curves", [("yes", lambda r: r["planted_shared_edges"] > 0), ("no", lambda r: r["planted_shared_edges"] == 0)]),
        ("planted loops and arcs", [("1", lambda r: r["planted_loops"] + r["planted_arcs"] == 1), ("2", lambda r: r["planted_loops"] + r["planted_arcs"] == 2),
                                    ("3 or more", lambda r: r["planted_loops"] + r["planted_arcs"] >= 3)]),
        ("genus", [(n, lambda r, lo=lo, hi=hi: lo <= r["genus"] <= hi) for lo, hi, n in genus]),
        ("size", [(n, lambda r, lo=lo, hi=hi: lo <= r["faces"] < hi) for lo, hi, n in sizes]),
    )
    for title, groups in tables:
        print(head % ("with handles, " + title))
        for name, pred in groups:
            rs = [r for r in gh if pred(r)]
            if rs:
                print(line(name, rs))
        print()
    print(head % "with handles, all broken")
    print(line("all", gh))
    print()


def confidence(d, thresholds=(0.5, 1, 2, 4, 8)):
    ok = load_ok(d)
    gh = [r for r in ok if r["simply_connected"] == 0 and r["gap_level"] > 0 and r.get("error_hint_missing_run") is not None]
    if not gh:
        print("no confidence data in %s" % d)
        return
    for r in gh:
        if r.get("min_flip_cost") is None:
            r["min_flip_cost"] = float("inf")   # no region to flip
        for k in ("error_second_best", "error_hint_least_confident"):
            if r.get(k) is None:
                r[k] = r["error_percent"]
    n = len(gh)
    share = lambda key: pct(sum(1 for r in gh if r[key] < 0.5) / n)
    fail = [r for r in gh if r["error_percent"] >= 0.5]
    print("Cases with handles, broken inputs: %d, of which %d fail (error >= 0.5 %%).\n" % (n, len(fail)))
    print("| labeling | share < 0.5 % | mean error (%) |")
    print("|---|---|---|")
    for name, key in (("SWN", "error_percent"), ("second-best labeling (the cheapest flip applied)", "error_second_best"),
                      ("hint: the user labels the least confident region", "error_hint_least_confident"),
                      ("hint: the user labels the largest mislabeled region", "error_hint_largest_mislabeled"),
                      ("hint: the user redraws one missing piece of the input (re-solve)", "error_hint_missing_run")):
        print("| %s | %s | %.3f |" % (name, share(key), statistics.fmean(r[key] for r in gh)))
    best2 = [min(r["error_percent"], r["error_second_best"]) for r in gh]
    print("| oracle: the better of SWN and the second-best labeling | %s | %.3f |" % (
        pct(sum(1 for x in best2 if x < 0.5) / n), statistics.fmean(best2)))
    print()
    print("Low confidence (cheapest flip of a region of >= 0.5 % of the area costs less than T mean edge lengths in")
    print("Eq. 11) as a predictor of failure:\n")
    print("| T | flagged | precision | recall | share < 0.5 % among the unflagged |")
    print("|---|---|---|---|---|")
    for t in thresholds:
        flagged = [r for r in gh if r["min_flip_cost"] < t]
        tp = sum(1 for r in flagged if r["error_percent"] >= 0.5)
        rest = [r for r in gh if r not in flagged]
        print("| %g | %d | %s | %s | %s |" % (t, len(flagged), pct(tp / len(flagged)) if flagged else "-",
                                             pct(tp / len(fail)) if fail else "-",
                                             pct(sum(1 for r in rest if r["error_percent"] < 0.5) / len(rest)) if rest else "-"))
    wc = [r["worst_cell_flip_cost"] for r in fail if r["worst_cell_flip_cost"] >= 0]
    if wc:
        print("\nFailing cases: median flip cost of the largest mislabeled region %.2f (%d of %d finite), median cheapest flip %.2f."
              % (statistics.median(wc), len(wc), len(fail), statistics.median(r["min_flip_cost"] for r in fail)))
    good = [r for r in gh if r["error_percent"] < 0.5]
    if good:
        print("Passing cases: median cheapest flip %.2f." % statistics.median(r["min_flip_cost"] for r in good))
    print("(The second-best labeling and the least-confident hint keep SWN's labels where no region is eligible.)")
    print()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir", nargs="?")
    ap.add_argument("--label", default="")
    ap.add_argument("--compare", nargs="+")
    ap.add_argument("--factors", action="store_true")
    ap.add_argument("--confidence", action="store_true")
    ap.add_argument("--speed", nargs=2, metavar=("BEFORE", "AFTER"))
    a = ap.parse_args()
    if a.speed:
        speed(*a.speed)
        return
    if a.compare:
        compare(a.compare)
        return
    if a.factors or a.confidence:
        if a.factors:
            factors(a.dir)
        if a.confidence:
            confidence(a.dir)
        return
    rows = list(csv.DictReader(open(os.path.join(a.dir, "cases.csv"))))
    s = json.load(open(os.path.join(a.dir, "summary.json")))
    ok = [r for r in rows if r["ok"] == "1"]
    for r in ok:
        for k in ("error_percent", "naive_error_percent", "gap_level", "time_swn", "time_residual", "faces", "vertices",
                  "cost_G", "cost_planted", "peak_rss_mb", "time_jump_laplace", "time_second_solve", "time_hodge",
                  "time_construct", "planted_shared_edges", "planted_cancelled_edges"):
            r[k] = num(r.get(k))
    g0 = [r for r in ok if r["simply_connected"] == "1"]
    gh = [r for r in ok if r["simply_connected"] == "0"]

    def st(rs, k="error_percent"):
        v = [r[k] for r in rs]
        if not v:
            return "-"
        return "%.3f / %.3f / %.2f / %s" % (statistics.fmean(v), statistics.median(v), max(v),
                                            pct(sum(1 for x in v if x < 0.5) / len(v)))

    print("### %s\n" % (a.label or a.dir))
    print("%d cases (%d simply connected, %d with handles), %d failed, %d timed out; LP backend(s): %s; sparse solver(s): %s.\n" % (
        s["cases"], len(g0), len(gh), s.get("cases_failed", 0), s.get("cases_timeout", 0), ", ".join(s.get("lp_backends", [])),
        ", ".join(s.get("sparse_solvers", [])) or "not recorded"))
    print("| class | method | mean / median / max error (%) / share < 0.5 % |")
    print("|---|---|---|")
    print("| simply connected | SWN | %s |" % st(g0))
    print("| simply connected | naive (round u) | %s |" % st(g0, "naive_error_percent"))
    print("| with handles | SWN | %s |" % st(gh))
    print("| with handles | naive (round u) | %s |" % st(gh, "naive_error_percent"))
    print()
    print("By gap level (mean error %, share of cases < 0.5 %; for handles also the share where G is homologous to the planted loops):\n")
    print("| gap | simply connected SWN (= naive) | handles SWN | handles naive | handles: G ~ planted |")
    print("|---|---|---|---|---|")
    for gap in sorted(set(r["gap_level"] for r in ok)):
        a0 = [r for r in g0 if r["gap_level"] == gap]
        ah = [r for r in gh if r["gap_level"] == gap]
        m = lambda rs, k="error_percent": ("%.3f (%s)" % (statistics.fmean(r[k] for r in rs), pct(sum(1 for r in rs if r[k] < 0.5) / len(rs)))) if rs else "-"
        rec = pct(sum(1 for r in ah if r["loops_recovered"] == "1") / len(ah)) if ah else "-"
        print("| %d %% | %s | %s | %s | %s |" % (round(100 * gap), m(a0), m(ah), m(ah, "naive_error_percent"), rec))
    print()
    # classification of the handle cases with error >= 0.5 %
    bad = [r for r in gh if r["error_percent"] >= 0.5]
    topo = [r for r in bad if r["loops_recovered"] != "1"]
    amb = [r for r in bad if r["loops_recovered"] == "1" and r["cost_G"] is not None and r["cost_G"] <= r["cost_planted"] + 1e-9]
    sub = [r for r in bad if r["loops_recovered"] == "1" and r not in amb]
    print("Cases with handles and error >= 0.5 %%: %d of %d.\n" % (len(bad), len(gh)))
    print("| why | cases | mean error (%) |")
    print("|---|---|---|")
    for name, rs in (("G not homologous to the planted loops (topology of the completion differs)", topo),
                     ("G homologous to the planted loops, and G is no more expensive than the planted loops in Eq. 11's cost (the model prefers its answer: regions absorbed into G)", amb),
                     ("G homologous, but more expensive than the planted loops (relaxation / Hodge projection / rounding)", sub)):
        print("| %s | %d | %s |" % (name, len(rs), f3(statistics.fmean(r["error_percent"] for r in rs)) if rs else "-"))
    if topo:
        cheaper = sum(1 for r in topo if r["cost_G"] is not None and r["cost_G"] <= r["cost_planted"] + 1e-9)
        print("\nOf the %d cases whose G is not homologous to the planted loops, %d have a G no more expensive than the planted loops." % (len(topo), cheaper))
    print()
    sh = [r for r in gh if (r["planted_shared_edges"] or 0) > 0]
    ns = [r for r in gh if (r["planted_shared_edges"] or 0) == 0]
    print("Planted loops sharing edges with region boundaries (handles): %d cases share, %d do not.\n" % (len(sh), len(ns)))
    print("| cases with handles | SWN mean / median / max (%) / share < 0.5 % | gap-0 share < 0.5 % |")
    print("|---|---|---|")
    for name, rs in (("planted loops share edges with region curves", sh), ("no shared edge", ns)):
        z = [r for r in rs if r["gap_level"] == 0]
        print("| %s | %s | %s |" % (name, st(rs), pct(sum(1 for r in z if r["error_percent"] < 0.5) / len(z)) if z else "-"))
    print()
    # per mesh
    print("| mesh | source | vertices | genus | border loops | cases | SWN mean err (%) | naive mean err (%) | G ~ planted | median time (s) | median LP (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    meshes = {}
    for r in ok:
        meshes.setdefault(r["mesh"], []).append(r)
    for name, rs in sorted(meshes.items(), key=lambda kv: (kv[1][0]["simply_connected"] == "0", int(kv[1][0]["genus"]), kv[0])):
        r0 = rs[0]
        print("| %s | %s | %d | %s | %s | %d | %.3f | %.3f | %s | %.2f | %.2f |" % (
            name, r0["source"], r0["vertices"], r0["genus"], r0["border_loops"], len(rs),
            statistics.fmean(r["error_percent"] for r in rs), statistics.fmean(r["naive_error_percent"] for r in rs),
            pct(sum(1 for r in rs if r["loops_recovered"] == "1") / len(rs)) if r0["simply_connected"] == "0" else "-",
            statistics.median(r["time_swn"] for r in rs), statistics.median(r["time_residual"] for r in rs)))
    print()
    # timings by size
    print("| class | faces | cases | median total (s) | median jump Laplace x2 (s) | median Hodge (s) | median residual LP (s) | max peak RSS (MB) |")
    print("|---|---|---|---|---|---|---|---|")
    bins = [(0, 30000), (30000, 60000), (60000, 120000), (120000, 10 ** 9)]
    for cls, rs in (("simply connected", g0), ("with handles", gh)):
        for lo, hi in bins:
            b = [r for r in rs if lo <= r["faces"] < hi]
            if not b:
                continue
            print("| %s | %s | %d | %.2f | %.2f | %.2f | %.2f | %.0f |" % (
                cls, "%dk-%s" % (lo // 1000, ("%dk" % (hi // 1000)) if hi < 10 ** 9 else "..."), len(b),
                statistics.median(r["time_swn"] for r in b),
                statistics.median(r["time_jump_laplace"] + r["time_second_solve"] for r in b),
                statistics.median(r["time_hodge"] for r in b), statistics.median(r["time_residual"] for r in b),
                max(r["peak_rss_mb"] for r in b)))
    print()
    if "genus0_time_vs_faces_exponent" in s:
        print("Least-squares slope of log(time) vs log(faces): simply connected %.2f, with handles %.2f.\n" % (
            s["genus0_time_vs_faces_exponent"], s.get("handles_time_vs_faces_exponent", float("nan"))))


if __name__ == "__main__":
    main()
