#!/usr/bin/env python3
"""Quad-mesh structure optimization (thesis Ch. 7, issue 40) over a folder of quad meshes: runs
`tessera optimize-quads --json` on every mesh at each alpha (with and without diagonal edges) and
writes one row a run: quads, irregular vertices, the patches of the trivial base complex B and of
the optimized layout, the cut (B / optimized), the layout check, |E_G|, |I|, P1's status, the angle
RSD and the time, beside the thesis's Table 7.1 (its meshes are not these: the figures of
comparable models are quoted for scale).

usage: bench/quad_structure.py [--tessera build/native/cli/tessera] [--meshes DIR]
                               [--alphas 5] [--report FILE.md]
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

THESIS_TABLE_7_1 = [
    ("Botijo", 74, 4957, 164, 27.27, 1.14),
    ("Fertility", 48, 2271, 100, 28.37, 0.78),
    ("Rockerarm", 36, 4524, 64, 28.36, 0.26),
    ("Drill hole", 26, 1368, 61, 22.83, 0.88),
    ("Fandisk", 30, 408, 66, 16.26, 0.18),
    ("Beetle", 56, 259, 156, 15.20, 0.07),
]


def run(tessera, mesh, alpha, diagonals, remesh=None):
    command = [tessera, "optimize-quads", mesh, "--alpha", str(alpha), "--json"]
    if not diagonals:
        command.append("--no-diagonals")
    if remesh:
        command += ["--remesh", remesh]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        return {"error": done.stderr.strip().splitlines()[-1] if done.stderr else "failed"}
    return json.loads(done.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tessera", default=os.path.join(ROOT, "build", "native", "cli", "tessera"))
    parser.add_argument("--meshes", default="/work/shared/quadmeshes")
    parser.add_argument("--alphas", default="5")
    parser.add_argument("--report", default=os.path.join(ROOT, "bench", "report", "quad_structure.md"))
    args = parser.parse_args()
    meshes = sorted(glob.glob(os.path.join(args.meshes, "*.obj")))
    if not meshes:
        sys.exit(f"no .obj quad meshes in {args.meshes}")
    alphas = [float(a) for a in args.alphas.split(",")]
    lines = [
        "# Quad-mesh structure optimization (thesis Ch. 7)",
        "",
        f"`tessera optimize-quads` on the quad meshes of `{args.meshes}`; B is the trivial base complex,",
        "'after' the layout of P1 (exact solver); valid: the project's checker on the layout over the quad",
        "mesh (every patch a disk with four corners, no T-junction). Seconds: the whole run, natively.",
        "",
        "B of remesh: the trivial base complex of the quad mesh `--remesh` makes of the optimized layout",
        "(Ch. 8, about the input's resolution), counted by a second run on it: the optimized layout",
        "realized as a quad mesh of its own.",
        "",
        "| mesh | alpha | diagonals | quads | irregular | B patches | after | cut | valid | E_G | I | P1 | angle RSD % | s | B of remesh |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for mesh in meshes:
        for alpha in alphas:
            for diagonals in (True, False):
                remeshed = os.path.join(tempfile.gettempdir(), "tessera_quad_structure_remesh.obj")
                j = run(args.tessera, mesh, alpha, diagonals, remeshed)
                name = os.path.basename(mesh)
                if "error" in j:
                    lines.append(f"| {name} | {alpha:g} | {diagonals} | error: {j['error']} |")
                    continue
                cut = j["base_complex_patches"] / max(j["patches"], 1)
                again = run(args.tessera, remeshed, alpha, diagonals)
                again_b = again.get("base_complex_patches", "error")
                lines.append(
                    f"| {name} | {alpha:g} | {'yes' if diagonals else 'no'} | {j['quads']:,} | "
                    f"{j['singularities']} | {j['base_complex_patches']:,} | {j['patches']:,} | "
                    f"{cut:.1f}x | {'yes' if j['valid'] else 'NO'} | {j['graph_edges']:,} | "
                    f"{j['conflicts']:,} | {j['matching_status']} | {j['angle_rsd']:.2f} | "
                    f"{j['seconds']['total']:.2f} | {again_b} |")
                print(lines[-1], flush=True)
    lines += [
        "",
        "Thesis Table 7.1 (alpha 5, its own meshes from [BZK09]; B -> optimized, RSD, total seconds):",
        "",
        "| model | S | B patches | optimized | cut | RSD % | s |",
        "|---|---|---|---|---|---|---|",
    ]
    for model, s, b, after, rsd, seconds in THESIS_TABLE_7_1:
        lines.append(f"| {model} | {s} | {b:,} | {after} | {b / after:.1f}x | {rsd} | {seconds} |")
    load = os.getloadavg()
    lines += ["", f"Load average of the machine ({os.cpu_count()} cores) when the runs ended: "
              f"{load[0]:.1f} (1 min), {load[1]:.1f} (5 min); the seconds grow with it."]
    os.makedirs(os.path.dirname(args.report), exist_ok=True)
    with open(args.report, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {args.report}")


if __name__ == "__main__":
    main()
