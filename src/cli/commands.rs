//! Each command's arguments, as clap reads them; the commands in `cmd` take these.

use super::common::{Common, MethodArg};
use clap::ValueEnum;
use std::path::PathBuf;

// `answer`

/// The output format of `answer`.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AnswerFormat {
    /// One block per question: its text, then each value with its unit.
    #[default]
    Text,
    /// `{ "answers": [ … ] }`, every number in full precision, for a grader.
    Json,
}

/// Arguments of `mbd-tutor answer`.
#[derive(clap::Args, Debug)]
pub struct AnswerArgs {
    /// The problem file, the method, the constants set and where the output goes.
    #[command(flatten)]
    pub common: Common,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: AnswerFormat,
}

// `check`

/// Arguments of `mbd-tutor check`.
#[derive(clap::Args, Debug)]
pub struct CheckArgs {
    /// The problem file (JSON).
    pub problem: PathBuf,
    /// Override constants: NAME=VALUE,... (the checks that depend on values run again).
    #[arg(long, value_name = "NAME=VALUE,...")]
    pub set: Vec<String>,
    /// Refuse problems with more bodies than this, as `solve` does.
    #[arg(long, value_name = "N", default_value_t = crate::cli::MAX_BODIES)]
    pub max_bodies: usize,
    /// Refuse problems with more coordinates than this, as `solve` does.
    #[arg(long, value_name = "N", default_value_t = crate::cli::MAX_COORDINATES)]
    pub max_coordinates: usize,
    /// Refuse a check whose symbolic work passes this many million expression terms.
    #[arg(long, value_name = "MILLIONS", default_value_t = crate::symbolic::budget::DEFAULT_LIMIT / 1_000_000)]
    pub max_work: u64,
}

// `draw`, `solve` and `linearize`

/// The state a command works at: `--state` and `--time`.
#[derive(clap::Args, Clone, Debug)]
pub struct GivenState {
    /// Coordinates and rates: q1=0.3,q1'=1.2; unset ones take the problem's initial values.
    #[arg(long, value_name = "NAME=VALUE,...")]
    pub state: Vec<String>,
    /// The time t.
    #[arg(long, default_value_t = 0.0)]
    pub time: f64,
}

impl GivenState {
    /// Refuses a time that is not finite (a usage error, exit status 2).
    ///
    /// # Errors
    /// `--time` is not finite.
    pub fn check_time(&self) -> Result<(), crate::Error> {
        if !self.time.is_finite() {
            return Err(crate::Error::Usage("--time must be finite".into()));
        }
        Ok(())
    }
}

// `draw`

/// Arguments of `mbd-tutor draw`.
#[derive(clap::Args, Debug)]
pub struct DrawArgs {
    /// The problem; `-o` names the directory the pictures go to (created if missing).
    #[command(flatten)]
    pub common: Common,
    /// The state and the time worked at.
    #[command(flatten)]
    pub given: GivenState,
    /// How a spatial system is seen: iso (default), front, side, top, or a direction
    /// X,Y,Z to look along. Planar systems are drawn in their plane.
    #[arg(long, value_name = "VIEW")]
    pub view: Option<String>,
    /// Also write each picture as a TikZ picture, NAME.tex.
    #[arg(long)]
    pub tikz: bool,
    /// Also write motion.svg: the configuration over the simulated motion, animated.
    #[arg(long)]
    pub animate: bool,
    /// With --animate: seconds of motion; default the problem's `simulate.duration` (5 s).
    #[arg(long, requires = "animate")]
    pub duration: Option<f64>,
    /// With --animate: frames per second.
    #[arg(long, requires = "animate", default_value_t = crate::numeric::DEFAULT_FPS)]
    pub fps: f64,
}

// `explain`

/// The output format of `explain`.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FormatArg {
    /// Markdown with `$…$` math (GitHub, pandoc).
    #[default]
    Markdown,
    /// A standalone LaTeX article for pdflatex.
    Latex,
    /// One self-contained HTML page with MathML.
    Html,
}

