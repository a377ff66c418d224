#!/usr/bin/env python3
"""The chains of tools/bench/chains.py derived with SymPy's LagrangesMethod, for the
derivation-time comparison with `derive_own` (benches/derive_own.rs): the Lagrangian of the
same bodies (gravity as each body's potential energy), Lagrange's equations formed, and
their q'' at the initial state as a cross-check.

  python3 tools/bench/sympy_lagrange.py KIND N [--derive-only]
prints: derive_seconds q''(initial state; left out with --derive-only)
"""
import sys
import time

import sympy as sm
import sympy.physics.mechanics as me

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from chains import link_constants, problem  # noqa: E402


def bodies_of(kind, n):
    """The chain's rigid bodies, each with its potential energy of gravity, and its q."""
    planar = kind == "planar"
    per_joint = 3 if kind == "spherical" else 1
    q = me.dynamicsymbols(f"q1:{n * per_joint + 1}")
    g = sm.Symbol("g")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    parent, pin = N, O
    bodies = []
    values = {g: 9.81}
    up = N.y if planar else N.z
    for i in range(1, n + 1):
        c = {k: sm.Symbol(k) for k in link_constants(i)}
        values.update({c[k]: v for k, v in link_constants(i).items()})
        m, L, a, b = c[f"m{i}"], c[f"L{i}"], c[f"a{i}"], c[f"b{i}"]
        B = me.ReferenceFrame(f"B{i}")
        if kind == "spherical":
            B.orient_body_fixed(parent, q[3 * i - 3: 3 * i], "XYZ")
        else:
            axis = "z" if planar else "xyz"[(i - 1) % 3]
            B.orient_axis(parent, getattr(parent, axis), q[i - 1])
        if i == 1:
            joint_point = O
        else:
            prev_L = sm.Symbol(f"L{i - 1}")
            joint_point = pin.locatenew(f"P{i}", -prev_L * (parent.y if planar else parent.z))
            joint_point.v2pt_theory(pin, N, parent)
        pin = joint_point
        if planar:
            center = joint_point.locatenew(f"G{i}", a * B.x - L / 2 * B.y)
            inertia = me.inertia(B, 0, 0, c[f"Izz{i}"])
        else:
            center = joint_point.locatenew(f"G{i}", a * B.x + b * B.y - L / 2 * B.z)
            inertia = me.inertia(B, c[f"Ixx{i}"], c[f"Iyy{i}"], c[f"Izz{i}"],
                                 c[f"Ixy{i}"], c[f"Iyz{i}"], c[f"Ixz{i}"])
        center.v2pt_theory(joint_point, N, B)
        body = me.RigidBody(f"B{i}", center, B, m, (inertia, center))
        body.potential_energy = m * g * center.pos_from(O).dot(up)
        bodies.append(body)
        parent = B
    return N, bodies, q, values


def main():
    kind, n = sys.argv[1], int(sys.argv[2])
    start = time.perf_counter()
    N, bodies, q, values = bodies_of(kind, n)
    lagrangian = me.Lagrangian(N, *bodies)
    method = me.LagrangesMethod(lagrangian, q, frame=N)
    method.form_lagranges_equations()
    mass, forcing = method.mass_matrix, method.forcing
    seconds = time.perf_counter() - start
    print(f"{seconds:.2f}", end=" ", flush=True)
    if "--derive-only" in sys.argv[3:]:
        print()
        return
    spec = problem(kind, n)
    state = {}
    for qi, c in zip(q, spec["coordinates"].values()):
        state[qi.diff()] = c["rate"]
        state[qi] = c["initial"]
    m_num = sm.Matrix(mass).subs(values).subs(state).evalf()
    f_num = sm.Matrix(forcing).subs(values).subs(state).evalf()
    qdd = m_num.LUsolve(f_num)
    print(" ".join(f"{float(x):.6f}" for x in qdd))


if __name__ == "__main__":
    main()
