#!/usr/bin/env python3
"""Driver of the Surface Winding Numbers benchmark (called by benchmark/run; standard library only).

  bench.py --suite quick|full --out DIR --build BUILD_DIR [--shard I/N] [--jobs J] [--timeout S]
           [--lp default|glpk] [--cgal-data DIR] [--mesh-cache DIR]
  bench.py --merge --out DIR SHARD_DIR...     merge shard results into DIR
  bench.py --summarize --out DIR              recompute summary.json and plots from DIR/cases.csv

Writes DIR/cases.csv (one row per case), DIR/summary.json and DIR/*.png (gnuplot and matplotlib, when
installed).
"""
import argparse
import csv
import datetime
import json
import math
import os
import platform
import shutil
import statistics
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

COLUMNS = [
    "case", "suite", "mesh", "source", "vertices", "faces", "genus", "border_loops", "simply_connected",
    "region_seed", "regions", "eigenfunction", "gap_level", "gap_fraction", "curve_edges_full", "curve_edges", "interior_endpoints",
    "max_gt_label", "planted_loops", "planted_arcs", "planted_edges", "planted_nontrivial",
    "planted_shared_edges", "planted_cancelled_edges", "loops_straightened", "loops_rerouting_failed",
    "ok", "status", "error", "lp_backend", "sparse_solver", "epsilon",
    "error_percent", "naive_error_percent",
    "G_edges", "G_closed", "G_closing_units", "G_nonzero_in_homology", "G_homologous_to_planted", "G_planted_edges_matched",
    "loops_recovered", "cost_G", "cost_planted",
    "homology_correction", "hodge_projection", "lp_ran", "lp_variables", "lp_rows", "lp_objective",
    "min_label", "max_label", "labels_hash", "G_hash",
    "time_read", "time_construct", "time_setup", "time_jump_laplace", "time_hodge", "time_residual",
    "time_second_solve", "time_labels", "time_total", "time_swn", "time_naive", "peak_rss_mb",
    "api_match",
    "decomposition_mismatch_edges", "cells", "cells_eligible", "min_flip_cost", "min_flip_boundary", "min_flip_area_percent",
    "error_second_best", "error_hint_least_confident", "worst_cell_wrong_percent", "worst_cell_flip_cost",
    "error_hint_largest_mislabeled", "hint_run_edges", "error_hint_missing_run",
]


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, **kw)


def solve_case(args, case_id, case_dir, check_api):
    meta = json.load(open(os.path.join(case_dir, "meta.json")))
    cmd = [os.path.join(args.build, "swn_bench_solve"), case_dir, meta["mesh_file"], "--lp", args.lp, "--epsilon", str(args.epsilon)]
    if args.completed_class:
        cmd.append("--completed-class")
    if check_api:
        cmd.append("--check-api")
    row = dict(meta)
    t0 = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
        line = p.stdout.strip().splitlines()[-1] if p.stdout.strip() else "{}"
        res = json.loads(line)
        if not res:
            res = {"ok": False, "error": "no output, exit code %d: %s" % (p.returncode, p.stderr.strip()[-300:])}
        row.update(res)
        row["status"] = "ok" if res.get("ok") else "failed"
    except subprocess.TimeoutExpired:
        row.update({"ok": False, "error": "timeout after %g s" % args.timeout})
        row["status"] = "timeout"
    except (json.JSONDecodeError, IndexError) as e:
        row.update({"ok": False, "error": "bad output: %s" % e})
        row["status"] = "failed"
    row["wall_time"] = time.time() - t0
    if row.get("ok"):
        planted = (row.get("planted_loops", 0) or 0) + (row.get("planted_arcs", 0) or 0)
        # recovered: G is closed and homologous to the planted chain in H1(M, border) (for no planted
        # loop: G bounds, i.e. no phantom nonbounding loop)
        row["loops_recovered"] = bool(row.get("G_closed")) and bool(row.get("G_homologous_to_planted"))
        row["planted_total"] = planted
    return row


