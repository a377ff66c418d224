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
use crate::symbolic::{add, linear_split, simplify, substitute, time_derivative, Expr, Symbol};

/// The most expression nodes `A_D⁻¹` may hold: beyond it the dependent speeds are not
/// written out (a long chain of contacts), and `C` is named, evaluated at each state.
const LARGEST_INVERSE: usize = 4_000;

/// The most operations an entry of `C` may have once simplified. Past it the relation
/// `u_D = C u_I` no longer reads as a textbook writes it (nested fractions the simplifier
/// cannot cancel, e.g. a no-slip row written by hand with a spin coefficient that is 1
/// only on the motion, `(x² + y²)²/(R − r)⁴`), and `C` is named instead, evaluated at each
/// state.
const LONGEST_ENTRY_OF_C: usize = 30;

/// The most dependent rates solved together in symbols (one block of `A_D`); a larger
/// block is solved at each state.
const LARGEST_BLOCK: usize = 6;

/// Why Kane's rows keep the constraint forces as unknowns instead of taking the independent
/// speeds alone: said in the handout, since a student expects the independent speeds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeptForces {
    /// The constraints are not linear in the rates with coefficients free of them, or do
    /// not fix as many dependent rates as they have rows.
    NotSolvable,
    /// `A_D` has a block too large even to solve at each state by minors.
    LargeBlock,
}

impl KeptForces {
    /// The reason, in words that end a sentence.
    pub fn reason(self) -> &'static str {
        match self {
            KeptForces::NotSolvable => {
                "the velocity constraints do not give the dependent rates as a linear map of the others"
            }
            KeptForces::LargeBlock => {
                "the dependent rates are coupled in a block too large to solve for at each state"
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
    /// Whether the entries of `C`, `C_P`, `A_D⁻¹` and `d` are named quantities evaluated at
    /// each state (a block too large to write out in symbols) rather than written out.
    pub at_each_state: bool,
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
        let split = Split {
            model,
            rows,
            dependent,
            independent,
            prescribed,
            a,
            beta,
        };
        let in_symbols = if super::speeds::largest_block(&a_d) > LARGEST_BLOCK {
            None
        } else {
            super::speeds::inverse_within(&a_d, Some(LARGEST_INVERSE))
                .filter(|inverse| fits(inverse))
                .and_then(|inverse| split.in_symbols(inverse))
        };
        match in_symbols {
            Some(speeds) => Ok(Some(speeds)),
            None => split.at_each_state(&a_d).map(Some),
        }
    }
}

/// Whether `A_D⁻¹` is short enough to be written in symbols.
fn fits(inverse: &[Vec<Expr>]) -> bool {
    let mut size = 0;
    for entry in inverse.iter().flatten() {
        size += entry.operation_count_capped(LARGEST_INVERSE);
        if size > LARGEST_INVERSE {
            return false;
        }
    }
    true
}

/// The velocity constraints split by columns, before `A_D` is inverted.
struct Split<'m> {
    model: &'m Model<'m>,
    rows: Vec<usize>,
    dependent: Vec<usize>,
    independent: Vec<usize>,
    prescribed: Vec<usize>,
    /// `A`: a row per constraint row solved, a column per coordinate's rate.
    a: Vec<Vec<Expr>>,
    /// `β`: what each row has besides the rates.
    beta: Vec<Expr>,
}

