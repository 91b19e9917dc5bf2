//! `export-st`: deterministic output with the project CRC in its header, the process image
//! where the project puts it, and every refusal of `check --dialect` with file:line:col.
//! (The real compilers run in tools/export_st_check.py and tools/openplc_e2e.py.)

use safelogic_project::export_st::{check, export, modbus_map, Dialect};
use safelogic_project::Project;

const ALL: [Dialect; 3] = [Dialect::Iec, Dialect::TwinCat, Dialect::Codesys];

const BASE: &str = r#"[project]
name = "t"

[[group]]
name = "safety"
links = ["estop.bEStopOut -> k1.bAndIn1"]

[[group.member]]
name = "estop"
type = "ESTOP"
active = ["bEStopIn1", "bEStopIn2"]
tDiscTime12 = "100 ms"

[[group.member]]
name = "k1"
type = "AND"
active = ["bAndIn1", "bAndIn2"]

[inputs]
S1 = ["estop.bEStopIn1", "estop.bEStopIn2"]
Ack = "safety.bErrAck"
Limit = "PLACEHOLDER"

[outputs]
K1 = "k1.bAndOut"
State = "safety.nState"
"#;

fn base() -> String {
    BASE.replace("Limit = \"PLACEHOLDER\"\n", "")
}

fn parse(text: &str) -> Project {
    Project::parse("p.toml", text).expect("the project loads")
}

/// "line:col: message" of the dialect check.
fn refused(text: &str, d: Dialect) -> String {
    let e = check(&parse(text), d).expect_err("refused");
    assert_eq!(e.file, "p.toml");
    format!("{}:{}: {}", e.line, e.col, e.msg)
}

fn line_col(text: &str, needle: &str) -> String {
    let at = text.find(needle).expect(needle);
    let line = text[..at].matches('\n').count() + 1;
    let col = at - text[..at].rfind('\n').map_or(0, |i| i + 1) + 1;
    format!("{line}:{col}")
}

#[test]
fn output_is_deterministic_and_names_the_project_crc() {
    let p = parse(&base());
    for d in ALL {
        let a = export(&p, d).unwrap();
        let b = export(&parse(&base()), d).unwrap();
        assert_eq!(a, b, "{d:?}");
        assert!(
            a.lines()
                .next()
                .unwrap()
                .contains(&format!("(project CRC 0x{:08X})", p.crc)),
            "{d:?}"
        );
        assert!(a.contains("PROGRAM PRG_SafeLogic"), "{d:?}");
    }
}

#[test]
fn iec_has_the_bindings_located_variables_and_a_configuration() {
    let s = export(&parse(&base()), Dialect::Iec).unwrap();
    for want in [
        "S1 AT %IX0.0 : BOOL;",
        "Ack AT %IX0.1 : BOOL;",
        "K1 AT %QX0.0 : BOOL;",
        "State AT %QB0 : BYTE;",
        "(* ==== POU FB_SL_GROUP ==== *)",
        "(* ==== POU SL_GROUP_ADD_ESTOP ==== *)",
        "(* ==== DUT ST_FB_AND ==== *)",
        "sl_m_estop.tDiscTime12 := UDINT#100;",
        "sl_m_estop.wInputActive := WORD#16#3;",
        "nSrcMember := UINT#0, nSrcOffset := UINT#57, nDstMember := UINT#1, nDstOffset := UINT#8",
        "bErrAck := Ack",
        "State := sl_g_safety.nState;",
        "TASK task0(INTERVAL := T#10ms, PRIORITY := 0);",
    ] {
        assert!(s.contains(want), "{want}");
    }
    // only the POUs it uses: no other block's functions
    assert!(!s.contains("FUNCTION SL_MON_CYCLE"));
}

