"""Small dense linear algebra in plain Python, and second-order Taylor jets.

A jet is the truncated Taylor series x(s) = x0 + x1*s + x2*s^2 of a quantity along a
straight line in the coordinates, q(s) = q + d*s.  Propagating jets through the
kinematics gives, exactly up to rounding, the first derivative x1 = (dx/dq) d and the
second derivative 2*x2 = d^T (d^2x/dq^2) d.  With d = q' these are the velocity and the
velocity-dependent part of the acceleration (the part with q'' = 0); with d a unit
vector e_i, x1 is column i of the Jacobian.  No symbolic algebra, no finite differences.
"""

import math

# ---- 3-vectors and 3x3 matrices (lists) ----


def vadd(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def vsub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def vscale(k, a):
    return [k * a[0], k * a[1], k * a[2]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def mv(m, v):
    return [dot(m[0], v), dot(m[1], v), dot(m[2], v)]


def mtv(m, v):
    """m^T v."""
    return [m[0][i] * v[0] + m[1][i] * v[1] + m[2][i] * v[2] for i in range(3)]


def mm(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def mt(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def madd(a, b):
    return [[a[i][j] + b[i][j] for j in range(3)] for i in range(3)]


def mscale(k, a):
    return [[k * a[i][j] for j in range(3)] for i in range(3)]


def eye():
    return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]


def zeros3():
    return [[0.0] * 3 for _ in range(3)]


def vee(m):
    """The vector of the skew-symmetric part of m: vee([w]x) = w."""
    return [0.5 * (m[2][1] - m[1][2]), 0.5 * (m[0][2] - m[2][0]), 0.5 * (m[1][0] - m[0][1])]


def skew(a):
    return [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]]


def outer(a, b):
    return [[a[i] * b[j] for j in range(3)] for i in range(3)]


# ---- general dense systems ----


class SingularError(Exception):
    """The linear system has no unique solution."""


def solve(a, b):
    """Solves a x = b (a: n x n list of lists) by Gaussian elimination with partial pivoting."""
    n = len(b)
    m = [list(a[i]) + [b[i]] for i in range(n)]
    scale = max([abs(x) for row in a for x in row] + [1e-300])
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        if abs(m[p][c]) <= 1e-13 * scale:
            raise SingularError(f"singular matrix (pivot {m[p][c]:.3e} in column {c})")
        m[c], m[p] = m[p], m[c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            if f != 0.0:
                for k in range(c, n + 1):
                    m[r][k] -= f * m[c][k]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (m[r][n] - sum(m[r][k] * x[k] for k in range(r + 1, n))) / m[r][r]
    return x


def pinv_columns(cols):
    """For independent columns c_j, the vectors d_k = C (C^T C)^-1 e_k: d_k . c_j = delta_jk,
    each in the span of the columns (the dual basis when the columns span the space)."""
    n = len(cols)
    g = [[dot(cols[i], cols[j]) for j in range(n)] for i in range(n)]
    duals = []
    for k in range(n):
        e = [1.0 if i == k else 0.0 for i in range(n)]
        y = solve(g, e)
        d = [0.0, 0.0, 0.0]
        for j in range(n):
            d = vadd(d, vscale(y[j], cols[j]))
        duals.append(d)
    return duals


# ---- jets ----
# A scalar jet is a tuple (x0, x1, x2); a matrix jet a tuple of three 3x3 matrices; a
# vector jet a tuple of three 3-vectors.


def jet_sin_cos(th):
    """sin and cos of the scalar jet th."""
    s, c = math.sin(th[0]), math.cos(th[0])
    a1, a2 = th[1], th[2]
    sj = (s, c * a1, c * a2 - 0.5 * s * a1 * a1)
    cj = (c, -s * a1, -s * a2 - 0.5 * c * a1 * a1)
    return sj, cj


def jet_rotation(axis, th):
    """The rotation by the jet angle th about the unit axis (Rodrigues), as a matrix jet:
    R = cos(th) (I - a a^T) + sin(th) [a]x + a a^T."""
    s, c = jet_sin_cos(th)
    aa = outer(axis, axis)
    perp = madd(eye(), mscale(-1.0, aa))
    k = skew(axis)
    out = []
    for i in range(3):
        m = madd(mscale(c[i], perp), mscale(s[i], k))
        if i == 0:
            m = madd(m, aa)
        out.append(m)
    return tuple(out)


def jm_const(m):
    return (m, zeros3(), zeros3())


def jv_const(v):
    return (list(v), [0.0] * 3, [0.0] * 3)


def jm_mul(a, b):
    return (
        mm(a[0], b[0]),
        madd(mm(a[0], b[1]), mm(a[1], b[0])),
        madd(madd(mm(a[0], b[2]), mm(a[1], b[1])), mm(a[2], b[0])),
    )


def jm_apply(a, v):
    """Matrix jet times vector jet."""
    return (
        mv(a[0], v[0]),
        vadd(mv(a[0], v[1]), mv(a[1], v[0])),
        vadd(vadd(mv(a[0], v[2]), mv(a[1], v[1])), mv(a[2], v[0])),
    )


def jv_add(a, b):
    return tuple(vadd(a[i], b[i]) for i in range(3))


def jv_sub(a, b):
    return tuple(vsub(a[i], b[i]) for i in range(3))


def jv_scale_jet(k, v):
    """Scalar jet k times constant vector v."""
    return tuple(vscale(k[i], v) for i in range(3))
