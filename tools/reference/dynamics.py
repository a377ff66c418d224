"""Equations of motion and joint reactions at one state, by a numeric formulation.

Kinematics: every body's rotation matrix R (body components -> N components) and origin
position o are built from the joints as products of axis-angle rotation matrices
(Rodrigues) and translations, propagated as second-order Taylor jets (see linalg.py).
This gives, for every point fixed on a body, its Jacobian J_v (dv/dq') and the
velocity-dependent part of its acceleration, and for every body its angular-velocity
Jacobian J_w and the velocity-dependent part of its angular acceleration, from
[w]x = R' R^T and [alpha]x = d/dt(R' R^T).

Equations: d'Alembert's principle in generalized coordinates (virtual power):
    sum_b  J_v(b*)^T (m_b a_b*)  +  J_w(b)^T (I_b alpha_b + w_b x I_b w_b)  =  Q,
with a = J_v q'' + a_bias, alpha = J_w q'' + alpha_bias, so
    M q'' = Q - h,   M = sum J_v^T m J_v + J_w^T I J_w,
    h = sum J_v^T m a_bias + J_w^T (I alpha_bias + w x I w),
and Q the generalized active forces: every load is turned into forces at points and
couples on bodies (an "action"), and Q_i = F . dv_point/dq'_i + C . dw_body/dq'_i.

Reactions: Newton-Euler for the subtree S outboard of the joint, with the accelerations
just found (see `reactions`).
"""

import math

import expr as ex
from linalg import (SingularError, cross, dot, jet_rotation, jm_apply, jm_const, jm_mul,
                    jv_add, jv_const, jv_scale_jet, jv_sub, mm, mt, mtv, mv, norm,
                    pinv_columns, solve, vadd, vee, vscale, vsub)
from model import JOINT_KINDS

UNIT = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])


class Kin:
    """Kinematics along one direction d of the coordinates: per body (R jet, origin jet)."""

    def __init__(self, prob, q, d):
        self.frames = {"N": (jm_const([list(r) for r in UNIT]), jv_const([0.0] * 3))}
        for j in prob.order:
            rp, op = self.frames[j.parent]
            th = [(q[i], d[i], 0.0) for i in j.coords]
            kinds = JOINT_KINDS[j.type]
            # Translation of the joint point, in parent components, and relative rotation.
            trans = jv_const([0.0] * 3)
            rot = jm_const([list(r) for r in UNIT])
            if j.type in ("prismatic", "cylindrical"):
                trans = jv_scale_jet(th[0], j.axis)
            elif j.type in ("planar", "free"):
                for k, c in enumerate(kinds):
                    if c == "T":
                        trans = jv_add(trans, jv_scale_jet(th[k], UNIT[k]))
            if j.type in ("revolute", "cylindrical"):
                rot = jet_rotation(j.axis, th[kinds.index("R")])
            elif j.type == "planar":
                rot = jet_rotation(UNIT[2], th[2])
            elif j.type in ("universal", "spherical", "free"):
                # Body-fixed sequence: each next rotation about the axis of the frame so far,
                # i.e. R_rel = R_1 R_2 R_3 (post-multiplied).
                angles = [th[k] for k, c in enumerate(kinds) if c == "R"]
                for axis, a in zip(j.sequence, angles):
                    rot = jm_mul(rot, jet_rotation(UNIT[axis], a))
            point = jv_add(op, jm_apply(rp, jv_add(jv_const(j.at), trans)))
            # An absolute angle turns the child from N itself (the axis is N's normal in 2D).
            rc = rot if j.absolute else jm_mul(rp, rot)
            oc = jv_sub(point, jm_apply(rc, jv_const(j.child_at)))
            self.frames[j.child] = (rc, oc)

    def point(self, body, local):
        """Jet of the position of the point of `body` at `local` (body components)."""
        r, o = self.frames[body]
        return jv_add(o, jm_apply(r, jv_const(local)))

    def omega(self, body):
        r = self.frames[body][0]
        return vee(mm(r[1], mt(r[0])))

    def alpha_bias(self, body):
        r = self.frames[body][0]
        a = mm(vscale_m(2.0, r[2]), mt(r[0]))
        b = mm(r[1], mt(r[1]))
        return vee([[a[i][k] + b[i][k] for k in range(3)] for i in range(3)])


