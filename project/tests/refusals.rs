//! Every refusal of the tool says where and why: the limits `sim` and `export-c` need are
//! checked by `check` (file:line:col, the limit stated), a refused parameter is reported at
//! its own line with the range its block allows, link hints name the right direction,
//! scenario values are checked against their signal's type with the project file's words,
//! reads and writes say which failed, and a failed run leaves no file behind.

use safelogic_project::sim::Scenario;
use safelogic_project::Project;
use std::path::PathBuf;
use std::process::Command;

const TYPED: &str = r#"[project]
name = "typed"

[[group]]
name = "g"

[[group.member]]
name = "add"
type = "ADD_INT"
active = ["nAnalogIn1", "nAnalogIn2"]

[[group.member]]
name = "door"
type = "MON"
active = ["bMonIn1"]

[inputs]
V1 = "add.nAnalogIn1"
S1 = "door.bMonIn1"

[outputs]
Speed = "add.nAnalogOut"
Door = "door.bMonOut"
"#;

fn project_error(text: &str) -> String {
    let e = Project::parse("p.toml", text).expect_err("an error");
    format!("{}:{}: {}", e.line, e.col, e.msg)
}

fn scenario_error(step: &str) -> String {
    let p = Project::parse("p.toml", TYPED).unwrap();
    let text = format!("[scenario]\nname = \"s\"\n\n[[step]]\nat = \"0 ms\"\n{step}\n");
    let e = Scenario::parse("s.toml", &text, &p).expect_err("an error");
    format!("{}:{}: {}", e.line, e.col, e.msg)
}

#[test]
fn check_enforces_the_member_limit_with_its_position() {
    let mut text = String::from("[project]\nname = \"big\"\n\n[[group]]\nname = \"g\"\n");
    for i in 0..65_536 {
        text +=
            &format!("[[group.member]]\nname = \"m{i}\"\ntype = \"MON\"\nactive = [\"bMonIn1\"]\n");
    }
    let e = project_error(&text);
    // The 65,536th member starts on line 6 + 4 · 65,535.
    assert_eq!(
        e,
        format!(
            "{}:1: group `g`: member `m65535` is one too many: at most 65535 members per group (the C API counts them in a UINT)",
            6 + 4 * 65_535
        )
    );
    // One fewer is fine for `check`.
    let cut = text.rfind("[[group.member]]").unwrap();
    assert!(Project::parse("p.toml", &text[..cut]).is_ok());
}

#[test]
fn a_refused_parameter_is_reported_at_its_line_with_the_allowed_range() {
    let text = "[project]\nname = \"t\"\n\n[[group]]\nname = \"g\"\n\n[[group.member]]\nname = \"th\"\ntype = \"TWOHAND\"\nactive = [\"bTwoHand1\", \"bTwoHand3\"]\ntDiscTimePairs = \"3 s\"\n";
    assert_eq!(
        project_error(text),
        "11:18: member `th`: TWOHAND: tDiscTimePairs (3000 ms) must be <= 2500 ms [reason 0xE001]; allowed with the other parameters as given: 0 ms … 2500 ms"
    );
    // Two parameters that depend on each other: the range of the first one that alone
    // makes the block accept.
    let text = "[project]\nname = \"t\"\n\n[[group]]\nname = \"g\"\n\n[[group.member]]\nname = \"lim\"\ntype = \"LIMIT_INT\"\nactive = [\"nAnalogIn\"]\nnMinimumValue = 100\nnMaximumValue = 50\n";
    let e = project_error(text);
    assert!(e.starts_with("11:17: member `lim`: LIMIT_INT: nMinimumValue (100) must be <= nMaximumValue (50) [Text ID 0x4090]; allowed with the other parameters as given: -32768 … 50"), "{e}");
}

#[test]
fn a_misspelled_link_source_suggests_outputs() {
    let text = "[project]\nname = \"t\"\n\n[[group]]\nname = \"g\"\nlinks = [\"estop.bEStopOutt -> k.bAndIn1\"]\n\n[[group.member]]\nname = \"estop\"\ntype = \"ESTOP\"\nactive = [\"bEStopIn1\", \"bEStopIn2\"]\n\n[[group.member]]\nname = \"k\"\ntype = \"AND\"\nactive = [\"bAndIn1\"]\n";
    let e = project_error(text);
    assert!(
        e.contains("unknown output `bEStopOutt` of ESTOP `estop` (did you mean bEStopOut, "),
        "{e}"
    );
    assert!(!e.contains("bEStopIn"), "{e}");
}

