//! Evaluating a derivation at a state: the compiled program for `A`, `b`, the reaction
//! directions and the energies (compiled in `build`), then the linear solve (see
//! [`super::linear`]).

mod build;

use super::linear::solve_linear_owned;
use super::recursive::Recursive;
use super::speeds::SpeedProgram;
use super::system::{describe_state, Evaluation, ReactionColumn, System};
use super::SolveError;
use crate::equations::Method;
use build::Lazy;
use nalgebra::{DMatrix, DVector};

/// Where one reaction component sits: its unknown's index and its direction's outputs.
#[derive(Clone, Debug)]
struct ReactionComponentSlot {
    is_force: bool,
    unknown: Option<usize>,
    direction_output: usize,
}

/// The reaction of one requested joint.
#[derive(Clone, Debug)]
struct ReactionSlot {
    joint: String,
    components: Vec<ReactionComponentSlot>,
}

/// A derivation compiled for fast, repeated evaluation.
#[derive(Clone, Debug)]
pub struct Compiled {
    /// The method the equations came from.
    pub method: Method,
    /// Coordinate names in contract order.
    pub coordinates: Vec<String>,
    /// For each coordinate, a massless body it moves: the reason its q'' may be undetermined.
    massless: Vec<Option<String>>,
    constants: Vec<f64>,
    unknowns: usize,
    /// A and b (and the reactions' directions); compiled when first run where the
    /// articulated-body algorithm gives the q'' and it is only the fallback.
    program: Lazy,
    reactions: Vec<ReactionSlot>,
    /// The kinetic and potential energies, compiled when first asked: `solve` never asks.
    energy: Lazy,
    conservative: bool,
    dissipative_only: bool,
    outputs: usize,
    /// The constraints, when there are any.
    assembly: Option<super::assemble::Assembly>,
    /// Each prescribed coordinate's name and the index of its drive among the unknowns.
    drives: Vec<(String, Option<usize>)>,
    // Reused between evaluations, so a solve allocates no program-sized buffer.
    scratch: std::cell::RefCell<Vec<f64>>,
    /// The declared speeds' kinematic differential equations, when there are any.
    speeds: Option<SpeedProgram>,
    /// The friction sites, when there are any.
    friction: Option<super::friction::Friction>,
    /// The q'' by the articulated-body algorithm, where [`Compiled::fastest`] chose it.
    recursive: Option<super::recursive::Recursive>,
}

/// The q'' and the requested reactions at one state.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// The q'', in coordinate order.
    pub accelerations: Vec<f64>,
    /// Each requested joint: name, force and moment in the parent's unit vectors.
    pub reactions: Vec<(String, [f64; 3], [f64; 3])>,
    /// Each prescribed coordinate: the generalized force that drives it.
    pub drives: Vec<(String, f64)>,
    /// Each friction site: sticking or slipping, its normal and friction forces.
    pub friction: Vec<super::friction::SiteState>,
}

/// The solution at one state.
#[derive(Clone, Debug, PartialEq)]
pub struct StateSolution {
    /// The q'', in coordinate order.
    pub accelerations: Vec<f64>,
    /// Each requested joint: name, force and moment in the parent's unit vectors.
    pub reactions: Vec<(String, [f64; 3], [f64; 3])>,
    /// Each prescribed coordinate: the generalized force that drives it.
    pub drives: Vec<(String, f64)>,
    /// Each declared speed: name, `u` and `u'` (empty when the speeds are the rates).
    pub speeds: Vec<(String, f64, f64)>,
    /// Each friction site: sticking or slipping, its normal and friction forces.
    pub friction: Vec<super::friction::SiteState>,
}

impl Compiled {
    /// The operations of one evaluation of the loads' generalized forces where the q'' come
    /// from the articulated-body algorithm (zero without loads); `None` where they do not.
    pub fn load_operation_count(&self) -> Option<usize> {
        self.recursive.as_ref().map(Recursive::load_operation_count)
    }

    /// The same equations with other values of the constants (in the problem's order):
    /// what statics evaluates at each trial value of a constant it seeks.
    pub fn with_constants(&self, constants: &[f64]) -> Compiled {
        Compiled {
            constants: constants.to_vec(),
            ..self.clone()
        }
    }

    /// Whether the q'' come from the articulated-body algorithm, not the compiled rows.
    pub fn is_recursive(&self) -> bool {
        self.recursive.is_some()
    }

    /// Sets constant `index` (in the problem's order) to `value`: the same equations for
    /// another value of it (an impact's impulse, one component at a time).
    pub fn set_constant(&mut self, index: usize, value: f64) {
        if let Some(c) = self.constants.get_mut(index) {
            *c = value;
        }
    }

    /// The number of operations to evaluate `A` and `b` once (with the reaction directions).
    pub fn operation_count(&self) -> usize {
        self.program.program().operation_count()
    }