def fmt(v):
    if isinstance(v, bool):
        return "1" if v else "0"
    if isinstance(v, float):
        return "%.6g" % v
    if v is None:
        return ""
    return str(v).replace(",", ";").replace("\n", " ")


def write_csv(path, rows):
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for r in rows:
            w.writerow([fmt(r.get(c)) for c in COLUMNS])
    os.replace(path + ".tmp", path)


def read_csv(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            d = {}
            for k, v in r.items():
                if v == "":
                    d[k] = None
                    continue
                try:
                    d[k] = int(v)
                except ValueError:
                    try:
                        d[k] = float(v)
                    except ValueError:
                        d[k] = v
            rows.append(d)
    return rows


def truthy(v):
    return v in (True, 1, "1", "true", "True")


def stats(vals):
    vals = [v for v in vals if v is not None]
    if not vals:
        return {"n": 0}
    s = sorted(vals)
    return {
        "n": len(s),
        "mean": statistics.fmean(s),
        "median": statistics.median(s),
        "max": s[-1],
        "p90": s[min(len(s) - 1, int(math.ceil(0.9 * len(s))) - 1)],
        "fraction_under_0_5_percent": sum(1 for v in s if v < 0.5) / len(s),
        "fraction_exact": sum(1 for v in s if v == 0) / len(s),
    }


def machine():
    cpu = platform.processor()
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    mem = None
    try:
        for line in open("/proc/meminfo"):
            if line.startswith("MemTotal"):
                mem = round(int(line.split()[1]) / 1024 / 1024, 1)
    except OSError:
        pass
    thp = None
    try:
        thp = open("/sys/kernel/mm/transparent_hugepage/enabled").read().strip()
    except OSError:
        pass
    return {"cpu": cpu, "cores": os.cpu_count(), "memory_gb": mem, "system": platform.platform(),
            "transparent_hugepages": thp}


def git_commit(root):
    try:
        c = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no", "--", "include"],
                               capture_output=True, text=True).stdout.strip()
        return c + ("+uncommitted-include-changes" if dirty else "")
    except OSError:
        return None


