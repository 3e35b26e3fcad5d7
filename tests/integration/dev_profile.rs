//! The dev profile names the dependencies it optimises one by one (two with their version): a
//! dependency bump that renames, drops or replaces one would leave it unoptimised in silence and
//! the suite slower. Every package the profile names must be in Cargo.lock, at the version named.

use std::collections::HashSet;

/// Every (name, version) in Cargo.lock.
fn locked_packages(lock: &str) -> HashSet<(String, String)> {
    let quoted = |line: &str, key: &str| {
        line.strip_prefix(key)
            .map(|rest| rest.trim().trim_matches('"').to_owned())
    };
    let mut packages = HashSet::new();
    let mut name = None;
    for line in lock.lines() {
        if let Some(n) = quoted(line, "name = ") {
            name = Some(n);
        } else if let (Some(v), Some(n)) = (quoted(line, "version = "), name.take()) {
            packages.insert((n, v));
        }
    }
    packages
}

#[test]
fn every_package_the_dev_profile_names_is_in_the_lock_file() {
    let root = env!("CARGO_MANIFEST_DIR");
    let manifest = std::fs::read_to_string(format!("{root}/Cargo.toml")).unwrap();
    let lock = std::fs::read_to_string(format!("{root}/Cargo.lock")).unwrap();
    let locked = locked_packages(&lock);
    assert!(locked.len() > 100, "read {} packages", locked.len());
    let named: Vec<&str> = manifest
        .lines()
        .filter_map(|line| line.strip_prefix("[profile.dev.package."))
        .map(|rest| rest.trim_end_matches(']').trim_matches('"'))
        .filter(|spec| *spec != "*")
        .collect();
    assert!(named.len() > 10, "the profile names {named:?}");
    let missing: Vec<&&str> = named
        .iter()
        .filter(|spec| {
            let (name, version) = spec.split_once(':').unwrap_or((spec, ""));
            !locked
                .iter()
                .any(|(n, v)| n == name && (version.is_empty() || v == version))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "the dev profile optimises packages Cargo.lock does not hold (renamed, dropped or \
         bumped): {missing:?}"
    );
}
