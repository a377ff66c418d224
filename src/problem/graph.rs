//! The joints must form a tree rooted at `N`: every body has exactly one joint to its
//! parent, and following parents always ends at `N`.

use super::json::{index_path, key_path, Diagnostics};
use super::model::{BodyId, JointKind};
use super::names::Names;

/// What the tree check needs to know of one joint; `None` where the joint had an error.
#[derive(Clone, Copy, Debug, Default)]
pub struct Link {
    /// The parent body.
    pub parent: Option<BodyId>,
    /// The child body.
    pub child: Option<BodyId>,
    /// The joint type.
    pub kind: Option<JointKind>,
}

/// Checks that `links` (joint `i` at `joints[i]`) form a tree rooted at `N` over every
/// declared body; records an error for each way they do not.
pub fn check_tree(links: &[Link], names: &Names, diag: &mut Diagnostics) {
    let bodies = names.bodies.len();
    // parent_joint[b] is the first joint whose child is body b.
    let mut parent_joint: Vec<Option<usize>> = vec![None; bodies + 1];
    for (i, link) in links.iter().enumerate() {
        let Some(child) = link.child else { continue };
        let path = key_path(&index_path("joints", i), "child");
        if child == BodyId::GROUND {
            diag.hint(
                &path,
                "`N` cannot be a child: it is the ground",
                "`N` may only be a parent; swap `parent` and `child`",
            );
            continue;
        }
        if link.parent == Some(child) {
            diag.error(
                &path,
                format!("the joint connects `{}` to itself", names.body_name(child)),
            );
            continue;
        }
        match parent_joint[child.0] {
            Some(first) => diag.hint(
                &path,
                format!(
                    "`{}` already has a parent through joint `{}` (joints[{first}]); a body has exactly one",
                    names.body_name(child),
                    names.joints.get(first).map_or("?", String::as_str)
                ),
                "the joints must form a tree; closed loops are not supported",
            ),
            None => parent_joint[child.0] = Some(i),
        }
    }

    // Follow parents from every body; 0 = not seen, 1 = on the current walk, 2 = done.
    let mut state = vec![0u8; bodies + 1];
    state[0] = 2;
    for start in 1..=bodies {
        if names.bodies[start - 1] == "N" {
            // Declaring `N` is already an error of its own.
            continue;
        }
        let mut walk = Vec::new();
        let mut body = start;
        let mut loop_at = None;
        while state[body] == 0 {
            state[body] = 1;
            walk.push(body);
            let Some(joint) = parent_joint[body] else {
                diag.hint(
                    &key_path("bodies", names.body_name(BodyId(body))),
                    format!(
                        "`{}` is not connected: no joint has it as its child",
                        names.body_name(BodyId(body))
                    ),
                    format!(
                        "add a joint with \"child\": \"{}\" and a parent on the way to N",
                        names.body_name(BodyId(body))
                    ),
                );
                break;
            };
            let Some(parent) = links[joint].parent else {
                break;
            };
            body = parent.0;
            if state[body] == 1 {
                loop_at = Some(body);
            }
        }
        if let Some(body) = loop_at {
            // `body` was reached twice on this walk: the walk from it on is a loop.
            let from = walk.iter().position(|b| *b == body).unwrap_or(0);
            let cycle: Vec<usize> = walk[from..].to_vec();
            let joints: Vec<usize> = cycle.iter().filter_map(|b| parent_joint[*b]).collect();
            let first = joints.iter().copied().min().unwrap_or(0);
            let mut tour: Vec<&str> = cycle
                .iter()
                .rev()
                .map(|b| names.body_name(BodyId(*b)))
                .collect();
            if let Some(first_body) = tour.first().copied() {
                tour.push(first_body);
            }
            let joint_names: Vec<&str> = joints
                .iter()
                .map(|j| names.joints.get(*j).map_or("?", String::as_str))
                .collect();
            diag.hint(
                &index_path("joints", first),
                format!(
                    "the joints {} form a closed loop ({}) that never reaches N",
                    super::json::list(&joint_names),
                    tour.join(" -> ")
                ),
                "the joints must form a tree rooted at N; one of them has parent and child the wrong way round or names the wrong body",
            );
        }
        for b in walk {
            state[b] = 2;
        }
    }
}

