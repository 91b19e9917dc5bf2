//! The committed header must be exactly what build.rs generates from the current sources.

#[test]
fn committed_header_matches_a_fresh_generation() {
    let fresh = include_str!(concat!(env!("OUT_DIR"), "/safelogic.h"));
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/include/safelogic.h");
    let committed = std::fs::read_to_string(path).expect("include/safelogic.h is committed");
    assert!(
        fresh == committed,
        "include/safelogic.h differs from a fresh generation: run `SAFELOGIC_WRITE_HEADER=1 cargo build` and commit it"
    );
}
