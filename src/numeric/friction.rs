//! Coulomb friction at a state: the textbook's process, with numbers.
//!
//! The equations are formed with every friction site sticking (rolling): its no-slip rows
//! are rows of `A x = b`, and its friction and normal forces unknowns. A site that slips
//! exchanges each of those rows for the sliding law `F_k = μ |N| f_k`, with `f` the unit
//! direction of the friction force (against the slip velocity) and `|N| = σ N`, σ the sign
//! of N; both known, the law is linear in the unknowns. A rough slider in 3D has two normal
//! components: `|N| = e·N` with `e` N's unit direction, taken from the last solution and
//! iterated until it stands still.
//!
//! A site whose slip velocity is zero is first assumed to stick; the solution is accepted
//! when `|F| ≤ μ |N|`, and otherwise solved again sliding, the friction force along the
//! force that sticking needed (it opposes the motion that would start).

use super::friction_vectors::{direction_of, dot, first_unit, norm, same_direction, signed_normal};
use super::linear::solve_linear;
use crate::equations::Derivation;
use crate::plan::Sum;
use crate::symbolic::{Expr, Program};
use nalgebra::{DMatrix, DVector};

/// A slip speed at or below this (times the largest rate, plus one) is zero: the site is
/// at rest relative to its surface.
const REST: f64 = 1e-8;

/// How a site is treated when the equations are solved.
#[derive(Clone, Debug, PartialEq)]
pub enum Held {
    /// Assume sticking, check `|F| ≤ μ|N|`, and slide if the check fails.
    Decide,
    /// Sticking (rolling), without the check.
    Stick,
    /// Sliding, the friction force along this unit direction (one component per tangent).
    Slip(Vec<f64>),
}

/// Whether a site sticks or slips.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// No relative motion at the contact (rolling, for a disc).
    Stick,
    /// Sliding, with friction μ|N| against the slip.
    Slip,
}

impl Mode {
    /// `stick` or `slip`, as the JSON writes it.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Stick => "stick",
            Mode::Slip => "slip",
        }
    }
}

/// The sticking solution that failed its check: the friction force sticking needed, and
/// the most friction can give.
#[derive(Clone, Debug, PartialEq)]
pub struct FailedStick {
    /// The friction force's components along the tangents (N).
    pub tangential: Vec<f64>,
    /// The normal force (N).
    pub normal: f64,
    /// μ |N| (N).
    pub limit: f64,
}

/// One friction site at a solved state.
#[derive(Clone, Debug, PartialEq)]
pub struct SiteState {
    /// The site's name (its contact's).
    pub name: String,
    /// Sticking or slipping.
    pub mode: Mode,
    /// The normal force, along the plane's normal (N).
    pub normal: f64,
    /// The friction force's components along the tangents (N).
    pub tangential: Vec<f64>,
    /// μ |N| (N).
    pub limit: f64,
    /// The coefficient of friction μ.
    pub coefficient: f64,
    /// The slip velocity's components along the tangents (m/s).
    pub slip: Vec<f64>,
    /// When the site was at rest and sticking failed its check: that first solution.
    pub failed_stick: Option<FailedStick>,
    /// Whether it sticks together with other sites whose forces statics does not split
    /// (the split taken is the one farthest from slipping, see `Friction::solve`).
    pub shared: bool,
}

impl SiteState {
    /// |F|, the friction force's magnitude (N).
    pub fn friction(&self) -> f64 {
        norm(&self.tangential)
    }

    /// |F| / (μ|N|): `None` where μ|N| is zero and friction is needed.
    pub fn friction_ratio(&self) -> Option<f64> {
        let force = self.friction();
        if self.limit > 0.0 {
            Some(force / self.limit)
        } else if force == 0.0 {
            Some(0.0)
        } else {
            None
        }
    }

    /// How to hold the site from here on: sticking, or sliding with its friction force's
    /// direction.
    pub fn held(&self) -> Held {
        let force = self.friction();
        match self.mode {
            Mode::Slip if force > 0.0 => {
                Held::Slip(self.tangential.iter().map(|t| t / force).collect())
            }
            Mode::Slip => Held::Slip(self.tangential.iter().map(|_| 0.0).collect()),
            Mode::Stick => Held::Stick,
        }
    }

