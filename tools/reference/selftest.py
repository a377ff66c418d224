#!/usr/bin/env python3
"""Checks the reference against closed forms derived by hand (written out below), and
against conservation of energy and Lagrange's equations on every case in cases/.

    python3 tools/reference/selftest.py

Plain asserts; problem files are written to a temporary folder.
"""

import glob
import json
import math
import os
import random
import sys
import tempfile

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from dynamics import State, solve_state  # noqa: E402
from linalg import cross, dot, mm, mt, mtv, mv, vadd, vscale, vsub  # noqa: E402
from model import JOINT_KINDS, load  # noqa: E402

TMP = tempfile.mkdtemp(prefix="mbd-reference-")
TOL = 1e-9


def close(a, b, tol=TOL, what=""):
    scale = max(1.0, abs(a), abs(b))
    assert abs(a - b) <= tol * scale, f"{what}: {a!r} != {b!r} (diff {a - b:.3e})"


def close_vec(a, b, tol=TOL, what=""):
    for i, (x, y) in enumerate(zip(a, b)):
        close(x, y, tol, f"{what}[{i}]")


def solve(problem, state, t=0.0):
    path = os.path.join(TMP, "p.json")
    with open(path, "w") as f:
        json.dump(problem, f)
    return solve_state(load(path), state, t)[0]


