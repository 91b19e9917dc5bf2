//! Every mistake class of a project file gets an error with file, line, column and what was
//! expected (one test per class), and the project CRC.

use safelogic_project::Project;

const GOOD: &str = r#"[project]
name = "demo"
cycle = "10 ms"

[[group]]
name = "safety"
links = ["estop.bEStopOut -> k1.bAndIn1", "door.bMonOut -> k1.bAndIn2"]

[[group.member]]
name = "estop"
type = "ESTOP"
active = ["bEStopIn1", "bEStopIn2"]
tDiscTime12 = "100 ms"

[[group.member]]
name = "door"
type = "MON"
active = ["bMonIn1"]

[[group.member]]
name = "k1"
type = "AND"
active = ["bAndIn1", "bAndIn2"]

[inputs]
S1 = ["estop.bEStopIn1", "estop.bEStopIn2"]
door = "door.bMonIn1"
ErrAck = "safety.bErrAck"

[outputs]
K1 = "k1.bAndOut"
"#;

/// The error for `GOOD` with `from` replaced by `to`, as "line:col: message".
fn error(from: &str, to: &str) -> String {
    assert!(GOOD.contains(from), "{from}");
    let text = GOOD.replacen(from, to, 1);
    let e = Project::parse("p.toml", &text).expect_err("an error");
    assert_eq!(e.file, "p.toml");
    let s = e.to_string();
    assert!(
        s.starts_with(&format!("p.toml:{}:{}: error: ", e.line, e.col)),
        "{s}"
    );
    format!("{}:{}: {}", e.line, e.col, e.msg)
}

#[test]
fn the_good_project_loads_and_describes_its_wiring() {
    let p = Project::parse("p.toml", GOOD).unwrap();
    let d = p.describe();
    assert!(
        d.contains("link estop.bEStopOut -> k1.bAndIn1 (BOOL)"),
        "{d}"
    );
    assert!(
        d.contains("input  S1             -> estop.bEStopIn1, estop.bEStopIn2 (BOOL)"),
        "{d}"
    );
    assert!(d.contains(&format!("project CRC 0x{:08X}", p.crc)));
    assert_eq!(p.groups[0].members[0].values.len(), 2); // tDiscTime12, wInputActive
}

#[test]
fn syntax_error() {
    let e = error("cycle = \"10 ms\"", "cycle = \"10 ms");
    assert!(e.starts_with("3:"), "{e}");
}

#[test]
fn unknown_type() {
    let e = error("type = \"ESTOP\"", "type = \"ESTOPP\"");
    assert!(e.starts_with("11:8: unknown type `ESTOPP`; expected a block type of the registry (did you mean ESTOP"), "{e}");
}

#[test]
fn unknown_field() {
    let e = error("tDiscTime12 =", "tDiscTime21 =");
    assert!(e.starts_with("13:1: unknown field `tDiscTime21` of ESTOP; expected a parameter or input (did you mean"), "{e}");
    let e = error("K1 = \"k1.bAndOut\"", "K1 = \"k1.bAndOt\"");
    assert!(
        e.starts_with("31:6: unknown output `bAndOt` of AND `k1`"),
        "{e}"
    );
    let e = error("active = [\"bMonIn1\"]", "active = [\"bMonIn9\"]");
    assert!(
        e.contains(
            "`bMonIn9` is not an input of MON with an active/negated bit; expected one of bMonIn1"
        ),
        "{e}"
    );
}

#[test]
fn wrong_value_type() {
    let e = error("tDiscTime12 = \"100 ms\"", "tDiscTime12 = 100");
    assert_eq!(e, "13:15: ESTOP.tDiscTime12: wrong value type: an integer given, expected a time like \"100 ms\"");
    let e = error("tDiscTime12 = \"100 ms\"", "tDiscTime12 = \"100 parsecs\"");
    assert!(
        e.starts_with("13:15: ESTOP.tDiscTime12: `100 parsecs` is not a time"),
        "{e}"
    );
    let e = error(
        "active = [\"bMonIn1\"]",
        "active = [\"bMonIn1\"]\nbSecure1 = 1",
    );
    assert_eq!(
        e,
        "19:12: MON.bSecure1: wrong value type: an integer given, expected true or false"
    );
}

#[test]
fn out_of_range_parameter() {
    // outside the field's type
    let e = error(
        "active = [\"bMonIn1\"]",
        "active = [\"bMonIn1\"]\ndwOptions = -1",
    );
    assert_eq!(
        e,
        "19:13: MON.dwOptions: -1 is out of range for UDINT/DWORD"
    );
    // inside the type, refused by the block's init: the library's reason at the line of
    // the field it names
    let e = error(
        "active = [\"bAndIn1\", \"bAndIn2\"]",
        "active = [\"bAndIn1\"]",
    );
    assert_eq!(
        e,
        "23:10: member `k1`: AND: wInputActive (0x0001) must have at least 2 bits set [reason 0xE00A]"
    );
}

