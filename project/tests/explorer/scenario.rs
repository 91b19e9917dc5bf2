//! A violation's trace as a one-block project and a scenario that `safelogic sim` replays
//! (docs/project.md): task cycle 1 ms, one step per explorer call, the offending call's
//! state and BOOL outputs as the last step's expectations.

use super::{is_time, Violation};
use safelogic::any::input_bit;
use safelogic::registry::{block_type_named, Dir, Kind};
use std::fmt::Write;

/// The process-image name of a driven input (the group's Run and ErrAck drive the block's).
fn place(input: &str) -> String {
    match input {
        "bRun" => "g.bRun".into(),
        "bErrAck" => "g.bErrAck".into(),
        _ => format!("b.{input}"),
    }
}

/// (project file, scenario file) of a violation.
pub fn files(v: &Violation) -> (String, String) {
    let ty = block_type_named(v.block).expect("a registered block");
    let mut p = String::new();
    writeln!(
        p,
        "# The explorer's one-block project for {} ({}).",
        v.block, v.config.label
    )
    .unwrap();
    writeln!(
        p,
        "[project]\nname = \"explore {}\"\ncycle = \"1 ms\"\n",
        v.block
    )
    .unwrap();
    writeln!(
        p,
        "[[group]]\nname = \"g\"\n\n[[group.member]]\nname = \"b\"\ntype = \"{}\"",
        v.block
    )
    .unwrap();
    for (f, val) in &v.config.params {
        match f.name {
            "wInputActive" => {
                let names: Vec<String> = ty
                    .fields
                    .iter()
                    .filter(|i| i.dir == Dir::Input)
                    .filter(|i| input_bit(v.block, i.name).is_some_and(|b| val & (1 << b) != 0))
                    .map(|i| format!("\"{}\"", i.name))
                    .collect();
                writeln!(p, "active = [{}]", names.join(", ")).unwrap();
            }
            _ if is_time(f) => writeln!(p, "{} = \"{val} ms\"", f.name).unwrap(),
            _ if f.kind == Kind::Bool => writeln!(p, "{} = {}", f.name, *val == 1).unwrap(),
            _ => writeln!(p, "{} = {val}", f.name).unwrap(),
        }
    }
    writeln!(p, "\n[inputs]").unwrap();
    for (f, _) in &v.config.driven {
        writeln!(p, "{} = \"{}\"", f.name, place(f.name)).unwrap();
    }
    writeln!(p, "\n[outputs]").unwrap();
    for (o, _) in &v.outputs_after {
        writeln!(p, "{o} = \"b.{o}\"").unwrap();
    }

    let mut s = String::new();
    writeln!(s, "# The explorer's shortest trace to: {}", v.what).unwrap();
    writeln!(
        s,
        "[scenario]\nname = \"{}: {}\"",
        v.block,
        v.what.replace('"', "'")
    )
    .unwrap();
    let mut t = 0u32;
    for (k, step) in v.trace.iter().enumerate() {
        let mut note = Vec::new();
        if k > 0 {
            if step.dt == 0 {
                note.push("explorer step of 0 ms, replayed 1 ms later");
            }
            t += step.dt.max(1);
        }
        let sets: Vec<String> = v
            .config
            .driven
            .iter()
            .zip(&step.inputs)
            .map(|((f, _), x)| match (f.kind, x) {
                (Kind::Bool, 2) => {
                    note.push("invalid BOOL byte 2 replayed as TRUE");
                    format!("{} = true", f.name)
                }
                (Kind::Bool, x) => format!("{} = {}", f.name, *x == 1),
                (_, x) => format!("{} = {x}", f.name),
            })
            .collect();
        writeln!(
            s,
            "\n[[step]]\nat = \"{t} ms\"\nset = {{ {} }}",
            sets.join(", ")
        )
        .unwrap();
        if k + 1 == v.trace.len() {
            let mut ex = vec![format!("\"b.state\" = \"{}\"", v.state_after)];
            ex.extend(v.diag_after.map(|d| format!("\"b.DiagCode\" = {d}")));
            ex.extend(
                v.outputs_after
                    .iter()
                    .map(|(o, x)| format!("{o} = {}", *x == 1)),
            );
            writeln!(s, "expect = {{ {} }}", ex.join(", ")).unwrap();
        }
        if !note.is_empty() {
            note.dedup();
            writeln!(s, "note = \"{}\"", note.join("; ")).unwrap();
        }
    }
    (p, s)
}