def summarize(rows, out, extra):
    ok = [r for r in rows if truthy(r.get("ok"))]
    g0 = [r for r in ok if truthy(r.get("simply_connected"))]
    gh = [r for r in ok if not truthy(r.get("simply_connected"))]
    e = lambda rs, k="error_percent": [r.get(k) for r in rs]
    s0, sh, n0, nh = stats(e(g0)), stats(e(gh)), stats(e(g0, "naive_error_percent")), stats(e(gh, "naive_error_percent"))
    summary = {
        "cases": len(rows),
        "cases_ok": len(ok),
        "cases_failed": sum(1 for r in rows if r.get("status") == "failed"),
        "cases_timeout": sum(1 for r in rows if r.get("status") == "timeout"),
        "genus0_cases": len(g0),
        "handles_cases": len(gh),
        "genus0_mean_error_percent": s0.get("mean"),
        "genus0_median_error_percent": s0.get("median"),
        "genus0_max_error_percent": s0.get("max"),
        "genus0_fraction_under_0_5_percent": s0.get("fraction_under_0_5_percent"),
        "handles_mean_error_percent": sh.get("mean"),
        "handles_median_error_percent": sh.get("median"),
        "handles_max_error_percent": sh.get("max"),
        "handles_fraction_under_0_5_percent": sh.get("fraction_under_0_5_percent"),
        "naive_genus0_mean_error_percent": n0.get("mean"),
        "naive_genus0_median_error_percent": n0.get("median"),
        "naive_genus0_max_error_percent": n0.get("max"),
        "naive_handles_mean_error_percent": nh.get("mean"),
        "naive_handles_median_error_percent": nh.get("median"),
        "naive_handles_max_error_percent": nh.get("max"),
        "naive_handles_fraction_under_0_5_percent": nh.get("fraction_under_0_5_percent"),
        "definitions": {
            "genus0": "simply connected surfaces: every component is a sphere or a disk (the library runs no LP)",
            "handles": "all other surfaces (genus > 0 and/or several border loops): nonbounding loops are planted",
            "error_percent": "mislabeled area in % of the total area, labels compared up to one integer per component",
            "naive": "rounding of the first jump-harmonic function u plus the shift tau (generalized-winding-number approach)",
            "loops_recovered": "G closed (relative to the border) and homologous to the planted chain in H1(M, border)",
        },
    }
    by_gap = {}
    for cls, rs in (("genus0", g0), ("handles", gh)):
        for gap in sorted(set(r.get("gap_level") for r in rs)):
            sel = [r for r in rs if r.get("gap_level") == gap]
            st, sn = stats(e(sel)), stats(e(sel, "naive_error_percent"))
            key = "%s_gap%02d" % (cls, round(100 * gap))
            by_gap[key] = {"cases": len(sel), "mean_error_percent": st.get("mean"), "median_error_percent": st.get("median"),
                           "max_error_percent": st.get("max"),
                           "fraction_under_0_5_percent": st.get("fraction_under_0_5_percent"),
                           "naive_mean_error_percent": sn.get("mean"), "naive_max_error_percent": sn.get("max")}
            if cls == "handles":
                by_gap[key]["loops_recovered_fraction"] = sum(1 for r in sel if truthy(r.get("loops_recovered"))) / max(1, len(sel))
    summary["by_gap"] = by_gap
    if gh:
        summary["handles_loops_recovered_fraction"] = sum(1 for r in gh if truthy(r.get("loops_recovered"))) / len(gh)
        summary["handles_G_closed_fraction"] = sum(1 for r in gh if truthy(r.get("G_closed"))) / len(gh)
        summary["handles_G_nonzero_fraction"] = sum(1 for r in gh if truthy(r.get("G_nonzero_in_homology"))) / len(gh)
    if g0:
        summary["genus0_G_zero_fraction"] = sum(1 for r in g0 if (r.get("G_edges") or 0) == 0) / len(g0)
    # per mesh
    per_mesh = {}
    for r in ok:
        m = per_mesh.setdefault(r["mesh"], {"source": r.get("source"), "vertices": r.get("vertices"), "faces": r.get("faces"),
                                            "genus": r.get("genus"), "border_loops": r.get("border_loops"), "errors": [], "naive": [],
                                            "time_swn": [], "time_residual": [], "recovered": []})
        m["errors"].append(r.get("error_percent"))
        m["naive"].append(r.get("naive_error_percent"))
        m["time_swn"].append(r.get("time_swn"))
        m["time_residual"].append(r.get("time_residual"))
        m["recovered"].append(truthy(r.get("loops_recovered")))
    for m in per_mesh.values():
        m["cases"] = len(m["errors"])
        m["mean_error_percent"] = statistics.fmean(m.pop("errors"))
        m["mean_naive_error_percent"] = statistics.fmean(m.pop("naive"))
        m["median_time_swn"] = statistics.median(m.pop("time_swn"))
        m["median_time_residual"] = statistics.median(m.pop("time_residual"))
        m["loops_recovered_fraction"] = sum(m["recovered"]) / len(m.pop("recovered"))
    summary["per_mesh"] = per_mesh
    # time vs size
    tv = sorted(((r.get("faces"), r.get("time_swn"), r.get("time_residual"), r.get("peak_rss_mb"), truthy(r.get("simply_connected"))) for r in ok))
    for cls, flag in (("genus0", True), ("handles", False)):
        sel = [t for t in tv if t[4] == flag]
        if sel:
            summary["%s_time_swn_seconds" % cls] = stats([t[1] for t in sel])
            summary["%s_time_residual_seconds" % cls] = stats([t[2] for t in sel])
            summary["%s_peak_rss_mb_max" % cls] = max(t[3] for t in sel)
            # least-squares fit of log(time) against log(faces)
            pts = [(math.log(t[0]), math.log(max(t[1], 1e-6))) for t in sel]
            if len(set(p[0] for p in pts)) > 1:
                mx, my = statistics.fmean(p[0] for p in pts), statistics.fmean(p[1] for p in pts)
                b = sum((p[0] - mx) * (p[1] - my) for p in pts) / sum((p[0] - mx) ** 2 for p in pts)
                summary["%s_time_vs_faces_exponent" % cls] = b
    summary["lp_backends"] = sorted(set(str(r.get("lp_backend")) for r in ok))
    summary["sparse_solvers"] = sorted(set(str(r.get("sparse_solver")) for r in ok if r.get("sparse_solver")))
    summary["failures"] = [{"case": r.get("case"), "status": r.get("status"), "error": r.get("error")} for r in rows if not truthy(r.get("ok"))]
    summary["api_match"] = all(truthy(r.get("api_match")) for r in ok if r.get("api_match") is not None)
    summary["machine"] = machine()
    summary["date"] = datetime.datetime.now().astimezone().isoformat(timespec="seconds")
    summary.update(extra)
    with open(os.path.join(out, "summary.json.tmp"), "w") as f:
        json.dump(summary, f, indent=1, sort_keys=False)
        f.write("\n")
    os.replace(os.path.join(out, "summary.json.tmp"), os.path.join(out, "summary.json"))
    return summary


