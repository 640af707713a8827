#!/usr/bin/env python3
"""Regular surfaces of the shipped catalog: builds every map up to a genus with
`tessera regmap surface --json` and reports, per base, how many surfaces are closed, oriented, of
the right genus, with the relations of A, B, C holding and free of self-intersections, with times.

usage: bench/regmap_surfaces.py [--tessera build/native/cli/tessera] [--max-genus 29]
                                [--maps R2.4 R3.1 ...] [--report FILE.md] [-- extra CLI options]
"""
import argparse
import json
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def catalog_maps(max_genus):
    path = os.path.join(ROOT, "data", "regmaps", "catalog_g2-101.tsv")
    maps = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            cols = line.split("\t")
            if int(cols[1]) <= max_genus:
                maps.append((cols[0], int(cols[1]), int(cols[2]), int(cols[3]), int(cols[7]), int(cols[6])))
    return maps


def build(tessera, name, extra):
    start = time.monotonic()
    run = subprocess.run([tessera, "regmap", "surface", name, "--json"] + extra,
                         capture_output=True, text=True)
    wall = time.monotonic() - start
    if run.returncode != 0:
        return {"name": name, "error": run.stderr.strip().splitlines()[-1:], "wall": wall}
    result = json.loads(run.stdout)
    result["wall"] = wall
    return result


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tessera", default=os.path.join(ROOT, "build", "native", "cli", "tessera"))
    parser.add_argument("--max-genus", type=int, default=29)
    parser.add_argument("--maps", nargs="*")
    parser.add_argument("--report")
    args, extra = parser.parse_known_args()
    extra = [a for a in extra if a != "--"]
    names = args.maps or [m[0] for m in catalog_maps(args.max_genus)]
    rows = []
    for i, name in enumerate(names):
        rows.append(build(args.tessera, name, extra))
        print(f"\r{i + 1}/{len(names)} {name}          ", end="", file=sys.stderr)
    print(file=sys.stderr)

    ok = [r for r in rows if "error" not in r]
    good = [r for r in ok if r["closed"] and r["oriented"] and r["relations_hold"]
            and r["genus"] == r["tubes"] - r["junctions"] + 1 and r["quarter_tubes"] == 4 * r["tubes"]]
    free = [r for r in ok if r["self_intersections"] == 0]
    lines = [f"# Regular surfaces: {len(names)} maps" + (f" (catalog up to genus {args.max_genus})" if not args.maps else ""),
             "", f"options: {' '.join(extra) or '(defaults)'}", "",
             f"- built: {len(ok)}, failed: {len(rows) - len(ok)}",
             f"- closed, oriented, genus E - V + 1, 4E quarter tubes, relations of A, B, C: {len(good)}",
             f"- free of self-intersections: {len(free)}",
             f"- total time (the CLI's own, enumeration included): {sum(r['seconds'] for r in ok):.1f} s,"
             f" slowest {max((r['seconds'] for r in ok), default=0):.2f} s", "",
             "| base | maps | self-intersection free | seconds |", "|---|---|---|---|"]
    for base in sorted({r["base"] if not r["base"].startswith("2-") else "2-Platonic" for r in ok}):
        group = [r for r in ok if (r["base"] if not r["base"].startswith("2-") else "2-Platonic") == base]
        lines.append(f"| {base} | {len(group)} | {sum(r['self_intersections'] == 0 for r in group)} |"
                     f" {sum(r['seconds'] for r in group):.1f} |")
    lines += ["", "| map | genus | V | E | base | self-intersecting pairs | symmetries | seconds |",
              "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if "error" in r:
            lines.append(f"| {r['name']} | error: {' '.join(r['error'])} | | | | | | |")
            continue
        lines.append(f"| {r['name']} | {r['genus']} | {r['junctions']} | {r['tubes']} | {r['base']} |"
                     f" {r['self_intersections']} | {r['symmetries_verified']}/{r['symmetries']} |"
                     f" {r['seconds']:.3f} |")
    text = "\n".join(lines) + "\n"
    if args.report:
        with open(args.report, "w") as f:
            f.write(text)
    print("\n".join(lines[:12 + len({r['base'] for r in ok})]))


if __name__ == "__main__":
    main()
