//! The JSON contract: the summary serialized as one object, SI units,
//! documented in docs/json.md.

use super::Summary;

pub fn render(summary: &Summary) -> String {
    let mut s =
        serde_json::to_string(summary).expect("a summary of finite numbers always serializes");
    s.push('\n');
    s
}
