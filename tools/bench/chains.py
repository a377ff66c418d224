#!/usr/bin/env python3
"""Chains for the size and speed benchmarks, written both as mbd-tutor problems and as
Pinocchio models, so that one evaluation of q'' can be timed side by side.

Three kinds, each link with full inertia (all six components) and its mass centre off every
axis:
  planar     revolute joints about z, in the x-y plane (2D problem);
  revolute   revolute joints whose axes cycle x, y, z (3D);
  spherical  spherical joints, body-fixed x-y-z angles (3D).

  python3 tools/bench/chains.py write KIND N OUT.json     the problem file
  python3 tools/bench/chains.py write KIND N OUT.json --springs
                                                           with loads: a spring and a damper
                                                           on every coordinate, and a spring
                                                           from the ground to the last link
  python3 tools/bench/chains.py aba KIND N                 Pinocchio's aba, µs per call
"""
import json
import sys
import time


def link_constants(i):
    """Constants of link i (1-based): varied so that no two links are alike."""
    k = 1.0 + 0.1 * i
    return {
        f"m{i}": round(1.0 + 0.2 * i, 6),
        f"L{i}": round(0.5 + 0.1 * i, 6),
        f"a{i}": round(0.05 * i, 6),
        f"b{i}": round(0.03 * i, 6),
        f"Ixx{i}": round(0.02 * k, 6),
        f"Iyy{i}": round(0.025 * k, 6),
        f"Izz{i}": round(0.01 * k, 6),
        f"Ixy{i}": round(0.001 * k, 6),
        f"Ixz{i}": round(0.0015 * k, 6),
        f"Iyz{i}": round(0.0005 * k, 6),
    }


AXES = "xyz"


def problem(kind, n):
    """The mbd-tutor problem: links hang along -z of their own frame (-y when planar)."""
    planar = kind == "planar"
    constants = {"g": 9.81}
    bodies, joints, coordinates = {}, [], {}
    for i in range(1, n + 1):
        constants.update(link_constants(i))
        name, parent = f"B{i}", ("N" if i == 1 else f"B{i - 1}")
        if planar:
            bodies[name] = {
                "mass": f"m{i}",
                "center": f"a{i}*{name}.x - L{i}/2*{name}.y",
                "inertia": f"Izz{i}",
            }
        else:
            bodies[name] = {
                "mass": f"m{i}",
                "center": f"a{i}*{name}.x + b{i}*{name}.y - L{i}/2*{name}.z",
                "inertia": {"xx": f"Ixx{i}", "yy": f"Iyy{i}", "zz": f"Izz{i}",
                            "xy": f"Ixy{i}", "zx": f"Ixz{i}", "yz": f"Iyz{i}"},
            }
        down = f"-L{i - 1}*{parent}.{'y' if planar else 'z'}"
        if kind == "spherical":
            qs = [f"q{3 * i - 2}", f"q{3 * i - 1}", f"q{3 * i}"]
            joint = {"name": f"S{i}", "type": "spherical", "parent": parent, "child": name,
                     "sequence": "xyz", "coordinates": qs}
        else:
            qs = [f"q{i}"]
            axis = "z" if planar else AXES[(i - 1) % 3]
            joint = {"name": f"J{i}", "type": "revolute", "parent": parent, "child": name,
                     "axis": f"{parent}.{axis}", "coordinates": qs}
        if i > 1:
            joint["at"] = down
        joints.append(joint)
        for j, q in enumerate(qs):
            coordinates[q] = {"initial": round(0.1 + 0.05 * (len(coordinates)), 6),
                              "rate": round(0.2 - 0.03 * len(coordinates), 6)}
    return {
        "title": f"{kind} chain of {n} links with full inertia and offset mass centres",
        "dimension": 2 if planar else 3,
        "constants": constants,
        "gravity": f"-g*N.{'y' if planar else 'z'}",
        "coordinates": coordinates,
        "bodies": bodies,
        "joints": joints,
    }


