#!/usr/bin/env python3
"""Times `explain` against `solve` of the same problem by the same method.

    python3 tools/bench/explain_speed.py [BIN] [--runs N] [--all] [--variants] [--grade]
    python3 tools/bench/explain_speed.py NEW --old OLD [--runs N]

For the Whipple bicycle, the ten-link chain, all-joints-3d, the rolling coin and the tall
block on a rough floor (two sticking contacts), by Kane and the Motion Law: the fastest of N runs (default 3) of `explain` (Markdown, to a null
output) and of `solve`, each as wall seconds and as CPU seconds (user + system, the
operating system's accounting of the finished child, which a loaded machine moves less),
and the ratio explain / max(solve, 0.1 s) against the target of 3. With --all, every
bundled handout (problems/*.json and problems/validation/*.json, every method, worked
and student, Lagrange's too) once, the slowest listed against the target of 0.5 s. With
--variants, `variants --count 30` of the heavy symmetric top (a worked solution and a
student handout each, LaTeX) against 30 explains of it, worked and student. With --grade,
`grade --batch` of a class of 300 (tools/bench/grade_class.py). With --old OLD, the two
binaries side by side instead: for each problem and method, each run of OLD followed by
one of NEW, so that both see the same load; CPU seconds, fastest of N each.
"""
import os
import subprocess
import sys

from handout_timing import (METHODS, PROBLEMS, ROOT, every_handout, fastest, heavy_top_variants,
                            timed)


def side_by_side(old, new, runs):
    """explain and solve of OLD and NEW in turn, fastest CPU seconds of `runs` each."""
    print(f"old {old}, new {new}: CPU seconds (user + system), fastest of {runs} runs each, "
          "the two binaries in turn; bound max(3 x solve, 0.3 s)")
    print("| problem | method | solve, old / new | explain, old | explain, new | bound | "
          "within, new |")
    print("|---|---|---|---|---|---|---|")
    for problem in PROBLEMS:
        for method in METHODS:
            cpu = {}
            for command in ["solve", "explain"]:
                times = {old: [], new: []}
                for _ in range(runs):
                    for binary in (old, new):
                        times[binary].append(timed([binary, command, problem,
                                                    "--method", method])[1])
                cpu[command] = (min(times[old]), min(times[new]))
            bound = max(3 * cpu["solve"][1], 0.3)
            explain = cpu["explain"][1]
            within = "yes" if explain <= bound else f"no ({explain / bound:.1f}x)"
            name = os.path.basename(problem)[:-5]
            print(f"| {name} | {method} | {cpu['solve'][0]:.3f} / {cpu['solve'][1]:.3f} | "
                  f"{cpu['explain'][0]:.3f} | {explain:.3f} | {bound:.2f} | {within} |")


def main():
    argv = sys.argv[1:]
    runs = 3
    if "--runs" in argv:
        runs = int(argv.pop(argv.index("--runs") + 1))
    old = argv.pop(argv.index("--old") + 1) if "--old" in argv else None
    args = [a for a in argv if not a.startswith("--")]
    binary = os.path.abspath(args[0]) if args else os.path.join(ROOT, "target/release/mbd-tutor")
    if old is not None:
        side_by_side(os.path.abspath(old), binary, runs)
        return
    print(f"explain against solve, fastest of {runs} runs, seconds (wall / cpu); "
          "target explain <= max(3 x solve, 0.3 s)")
    print("| problem | method | solve wall | solve cpu | explain wall | explain cpu | "
          "cpu ratio | within |")
    print("|---|---|---|---|---|---|---|---|")
    for problem in PROBLEMS:
        for method in METHODS:
            solve = fastest([binary, "solve", problem, "--method", method], runs)
            explain = fastest([binary, "explain", problem, "--method", method], runs)
            bound = max(3 * solve[1], 0.3)
            ratio = explain[1] / max(solve[1], 0.1)
            name = os.path.basename(problem)[:-5]
            print(f"| {name} | {method} | {solve[0]:.3f} | {solve[1]:.3f} | "
                  f"{explain[0]:.3f} | {explain[1]:.3f} | {ratio:.1f} | "
                  f"{'yes' if explain[1] <= bound else 'no'} |")
    if "--variants" in sys.argv:
        variants_against_explains(binary, runs)
    if "--grade" in sys.argv:
        subprocess.run([sys.executable, os.path.join(ROOT, "tools/bench/grade_class.py"),
                        "--bin", binary], cwd=ROOT, check=True)
    if "--all" not in sys.argv:
        return
    handouts = every_handout(binary)
    over = [h for h in handouts if h[0][1] > 0.5]
    print(f"\n{len(handouts)} handouts, {len(over)} over 0.5 s of CPU; the slowest ten (wall / cpu):")
    for (wall, cpu, _), path, method, student in handouts[:10]:
        version = "student" if student else "worked"
        print(f"  {cpu:6.3f} cpu {wall:6.3f} wall  {path} {method} {version}")


def variants_against_explains(binary, runs):
    """CPU seconds of `variants --count 30` of the heavy top against 30 explains of it."""
    variants, worked, student = heavy_top_variants(binary, runs)
    print(f"\nvariants --count 30 of the heavy top: {variants:.3f} s cpu; 30 explains "
          f"{30 * worked:.3f} s (worked) and {30 * (worked + student):.3f} s (worked and "
          f"student); ratio {variants / (30 * (worked + student)):.2f}")


if __name__ == "__main__":
    main()
