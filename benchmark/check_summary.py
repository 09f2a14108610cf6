#!/usr/bin/env python3
"""Sanity check of a benchmark summary (the ctest smoke test runs it on the --quick summary).

  check_summary.py DIR [--min-cases N] [--max-genus0-mean P]

Checks accuracy only (never times): required fields present, every case solved, the free function
agrees with the solver class, gap-free simply connected cases are exact, the genus-0 mean error and
is under a sane bound, on gap-free surfaces with handles the nonbounding chain G is homologous to
the planted loops, G is closed in every case with handles, and SWN beats the naive baseline on
surfaces with handles; the confidence data of the cases with handles: input = J W + G on gap-free input, a
hint on the largest mislabeled region never raises the error. (The error of single
cases with handles is not bounded: a region may legitimately be absorbed into G, see RESULTS.md.) Prints one line per check and 'N passed, N failed'.
"""
import argparse
import csv
import json
import os
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--min-cases", type=int, default=8)
    ap.add_argument("--max-genus0-mean", type=float, default=1.0)
    a = ap.parse_args()
    s = json.load(open(os.path.join(a.dir, "summary.json")))
    rows = list(csv.DictReader(open(os.path.join(a.dir, "cases.csv"))))
    checks = []

    def check(name, ok, detail=""):
        checks.append(ok)
        print("%s: %s %s" % ("PASS" if ok else "FAIL", name, detail))

    required = ["cases", "genus0_mean_error_percent", "genus0_max_error_percent",
                "handles_fraction_under_0_5_percent", "naive_genus0_mean_error_percent", "machine", "date"]
    missing = [k for k in required if k not in s]
    check("summary fields present", not missing, "missing: %s" % missing if missing else "")
    check("enough cases", s.get("cases", 0) >= a.min_cases, "(%s cases)" % s.get("cases"))
    check("every case solved", s.get("cases_ok") == s.get("cases"), str(s.get("failures", ""))[:300])
    check("cases.csv has one row per case", len(rows) == s.get("cases"))
    check("free function == solver class", bool(s.get("api_match")))
    g0 = s.get("genus0_mean_error_percent")
    check("genus-0 mean error < %g %%" % a.max_genus0_mean, g0 is not None and g0 < a.max_genus0_mean, "(%s)" % g0)
    exact = [r for r in rows if r.get("simply_connected") == "1" and float(r.get("gap_level") or 0) == 0]
    check("gap-free simply connected cases are exact",
          bool(exact) and all(float(r["error_percent"]) == 0 for r in exact), "(%d cases)" % len(exact))
    if s.get("handles_cases", 0) > 0:
        h0 = [r for r in rows if r.get("simply_connected") == "0" and float(r.get("gap_level") or 0) == 0]
        check("gap-free cases with handles: G homologous to the planted loops",
              bool(h0) and all(r.get("loops_recovered") == "1" for r in h0), "(%d cases)" % len(h0))
        handles = [r for r in rows if r.get("simply_connected") == "0"]
        open_G = [r["case"] for r in handles if r.get("G_closed") != "1"]
        check("G is closed (relative to the border) in every case with handles", not open_G,
              "(%d cases%s)" % (len(handles), ", open: %s" % open_G[:5] if open_G else ""))
        conf = [r for r in handles if r.get("decomposition_mismatch_edges") not in (None, "")]
        check("confidence computed in every case with handles", len(conf) == len(handles), "(%d of %d)" % (len(conf), len(handles)))
        bad = [r["case"] for r in conf if float(r.get("gap_level") or 0) == 0 and r["decomposition_mismatch_edges"] != "0"]
        check("gap-free cases with handles: input = J W + G on every edge", not bad, "(%s)" % bad[:5])
        worse = [r["case"] for r in conf if float(r["error_hint_largest_mislabeled"]) > float(r["error_percent"]) + 1e-9]
        check("labelling the largest mislabeled region right never raises the error", not worse, "(%s)" % worse[:5])
        nm, sm = s.get("naive_handles_mean_error_percent"), s.get("handles_mean_error_percent")
        check("SWN beats naive rounding on surfaces with handles", sm is not None and nm is not None and sm < nm,
              "(SWN %s, naive %s)" % (sm, nm))
    passed = sum(1 for c in checks if c)
    print("%d passed, %d failed" % (passed, len(checks) - passed))
    return 0 if all(checks) else 1


if __name__ == "__main__":
    sys.exit(main())
