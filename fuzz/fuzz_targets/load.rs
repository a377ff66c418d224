//! The problem reader on arbitrary bytes: it never panics, hangs or aborts, and when the
//! text is a JSON object every error names its JSON path.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Err(errors) = mbd_tutor::problem::load(text) else {
        return;
    };
    assert!(!errors.0.is_empty());
    let _ = errors.to_string();
    let object = serde_json::from_str::<serde_json::Value>(text).is_ok_and(|v| v.is_object());
    if object {
        assert!(
            errors.0.iter().all(|e| !e.path.is_empty()),
            "an error without a JSON path: {errors}"
        );
    }
});
