//! A VCD file (IEEE 1364 value change dump) of a run, timescale 1 ms: BOOLs as 1-bit wires,
//! integers as vectors, states as their name (a GTKWave string) plus the state number.

use crate::sim::{ColKind, Run, Val};
use std::fmt::Write;

/// The identifier of column `i` (printable ASCII 33–126, base 94).
fn ident(mut i: usize) -> String {
    let mut s = String::new();
    loop {
        s.push(char::from(b'!' + (i % 94) as u8));
        i /= 94;
        if i == 0 {
            return s;
        }
    }
}

fn value(kind: ColKind, v: &Val, id: &str) -> String {
    match (kind, v) {
        (ColKind::Bool, Val::N(n)) => format!("{}{id}", u8::from(*n != 0)),
        (ColKind::Int(bits), Val::N(n)) => {
            let mask = if bits >= 64 {
                u64::MAX
            } else {
                (1u64 << bits) - 1
            };
            format!("b{:b} {id}", (*n as u64) & mask)
        }
        (_, v) => format!("s{} {id}", v.to_string().replace(' ', "_")),
    }
}

/// The VCD text of a run.
pub fn vcd(run: &Run, project: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "$comment safelogic sim: {} $end",
        project.replace('$', "")
    );
    s += "$timescale 1 ms $end\n$scope module project $end\n";
    for (i, c) in run.columns.iter().enumerate() {
        let name = c.name.replace('.', "_");
        let _ = match c.kind {
            ColKind::Bool => writeln!(s, "$var wire 1 {} {name} $end", ident(i)),
            ColKind::Int(b) => writeln!(s, "$var integer {b} {} {name} $end", ident(i)),
            ColKind::State => writeln!(s, "$var string 1 {} {name} $end", ident(i)),
        };
    }
    s += "$upscope $end\n$enddefinitions $end\n";
    // All changes by time.
    let mut events: Vec<(u32, usize, &Val)> = Vec::new();
    for (i, c) in run.columns.iter().enumerate() {
        events.extend(c.changes.iter().map(|(t, v)| (*t, i, v)));
    }
    events.sort_by_key(|(t, i, _)| (*t, *i));
    let mut last = None;
    for (t, i, v) in events {
        if last != Some(t) {
            if last == Some(0) {
                s += "$end\n";
            }
            let _ = writeln!(s, "#{t}");
            if t == 0 {
                s += "$dumpvars\n";
            }
            last = Some(t);
        }
        let _ = writeln!(s, "{}", value(run.columns[i].kind, v, &ident(i)));
    }
    if last == Some(0) {
        s += "$end\n";
    }
    let _ = writeln!(s, "#{}", run.until + 1);
    s
}
