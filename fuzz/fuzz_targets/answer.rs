//! What the targets that answer in JSON check of an answer: no NaN or infinity as a number.

/// Panics unless `text` is JSON lines whose numbers are all finite (serde_json cannot write
/// NaN; a string "NaN" would be a lie in a number's place, so any "nan"/"inf" string in a
/// numeric field is caught by the callers' own checks).
pub fn assert_json(text: &str) {
    for line in text.lines() {
        let value: serde_json::Value =
            serde_json::from_str(line).unwrap_or_else(|e| panic!("not JSON ({e}): {line}"));
        assert_finite(&value, line);
    }
}

fn assert_finite(value: &serde_json::Value, line: &str) {
    match value {
        serde_json::Value::Number(n) => {
            let x = n.as_f64().unwrap_or(0.0);
            assert!(x.is_finite(), "a number that is not finite in {line}");
        }
        serde_json::Value::Array(items) => items.iter().for_each(|v| assert_finite(v, line)),
        serde_json::Value::Object(map) => map.values().for_each(|v| assert_finite(v, line)),
        _ => {}
    }
}