#[test]
fn scenario_values_are_checked_against_the_signal_type() {
    assert_eq!(
        scenario_error("set = { V1 = true }"),
        "6:14: V1: wrong value type: a boolean given, expected an integer (INT)"
    );
    assert_eq!(
        scenario_error("set = { S1 = 2 }"),
        "6:14: S1: wrong value type: an integer given, expected true or false"
    );
    assert_eq!(
        scenario_error("set = { V1 = 40000 }"),
        "6:14: V1: 40000 is out of range for INT"
    );
    assert_eq!(
        scenario_error("expect = { Speed = true }"),
        "6:20: Speed: wrong value type: a boolean given, expected an integer (INT)"
    );
    assert_eq!(
        scenario_error("expect = { Door = 1 }"),
        "6:19: Door: wrong value type: an integer given, expected true or false"
    );
    assert_eq!(
        scenario_error("expect = { \"door.nDiag\" = true }"),
        "6:27: door.nDiag: wrong value type: a boolean given, expected an integer (UINT/WORD)"
    );
    // Every message names its key: a time that is not one.
    let p = Project::parse("p.toml", TYPED).unwrap();
    let e =
        Scenario::parse("s.toml", "[scenario]\nname = \"s\"\nuntil = \"soon\"\n", &p).unwrap_err();
    assert_eq!(e.msg, "scenario.until: `soon` is not a time; expected a whole number with a unit, like \"100 ms\"");
    let e = Scenario::parse(
        "s.toml",
        "[scenario]\nname = \"s\"\n[[step]]\nat = \"1 parsec\"\n",
        &p,
    )
    .unwrap_err();
    assert_eq!(
        e.msg,
        "step.at: `1 parsec` is not a time; expected a whole number with a unit, like \"100 ms\""
    );
}

#[test]
fn duplicate_keys_are_named_and_non_utf8_has_a_position() {
    let e = project_error("[project]\nname = \"x\"\nname = \"y\"\n");
    assert_eq!(e, "3:1: duplicate key `name`");
    let dir = tmp("utf8");
    let f = dir.join("bad.toml");
    std::fs::write(&f, b"[project]\nname = \"x\xff\"\n").unwrap();
    let e = safelogic_project::load_project(f.to_str().unwrap()).unwrap_err();
    assert_eq!((e.line, e.col), (2, 10), "{e}");
    assert_eq!(
        e.msg,
        "the file is not UTF-8 text: byte 0xFF at byte offset 19 is not valid UTF-8"
    );
    std::fs::remove_dir_all(dir).ok();
}

fn tmp(what: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("safelogic-refusals-{what}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

#[test]
fn a_failed_run_leaves_no_file_and_says_write() {
    let dir = tmp("atomic");
    let p = root().join("examples/projects/kl6904_5_1.toml");
    let s = root().join("examples/projects/kl6904_5_1.scenario.toml");
    let out = Command::new(env!("CARGO_BIN_EXE_safelogic"))
        .current_dir(&dir)
        .args(["sim".as_ref(), p.as_os_str(), s.as_os_str()])
        .args(["--vcd", "a.vcd", "--svg", "/nonexistent/x.svg"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("/nonexistent/x.svg: error: cannot write the file"),
        "{err}"
    );
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
    // A file that cannot be read says so.
    let out = Command::new(env!("CARGO_BIN_EXE_safelogic"))
        .args(["check", "/nonexistent/p.toml"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("/nonexistent/p.toml: error: cannot read the file"),
        "{err}"
    );
    // A successful run writes both, and nothing else.
    let out = Command::new(env!("CARGO_BIN_EXE_safelogic"))
        .current_dir(&dir)
        .args(["sim".as_ref(), p.as_os_str(), s.as_os_str()])
        .args(["--vcd", "a.vcd", "--svg", "b.svg"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let mut left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    left.sort();
    assert_eq!(left, ["a.vcd", "b.svg"]);
    std::fs::remove_dir_all(dir).ok();
}
