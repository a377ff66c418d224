#!/usr/bin/env python3
"""The same chains as tools/bench/chains.py derived with SymPy's KanesMethod, for the
operation-count comparison: the mass matrix and forcing vector after common-subexpression
elimination (`sympy.cse`), counted with `count_ops`, and the time SymPy takes.

  python3 tools/bench/sympy_chain.py KIND N
prints: derive_seconds cse_operations q''(initial state, for the cross-check)
"""
import sys
import time

import sympy as sm
import sympy.physics.mechanics as me

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from chains import link_constants, problem  # noqa: E402


def derive(kind, n):
    spec = problem(kind, n)
    planar = kind == "planar"
    per_joint = 3 if kind == "spherical" else 1
    q = me.dynamicsymbols(f"q1:{n * per_joint + 1}")
    u = me.dynamicsymbols(f"u1:{n * per_joint + 1}")
    g = sm.Symbol("g")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    parent, pin = N, O
    bodies, loads = [], []
    values = {g: 9.81}
    for i in range(1, n + 1):
        c = {k: sm.Symbol(k) for k in link_constants(i)}
        values.update({c[k]: v for k, v in link_constants(i).items()})
        m, L, a, b = c[f"m{i}"], c[f"L{i}"], c[f"a{i}"], c[f"b{i}"]
        B = me.ReferenceFrame(f"B{i}")
        if kind == "spherical":
            qs = q[3 * i - 3: 3 * i]
            B.orient_body_fixed(parent, qs, "XYZ")
        else:
            qs = [q[i - 1]]
            axis = "z" if planar else "xyz"[(i - 1) % 3]
            B.orient_axis(parent, getattr(parent, axis), qs[0])
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
        bodies.append(body)
        loads.append((center, -m * g * (N.y if planar else N.z)))
        parent = B
    # Speeds are the coordinates' rates, as in mbd-tutor's default.
    kde = [qi.diff() - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kde)
    kane.kanes_equations(bodies, loads)
    return kane, q, u, values, spec


def main():
    kind, n = sys.argv[1], int(sys.argv[2])
    start = time.perf_counter()
    kane, q, u, values, spec = derive(kind, n)
    mass, forcing = kane.mass_matrix, kane.forcing
    outputs = list(mass) + list(forcing)
    replacements, reduced = sm.cse(outputs)
    ops = sum(sm.count_ops(e) for _, e in replacements) + sum(sm.count_ops(e) for e in reduced)
    seconds = time.perf_counter() - start
    state = {}
    for qi, ui, c in zip(q, u, spec["coordinates"].values()):
        state[qi] = c["initial"]
        state[ui] = c["rate"]
    m_num = sm.Matrix(mass).subs(values).subs(state).evalf()
    f_num = sm.Matrix(forcing).subs(values).subs(state).evalf()
    qdd = m_num.LUsolve(f_num)
    print(f"{seconds:.2f} {ops} " + " ".join(f"{float(x):.6f}" for x in qdd))


if __name__ == "__main__":
    main()
