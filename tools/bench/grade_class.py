#!/usr/bin/env python3
"""A class of 300 graded: the double pendulum with m1 and L1 varied, 300 variants (one per
student, so 300 worked solutions are derived), 300 submissions with two equations of
motion, two answers and a kinematics vector, every fifth equation and every seventh answer
wrong. Prints the time of `grade --batch` and checks the wrong ones were found.

    python3 tools/bench/grade_class.py [--bin target/release/mbd-tutor] [--dir /tmp/grade-class]
"""
import argparse, csv, json, os, resource, subprocess, time

EQUATIONS = [
    "(m1*L1^2/3 + m2*L1^2 + m2*L2^2/3 + m2*L1*L2*cos(q2))*q1'' + (m2*L2^2/3 + m2*L1*L2/2*cos(q2))*q2''"
    " - m2*L1*L2/2*sin(q2)*(2*q1'*q2' + q2'^2) + (m1/2 + m2)*g*L1*sin(q1) + m2*g*L2/2*sin(q1 + q2) = 0",
    "m2*L2^2/3*(q1'' + q2'') + m2*L1*L2/2*(cos(q2)*q1'' + sin(q2)*q1'^2) = -m2*g*L2/2*sin(q1 + q2)",
]
WRONG = "m2*L2^2/3*(q1'' + q2'') + m2*L1*L2/2*cos(q2)*q1'' = -m2*g*L2/2*sin(q1 + q2)"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", default="target/release/mbd-tutor")
    parser.add_argument("--dir", default="/tmp/grade-class")
    args = parser.parse_args()
    os.makedirs(args.dir, exist_ok=True)
    problem = json.load(open("problems/double-pendulum-rods.json"))
    problem["constants"]["m1"] = {"value": 1.2, "vary": [0.8, 1.6], "step": 0.01, "unit": "kg"}
    problem["constants"]["L1"] = {"value": 0.6, "vary": [0.4, 0.8], "step": 0.01, "unit": "m"}
    varied = os.path.join(args.dir, "varied.json")
    json.dump(problem, open(varied, "w"), indent=2)
    variants = os.path.join(args.dir, "variants")
    subprocess.run([args.bin, "variants", varied, "--count", "300", "--seed", "3",
                    "--format", "markdown", "-o", variants], check=True)
    subs = os.path.join(args.dir, "submissions")
    os.makedirs(subs, exist_ok=True)
    rows = list(csv.DictReader(open(os.path.join(variants, "key.csv"))))
    for i, row in enumerate(rows):
        submission = {
            "student": "s%03d" % i, "variant": row["file"],
            "answers": {"0": float(row["0"]) * (1.03 if i % 7 == 0 else 1.0), "1": float(row["1"])},
            "equations": [EQUATIONS[0], WRONG if i % 5 == 0 else EQUATIONS[1]],
            "kinematics": {"B": {"angular_velocity": "(q1'+q2')*N.z"}},
        }
        json.dump(submission, open(os.path.join(subs, "s%03d.json" % i), "w"))
    grades = os.path.join(args.dir, "grades.csv")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([args.bin, "grade", "--batch", subs, "--key", os.path.join(variants, "key.csv"),
                    "-o", grades], check=True)
    elapsed = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    # The CPU seconds of the grading alone (user + system), which a loaded machine moves least.
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    book = list(csv.DictReader(open(grades)))
    wrong_answers = sum(r["answers.0"] == "0.0" for r in book)
    wrong_equations = sum(r["equations[1]"] == "0.0" for r in book)
    assert (len(book), wrong_answers, wrong_equations) == (300, 43, 60), (len(book), wrong_answers, wrong_equations)
    print(f"300 submissions, 300 variants: {elapsed:.2f} s wall, {cpu:.2f} s CPU")


if __name__ == "__main__":
    main()
