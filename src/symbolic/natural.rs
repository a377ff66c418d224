//! The order names sort in everywhere: as a reader counts, `q2` before `q10`.

use std::cmp::Ordering;

/// Compares names as a reader counts: runs of digits by their value, so `q2 < q10`, and
/// everything else character by character.
pub fn natural_cmp(a: &str, b: &str) -> Ordering {
    // A comparator of every canonical sort: no allocation, and equal names at once.
    if a == b {
        return Ordering::Equal;
    }
    let (mut a, mut b) = (a.as_bytes(), b.as_bytes());
    loop {
        match (a.first(), b.first()) {
            (None, None) => return Ordering::Equal,
            (None, Some(_)) => return Ordering::Less,
            (Some(_), None) => return Ordering::Greater,
            (Some(x), Some(y)) if x.is_ascii_digit() && y.is_ascii_digit() => {
                let digits = |s: &[u8]| s.iter().take_while(|c| c.is_ascii_digit()).count();
                let (da, db) = (digits(a), digits(b));
                // Without leading zeros, a longer run is a larger number.
                let (sa, sb) = (without_zeros(&a[..da]), without_zeros(&b[..db]));
                let order = sa.len().cmp(&sb.len()).then_with(|| sa.cmp(sb));
                if order != Ordering::Equal {
                    return order;
                }
                (a, b) = (&a[da..], &b[db..]);
            }
            (Some(x), Some(y)) => {
                if x != y {
                    return x.cmp(y);
                }
                (a, b) = (&a[1..], &b[1..]);
            }
        }
    }
}

fn without_zeros(digits: &[u8]) -> &[u8] {
    let zeros = digits.iter().take_while(|c| **c == b'0').count();
    &digits[zeros..]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_sort_as_a_reader_counts() {
        let mut names = vec![
            "q10",
            "q2",
            "q1",
            "line2.l",
            "line10.l",
            "line1.u.x",
            "line1.l",
        ];
        names.sort_by(|a, b| natural_cmp(a, b));
        assert_eq!(
            names,
            [
                "line1.l",
                "line1.u.x",
                "line2.l",
                "line10.l",
                "q1",
                "q2",
                "q10"
            ]
        );
    }
}
