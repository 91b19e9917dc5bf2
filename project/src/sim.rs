//! Scenarios: input changes at given times and expectations (outputs, fields, states) at
//! given times, run against a loaded project; the readable timeline, the cycle-by-cycle
//! trace (what the exported C program prints too) and the recorded signal changes that the
//! VCD and SVG writers draw.

use crate::error::{Error, Source};
use crate::project::{parse_time, typed_value, Place, Project};
use crate::runtime::Runtime;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::io::Write;
use toml::{Spanned, Value};

type Table = BTreeMap<Spanned<String>, Spanned<Value>>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScenario {
    scenario: RawHeader,
    #[serde(default)]
    step: Vec<RawStep>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHeader {
    name: String,
    until: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawStep {
    at: Spanned<String>,
    #[serde(default)]
    set: Table,
    #[serde(default)]
    expect: Table,
    note: Option<String>,
}

/// What an expectation looks at.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Probe {
    /// A process-image output (index).
    Output(usize),
    /// Any field of a member or group.
    Place(Place),
    /// The state of member (group, member).
    MemberState(usize, usize),
    /// The state of a group.
    GroupState(usize),
}

/// One expectation, checked after the cycle at its step's time.
#[derive(Clone, Debug)]
pub struct Expect {
    /// As written ("K1", "estop.state").
    pub label: String,
    /// What it reads.
    pub probe: Probe,
    /// The value wanted (a number, or a state name).
    pub want: Val,
    /// Where it is written (file:line:col).
    pub at: String,
}

/// A value in a trace: a number or a state name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Val {
    /// BOOL (0/1) or an integer.
    N(i64),
    /// A state name.
    S(&'static str),
}

impl std::fmt::Display for Val {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Val::N(n) => write!(f, "{n}"),
            Val::S(s) => f.write_str(s),
        }
    }
}

/// One step of a scenario.
#[derive(Clone, Debug)]
pub struct Step {
    /// Time in ms (a multiple of the task cycle).
    pub at: u32,
    /// Process-image inputs written before the cycle at `at`: (input index, value).
    pub sets: Vec<(usize, i64)>,
    /// Checked after the cycle at `at`.
    pub expects: Vec<Expect>,
    /// A comment shown in the timeline.
    pub note: Option<String>,
}

/// A checked scenario.
#[derive(Clone, Debug)]
pub struct Scenario {
    /// Its name.
    pub name: String,
    /// The last simulated time (ms).
    pub until: u32,
    /// Steps by time.
    pub steps: Vec<Step>,
}

impl Scenario {
    /// Parses a scenario for `project`.
    pub fn parse(file: &str, text: &str, project: &Project) -> Result<Scenario, Error> {
        let src = Source { file, text };
        let raw: RawScenario = toml::from_str(text).map_err(|e| src.toml_error(&e))?;
        let time = |key: &str, s: &Spanned<String>| -> Result<u32, Error> {
            let t = parse_time(s.get_ref()).ok_or_else(|| {
                src.error(
                    s.span(),
                    format!(
                        "{key}: `{}` is not a time; expected a whole number with a unit, like \"100 ms\"",
                        s.get_ref()
                    ),
                )
            })?;
            if t % project.cycle_ms != 0 {
                return Err(src.error(
                    s.span(),
                    format!(
                        "{key}: {t} ms is not a multiple of the task cycle ({} ms)",
                        project.cycle_ms
                    ),
                ));
            }
            Ok(t)
        };
        let mut steps = Vec::new();
        for rs in &raw.step {
            let at = time("step.at", &rs.at)?;
            let mut sets = Vec::new();
            let mut entries: Vec<_> = rs.set.iter().collect();
            entries.sort_by_key(|(k, _)| k.span().start);
            for (k, v) in entries {
                let i = project
                    .inputs
                    .iter()
                    .position(|s| s.name == *k.get_ref())
                    .ok_or_else(|| {
                        src.error(
                            k.span(),
                            format!(
                                "unknown input `{}`; expected one of {}",
                                k.get_ref(),
                                project
                                    .inputs
                                    .iter()
                                    .map(|s| s.name.as_str())
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            ),
                        )
                    })?;
                // The signal's own type, with the project file's rules and words.
                let n = typed_value(&src, project.inputs[i].kind, false, v, k.get_ref())?;
                sets.push((i, n));
            }
            let mut expects = Vec::new();
            let mut entries: Vec<_> = rs.expect.iter().collect();
            entries.sort_by_key(|(k, _)| k.span().start);
            for (k, v) in entries {
                let label = k.get_ref().clone();
                let probe = probe(project, &label).ok_or_else(|| {
                    src.error(k.span(), format!("unknown signal `{label}`; expected an output ({}), <member>.state, <group>.state or <member>.<field>", project.outputs.iter().map(|s| s.name.as_str()).collect::<Vec<_>>().join(", ")))
                })?;
                let want = match (v.get_ref(), &probe) {
                    (Value::String(s), Probe::MemberState(..) | Probe::GroupState(..)) => {
                        Val::S(state_name_static(project, &probe, s).ok_or_else(|| {
                            src.error(
                                v.span(),
                                format!("{label}: `{s}` is not a state of `{label}`"),
                            )
                        })?)
                    }
                    (_, Probe::MemberState(..) | Probe::GroupState(..)) => {
                        return Err(src.error(
                            v.span(),
                            format!(
                                "{label}: wrong value type: a state name like \"RUN\" expected"
                            ),
                        ))
                    }
                    (_, Probe::Output(i)) => Val::N(typed_value(
                        &src,
                        project.outputs[*i].kind,
                        false,
                        v,
                        &label,
                    )?),
                    (_, Probe::Place(p)) => Val::N(typed_value(&src, p.kind(), false, v, &label)?),
                };
                let e = src.error(k.span(), "");
                expects.push(Expect {
                    label,
                    probe,
                    want,
                    at: format!("{}:{}:{}", e.file, e.line, e.col),
                });
            }
            steps.push(Step {
                at,
                sets,
                expects,
                note: rs.note.clone(),
            });
        }
        steps.sort_by_key(|s| s.at);
        let last = steps.last().map_or(0, |s| s.at);
        let until = match &raw.scenario.until {
            Some(u) => time("scenario.until", u)?.max(last),
            None => last,
        };
        Ok(Scenario {
            name: raw.scenario.name,
            until,
            steps,
        })
    }
}

