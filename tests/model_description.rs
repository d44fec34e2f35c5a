//! The committed `modelDescription/modelDescription.xml` equals the one build.rs generates from the
//! variable table (interface changes show up in review). `UPDATE_SNAPSHOT=1 cargo test` rewrites it.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use flexible_slider_crank::fmi::{GUID, MODEL_DESCRIPTION};
use flexible_slider_crank::variables::{FMI3, VARIABLES};

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

/// Every variable name the source quotes (in messages and docs, between double quotes) and the
/// user documentation names (between backticks) exists in the variable table: any word under one
/// of the table's components (`rod.`, `crankPin.`, `energy.`, …, each first segment of a dotted
/// name) must be a name of the table.
#[test]
fn quoted_variable_names_exist() {
    let fmi3 = FMI3.structural_parameters.iter().map(|p| p.name);
    let names: Vec<&str> = VARIABLES
        .iter()
        .map(|v| v.name)
        .chain(fmi3)
        .chain(FMI3.arrays.iter().map(|a| a.name))
        .collect();
    let mut components: Vec<String> = names
        .iter()
        .filter_map(|n| n.split_once('.').map(|(c, _)| format!("{c}.")))
        .collect();
    components.sort();
    components.dedup();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![root.join("src"), root.join("docs"), root.join("README.md")];
    let mut unknown = Vec::new();
    while let Some(path) = files.pop() {
        if path.is_dir() {
            files.extend(std::fs::read_dir(&path).unwrap().map(|e| e.unwrap().path()));
            continue;
        }
        let quote = match path.extension().and_then(|e| e.to_str()) {
            Some("rs") => '"',
            Some("md") => '`',
            _ => continue,
        };
        let text = std::fs::read_to_string(&path).unwrap();
        for quoted in text.split(quote).skip(1).step_by(2) {
            for w in quoted.split(|c: char| !(c.is_ascii_alphanumeric() || "._/".contains(c))) {
                // A path names a file, not a variable; "x.aX/Y" names x.aX and x.aY.
                let w = w
                    .split('/')
                    .next()
                    .unwrap_or_default()
                    .trim_end_matches('.');
                let named = components
                    .iter()
                    .any(|p| w.starts_with(p.as_str()) && w.len() > p.len());
                if named && !names.contains(&w) {
                    unknown.push(format!("{}: {w}", path.display()));
                }
            }
        }
    }
    assert!(unknown.is_empty(), "{unknown:#?}");
}
