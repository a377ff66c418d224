//! Compiling a derivation for evaluation: the program for `A`, `b` and the reaction
//! directions (compiled at once, or on its first run where the articulated-body algorithm
//! gives the q''), the energies' program, and what the checks need to know of the loads.

use super::{Compiled, ReactionComponentSlot, ReactionSlot};
use crate::equations::{has_potential, kinetic, potential, Derivation, SMALL_PROGRAM};
use crate::mechanics::ComponentKind;
use crate::numeric::inputs::input_symbols;
use crate::numeric::recursive::Recursive;
use crate::numeric::speeds::SpeedProgram;
use crate::problem::LoadKind;
use crate::symbolic::{Expr, Program, Symbol};

/// A program compiled on its first run.
#[derive(Clone, Debug)]
pub(super) struct Lazy {
    inputs: Vec<Symbol>,
    outputs: Vec<Expr>,
    program: std::cell::OnceCell<Program>,
}

impl Lazy {
    pub(super) fn program(&self) -> &Program {
        self.program
            .get_or_init(|| Program::compile(&self.inputs, &self.outputs))
    }

    /// Compiled already.
    fn compiled(program: Program) -> Lazy {
        Lazy {
            inputs: Vec::new(),
            outputs: Vec::new(),
            program: std::cell::OnceCell::from(program),
        }
    }
}

/// When the q'' come from the articulated-body algorithm (where it applies: a tree of
/// joints, bodies, gravity and loads).
#[derive(Clone, Copy)]
enum Aba {
    Never,
    WhenFaster,
    Always,
}

impl Compiled {
    /// Compiles the system, the requested reactions and the energies of a derivation: the
    /// system by composite bodies where the derivation has it, unless it is small and the
    /// rows as formed compile shorter (see [`SMALL_PROGRAM`]).
    pub fn new(derivation: &Derivation) -> Compiled {
        Compiled::build(derivation, Aba::Never)
    }

    /// As [`Compiled::new`], with the q'' by the articulated-body algorithm where it
    /// applies and `aba` asks for it; then the dense program, only a fallback, is compiled
    /// when first run.
    fn build(derivation: &Derivation, aba: Aba) -> Compiled {
        let model = &derivation.model;
        let problem = model.problem;
        let formed = &derivation.system;
        let n = formed.unknowns.len();
        // The reaction directions come after A and b, whichever system gives those.
        let (reactions, directions) = reaction_slots(derivation);
        let inputs = input_symbols(problem);
        let outputs_of = |system: &crate::equations::LinearSystem| {
            let mut outputs: Vec<Expr> = system.a.iter().flatten().cloned().collect();
            outputs.extend(system.b.iter().cloned());
            outputs.extend(directions.iter().cloned());
            outputs
        };
        let compile = |system: &crate::equations::LinearSystem| {
            Program::compile(&inputs, &outputs_of(system))
        };
        let assembly = crate::numeric::assemble::Assembly::new(model);
        let speeds = SpeedProgram::new(problem);
        let friction = crate::numeric::friction::Friction::new(derivation, &inputs);
        // The articulated-body algorithm takes a tree of joints, bodies, gravity and loads:
        // no reactions asked, drives, friction, declared speeds or constraints.
        let plain = reactions.is_empty()
            && model.constraints.prescribed.is_empty()
            && friction.is_none()
            && speeds.is_none()
            && assembly.is_none();
        let wanted = match aba {
            Aba::Never => false,
            Aba::WhenFaster => {
                crate::numeric::recursive::is_faster(problem.coordinates.len(), model.is_planar())
            }
            Aba::Always => true,
        };
        let recursive = (wanted && plain)
            .then(|| Recursive::new(derivation))
            .flatten();
        let program = if recursive.is_some() {
            let system = derivation.composite_system.as_ref().unwrap_or(formed);
            Lazy {
                inputs: inputs.clone(),
                outputs: outputs_of(system),
                program: std::cell::OnceCell::new(),
            }
        } else {
            Lazy::compiled(match &derivation.composite_system {
                None => compile(formed),
                Some(composite) => {
                    let by_composite = compile(composite);
                    if by_composite.operation_count() < SMALL_PROGRAM {
                        let as_formed = compile(formed);
                        if as_formed.operation_count() < by_composite.operation_count() {
                            as_formed
                        } else {
                            by_composite
                        }
                    } else {
                        by_composite
                    }
                }
            })
        };
        // The energies are a program of their own: they are not part of A and b.
        let energy = Lazy {
            inputs,
            outputs: vec![kinetic(model), potential(model)],
            program: std::cell::OnceCell::new(),
        };
        let drives = model
            .constraints
            .prescribed
            .iter()
            .map(|&p| {
                let name = problem.coordinates[p].name.clone();
                let symbol = crate::mechanics::drive_symbol(problem, p);
                (name, formed.unknowns.iter().position(|u| *u == symbol))
            })
            .collect();
        let drives_work = drives_work(model);
        Compiled {
            recursive,
            friction,
            assembly,
            drives,
            method: derivation.method,
            coordinates: problem.coordinates.iter().map(|c| c.name.clone()).collect(),
            massless: (0..problem.coordinates.len())
                .map(|i| {
                    crate::mechanics::massless_body_moved_by(model, i)
                        .map(|b| problem.body_name(b).to_string())
                })
                .collect(),
            constants: problem.constants.iter().map(|c| c.value).collect(),
            unknowns: n,
            program,
            reactions,
            energy,
            outputs: n * n + n + directions.len(),
            scratch: std::cell::RefCell::new(Vec::new()),
            speeds,
            conservative: !drives_work
                && model.constraints.friction.is_empty()
                && (0..problem.loads.len()).all(|i| has_potential(model, i)),
            dissipative_only: !drives_work
                && (0..problem.loads.len())
                    .all(|i| has_potential(model, i) || is_dissipative(&problem.loads[i].kind)),
        }
    }