    /// |F| / |N|, 0 when N is 0.
    pub fn ratio(&self) -> f64 {
        let n = self.normal.abs();
        if n > 0.0 {
            self.friction() / n
        } else {
            0.0
        }
    }
}

/// One site's places in the system.
#[derive(Clone, Debug)]
struct Slot {
    name: String,
    /// The stick rows' indices in `A`.
    rows: Vec<usize>,
    /// The friction force components' indices among the unknowns.
    tangential: Vec<usize>,
    /// The normal force's components' indices among the unknowns (two for a rough slider
    /// in 3D).
    normal: Vec<usize>,
    /// μ's output, then the slip velocity components', in the program.
    first_output: usize,
}

/// The friction sites of a derivation, compiled.
#[derive(Clone, Debug)]
pub struct Friction {
    slots: Vec<Slot>,
    program: Program,
    outputs: usize,
}

impl Friction {
    /// The friction sites of `derivation`, or `None` when it has none. `inputs` are the
    /// symbols the compiled equations take.
    pub fn new(derivation: &Derivation, inputs: &[crate::symbolic::Symbol]) -> Option<Friction> {
        let model = &derivation.model;
        let sites = &model.constraints.friction;
        if sites.is_empty() {
            return None;
        }
        let unknowns = &derivation.system.unknowns;
        let row_of = |name: &str| {
            derivation
                .rows
                .iter()
                .position(|r| matches!(&r.sum, Sum::Constraint { name: n } if n == name))
        };
        let mut outputs: Vec<Expr> = Vec::new();
        let mut slots = Vec::new();
        for site in sites {
            let first_output = outputs.len();
            outputs.push(site.coefficient.clone());
            outputs.extend(site.stick.iter().map(|r| r.velocity.clone()));
            slots.push(Slot {
                name: site.name.clone(),
                rows: site
                    .stick
                    .iter()
                    .map(|r| row_of(&r.name))
                    .collect::<Option<_>>()?,
                tangential: site
                    .stick
                    .iter()
                    .map(|r| unknowns.iter().position(|u| *u == r.unknown))
                    .collect::<Option<_>>()?,
                normal: site
                    .normal
                    .iter()
                    .map(|n| unknowns.iter().position(|u| u == n))
                    .collect::<Option<_>>()?,
                first_output,
            });
        }
        Some(Friction {
            slots,
            outputs: outputs.len(),
            program: Program::compile(inputs, &outputs),
        })
    }

    /// The sites' names.
    pub fn names(&self) -> Vec<String> {
        self.slots.iter().map(|s| s.name.clone()).collect()
    }

    /// Each site's μ and slip velocity components at the state of `inputs`.
    fn run(&self, inputs: &[f64]) -> Vec<(f64, Vec<f64>)> {
        let mut values = vec![0.0; self.outputs];
        self.program.run(inputs, &mut Vec::new(), &mut values);
        self.slots
            .iter()
            .map(|s| {
                let v = &values[s.first_output..s.first_output + 1 + s.rows.len()];
                (v[0], v[1..].to_vec())
            })
            .collect()
    }

    /// What a site does with no history: slides against its slip where it slips, and is
    /// decided by the check where it is at rest.
    pub fn held_at(&self, inputs: &[f64], rates: &[f64]) -> Vec<Held> {
        let scale = 1.0 + rates.iter().fold(0.0f64, |m, r| m.max(r.abs()));
        self.run(inputs)
            .into_iter()
            .map(|(_, slip)| {
                let speed = norm(&slip);
                if speed > REST * scale {
                    Held::Slip(slip.iter().map(|v| -v / speed).collect())
                } else {
                    Held::Decide
                }
            })
            .collect()
    }