/// Which frames always have the same orientation: those joined by chains of prismatic
/// and weld joints, which never turn the child relative to the parent.
#[derive(Clone, Debug)]
pub struct Orientation {
    root: Vec<usize>,
}

impl Orientation {
    /// Groups `N` and the bodies by the non-turning joints among `links`.
    pub fn new(bodies: usize, links: &[Link]) -> Orientation {
        let mut root: Vec<usize> = (0..=bodies).collect();
        fn find(root: &mut [usize], mut i: usize) -> usize {
            while root[i] != i {
                root[i] = root[root[i]];
                i = root[i];
            }
            i
        }
        for link in links {
            if let (Some(p), Some(c), Some(JointKind::Prismatic | JointKind::Weld)) =
                (link.parent, link.child, link.kind)
            {
                if p.0 <= bodies && c.0 <= bodies {
                    let (a, b) = (find(&mut root, p.0), find(&mut root, c.0));
                    root[a.max(b)] = a.min(b);
                }
            }
        }
        let roots = (0..=bodies).map(|i| find(&mut root, i)).collect();
        Orientation { root: roots }
    }

    /// Whether frames `a` and `b` are always aligned.
    pub fn aligned(&self, a: BodyId, b: BodyId) -> bool {
        a == b || matches!((self.root.get(a.0), self.root.get(b.0)), (Some(x), Some(y)) if x == y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(bodies: &[&str]) -> Names {
        let mut names = Names::default();
        names.bodies = bodies.iter().map(|b| b.to_string()).collect();
        names.joints = (0..bodies.len() + 1).map(|i| format!("J{i}")).collect();
        names
    }

    fn link(parent: usize, child: usize) -> Link {
        Link {
            parent: Some(BodyId(parent)),
            child: Some(BodyId(child)),
            kind: Some(JointKind::Revolute),
        }
    }

    fn errors(bodies: &[&str], links: &[Link]) -> Vec<String> {
        let mut diag = Diagnostics::default();
        check_tree(links, &names(bodies), &mut diag);
        diag.errors
            .iter()
            .map(|e| format!("{}: {}", e.path, e.message))
            .collect()
    }

    #[test]
    fn a_chain_is_a_tree() {
        assert!(errors(&["A", "B"], &[link(0, 1), link(1, 2)]).is_empty());
        assert!(errors(&["A", "B"], &[link(1, 2), link(0, 1)]).is_empty());
        assert!(errors(&["A", "B", "C"], &[link(0, 1), link(1, 2), link(1, 3)]).is_empty());
    }

    #[test]
    fn what_is_not_a_tree() {
        let e = errors(&["A", "B"], &[link(0, 1), link(2, 1)]);
        assert!(
            e[0].starts_with("joints[1].child") && e[0].contains("already has a parent"),
            "{e:?}"
        );
        assert!(
            e[1].starts_with("bodies.B") && e[1].contains("not connected"),
            "{e:?}"
        );
        let e = errors(&["A", "B"], &[link(2, 1), link(1, 2)]);
        assert_eq!(e.len(), 1, "{e:?}");
        assert!(
            e[0].starts_with("joints[0]:") && e[0].contains("closed loop"),
            "{e:?}"
        );
        let e = errors(&["A"], &[link(0, 1), link(1, 0)]);
        assert!(
            e[0].starts_with("joints[1].child") && e[0].contains("cannot be a child"),
            "{e:?}"
        );
        let e = errors(&["A"], &[link(1, 1)]);
        assert!(e[0].contains("to itself"), "{e:?}");
    }

    #[test]
    fn sliding_keeps_orientation() {
        let mut slide = link(0, 1);
        slide.kind = Some(JointKind::Prismatic);
        let links = [slide, link(1, 2)];
        let orientation = Orientation::new(2, &links);
        assert!(orientation.aligned(BodyId(0), BodyId(1)));
        assert!(!orientation.aligned(BodyId(1), BodyId(2)));
    }
}
