//! The independent speeds of a constrained system and the dependent ones written with
//! them, `u_D = C u_I + d`, symbolically: what Kane's method needs to form one equation per
//! independent speed, in which no constraint force appears (Kane & Levinson, ch. 4).
//!
//! With the velocity constraints `A q̇ + β = 0` split by columns into the dependent rates
//! `D` (chosen in [`super::dependent`]), the independent ones `I` and the prescribed ones
//! `P`: `q̇_D = C q̇_I + C_P q̇_P + d`, with `C = −A_D⁻¹ A_I` and `C_P = −A_D⁻¹ A_P`.
//! The columns of `A_D⁻¹` are the dependent rates that violate one constraint by a unit
//! while keeping the others: the motion of an auxiliary speed along that constraint's
//! reaction.

use super::constraints::RowOrigin;
use super::model::Model;
use crate::symbolic::diff::time_derivative;
use crate::symbolic::linear::linear_split;
use crate::symbolic::subst::substitute;
use crate::symbolic::{add, simplify, Expr, Symbol};

/// The most expression nodes `A_D⁻¹` may hold: beyond it the dependent speeds are not
/// written out (a long chain of contacts), and Kane's rows keep the constraint forces.
const LARGEST_INVERSE: usize = 4_000;

/// The most operations an entry of `C` may have once simplified. Past it the relation
/// `u_D = C u_I` no longer reads as a textbook writes it (nested fractions the simplifier
/// cannot cancel, e.g. a no-slip row written by hand with a spin coefficient that is 1
/// only on the motion, `(x² + y²)²/(R − r)⁴`), and Kane's rows keep the constraint forces
/// instead, which reads better.
const LONGEST_ENTRY_OF_C: usize = 30;

/// The most dependent rates solved together symbolically (one block of `A_D`).
const LARGEST_BLOCK: usize = 6;

/// Why Kane's rows keep the constraint forces as unknowns instead of taking the independent
/// speeds alone: said in the handout, since a student expects the independent speeds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeptForces {
    /// The constraints are not linear in the rates with coefficients free of them, or do
    /// not fix as many dependent rates as they have rows.
    NotSolvable,
    /// `A_D` has a block too large, or its elimination grows past what can be written.
    LargeBlock,
    /// An entry of `C` would not read as a textbook writes it.
    LongRelation,
}

impl KeptForces {
    /// The reason, in words that end a sentence.
    pub fn reason(self) -> &'static str {
        match self {
            KeptForces::NotSolvable => {
                "the velocity constraints do not give the dependent rates as a linear map of the others"
            }
            KeptForces::LargeBlock => {
                "the dependent rates are coupled in a block too large to solve for in symbols that a reader could follow"
            }
            KeptForces::LongRelation => {
                "solved in symbols, the dependent rates would be fractions within fractions, longer than the rows they would save"
            }
        }
    }
}

/// The dependent speeds of a constrained model as linear maps of the independent ones.
#[derive(Clone, Debug)]
pub struct DependentSpeeds {
    /// Coordinates whose rates are the independent speeds, in coordinate order.
    pub independent: Vec<usize>,
    /// Coordinates whose rates are dependent, in the order of `C`'s rows.
    pub dependent: Vec<usize>,
    /// Prescribed coordinates, in coordinate order.
    pub prescribed: Vec<usize>,
    /// The velocity constraint rows solved (indices into `Constraints::rows`), in the order
    /// of `A_D⁻¹`'s columns: every row but the prescribed coordinates'.
    pub rows: Vec<usize>,
    /// `C[s][r] = ∂q̇_{D_s}/∂q̇_{I_r}`, simplified.
    pub c: Vec<Vec<Expr>>,
    /// `C_P[s][p] = ∂q̇_{D_s}/∂q̇_{P_p}`, simplified.
    pub c_prescribed: Vec<Vec<Expr>>,
    /// `A_D⁻¹[s][k]`: the dependent rate `s` that violates constraint row `rows[k]` by a
    /// unit, the others held.
    pub violation: Vec<Vec<Expr>>,
    /// `d_s = −Σ_k A_D⁻¹[s][k] β_k`: what the dependent rate `s` has besides the speeds
    /// (terms of time in a constraint, e.g. a moving support).
    pub rest: Vec<Expr>,
}