/// Arguments of `mbd-tutor explain`.
// Each bool is a command-line switch of its own, as clap reads it.
#[allow(clippy::struct_excessive_bools)]
#[derive(clap::Args, Debug)]
pub struct ExplainArgs {
    /// A problem file, or a directory of them (then `-o` names the output directory).
    #[command(flatten)]
    pub common: Common,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: FormatArg,
    /// A directory of templates (`solution.md.tera`, `solution.tex.tera`,
    /// `solution.html.tera`) that replace the built-in ones, to restyle a handout.
    #[arg(long, value_name = "DIR")]
    pub templates: Option<PathBuf>,
    /// Write the student's handout: the statement and the set-up, with blank tables.
    #[arg(long, conflicts_with = "both")]
    pub student: bool,
    /// Write both versions from one run: the worked solution to `-o NAME.EXT` and the
    /// student's handout beside it as `NAME-student.EXT` (needs `-o`).
    #[arg(long)]
    pub both: bool,
    /// Add a section on small motions about the initial state, or about the state given
    /// (`--linearize=q1=0,q1'=0`): M, C, K, the state matrix, eigenvalues and modes. The
    /// state follows an `=`, so that `--linearize problem.json` keeps the problem's path.
    #[arg(
        long,
        value_name = "STATE",
        num_args = 0..=1,
        require_equals = true,
        default_missing_value = ""
    )]
    pub linearize: Option<String>,
    /// List every candidate equation the Motion Law's planner did not use, with its reason,
    /// not only the few that show why the plan is what it is.
    #[arg(long)]
    pub verbose: bool,
    /// The worked solution of the problem at rest: the equilibrium, its reactions, holding
    /// forces, friction ratios and stability, with no inertia forces.
    #[arg(long, conflicts_with = "linearize")]
    pub statics: bool,
}

// `grade`

/// The output format of `grade`.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GradeFormat {
    /// The total, then one line per item with its verdict and diagnosis.
    #[default]
    Text,
    /// `{ "student", "items": [ … ], "score", "out_of" }`.
    Json,
}

/// Arguments of `mbd-tutor grade`.
#[derive(clap::Args, Debug)]
pub struct GradeArgs {
    /// The problem file (JSON): the student's variant, for homework from `variants`.
    #[arg(required_unless_present = "batch")]
    pub problem: Option<PathBuf>,
    /// The student's submission (JSON).
    #[arg(required_unless_present = "batch")]
    pub submission: Option<PathBuf>,
    /// Grade every submission (*.json) in this directory, each against the variant it
    /// names, into one CSV gradebook.
    #[arg(long, value_name = "DIR", requires = "key", conflicts_with_all = ["problem", "submission"])]
    pub batch: Option<PathBuf>,
    /// With --batch: the key.csv written by `variants`; the variant files are beside it.
    #[arg(long, value_name = "KEY.csv")]
    pub key: Option<PathBuf>,
    /// Output format (a single submission).
    #[arg(long, value_enum, default_value_t)]
    pub format: GradeFormat,
    /// Which method's worked solution the equations are matched against.
    #[arg(long, value_enum, default_value_t)]
    pub method: MethodArg,
    /// Write there instead of standard output.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

// `linearize`

/// Arguments of `mbd-tutor linearize`.
#[derive(clap::Args, Debug)]
pub struct LinearizeArgs {
    /// The problem, the state to linearize about and the output format.
    #[command(flatten)]
    pub at: AtState,
    /// Repeat over COUNT evenly spaced values of a constant, both ends included.
    #[arg(long, value_name = "NAME=FROM:TO:COUNT")]
    pub sweep: Option<String>,
    /// With --sweep, also plot the eigenvalues against the constant into this SVG file
    /// (as does `-o FILE.svg`, the report then going to standard output).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
}

// `schema`

/// Arguments of `mbd-tutor schema`.
#[derive(clap::Args, Debug)]
pub struct SchemaArgs {
    /// Write there instead of standard output.
    #[arg(short, long)]
    pub output: Option<std::path::PathBuf>,
}

// `serve`

/// Arguments of `mbd-tutor serve`.
#[derive(clap::Args, Debug)]
pub struct ServeArgs {
    /// The problem file (JSON).
    pub problem: PathBuf,
    /// The port to listen on; 0 picks a free one.
    #[arg(long, default_value_t = 7070)]
    pub port: u16,
    /// The address to listen on.
    #[arg(long, default_value = "127.0.0.1")]
    pub host: String,
    /// Which method forms the equations.
    #[arg(long, value_enum, default_value_t)]
    pub method: MethodArg,
}

// `simulate`

/// How `simulate` writes its table.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SimulateFormat {
    /// A header row, then one row per output step.
    #[default]
    Csv,
    /// `{ "columns": [...], "rows": [[...], ...] }`.
    Json,
}

