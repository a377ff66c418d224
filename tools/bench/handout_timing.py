"""What explain_speed.py and interactive.py both time: whole runs of the binary as wall and
CPU seconds (user + system of the finished child, the operating system's accounting, which
a loaded machine moves least), the problems explain is held against solve on, every bundled
handout, and `variants --count 30` of the heavy symmetric top against 30 explains of it.
"""
import os
import resource
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PROBLEMS = [
    "problems/validation/whipple-bicycle.json",
    "problems/validation/ten-link-chain.json",
    "problems/validation/all-joints-3d.json",
    "problems/rolling-coin.json",
    "problems/validation/statics-tall-block.json",
]
METHODS = ["kane", "motion-law"]


def timed(argv, limit=None):
    """Wall and CPU seconds of one run of argv (output thrown away), and whether it finished
    within `limit` wall seconds (no limit: None)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    finished = True
    try:
        subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=ROOT,
                       timeout=limit)
    except subprocess.TimeoutExpired:
        finished = False
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, finished


def fastest(argv, runs):
    """The least wall and the least CPU seconds over `runs` runs."""
    times = [timed(argv) for _ in range(runs)]
    return min(t[0] for t in times), min(t[1] for t in times)


def every_handout(binary, limit=None):
    """Every bundled handout (problems/*.json and problems/validation/*.json, the four
    methods, worked and student) timed once, slowest CPU first, as
    ((wall, cpu, finished), path, method, student)."""
    handouts = []
    for folder in ["problems", "problems/validation"]:
        for name in sorted(os.listdir(os.path.join(ROOT, folder))):
            if not name.endswith(".json"):
                continue
            path = f"{folder}/{name}"
            for method in ["motion-law", "newton-euler", "kane", "lagrange"]:
                for student in [[], ["--student"]]:
                    argv = [binary, "explain", path, "--method", method] + student
                    handouts.append((timed(argv, limit), path, method, bool(student)))
    handouts.sort(key=lambda h: -h[0][1])
    return handouts


def heavy_top_variants(binary, runs):
    """CPU seconds of `variants --count 30` of the heavy top (LaTeX, fastest of `runs`), and
    of one worked and one student explain of it (LaTeX, fastest of `runs` each)."""
    top = "problems/heavy-symmetric-top.json"
    with tempfile.TemporaryDirectory() as out:
        variants = min(timed([binary, "variants", top, "--count", "30", "--format", "latex",
                              "-o", os.path.join(out, str(k))])[1] for k in range(runs))
    worked = fastest([binary, "explain", top, "--format", "latex"], runs)[1]
    student = fastest([binary, "explain", top, "--format", "latex", "--student"], runs)[1]
    return variants, worked, student
