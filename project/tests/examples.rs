//! The manual's samples in examples/projects: every scenario passes, its committed timing
//! diagram in docs/diagrams is what the tool draws now (SAFELOGIC_BLESS=1 rewrites them),
//! every SVG is well-formed XML and renders with rsvg-convert (librsvg; required when
//! SAFELOGIC_REQUIRE_RSVG=1, as tools/test-all.sh sets it), every VCD is well-formed, and
//! `export-c` of each project, compiled with cc and replayed, prints the `sim --trace`
//! lines cycle by cycle.

use safelogic_project::sim::{self, Scenario};
use safelogic_project::{export_c, svg, vcd, Project};
use std::path::{Path, PathBuf};
use std::process::Command;

/// (project, scenario, diagram name) of every example.
const EXAMPLES: &[(&str, &str, &str)] = &[
    ("estop_edm", "estop_sample1", "estop_sample1"),
    ("estop_edm", "estop_sample2", "estop_sample2"),
    ("estop_edm", "estop_sample3", "estop_sample3"),
    ("estop", "estop_sample4", "estop_sample4"),
    ("mon", "mon_sample1", "mon_sample1"),
    ("mon", "mon_sample2", "mon_sample2"),
    ("mon", "mon_sample3", "mon_sample3"),
    ("opmode", "opmode_sample1", "opmode_sample1"),
    ("opmode", "opmode_sample2", "opmode_sample2"),
    ("kl6904_5_1", "kl6904_5_1", "kl6904_5_1"),
    ("kl6904_5_2", "kl6904_5_2", "kl6904_5_2"),
    ("speed_monitor", "speed_monitor", "speed_monitor"),
];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn load(project: &str, scenario: &str) -> (Project, Scenario) {
    let dir = root().join("examples/projects");
    let pf = dir.join(format!("{project}.toml"));
    let sf = dir.join(format!("{scenario}.scenario.toml"));
    let p = Project::parse(
        &pf.display().to_string(),
        &std::fs::read_to_string(&pf).unwrap(),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let s = Scenario::parse(
        &sf.display().to_string(),
        &std::fs::read_to_string(&sf).unwrap(),
        &p,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    (p, s)
}

fn run(p: &Project, s: &Scenario, trace: bool) -> (sim::Run, String) {
    let mut out = Vec::new();
    let r = sim::run(p, s, trace, &mut out).unwrap();
    (r, String::from_utf8(out).unwrap())
}

#[test]
fn every_example_scenario_passes() {
    for (project, scenario, _) in EXAMPLES {
        let (p, s) = load(project, scenario);
        let (r, text) = run(&p, &s, false);
        assert!(r.checked > 0, "{scenario} checks something");
        assert_eq!(r.failures, 0, "{scenario}:\n{text}");
        assert!(text.contains(&format!(
            "{} expectations: {} passed, 0 failed",
            r.checked, r.checked
        )));
    }
}

#[test]
fn committed_diagrams_are_fresh_well_formed_and_render() {
    let bless = std::env::var_os("SAFELOGIC_BLESS").is_some();
    let require_rsvg = std::env::var_os("SAFELOGIC_REQUIRE_RSVG").is_some();
    let has_rsvg = Command::new("rsvg-convert")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    assert!(
        has_rsvg || !require_rsvg,
        "rsvg-convert (Debian librsvg2-bin) is required (SAFELOGIC_REQUIRE_RSVG=1) but missing"
    );
    let tmp = std::env::temp_dir().join(format!("safelogic-svg-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let mut stale = Vec::new();
    for (project, scenario, name) in EXAMPLES {
        let (p, s) = load(project, scenario);
        let (r, _) = run(&p, &s, false);
        let text = svg::svg(&r, &format!("{} — {}", p.name, s.name));
        // XML: an <svg> root with one row label per recorded signal.
        let doc = roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{name}.svg: {e}"));
        assert_eq!(doc.root_element().tag_name().name(), "svg");
        for c in &r.columns {
            assert!(
                doc.descendants().any(|n| n.text() == Some(c.name.as_str())),
                "{name}: row {}",
                c.name
            );
        }
        let committed = root().join(format!("docs/diagrams/{name}.svg"));
        if bless {
            std::fs::write(&committed, &text).unwrap();
        } else if std::fs::read_to_string(&committed).ok().as_deref() != Some(text.as_str()) {
            stale.push(committed.display().to_string());
        }
        if has_rsvg {
            let png = tmp.join(format!("{name}.png"));
            let svg_file = tmp.join(format!("{name}.svg"));
            std::fs::write(&svg_file, &text).unwrap();
            let st = Command::new("rsvg-convert")
                .arg(&svg_file)
                .arg("-o")
                .arg(&png)
                .status()
                .unwrap();
            assert!(st.success(), "rsvg-convert {name}.svg");
            let bytes = std::fs::read(&png).unwrap();
            assert!(
                bytes.len() > 1000 && bytes.starts_with(b"\x89PNG"),
                "{name}.png"
            );
        }
        // VCD: header, one $var per column, time-ordered changes.
        let v = vcd::vcd(&r, &p.name);
        assert!(v.contains("$timescale 1 ms $end") && v.contains("$enddefinitions $end"));
        assert_eq!(v.matches("$var ").count(), r.columns.len());
        let times: Vec<u32> = v
            .lines()
            .filter_map(|l| l.strip_prefix('#'))
            .map(|t| t.parse().unwrap())
            .collect();
        assert!(
            times.windows(2).all(|w| w[0] < w[1]),
            "{name}.vcd times increase"
        );
    }
    std::fs::remove_dir_all(&tmp).ok();
    assert!(stale.is_empty(), "stale timing diagrams (regenerate with SAFELOGIC_BLESS=1 cargo test -p safelogic-project --test examples): {stale:?}");
}

#[test]
fn exported_c_replays_every_scenario_like_sim() {
    let lib = root().join("target/release/libsafelogic.a");
    assert!(
        lib.exists(),
        "{} is missing: run `cargo build --release` first (tools/test-all.sh does)",
        lib.display()
    );
    let tmp = std::env::temp_dir().join(format!("safelogic-c-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    for (project, scenario, name) in EXAMPLES {
        let (p, s) = load(project, scenario);
        let c = tmp.join(format!("{name}.c"));
        let exe = tmp.join(name);
        std::fs::write(&c, export_c::export(&p, Some(&s))).unwrap();
        let out = Command::new("cc")
            .args(["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-I"])
            .arg(root().join("include"))
            .arg(&c)
            .arg(&lib)
            .args(["-lpthread", "-ldl", "-lm", "-o"])
            .arg(&exe)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "cc {name}.c:\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let out = Command::new(&exe).output().unwrap();
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let c_trace = String::from_utf8(out.stdout).unwrap();
        let (_, rust_trace) = run(&p, &s, true);
        assert_eq!(
            c_trace.lines().count(),
            (s.until / p.cycle_ms + 1) as usize,
            "{name}: one line per cycle"
        );
        for (i, (a, b)) in rust_trace.lines().zip(c_trace.lines()).enumerate() {
            assert_eq!(a, b, "{name}: cycle {i} differs (Rust sim, then C)");
        }
        assert_eq!(rust_trace, c_trace, "{name}");
    }
    std::fs::remove_dir_all(&tmp).ok();
}
