//! File names made from a problem's names (a picture per free body, `fbd-NAME.svg`): a
//! long name is shortened so that the file can be created (a name has at most 255 bytes),
//! and stays distinct from every other by a hash of the whole name.

/// The longest stem kept as it is, in bytes: with an extension and a temporary file's
/// dot and suffix, well under 255.
const LONGEST: usize = 100;

/// `name` itself when it is short, else its first 80 bytes (on a character's boundary),
/// `-` and 16 hexadecimal digits of a hash of the whole name.
pub fn short_stem(name: &str) -> String {
    if name.len() <= LONGEST {
        return name.to_string();
    }
    let mut cut = 80;
    while !name.is_char_boundary(cut) {
        cut -= 1;
    }
    format!("{}-{:016x}", &name[..cut], fnv1a(name.as_bytes()))
}

/// FNV-1a, 64 bits: the same on every machine and run.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |hash, &b| {
        (hash ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

#[cfg(test)]
mod tests {
    use super::short_stem;

    #[test]
    fn short_names_stay_and_long_ones_are_cut_and_kept_apart() {
        assert_eq!(short_stem("fbd-B"), "fbd-B");
        let a = format!("fbd-{}", "a".repeat(250));
        let b = format!("fbd-{}b", "a".repeat(249));
        assert!(short_stem(&a).len() <= 100);
        assert_ne!(short_stem(&a), short_stem(&b));
        assert_eq!(short_stem(&a), short_stem(&a));
        let greek = format!("fbd-{}", "θ".repeat(200));
        assert!(short_stem(&greek).len() <= 100);
    }
}