impl Split<'_> {
    /// `−A_D⁻¹ A_X` for the columns `columns`, each entry passed through `finish`.
    fn map(
        &self,
        violation: &[Vec<Expr>],
        columns: &[usize],
        finish: &dyn Fn(Expr) -> Expr,
    ) -> Vec<Vec<Expr>> {
        (0..self.dependent.len())
            .map(|s| {
                columns
                    .iter()
                    .map(|&r| {
                        let terms = (0..self.rows.len()).map(|k| &violation[s][k] * &self.a[k][r]);
                        finish(-add(terms))
                    })
                    .collect()
            })
            .collect()
    }

    /// `d = −A_D⁻¹ β`, each entry passed through `finish`.
    fn rest(&self, violation: &[Vec<Expr>], finish: &dyn Fn(Expr) -> Expr) -> Vec<Expr> {
        (0..self.dependent.len())
            .map(|s| {
                let terms = self
                    .beta
                    .iter()
                    .enumerate()
                    .map(|(k, b)| &violation[s][k] * b);
                finish(-add(terms))
            })
            .collect()
    }

    /// The map in symbols from `A_D⁻¹` in symbols, or `None` when an entry of `C` would not
    /// read as a textbook writes it.
    fn in_symbols(&self, violation: Vec<Vec<Expr>>) -> Option<DependentSpeeds> {
        let constraints = &self.model.constraints;
        // Written with what holds on the motion, where the map is used: inside a ring,
        // θ̇ = (R − r)/(r y) ẋ rather than (x² + y²)/((R − r) r y) ẋ.
        let on_motion = |e: Expr| {
            constraints
                .relations
                .iter()
                .fold(e, |e, (_, relation)| relation.reduce(&e))
        };
        let mut violation: Vec<Vec<Expr>> = violation
            .into_iter()
            .map(|row| row.into_iter().map(on_motion).collect())
            .collect();
        let finish = |e: Expr| on_motion(simplify(&e));
        let mut c = self.map(&violation, &self.independent, &finish);
        let mut c_prescribed = self.map(&violation, &self.prescribed, &finish);
        let mut rest = self.rest(&violation, &finish);
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
            return None;
        }
        Some(self.speeds(c, c_prescribed, violation, rest, false))
    }

    /// The map with each entry of `A_D⁻¹`, `C`, `C_P` and `d` a named quantity evaluated at
    /// each state, as a computer, not a reader, solves a large block (PyDy does likewise).
    fn at_each_state(&self, a_d: &[Vec<Expr>]) -> Result<DependentSpeeds, KeptForces> {
        let inverse = super::inverse_by_minors::inverse_by_minors(a_d, "A_D^-1")
            .ok_or(KeptForces::LargeBlock)?;
        let named = |matrix: Vec<Vec<Expr>>, name: &str, latex: &str, note: &str| {
            let many = matrix.len() > 9 || matrix.first().is_some_and(|row| row.len() > 9);
            (matrix.into_iter().enumerate())
                .map(|(i, row)| {
                    (row.into_iter().enumerate())
                        .map(|(j, value)| {
                            let index = if many {
                                format!("{},{}", i + 1, j + 1)
                            } else {
                                format!("{}{}", i + 1, j + 1)
                            };
                            let latex = format!("{latex}_{{{index}}}");
                            Expr::evaluated(&format!("{name}[{index}]"), &latex, note, value)
                        })
                        .collect()
                })
                .collect::<Vec<Vec<Expr>>>()
        };
        let plain = |e: Expr| e;
        let c = self.map(&inverse, &self.independent, &plain);
        let c_prescribed = self.map(&inverse, &self.prescribed, &plain);
        let rest = self.rest(&inverse, &plain);
        let note = "evaluated at each state";
        let c = named(c, "C", "C", note);
        let c_prescribed = named(c_prescribed, "C_P", "C^{P}", note);
        let violation = named(inverse, "A_D^-1", "\\left(A_D^{-1}\\right)", note);
        let rest = (rest.into_iter().enumerate())
            .map(|(s, value)| {
                Expr::evaluated(
                    &format!("d[{}]", s + 1),
                    &format!("d_{{{}}}", s + 1),
                    note,
                    value,
                )
            })
            .collect();
        Ok(self.speeds(c, c_prescribed, violation, rest, true))
    }

    fn speeds(
        &self,
        c: Vec<Vec<Expr>>,
        c_prescribed: Vec<Vec<Expr>>,
        violation: Vec<Vec<Expr>>,
        rest: Vec<Expr>,
        at_each_state: bool,
    ) -> DependentSpeeds {
        DependentSpeeds {
            rest,
            c,
            c_prescribed,
            independent: self.independent.clone(),
            dependent: self.dependent.clone(),
            prescribed: self.prescribed.clone(),
            rows: self.rows.clone(),
            violation,
            at_each_state,
        }
    }
}

impl DependentSpeeds {
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
    ) -> Result<Vec<Expr>, crate::symbolic::DiffError> {
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