    /// Each sliding site's rows of `a x = b` replaced by the sliding law: the friction
    /// force μ|N| against the slip, or along the direction held at rest.
    fn slip_rows(
        &self,
        a: &mut DMatrix<f64>,
        b: &mut DVector<f64>,
        modes: &[Held],
        signs: &[Vec<f64>],
        run: &[(f64, Vec<f64>)],
    ) {
        for ((slot, mode), (sign, (mu, slip))) in
            self.slots.iter().zip(modes).zip(signs.iter().zip(run))
        {
            if let Held::Slip(held_direction) = mode {
                // Against the slip while there is one (it turns in 3D), as held at rest
                // and past it: a slip that overshoots zero within a step must not turn
                // the friction round, or the step would straddle a jump.
                let speed = norm(slip);
                let against: Vec<f64> = slip.iter().map(|v| -v / speed).collect();
                let direction = if speed > REST && dot(&against, held_direction) > 0.0 {
                    against
                } else {
                    held_direction.clone()
                };
                for (k, &row) in slot.rows.iter().enumerate() {
                    a.row_mut(row).fill(0.0);
                    a[(row, slot.tangential[k])] = 1.0;
                    for (&n, e) in slot.normal.iter().zip(sign) {
                        a[(row, n)] -= mu * e * direction[k];
                    }
                    b[row] = 0.0;
                }
            }
        }
    }

    /// Solves `a x = b` with each site `held` as given; where a site is to be decided,
    /// sticking first and sliding if the check fails. `None` when a system is singular.
    pub fn solve(
        &self,
        a: &DMatrix<f64>,
        b: &DVector<f64>,
        inputs: &[f64],
        held: &[Held],
    ) -> Option<(DVector<f64>, Vec<SiteState>)> {
        let run = self.run(inputs);
        let mut modes: Vec<Held> = held
            .iter()
            .map(|h| match h {
                Held::Decide => Held::Stick,
                other => other.clone(),
            })
            .collect();
        // The unit direction of each site's N among its components, so that |N| = e·N is
        // linear in the unknowns: with one component e is N's sign.
        let mut signs: Vec<Vec<f64>> = self
            .slots
            .iter()
            .map(|s| first_unit(s.normal.len()))
            .collect();
        let mut failed: Vec<Option<FailedStick>> = vec![None; self.slots.len()];
        // Sites at rest that could not stick (their sticking system was singular).
        let mut forced = vec![false; self.slots.len()];
        let (a_formed, b_formed) = (a, b);
        // Each pass settles a site's mode or the sign of its N; a few suffice. With two
        // components (a rough slider in 3D) |N| is not linear: the passes iterate on N's
        // direction until it stands still.
        for _ in 0..=2 * self.slots.len() + 2 + DIRECTION_PASSES {
            let (mut a, mut b) = (a.clone(), b.clone());
            self.slip_rows(&mut a, &mut b, &modes, &signs, &run);
            let solved = solve_linear(&a, &b);
            // Whether this pass takes the split of forces that statics leaves free.
            let shared = solved.is_none();
            let solved = solved.or_else(|| self.shared(&a, &b, &modes, &run));
            let Some(x) = solved else {
                // Sticking can be impossible at rest: where the kinematics make the slip
                // accelerate (a slider at a dead centre), no force holds it. It slides
                // then, against the slip acceleration (found on the next pass).
                let stuck = (0..self.slots.len())
                    .find(|&i| held[i] == Held::Decide && modes[i] == Held::Stick && !forced[i])?;
                forced[stuck] = true;
                modes[stuck] = Held::Slip(first_unit(self.slots[stuck].rows.len()));
                continue;
            };
            let mut settled = true;
            for (i, slot) in self.slots.iter().enumerate() {
                let Held::Slip(direction) = &modes[i] else {
                    continue;
                };
                if !forced[i] {
                    continue;
                }
                // The slip acceleration: each stick row's residual, with the rows as formed.
                let accelerating: Vec<f64> = slot
                    .rows
                    .iter()
                    .map(|&r| (a_formed.row(r) * &x)[0] - b_formed[r])
                    .collect();
                let size = norm(&accelerating);
                if size > 0.0 && dot(direction, &accelerating) > 1e-12 * size {
                    modes[i] = Held::Slip(accelerating.iter().map(|v| -v / size).collect());
                    settled = false;
                }
            }
            for (i, slot) in self.slots.iter().enumerate() {
                let components: Vec<f64> = slot.normal.iter().map(|&n| x[n]).collect();
                let normal = signed_normal(&components);
                let mu = run[i].0;
                let tangential: Vec<f64> = slot.tangential.iter().map(|&t| x[t]).collect();
                let sign = direction_of(&components, &signs[i]);
                match &modes[i] {
                    Held::Slip(_) if !same_direction(&sign, &signs[i]) => {
                        signs[i] = sign;
                        settled = false;
                    }
                    Held::Stick if held[i] == Held::Decide => {
                        let (force, limit) = (norm(&tangential), mu * normal.abs());
                        if force > limit * (1.0 + 1e-12) + 1e-12 {
                            modes[i] = Held::Slip(tangential.iter().map(|t| t / force).collect());
                            signs[i] = sign;
                            failed[i] = Some(FailedStick {
                                tangential,
                                normal,
                                limit,
                            });
                            settled = false;
                        }
                    }
                    _ => {}
                }
            }
            if settled {
                let states = self
                    .slots
                    .iter()
                    .enumerate()
                    .map(|(i, slot)| {
                        let components: Vec<f64> = slot.normal.iter().map(|&n| x[n]).collect();
                        let normal = signed_normal(&components);
                        SiteState {
                            name: slot.name.clone(),
                            mode: match modes[i] {
                                Held::Slip(_) => Mode::Slip,
                                _ => Mode::Stick,
                            },
                            normal,
                            tangential: slot.tangential.iter().map(|&t| x[t]).collect(),
                            limit: run[i].0 * normal.abs(),
                            coefficient: run[i].0,
                            slip: run[i].1.clone(),
                            failed_stick: failed[i].take(),
                            shared: shared && modes[i] == Held::Stick,
                        }
                    })
                    .collect();
                return Some((x, states));
            }
        }
        None
    }