fn probe(p: &Project, label: &str) -> Option<Probe> {
    if let Some(i) = p.outputs.iter().position(|s| s.name == label) {
        return Some(Probe::Output(i));
    }
    let (owner, field) = label.split_once('.')?;
    for (gi, g) in p.groups.iter().enumerate() {
        if g.name == owner {
            if field == "state" {
                return Some(Probe::GroupState(gi));
            }
            let f = crate::project::GROUP_INPUTS
                .iter()
                .chain(crate::project::GROUP_OUTPUTS)
                .find(|n| **n == field)?;
            return Some(Probe::Place(Place::Group {
                group: gi,
                field: f,
            }));
        }
        for (mi, m) in g.members.iter().enumerate() {
            if m.name == owner {
                if field == "state" {
                    return Some(Probe::MemberState(gi, mi));
                }
                let f = m.block.field(field)?;
                return Some(Probe::Place(Place::Member {
                    group: gi,
                    member: mi,
                    field: f,
                }));
            }
        }
    }
    None
}

const GROUP_STATES: &[&str] = &["RUN", "STOP", "ERROR", "RESET", "START", "STOPERROR"];

fn state_name_static(p: &Project, probe: &Probe, s: &str) -> Option<&'static str> {
    match probe {
        Probe::GroupState(_) => GROUP_STATES.iter().find(|n| **n == s).copied(),
        Probe::MemberState(g, m) => p.groups[*g].members[*m]
            .block
            .info
            .states
            .iter()
            .map(|(_, n)| n.trim_end_matches('\0'))
            .find(|n| *n == s),
        _ => None,
    }
}

/// How a recorded column is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColKind {
    /// A BOOL signal.
    Bool,
    /// An integer of this many bits.
    Int(u32),
    /// A state name.
    State,
}

/// One recorded signal: its changes over time.
#[derive(Clone, Debug)]
pub struct Column {
    /// Its name.
    pub name: String,
    /// How it is drawn.
    pub kind: ColKind,
    /// (time, value) at each change, the first at 0.
    pub changes: Vec<(u32, Val)>,
}

/// What a run produced.
#[derive(Clone, Debug)]
pub struct Run {
    /// Inputs, outputs, group states, member states.
    pub columns: Vec<Column>,
    /// Last simulated time.
    pub until: u32,
    /// Failed expectations.
    pub failures: usize,
    /// Checked expectations.
    pub checked: usize,
    /// Step notes by time (for the diagram).
    pub notes: Vec<(u32, String)>,
}

fn bits(k: safelogic::base::block::Kind) -> ColKind {
    use safelogic::base::block::Kind;
    match k {
        Kind::Bool => ColKind::Bool,
        Kind::U8 => ColKind::Int(8),
        Kind::U16 | Kind::I16 => ColKind::Int(16),
        Kind::U32 | Kind::I32 => ColKind::Int(32),
    }
}

/// The values of every column now.
fn sample(p: &Project, rt: &Runtime, out: &mut Vec<Val>) {
    out.clear();
    for s in p.inputs.iter().chain(&p.outputs) {
        out.push(Val::N(rt.read(&s.places[0])));
    }
    for (gi, g) in p.groups.iter().enumerate() {
        out.push(Val::S(rt.group_state(gi)));
        for mi in 0..g.members.len() {
            out.push(Val::S(rt.member_state(gi, mi)));
        }
    }
}

