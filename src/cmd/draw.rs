//! `mbd-tutor draw`: the configuration and every free-body diagram as SVG files.

use crate::cli::{Common, DrawArgs};
use crate::equations::{Derivation, Method};
use crate::numeric::System;
use crate::problem::State;
use crate::render::draw::{Drawing, View};
use crate::solution::draw_pictures as draw;
use crate::Error;

/// The derivation whose plan the pictures show and the q'' at the state, if solvable. The
/// state is first made to meet the constraints (dependent coordinates and rates, prescribed
/// motion), so that a loop is drawn closed; the solver plans again where the Motion Law's
/// plan is singular, as for `solve`.
///
/// # Errors
/// When the equations cannot be derived, or the constraints cannot be met.
pub fn derivation_at<'p>(
    problem: &'p crate::problem::Problem,
    method: Method,
    state: &mut State,
) -> Result<(Derivation<'p>, Option<Vec<f64>>), Error> {
    let derivation = crate::pipeline::derive(problem, method, crate::pipeline::Purpose::Handout)?;
    let solver = crate::pipeline::Solver::new(problem, &derivation);
    solver.assemble(state.t, &mut state.q, &mut state.rates)?;
    let accelerations = solver
        .solve(state.t, &state.q, &state.rates)
        .ok()
        .map(|s| s.accelerations);
    Ok((derivation, accelerations))
}

/// Every picture of the problem named on the command line at the chosen state.
///
/// # Errors
/// A usage error for a bad `--view`, `--time` or `--state`; an invalid problem.
pub fn drawings(args: &DrawArgs) -> Result<Vec<Drawing>, Error> {
    let view = match &args.view {
        Some(text) => View::parse(text).map_err(Error::Usage)?,
        None => View::Isometric,
    };
    args.given.check_time()?;
    let problem = super::load_with_overrides(&Common {
        output: None,
        ..args.common.clone()
    })?;
    let (q, rates) = super::solve::initial_state(&problem, &args.given.state)?;
    let method = super::method(args.common.method);
    let mut state = State {
        t: args.given.time,
        q,
        rates,
    };
    let (derivation, accelerations) = derivation_at(&problem, method, &mut state)?;
    Ok(draw(
        &derivation,
        state.t,
        &state.q,
        &state.rates,
        accelerations.as_deref(),
        view,
    ))
}

/// Runs `mbd-tutor draw`.
///
/// # Errors
/// A usage error without `-o DIR`; whatever [`drawings`] reports; an unwritable directory.
pub fn run(args: DrawArgs) -> Result<(), Error> {
    let Some(directory) = args.common.output.clone() else {
        return Err(Error::Usage(
            "draw writes several pictures: name the output directory with -o DIR".into(),
        ));
    };
    if directory.is_file() {
        return Err(Error::Usage(format!(
            "{} is a file: -o names the directory the pictures go to",
            directory.display()
        )));
    }
    let drawings = drawings(&args)?;
    let motion = if args.animate {
        Some(motion_svg(&args)?)
    } else {
        None
    };
    let mut planned: Vec<String> = Vec::new();
    for drawing in &drawings {
        let stem = crate::output::short_stem(&drawing.name);
        planned.push(format!("{stem}.svg"));
        if args.tikz {
            planned.push(format!("{stem}.tex"));
        }
    }
    if motion.is_some() {
        planned.push("motion.svg".into());
    }
    // Nothing is written when one of the pictures would replace the problem file.
    crate::output::refuse_input_in(&args.common.problem, &directory, |name| {
        planned.iter().any(|p| p == name)
    })?;
    std::fs::create_dir_all(&directory).map_err(|source| Error::Io {
        path: directory.clone(),
        source,
    })?;
    for drawing in &drawings {
        let stem = crate::output::short_stem(&drawing.name);
        let path = directory.join(format!("{stem}.svg"));
        // Names in words (`push_1`) with their subscripts, as the handout writes them.
        let svg = crate::render::subscripts_in_words(&drawing.svg(""));
        crate::output::write_output(Some(&path), svg.as_bytes())?;
        if args.tikz {
            let path = directory.join(format!("{stem}.tex"));
            crate::output::write_output(Some(&path), drawing.tikz().as_bytes())?;
        }
    }
    if let Some(svg) = motion {
        let svg = crate::render::subscripts_in_words(&svg);
        crate::output::write_output(Some(&directory.join("motion.svg")), svg.as_bytes())?;
    }
    Ok(())
}

/// `motion.svg`: the simulated motion from the problem's initial state, animated.
///
/// # Errors
/// A usage error for a bad `--duration`, `--fps` or `--view`, or too many frames (before
/// any work); an invalid problem; a simulation that cannot start.
pub fn motion_svg(args: &DrawArgs) -> Result<String, Error> {
    use crate::pipeline::frame_count;
    use crate::render::draw::motion_svg;
    use crate::solution::motion_picture;
    let view = match &args.view {
        Some(text) => View::parse(text).map_err(Error::Usage)?,
        None => View::Isometric,
    };
    let problem = super::load_with_overrides(&Common {
        output: None,
        ..args.common.clone()
    })?;
    let duration = args.duration.unwrap_or(problem.simulate.duration);
    frame_count(duration, args.fps)?;
    let derivation = crate::pipeline::derive(
        &problem,
        super::method(args.common.method),
        crate::pipeline::Purpose::Handout,
    )?;
    let frames = crate::pipeline::frames(&problem, &derivation, duration, args.fps)?;
    Ok(motion_svg::export(&motion_picture(
        &derivation,
        &frames,
        view,
    )))
}
