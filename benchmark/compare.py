#!/usr/bin/env python3
"""Two or more builds (or settings) of the solver on the same benchmark cases, interleaved case by case.

  compare.py --cases DIR --out OUT NAME=BUILD_DIR[:VAR=VALUE,...] NAME=... [--handles-only] [--only SUBSTRING]
             [--rounds N]

DIR is a `cases-data` folder written by `benchmark/run` (its index.tsv lists the cases); BUILD_DIR holds a
`swn_bench_solve` (benchmark/CMakeLists.txt built from the code to measure); the optional VAR=VALUE pairs are
added to that variant's environment. For every case, every variant runs once per round, in an order that
rotates from case to case, so that the machine's drift falls on all variants alike. Writes OUT/NAME/cases.csv
(the columns of benchmark/run's cases.csv, with `analyze.py --speed OUT/A OUT/B` for the "whole <= 3x the
first solve" table) and prints, per variant, the sums of the residual step and of the whole solve, the cases
whose labels or G differ from the first variant's (hashes printed by swn_bench_solve), and the ratio of the
sums to the first variant's.
"""
import argparse
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench  # noqa: E402  (solve_case, write_csv: the runner's own case solver and CSV writer)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--handles-only", action="store_true")
    ap.add_argument("--only", default="")
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=1200)
    ap.add_argument("variants", nargs="+")
    args = ap.parse_args()

    variants = []
    for v in args.variants:
        name, spec = v.split("=", 1)
        build, _, env = spec.partition(":")
        extra = dict(kv.split("=", 1) for kv in env.split(",") if kv)
        variants.append((name, os.path.abspath(build), extra))
    cases = [l.rstrip("\n").split("\t") for l in open(os.path.join(args.cases, "index.tsv")) if l.strip()]
    if args.only:
        cases = [c for c in cases if args.only in c[0]]
    if args.handles_only:
        cases = [c for c in cases
                 if not json.load(open(os.path.join(c[1], "meta.json"))).get("simply_connected", False)]
    rows = {name: [] for name, _, _ in variants}
    for i, (cid, cdir) in enumerate(cases):
        for r in range(args.rounds):
            k = (i + r) % len(variants)
            for name, build, extra in variants[k:] + variants[:k]:
                saved = {key: os.environ.get(key) for key in extra}
                os.environ.update(extra)
                try:
                    row = bench.solve_case(argparse.Namespace(build=build, lp="default", epsilon=0.01,
                                                              timeout=args.timeout), cid, cdir, check_api=False)
                finally:
                    for key, value in saved.items():
                        if value is None:
                            os.environ.pop(key, None)
                        else:
                            os.environ[key] = value
                row["round"] = r
                rows[name].append(row)
        line = "  ".join("%s %.3f" % (name, rows[name][-1].get("time_residual", float("nan")) or 0)
                         for name, _, _ in variants)
        print("[compare] %3d/%d %-28s residual: %s" % (i + 1, len(cases), cid, line), file=sys.stderr, flush=True)

    first = variants[0][0]
    ref = {(r["case"], r["round"]): r for r in rows[first]}
    sums = {}
    for name, _, _ in variants:
        d = os.path.join(args.out, name)
        os.makedirs(d, exist_ok=True)
        bench.write_csv(os.path.join(d, "cases.csv"), rows[name])
        ok = [r for r in rows[name] if r.get("ok")]
        differ = [r["case"] for r in ok if (r["case"], r["round"]) in ref and
                  (r.get("labels_hash") != ref[(r["case"], r["round"])].get("labels_hash") or
                   r.get("G_hash") != ref[(r["case"], r["round"])].get("G_hash"))]
        sums[name] = (sum(float(r.get("time_residual", 0)) for r in ok), sum(float(r.get("time_swn", 0)) for r in ok))
        print("%-16s cases %d ok %d  residual %.2f s  whole %.2f s  (x%.3f, x%.3f of %s)  labels or G differ: %d %s" % (
            name, len(rows[name]), len(ok), sums[name][0], sums[name][1], sums[name][0] / max(sums[first][0], 1e-9),
            sums[name][1] / max(sums[first][1], 1e-9), first, len(differ), " ".join(sorted(set(differ)))[:400]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
