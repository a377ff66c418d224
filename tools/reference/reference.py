#!/usr/bin/env python3
"""Independent reference for `mbd-tutor solve`: accelerations and joint reactions.

    python3 tools/reference/reference.py PROBLEM.json [--state q1=0.3,q1'=1.2]
                                                      [--time T] [--set NAME=VALUE,...]

Prints the JSON of `mbd-tutor solve --format json` (method "reference"). Plain Python,
no dependencies; shares no code with the Rust program. The formulation (rotation
matrices, Taylor jets, virtual power, subtree Newton-Euler) is described in dynamics.py.
"""

import argparse
import json
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import expr  # noqa: E402
from dynamics import solve_state  # noqa: E402
from linalg import SingularError  # noqa: E402
from model import ProblemError, load  # noqa: E402


def parse_pairs(text, flag):
    """`a=1,b'=2` -> {"a": 1.0, "b'": 2.0}."""
    out = {}
    if not text:
        return out
    for item in text.split(","):
        if "=" not in item:
            raise ValueError(f"{flag}: expected NAME=VALUE, found {item!r}")
        k, v = item.split("=", 1)
        out[k.strip()] = float(v)
    return out


def run(path, state=None, time=0.0, overrides=None):
    """Solves one problem file; returns the output dict."""
    prob = load(path, overrides)
    return solve_state(prob, state, time)[0]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("problem")
    ap.add_argument("--state", default="")
    ap.add_argument("--time", type=float, default=0.0)
    ap.add_argument("--set", dest="overrides", default="")
    args = ap.parse_args(argv)
    try:
        state = parse_pairs(args.state, "--state")
        overrides = parse_pairs(args.overrides, "--set")
        out = run(args.problem, state, args.time, overrides)
    except (ProblemError, expr.ExprError, SingularError, ValueError, OSError) as e:
        print(f"reference: {e}", file=sys.stderr)
        return 1
    print(json.dumps(out, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