    /// Solves for the q'' and the requested reactions at time `t`, coordinates `q`, rates `rates`.
    ///
    /// # Errors
    /// A singular system, naming the state (and the coordinate that moves no mass, when one
    /// does not), or a value that is not finite.
    pub fn solve(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<StateSolution, SolveError> {
        let motion = self.motion(t, q, rates)?;
        let speeds = match &self.speeds {
            Some(program) => {
                let inputs = self.inputs(t, q, rates);
                let values = program.run(&inputs[..inputs.len() - program.n]);
                program.rates_of_speeds(&values, &motion.accelerations)
            }
            None => Vec::new(),
        };
        Ok(StateSolution {
            speeds,
            accelerations: motion.accelerations,
            reactions: motion.reactions,
            drives: motion.drives,
            friction: motion.friction,
        })
    }

    fn inputs(&self, t: f64, q: &[f64], rates: &[f64]) -> Vec<f64> {
        let mut inputs = self.constants.clone();
        inputs.extend_from_slice(q);
        inputs.extend_from_slice(rates);
        inputs.push(t);
        if let Some(speeds) = &self.speeds {
            let values = speeds.run(&inputs);
            inputs.extend_from_slice(&values[..speeds.n]);
        }
        inputs
    }

    /// The q'' and the requested reactions only (no energies): one evaluation of `A` and
    /// `b` and one LU solve.
    ///
    /// # Errors
    /// As for [`Compiled::solve`].
    pub fn motion(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Motion, SolveError> {
        self.motion_held(t, q, rates, None)
    }

    /// The friction sites' names (empty without friction).
    pub fn friction_sites(&self) -> Vec<String> {
        self.friction.as_ref().map_or_else(Vec::new, |f| f.names())
    }

    /// Each friction site at a state, held as `held` (decided when `None`), with the values
    /// of its switching functions (see `super::friction::Friction::switching`).
    ///
    /// # Errors
    /// As for [`Compiled::solve`].
    pub fn friction_at(
        &self,
        t: f64,
        q: &[f64],
        rates: &[f64],
        held: Option<&[super::friction::Held]>,
    ) -> Result<(Vec<super::friction::SiteState>, Vec<f64>), SolveError> {
        let Some(friction) = &self.friction else {
            return Ok((Vec::new(), Vec::new()));
        };
        let states = self.motion_held(t, q, rates, held)?.friction;
        let held: Vec<super::friction::Held> = match held {
            Some(held) => held.to_vec(),
            None => states
                .iter()
                .map(super::friction::SiteState::held)
                .collect(),
        };
        let switching = friction.switching(&self.inputs(t, q, rates), &held, &states);
        Ok((states, switching))
    }

    /// As [`Compiled::motion`], each friction site held as `held` (decided from its slip
    /// velocity when `None`).
    ///
    /// # Errors
    /// As for [`Compiled::solve`].
    pub fn motion_held(
        &self,
        t: f64,
        q: &[f64],
        rates: &[f64],
        held: Option<&[super::friction::Held]>,
    ) -> Result<Motion, SolveError> {
        // A state the recursive form finds singular goes on to the dense form, which says why.
        if let (Some(tree), None) = (&self.recursive, held) {
            if let Some(accelerations) = tree.accelerations(t, q, rates) {
                return Ok(Motion {
                    accelerations,
                    reactions: Vec::new(),
                    drives: Vec::new(),
                    friction: Vec::new(),
                });
            }
        }
        let inputs = self.inputs(t, q, rates);
        let mut scratch = self.scratch.take();
        let mut values = vec![0.0; self.outputs];
        self.program
            .program()
            .run(&inputs, &mut scratch, &mut values);
        self.scratch.replace(scratch);
        let n = self.unknowns;
        let state = || describe_state(t, &self.coordinates, q, rates);
        if !values[..n * n + n].iter().all(|x| x.is_finite()) {
            return Err(SolveError::NotFinite {
                state: state(),
                what: "a coefficient of the equations".into(),
            });
        }
        let a = DMatrix::from_row_slice(n, n, &values[..n * n]);
        let b = DVector::from_column_slice(&values[n * n..n * n + n]);
        let singular = || SolveError::SingularSystem {
            state: state(),
            detail: self.singularity_detail(&DMatrix::from_row_slice(n, n, &values[..n * n])),
        };
        // Factored in place; rebuilt from the values only to explain a singular one.
        let (x, friction) = match &self.friction {
            None => (solve_linear_owned(a, b).ok_or_else(singular)?, Vec::new()),
            Some(friction) => {
                let decided;
                let held = match held {
                    Some(held) => held,
                    None => {
                        decided = friction.held_at(&inputs, rates);
                        &decided
                    }
                };
                friction.solve(&a, &b, &inputs, held).ok_or_else(singular)?
            }
        };
        let mut accelerations: Vec<f64> = x.iter().take(self.coordinates.len()).copied().collect();
        if let Some(speeds) = &self.speeds {
            // The unknowns are the u': q'' = W⁻¹ (u' − Ẇ q').
            let values = speeds.run(&inputs[..inputs.len() - speeds.n]);
            accelerations = speeds
                .accelerations(&values, &accelerations)
                .ok_or_else(|| SolveError::SingularSystem {
                    state: state(),
                    detail:
                        "the speeds do not determine the rates here: W of u = W(q) q' is singular"
                            .into(),
                })?;
        }
        let mut reactions = Vec::new();
        for slot in &self.reactions {
            let (mut force, mut moment) = ([0.0; 3], [0.0; 3]);
            for c in &slot.components {
                let magnitude = c.unknown.map_or(0.0, |i| x[i]);
                let target = if c.is_force { &mut force } else { &mut moment };
                for (k, value) in target.iter_mut().enumerate() {
                    *value += magnitude * values[c.direction_output + k];
                }
            }
            reactions.push((slot.joint.clone(), force, moment));
        }
        let finite = accelerations.iter().all(|x| x.is_finite())
            && reactions
                .iter()
                .all(|(_, f, m)| f.iter().chain(m).all(|x| x.is_finite()));
        if !finite {
            return Err(SolveError::NotFinite {
                state: state(),
                what: "the solution".into(),
            });
        }
        let drives = self
            .drives
            .iter()
            .map(|(name, index)| (name.clone(), index.map_or(0.0, |i| x[i])))
            .collect();
        Ok(Motion {
            accelerations,
            reactions,
            drives,
            friction,
        })
    }

    fn singularity_detail(&self, a: &DMatrix<f64>) -> String {
        let scale = a
            .iter()
            .fold(0.0f64, |m, x| m.max(x.abs()))
            .max(f64::MIN_POSITIVE);
        for (i, name) in self.coordinates.iter().enumerate() {
            if a.column(i).iter().all(|x| x.abs() <= 1e-12 * scale) {
                return match &self.massless[i] {
                    Some(body) => crate::mechanics::undetermined(name, body),
                    None => format!("the coordinate `{name}` moves nothing with mass or inertia, so `{name}''` is undetermined"),
                };
            }
        }
        // Rows that keep every column can still leave a massless body's coordinate free
        // together with others (a light slider under a pendulum hanging straight down): its
        // q'' is then part of the motion the equations do not fix.
        if let Some(i) = self.massless_left_free(a) {
            if let Some(body) = &self.massless[i] {
                return crate::mechanics::undetermined(&self.coordinates[i], body);
            }
        }
        "the equations do not determine the unknowns here (a singular configuration, such as gimbal lock)".into()
    }

    /// A coordinate that moves a massless body and takes part in the motion that `a`
    /// leaves undetermined (its null space, from the smallest singular value).
    fn massless_left_free(&self, a: &DMatrix<f64>) -> Option<usize> {
        if self.massless.iter().all(Option::is_none) || a.nrows() != a.ncols() {
            return None;
        }
        let svd = a.clone().svd(false, true);
        let v_t = svd.v_t.as_ref()?;
        let smallest = svd.singular_values.imin();
        let null = v_t.row(smallest);
        let size = null.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        (0..self.coordinates.len().min(null.len()))
            .find(|&i| self.massless[i].is_some() && null[i].abs() > 1e-6 * size)
    }
}

impl System for Compiled {
    fn coordinate_names(&self) -> Vec<String> {
        self.coordinates.clone()
    }

    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        let mut columns: Vec<ReactionColumn> = self
            .reactions
            .iter()
            .flat_map(|slot| ReactionColumn::of_site(&slot.joint))
            .collect();
        columns.extend(self.drives.iter().map(|(name, _)| ReactionColumn::Drive {
            coordinate: name.clone(),
        }));
        columns
    }

    fn evaluate(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        let s = self.solve(t, q, rates)?;
        let (kinetic, potential) = self.energies(t, q, rates)?;
        let reactions = s
            .reactions
            .iter()
            .flat_map(|(_, f, m)| f.iter().chain(m.iter()).copied())
            .chain(s.drives.iter().map(|(_, v)| *v))
            .collect();
        Ok(Evaluation {
            accelerations: s.accelerations,
            reactions,
            kinetic,
            potential,
        })
    }

    fn accelerations(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Vec<f64>, SolveError> {
        self.motion(t, q, rates).map(|m| m.accelerations)
    }

    fn energies(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<(f64, f64), SolveError> {
        let mut scratch = self.scratch.take();
        let mut energies = [0.0; 2];
        self.energy
            .program()
            .run(&self.inputs(t, q, rates), &mut scratch, &mut energies);
        self.scratch.replace(scratch);
        Ok((energies[0], energies[1]))
    }

    fn is_conservative(&self) -> bool {
        self.conservative
    }

    fn assemble(&self, t: f64, q: &mut [f64], rates: &mut [f64]) -> Result<(), SolveError> {
        match &self.assembly {
            Some(assembly) => assembly.assemble(&self.constants, t, q, rates),
            None => Ok(()),
        }
    }

    fn drift(&self, t: f64, q: &[f64], rates: &[f64]) -> f64 {
        self.assembly
            .as_ref()
            .map_or(0.0, |a| a.drift(&self.constants, t, q, rates))
    }

    fn is_constrained(&self) -> bool {
        self.assembly.is_some()
    }

    fn has_dissipation_only(&self) -> bool {
        self.dissipative_only
    }
}
