#!/usr/bin/env python3
"""The interactive-speed targets in one run, each with its figure and pass or fail:

    python3 tools/bench/interactive.py [BIN] [--runs N] [--limit SECONDS] [--skip-all]

1. `explain` against `solve` of the Whipple bicycle, the ten-link chain, all-joints-3d, the
   rolling coin and the tall block on a rough floor, by Kane and the Motion Law: the
   fastest of N runs (default 3) of each, and explain <= max(3 x solve, 0.3 s). Then
   Lagrange's handout of the spherical chain of 3 against its solve, explain <= max(3 x
   solve, 0.5 s).
2. Every bundled handout (problems/*.json and problems/validation/*.json, the four
   methods, worked and student) once, against 0.5 s; one still running after --limit
   seconds (default 60) is stopped and counted over.
3. `variants --count 30` of the heavy symmetric top (a worked solution and a student
   handout each, LaTeX) against 30 explains of it, worked and student.
4. `grade --batch` of 300 submissions made from the key of 300 variants
   (tools/bench/grade_class.py) under 10 s.

Times are CPU seconds (user + system of the finished child, which a loaded machine moves
least), wall seconds beside them. Prints one summary line per target at the end.
"""
import os
import re
import subprocess
import sys
import tempfile

from handout_timing import METHODS, PROBLEMS, ROOT, every_handout, fastest, heavy_top_variants

HANDOUT_LIMIT = 0.5
GRADE_LIMIT = 10.0
LAGRANGE_CHAIN_LIMIT = 0.5


def verdict(ok):
    return "pass" if ok else "FAIL"


def explain_against_solve(binary, runs):
    """Section 1: the table, and how many pairs are within the bound."""
    print(f"1. explain against solve, fastest of {runs} runs, CPU s (wall s); "
          "bound max(3 x solve, 0.3 s)")
    print("| problem | method | solve | explain | bound | explain / bound | within |")
    print("|---|---|---|---|---|---|---|")
    within = 0
    for problem in PROBLEMS:
        for method in METHODS:
            solve = fastest([binary, "solve", problem, "--method", method], runs)
            explain = fastest([binary, "explain", problem, "--method", method], runs)
            bound = max(3 * solve[1], 0.3)
            ok = explain[1] <= bound
            within += ok
            name = os.path.basename(problem)[:-5]
            print(f"| {name} | {method} | {solve[1]:.3f} ({solve[0]:.3f}) | "
                  f"{explain[1]:.3f} ({explain[0]:.3f}) | {bound:.3f} | "
                  f"{explain[1] / bound:.2f} | {verdict(ok)} |")
    total = len(PROBLEMS) * len(METHODS)
    return f"explain <= max(3 x solve, 0.3 s): {within} of {total}", within == total


def lagrange_chain(binary, runs):
    """Section 1b: Lagrange's handout of the spherical chain of 3 against its solve."""
    chain = "problems/validation/spherical-chain-3.json"
    solve = fastest([binary, "solve", chain, "--method", "lagrange"], runs)
    explain = fastest([binary, "explain", chain, "--method", "lagrange"], runs)
    bound = max(3 * solve[1], LAGRANGE_CHAIN_LIMIT)
    ok = explain[1] <= bound
    print(f"\n1b. Lagrange's spherical chain of 3, fastest of {runs} runs, CPU s (wall s): "
          f"solve {solve[1]:.3f} ({solve[0]:.3f}), explain {explain[1]:.3f} "
          f"({explain[0]:.3f}), bound {bound:.3f}: {verdict(ok)}")
    return (f"Lagrange's spherical chain of 3 explain <= max(3 x solve, "
            f"{LAGRANGE_CHAIN_LIMIT} s): {explain[1]:.3f} s", ok)


def all_handouts(binary, limit):
    """Section 2: every bundled handout once against 0.5 s."""
    handouts = every_handout(binary, limit)
    over = [h for h in handouts if h[0][1] > HANDOUT_LIMIT or not h[0][2]]
    print(f"\n2. every bundled handout once: {len(handouts)} handouts, {len(over)} over "
          f"{HANDOUT_LIMIT} s of CPU; the slowest (CPU s, wall s):")
    for (wall, cpu, finished), path, method, student in handouts[:max(10, len(over))]:
        version = "student" if student else "worked"
        stopped = f"  stopped after {limit} s" if not finished else ""
        print(f"  {cpu:7.3f} {wall:7.3f}  {path} {method} {version}{stopped}")
    return (f"every handout <= {HANDOUT_LIMIT} s: {len(handouts) - len(over)} of "
            f"{len(handouts)}", not over)


def variants_against_explains(binary, runs):
    """Section 3: `variants --count 30` of the heavy top against 30 explains of it."""
    variants, worked, student = heavy_top_variants(binary, runs)
    explains = 30 * (worked + student)
    print(f"\n3. variants --count 30 of the heavy top: {variants:.3f} s CPU; 30 explains, "
          f"worked and student: {explains:.3f} s; ratio {variants / explains:.2f}")
    return (f"variants --count 30 <= 30 explains: {variants:.3f} s against {explains:.3f} s",
            variants <= explains)


def grade_class(binary):
    """Section 4: `grade --batch` of 300 submissions under 10 s."""
    with tempfile.TemporaryDirectory() as out:
        done = subprocess.run([sys.executable, os.path.join(ROOT, "tools/bench/grade_class.py"),
                               "--bin", binary, "--dir", out], cwd=ROOT, check=True,
                              capture_output=True, text=True)
    seconds = float(re.search(r"variants: ([0-9.]+) s", done.stdout).group(1))
    cpu = re.search(r"([0-9.]+) s CPU", done.stdout)
    cpu = f", {float(cpu.group(1)):.2f} s CPU" if cpu else ""
    print(f"\n4. grade --batch, 300 submissions of 300 variants: {seconds:.2f} s wall{cpu}")
    return f"grade --batch of 300 < {GRADE_LIMIT} s: {seconds:.2f} s", seconds < GRADE_LIMIT


def main():
    argv = sys.argv[1:]
    runs, limit = 3, 60.0
    if "--runs" in argv:
        runs = int(argv.pop(argv.index("--runs") + 1))
    if "--limit" in argv:
        limit = float(argv.pop(argv.index("--limit") + 1))
    names = [a for a in argv if not a.startswith("--")]
    binary = os.path.abspath(names[0]) if names else os.path.join(ROOT, "target/release/mbd-tutor")
    results = [explain_against_solve(binary, runs), lagrange_chain(binary, runs)]
    if "--skip-all" not in argv:
        results.append(all_handouts(binary, limit))
    results.append(variants_against_explains(binary, runs))
    results.append(grade_class(binary))
    print("\nsummary:")
    for line, ok in results:
        print(f"  {verdict(ok)}  {line}")


if __name__ == "__main__":
    main()
