#!/usr/bin/env python3
"""The opening table of BENCHMARKS.md: one evaluate-and-solve of q'' by each method of
mbd-tutor against Pinocchio's `aba` (the O(n) articulated-body algorithm) in C++, on the
chains of tools/bench/chains.py, after checking that the q'' agree to 1e-9. The two are
timed alternately, 3 rounds, and each figure is the fastest of its rounds.

  python3 tools/bench/versus_pinocchio.py [--sympy] [--bicycle] [--growth]

Pinocchio comes from the `pin` wheel (`pip install pin`), whose headers and libraries are
under site-packages/cmeel.prefix; Eigen from `libeigen3-dev`. tools/bench/aba.cpp is
compiled with g++ -O3 -DNDEBUG (no -march=native, as our release build) into
target/bench/aba; our figures come from `cargo bench --bench evaluate -- FILE`.

--sympy   also SymPy's KanesMethod on the revolute chain of 6 (tools/bench/sympy_chain.py)
--bicycle also `solve` and `linearize` of the Whipple bicycle, CPU time and peak memory
--growth  also `solve` of spherical chains of 5, 10 and 20 bodies and the growth exponent
"""
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from chains import link_constants, problem  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CHAINS = [("planar", 10), ("planar", 20), ("revolute", 6), ("spherical", 3),
          ("spherical", 6), ("spherical", 10)]
METHODS = ["kane", "newton-euler", "motion-law"]
TOLERANCE = 1e-9
REPEATS = 20000
ROUNDS = 3


def run(command, **kwargs):
    return subprocess.run(command, check=True, capture_output=True, text=True, cwd=ROOT,
                          **kwargs)


def pinocchio_joints(kind, n):
    """The chain as Pinocchio joints: (axis, parent, placement, mass, mass centre, inertia
    about it as xx xy yy xz yz zz). A spherical joint with body-fixed x-y-z angles is three
    revolute joints about x, y, z with massless links between, as mbd-tutor's sequence."""
    joints = []
    for i in range(1, n + 1):
        c = link_constants(i)
        m, L, a, b = c[f"m{i}"], c[f"L{i}"], c[f"a{i}"], c[f"b{i}"]
        prev_L = link_constants(i - 1)[f"L{i - 1}"] if i > 1 else 0.0
        parent = len(joints)
        if kind == "planar":
            place, com = [0.0, -prev_L, 0.0], [a, -L / 2, 0.0]
            inertia = [1e-3, 0.0, 1e-3, 0.0, 0.0, c[f"Izz{i}"]]
            joints.append((2, parent, place, m, com, inertia))
            continue
        place, com = [0.0, 0.0, -prev_L], [a, b, -L / 2]
        # The problem format's `xy` is the tensor element itself (minus the product).
        inertia = [c[f"Ixx{i}"], c[f"Ixy{i}"], c[f"Iyy{i}"], c[f"Ixz{i}"], c[f"Iyz{i}"],
                   c[f"Izz{i}"]]
        if kind == "revolute":
            joints.append(((i - 1) % 3, parent, place, m, com, inertia))
        else:
            zero = (0.0, [0.0] * 3, [0.0] * 6)
            joints.append((0, parent, place) + zero)
            joints.append((1, parent + 1, [0.0] * 3) + zero)
            joints.append((2, parent + 2, [0.0] * 3, m, com, inertia))
    return joints


def aba_binary():
    """tools/bench/aba.cpp compiled against the `pin` wheel, rebuilt when older."""
    import pinocchio

    prefix = pinocchio.__file__.rsplit("/lib/python", 1)[0]
    source = os.path.join(ROOT, "tools/bench/aba.cpp")
    binary = os.path.join(ROOT, "target/bench/aba")
    if not os.path.exists(binary) or os.path.getmtime(binary) < os.path.getmtime(source):
        os.makedirs(os.path.dirname(binary), exist_ok=True)
        defines = ["-DBOOST_MPL_LIMIT_LIST_SIZE=30", "-DBOOST_MPL_LIMIT_VECTOR_SIZE=30",
                   "-DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS",
                   "-DBOOST_FUSION_INVOKE_MAX_ARITY=12"]
        run(["g++", "-O3", "-DNDEBUG", "-std=c++17", *defines, f"-I{prefix}/include",
             "-I/usr/include/eigen3", source, "-o", binary, f"-L{prefix}/lib",
             f"-Wl,-rpath,{prefix}/lib", "-lpinocchio_default"])
    return binary


def aba(kind, n, spec):
    """Pinocchio's µs per `aba` call and its q''."""
    gravity = "0 -9.81 0" if kind == "planar" else "0 0 -9.81"
    joints = pinocchio_joints(kind, n)
    lines = [f"{REPEATS} {gravity} {len(joints)}"]
    for axis, parent, place, m, com, inertia in joints:
        numbers = [axis, parent, *place, m, *com, *inertia]
        lines.append(" ".join(repr(x) for x in numbers))
    lines.append(" ".join(repr(c["initial"]) for c in spec["coordinates"].values()))
    lines.append(" ".join(repr(c["rate"]) for c in spec["coordinates"].values()))
    out = run([aba_binary()], input="\n".join(lines) + "\n").stdout.split("\n")
    return float(out[0]), [float(x) for x in out[1].split()]


