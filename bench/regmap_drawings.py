#!/usr/bin/env python3
"""Every realized map of the manifest drawn on its target: runs `tessera regmap map <source>
--on <target> --json` for each entry of data/regmaps/realizations.json (two at a time) and counts
the drawings that are right (V, E, F as the catalog says, faces open disks, flags covered once,
closed, oriented, of the map's genus) and those also free of self-intersections, with times and
triangle counts. The failures are listed with their messages.

usage: bench/regmap_drawings.py [--tessera build/native/cli/tessera] [--genus G..H]
                                [--manifest FILE] [--jobs 2] [--report FILE.md]
"""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def draw(tessera, entry):
    start = time.monotonic()
    run = subprocess.run([tessera, "regmap", "map", entry["source"], "--on", entry["target"], "--json"],
                         capture_output=True, text=True)
    wall = time.monotonic() - start
    if run.returncode != 0:
        lines = run.stderr.strip().splitlines()
        return {"entry": entry, "error": lines[-1] if lines else f"exit {run.returncode}", "wall": wall}
    return {"entry": entry, "result": json.loads(run.stdout), "wall": wall}


def right(entry, r):
    return (r["V"] == r["expected"]["V"] and r["E"] == r["expected"]["E"] and
            r["F"] == r["expected"]["F"] and r["faces_are_disks"] and r["covers_once"] and
            r["closed"] and r["oriented"] and r["genus"] == entry["genus"])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tessera", default=os.path.join(ROOT, "build", "native", "cli", "tessera"))
    ap.add_argument("--manifest", default=os.path.join(ROOT, "data", "regmaps", "realizations.json"))
    ap.add_argument("--genus", default="2..101")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--report")
    args = ap.parse_args()
    lo, _, hi = args.genus.partition("..")
    lo, hi = int(lo), int(hi or lo)
    with open(args.manifest) as f:
        entries = [m for m in json.load(f)["maps"] if lo <= m["genus"] <= hi]

    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        runs = list(pool.map(lambda e: draw(args.tessera, e), entries))

    good, clean, failures, walls, triangles = [], [], [], [], []
    for run in runs:
        entry = run["entry"]
        if "error" in run:
            failures.append(f"{entry['source']} on {entry['target']}: {run['error']}")
            continue
        r = run["result"]
        walls.append(run["wall"])
        triangles.append(r["mesh_faces"])
        if not right(entry, r):
            failures.append(f"{entry['source']} on {entry['target']}: V {r['V']}/{r['expected']['V']} "
                            f"F {r['F']}/{r['expected']['F']} disks {r['faces_are_disks']} "
                            f"covered {r['covers_once']} closed {r['closed']} genus {r['genus']}")
            continue
        good.append(entry)
        if r["self_intersections"] == 0:
            clean.append(entry)
        else:
            failures.append(f"{entry['source']} on {entry['target']}: {r['self_intersections']} "
                            "self-intersecting triangle pairs")

    lines = [f"# Realized maps drawn, genus {lo}..{hi}", "",
             f"- drawn: {len(runs)}; right: {len(good)}; right and free of self-intersections: "
             f"{len(clean)} ({sum(1 for e in clean if e['target_kind'] != 'hosohedron')} not on a "
             "hosohedral surface)",
             f"- highest genus right and clean: {max((e['genus'] for e in clean), default=0)}"]
    if walls:
        lines.append(f"- seconds per map: median {statistics.median(walls):.2f}, max {max(walls):.2f}; "
                     f"triangles: median {int(statistics.median(triangles))}, max {max(triangles)}")
    lines += ["", "## Not right or not clean", ""] + [f"- {f}" for f in failures]
    text = "\n".join(lines) + "\n"
    print(text)
    if args.report:
        with open(args.report, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
