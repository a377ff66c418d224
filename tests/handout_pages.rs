//! The length of a handout: every bundled problem of one or two bodies, by every method,
//! worked and as the student's worksheet, is within 4 pages in LaTeX, and nothing sticks
//! out of the margin by more than a few points.
//!
//! pdflatex runs once per handout (the tables' widths are fixed, so a second run changes
//! no page break), the handouts compiled in parallel, one a core. A handout that stops
//! pdflatex writes no pages, and is a fault.

use crate::support::handouts::explained;
use crate::support::{all_problems, pdflatex_present, pdflatex_source, Typeset, METHODS};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The most pages a one- or two-body handout may take.
const MOST_PAGES: usize = 4;

/// Handouts still longer than [`MOST_PAGES`], each with the most pages it may take until
/// its text is made shorter: none may grow, and none other may pass 4 pages. The worked
/// handouts measured on every problem once over 4 pages; the worksheets as first measured.
/// The wheel pendulum by Kane and by Lagrange end with step 6 and the answers, half a page,
/// on page 5; the unbalanced disk by Lagrange, eleven reactions in eleven rows, with its
/// answers.
const STILL_LONGER: &[(&str, usize)] = &[
    // Their weights' moments now written out as cross products: the answers on page 5.
    ("wheel-pendulum-motion-law", 5),
    ("unbalanced-disk-shaft-motion-law", 5),
    // Its auxiliary speeds' rates and plan column: answer 2's last lines on page 5.
    ("rolling-coin-kane", 5),
    ("wheel-pendulum-kane", 5),
    ("wheel-pendulum-lagrange", 5),
    ("unbalanced-disk-shaft-lagrange", 5),
];

/// Worked handouts near [`MOST_PAGES`], set on every run: the gyroscope by the Motion Law
/// (its statement asks for the gimbal's reaction alone; its free bodies' inertia rows a
/// line each in LaTeX) and by Kane (its four reactions through auxiliary speeds), the disc
/// on the cart and the double pendulum by Kane, whose step 5 solves its system with
/// numbers; the heavy top by Lagrange, whose first free body now fills page 1 and whose
/// answers, long derivations, end page 4. The Motion Law's handout of the struck double pendulum, whose rows' products ("Written out:") a page may
/// break between, set with no empty line above them, and whose two plots to a row are
/// lower than wide.
const LAST_BROUGHT_IN: [(&str, &str); 6] = [
    ("impact-double-pendulum", "motion-law"),
    ("gyroscope-gimbal", "motion-law"),
    ("gyroscope-gimbal", "kane"),
    ("disc-on-cart", "kane"),
    ("double-pendulum-rods", "kane"),
    ("heavy-symmetric-top", "lagrange"),
];

/// The most pages the handout `name` may take.
fn most_pages(name: &str) -> usize {
    STILL_LONGER
        .iter()
        .find(|(n, _)| *n == name)
        .map_or(MOST_PAGES, |&(_, pages)| pages)
}

/// The widest a line may stick out of the margin, in points: a display's last symbol.
const MOST_OVERFULL: f64 = 4.0;

/// The bodies a problem file declares.
fn body_count(path: &Path) -> usize {
    let text = std::fs::read_to_string(path).expect("problem is readable");
    let json: serde_json::Value = serde_json::from_str(&text).expect("problem is JSON");
    json["bodies"].as_object().map_or(0, serde_json::Map::len)
}

/// One handout to set: its problem, method and whether it is the student's.
struct Handout {
    problem: PathBuf,
    method: &'static str,
    student: bool,
}

impl Handout {
    fn name(&self) -> String {
        let stem = self.problem.file_stem().expect("stem").to_string_lossy();
        let kind = if self.student { "-student" } else { "" };
        format!("{stem}-{}{kind}", self.method)
    }
}

/// Sets the handout's LaTeX, as `explain` prints it, in `dir`; `None` when `explain`
/// cannot write it (the library's tests answer for that).
fn set(handout: &Handout, dir: &Path) -> Option<Typeset> {
    let out = explained(&handout.problem, handout.method, "latex", handout.student);
    if !out.status.success() {
        return None;
    }
    let source = String::from_utf8_lossy(&out.stdout);
    Some(pdflatex_source(dir, &handout.name(), &source))
}

#[test]
fn the_handouts_last_brought_within_four_pages_stay_there() {
    if !pdflatex_present("the handouts' pages") {
        return;
    }
    let dir = std::env::temp_dir().join(format!("mbd-pages-last-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch");
    for (name, method) in LAST_BROUGHT_IN {
        let handout = Handout {
            problem: crate::support::problem(name),
            method,
            student: false,
        };
        let m = set(&handout, &dir).expect("explain writes the handout");
        assert!(
            (1..=MOST_PAGES).contains(&m.pages()),
            "{}: {} pages",
            handout.name(),
            m.pages()
        );
        assert!(m.widest_overfull() <= MOST_OVERFULL, "{}", handout.name());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every one- and two-body handout: 344 handouts, twenty minutes and more of pdflatex on a
/// shared 2-core machine, far past a suite's minute, so a benchmark run on demand:
/// `cargo test --release --test main handout_pages -- --ignored`. `tools/bench/pages.sh`
/// prints the same pages handout by handout; BENCHMARKS.md records them.
#[test]
#[ignore = "minutes of pdflatex; run on demand"]
fn one_and_two_body_handouts_fit_four_pages_within_the_margins() {
    if !pdflatex_present("the handouts' pages") {
        return;
    }
    let dir = std::env::temp_dir().join(format!("mbd-pages-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch");
    let mut work = Vec::new();
    for problem in all_problems().into_iter().filter(|p| body_count(p) <= 2) {
        for method in METHODS {
            for student in [false, true] {
                work.push(Handout {
                    problem: problem.clone(),
                    method,
                    student,
                });
            }
        }
    }
    let queue = Mutex::new(work);
    let faults = Mutex::new(Vec::new());
    let set_at_all = Mutex::new(0usize);
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let Some(handout) = queue.lock().expect("queue").pop() else {
                    break;
                };
                let Some(m) = set(&handout, &dir) else {
                    continue;
                };
                *set_at_all.lock().expect("count") += 1;
                let name = handout.name();
                let mut found = faults.lock().expect("faults");
                if m.pages() == 0 {
                    found.push(format!("{name}: no pages: {}", m.faults()));
                } else if m.pages() > most_pages(&name) {
                    found.push(format!("{name}: {} pages", m.pages()));
                }
                if m.widest_overfull() > MOST_OVERFULL {
                    found.push(format!(
                        "{name}: a line {:.1} pt out of the margin",
                        m.widest_overfull()
                    ));
                }
            });
        }
    });
    let set_at_all = set_at_all.into_inner().expect("count");
    assert!(set_at_all > 100, "only {set_at_all} handouts were set");
    let mut faults = faults.into_inner().expect("faults");
    faults.sort();
    assert!(faults.is_empty(), "{}", faults.join("\n"));
    let _ = std::fs::remove_dir_all(&dir);
}