/// Runs `sc` on `p`. Writes the readable timeline (or, with `trace`, one line per cycle)
/// to `w`; progress to stderr on long runs.
pub fn run(p: &Project, sc: &Scenario, trace: bool, w: &mut dyn Write) -> Result<Run, String> {
    let mut rt = Runtime::load(p)?;
    let mut columns: Vec<Column> = Vec::new();
    for s in &p.inputs {
        columns.push(Column {
            name: s.name.clone(),
            kind: bits(s.kind),
            changes: Vec::new(),
        });
    }
    for s in &p.outputs {
        columns.push(Column {
            name: s.name.clone(),
            kind: bits(s.kind),
            changes: Vec::new(),
        });
    }
    for g in &p.groups {
        columns.push(Column {
            name: format!("{}.state", g.name),
            kind: ColKind::State,
            changes: Vec::new(),
        });
        for m in &g.members {
            columns.push(Column {
                name: format!("{}.state", m.name),
                kind: ColKind::State,
                changes: Vec::new(),
            });
        }
    }
    let n_in = p.inputs.len();
    let n_out = p.outputs.len();
    let io = |e: std::io::Error| e.to_string();
    if !trace {
        writeln!(
            w,
            "scenario \"{}\" on project \"{}\" (CRC 0x{:08X}, task cycle {} ms)",
            sc.name, p.name, p.crc, p.cycle_ms
        )
        .map_err(io)?;
    }
    let mut now = Vec::new();
    let mut step = 0usize;
    let mut failures = 0usize;
    let mut checked = 0usize;
    let cycles = u64::from(sc.until / p.cycle_ms) + 1;
    let long = cycles > 200_000;
    let mut t: u32 = 0;
    loop {
        let mut notes = Vec::new();
        let mut checks = Vec::new();
        while step < sc.steps.len() && sc.steps[step].at == t {
            let s = &sc.steps[step];
            for &(i, v) in &s.sets {
                for place in &p.inputs[i].places {
                    rt.write(place, v);
                }
            }
            checks.extend(s.expects.iter());
            notes.extend(s.note.iter().cloned());
            step += 1;
        }
        rt.cycle(t);
        sample(p, &rt, &mut now);
        let mut changed = Vec::new();
        for (c, v) in columns.iter_mut().zip(&now) {
            if c.changes.last().map(|(_, last)| last) != Some(v) {
                c.changes.push((t, v.clone()));
                changed.push(true);
            } else {
                changed.push(false);
            }
        }
        if trace {
            let part = |r: std::ops::Range<usize>| -> String {
                columns[r.clone()]
                    .iter()
                    .zip(&now[r])
                    .map(|(c, v)| format!("{}={v}", c.name.trim_end_matches(".state")))
                    .collect::<Vec<_>>()
                    .join(" ")
            };
            writeln!(
                w,
                "{t} | {} | {} | {}",
                part(0..n_in),
                part(n_in..n_in + n_out),
                part(n_in + n_out..columns.len())
            )
            .map_err(io)?;
        } else if changed.iter().any(|&c| c) || !checks.is_empty() || !notes.is_empty() {
            let part = |r: std::ops::Range<usize>| -> String {
                columns[r.clone()]
                    .iter()
                    .zip(&now[r.clone()])
                    .zip(&changed[r])
                    .filter(|(_, c)| **c)
                    .map(|((c, v), _)| format!("{}={v}", c.name.trim_end_matches(".state")))
                    .collect::<Vec<_>>()
                    .join(" ")
            };
            let mut line = format!("{t:>8} ms");
            for (label, r) in [
                ("in", 0..n_in),
                ("out", n_in..n_in + n_out),
                ("state", n_in + n_out..columns.len()),
            ] {
                let s = part(r);
                if !s.is_empty() {
                    line += &format!("  {label}: {s}");
                }
            }
            for n in &notes {
                line += &format!("  # {n}");
            }
            writeln!(w, "{line}").map_err(io)?;
        }
        for e in checks {
            checked += 1;
            let got = match &e.probe {
                Probe::Output(i) => Val::N(rt.read(&p.outputs[*i].places[0])),
                Probe::Place(pl) => Val::N(rt.read(pl)),
                Probe::MemberState(g, m) => Val::S(rt.member_state(*g, *m)),
                Probe::GroupState(g) => Val::S(rt.group_state(*g)),
            };
            if got != e.want {
                failures += 1;
                if trace {
                    continue;
                }
                writeln!(
                    w,
                    "{:>11}  FAIL {} = {got}, expected {} ({})",
                    "", e.label, e.want, e.at
                )
                .map_err(io)?;
            } else if !trace {
                writeln!(w, "{:>11}  ok   {} = {got}", "", e.label).map_err(io)?;
            }
        }
        let done = u64::from(t / p.cycle_ms) + 1;
        if long && done % (cycles / 10).max(1) == 0 {
            eprintln!(
                "sim: {}% ({done} of {cycles} cycles, t = {t} ms)",
                done * 100 / cycles
            );
        }
        if t >= sc.until {
            break;
        }
        t += p.cycle_ms;
    }
    if !trace {
        writeln!(
            w,
            "{checked} expectations: {} passed, {failures} failed",
            checked - failures
        )
        .map_err(io)?;
    }
    let notes = sc
        .steps
        .iter()
        .filter_map(|s| s.note.clone().map(|n| (s.at, n)))
        .collect();
    Ok(Run {
        columns,
        until: sc.until,
        failures,
        checked,
        notes,
    })
}