def vscale_m(k, m):
    return [[k * x for x in row] for row in m]


class State:
    """Everything at one state: kinematics, generalized equations, accelerations."""

    def __init__(self, prob, q, u, t):
        self.prob, self.q, self.u, self.t = prob, q, u, t
        n = len(prob.coords)
        self.n = n
        self.ku = Kin(prob, q, u)
        self.ke = [Kin(prob, q, [1.0 if k == i else 0.0 for k in range(n)]) for i in range(n)]
        self.R = {b: f[0][0] for b, f in self.ku.frames.items()}
        self.o = {b: f[1][0] for b, f in self.ku.frames.items()}
        self.vals = {name: q[i] for i, name in enumerate(prob.coords)}
        self.rates = {name: u[i] for i, name in enumerate(prob.coords)}

    # ---- kinematic quantities ----

    def point_pos(self, body, local):
        return vadd(self.o[body], mv(self.R[body], local))

    def point_jac(self, body, local):
        """Columns dv/dq'_i of the body point at `local`."""
        return [k.point(body, local)[1] for k in self.ke]

    def point_vel_bias(self, body, local):
        p = self.ku.point(body, local)
        return p[1], vscale(2.0, p[2])

    def omega_jac(self, body):
        return [k.omega(body) for k in self.ke]

    def inertia_n(self, body):
        r = self.R[body]
        return mm(mm(r, self.prob.bodies[body].inertia), mt(r))

    # ---- loads ----

    def lookup(self, name, primes, column):
        p = self.prob
        if primes == 0:
            if name in p.constants:
                return p.constants[name]
            if name in self.vals:
                return self.vals[name]
            if name == "t":
                return self.t
            if name == "pi":
                return math.pi
        elif primes == 1 and name in self.rates:
            return self.rates[name]
        raise ex.ExprError(f"unknown name {name + chr(39) * primes!r} in a load", column)

    def scalar(self, tree):
        v = ex.evaluate(tree, self.lookup)
        if isinstance(v, ex.Vec):
            raise ex.ExprError("expected a scalar, found a vector")
        return v

    def vector_n(self, tree):
        """A vector expression (any frames) in N components at this state."""
        v = ex.evaluate(tree, self.lookup)
        if not isinstance(v, ex.Vec):
            if v == 0.0:
                return [0.0, 0.0, 0.0]
            raise ex.ExprError("expected a vector, found a scalar")
        out = [0.0, 0.0, 0.0]
        for f, c in v.parts.items():
            if f not in self.R:
                raise ex.ExprError(f"unknown frame {f!r}")
            out = vadd(out, mv(self.R[f], c))
        return out

    def joint_load_action(self, joint, index, value):
        """The force at the joint point and the couple on the child whose generalized
        force is `value` on the joint's coordinate `index` and zero on all others.

        Within the joint's translational (or rotational) coordinates, with relative
        partial velocities c_j, the force (couple) is value * d_k with d_k . c_j = delta_jk
        and d_k in the span of the c_j: for one coordinate, value along its unit axis."""
        kinds = JOINT_KINDS[joint.type]
        group = [k for k, c in enumerate(kinds) if c == kinds[index]]
        cols = []
        for k in group:
            i = joint.coords[k]
            if kinds[index] == "T":
                cols.append(self.ke[i].point(joint.child, joint.child_at)[1])
            else:
                cols.append(self.ke[i].omega(joint.child))
        d = vscale(value, pinv_columns(cols)[group.index(index)])
        zero = [0.0, 0.0, 0.0]
        return (d, zero) if kinds[index] == "T" else (zero, d)

    def actions(self):
        """Every load as (body, force, application point, couple), all in N components."""
        p = self.prob
        out = []
        zero = [0.0, 0.0, 0.0]
        if p.gravity is not None:
            g = self.vector_n(p.gravity)
            for b, body in p.bodies.items():
                out.append((b, vscale(body.mass, g), self.point_pos(b, body.center), zero))
        for ld in p.loads:
            t = ld["type"]
            if t == "force":
                pb, local = ld["point"]
                out.append((ld["on"], self.vector_n(ld["vector"]), self.point_pos(pb, local), zero))
            elif t == "torque":
                c = self.vector_n(ld["vector"])
                out.append((ld["on"], zero, self.o[ld["on"]], c))
                if ld["reaction_on"] is not None:
                    r = ld["reaction_on"]
                    out.append((r, zero, self.o[r], vscale(-1.0, c)))
            elif t in ("spring", "damper"):
                (b1, l1), (b2, l2) = ld["points"]
                r1, r2 = self.point_pos(b1, l1), self.point_pos(b2, l2)
                d = vsub(r2, r1)
                length = norm(d)
                if length == 0.0:
                    raise ex.ExprError(f"{ld['path']}: the points coincide, no direction")
                e = vscale(1.0 / length, d)
                if t == "spring":
                    # Tension k (l - l0): pulls point 1 towards point 2 and 2 towards 1.
                    tension = self.scalar(ld["stiffness"]) * (length - self.scalar(ld["free_length"]))
                else:
                    v1 = self.point_vel_bias(b1, l1)[0]
                    v2 = self.point_vel_bias(b2, l2)[0]
                    tension = self.scalar(ld["coefficient"]) * dot(e, vsub(v2, v1))
                out.append((b1, vscale(tension, e), r1, zero))
                out.append((b2, vscale(-tension, e), r2, zero))
            else:
                j = ld["joint"]
                i = j.coords[ld["index"]]
                if t == "joint_spring":
                    value = -self.scalar(ld["stiffness"]) * (self.q[i] - self.scalar(ld["rest"]))
                elif t == "joint_damper":
                    value = -self.scalar(ld["coefficient"]) * self.u[i]
                else:
                    value = self.scalar(ld["value"])
                f, c = self.joint_load_action(j, ld["index"], value)
                pos = self.point_pos(j.child, j.child_at)
                out.append((j.child, f, pos, c))
                out.append((j.parent, vscale(-1.0, f), pos, vscale(-1.0, c)))
        return out

    def generalized_forces(self, actions):
        q = [0.0] * self.n
        for body, f, r, c in actions:
            if body == "N":
                continue
            # The body's material point at r: v = v_o + w x (r - o).
            arm = vsub(r, self.o[body])
            for i, k in enumerate(self.ke):
                vo = k.frames[body][1][1]
                w = k.omega(body)
                q[i] += dot(f, vadd(vo, cross(w, arm))) + dot(c, w)
        return q

    # ---- equations ----

    def solve(self):
        """The accelerations q'' (list, in coordinate order)."""
        p = self.prob
        n = self.n
        mass = [[0.0] * n for _ in range(n)]
        h = [0.0] * n
        self.cm = {}
        for b, body in p.bodies.items():
            jv = self.point_jac(b, body.center)
            v, abias = self.point_vel_bias(b, body.center)
            jw = self.omega_jac(b)
            w = self.ku.omega(b)
            wbias = self.ku.alpha_bias(b)
            inn = self.inertia_n(b)
            gyro = vadd(mv(inn, wbias), cross(w, mv(inn, w)))
            self.cm[b] = (jv, abias, jw, wbias, w, inn)
            for i in range(n):
                h[i] += body.mass * dot(jv[i], abias) + dot(jw[i], gyro)
                ijw = mv(inn, jw[i])
                for k in range(n):
                    mass[k][i] += body.mass * dot(jv[k], jv[i]) + dot(jw[k], ijw)
        self.acts = self.actions()
        gen = self.generalized_forces(self.acts)
        self.mass, self.h, self.gen = mass, h, gen
        if n == 0:
            self.qdd = []
        else:
            self.qdd = solve(mass, [gen[i] - h[i] for i in range(n)])
        return self.qdd

    def subtree(self, root):
        """The bodies outboard of and including `root`, in tree order (a list, so sums
        are taken in the same order on every run)."""
        bodies = [root]
        for j in self.prob.order:
            if j.parent in bodies:
                bodies.append(j.child)
        return bodies

    def reactions(self, joint):
        """The force and the moment about the joint's point on the child that the parent
        exerts on the child through the joint, excluding the joint's own loads, in the
        parent's components.

        For the subtree S outboard of the joint (the child and everything beyond it),
        Newton-Euler with P the joint's point on the child:
          R_F = sum_S m a*  -  sum of the forces of all actions on S,
          R_M = sum_S [(b* - P) x m a* + I alpha + w x I w]
                -  sum of [(r - P) x F + C] over all actions on S.
        Actions on S include the child's side of this joint's joint loads (so they are
        not part of R) and both sides of joint loads inside S (they cancel); nothing
        outside S acts on S except through this joint."""
        s = self.subtree(joint.child)
        pj = self.point_pos(joint.child, joint.child_at)
        fr = [0.0, 0.0, 0.0]
        mr = [0.0, 0.0, 0.0]
        for b in s:
            body = self.prob.bodies[b]
            jv, abias, jw, wbias, w, inn = self.cm[b]
            a = list(abias)
            alpha = list(wbias)
            for i in range(self.n):
                a = vadd(a, vscale(self.qdd[i], jv[i]))
                alpha = vadd(alpha, vscale(self.qdd[i], jw[i]))
            ma = vscale(body.mass, a)
            fr = vadd(fr, ma)
            arm = vsub(self.point_pos(b, body.center), pj)
            mr = vadd(mr, vadd(cross(arm, ma), vadd(mv(inn, alpha), cross(w, mv(inn, w)))))
        for body, f, r, c in self.acts:
            if body in s:
                fr = vsub(fr, f)
                mr = vsub(mr, vadd(cross(vsub(r, pj), f), c))
        rp = self.R[joint.parent]
        force, moment = mtv(rp, fr), mtv(rp, mr)
        if self.prob.dimension == 2:
            force[2] = 0.0
            moment[0] = moment[1] = 0.0
        return force, moment


def solve_state(prob, state=None, t=0.0):
    """Accelerations and requested reactions at a state.

    `state` maps coordinate names to values and `name'` to rates; unset ones take the
    problem's initial values. Returns the JSON-shaped dict of `mbd-tutor solve`."""
    state = dict(state or {})
    q, u = [], []
    for name in prob.coords:
        decl = prob.declared_coords.get(name, {})
        q.append(float(state.pop(name, decl.get("initial", 0.0))))
        u.append(float(state.pop(name + "'", decl.get("rate", 0.0))))
    if state:
        raise ValueError(f"--state: unknown coordinates {sorted(state)}")
    st = State(prob, q, u, t)
    qdd = st.solve()
    out = {
        "method": "reference",
        "time": t,
        "state": {**{n: q[i] for i, n in enumerate(prob.coords)},
                  **{n + "'": u[i] for i, n in enumerate(prob.coords)}},
        "accelerations": {n: qdd[i] for i, n in enumerate(prob.coords)},
        "reactions": {},
    }
    for name in prob.find:
        f, m = st.reactions(prob.joint_by_name[name])
        out["reactions"][name] = {"force": f, "moment": m}
    return out, st


__all__ = ["State", "Kin", "solve_state", "SingularError"]