def matplotlib_plots(out):
    """error_factors.png and confidence.png (plots.py), when python3-matplotlib is installed."""
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "plots.py")
    r = subprocess.run([sys.executable, script, out], capture_output=True, text=True)
    if r.returncode != 0:
        print("[bench] plots.py failed (apt-get install python3-matplotlib): " + r.stderr.strip()[-300:], file=sys.stderr)


def plots(rows, out):
    matplotlib_plots(out)
    gp = shutil.which("gnuplot")
    if not gp:
        print("[bench] gnuplot not found: no plots (apt-get install gnuplot-nox)", file=sys.stderr)
        return
    ok = [r for r in rows if truthy(r.get("ok"))]
    if not ok:
        return
    # Fig. 16: error per case, SWN (top) vs naive rounding of u (bottom), cases sorted by class, mesh, gap
    ok.sort(key=lambda r: (not truthy(r.get("simply_connected")), r.get("mesh"), r.get("gap_level"), r.get("region_seed")))
    with open(os.path.join(out, "errors.dat"), "w") as f:
        for i, r in enumerate(ok):
            f.write("%d %g %g %d\n" % (i, r["error_percent"], r["naive_error_percent"], 0 if truthy(r.get("simply_connected")) else 1))
    split = sum(1 for r in ok if truthy(r.get("simply_connected"))) - 0.5
    ymax = max(5.0, max(max(r["error_percent"], r["naive_error_percent"]) for r in ok) * 1.05)
    script = """
set terminal pngcairo size 1200,800 font ",10"
set output '{out}/errors.png'
set multiplot layout 2,1
set ylabel 'mislabeled area (%)'
set yrange [0:{ymax}]
set xrange [-1:{n}]
set arrow 1 from {split},graph 0 to {split},graph 1 nohead dt 2
set label 1 'simply connected' at graph 0.02,0.92
set label 2 'with handles' at {split},graph 0.92 offset 1,0
set style fill solid 0.8
set boxwidth 0.8
set title 'SWN: error per case'
plot '{out}/errors.dat' u 1:($4==0?$2:1/0) w boxes lc rgb '#1f77b4' t 'genus 0', '' u 1:($4==1?$2:1/0) w boxes lc rgb '#d62728' t 'handles'
set title 'naive rounding of u (GWN-style): error per case'
set xlabel 'case (sorted by class, mesh, gap level)'
plot '{out}/errors.dat' u 1:($4==0?$3:1/0) w boxes lc rgb '#1f77b4' t 'genus 0', '' u 1:($4==1?$3:1/0) w boxes lc rgb '#d62728' t 'handles'
unset multiplot
""".format(out=out, ymax=ymax, n=len(ok), split=split)
    # Fig. 17: time vs size
    with open(os.path.join(out, "times.dat"), "w") as f:
        for r in ok:
            f.write("%d %g %g %g %d\n" % (r["faces"], r["time_swn"], r["time_residual"] or 0, r["time_jump_laplace"] + r["time_second_solve"],
                                          0 if truthy(r.get("simply_connected")) else 1))
    script += """
set terminal pngcairo size 1000,800 font ",10"
set output '{out}/times.png'
unset arrow 1
unset label 1
unset label 2
set multiplot layout 2,1
set logscale xy
set xrange [*:*]
set yrange [*:*]
set xlabel 'faces'
set ylabel 'seconds'
set key left top
set title 'simply connected surfaces: total time (one linear solve)'
plot '{out}/times.dat' u 1:($5==0?$2:1/0) w p pt 7 ps 0.6 lc rgb '#1f77b4' t 'SWN total (construction + solve)'
set title 'surfaces with handles: total time and residual (LP) time'
plot '{out}/times.dat' u 1:($5==1?$2:1/0) w p pt 7 ps 0.6 lc rgb '#d62728' t 'SWN total', '' u 1:($5==1?$3:1/0) w p pt 6 ps 0.8 lc rgb 'black' t 'residual (LP) step', '' u 1:($5==1?$4:1/0) w p pt 2 ps 0.6 lc rgb '#2ca02c' t 'jump Laplace solves'
unset multiplot
""".format(out=out)
    # error vs gap level
    with open(os.path.join(out, "gaps.dat"), "w") as f:
        for cls in (1, 0):
            for gap in sorted(set(r["gap_level"] for r in ok)):
                sel = [r for r in ok if r["gap_level"] == gap and (truthy(r.get("simply_connected")) == (cls == 1))]
                if sel:
                    f.write("%g %g %g %d\n" % (100 * gap, statistics.fmean(r["error_percent"] for r in sel),
                                               statistics.fmean(r["naive_error_percent"] for r in sel), cls))
    script += """
set terminal pngcairo size 800,500 font ",10"
set output '{out}/gaps.png'
unset logscale
set xrange [*:*]
set yrange [0:*]
set xlabel 'deleted curve length (%)'
set ylabel 'mean mislabeled area (%)'
set title 'mean error vs gap level'
plot '{out}/gaps.dat' u 1:($4==1?$2:1/0) w lp pt 7 lc rgb '#1f77b4' t 'SWN, genus 0', '' u 1:($4==1?$3:1/0) w lp pt 6 dt 2 lc rgb '#1f77b4' t 'naive, genus 0', '' u 1:($4==0?$2:1/0) w lp pt 7 lc rgb '#d62728' t 'SWN, handles', '' u 1:($4==0?$3:1/0) w lp pt 6 dt 2 lc rgb '#d62728' t 'naive, handles'
""".format(out=out)
    with open(os.path.join(out, "plots.gp"), "w") as f:
        f.write(script)
    r = subprocess.run([gp, os.path.join(out, "plots.gp")], capture_output=True, text=True)
    if r.returncode != 0:
        print("[bench] gnuplot failed: " + r.stderr[-500:], file=sys.stderr)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--suite", default="quick")
    ap.add_argument("--out", required=True)
    ap.add_argument("--build")
    ap.add_argument("--shard", default="0/1")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=1200)
    ap.add_argument("--lp", default="default")
    ap.add_argument("--epsilon", type=float, default=0.01, help="epsilon of Eq. 11 (the library's default is 0.01)")
    ap.add_argument("--completed-class", action="store_true", help="the named parameter completed_homology_class(true)")
    ap.add_argument("--cgal-data", default="")
    ap.add_argument("--mesh-cache", default="")
    ap.add_argument("--command", default="")
    ap.add_argument("--gaps", default="per-curve", help="gap mode of the generator: per-curve | global")
    ap.add_argument("--straighten", default="on", help="straighten the planted loops: on | off")
    ap.add_argument("--gap-levels", default="", help="comma-separated gap levels instead of the suite's (calibration)")
    ap.add_argument("--only", default="", help="simply-connected | handles: the meshes of one class only")
    ap.add_argument("--regions", default="", help="field | eigen: the region draws instead of the suite's")
    ap.add_argument("--loops-off-regions", default="", help="on | off: route the planted loops off the region curves or not")
    ap.add_argument("--merge", action="store_true")
    ap.add_argument("--summarize", action="store_true")
    ap.add_argument("dirs", nargs="*")
    args = ap.parse_args()
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

    if args.merge or args.summarize:
        rows = []
        srcs = args.dirs if args.merge else [out]
        extra = {}
        for d in srcs:
            rows += read_csv(os.path.join(d, "cases.csv"))
            try:
                s = json.load(open(os.path.join(d, "summary.json")))
                for k in ("suite", "command", "git_commit", "wall_time_seconds", "jobs", "gap_mode", "straighten", "lp_option", "epsilon"):
                    if k in s and k not in extra:
                        extra[k] = s[k]
            except OSError:
                pass
        extra["merged_from"] = srcs if args.merge else extra.get("merged_from")
        rows.sort(key=lambda r: str(r.get("case")))
        write_csv(os.path.join(out, "cases.csv"), rows)
        s = summarize(rows, out, extra)
        plots(rows, out)
        print(json.dumps({k: s[k] for k in ("cases", "genus0_mean_error_percent", "genus0_max_error_percent",
                                            "handles_fraction_under_0_5_percent", "naive_genus0_mean_error_percent")}))
        return 0

    t0 = time.time()
    cases_dir = os.path.join(out, "cases-data")
    gen = [os.path.join(args.build, "swn_bench_gen"), "--suite", args.suite, "--out", cases_dir, "--shard", args.shard]
    if args.cgal_data:
        gen += ["--cgal-data", args.cgal_data]
    if args.mesh_cache:
        gen += ["--mesh-cache", args.mesh_cache]
    gen += ["--gaps", args.gaps, "--straighten", args.straighten]
    if args.gap_levels:
        gen += ["--gap-levels", args.gap_levels]
    if args.only:
        gen += ["--only", args.only]
    if args.regions:
        gen += ["--regions", args.regions]
    if args.loops_off_regions:
        gen += ["--loops-off-regions", args.loops_off_regions]
    print("[bench] generating cases: " + " ".join(gen), file=sys.stderr)
    run(gen)
    t_gen = time.time() - t0
    cases = [l.rstrip("\n").split("\t") for l in open(os.path.join(cases_dir, "index.tsv")) if l.strip()]
    print("[bench] %d cases, generated in %.1f s; solving with %d job(s)" % (len(cases), t_gen, args.jobs), file=sys.stderr)
    rows = []

    def one(i_case):
        i, (cid, cdir) = i_case
        r = solve_case(args, cid, cdir, check_api=(i == 0))
        print("[bench] %3d/%d %-28s %-7s err %7.3f%%  naive %7.3f%%  G %s  %.2f s" % (
            i + 1, len(cases), cid, r.get("status"), r.get("error_percent", float("nan")) if r.get("ok") else float("nan"),
            r.get("naive_error_percent", float("nan")) if r.get("ok") else float("nan"),
            "ok" if r.get("loops_recovered") else "-", r.get("time_swn", float("nan")) if r.get("ok") else float("nan")),
            file=sys.stderr, flush=True)
        return r

    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        rows = list(ex.map(one, enumerate(cases)))
    write_csv(os.path.join(out, "cases.csv"), rows)
    extra = {"suite": args.suite, "shard": args.shard, "jobs": args.jobs, "timeout_seconds": args.timeout,
             "lp_option": args.lp, "epsilon": args.epsilon, "completed_class": args.completed_class, "gap_mode": args.gaps, "gap_levels_option": args.gap_levels, "only": args.only,
             "regions_option": args.regions, "loops_off_regions_option": args.loops_off_regions, "straighten": args.straighten, "command": args.command or " ".join(sys.argv), "git_commit": git_commit(root),
             "generation_seconds": t_gen, "wall_time_seconds": time.time() - t0}
    s = summarize(rows, out, extra)
    plots(rows, out)
    print(json.dumps({k: s[k] for k in ("cases", "genus0_mean_error_percent", "genus0_max_error_percent",
                                        "handles_fraction_under_0_5_percent", "naive_genus0_mean_error_percent")}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