#[test]
fn link_between_different_types() {
    let text = GOOD.replace(
        "links = [\"estop.bEStopOut -> k1.bAndIn1\"",
        "links = [\"estop.nDiag -> k1.bAndIn1\"",
    );
    let e = Project::parse("p.toml", &text).unwrap_err();
    assert_eq!((e.line, e.col), (7, 10));
    assert!(e.msg.contains("is not an output"), "{}", e.msg);
    let text = GOOD
        .replace("type = \"AND\"", "type = \"ADD_INT\"")
        .replace(
            "active = [\"bAndIn1\", \"bAndIn2\"]",
            "active = [\"nAnalogIn1\", \"nAnalogIn2\"]",
        );
    let text = text
        .replace("k1.bAndIn1", "k1.nAnalogIn1")
        .replace("k1.bAndIn2", "k1.nAnalogIn2")
        .replace("k1.bAndOut", "k1.nAnalogOut");
    let e = Project::parse("p.toml", &text).unwrap_err();
    assert_eq!((e.line, e.col), (7, 10), "{e}");
    assert_eq!(e.msg, "link between different types: `estop.bEStopOut` is BOOL, `k1.nAnalogIn1` is INT; expected the same type on both ends");
}

#[test]
fn input_linked_twice() {
    let e = error("door = \"door.bMonIn1\"", "door = \"k1.bAndIn2\"");
    assert_eq!(e, "27:8: input `k1.bAndIn2` is linked twice: already driven by link `door.bMonOut -> k1.bAndIn2`");
    let e = error(
        "\"door.bMonOut -> k1.bAndIn2\"",
        "\"door.bMonOut -> k1.bAndIn1\"",
    );
    assert!(e.starts_with("7:43: input `k1.bAndIn1` is linked twice: already driven by link `estop.bEStopOut -> k1.bAndIn1`"), "{e}");
}

#[test]
fn duplicate_names() {
    let e = error("name = \"door\"", "name = \"estop\"");
    assert_eq!(
        e,
        "16:8: duplicate name `estop`: groups and members need unique names"
    );
    let e = error("K1 = \"k1.bAndOut\"", "door = \"k1.bAndOut\"");
    assert!(e.starts_with("31:1: duplicate name `door`"), "{e}");
}

#[test]
fn crc_covers_the_content_not_the_formatting() {
    let p = Project::parse("p.toml", GOOD).unwrap();
    // comments, spacing, key order inside a member: same CRC
    let reformatted = GOOD.replace("[project]", "# a comment\n[project]").replace(
        "active = [\"bEStopIn1\", \"bEStopIn2\"]\ntDiscTime12 = \"100 ms\"",
        "tDiscTime12   =   \"100 ms\"\nactive=[\"bEStopIn2\",\"bEStopIn1\"]",
    );
    assert_eq!(Project::parse("p.toml", &reformatted).unwrap().crc, p.crc);
    // the same time in another unit: same CRC
    let p2 = Project::parse(
        "p.toml",
        &GOOD.replace("cycle = \"10 ms\"", "cycle = \"1 s\""),
    )
    .unwrap();
    let p3 = Project::parse(
        "p.toml",
        &GOOD.replace("cycle = \"10 ms\"", "cycle = \"1000 ms\""),
    )
    .unwrap();
    assert_eq!(p2.crc, p3.crc);
    assert_ne!(p2.crc, p.crc);
    // a parameter changed: another CRC
    let changed = Project::parse("p.toml", &GOOD.replace("\"100 ms\"", "\"110 ms\"")).unwrap();
    assert_ne!(changed.crc, p.crc);
    // the canonical content is the documented one
    assert!(p.canonical().starts_with("project demo\ncycle 10\ngroup safety connections=0\nmember estop ESTOP\n  tDiscTime12=100\n  wInputActive=3\n"), "{}", p.canonical());
}

#[test]
fn a_stated_crc_must_match() {
    let p = Project::parse("p.toml", GOOD).unwrap();
    let stated = GOOD.replace(
        "cycle = \"10 ms\"",
        &format!("cycle = \"10 ms\"\ncrc = \"0x{:08X}\"", p.crc),
    );
    assert_eq!(Project::parse("p.toml", &stated).unwrap().crc, p.crc);
    let wrong = GOOD.replace(
        "cycle = \"10 ms\"",
        "cycle = \"10 ms\"\ncrc = \"0x12345678\"",
    );
    let e = Project::parse("p.toml", &wrong).unwrap_err();
    assert_eq!((e.line, e.col), (4, 7));
    assert!(e.msg.starts_with(&format!("project CRC mismatch: the file states 0x12345678, the project's content has 0x{:08X}; the project refuses to run", p.crc)), "{}", e.msg);
}