def with_springs(spec, kind, n):
    """The chain with loads: a joint spring and damper on every coordinate, and a spring of
    free length 0.5 from a point of the ground to the last link's mass centre."""
    planar = kind == "planar"
    spec["title"] += ", with springs and dampers"
    spec["constants"].update({"k": 20.0, "c": 0.4, "K": 50.0, "l0": 0.5})
    spec["points"] = {"anchor": {"on": "N", "at": "0.3*N.x" if planar else "0.3*N.x + 0.2*N.y"}}
    loads = []
    for joint in spec["joints"]:
        for q in joint["coordinates"]:
            loads.append({"type": "joint_spring", "joint": joint["name"], "coordinate": q,
                          "stiffness": "k"})
            loads.append({"type": "joint_damper", "joint": joint["name"], "coordinate": q,
                          "coefficient": "c"})
    loads.append({"type": "spring", "between": ["anchor", f"B{n}*"], "stiffness": "K",
                  "free_length": "l0"})
    spec["loads"] = loads
    return spec


def pinocchio_model(kind, n):
    """The same chain as a Pinocchio model (joint frames at the pins, z up, gravity -g z)."""
    import numpy as np
    import pinocchio as pin

    model = pin.Model()
    model.gravity.linear = np.array([0.0, -9.81, 0.0] if kind == "planar" else [0.0, 0.0, -9.81])
    parent = 0
    for i in range(1, n + 1):
        c = link_constants(i)
        m, L, a, b = c[f"m{i}"], c[f"L{i}"], c[f"a{i}"], c[f"b{i}"]
        prev_L = link_constants(i - 1)[f"L{i - 1}"] if i > 1 else 0.0
        if kind == "planar":
            placement = pin.SE3(np.eye(3), np.array([0.0, -prev_L, 0.0]))
            joint = pin.JointModelRZ()
            com = np.array([a, -L / 2, 0.0])
            inertia_c = np.diag([1e-3, 1e-3, c[f"Izz{i}"]])
        else:
            placement = pin.SE3(np.eye(3), np.array([0.0, 0.0, -prev_L]))
            if kind != "spherical":
                joint = [pin.JointModelRX, pin.JointModelRY, pin.JointModelRZ][(i - 1) % 3]()
            com = np.array([a, b, -L / 2])
            ixx, iyy, izz = c[f"Ixx{i}"], c[f"Iyy{i}"], c[f"Izz{i}"]
            ixy, ixz, iyz = c[f"Ixy{i}"], c[f"Ixz{i}"], c[f"Iyz{i}"]
            # The problem format's `xy` is the tensor element itself (minus the product).
            inertia_c = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        inertia = pin.Inertia(m, com, inertia_c)
        if kind == "spherical":
            # Body-fixed x-y-z angles: three revolute joints about x, y, z with massless
            # links in between, the same kinematics as mbd-tutor's x-y-z sequence.
            for k, j in enumerate([pin.JointModelRX(), pin.JointModelRY(), pin.JointModelRZ()]):
                pl = placement if k == 0 else pin.SE3.Identity()
                parent = model.addJoint(parent, j, pl, f"S{i}{'xyz'[k]}")
                if k < 2:
                    model.appendBodyToJoint(parent, pin.Inertia.Zero(), pin.SE3.Identity())
            model.appendBodyToJoint(parent, inertia, pin.SE3.Identity())
        else:
            parent = model.addJoint(parent, joint, placement, f"J{i}")
            model.appendBodyToJoint(parent, inertia, pin.SE3.Identity())
    return model


def aba_microseconds(kind, n, repeats=20000):
    """The fastest of 5 tries of the mean time of one `pin.aba` call, in µs."""
    import numpy as np
    import pinocchio as pin

    model = pinocchio_model(kind, n)
    data = model.createData()
    spec = problem(kind, n)["coordinates"]
    q = np.array([v["initial"] for v in spec.values()])
    v = np.array([v["rate"] for v in spec.values()])
    tau = np.zeros(model.nv)
    best = float("inf")
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(repeats):
            pin.aba(model, data, q, v, tau)
        best = min(best, (time.perf_counter() - start) / repeats * 1e6)
    return best, pin.aba(model, data, q, v, tau)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    command, kind, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
    if command == "write":
        spec = problem(kind, n)
        if "--springs" in sys.argv[5:]:
            spec = with_springs(spec, kind, n)
        with open(sys.argv[4], "w") as out:
            json.dump(spec, out, indent=1)
            out.write("\n")
    elif command == "aba":
        us, qdd = aba_microseconds(kind, n)
        print(f"{us:.3f}")
        print(" ".join(f"{x:.12g}" for x in qdd), file=sys.stderr)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
