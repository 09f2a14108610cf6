#!/usr/bin/env python3
"""Why do the failing cases with handles fail? Splits them into ambiguity of the complete input and gaps.

  failure_classes.py RUN_DIR UNBROKEN_DIR SWN [SWN_OPTION ...]

RUN_DIR is a `benchmark/run --paper --only handles` output (cases.csv, cases-data/), UNBROKEN_DIR the same
suite run with `--gap-levels 0` (every curve complete; its cases.csv only). A case fails when its mislabeled area
is 0.5 % or more. A failing case is
  * ambiguous if its draw (mesh and region seed) fails on the complete curves too: the planted loops are then
    not Eq. 11's choice even without gaps (a shorter decomposition of the same curves exists, paper Fig. 7, 18);
  * otherwise caused by the gaps, and then, after solving it again with SWN (the `swn` tool; SWN_OPTIONs are
    passed on, e.g. --completed-class) and reading its nonbounding chain G:
      - lost loop: G has fewer than half as many edges on the curves (planted loops and region curves) as
        the planted loops have;
      - region: otherwise, if G runs along 2 or more edges of the region curves (J of the true labels), in
        place of stretches of the planted loops;
      - labels: otherwise (G follows the planted loops, but labels differ).
Edges of G on vertices made by the tool's refinement of short curve pieces count as off the curves.
Prints one line per failing case and the counts. Pure Python; the solves take about a second per 30k faces.
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from completion_class import key, read_chain, read_off  # noqa: E402


def read_G(path):
    """nonbounding.obj of the swn tool -> {edge (a < b): value along a -> b} in the solved mesh's vertices"""
    ids, chain = [], defaultdict(int)
    for line in open(path):
        if line.startswith("# mesh vertices:"):
            ids = [int(x) for x in line.split(":")[1].split()]
        elif line.startswith("l "):
            poly = [ids[int(x) - 1] for x in line.split()[1:]]
            for a, b in zip(poly, poly[1:]):
                chain[key(a, b)] += 1 if a < b else -1
    return {e: v for e, v in chain.items() if v}


def region_curve(faces, gt):
    """the edges where the true labels jump"""
    sides = defaultdict(list)
    for f, poly in enumerate(faces):
        for i in range(len(poly)):
            sides[key(poly[i], poly[(i + 1) % len(poly)])].append(f)
    return {e for e, s in sides.items() if len(s) == 2 and gt[s[0]] != gt[s[1]]}


def classify(case_dir, swn, options, meshes):
    meta = json.load(open(os.path.join(case_dir, "meta.json")))
    if meta["mesh_file"] not in meshes:
        meshes[meta["mesh_file"]] = read_off(meta["mesh_file"])[1]
    faces = meshes[meta["mesh_file"]]
    gt = [int(x) for x in open(os.path.join(case_dir, "labels_gt.txt")).read().split()]
    planted = read_chain(os.path.join(case_dir, "planted.txt"))
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([swn, meta["mesh_file"], "--curve", os.path.join(case_dir, "curve.txt"), "--output-dir", out,
                        "--quiet"] + options, check=True, stdout=subprocess.DEVNULL)
        G = read_G(os.path.join(out, "nonbounding.obj"))
    region = region_curve(faces, gt)
    on_p = sum(1 for e in G if e in planted)
    on_r = sum(1 for e in G if e in region)
    kind = "lost loop" if 2 * (on_p + on_r) < len(planted) else "region" if on_r >= 2 else "labels"
    return kind, "G %d edges: %d on the planted loops (%d edges), %d on region curves, %d off" % (
        len(G), on_p, len(planted), on_r, len(G) - on_p - on_r)


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    run, unbroken, swn, options = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    draw = lambda case: case.rsplit("_g", 1)[0]
    unbroken_error = {draw(r["case"]): float(r["error_percent"]) for r in csv.DictReader(open(os.path.join(unbroken, "cases.csv")))}
    rows = [r for r in csv.DictReader(open(os.path.join(run, "cases.csv"))) if r["simply_connected"] == "0"]
    counts, meshes = defaultdict(int), {}
    for r in rows:
        error = float(r["error_percent"]) if r["error_percent"] else 100.0
        if error < 0.5:
            counts["under 0.5 %"] += 1
            continue
        if draw(r["case"]) not in unbroken_error:
            raise SystemExit("%s: no case of its draw in %s" % (r["case"], unbroken))
        if unbroken_error[draw(r["case"])] >= 0.5:
            kind, what = "ambiguous", "unbroken error %.2f %%" % unbroken_error[draw(r["case"])]
        else:
            kind, what = classify(os.path.join(run, "cases-data", "cases", r["case"]), swn, options, meshes)
        counts[kind] += 1
        print("%-26s %6.2f %%  %-10s %s" % (r["case"], error, kind, what), flush=True)
    print("cases with handles: %d; %s" % (len(rows), ", ".join("%s %d" % kv for kv in sorted(counts.items()))))


if __name__ == "__main__":
    main()