impl DependentSpeeds {
    /// The dependent speeds of `model`: `Ok(None)` when it has no velocity constraints to
    /// solve, and why Kane's rows keep the constraint forces when the map is not written
    /// (the constraints do not fix the dependent rates, or the map would be too long).
    ///
    /// # Errors
    /// [`KeptForces`]: why the dependent speeds are not written.
    pub fn written(model: &Model) -> Result<Option<DependentSpeeds>, KeptForces> {
        let problem = model.problem;
        let constraints = &model.constraints;
        let n = problem.coordinates.len();
        let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
        let rows: Vec<usize> = (0..constraints.rows.len())
            .filter(|&k| !matches!(constraints.rows[k].origin, RowOrigin::Prescribed(_)))
            .collect();
        let dependent = constraints.dependent_rates.clone();
        let prescribed = constraints.prescribed.clone();
        if rows.is_empty() && prescribed.is_empty() {
            return Ok(None);
        }
        if dependent.len() != rows.len() {
            return Err(KeptForces::NotSolvable);
        }
        let independent: Vec<usize> = (0..n)
            .filter(|i| !dependent.contains(i) && !prescribed.contains(i))
            .collect();
        let mut a: Vec<Vec<Expr>> = Vec::with_capacity(rows.len());
        let mut beta: Vec<Expr> = Vec::with_capacity(rows.len());
        for &k in &rows {
            let (coefficients, rest) = linear_split(&constraints.rows[k].velocity, &rates)
                .map_err(|_| KeptForces::NotSolvable)?;
            if coefficients
                .iter()
                .any(|c| rates.iter().any(|r| c.contains(r)))
            {
                return Err(KeptForces::NotSolvable);
            }
            a.push(coefficients.iter().map(simplify).collect());
            beta.push(rest);
        }
        // A_D: rows are constraints, columns the dependent rates.
        let a_d: Vec<Vec<Expr>> = a
            .iter()
            .map(|row| dependent.iter().map(|&s| row[s].clone()).collect())
            .collect();
        if super::speeds::largest_block(&a_d) > LARGEST_BLOCK {
            return Err(KeptForces::LargeBlock);
        }
        // `inverse` maps the rows' values back to the columns: [s][k].
        let violation = super::speeds::inverse_within(&a_d, Some(LARGEST_INVERSE))
            .ok_or(KeptForces::LargeBlock)?;
        let mut size = 0;
        for entry in violation.iter().flatten() {
            size += entry.operation_count_capped(LARGEST_INVERSE);
            if size > LARGEST_INVERSE {
                return Err(KeptForces::LargeBlock);
            }
        }
        // Written with what holds on the motion, where the map is used: inside a ring,
        // θ̇ = (R − r)/(r y) ẋ rather than (x² + y²)/((R − r) r y) ẋ.
        let on_motion = |e: Expr| {
            constraints
                .relations
                .iter()
                .fold(e, |e, (_, relation)| relation.reduce(&e))
        };
        let violation: Vec<Vec<Expr>> = violation
            .into_iter()
            .map(|row| row.into_iter().map(on_motion).collect())
            .collect();
        let map = |columns: &[usize]| -> Vec<Vec<Expr>> {
            (0..dependent.len())
                .map(|s| {
                    columns
                        .iter()
                        .map(|&r| {
                            let terms = rows
                                .iter()
                                .enumerate()
                                .map(|(k, _)| &violation[s][k] * &a[k][r]);
                            on_motion(simplify(&-add(terms)))
                        })
                        .collect()
                })
                .collect()
        };
        let rest: Vec<Expr> = (0..dependent.len())
            .map(|s| {
                on_motion(simplify(&-add(beta
                    .iter()
                    .enumerate()
                    .map(|(k, b)| &violation[s][k] * b))))
            })
            .collect();
        let mut c = map(&independent);
        let mut c_prescribed = map(&prescribed);
        let (mut rest, mut violation) = (rest, violation);
        // One name for the sum the dependent rates are divided by, as a textbook writes it.
        let mut entries: Vec<&mut Expr> = c
            .iter_mut()
            .chain(c_prescribed.iter_mut())
            .chain(violation.iter_mut())
            .flatten()
            .chain(rest.iter_mut())
            .collect();
        super::denominator::name_denominators(&mut entries);
        if c.iter()
            .flatten()
            .any(|e| e.operation_count_capped(LONGEST_ENTRY_OF_C) > LONGEST_ENTRY_OF_C)
        {
            return Err(KeptForces::LongRelation);
        }
        Ok(Some(DependentSpeeds {
            rest,
            c,
            c_prescribed,
            independent,
            dependent,
            prescribed,
            rows,
            violation,
        }))
    }