    /// Sticking can fix the motion and leave the contact forces undetermined: two rough
    /// contacts of one body at rest (a box on two edges, a ladder on a rough floor and
    /// wall) share one no-slip motion, and statics alone does not split the forces between
    /// them. Where `a x = b` is consistent and leaves free only the forces of sites that
    /// stick, the tool takes the split that keeps every site farthest from slipping (the
    /// least largest |F|/(μ|N|)), so that all stick whenever some split could hold them;
    /// the check then decides as usual. `None` otherwise (the system is singular).
    fn shared(
        &self,
        a: &DMatrix<f64>,
        b: &DVector<f64>,
        modes: &[Held],
        run: &[(f64, Vec<f64>)],
    ) -> Option<DVector<f64>> {
        let sticking: Vec<(&Slot, f64)> = self
            .slots
            .iter()
            .zip(modes)
            .zip(run)
            .filter(|((_, mode), _)| **mode == Held::Stick)
            .map(|((slot, _), (mu, _))| (slot, *mu))
            .collect();
        let forces: Vec<usize> = sticking
            .iter()
            .flat_map(|(slot, _)| slot.tangential.iter().chain(&slot.normal).copied())
            .collect();
        if sticking.is_empty() || a.nrows() != a.ncols() {
            return None;
        }
        let svd = a.clone().svd(true, true);
        let largest = svd.singular_values.max();
        if largest.is_nan() || largest <= 0.0 {
            return None;
        }
        let tolerance = 1e-10 * largest;
        let v_t = svd.v_t.as_ref()?;
        let free: Vec<DVector<f64>> = (0..svd.singular_values.len())
            .filter(|&k| svd.singular_values[k] <= tolerance)
            .map(|k| v_t.row(k).transpose())
            .collect();
        let only_forces = free
            .iter()
            .all(|v| (0..v.len()).all(|j| forces.contains(&j) || v[j].abs() <= 1e-8 * v.amax()));
        if free.is_empty() || !only_forces {
            return None;
        }
        let x = svd.solve(b, tolerance).ok()?;
        if (a * &x - b).norm() > 1e-9 * (b.norm() + a.norm() * x.norm()) {
            return None;
        }
        let planar = sticking
            .iter()
            .all(|(slot, _)| slot.tangential.len() == 1 && slot.normal.len() == 1);
        match free.as_slice() {
            [v] if planar => Some(farthest_from_slipping(&x, v, &sticking)),
            _ => Some(x),
        }
    }

