//! Points and directions in `N` as numbers, and the vector algebra the pictures need.

/// A point or a direction in `N`'s unit vectors.
pub type P3 = [f64; 3];

/// `a + b`.
pub fn add(a: P3, b: P3) -> P3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a - b`.
pub fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `k a`.
pub fn scale(a: P3, k: f64) -> P3 {
    [a[0] * k, a[1] * k, a[2] * k]
}

/// `a · b`.
pub fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a × b`.
pub fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `|a|`.
pub fn norm(a: P3) -> f64 {
    dot(a, a).sqrt()
}

/// `a / |a|`, or `None` for a (nearly) zero or non-finite vector.
pub fn unit(a: P3) -> Option<P3> {
    let n = norm(a);
    (n.is_finite() && n > 1e-12).then(|| scale(a, 1.0 / n))
}

/// `v` turned by `angle` about the unit `axis` (Rodrigues).
pub fn rotate(v: P3, axis: P3, angle: f64) -> P3 {
    let (s, c) = angle.sin_cos();
    let k = axis;
    let kxv = cross(k, v);
    let kdv = dot(k, v);
    std::array::from_fn(|i| v[i] * c + kxv[i] * s + k[i] * kdv * (1.0 - c))
}

/// A circle about `center` of `radius` perpendicular to the unit `normal`, as points.
pub fn circle(center: P3, normal: P3, radius: f64) -> Vec<P3> {
    let helper = if normal[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let u = unit(cross(normal, helper)).unwrap_or([1.0, 0.0, 0.0]);
    let v = cross(normal, u);
    (0..48)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 48.0;
            add(
                center,
                add(scale(u, radius * t.cos()), scale(v, radius * t.sin())),
            )
        })
        .collect()
}
