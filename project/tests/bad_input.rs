//! The bad-input corpus (`tests/bad_input/`): project files, scenarios (against
//! `bad_input/base.toml`) and C-level configurations, each with the refusal it must get.
//!
//! - `projects/*.toml`, `scenarios/*.scenario.toml`: the first line is
//!   `# expect: <line>:<col>: <message>`, the tool's whole message (positions in the file
//!   as it is, this line included). `SAFELOGIC_BLESS=1` rewrites these lines from the
//!   current messages (then read the diff).
//! - `c/*.toml`: `target` = "block" (a registered type, `[set]` fields by name, then its
//!   init), "group" (`call` = "init" with `[set]`, or a cycle of a running group with a
//!   NULL table) or "fsoe" (a valid master connection with `[set]` applied, then
//!   `sl_fsoe_init`); `expect` is the status. Every refusal also leaves the safe state: a
//!   block in STOP with every BOOL output FALSE, a group not in RUN with bInRun/bFbRun FALSE,
//!   a connection in Reset that sends nothing and refuses its cycles.

use safelogic::any::AnyBlock;
use safelogic::ffi::*;
use safelogic::fsoe::conn::SL_FSOE_CONN;
use safelogic::registry::{block_type_named, Dir, Kind};
use safelogic::*;
use safelogic_project::sim::Scenario;
use safelogic_project::Project;
use std::path::{Path, PathBuf};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_input")
}

fn files(sub: &str) -> Vec<PathBuf> {
    let mut v: Vec<_> = std::fs::read_dir(dir().join(sub))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    v.sort();
    v
}

/// The expectation line and the rest of a corpus file.
fn expectation(bytes: &[u8], path: &Path) -> String {
    let first = bytes.split(|&b| b == b'\n').next().unwrap();
    let line = std::str::from_utf8(first).unwrap();
    line.strip_prefix("# expect: ")
        .unwrap_or_else(|| panic!("{}: no `# expect:` first line", path.display()))
        .to_string()
}

fn bless(path: &Path, bytes: &[u8], got: &str) {
    let rest = if bytes.starts_with(b"# expect: ") {
        bytes.splitn(2, |&b| b == b'\n').nth(1).unwrap_or(b"")
    } else {
        bytes
    };
    let mut out = format!("# expect: {got}\n").into_bytes();
    out.extend_from_slice(rest);
    std::fs::write(path, out).unwrap();
}