def ours(path):
    """Per method: (µs of one evaluate-and-solve, operations, q'') from the evaluate bench."""
    out = run(["cargo", "bench", "--quiet", "--bench", "evaluate", "--", path]).stdout
    rows, header = {}, None
    for line in out.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells and cells[0] == "method":
            # Columns by their headings: the bench may print more than these.
            header = {name: i for i, name in enumerate(cells)}
        elif header and cells and cells[0] in METHODS:
            rows[cells[0]] = (float(cells[header["evaluate and solve (µs)"]]),
                              int(cells[header["operations"]]),
                              [float(x) for x in cells[header["q''"]].split()])
    return rows


def chains_table():
    print("| chain | dof | Pinocchio `aba` (µs) | "
          + " | ".join(f"{m} (µs, ratio)" for m in METHODS) + " | largest q'' difference |")
    print("|---|---|---|" + "---|" * len(METHODS) + "---|")
    failed = False
    for kind, n in CHAINS:
        spec = problem(kind, n)
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            import json
            json.dump(spec, f)
        # Alternating, each figure the fastest of its rounds: the machine's speed drifts.
        theirs_us, rows = float("inf"), {}
        for _ in range(ROUNDS):
            us, theirs = aba(kind, n, spec)
            theirs_us = min(theirs_us, us)
            for method, row in ours(f.name).items():
                if method not in rows or row[0] < rows[method][0]:
                    rows[method] = row
        os.unlink(f.name)
        cells, worst = [], 0.0
        for method in METHODS:
            us, _, qdd = rows[method]
            worst = max(worst, max(abs(x - y) / max(1.0, abs(y)) for x, y in zip(qdd, theirs)))
            cells.append(f"{us:.2f}, {us / theirs_us:.2f}×")
        failed |= worst > TOLERANCE
        print(f"| {kind} {n} | {len(theirs)} | {theirs_us:.2f} | " + " | ".join(cells)
              + f" | {worst:.1e} |")
    if failed:
        sys.exit(f"q'' differ from Pinocchio's by more than {TOLERANCE}")


def timed(args):
    """CPU seconds and peak MB of one run of the release binary. The CPU time comes from
    the kernel's accounting of the child (to the microsecond): /usr/bin/time rounds to
    0.01 s, coarser than a 5-body chain's whole run."""
    import resource
    binary = os.path.join(ROOT, "target/release/mbd-tutor")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    err = run(["/usr/bin/time", "-f", "%M", binary, *args]).stderr.split()
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, float(err[-1]) / 1024


def median_of_3(args):
    runs = sorted(timed(args) for _ in range(3))
    return runs[1]


def median_of_5(args):
    runs = sorted(timed(args) for _ in range(5))
    return runs[2]


def bicycle():
    run(["cargo", "build", "--release", "--quiet", "--bin", "mbd-tutor"])
    path = "problems/validation/whipple-bicycle.json"
    solve = median_of_3(["solve", path, "--method", "kane"])
    linear = median_of_3(["linearize", path, "--method", "kane"])
    print(f"\nWhipple bicycle, median of 3: solve {solve[0]:.2f} s CPU {solve[1]:.0f} MB; "
          f"linearize {linear[0]:.2f} s CPU {linear[1]:.0f} MB "
          f"({linear[0] / solve[0]:.1f}× solve)")


def growth():
    run(["cargo", "build", "--release", "--quiet", "--bin", "mbd-tutor"])
    times = {}
    for n in (5, 10, 20):
        import json
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            json.dump(problem("spherical", n), f)
        for method in METHODS:
            times[(n, method)] = median_of_5(["solve", f.name, "--method", method])
        os.unlink(f.name)
    print("\n| `solve`, spherical chain | " + " | ".join(METHODS) + " |")
    print("|---|" + "---|" * len(METHODS))
    for n in (5, 10, 20):
        print(f"| {n} bodies | " + " | ".join(
            f"{times[(n, m)][0]:.3f} s, {times[(n, m)][1]:.0f} MB" for m in METHODS) + " |")
    print("| exponent 5 → 20 | " + " | ".join(
        f"{math.log(times[(20, m)][0] / times[(5, m)][0]) / math.log(4):.2f}"
        for m in METHODS) + " |")


def sympy():
    out = run([sys.executable, "tools/bench/sympy_chain.py", "revolute", "6"]).stdout.split()
    print(f"\nSymPy KanesMethod + cse, revolute chain of 6: {float(out[0]):.1f} s, "
          f"{out[1]} operations")


def main():
    flags = set(sys.argv[1:])
    unknown = flags - {"--sympy", "--bicycle", "--growth"}
    if unknown:
        sys.exit(__doc__)
    chains_table()
    if "--sympy" in flags:
        sympy()
    if "--bicycle" in flags:
        bicycle()
    if "--growth" in flags:
        growth()


if __name__ == "__main__":
    main()