def rot(axis, a):
    """Elementary rotation matrices written out by hand."""
    c, s = math.cos(a), math.sin(a)
    if axis == "x":
        return [[1, 0, 0], [0, c, -s], [0, s, c]]
    if axis == "y":
        return [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def omega_dot(omega, q, u, qdd, h=1e-6):
    """d/dt of a hand-written body-frame angular velocity omega(q, u): the q-derivatives by
    central differences (the formula is by hand; only its derivative is numeric), the
    u-part exactly since omega is linear in u."""
    n = len(q)
    out = omega(q, qdd)
    for i in range(n):
        qp = list(q)
        qm = list(q)
        qp[i] += h
        qm[i] -= h
        d = vscale(1.0 / (2 * h), vsub(omega(qp, u), omega(qm, u)))
        out = vadd(out, vscale(u[i], d))
    return out


# ---------------------------------------------------------------- planar closed forms

def test_simple_pendulum():
    # Particle of mass m at distance L below the pin: q'' = -(g/L) sin q.
    # Bob at r = L (sin q, -cos q); a = L q'' (cos q, sin q) + L q'^2 (-sin q, cos q);
    # pin force on the bob R = m a - m g = m a + (0, m g); its moment about the pin is 0.
    m, L, g = 1.7, 0.8, 9.81
    p = {"title": "pendulum", "dimension": 2, "constants": {"m": m, "L": L, "g": g},
         "gravity": "-g*N.y",
         "bodies": {"A": {"mass": "m", "center": "-L*A.y", "inertia": 0}},
         "joints": [{"name": "O", "type": "revolute", "parent": "N", "child": "A",
                     "axis": "N.z", "coordinates": ["q"]}],
         "find": {"reactions": ["O"]}}
    for q, u in [(0.3, 1.1), (-2.0, 0.4), (3.0, -2.5)]:
        out = solve(p, {"q": q, "q'": u})
        qdd = -(g / L) * math.sin(q)
        close(out["accelerations"]["q"], qdd, what="pendulum q''")
        a = [L * qdd * math.cos(q) - L * u * u * math.sin(q),
             L * qdd * math.sin(q) + L * u * u * math.cos(q)]
        r = out["reactions"]["O"]
        close_vec(r["force"], [m * a[0], m * a[1] + m * g, 0.0], what="pendulum pin force")
        close_vec(r["moment"], [0.0, 0.0, 0.0], what="pendulum pin moment")
    # The same pendulum as a uniform rod laid along A.x, angle from N.x, rod hanging at
    # q = -pi/2: q'' = -(3 g / 2 L) cos q; mass center at L/2 (cos q, sin q).
    p["bodies"]["A"] = {"mass": "m", "center": "L/2*A.x", "inertia": "m*L^2/12"}
    for q, u in [(0.3, 1.1), (-1.0, -0.7)]:
        out = solve(p, {"q": q, "q'": u})
        qdd = -(3 * g / (2 * L)) * math.cos(q)
        close(out["accelerations"]["q"], qdd, what="rod q''")
        a = [L / 2 * (-qdd * math.sin(q) - u * u * math.cos(q)),
             L / 2 * (qdd * math.cos(q) - u * u * math.sin(q))]
        close_vec(out["reactions"]["O"]["force"], [m * a[0], m * a[1] + m * g, 0.0], what="rod pin")


def test_double_pendulum():
    # Point masses m1, m2 on massless rods L1, L2; absolute angles th1 = q1, th2 = q1 + q2
    # from the downward vertical.  The textbook result (e.g. Lagrange, any dynamics text):
    #   den = 2 m1 + m2 - m2 cos(2 th1 - 2 th2)
    #   th1'' = (-g (2 m1 + m2) sin th1 - m2 g sin(th1 - 2 th2)
    #            - 2 sin(th1 - th2) m2 (th2'^2 L2 + th1'^2 L1 cos(th1 - th2))) / (L1 den)
    #   th2'' = 2 sin(th1 - th2) (th1'^2 L1 (m1 + m2) + g (m1 + m2) cos th1
    #            + th2'^2 L2 m2 cos(th1 - th2)) / (L2 den)
    m1, m2, L1, L2, g = 1.3, 0.7, 0.9, 0.6, 9.81
    p = {"title": "double pendulum", "dimension": 2,
         "constants": {"m1": m1, "m2": m2, "L1": L1, "L2": L2, "g": g},
         "gravity": "-g*N.y",
         "bodies": {"A": {"mass": "m1", "center": "-L1*A.y", "inertia": 0},
                    "B": {"mass": "m2", "center": "-L2*B.y", "inertia": 0}},
         "joints": [
             {"name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z",
              "coordinates": ["q1"]},
             {"name": "P", "type": "revolute", "parent": "A", "child": "B", "axis": "A.z",
              "at": "-L1*A.y", "coordinates": ["q2"]}]}
    rng = random.Random(1)
    for _ in range(5):
        q1, q2, u1, u2 = (rng.uniform(-2, 2) for _ in range(4))
        out = solve(p, {"q1": q1, "q2": q2, "q1'": u1, "q2'": u2})
        t1, t2, w1, w2 = q1, q1 + q2, u1, u1 + u2
        den = 2 * m1 + m2 - m2 * math.cos(2 * t1 - 2 * t2)
        a1 = (-g * (2 * m1 + m2) * math.sin(t1) - m2 * g * math.sin(t1 - 2 * t2)
              - 2 * math.sin(t1 - t2) * m2 * (w2 ** 2 * L2 + w1 ** 2 * L1 * math.cos(t1 - t2))) / (L1 * den)
        a2 = 2 * math.sin(t1 - t2) * (w1 ** 2 * L1 * (m1 + m2) + g * (m1 + m2) * math.cos(t1)
                                       + w2 ** 2 * L2 * m2 * math.cos(t1 - t2)) / (L2 * den)
        close(out["accelerations"]["q1"], a1, what="double pendulum q1''")
        close(out["accelerations"]["q2"], a2 - a1, what="double pendulum q2''")


def test_cart_pole():
    # Cart M on a horizontal rail (x), pendulum particle m at distance l, th from the
    # downward vertical, horizontal force F cos(w t) on the cart applied h above its center.
    #   (M + m) x'' + m l cos th th'' - m l sin th th'^2 = F
    #   m l cos th x'' + m l^2 th'' + m g l sin th = 0
    # =>  x'' = (F + m sin th (g cos th + l th'^2)) / (M + m sin^2 th),
    #     th'' = -(cos th x'' + g sin th) / l.
    # Rail reaction on the cart (subtree cart + pendulum): along x it is 0 (free direction);
    # along y, N = (M + m) g + m l (th'' sin th + th'^2 cos th); the moment about the cart
    # origin is h F (the pendulum's own moment balance is its equation of motion).
    M, m, l, g, F, w, h = 2.0, 0.5, 0.7, 9.81, 3.0, 1.3, 0.2
    p = {"title": "cart-pole", "dimension": 2,
         "constants": {"M": M, "m": m, "l": l, "g": g, "F": F, "w": w, "h": h},
         "gravity": "-g*N.y",
         "bodies": {"C": {"mass": "M", "inertia": "M/10"},
                    "P": {"mass": "m", "center": "-l*P.y", "inertia": 0}},
         "joints": [
             {"name": "rail", "type": "prismatic", "parent": "N", "child": "C", "axis": "N.x",
              "coordinates": ["x"]},
             {"name": "pin", "type": "revolute", "parent": "C", "child": "P", "axis": "C.z",
              "coordinates": ["th"]}],
         "loads": [{"type": "force", "on": "C", "at": "h*C.y", "vector": "F*cos(w*t)*N.x"}],
         "find": {"reactions": ["rail", "pin"]}}
    for th, u, x, tm in [(0.4, 1.2, 0.3, 0.0), (2.5, -0.3, -1.0, 0.7)]:
        out = solve(p, {"x": x, "th": th, "x'": 0.9, "th'": u}, tm)
        f = F * math.cos(w * tm)
        s, c = math.sin(th), math.cos(th)
        xdd = (f + m * s * (g * c + l * u * u)) / (M + m * s * s)
        thdd = -(c * xdd + g * s) / l
        close(out["accelerations"]["x"], xdd, what="cart x''")
        close(out["accelerations"]["th"], thdd, what="cart th''")
        rail = out["reactions"]["rail"]
        close_vec(rail["force"], [0.0, (M + m) * g + m * l * (thdd * s + u * u * c), 0.0], what="rail force")
        close_vec(rail["moment"], [0.0, 0.0, h * f], what="rail moment")
        # Pin force on the pendulum: m a_bob - m g, bob at (x + l s, -l c).
        a = [xdd + l * (thdd * c - u * u * s), l * (thdd * s + u * u * c)]
        close_vec(out["reactions"]["pin"]["force"], [m * a[0], m * a[1] + m * g, 0.0], what="pin force")


def bead_problem(dimension):
    rod_inertia = "Ir" if dimension == 2 else {"xx": "Ir/5", "yy": "Ir", "zz": "Ir"}
    return {"title": "bead on a rotating rod", "dimension": dimension,
            "constants": {"m": 0.3, "mr": 2.0, "Ir": 0.4},
            "bodies": {"R": {"mass": "mr", "inertia": rod_inertia},
                       "B": {"mass": "m", "inertia": 0 if dimension == 2 else {}}},
            "joints": [
                {"name": "O", "type": "revolute", "parent": "N", "child": "R", "axis": "N.z",
                 "coordinates": ["th"]},
                {"name": "S", "type": "prismatic", "parent": "R", "child": "B", "axis": "R.x",
                 "coordinates": ["r"]}],
            # The motor torque that keeps the rate constant: d/dt((Ir + m r^2) th') = tau
            # with th'' = 0 gives tau = 2 m r r' th'.
            "loads": [{"type": "joint_actuator", "joint": "O", "coordinate": "th",
                       "value": "2*m*r*r'*th'"}],
            "find": {"reactions": ["S", "O"]}}


def test_bead_on_rotating_rod():
    # Rod turning at constant rate w about N.z; the bead slides freely along it:
    # r'' = r w^2, th'' = 0.  In the rod's axes the bead's acceleration is
    # (r'' - r w^2, r th'' + 2 r' w) = (0, 2 r' w), so the rod pushes it with the Coriolis
    # force 2 m r' w along R.y.  The pin at O carries no moment about N.z (the motor torque
    # is a joint load, not a reaction).
    m = 0.3
    for dim in (2, 3):
        p = bead_problem(dim)
        for r, rd, w in [(0.5, 0.2, 3.0), (-0.4, -1.0, 1.5)]:
            out = solve(p, {"th": 0.7, "r": r, "th'": w, "r'": rd})
            close(out["accelerations"]["th"], 0.0, what="bead th''")
            close(out["accelerations"]["r"], r * w * w, what="bead r''")
            close_vec(out["reactions"]["S"]["force"], [0.0, 2 * m * rd * w, 0.0], what="bead force")
            close_vec(out["reactions"]["S"]["moment"], [0.0, 0.0, 0.0], what="bead moment")
            close(out["reactions"]["O"]["moment"][2], 0.0, what="pin moment about its axis")


def test_spring_damper_particle():
    # A particle free in the plane (planar joint, its angle carrying a small disk inertia),
    # a spring of stiffness k and free length l0 and a damper c from the fixed point O at
    # (1, 2), a force F at the particle and a motor torque on the angle:
    #   m r'' = -k (|d| - l0) d/|d| - c (d/|d| . r') d/|d| + F,  d = r - O,
    #   I phi'' = tau.
    m, k, l0, c, inertia = 0.9, 12.0, 0.5, 0.7, 0.02
    p = {"title": "particle", "dimension": 2,
         "constants": {"m": m, "k": k, "l0": l0, "c": c, "I": inertia},
         "bodies": {"A": {"mass": "m", "inertia": "I"}},
         "joints": [{"name": "J", "type": "planar", "parent": "N", "child": "A",
                     "coordinates": ["x", "y", "phi"]}],
         "points": {"O": {"on": "N", "at": "1*N.x + 2*N.y"}},
         "loads": [{"type": "spring", "between": ["O", "A*"], "stiffness": "k", "free_length": "l0"},
                   {"type": "damper", "between": ["A.o", "O"], "coefficient": "c"},
                   {"type": "force", "on": "A", "vector": "0.3*t*N.x - 0.2*A.y"},
                   {"type": "joint_actuator", "joint": "J", "coordinate": "phi", "value": "0.05*phi'"}],
         "find": {"reactions": ["J"]}}
    x, y, phi, vx, vy, w, t = 0.2, -0.4, 0.6, 0.8, -0.3, 1.7, 0.5
    out = solve(p, {"x": x, "y": y, "phi": phi, "x'": vx, "y'": vy, "phi'": w}, t)
    d = [x - 1.0, y - 2.0]
    ln = math.hypot(*d)
    e = [d[0] / ln, d[1] / ln]
    ldot = e[0] * vx + e[1] * vy
    f = [0.3 * t + 0.2 * math.sin(phi), -0.2 * math.cos(phi)]  # -0.2 A.y in N axes
    for i, n in enumerate(("x", "y")):
        want = (-k * (ln - l0) * e[i] - c * ldot * e[i] + f[i]) / m
        close(out["accelerations"][n], want, what=f"particle {n}''")
    close(out["accelerations"]["phi"], 0.05 * w / inertia, what="particle phi''")
    r = out["reactions"]["J"]
    close_vec(r["force"] + r["moment"], [0.0] * 6, what="planar joint reaction")


def test_revolute_joint_loads():
    # A disk on a revolute about a skew axis through its center, no gravity:
    # I_a q'' = -k (q - q0) - c q' + tau(t), I_a = a^T I a.  The joint's own loads are
    # not part of its reaction, so the moment about the axis is 0; the rest of the moment
    # is the gyroscopic one, (I alpha + w x I w) minus its axial part.
    inertia = [[0.3, 0.02, 0.0], [0.02, 0.5, 0.01], [0.0, 0.01, 0.4]]
    p = {"title": "disk", "dimension": 3, "constants": {"k": 2.0, "c": 0.3},
         "bodies": {"D": {"mass": 1.0, "inertia": inertia_json(inertia)}},
         "joints": [{"name": "J", "type": "revolute", "parent": "N", "child": "D",
                     "axis": "N.x + 2*N.y + 2*N.z", "coordinates": ["q"]}],
         "loads": [{"type": "joint_spring", "joint": "J", "coordinate": "q", "stiffness": "k", "rest": 0.2},
                   {"type": "joint_damper", "joint": "J", "coordinate": "q", "coefficient": "c"},
                   {"type": "joint_actuator", "joint": "J", "coordinate": "q", "value": "sin(t)"}],
         "find": {"reactions": ["J"]}}
    a = [1 / 3, 2 / 3, 2 / 3]
    ia = dot(a, mv(inertia, a))  # about the axis through the center: invariant under the turn
    q, u, t = 0.7, -1.3, 0.4
    out = solve(p, {"q": q, "q'": u}, t)
    qdd = (-2.0 * (q - 0.2) - 0.3 * u + math.sin(t)) / ia
    close(out["accelerations"]["q"], qdd, what="disk q''")
    m = out["reactions"]["J"]["moment"]
    close(dot(m, a), 0.0, what="disk reaction about the axis")
    close_vec(out["reactions"]["J"]["force"], [0.0] * 3, what="disk reaction force")


# ---------------------------------------------------------------- spatial closed forms

INERTIA = [[0.9, 0.12, -0.07], [0.12, 1.4, 0.05], [-0.07, 0.05, 2.1]]


def inertia_json(i):
    return {"xx": i[0][0], "yy": i[1][1], "zz": i[2][2], "xy": i[0][1], "yz": i[1][2], "zx": i[2][0]}


def omega_zxy(q, u):
    # R = Rz(q1) Rx(q2) Ry(q3); in body axes
    # w = Ry^T Rx^T (0,0,q1') + Ry^T (q2',0,0) + (0,q3',0)
    #   = (-s3 c2 q1' + c3 q2',  s2 q1' + q3',  c3 c2 q1' + s3 q2').
    s2, c2, s3, c3 = math.sin(q[1]), math.cos(q[1]), math.sin(q[2]), math.cos(q[2])
    return [-s3 * c2 * u[0] + c3 * u[1], s2 * u[0] + u[2], c3 * c2 * u[0] + s3 * u[1]]


def omega_xyz(q, u):
    # R = Rx(a) Ry(b) Rz(c): w = Rz^T Ry^T (a',0,0) + Rz^T (0,b',0) + (0,0,c')
    #   = (cc cb a' + sc b', -sc cb a' + cc b', sb a' + c').
    sb, cb, sc, cc = math.sin(q[1]), math.cos(q[1]), math.sin(q[2]), math.cos(q[2])
    return [cc * cb * u[0] + sc * u[1], -sc * cb * u[0] + cc * u[1], sb * u[0] + u[2]]


def omega_zxz(q, u):
    # R = Rz(phi) Rx(th) Rz(psi): w = (s_psi s_th phi' + c_psi th', c_psi s_th phi' - s_psi th',
    #                                   c_th phi' + psi').
    sth, cth, sps, cps = math.sin(q[1]), math.cos(q[1]), math.sin(q[2]), math.cos(q[2])
    return [sps * sth * u[0] + cps * u[1], cps * sth * u[0] - sps * u[1], cth * u[0] + u[2]]


def test_torque_free_body():
    # A body on a spherical joint at its mass center, no loads: Euler's equations
    # I w' + w x I w = 0 in body axes, with products of inertia.
    p = {"title": "torque-free", "dimension": 3,
         "bodies": {"B": {"mass": 2.0, "inertia": inertia_json(INERTIA)}},
         "joints": [{"name": "O", "type": "spherical", "parent": "N", "child": "B",
                     "sequence": "zxy", "coordinates": ["a", "b", "c"]}],
         "find": {"reactions": ["O"]}}
    rng = random.Random(2)
    for _ in range(4):
        q = [rng.uniform(-1, 1) for _ in range(3)]
        u = [rng.uniform(-2, 2) for _ in range(3)]
        out = solve(p, dict(zip(["a", "b", "c", "a'", "b'", "c'"], q + u)))
        qdd = [out["accelerations"][n] for n in "abc"]
        w = omega_zxy(q, u)
        wd = omega_dot(omega_zxy, q, u, qdd)
        res = vadd(mv(INERTIA, wd), cross(w, mv(INERTIA, w)))
        close_vec(res, [0.0, 0.0, 0.0], 1e-7, "Euler's equations")
        close_vec(out["reactions"]["O"]["force"], [0.0] * 3, what="torque-free force")
        close_vec(out["reactions"]["O"]["moment"], [0.0] * 3, what="torque-free moment")


def test_free_body():
    # A free body (translation along N.x, N.y, N.z then rotations "xyz"), gravity along
    # -N.z, mass center off the origin, the joint point off the origin on both sides:
    # the mass center falls with g and Euler's equations hold about it.
    g = 9.81
    c = [0.3, -0.2, 0.5]
    p = {"title": "free body", "dimension": 3, "constants": {"g": g}, "gravity": "-g*N.z",
         "bodies": {"B": {"mass": 1.5, "center": "0.3*B.x - 0.2*B.y + 0.5*B.z",
                          "inertia": inertia_json(INERTIA)}},
         "joints": [{"name": "F", "type": "free", "parent": "N", "child": "B", "sequence": "xyz",
                     "at": "N.x + 2*N.y", "child_at": "-0.4*B.y + 0.1*B.z",
                     "coordinates": ["x", "y", "z", "a", "b", "c"]}]}
    rng = random.Random(3)
    names = ["x", "y", "z", "a", "b", "c"]
    for _ in range(4):
        q = [rng.uniform(-1, 1) for _ in range(6)]
        u = [rng.uniform(-2, 2) for _ in range(6)]
        out = solve(p, dict(zip(names + [n + "'" for n in names], q + u)))
        qdd = [out["accelerations"][n] for n in names]
        w = omega_xyz(q[3:], u[3:])
        wd = omega_dot(omega_xyz, q[3:], u[3:], qdd[3:])
        close_vec(vadd(mv(INERTIA, wd), cross(w, mv(INERTIA, w))), [0.0] * 3, 1e-7, "free Euler")
        # Mass center acceleration: the joint point moves by (x, y, z), and the mass center
        # is at P + R (c - child_at); so a* = (x'', y'', z'') + R (w' x s + w x (w x s)), s = c - child_at.
        r = mm(mm(rot("x", q[3]), rot("y", q[4])), rot("z", q[5]))
        s = vsub(c, [0.0, -0.4, 0.1])
        rel = vadd(cross(wd, s), cross(w, cross(w, s)))
        a = vadd(qdd[:3], mv(r, rel))
        close_vec(a, [0.0, 0.0, -g], 1e-7, "free fall of the mass center")


def test_heavy_top():
    # Spherical joint at the fixed tip O, Euler angles "zxz"; mass center h along T.z.
    # About O in body axes: I_O w' + w x I_O w = r x m g_body,
    #   I_O = I* + m (|r|^2 1 - r r^T),  g_body = R^T (0, 0, -g),  R = Rz Rx Rz.
    # Reaction at O (N axes): m a* - m g with a* = R (w' x r + w x (w x r)); no moment.
    m, h, g = 1.2, 0.25, 9.81
    r = [0.0, 0.0, h]
    p = {"title": "heavy top", "dimension": 3, "constants": {"m": m, "h": h, "g": g},
         "gravity": "-g*N.z",
         "bodies": {"T": {"mass": "m", "center": "h*T.z", "inertia": inertia_json(INERTIA)}},
         "joints": [{"name": "O", "type": "spherical", "parent": "N", "child": "T",
                     "sequence": "zxz", "coordinates": ["phi", "th", "psi"]}],
         "find": {"reactions": ["O"]}}
    io = [[INERTIA[i][j] + m * ((h * h if i == j else 0.0) - r[i] * r[j]) for j in range(3)]
          for i in range(3)]
    rng = random.Random(4)
    names = ["phi", "th", "psi"]
    for _ in range(4):
        q = [rng.uniform(-1, 1), rng.uniform(0.3, 1.2), rng.uniform(-1, 1)]
        u = [rng.uniform(-3, 3) for _ in range(3)]
        out = solve(p, dict(zip(names + [n + "'" for n in names], q + u)))
        qdd = [out["accelerations"][n] for n in names]
        w = omega_zxz(q, u)
        wd = omega_dot(omega_zxz, q, u, qdd)
        rm = mm(mm(rot("z", q[0]), rot("x", q[1])), rot("z", q[2]))
        gb = mtv(rm, [0.0, 0.0, -g])
        lhs = vadd(mv(io, wd), cross(w, mv(io, w)))
        close_vec(lhs, cross(r, vscale(m, gb)), 1e-7, "heavy top")
        a = mv(rm, vadd(cross(wd, r), cross(w, cross(w, r))))
        close_vec(out["reactions"]["O"]["force"], vsub(vscale(m, a), [0.0, 0.0, -m * g]), 1e-7, "top pin")
        close_vec(out["reactions"]["O"]["moment"], [0.0] * 3, 1e-9, "top moment")


def test_planar_2d_equals_3d():
    # The 2D double pendulum of rods and the same system written in 3D agree.
    p2 = {"title": "dp", "dimension": 2, "constants": {"m": 1.0, "L": 0.5, "g": 9.81},
          "gravity": "-g*N.y",
          "bodies": {"A": {"mass": "m", "center": "-L/2*A.y", "inertia": "m*L^2/12"},
                     "B": {"mass": "m", "center": "-L/2*B.y", "inertia": "m*L^2/12"}},
          "joints": [{"name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z",
                      "coordinates": ["q1"]},
                     {"name": "P", "type": "revolute", "parent": "A", "child": "B", "axis": "A.z",
                      "at": "-L*A.y", "coordinates": ["q2"]}],
          "find": {"reactions": ["O", "P"]}}
    p3 = json.loads(json.dumps(p2))
    p3["dimension"] = 3
    for b in ("A", "B"):
        p3["bodies"][b]["inertia"] = {"xx": "m*L^2/12", "zz": "m*L^2/12"}
    s = {"q1": 0.3, "q2": -0.2, "q1'": 1.0, "q2'": 0.5}
    o2, o3 = solve(p2, s), solve(p3, s)
    for n in ("q1", "q2"):
        close(o2["accelerations"][n], o3["accelerations"][n], what="2D vs 3D")
    for j in ("O", "P"):
        close_vec(o2["reactions"][j]["force"], o3["reactions"][j]["force"], what="2D vs 3D force")
        close(o2["reactions"][j]["moment"][2], o3["reactions"][j]["moment"][2], what="2D vs 3D moment")


def test_expressions():
    import expr as ex
    look = {"a": 2.0, "b": 3.0}
    cases = [("-2^2", -4.0), ("2^-1", 0.5), ("2^3^2", 512.0), ("-a^b", -8.0),
             ("a*b/4", 1.5), ("a-b-1", -2.0), ("8/a/2", 2.0), ("atan2(1,-1)", 3 * math.pi / 4),
             ("sign(-a)", -1.0), ("min(a,b)", 2.0), ("ln(exp(b))", 3.0), ("1.5e1", 15.0)]
    for text, want in cases:
        got = ex.evaluate(ex.parse(text), lambda n, p, c: look[n])
        close(got, want, what=text)


# ---------------------------------------------------------------- generic checks on cases/

def energy(st):
    """Kinetic plus potential energy for gravity, springs and joint springs."""
    p = st.prob
    ke = 0.0
    pe = 0.0
    g = st.vector_n(p.gravity) if p.gravity is not None else [0.0] * 3
    for b, body in p.bodies.items():
        v = st.point_vel_bias(b, body.center)[0]
        w = st.ku.omega(b)
        ke += 0.5 * body.mass * dot(v, v) + 0.5 * dot(w, mv(st.inertia_n(b), w))
        pe -= body.mass * dot(g, st.point_pos(b, body.center))
    for ld in p.loads:
        if ld["type"] == "spring":
            (b1, l1), (b2, l2) = ld["points"]
            d = vsub(st.point_pos(b2, l2), st.point_pos(b1, l1))
            stretch = math.sqrt(dot(d, d)) - st.scalar(ld["free_length"])
            pe += 0.5 * st.scalar(ld["stiffness"]) * stretch ** 2
        elif ld["type"] == "joint_spring":
            i = ld["joint"].coords[ld["index"]]
            pe += 0.5 * st.scalar(ld["stiffness"]) * (st.q[i] - st.scalar(ld["rest"])) ** 2
    return ke + pe


def conservative(prob):
    return all(ld["type"] in ("spring", "joint_spring") for ld in prob.loads)


def rk4_energy_drift(prob, q, u, dt=1e-3, steps=200):
    def f(y):
        n = len(q)
        st = State(prob, y[:n], y[n:], 0.0)
        return y[n:] + st.solve()

    y = q + u
    e0 = energy(State(prob, q, u, 0.0))
    for _ in range(steps):
        k1 = f(y)
        k2 = f([a + dt / 2 * b for a, b in zip(y, k1)])
        k3 = f([a + dt / 2 * b for a, b in zip(y, k2)])
        k4 = f([a + dt * b for a, b in zip(y, k3)])
        y = [a + dt / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(y, k1, k2, k3, k4)]
    n = len(q)
    e1 = energy(State(prob, y[:n], y[n:], 0.0))
    return abs(e1 - e0) / max(1.0, abs(e0))


def lagrange_residual(st, hstep=1e-5):
    """h from the jets against Lagrange's form h_i = sum_jk dM_ij/dq_k u_j u_k
    - 1/2 u^T dM/dq_i u, with dM/dq by central differences (independent of the jets'
    second-order terms)."""
    n = st.n
    dm = []
    for k in range(n):
        qp, qm = list(st.q), list(st.q)
        qp[k] += hstep
        qm[k] -= hstep
        sp, sm = State(st.prob, qp, st.u, st.t), State(st.prob, qm, st.u, st.t)
        sp.solve()
        sm.solve()
        dm.append([[(sp.mass[i][j] - sm.mass[i][j]) / (2 * hstep) for j in range(n)] for i in range(n)])
    u = st.u
    worst = 0.0
    scale = max([abs(x) for x in st.h] + [1.0])
    for i in range(n):
        hl = sum(dm[k][i][j] * u[j] * u[k] for j in range(n) for k in range(n))
        hl -= 0.5 * sum(dm[i][j][k] * u[j] * u[k] for j in range(n) for k in range(n))
        worst = max(worst, abs(hl - st.h[i]) / scale)
    return worst


def power_residual(st, h=1e-5):
    """dE/dt along the motion (central differences of the energy) against the power of
    the loads that have no potential in `energy` (forces, torques, dampers, joint dampers
    and actuators), computed from the actual velocities of their points and bodies."""
    p = st.prob
    n = st.n
    qdd = st.qdd
    ep = energy(State(p, [a + h * b for a, b in zip(st.q, st.u)], [a + h * b for a, b in zip(st.u, qdd)], st.t))
    em = energy(State(p, [a - h * b for a, b in zip(st.q, st.u)], [a - h * b for a, b in zip(st.u, qdd)], st.t))
    de = (ep - em) / (2 * h)
    # The actions of conservative loads are left out: gravity and springs come first in
    # `actions` in a known count; rebuild the list without them instead.
    saved = p.loads, p.gravity
    p.loads = [ld for ld in p.loads if ld["type"] not in ("spring", "joint_spring")]
    p.gravity = None
    try:
        acts = st.actions()
    finally:
        p.loads, p.gravity = saved
    power = 0.0
    for body, f, r, c in acts:
        if body == "N":
            continue
        vo = st.ku.frames[body][1][1]
        w = st.ku.omega(body)
        power += dot(f, vadd(vo, cross(w, vsub(r, st.o[body])))) + dot(c, w)
    return abs(de - power) / max(1.0, abs(power), abs(de)), n


def free_directions_residual(st, joint):
    """The reaction's components along the joint's free directions (must be 0)."""
    force, moment = st.reactions(joint)
    rp = st.R[joint.parent]
    fn, mn = mv(rp, force), mv(rp, moment)
    worst = 0.0
    for k, kind in zip(joint.coords, JOINT_KINDS[joint.type]):
        if kind == "T":
            d = st.ke[k].point(joint.child, joint.child_at)[1]
            worst = max(worst, abs(dot(fn, d)))
        else:
            worst = max(worst, abs(dot(mn, st.ke[k].omega(joint.child))))
    scale = max([abs(x) for x in force + moment] + [1.0])
    return worst / scale


def test_cases():
    files = sorted(glob.glob(os.path.join(HERE, "cases", "*.json")))
    rng = random.Random(5)
    for path in files:
        prob = load(path)
        n = len(prob.coords)
        for _ in range(2):
            q = [rng.uniform(-1, 1) for _ in range(n)]
            u = [rng.uniform(-1, 1) for _ in range(n)]
            st = State(prob, q, u, 0.3)
            st.solve()
            res = lagrange_residual(st)
            assert res < 1e-7, f"{path}: Lagrange residual {res:.3e}"
            res = power_residual(st)[0]
            assert res < 1e-7, f"{path}: power balance residual {res:.3e}"
            for j in prob.joints:
                res = free_directions_residual(st, j)
                if prob.dimension == 2 and j.type != "weld":
                    pass  # in 2D only in-plane components are kept; checked the same way
                assert res < 1e-9, f"{path}: joint {j.name} carries {res:.3e} along a free direction"
        if conservative(prob) and n > 0:
            drift = rk4_energy_drift(prob, [rng.uniform(-1, 1) for _ in range(n)],
                                     [rng.uniform(-1, 1) for _ in range(n)])
            assert drift < 1e-8, f"{path}: energy drift {drift:.3e}"
    print(f"  {len(files)} case files")


def main():
    tests = [(name, f) for name, f in sorted(globals().items()) if name.startswith("test_")]
    for name, f in tests:
        f()
        print(f"ok {name}")
    print(f"all {len(tests)} checks passed")


if __name__ == "__main__":
    main()