#[test]
fn every_bad_file_gets_its_refusal() {
    let blessing = std::env::var_os("SAFELOGIC_BLESS").is_some();
    let base = Project::parse(
        "base.toml",
        &std::fs::read_to_string(dir().join("base.toml")).unwrap(),
    )
    .expect("base.toml is valid");
    let mut count = 0;
    let mut wrong = Vec::new();
    for (sub, scenario) in [("projects", false), ("scenarios", true)] {
        for path in files(sub) {
            let bytes = std::fs::read(&path).unwrap();
            let name = path.file_name().unwrap().to_str().unwrap();
            let e = if scenario {
                let text = String::from_utf8(bytes.clone()).unwrap();
                Scenario::parse(name, &text, &base).map(|_| ()).unwrap_err()
            } else {
                safelogic_project::load_project(path.to_str().unwrap())
                    .map(|_| ())
                    .unwrap_err()
            };
            let got = format!("{}:{}: {}", e.line, e.col, e.msg);
            if blessing {
                bless(&path, &bytes, &got);
            } else if expectation(&bytes, &path) != got {
                wrong.push(format!(
                    "{sub}/{name}:\n  want {}\n  got  {got}",
                    expectation(&bytes, &path)
                ));
            }
            count += 1;
        }
    }
    for path in files("c") {
        c_case(&path);
        count += 1;
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(count >= 60, "{count} corpus files");
}

fn status_named(s: &str) -> i32 {
    match s {
        "SL_E_NULL" => SL_E_NULL,
        "SL_E_CONFIG" => SL_E_CONFIG,
        other => panic!("unknown status {other}"),
    }
}

fn c_case(path: &Path) {
    let what = path.display().to_string();
    let t: toml::Table = std::fs::read_to_string(path).unwrap().parse().unwrap();
    let want = status_named(t["expect"].as_str().unwrap());
    let empty = toml::Table::new();
    let set = t.get("set").and_then(|s| s.as_table()).unwrap_or(&empty);
    let int = |v: &toml::Value| v.as_integer().unwrap_or_else(|| panic!("{what}: {v:?}"));
    match t["target"].as_str().unwrap() {
        "block" => {
            let ty = block_type_named(t["type"].as_str().unwrap()).expect("a registered type");
            let mut b = AnyBlock::new(ty.info.tag).unwrap();
            for (k, v) in set {
                b.set(k, int(v)).unwrap_or_else(|_| panic!("{what}: {k}"));
            }
            assert_eq!(b.init(), want, "{what}");
            // The safe state: STOP, every BOOL output FALSE (ABI §5 for SL_E_CONFIG).
            let f = ty.field("nState").unwrap();
            assert_eq!(b.value(f), Some(i64::from(SL_STATE_STOP)), "{what}");
            for f in ty
                .fields
                .iter()
                .filter(|f| f.dir == Dir::Output && f.kind == Kind::Bool)
            {
                assert_eq!(b.value(f), Some(0), "{what}: {}", f.name);
            }
        }
        "fsoe" => {
            let mut c = SL_FSOE_CONN {
                nConnectionId: 7,
                nFsoeAddress: 3,
                nRole: fsoe::SL_FSOE_ROLE_MASTER,
                nTxDataLen: 2,
                nRxDataLen: 2,
                tWatchdogTime: 100,
                ..Default::default()
            };
            // SAFETY: a live, exclusively borrowed connection.
            assert_eq!(
                unsafe { sl_fsoe_init(&mut c) },
                SL_OK,
                "{what}: the base is valid"
            );
            for (k, v) in set {
                let v = int(v);
                match k.as_str() {
                    "nConnectionId" => c.nConnectionId = v as u16,
                    "nRole" => c.nRole = v as u16,
                    "nTxDataLen" => c.nTxDataLen = v as u16,
                    "nRxDataLen" => c.nRxDataLen = v as u16,
                    "nAppParaLen" => c.nAppParaLen = v as u16,
                    "tWatchdogTime" => c.tWatchdogTime = v as u32,
                    "dwOptions" => c.dwOptions = v as u32,
                    other => panic!("{what}: field {other}"),
                }
            }
            // SAFETY: as above.
            assert_eq!(unsafe { sl_fsoe_init(&mut c) }, want, "{what}");
            assert_eq!(c.nState, fsoe::SL_FSOE_STATE_RESET, "{what}");
            assert_eq!((c.bDataValid, c.bComStartup), (0, 0), "{what}");
            let mut tx = [0u8; 67];
            let mut len = 0usize;
            // SAFETY: live buffers of the given sizes.
            let rc = unsafe {
                sl_fsoe_cycle(
                    &mut c,
                    1,
                    std::ptr::null(),
                    0,
                    tx.as_mut_ptr(),
                    tx.len(),
                    &mut len,
                )
            };
            assert_eq!(
                (rc, len),
                (SL_E_CONFIG, 0),
                "{what}: a refused connection sends nothing"
            );
        }
        "group" => group_case(&what, t["call"].as_str().unwrap(), set, want),
        other => panic!("{what}: target {other}"),
    }
}

fn group_case(what: &str, call: &str, set: &toml::Table, want: i32) {
    let mut g = Box::new(SL_GROUP::default());
    let mut m = Box::new([SL_MEMBER::default(); 2]);
    let mut l = Box::new([SL_LINK::default(); 2]);
    if call == "init" {
        for (k, v) in set {
            match k.as_str() {
                "bConnections" => g.bConnections = v.as_integer().unwrap() as u8,
                other => panic!("{what}: field {other}"),
            }
        }
        // SAFETY: live boxed tables of the given capacities.
        assert_eq!(
            unsafe { sl_group_init(&mut *g, m.as_mut_ptr(), 2, l.as_mut_ptr(), 2) },
            want,
            "{what}"
        );
        assert_eq!((g.bInRun, g.bFbRun), (0, 0), "{what}");
        return;
    }
    let mut e = Box::new(FB_ESTOP {
        wInputActive: 3,
        bEStopIn1: 1,
        bEStopIn2: 1,
        ..Default::default()
    });
    let mut a = Box::new(FB_AND {
        wInputActive: 3,
        bAndIn2: 1,
        ..Default::default()
    });
    // SAFETY: live boxed blocks and tables; every call checks what it can.
    unsafe {
        assert_eq!(sl_estop_init(&mut *e), SL_OK);
        assert_eq!(sl_and_init(&mut *a), SL_OK);
        assert_eq!(
            sl_group_init(&mut *g, m.as_mut_ptr(), 2, l.as_mut_ptr(), 2),
            SL_OK
        );
        let mut idx = 0u16;
        assert_eq!(
            sl_group_add_member(
                &mut *g,
                m.as_mut_ptr(),
                SL_TYPE_ESTOP,
                (&mut *e as *mut FB_ESTOP).cast(),
                &mut idx
            ),
            SL_OK
        );
        assert_eq!(
            sl_group_add_member(
                &mut *g,
                m.as_mut_ptr(),
                SL_TYPE_AND,
                (&mut *a as *mut FB_AND).cast(),
                &mut idx
            ),
            SL_OK
        );
        let src = std::mem::offset_of!(FB_ESTOP, bEStopOut) as u16;
        let dst = std::mem::offset_of!(FB_AND, bAndIn1) as u16;
        assert_eq!(
            sl_group_add_link(&mut *g, m.as_mut_ptr(), l.as_mut_ptr(), 0, src, 1, dst),
            SL_OK
        );
        g.bRun = 1;
        for t in 0..3 {
            sl_group_cycle(&mut *g, m.as_mut_ptr(), l.as_mut_ptr(), t);
        }
        assert_eq!(g.nState, SL_STATE_RUN, "{what}: the group runs first");
        let rc = match call {
            "cycle-null-members" => {
                sl_group_cycle(&mut *g, std::ptr::null_mut(), l.as_mut_ptr(), 10)
            }
            "cycle-null-links" => sl_group_cycle(&mut *g, m.as_mut_ptr(), std::ptr::null_mut(), 10),
            other => panic!("{what}: call {other}"),
        };
        assert_eq!(rc, want, "{what}");
    }
    assert_eq!(g.nState, SL_STATE_ERROR, "{what}");
    assert_eq!((g.bInRun, g.bFbRun, g.bFbErr), (0, 0, 1), "{what}");
}

/// `c_rules.toml`: one violating configuration per parameter rule of every registered type
/// (`[[case]]`: `types`, `set` fields by name, `raw` BOOL bytes, LOADSENSING `rows` as
/// `[X, Y1, Y2, WY1, WY2]`),
/// with the exact sentence `sl_reason_text` writes (`{type}` stands for the type's name)
/// and the refusal it gets: `expect = "SL_E_CONFIG"` (a TwinSAFE block held in STOP with
/// every BOOL output FALSE, a PLCopen block in DiagCode C3FC at activation) or a PLCopen
/// parameter-error DiagCode (`expect = "DiagCode 0xC000"`), Error TRUE and every other BOOL
/// output FALSE. Then the reach check: every rule of every type's list (`BlockType::rules`,
/// the lists the checks run) was the refusal of a case, so a rule added without a case
/// fails here. `SAFELOGIC_BLESS=1` rewrites the `reason` lines from the current sentences.
#[test]
fn every_parameter_rule_of_every_block_has_its_refusal() {
    use safelogic::registry::{family, Family, BLOCKS};
    use std::collections::BTreeSet;
    let blessing = std::env::var_os("SAFELOGIC_BLESS").is_some();
    let path = dir().join("c_rules.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let t: toml::Table = text.parse().unwrap();
    let cases = t["case"].as_array().unwrap();
    let mut hit = BTreeSet::new();
    let mut blessed = Vec::new();
    let mut wrong = Vec::new();
    for (n, case) in cases.iter().enumerate() {
        let case = case.as_table().unwrap();
        let want = case["reason"].as_str().unwrap();
        let expect = case["expect"].as_str().unwrap();
        let mut templated = None;
        for ty_name in case["types"].as_array().unwrap() {
            let ty_name = ty_name.as_str().unwrap();
            let what = format!("case {} ({ty_name})", n + 1);
            let ty = block_type_named(ty_name).unwrap_or_else(|| panic!("{what}: a type"));
            let mut b = AnyBlock::new(ty.info.tag).unwrap();
            if let Some(set) = case.get("set").and_then(|s| s.as_table()) {
                for (k, v) in set {
                    b.set(k, v.as_integer().unwrap())
                        .unwrap_or_else(|_| panic!("{what}: {k}"));
                }
            }
            // A BOOL constant's byte that is neither 0 nor 1 (`set` refuses it).
            if let Some(raw) = case.get("raw").and_then(|s| s.as_table()) {
                for (k, v) in raw {
                    let f = ty.field(k).unwrap_or_else(|| panic!("{what}: {k}"));
                    assert_eq!(f.kind, Kind::Bool, "{what}: {k}");
                    let byte = u8::try_from(v.as_integer().unwrap()).unwrap();
                    // SAFETY: the field's byte inside the block.
                    unsafe { *b.as_mut_ptr().cast::<u8>().add(usize::from(f.offset)) = byte };
                }
            }
            if let Some(rows) = case.get("rows").and_then(|r| r.as_array()) {
                write_rows(&mut b, rows, &what);
            }
            let init = b.init();
            let refusal = b
                .refusal()
                .unwrap_or_else(|| panic!("{what}: the configuration is refused"));
            hit.insert((ty.info.tag, refusal.index));
            // The sentence through the C ABI.
            let mut buf = [0u8; 300];
            // SAFETY: a live block of the type named by the tag; a buffer of its length.
            let rc = unsafe {
                sl_reason_text(ty.info.tag, b.as_ptr(), buf.as_mut_ptr().cast(), buf.len())
            };
            assert_eq!(rc, SL_OK, "{what}");
            let got = std::ffi::CStr::from_bytes_until_nul(&buf)
                .unwrap()
                .to_str()
                .unwrap()
                .replace(ty.info.name, "{type}");
            assert_eq!(
                templated.get_or_insert_with(|| got.clone()),
                &got,
                "{what}: the types of one case give one sentence"
            );
            if !blessing && got != want {
                wrong.push(format!("{what}:\n  want {want}\n  got  {got}"));
            }
            refused_safely(&mut b, init, expect, &what);
            assert_eq!(
                b.reason().replace(ty.info.name, "{type}"),
                got,
                "{what}: Rust"
            );
        }
        blessed.push(templated.unwrap());
    }
    if blessing {
        let mut n = 0;
        let out: Vec<String> = text
            .lines()
            .map(|l| {
                if l.starts_with("reason = ") {
                    n += 1;
                    format!("reason = {:?}", blessed[n - 1])
                } else {
                    l.to_string()
                }
            })
            .collect();
        std::fs::write(&path, out.join("\n") + "\n").unwrap();
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    let missing: Vec<String> = BLOCKS
        .iter()
        .flat_map(|bt| {
            let hit = &hit;
            bt.rules()
                .enumerate()
                .filter(move |&(i, _)| !hit.contains(&(bt.info.tag, i)))
                .map(move |(i, r)| format!("{} rule {i}: {} {:?}", bt.info.name, r.field, r.rule))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "rules without a case in c_rules.toml:\n{}",
        missing.join("\n")
    );
    // Every family is in the list (a type without rules would need none).
    assert!(BLOCKS.iter().all(|bt| bt.rules().next().is_some()));
    assert!(BLOCKS
        .iter()
        .any(|bt| family(bt.info.tag) == Family::PlcOpen));
}

/// Writes LOADSENSING's rows (`[X, Y1, Y2, WY1, WY2]` each) into the table parameter.
fn write_rows(b: &mut AnyBlock, rows: &[toml::Value], what: &str) {
    let ty = b.block_type();
    let &(offset, bytes) = ty.table_params.first().expect("a table parameter");
    let kind = ty.field("nAnalogInX").expect("LOADSENSING").kind;
    let size = kind.size();
    assert!(rows.len() * 5 * size <= bytes, "{what}: rows");
    let base = b.as_mut_ptr().cast::<u8>();
    for (i, row) in rows.iter().enumerate() {
        for (j, v) in row.as_array().unwrap().iter().enumerate() {
            let v = v.as_integer().unwrap();
            assert!(safelogic::any::in_range(kind, v), "{what}: row value {v}");
            let le = (v as u32).to_le_bytes();
            // SAFETY: inside the table parameter of the block (checked above); bytes.
            unsafe {
                let at = base.add(offset + (i * 5 + j) * size);
                core::ptr::copy_nonoverlapping(le.as_ptr(), at, size);
            }
        }
    }
}

/// The refusal leaves the safe state (see `every_parameter_rule_of_every_block_has_its_refusal`).
fn refused_safely(b: &mut AnyBlock, init: i32, expect: &str, what: &str) {
    use safelogic::registry::{family, Family};
    let ty = b.block_type();
    let bool_outputs: Vec<_> = ty
        .fields
        .iter()
        .filter(|f| f.dir == Dir::Output && f.kind == Kind::Bool)
        .collect();
    match family(ty.info.tag) {
        Family::TwinSafe => {
            assert_eq!((init, expect), (SL_E_CONFIG, "SL_E_CONFIG"), "{what}");
            b.member_mut().drive(1, 0);
            assert_eq!(b.member_mut().execute(1).code(), SL_E_CONFIG, "{what}");
            let f = ty.field("nState").unwrap();
            assert_eq!(b.value(f), Some(i64::from(SL_STATE_STOP)), "{what}");
            for f in &bool_outputs {
                assert_eq!(b.value(f), Some(0), "{what}: {}", f.name);
            }
        }
        Family::PlcOpen => {
            let act = if ty.info.name == "SF_ResetButton" {
                "ResetRequested"
            } else {
                "Activate"
            };
            b.set(act, 1).unwrap();
            let status = b.member_mut().execute(1).code();
            let code = b.value(ty.field("DiagCode").unwrap()).unwrap();
            if expect == "SL_E_CONFIG" {
                assert_eq!(
                    (init, status, code),
                    (SL_E_CONFIG, SL_E_CONFIG, 0xC3FC),
                    "{what}"
                );
            } else {
                let want = expect.strip_prefix("DiagCode 0x").expect("a DiagCode");
                let want = i64::from_str_radix(want, 16).unwrap();
                assert_eq!((init, status, code), (SL_OK, SL_OK, want), "{what}");
            }
            for f in &bool_outputs {
                let v = b.value(f);
                // S_TestOut drives the sensor's transmitter (TRUE but while a test runs),
                // not a safety function.
                let want = match f.name {
                    "Ready" | "Error" | "S_TestOut" => v,
                    _ => Some(0),
                };
                if f.name == "Error" {
                    assert_eq!(v, Some(1), "{what}: Error");
                }
                assert_eq!(v, want, "{what}: {}", f.name);
            }
        }
    }
}
