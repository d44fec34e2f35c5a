//! The committed `modelDescription/modelDescription.xml` equals the one build.rs generates from the
//! variable table (interface changes show up in review). `UPDATE_SNAPSHOT=1 cargo test` rewrites it.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use flexible_slider_crank::fmi::{GUID, MODEL_DESCRIPTION};
use flexible_slider_crank::variables::VARIABLES;

#[test]
fn committed_snapshot_is_current() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("modelDescription/modelDescription.xml");
    if std::env::var_os("UPDATE_SNAPSHOT").is_some() {
        std::fs::write(&path, MODEL_DESCRIPTION).unwrap();
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == MODEL_DESCRIPTION,
        "modelDescription/modelDescription.xml is stale: run UPDATE_SNAPSHOT=1 cargo test --test model_description"
    );
}

#[test]
fn guid_is_the_one_in_the_xml() {
    assert!(GUID.starts_with('{') && GUID.ends_with('}') && GUID.len() == 38);
    assert!(MODEL_DESCRIPTION.contains(&format!("guid=\"{GUID}\"")));
    assert_eq!(
        MODEL_DESCRIPTION.matches("<ScalarVariable ").count(),
        VARIABLES.len()
    );
}

/// Every variable name the source quotes (in messages and docs) exists in the variable table.
#[test]
fn quoted_variable_names_exist() {
    let names: Vec<&str> = VARIABLES.iter().map(|v| v.name).collect();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = vec![root];
    let mut unknown = Vec::new();
    while let Some(path) = files.pop() {
        if path.is_dir() {
            files.extend(std::fs::read_dir(&path).unwrap().map(|e| e.unwrap().path()));
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        for quoted in text.split('"').skip(1).step_by(2) {
            let prefixes = ["rod.", "crank.", "joint.", "solver.", "drive.", "slider."];
            for w in quoted.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.')) {
                let w = w.trim_end_matches('.');
                let named = prefixes
                    .iter()
                    .any(|p| w.starts_with(p) && w.len() > p.len());
                if named && !names.contains(&w) {
                    unknown.push(format!("{}: {w}", path.display()));
                }
            }
        }
    }
    assert!(unknown.is_empty(), "{unknown:#?}");
}