/// Arguments of `mbd-tutor simulate`.
#[derive(clap::Args, Debug)]
pub struct SimulateArgs {
    /// The problem file, the method, the constants set and where the output goes.
    #[command(flatten)]
    pub common: Common,
    /// Seconds to simulate; default the problem's `simulate.duration` (5 s).
    #[arg(long)]
    pub duration: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: SimulateFormat,
    /// The most output rows before the run is refused (a guard against gigabytes of output).
    #[arg(long, default_value_t = crate::numeric::MAX_ROWS)]
    pub max_rows: usize,
    /// Skip the confirmation checks (energy, agreement of the four methods, period of small
    /// oscillations) that are otherwise reported on standard error.
    #[arg(long)]
    pub no_checks: bool,
}

// `solve`

/// How `solve` prints its result.
#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SolveFormat {
    /// A readable table.
    #[default]
    Text,
    /// The JSON object of the command-line contract.
    Json,
}

/// What `solve` and `linearize` share: the problem, one state and the output format.
#[derive(clap::Args, Debug)]
pub struct AtState {
    /// The problem file, the method, the constants set and where the output goes.
    #[command(flatten)]
    pub common: Common,
    /// The state and the time worked at.
    #[command(flatten)]
    pub given: GivenState,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: SolveFormat,
}

/// Arguments of `mbd-tutor solve`.
#[derive(clap::Args, Debug)]
pub struct SolveArgs {
    /// The problem, the state and the output format.
    #[command(flatten)]
    pub at: AtState,
}

// `statics`

/// Arguments of `mbd-tutor statics`.
#[derive(clap::Args, Debug)]
pub struct StaticsArgs {
    /// The problem file, the method, the constants set and where the output goes.
    #[command(flatten)]
    pub common: Common,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: SolveFormat,
    /// A starting guess for Newton's method, q1=V,q2=V (the others initial); repeat for
    /// several equilibria. Without it: the initial configuration.
    #[arg(long, value_name = "NAME=VALUE,...")]
    pub near: Vec<String>,
}

// `impact`

/// Arguments of `mbd-tutor impact`.
#[derive(clap::Args, Debug)]
pub struct ImpactArgs {
    /// The problem file, the method, the constants set and where the output goes.
    #[command(flatten)]
    pub common: Common,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: SolveFormat,
}

// `variants`

/// Arguments of `mbd-tutor variants`.
#[derive(clap::Args, Debug)]
pub struct VariantsArgs {
    /// The problem file (JSON), with at least one constant that declares `vary`.
    pub problem: PathBuf,
    /// How many variants to write (1 to 500).
    #[arg(long, value_name = "N")]
    pub count: usize,
    /// The seed of the draws: the same seed writes the same files, byte for byte.
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,
    /// The directory to write into (made if missing).
    #[arg(short, long, value_name = "DIR")]
    pub output: PathBuf,
    /// The format of each worked solution and student handout.
    #[arg(long, value_enum, default_value_t = FormatArg::Latex)]
    pub format: FormatArg,
    /// Which method forms the equations.
    #[arg(long, value_enum, default_value_t)]
    pub method: MethodArg,
}
