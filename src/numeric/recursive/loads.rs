//! The loads as the articulated-body passes take them: their generalized active forces
//! (see Kane's generalized forces, [`crate::equations::kane_generalized_forces`]), formed in symbols once and compiled into one
//! program of the constants, the coordinates, their rates and `t`, run at each state for
//! the joint forces τ.

use crate::equations::kane_generalized_forces as generalized_forces;
use crate::equations::Derivation;
use crate::numeric::inputs::state_symbols;
use crate::symbolic::Program;
use std::cell::RefCell;

/// The compiled generalized forces of a problem's loads.
#[derive(Clone, Debug)]
pub(super) struct Loads {
    program: Program,
    /// The inputs of one run: the constants' values, then the state (written per run).
    inputs: RefCell<Vec<f64>>,
    constants: usize,
    scratch: RefCell<Vec<f64>>,
}

impl Loads {
    /// The loads of `derivation`'s problem; `None` where none does work with the rates.
    pub fn new(derivation: &Derivation) -> Option<Loads> {
        let model = &derivation.model;
        let forces = generalized_forces(model, &derivation.actions);
        if forces.iter().all(|q| q.is_zero()) {
            return None;
        }
        let problem = model.problem;
        let inputs: Vec<f64> = problem.constants.iter().map(|c| c.value).collect();
        Some(Loads {
            program: Program::compile(&state_symbols(problem), &forces),
            constants: inputs.len(),
            inputs: RefCell::new(inputs),
            scratch: RefCell::default(),
        })
    }

    /// τ at time `t`, coordinates `q` and rates `rates`, into `tau` (coordinate order).
    pub fn run(&self, t: f64, q: &[f64], rates: &[f64], tau: &mut [f64]) {
        let mut inputs = self.inputs.borrow_mut();
        inputs.truncate(self.constants);
        inputs.extend_from_slice(q);
        inputs.extend_from_slice(rates);
        inputs.push(t);
        self.program
            .run(&inputs, &mut self.scratch.borrow_mut(), tau);
    }

    /// The number of operations of one run.
    pub fn operation_count(&self) -> usize {
        self.program.operation_count()
    }
}
