#!/usr/bin/env python3
"""Compares `mbd-tutor solve` with the independent reference at random states.

    python3 tools/reference/compare.py [--methods motion-law,newton-euler,kane,lagrange]
        [--states K] [--seed S] [--bin target/release/mbd-tutor] [--tol 1e-6]
        [--time T] [--set NAME=VALUE,...] PROBLEM.json...

For each problem and each of K seeded random states (every coordinate and rate drawn
uniformly within +-1 of its initial value and rate), runs the reference and
`BIN solve PROBLEM --method M --state ... --time T --format json`, and reports the largest
relative difference per problem and method. Exits 1 when any difference exceeds --tol
or a run fails, 2 on a usage error (such as a missing binary).

Relative difference of a value against the reference r: |x - r| / (|r| + 1e-3 * s),
where s is the largest magnitude in the same group (all accelerations; one joint's
force; one joint's moment), so components that should vanish are judged against the
size of their group rather than against zero; and s is at least 1e-3 of the largest
magnitude in the whole output, so a group that should vanish entirely (the reaction of
a free joint) is judged against the output's size rather than against rounding noise.
"""

import argparse
import json
import os
import random
import subprocess
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from dynamics import solve_state  # noqa: E402
from model import load  # noqa: E402
from reference import parse_pairs  # noqa: E402

FLOOR = 1e-3
ABS_FLOOR = 1e-6


def group_diffs(label, got, ref, overall, names=None):
    """[(relative difference, description)] for two equal-length lists."""
    scale = max([abs(x) for x in ref] + [0.0])
    out = []
    for i, (x, r) in enumerate(zip(got, ref)):
        den = abs(r) + max(FLOOR * scale, ABS_FLOOR * overall)
        if den == 0.0:
            d = 0.0 if x == 0.0 else float("inf")
        else:
            d = abs(x - r) / den
        where = f"{names[i]}''" if names else f"{label}[{i}]"
        out.append((d, f"{where}: got {x:.12g}, reference {r:.12g}"))
    return out


def flatten(out):
    yield 0.0
    yield from out["accelerations"].values()
    for r in out["reactions"].values():
        yield from r["force"]
        yield from r["moment"]


def compare_outputs(got, ref):
    """All relative differences between a `solve --format json` output and the reference."""
    diffs = []
    names = list(ref["accelerations"])
    missing = [n for n in names if n not in got.get("accelerations", {})]
    if missing:
        return [(float("inf"), f"accelerations missing {missing}")]
    overall = max(abs(x) for x in flatten(ref))
    diffs += group_diffs("accelerations", [got["accelerations"][n] for n in names],
                         [ref["accelerations"][n] for n in names], overall, names)
    for joint, r in ref["reactions"].items():
        g = got.get("reactions", {}).get(joint)
        if g is None:
            diffs.append((float("inf"), f"reaction {joint} missing"))
            continue
        for key in ("force", "moment"):
            diffs += group_diffs(f"{joint}.{key}", g[key], r[key], overall)
    return diffs


def number(value):
    return value if isinstance(value, (int, float)) else 0.0


def random_states(prob, k, rng):
    states = []
    for _ in range(k):
        s = {}
        for name in prob.coords:
            decl = prob.declared_coords.get(name, {})
            # A value written as an expression (a rate of "-v/rR") is a state like any
            # other here: the states are random about the number, or about zero.
            s[name] = number(decl.get("initial")) + rng.uniform(-1.0, 1.0)
            s[name + "'"] = number(decl.get("rate")) + rng.uniform(-1.0, 1.0)
        states.append(s)
    return states


def run_binary(binary, path, method, state, time, overrides):
    cmd = [binary, "solve", path, "--method", method, "--format", "json", "--time", repr(time)]
    if state:
        cmd += ["--state", ",".join(f"{k}={v!r}" for k, v in state.items())]
    if overrides:
        cmd += ["--set", overrides]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if proc.returncode != 0:
        raise RuntimeError(f"exit {proc.returncode}: {proc.stderr.strip()[:500]}")
    return json.loads(proc.stdout)


def is_constrained(path):
    """Whether the problem uses the constraint extension (closures, constraints, prescribed
    motion or held coordinates, Coulomb friction on a joint), which the reference lacks."""
    with open(path, encoding="utf-8") as f:
        raw = json.load(f)
    motion = any(isinstance(c, dict) and ("motion" in c or c.get("held"))
                 for c in raw.get("coordinates", {}).values())
    rough = any(isinstance(j, dict) and "friction" in j for j in raw.get("joints", []))
    return bool(raw.get("closures") or raw.get("constraints") or motion or rough)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("problems", nargs="+")
    ap.add_argument("--methods", default="motion-law,newton-euler,kane,lagrange")
    ap.add_argument("--states", type=int, default=5)
    ap.add_argument("--seed", type=int, default=12345)
    ap.add_argument("--bin", default="target/release/mbd-tutor")
    ap.add_argument("--tol", type=float, default=1e-6)
    ap.add_argument("--time", type=float, default=0.0)
    ap.add_argument("--set", dest="overrides", default="")
    ap.add_argument("-v", "--verbose", action="store_true", help="print the worst value of each run")
    args = ap.parse_args(argv)
    if not (os.path.isfile(args.bin) and os.access(args.bin, os.X_OK)):
        print(f"compare: no executable at {args.bin} (build it, or pass --bin)", file=sys.stderr)
        return 2
    methods = [m for m in args.methods.split(",") if m]
    overrides = parse_pairs(args.overrides, "--set")
    failed = False
    print(f"{'problem':40s} {'method':13s} {'max rel diff':>12s}  worst")
    for path in args.problems:
        name = os.path.basename(path)
        if is_constrained(path):
            # Closures, constraints and prescribed motion are checked by the hand
            # derivations of tests/constraints.rs; this solver knows open trees only.
            print(f"{name:40s} {'reference':13s} {'skipped':>12s}  constrained (see tests/constraints.rs, tests/slider_friction.rs)")
            continue
        try:
            prob = load(path, overrides)
        except Exception as e:  # report and go on with the other problems
            print(f"{name:40s} {'reference':13s} {'ERROR':>12s}  {e}")
            failed = True
            continue
        rng = random.Random(f"{args.seed}:{name}")
        states = random_states(prob, args.states, rng)
        refs = []
        for s in states:
            try:
                refs.append(solve_state(prob, s, args.time)[0])
            except Exception as e:
                print(f"{name:40s} {'reference':13s} {'ERROR':>12s}  {e} at {s}")
                refs.append(None)
        for method in methods:
            worst = (0.0, "")
            error = None
            for s, ref in zip(states, refs):
                if ref is None:
                    continue
                try:
                    got = run_binary(args.bin, path, method, s, args.time, args.overrides)
                except (RuntimeError, ValueError, subprocess.TimeoutExpired) as e:
                    error = str(e)
                    break
                for d, what in compare_outputs(got, ref):
                    if d > worst[0] or not worst[1]:
                        worst = (d, what)
            if error is not None:
                failed = True
                print(f"{name:40s} {method:13s} {'ERROR':>12s}  {error}")
                continue
            bad = worst[0] > args.tol
            failed |= bad
            detail = worst[1] if (bad or args.verbose) else ""
            print(f"{name:40s} {method:13s} {worst[0]:12.3e}  {'FAIL ' if bad else ''}{detail}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
