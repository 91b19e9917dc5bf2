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

/// The header's `#define SL_… value` lines (name → value text).
fn defines(header: &str) -> Vec<(String, String)> {
    header
        .lines()
        .filter_map(|l| l.strip_prefix("#define "))
        .filter_map(|l| l.split_once(' '))
        .filter(|(n, _)| n.starts_with("SL_"))
        .map(|(n, v)| (n.to_string(), v.trim().to_string()))
        .collect()
}

/// Every `pub const SL_…: u32` of the library's sources (the C `uint32_t` constants), the
/// declarations build.rs generates from the `*.abi.toml` data files (`OUT_DIR/abi`) included.
fn u32_constants() -> Vec<String> {
    fn walk(dir: &std::path::Path, out: &mut Vec<String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                for l in std::fs::read_to_string(&p).unwrap().lines() {
                    if let Some(rest) = l.trim().strip_prefix("pub const SL_") {
                        if let Some((name, _)) = rest.split_once(": u32 =") {
                            out.push(format!("SL_{name}"));
                        }
                    }
                }
            }
        }
    }
    let mut out = Vec::new();
    walk(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        &mut out,
    );
    walk(
        std::path::Path::new(concat!(env!("OUT_DIR"), "/abi")),
        &mut out,
    );
    out
}

/// The manual lists Text IDs in hex (0x4090), so does the header; an unsigned 32-bit
/// constant carries `U`, so its C type does not depend on the platform (a literal above
/// INT_MAX would be `long` or `long long`, and `1 << 31` would overflow `int`).
#[test]
fn text_ids_are_hex_and_unsigned_constants_carry_u() {
    let h = include_str!(concat!(env!("OUT_DIR"), "/safelogic.h"));
    let d = defines(h);
    let texts: Vec<_> = d
        .iter()
        .filter(|(n, _)| n.starts_with("SL_TEXT_"))
        .collect();
    assert!(texts.len() >= 40, "{} Text IDs", texts.len());
    for (n, v) in &texts {
        let hex = v
            .strip_prefix("0x")
            .unwrap_or_else(|| panic!("{n} = {v}: not hex"));
        assert!(
            hex.len() == 4
                && hex
                    .chars()
                    .all(|c| c.is_ascii_hexdigit() && !c.is_ascii_lowercase()),
            "{n} = {v}"
        );
    }
    assert!(d.contains(&("SL_TEXT_LIMIT_MIN_ABOVE_MAX".into(), "0x4090".into())));
    let u32s = u32_constants();
    assert!(u32s.len() >= 30, "{} u32 constants", u32s.len());
    for name in &u32s {
        let (_, v) = d
            .iter()
            .find(|(n, _)| n == name)
            .unwrap_or_else(|| panic!("{name} is not in the header"));
        let ok = v
            .strip_suffix('U')
            .is_some_and(|n| n.parse::<u32>().is_ok())
            || (v.starts_with("(1U << ") && v.ends_with(')'));
        assert!(ok, "{name} = {v}: an unsigned 32-bit constant needs U");
    }
    assert!(d.contains(&("SL_SBT_TIME_MAX".into(), "4294967000U".into())));
    // No literal above INT_MAX without U, whatever its Rust type.
    for (n, v) in &d {
        if let Ok(x) = v.parse::<u64>() {
            assert!(x <= i32::MAX as u64, "{n} = {v}");
        }
    }
}