    /// As [`Compiled::new`], with the q'' by the articulated-body algorithm where it
    /// applies and is the faster: an unconstrained tree of joints, bodies, gravity and
    /// loads, no reactions asked, with as many coordinates as make it the faster
    /// ([`crate::numeric::recursive::is_faster`]). The numbers of `solve` and `simulate`; the confirmation
    /// checks compile each method's own rows with [`Compiled::new`].
    pub fn fastest(derivation: &Derivation) -> Compiled {
        Compiled::build(derivation, Aba::WhenFaster)
    }

    /// As [`Compiled::new`], with the q'' by the articulated-body algorithm wherever it
    /// applies, whatever the number of coordinates: the benchmarks time both forms with it.
    pub fn recursive(derivation: &Derivation) -> Compiled {
        Compiled::build(derivation, Aba::Always)
    }
}

fn is_dissipative(kind: &LoadKind) -> bool {
    matches!(kind, LoadKind::Damper { .. } | LoadKind::JointDamper { .. })
}

/// The slots of the requested reactions' components, and their directions in the parent's
/// unit vectors, output after `A` and `b`.
fn reaction_slots(derivation: &Derivation) -> (Vec<ReactionSlot>, Vec<Expr>) {
    let model = &derivation.model;
    let formed = &derivation.system;
    let n = formed.unknowns.len();
    let mut directions: Vec<Expr> = Vec::new();
    let mut reactions = Vec::new();
    for &j in &model.problem.find_reactions {
        let joint = &model.sites[j];
        let mut components = Vec::new();
        for component in &joint.reactions {
            let symbol = component.unknown(&joint.name);
            let direction = component
                .direction
                .components_in(joint.parent, &model.frames);
            components.push(ReactionComponentSlot {
                is_force: component.kind == ComponentKind::Force,
                unknown: formed.unknowns.iter().position(|u| *u == symbol),
                direction_output: n * n + n + directions.len(),
            });
            directions.extend(direction);
        }
        reactions.push(ReactionSlot {
            joint: joint.name.clone(),
            components,
        });
    }
    (reactions, directions)
}

/// Whether drives, or constraints that change with time, do work: a prescribed `w*t` has
/// the rate row `q' - w`, free of t, so the position row and the origin are asked too.
fn drives_work(model: &crate::mechanics::Model) -> bool {
    let time = crate::symbolic::Symbol::Time;
    let problem = model.problem;
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 1))
        .collect();
    // A `velocity` entry with a term free of the rates (`x' - v0`) moves the system as a
    // drive does: its force works.
    let affine = |r: &crate::mechanics::ConstraintRow| {
        matches!(r.origin, crate::mechanics::RowOrigin::Velocity(_))
            && !matches!(
                crate::symbolic::linear_split(&r.velocity, &rates),
                Ok((_, rest)) if rest.is_zero()
            )
    };
    model.constraints.rows.iter().any(|r| {
        matches!(r.origin, crate::mechanics::RowOrigin::Prescribed(_))
            || r.velocity.contains(&time)
            || r.position.as_ref().is_some_and(|p| p.contains(&time))
            || affine(r)
    })
}