    /// The weights of the coordinates' rates in the motion of independent speed `r`
    /// (index into `independent`): one on its own rate, `C[s][r]` on each dependent one.
    pub fn independent_weights(&self, r: usize, n: usize) -> Vec<Expr> {
        self.weights(self.independent[r], |s| self.c[s][r].clone(), n)
    }

    /// The weights of the motion of prescribed coordinate `p` (index into `prescribed`),
    /// the drive's own speed: one on its rate, `C_P[s][p]` on each dependent one.
    pub fn prescribed_weights(&self, p: usize, n: usize) -> Vec<Expr> {
        self.weights(self.prescribed[p], |s| self.c_prescribed[s][p].clone(), n)
    }

    /// The weights of the motion that violates row `rows[k]` by a unit: `A_D⁻¹[s][k]` on
    /// each dependent rate, nothing on the others.
    pub fn violation_weights(&self, k: usize, n: usize) -> Vec<Expr> {
        let mut w = vec![Expr::zero(); n];
        for (s, &d) in self.dependent.iter().enumerate() {
            w[d] = self.violation[s][k].clone();
        }
        w
    }

    fn weights(&self, own: usize, dependent: impl Fn(usize) -> Expr, n: usize) -> Vec<Expr> {
        let mut w = vec![Expr::zero(); n];
        w[own] = Expr::one();
        for (s, &d) in self.dependent.iter().enumerate() {
            w[d] = dependent(s);
        }
        w
    }

    /// Each dependent rate written with the independent ones: `C q̇_I + C_P q̇_P + d`.
    pub fn dependent_rates(&self, model: &Model) -> Vec<Expr> {
        let problem = model.problem;
        (0..self.dependent.len())
            .map(|s| {
                let of = |list: &[usize], c: &[Expr]| -> Vec<Expr> {
                    list.iter()
                        .zip(c)
                        .map(|(&i, c)| c * &problem.coordinate_expr(i, 1))
                        .collect()
                };
                let mut terms = of(&self.independent, &self.c[s]);
                terms.extend(of(&self.prescribed, &self.c_prescribed[s]));
                terms.push(self.rest[s].clone());
                add(terms)
            })
            .collect()
    }

    /// Each dependent q'' written with the independent ones: the derivative of
    /// [`Self::dependent_rates`], its dependent rates written likewise.
    ///
    /// # Errors
    /// When a rate's expression cannot be differentiated.
    pub fn dependent_accelerations(
        &self,
        model: &Model,
    ) -> Result<Vec<Expr>, crate::symbolic::diff::DiffError> {
        let rates = self.dependent_rates(model);
        rates
            .iter()
            .map(|rate| Ok(self.with_independent_rates(model, &rates, &time_derivative(rate)?)))
            .collect()
    }

    /// `e` with each dependent rate replaced by its expression in `rates`.
    pub fn with_independent_rates(&self, model: &Model, rates: &[Expr], e: &Expr) -> Expr {
        let problem = model.problem;
        substitute(e, &|symbol| {
            self.dependent
                .iter()
                .position(|&d| problem.coordinate_symbol(d, 1) == *symbol)
                .map(|s| rates[s].clone())
        })
    }

    /// The column of `A_D⁻¹` for the constraint row enforced by `unknown`, if one is solved.
    pub fn row_of(&self, model: &Model, unknown: &Symbol) -> Option<usize> {
        self.rows
            .iter()
            .position(|&k| model.constraints.rows[k].unknown == *unknown)
    }
}
