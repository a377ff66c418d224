//! Snapshots of the generated tables, one named snapshot per stage, problem and method:
//! the planner's table (step 3) and the equations (step 5). A snapshot only shows that
//! nothing changed; the numbers are checked against references in `library` and `methods`.

use mbd_tutor::equations::Method;
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::solution::equation_view;
use mbd_tutor::solution::plan_view as plan;

fn plan_markdown(p: &mbd_tutor::render::context::Plan) -> String {
    let mut out =
        String::from("| Free body | Equation | Direction | Unknowns |\n|---|---|---|---|\n");
    for row in &p.rows {
        out.push_str(&format!(
            "| ${}$ | ${}$ | ${}$ | ${}$ |\n",
            row.free_body_tex, row.equation_tex, row.direction_tex, row.unknowns_tex
        ));
    }
    out.push_str(&format!(
        "\n{} equations, {} unknowns.\n",
        p.equations_count, p.unknowns_count
    ));
    if !p.rejected.is_empty() {
        out.push_str(&format!(
            "\nRejected ({} of {} shown):\n",
            p.rejected.len(),
            p.rejected_total
        ));
        for r in &p.rejected {
            let tex = if r.reason_tex.is_empty() {
                String::new()
            } else {
                format!(" (${}$)", r.reason_tex)
            };
            out.push_str(&format!(
                "- ${}$, ${}$ along ${}$: {}{tex}{}\n",
                r.free_body_tex, r.equation_tex, r.direction_tex, r.reason, r.reason_after
            ));
        }
    }
    out
}

#[test]
fn plan_tables_and_equations_of_every_problem() {
    insta::glob!("../problems", "*.json", |path| {
        let stem = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("problem")
            .to_string();
        let problem = mbd_tutor::problem::load_file(path).unwrap_or_else(|e| panic!("{stem}: {e}"));
        for method in Method::ALL {
            // The handout's form: these are the tables a worked solution prints.
            let derivation = derive(&problem, method, Purpose::Handout)
                .unwrap_or_else(|e| panic!("{stem}: {e}"));
            insta::assert_snapshot!(
                format!("plan-{stem}-{}", method.name()),
                plan_markdown(&plan(&derivation))
            );
            let equations: Vec<String> = derivation
                .rows
                .iter()
                .map(|row| {
                    let view = equation_view(&derivation, row);
                    format!(
                        "${}$ {}\n$$ {} $$\n",
                        view.label_tex, view.label, view.simplified_tex
                    )
                })
                .collect();
            insta::assert_snapshot!(
                format!("equations-{stem}-{}", method.name()),
                equations.join("\n")
            );
        }
    });
}