    /// The functions whose zeros are the instants a site changes mode, while each is held
    /// as `held`: a slipping site's slip velocity along the way it started (it stops, or
    /// turns), a sticking site's margin μ|N| − |F| (it starts to slip). Positive until then.
    pub fn switching(&self, inputs: &[f64], held: &[Held], states: &[SiteState]) -> Vec<f64> {
        self.run(inputs)
            .into_iter()
            .zip(held.iter().zip(states))
            .map(|((_, slip), (held, state))| match held {
                Held::Slip(direction) => -dot(direction, &slip),
                _ => state.limit - state.friction(),
            })
            .collect()
    }
}

/// Passes allowed, beyond those that settle modes and signs, for N's direction to settle
/// where N has two components.
const DIRECTION_PASSES: usize = 60;

/// Along the one free direction `v` of the forces, from the solution `x`, the point that
/// keeps the sites (each with one friction and one normal component, and its μ) farthest
/// from slipping: the least r with |F| ≤ r μ N and N ≥ 0 at every site, by bisection on r.
/// N's sign is as in `x`; where `x` has N at zero (to rounding) both signs are tried, and
/// the one that holds with the least r kept. `x` itself when no point has every N on its
/// side.
fn farthest_from_slipping(
    x: &DVector<f64>,
    v: &DVector<f64>,
    sites: &[(&Slot, f64)],
) -> DVector<f64> {
    let scale = x.amax();
    let open: Vec<usize> = (0..sites.len())
        .filter(|&k| x[sites[k].0.normal[0]].abs() <= 1e-9 * scale)
        .collect();
    let mut best: Option<(DVector<f64>, f64)> = None;
    for choice in 0..1usize << open.len() {
        let signs: Vec<f64> = (0..sites.len())
            .map(|k| match open.iter().position(|&o| o == k) {
                Some(bit) if choice >> bit & 1 == 1 => -1.0,
                Some(_) => 1.0,
                None if x[sites[k].0.normal[0]] < 0.0 => -1.0,
                None => 1.0,
            })
            .collect();
        if let Some((point, r)) = farthest_with_signs(x, v, sites, &signs) {
            if best.as_ref().is_none_or(|(_, least)| r < *least) {
                best = Some((point, r));
            }
        }
    }
    best.map_or_else(|| x.clone(), |(point, _)| point)
}

/// [`farthest_from_slipping`] with each site's N on the side of `signs`: the point and its
/// r, or `None` when no point has every N on its side.
fn farthest_with_signs(
    x: &DVector<f64>,
    v: &DVector<f64>,
    sites: &[(&Slot, f64)],
    signs: &[f64],
) -> Option<(DVector<f64>, f64)> {
    // Each condition as `c0 + c1 t ≤ 0` on x + t v.
    let conditions = |r: f64| -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        for ((slot, mu), sign) in sites.iter().zip(signs) {
            let (f, n) = (slot.tangential[0], slot.normal[0]);
            let (n0, n1) = (sign * x[n], sign * v[n]);
            out.push((-n0, -n1));
            out.push((x[f] - r * mu * n0, v[f] - r * mu * n1));
            out.push((-x[f] - r * mu * n0, -v[f] - r * mu * n1));
        }
        out
    };
    let interval = |r: f64| -> Option<(f64, f64)> {
        let (mut low, mut high) = (f64::NEG_INFINITY, f64::INFINITY);
        for (c0, c1) in conditions(r) {
            let slack = 1e-12 * (c0.abs() + 1.0);
            if c1.abs() <= 1e-15 {
                if c0 > slack {
                    return None;
                }
            } else if c1 > 0.0 {
                high = high.min(-c0 / c1);
            } else {
                low = low.max(-c0 / c1);
            }
        }
        (low <= high).then_some((low, high))
    };
    let at = |t: f64| x + v * t;
    let mut high = 1.0;
    while interval(high).is_none() {
        high *= 2.0;
        if high > 1e12 {
            return None;
        }
    }
    let mut low = 0.0;
    for _ in 0..100 {
        let middle = 0.5 * (low + high);
        if interval(middle).is_some() {
            high = middle;
        } else {
            low = middle;
        }
    }
    let point = match interval(high)? {
        (from, to) if from.is_finite() && to.is_finite() => at(0.5 * (from + to)),
        (from, _) if from.is_finite() => at(from),
        (_, to) if to.is_finite() => at(to),
        _ => return None,
    };
    Some((point, high))
}