#[test]
fn stated_locations_clock_states_and_start() {
    let text = base()
        + "\n[plc]\nclock = \"%MD0\"\nstates = \"%MW10\"\nstart = \"%QX100.7\"\n\n[plc.locations]\nS1 = \"%QX100.0\"\nK1 = \"%QX0.3\"\n";
    let p = parse(&text);
    let s = export(&p, Dialect::Iec).unwrap();
    for want in [
        "S1 AT %QX100.0 : BOOL;",
        "Ack AT %IX0.0 : BOOL;",
        "K1 AT %QX0.3 : BOOL;",
        "sl_clock AT %MD0 : UDINT;",
        "sl_st_safety AT %MW10 : UINT;",
        "sl_st_estop AT %MW11 : UINT;",
        "sl_st_k1 AT %MW12 : UINT;",
        "sl_start AT %QX100.7 : BOOL;",
        "IF NOT sl_bSetUp AND sl_start THEN",
    ] {
        assert!(s.contains(want), "{want}");
    }
    let m = modbus_map(&p).unwrap();
    assert!(
        m.contains(
            r#""location": "%QX100.0", "modbus": {"table": "coil", "address": 800, "words": 1}"#
        ),
        "{m}"
    );
    assert!(m.contains(r#""location": "%MD0", "modbus": {"table": "holding register", "address": 2048, "words": 2}"#));
    assert!(m.contains(r#""location": "%MW11", "modbus": {"table": "holding register", "address": 1035, "words": 1}"#));
    // the table is part of the CRC; the project without it keeps its CRC
    assert_ne!(p.crc, parse(&base()).crc);
    // TwinCAT: stated addresses kept, the rest linked in the System Manager
    let tc = export(&p, Dialect::TwinCat).unwrap();
    assert!(tc.contains("S1 AT %QX100.0 : BOOL;"));
    assert!(tc.contains("Ack AT %I* : BOOL;"));
    assert!(tc.contains("State AT %Q* : BYTE;"));
    let cds = export(&p, Dialect::Codesys).unwrap();
    assert!(cds.contains("    Ack : BOOL;"));
    assert!(cds.contains("cds_sl_group_add_member("));
}

#[test]
fn location_errors_point_at_the_value() {
    let bad = |loc: &str| {
        let text = base() + &format!("\n[plc.locations]\nK1 = \"{loc}\"\n");
        let e = Project::parse("p.toml", &text).expect_err("refused");
        (
            format!("{}:{}", e.line, e.col),
            e.msg,
            line_col(&text, &format!("\"{loc}\"")),
        )
    };
    for (loc, msg) in [
        ("%QW0", "does not fit a BOOL signal"),
        ("%IX0.0", "is in the input image"),
        ("%QX0.8", "is not a direct address"),
        ("QX0.0", "is not a direct address"),
    ] {
        let (at, m, want) = bad(loc);
        assert_eq!(at, want, "{loc}");
        assert!(m.contains(msg), "{loc}: {m}");
    }
    let text = base() + "\n[plc.locations]\nNope = \"%QX0.0\"\n";
    let e = Project::parse("p.toml", &text).unwrap_err();
    assert!(e.msg.contains("unknown signal `Nope`"), "{}", e.msg);
    // two signals at one address
    let text = base() + "\n[plc.locations]\nS1 = \"%QX1.0\"\nAck = \"%QX1.0\"\n";
    let e = check(&parse(&text), Dialect::Iec).unwrap_err();
    let second = line_col(&text, "Ack = \"%QX1.0\"");
    let (l, c) = second.split_once(':').unwrap();
    assert_eq!(
        format!("{}:{}", e.line, e.col),
        format!("{l}:{}", c.parse::<usize>().unwrap() + 6)
    );
    assert!(e.msg.contains("already taken by signal `S1`"), "{}", e.msg);
}

#[test]
fn names_a_dialect_cannot_take_are_refused_where_they_are_written() {
    for (from, to, needle, msg) in [
        (
            "K1 = \"k1.bAndOut\"",
            "END_IF = \"k1.bAndOut\"",
            "END_IF =",
            "reserved word",
        ),
        (
            "K1 = \"k1.bAndOut\"",
            "sl_out = \"k1.bAndOut\"",
            "sl_out =",
            "starts with SL_",
        ),
        (
            "K1 = \"k1.bAndOut\"",
            "s1 = \"k1.bAndOut\"",
            "s1 =",
            "differs only in case",
        ),
        (
            "name = \"k1\"",
            "name = \"k1_\"",
            "\"k1_\"",
            "not an IEC 61131-3 identifier",
        ),
        (
            "name = \"k1\"",
            "name = \"k__1\"",
            "\"k__1\"",
            "not an IEC 61131-3 identifier",
        ),
        (
            "name = \"k1\"",
            "name = \"ESTOP\"",
            "\"ESTOP\"\ntype = \"AND\"",
            "differs only in case",
        ),
    ] {
        let text = if from.starts_with("name") {
            // a member renamed: its links and outputs follow
            base().replace("k1", to.trim_start_matches("name = ").trim_matches('"'))
        } else {
            base().replace(from, to)
        };
        for d in ALL {
            let r = refused(&text, d);
            assert!(
                r.starts_with(&format!("{}: ", line_col(&text, needle))),
                "{to} {d:?}: {r}"
            );
            assert!(r.contains(msg), "{to}: {r}");
        }
    }
}

#[test]
fn group_sizes_the_bindings_cannot_hold() {
    // 33 members: every dialect's SL_MEMBER_STORAGE holds 32
    let mut text = String::from("[project]\nname = \"big\"\n\n[[group]]\nname = \"g\"\nlinks = [");
    let links: Vec<String> = (0..33)
        .map(|i| format!("\"a{i}.bAndOut -> b{i}.bAndIn1\""))
        .collect();
    text += &links.join(", ");
    text += "]\n";
    for i in 0..33 {
        text += &format!("\n[[group.member]]\nname = \"a{i}\"\ntype = \"AND\"\nactive = [\"bAndIn1\", \"bAndIn2\"]\n\n[[group.member]]\nname = \"b{i}\"\ntype = \"AND\"\nactive = [\"bAndIn1\", \"bAndIn2\"]\n");
    }
    for d in ALL {
        let r = refused(&text, d);
        assert!(
            r.starts_with(&format!("{}: ", line_col(&text, "\"g\""))),
            "{r}"
        );
        assert!(r.contains("66 members") && r.contains("32"), "{r}");
    }
    // 16 members with 33 links: too many links for the IEC storage only
    let mut text =
        String::from("[project]\nname = \"links\"\n\n[[group]]\nname = \"g\"\nlinks = [");
    let links: Vec<String> = (0..33)
        .map(|i| format!("\"a{}.bAndOut -> b{}.bAndIn{}\"", i % 4, i / 8, i % 8 + 1))
        .collect();
    text += &links.join(", ");
    text += "]\n";
    for i in 0..4 {
        text += &format!(
            "\n[[group.member]]\nname = \"a{i}\"\ntype = \"AND\"\nactive = [\"bAndIn1\", \"bAndIn2\"]\n"
        );
    }
    for i in 0..5 {
        text += &format!(
            "\n[[group.member]]\nname = \"b{i}\"\ntype = \"AND\"\nactive = [\"bAndIn1\", \"bAndIn2\"]\n"
        );
    }
    let r = refused(&text, Dialect::Iec);
    assert!(
        r.contains("33 links") && r.contains("SL_LINK_STORAGE"),
        "{r}"
    );
    assert!(check(&parse(&text), Dialect::TwinCat).is_ok());
    assert!(export(&parse(&text), Dialect::Codesys)
        .unwrap()
        .contains("sl_gl_g : ARRAY [0..32] OF SL_LINK;"));
}
