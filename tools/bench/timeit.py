#!/usr/bin/env python3
"""Time whole processes: several runs after a warm-up, CPU (user + system) and wall seconds;
with --vs a second command run in turn (A B A B ...) and the ratio pair by pair.

    python3 tools/bench/timeit.py -n 5 --warmup 1 -- target/release/mbd-tutor solve F.json
    python3 tools/bench/timeit.py -n 5 --vs "OLD explain F.json -o a.tex" -- NEW explain F.json -o b.tex

Prints the median (and min, max) of each figure; the machine's own accounting of each finished
child (os.wait4), so the figures hold on a shared machine when quoted as medians and ratios.
"""
import argparse
import os
import shlex
import statistics
import subprocess
import time


def run_once(argv):
    start = time.perf_counter()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    return {
        "cpu": usage.ru_utime + usage.ru_stime,
        "wall": wall,
        "status": os.waitstatus_to_exitcode(status),
    }


def summary(name, values, unit):
    return "%-6s median %.3f %s (min %.3f, max %.3f)" % (
        name, statistics.median(values), unit, min(values), max(values))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-n", type=int, default=5, help="counted runs of each command")
    parser.add_argument("--warmup", type=int, default=1, help="runs not counted, first")
    parser.add_argument("--vs", help="a second command, split as a shell splits words")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = [word for word in args.command if word != "--"] if args.command[:1] == ["--"] else args.command
    others = shlex.split(args.vs) if args.vs else None
    for _ in range(args.warmup):
        run_once(command)
        if others:
            run_once(others)
    runs_a, runs_b = [], []
    for _ in range(args.n):
        runs_a.append(run_once(command))
        if others:
            runs_b.append(run_once(others))
    for label, runs in (("A", runs_a), ("B", runs_b)):
        if not runs:
            continue
        print("%s: %s (exit %s)" % (label, " ".join(command if label == "A" else others),
                                    sorted({r["status"] for r in runs})))
        for key, unit in (("cpu", "s"), ("wall", "s")):
            print("  " + summary(key, [r[key] for r in runs], unit))
    if runs_b:
        for key in ("cpu", "wall"):
            ratios = [a[key] / b[key] for a, b in zip(runs_a, runs_b) if b[key] > 0]
            print("  A/B " + summary(key, ratios, ""))


if __name__ == "__main__":
    main()
