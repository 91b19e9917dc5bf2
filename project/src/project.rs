//! The project file: parsing (serde + toml, every value with its span), checking against the
//! registry's field tables, and the project CRC. Nothing here knows a particular block:
//! types, fields, directions and IEC types come from `safelogic::registry`, the
//! wInputActive / wInputNegated bits from `safelogic::any::input_bit`.

use crate::error::{Error, Source};
use crate::plc::{Plc, RawPlc};
use safelogic::any::{in_range, input_bit, AnyBlock};
use safelogic::group::link_kind;
use safelogic::registry::{block_type_named, BlockType, Dir, Field, Kind, BLOCKS};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::{Spanned, Value};

type Table = BTreeMap<Spanned<String>, Spanned<Value>>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    project: RawHeader,
    #[serde(default)]
    group: Vec<RawGroup>,
    #[serde(default)]
    inputs: Table,
    #[serde(default)]
    outputs: BTreeMap<Spanned<String>, Spanned<String>>,
    plc: Option<RawPlc>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHeader {
    name: String,
    cycle: Option<Spanned<String>>,
    crc: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGroup {
    name: Spanned<String>,
    #[serde(default)]
    connections: bool,
    #[serde(default)]
    member: Vec<Spanned<Table>>,
    #[serde(default)]
    links: Vec<Spanned<String>>,
}

/// The group's own fields a project can name (`<group>.bErrAck`, `<group>.bFbErr`, …).
pub const GROUP_INPUTS: &[&str] = &[
    "bRun",
    "bErrAck",
    "bModuleFault",
    "bComErrIn",
    "bComStartupIn",
];
/// The group's outputs and info a project can read.
pub const GROUP_OUTPUTS: &[&str] = &[
    "bComErr",
    "bFbErr",
    "bOtherErr",
    "bComStartup",
    "bFbRun",
    "bInRun",
    "nState",
    "nDiag",
];

/// A named place in the project: a member's field or a group's own field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// Field `field` of member `member` of group `group`.
    Member {
        /// Group index.
        group: usize,
        /// Member index in the group (execution order).
        member: usize,
        /// The field.
        field: &'static Field,
    },
    /// A field of group `group` itself (one of [`GROUP_INPUTS`] / [`GROUP_OUTPUTS`]).
    Group {
        /// Group index.
        group: usize,
        /// Field name.
        field: &'static str,
    },
}

impl Place {
    /// The IEC type carried.
    pub fn kind(&self) -> Kind {
        match self {
            Place::Member { field, .. } => field.kind,
            Place::Group { field, .. } if *field == "nState" => Kind::U8,
            Place::Group { field, .. } if *field == "nDiag" => Kind::U16,
            Place::Group { .. } => Kind::Bool,
        }
    }
}

/// Where a name is written in the project file (1-based line and column), for errors
/// found after loading (`export-st`'s dialect checks).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pos {
    /// 1-based line.
    pub line: usize,
    /// 1-based column in characters.
    pub col: usize,
}

/// One member: its name, type and the values written before `init` (parameters, and
/// inputs with a constant value), in field-table order.
#[derive(Clone, Debug)]
pub struct Member {
    /// Unique name in the project.
    pub name: String,
    /// Where its name is written.
    pub pos: Pos,
    /// Its registered type.
    pub block: &'static BlockType,
    /// (field, value) written before init.
    pub values: Vec<(&'static Field, i64)>,
}

/// A link inside one group: output `src_field` of member `src` to input `dst_field` of
/// member `dst`.
#[derive(Clone, Copy, Debug)]
pub struct Link {
    /// Source member index.
    pub src: usize,
    /// Source output.
    pub src_field: &'static Field,
    /// Destination member index.
    pub dst: usize,
    /// Destination input.
    pub dst_field: &'static Field,
}

/// One group.
#[derive(Clone, Debug)]
pub struct Group {
    /// Unique name in the project.
    pub name: String,
    /// Where its name is written.
    pub pos: Pos,
    /// bConnections.
    pub connections: bool,
    /// Members in execution order.
    pub members: Vec<Member>,
    /// Links in file order.
    pub links: Vec<Link>,
}

/// A named process-image signal: an input the host writes (to one or more places) or an
/// output it reads (from one place).
#[derive(Clone, Debug)]
pub struct Signal {
    /// Its name.
    pub name: String,
    /// Where its name is written.
    pub pos: Pos,
    /// Where it goes (inputs) or comes from (outputs: exactly one).
    pub places: Vec<Place>,
    /// Its IEC type.
    pub kind: Kind,
}

/// A checked project.
#[derive(Clone, Debug)]
pub struct Project {
    /// The file as given (for errors found after loading).
    pub file: String,
    /// The project's name.
    pub name: String,
    /// Task cycle in ms.
    pub cycle_ms: u32,
    /// The groups, in execution order.
    pub groups: Vec<Group>,
    /// Process-image inputs, in file order.
    pub inputs: Vec<Signal>,
    /// Process-image outputs, in file order.
    pub outputs: Vec<Signal>,
    /// The PLC table: process-image locations and diagnostics (`[plc]`, for `export-st`).
    pub plc: Plc,
    /// CRC-32 of the canonical content ([`Project::canonical`]).
    pub crc: u32,
}

/// A time value "100 ms", "2 s", "1 min" in ms.
pub fn parse_time(s: &str) -> Option<u32> {
    let s = s.trim();
    let split = s.find(|c: char| !c.is_ascii_digit())?;
    let (num, unit) = s.split_at(split);
    let n: u64 = num.parse().ok()?;
    let factor = match unit.trim() {
        "ms" => 1,
        "s" => 1000,
        "min" => 60_000,
        _ => return None,
    };
    u32::try_from(n.checked_mul(factor)?).ok()
}

fn is_time(f: &Field) -> bool {
    f.name.starts_with('t') && f.kind == Kind::U32
}

fn is_ident(s: &str) -> bool {
    let mut c = s.chars();
    c.next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && c.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

fn type_name(v: &Value) -> &'static str {
    match v {
        Value::String(_) => "a string",
        Value::Integer(_) => "an integer",
        Value::Float(_) => "a float",
        Value::Boolean(_) => "a boolean",
        Value::Datetime(_) => "a date",
        Value::Array(_) => "an array",
        Value::Table(_) => "a table",
    }
}

/// The IEC type's name in messages.
pub fn kind_name(k: Kind) -> &'static str {
    match k {
        Kind::Bool => "BOOL",
        Kind::U8 => "BYTE",
        Kind::U16 => "UINT/WORD",
        Kind::I16 => "INT",
        Kind::U32 => "UDINT/DWORD",
        Kind::I32 => "DINT",
    }
}

/// Names close to `name` (same start or containing it, case-insensitive), for "did you
/// mean" hints.
fn near<'a>(name: &str, all: impl Iterator<Item = &'a str>) -> String {
    let low = name.to_ascii_lowercase();
    let cands: Vec<&str> = all
        .filter(|c| {
            let c = c.to_ascii_lowercase();
            c.starts_with(low.get(..3).unwrap_or(&low)) || c.contains(&low) || low.contains(&c)
        })
        .take(8)
        .collect();
    if cands.is_empty() {
        String::new()
    } else {
        format!(" (did you mean {}?)", cands.join(", "))
    }
}

/// A value for field `f` from the file.
fn field_value(src: &Source, f: &Field, v: &Spanned<Value>, block: &str) -> Result<i64, Error> {
    typed_value(src, f.kind, is_time(f), v, &format!("{block}.{}", f.name))
}

/// A value of IEC type `kind` (a time in ms when `time`) for `what` (the key or field it
/// is given for, named in every message): the project file's parameters and inputs and the
/// scenario's sets and expectations use the same rules and the same words.
pub fn typed_value(
    src: &Source,
    kind: Kind,
    time: bool,
    v: &Spanned<Value>,
    what: &str,
) -> Result<i64, Error> {
    let at = v.span();
    let n = match (v.get_ref(), kind) {
        (Value::Boolean(b), Kind::Bool) => i64::from(*b),
        (Value::String(s), _) if time => i64::from(parse_time(s).ok_or_else(|| {
            src.error(
                at.clone(),
                format!("{what}: `{s}` is not a time; expected a whole number with a unit, like \"100 ms\", \"2 s\""),
            )
        })?),
        (Value::Integer(i), k) if k != Kind::Bool && !time => *i,
        (other, k) => {
            let expected = if time {
                "a time like \"100 ms\"".to_string()
            } else if k == Kind::Bool {
                "true or false".to_string()
            } else {
                format!("an integer ({})", kind_name(k))
            };
            return Err(src.error(
                at,
                format!("{what}: wrong value type: {} given, expected {expected}", type_name(other)),
            ));
        }
    };
    if !in_range(kind, n) {
        return Err(src.error(
            at,
            format!("{what}: {n} is out of range for {}", kind_name(kind)),
        ));
    }
    Ok(n)
}

/// The most members (and links) of one group: the C API counts them in a UINT
/// (`sl_group_init`), so `sim` and `export-c` could not build more.
pub const GROUP_MAX: usize = u16::MAX as usize;

/// A list of input names given for `active` / `negated`, as a bit mask.
fn input_mask(
    src: &Source,
    block: &BlockType,
    key: &str,
    v: &Spanned<Value>,
) -> Result<i64, Error> {
    let Value::Array(items) = v.get_ref() else {
        return Err(src.error(
            v.span(),
            format!(
                "{key}: wrong value type: {} given, expected a list of input names like [\"bEStopIn1\"]",
                type_name(v.get_ref())
            ),
        ));
    };
    let mut mask = 0i64;
    for item in items {
        let name = item.as_str().unwrap_or("");
        let bit = input_bit(block.info.name, name).ok_or_else(|| {
            let with_bits = block
                .fields
                .iter()
                .filter(|f| input_bit(block.info.name, f.name).is_some())
                .map(|f| f.name)
                .collect::<Vec<_>>()
                .join(", ");
            src.error(
                v.span(),
                format!("{key}: `{name}` is not an input of {} with an active/negated bit; expected one of {with_bits}", block.info.name),
            )
        })?;
        mask |= 1 << bit;
    }
    Ok(mask)
}

/// What a reference names: a source (an output or info field) or a destination (an input).
#[derive(Clone, Copy)]
enum Role {
    Output,
    Input,
}

impl Role {
    fn noun(self) -> &'static str {
        match self {
            Role::Output => "output",
            Role::Input => "input",
        }
    }

    fn fits(self, d: Dir) -> bool {
        match self {
            Role::Output => matches!(d, Dir::Output | Dir::Info),
            Role::Input => d == Dir::Input,
        }
    }
}

struct Names {
    /// (group, member) by member name; groups by name.
    members: BTreeMap<String, (usize, usize)>,
    groups: BTreeMap<String, usize>,
}

impl Project {
    /// Parses and checks a project file. `file` names it in errors.
    pub fn parse(file: &str, text: &str) -> Result<Project, Error> {
        let src = Source { file, text };
        let raw: RawFile = toml::from_str(text).map_err(|e| src.toml_error(&e))?;
        let cycle_ms = match &raw.project.cycle {
            None => 10,
            Some(c) => parse_time(c.get_ref()).filter(|&t| t > 0).ok_or_else(|| {
                src.error(c.span(), format!("project.cycle: `{}` is not a time; expected a whole number of ms above 0 with a unit, like \"10 ms\"", c.get_ref()))
            })?,
        };
        let expected_crc = match &raw.project.crc {
            None => None,
            Some(c) => Some(
                u32::from_str_radix(c.get_ref().trim_start_matches("0x"), 16).map_err(|_| {
                    src.error(c.span(), format!("project.crc: `{}` is not a CRC; expected 8 hex digits like \"0x1A2B3C4D\"", c.get_ref()))
                })?,
            ),
        };

        // Names: groups and members share one namespace.
        let mut names = Names {
            members: BTreeMap::new(),
            groups: BTreeMap::new(),
        };
        let mut seen: BTreeMap<String, ()> = BTreeMap::new();
        let mut claim = |n: &Spanned<String>| -> Result<(), Error> {
            if !is_ident(n.get_ref()) {
                return Err(src.error(n.span(), format!("`{}` is not a name; expected letters, digits and _ (starting with a letter)", n.get_ref())));
            }
            if seen.insert(n.get_ref().clone(), ()).is_some() {
                return Err(src.error(
                    n.span(),
                    format!(
                        "duplicate name `{}`: groups and members need unique names",
                        n.get_ref()
                    ),
                ));
            }
            Ok(())
        };
        let mut groups = Vec::new();
        for (gi, rg) in raw.group.iter().enumerate() {
            claim(&rg.name)?;
            names.groups.insert(rg.name.get_ref().clone(), gi);
            let mut members = Vec::new();
            for rm in &rg.member {
                let (mut m, spans) = parse_member(&src, rm)?;
                if members.len() == GROUP_MAX {
                    return Err(src.error(rm.span(), format!("group `{}`: member `{}` is one too many: at most {GROUP_MAX} members per group (the C API counts them in a UINT)", rg.name.get_ref(), m.name)));
                }
                let name_v = rm
                    .get_ref()
                    .iter()
                    .find(|(k, _)| k.get_ref() == "name")
                    .map(|(_, v)| v);
                let span = name_v.map_or(rm.span(), Spanned::span);
                m.pos = src.pos(span.clone());
                claim(&Spanned::new(span, m.name.clone()))?;
                members.push((m, rm.span(), spans));
            }
            groups.push((rg, members));
        }
        for (gi, (_, members)) in groups.iter().enumerate() {
            for (mi, (m, ..)) in members.iter().enumerate() {
                names.members.insert(m.name.clone(), (gi, mi));
            }
        }
        let member_of = |gi: usize, mi: usize| -> &Member { &groups[gi].1[mi].0 };

        // A "member.field" or "group.field" reference; `role` says what is looked for, so
        // that a misspelled name gets hints of that direction.
        let resolve = |s: &str, span: Range<usize>, role: Role| -> Result<Place, Error> {
            let Some((owner, field)) = s.split_once('.') else {
                return Err(src.error(
                    span,
                    format!(
                        "`{s}` is not a signal; expected <member>.<field> like \"estop.bEStopIn1\""
                    ),
                ));
            };
            if let Some(&(gi, mi)) = names.members.get(owner) {
                let b = member_of(gi, mi).block;
                let f = b.field(field).ok_or_else(|| {
                    src.error(
                        span.clone(),
                        format!(
                            "unknown {} `{field}` of {} `{owner}`{}",
                            role.noun(),
                            b.info.name,
                            near(
                                field,
                                b.fields.iter().filter(|f| role.fits(f.dir)).map(|f| f.name)
                            )
                        ),
                    )
                })?;
                return Ok(Place::Member {
                    group: gi,
                    member: mi,
                    field: f,
                });
            }
            if let Some(&gi) = names.groups.get(owner) {
                let f = GROUP_INPUTS
                    .iter()
                    .chain(GROUP_OUTPUTS)
                    .find(|n| **n == field)
                    .ok_or_else(|| {
                        src.error(
                            span.clone(),
                            format!(
                                "unknown field `{field}` of group `{owner}`; expected one of {}",
                                GROUP_INPUTS
                                    .iter()
                                    .chain(GROUP_OUTPUTS)
                                    .copied()
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            ),
                        )
                    })?;
                return Ok(Place::Group {
                    group: gi,
                    field: f,
                });
            }
            Err(src.error(
                span,
                format!(
                    "unknown member or group `{owner}`{}",
                    near(
                        owner,
                        names
                            .members
                            .keys()
                            .chain(names.groups.keys())
                            .map(String::as_str)
                    )
                ),
            ))
        };

        // Links, group by group; every input is driven once (a link, a process-image
        // input, or a constant in the member table).
        let mut driven: BTreeMap<(usize, usize, u16), String> = BTreeMap::new();
        for (gi, (_, members)) in groups.iter().enumerate() {
            for (mi, (m, ..)) in members.iter().enumerate() {
                for (f, _) in &m.values {
                    if f.dir == Dir::Input {
                        driven.insert(
                            (gi, mi, f.offset),
                            format!("the constant in member `{}`", m.name),
                        );
                    }
                }
            }
        }
        let mut out_groups = Vec::new();
        for (gi, (rg, members)) in groups.iter().enumerate() {
            let mut links = Vec::new();
            for l in &rg.links {
                let span = l.span();
                if links.len() == GROUP_MAX {
                    return Err(src.error(span, format!("group `{}`: link `{}` is one too many: at most {GROUP_MAX} links per group (the C API counts them in a UINT)", rg.name.get_ref(), l.get_ref())));
                }
                let Some((a, b)) = l.get_ref().split_once("->") else {
                    return Err(src.error(span, format!("`{}` is not a link; expected \"<member>.<output> -> <member>.<input>\"", l.get_ref())));
                };
                let (a, b) = (a.trim(), b.trim());
                let pa = resolve(a, span.clone(), Role::Output)?;
                let pb = resolve(b, span.clone(), Role::Input)?;
                let (
                    Place::Member {
                        group: ga,
                        member: sa,
                        field: fa,
                    },
                    Place::Member {
                        group: gb,
                        member: db,
                        field: fb,
                    },
                ) = (pa, pb)
                else {
                    return Err(src.error(span, format!("link `{}`: a link connects two members; group fields are process-image signals (use [inputs] / [outputs])", l.get_ref())));
                };
                if ga != gi || gb != gi {
                    return Err(src.error(
                        span,
                        format!(
                            "link `{}`: both members must be in group `{}`",
                            l.get_ref(),
                            rg.name.get_ref()
                        ),
                    ));
                }
                if fa.dir != Dir::Output {
                    return Err(src.error(
                        span,
                        format!(
                            "link source `{a}` is not an output; expected a VAR_OUTPUT of {}",
                            member_of(ga, sa).block.info.name
                        ),
                    ));
                }
                if fb.dir != Dir::Input {
                    return Err(src.error(
                        span,
                        format!(
                            "link destination `{b}` is not an input; expected a VAR_INPUT of {}",
                            member_of(gb, db).block.info.name
                        ),
                    ));
                }
                if fa.kind != fb.kind || link_kind(fa.kind).is_none() {
                    return Err(src.error(span, format!("link between different types: `{a}` is {}, `{b}` is {}; expected the same type on both ends", kind_name(fa.kind), kind_name(fb.kind))));
                }
                if let Some(by) =
                    driven.insert((gi, db, fb.offset), format!("link `{}`", l.get_ref()))
                {
                    return Err(src.error(
                        span,
                        format!("input `{b}` is linked twice: already driven by {by}"),
                    ));
                }
                links.push(Link {
                    src: sa,
                    src_field: fa,
                    dst: db,
                    dst_field: fb,
                });
            }
            out_groups.push(Group {
                name: rg.name.get_ref().clone(),
                pos: src.pos(rg.name.span()),
                connections: rg.connections,
                members: members.iter().map(|(m, ..)| m.clone()).collect(),
                links,
            });
        }

        // Process image, in file order.
        let mut signal_names: BTreeMap<String, ()> = BTreeMap::new();
        let mut inputs = Vec::new();
        let mut raw_inputs: Vec<_> = raw.inputs.iter().collect();
        raw_inputs.sort_by_key(|(k, _)| k.span().start);
        for (k, v) in raw_inputs {
            if !is_ident(k.get_ref()) || signal_names.insert(k.get_ref().clone(), ()).is_some() {
                return Err(src.error(
                    k.span(),
                    format!("duplicate or invalid signal name `{}`", k.get_ref()),
                ));
            }
            let targets: Vec<(&str, Range<usize>)> = match v.get_ref() {
                Value::String(s) => vec![(s.as_str(), v.span())],
                Value::Array(a) if !a.is_empty() && a.iter().all(Value::is_str) => {
                    a.iter().map(|s| (s.as_str().unwrap_or(""), v.span())).collect()
                }
                other => return Err(src.error(v.span(), format!("input `{}`: wrong value type: {} given, expected \"<member>.<input>\" or a list of them", k.get_ref(), type_name(other)))),
            };
            let mut places = Vec::new();
            for (t, span) in targets {
                let p = resolve(t, span.clone(), Role::Input)?;
                let ok = match p {
                    Place::Member { field, .. } => field.dir == Dir::Input,
                    Place::Group { field, .. } => GROUP_INPUTS.contains(&field),
                };
                if !ok {
                    return Err(src.error(span, format!("input `{}`: `{t}` is not an input the host can write; expected a member's VAR_INPUT or a group's {}", k.get_ref(), GROUP_INPUTS.join("/"))));
                }
                if let Place::Member {
                    group,
                    member,
                    field,
                } = p
                {
                    if let Some(by) = driven.insert(
                        (group, member, field.offset),
                        format!("input `{}`", k.get_ref()),
                    ) {
                        return Err(src.error(
                            span,
                            format!("input `{t}` is linked twice: already driven by {by}"),
                        ));
                    }
                }
                if let Some(first) = places.first().map(Place::kind) {
                    if first != p.kind() {
                        return Err(src.error(
                            span,
                            format!(
                                "input `{}` drives places of different types; expected one type",
                                k.get_ref()
                            ),
                        ));
                    }
                }
                places.push(p);
            }
            let kind = places[0].kind();
            inputs.push(Signal {
                name: k.get_ref().clone(),
                pos: src.pos(k.span()),
                places,
                kind,
            });
        }
        let mut outputs = Vec::new();
        let mut raw_outputs: Vec<_> = raw.outputs.iter().collect();
        raw_outputs.sort_by_key(|(k, _)| k.span().start);
        for (k, v) in raw_outputs {
            if !is_ident(k.get_ref()) || signal_names.insert(k.get_ref().clone(), ()).is_some() {
                return Err(src.error(
                    k.span(),
                    format!(
                        "duplicate name `{}`: every process-image signal needs a unique name",
                        k.get_ref()
                    ),
                ));
            }
            let p = resolve(v.get_ref(), v.span(), Role::Output)?;
            let ok = match p {
                Place::Member { field, .. } => matches!(field.dir, Dir::Output | Dir::Info),
                Place::Group { field, .. } => GROUP_OUTPUTS.contains(&field),
            };
            if !ok {
                return Err(src.error(v.span(), format!("output `{}`: `{}` is not an output; expected a member's VAR_OUTPUT / info field or a group's {}", k.get_ref(), v.get_ref(), GROUP_OUTPUTS.join("/"))));
            }
            outputs.push(Signal {
                name: k.get_ref().clone(),
                pos: src.pos(k.span()),
                places: vec![p],
                kind: p.kind(),
            });
        }

        let plc = match &raw.plc {
            Some(rp) => Plc::parse(&src, rp, &inputs, &outputs)?,
            None => Plc::default(),
        };
        let mut project = Project {
            file: file.to_string(),
            name: raw.project.name.clone(),
            cycle_ms,
            groups: out_groups,
            inputs,
            outputs,
            plc,
            crc: 0,
        };
        // Every member's parameters through its own init (limits the types cannot say).
        for (gi, g) in project.groups.iter().enumerate() {
            for (mi, m) in g.members.iter().enumerate() {
                if let Err(msg) = m.build() {
                    let (_, member_span, spans) = &groups[gi].1[mi];
                    let at = |f: &Field| spans.get(&f.offset).unwrap_or(member_span).clone();
                    // The library's reason (the field and the rule it breaks), at that
                    // field's line, with the interval the init accepts where one field alone
                    // is the cause.
                    return Err(match (m.reason(), m.refused_value()) {
                        (Some((Some(f), why)), Some((g, _, range))) if f == g => {
                            src.error(at(f), format!("member `{}`: {why}; {range}", m.name))
                        }
                        (Some((Some(f), why)), _) => {
                            src.error(at(f), format!("member `{}`: {why}", m.name))
                        }
                        (Some((None, why)), _) => {
                            src.error(member_span.clone(), format!("member `{}`: {why}", m.name))
                        }
                        (None, Some((f, given, range))) => {
                            src.error(at(f), format!("member `{}`: {given}; {range}", m.name))
                        }
                        (None, None) => {
                            src.error(member_span.clone(), format!("member `{}`: {msg}", m.name))
                        }
                    });
                }
            }
        }
        project.crc = crc32(&project.canonical());
        if let (Some(want), Some(c)) = (expected_crc, &raw.project.crc) {
            if want != project.crc {
                return Err(src.error(c.span(), format!("project CRC mismatch: the file states 0x{want:08X}, the project's content has 0x{:08X}; the project refuses to run (check the change, then update project.crc)", project.crc)));
            }
        }
        Ok(project)
    }

    /// The canonical content the CRC covers (docs/project.md): one line per item, times
    /// in ms, masks as numbers, parameters in field-table order, members in execution
    /// order, links and signals in file order; no comments, no formatting, no `crc`.
    pub fn canonical(&self) -> String {
        let mut s = format!("project {}\ncycle {}\n", self.name, self.cycle_ms);
        for g in &self.groups {
            s += &format!("group {} connections={}\n", g.name, u8::from(g.connections));
            for m in &g.members {
                s += &format!("member {} {}\n", m.name, m.block.info.name);
                for (f, v) in &m.values {
                    s += &format!("  {}={v}\n", f.name);
                }
            }
            for l in &g.links {
                s += &format!(
                    "link {}.{} -> {}.{}\n",
                    g.members[l.src].name,
                    l.src_field.name,
                    g.members[l.dst].name,
                    l.dst_field.name
                );
            }
        }
        for (dir, sigs) in [("input", &self.inputs), ("output", &self.outputs)] {
            for sig in sigs {
                let places: Vec<String> = sig.places.iter().map(|p| self.place_name(p)).collect();
                s += &format!("{dir} {} = {}\n", sig.name, places.join(", "));
            }
        }
        s += &self.plc.canonical(&self.inputs, &self.outputs);
        s
    }

    /// "member.field" / "group.field".
    pub fn place_name(&self, p: &Place) -> String {
        match p {
            Place::Member {
                group,
                member,
                field,
            } => {
                format!(
                    "{}.{}",
                    self.groups[*group].members[*member].name, field.name
                )
            }
            Place::Group { group, field } => format!("{}.{field}", self.groups[*group].name),
        }
    }

    /// The wiring as text (what `safelogic check` prints).
    pub fn describe(&self) -> String {
        let mut s = format!(
            "project \"{}\", task cycle {} ms\n",
            self.name, self.cycle_ms
        );
        for g in &self.groups {
            s += &format!(
                "group {}{}\n",
                g.name,
                if g.connections { " (connections)" } else { "" }
            );
            for (i, m) in g.members.iter().enumerate() {
                let vals: Vec<String> = m
                    .values
                    .iter()
                    .map(|(f, v)| {
                        if is_time(f) {
                            format!("{}={v} ms", f.name)
                        } else if f.name.starts_with('w') || f.name.starts_with("dw") {
                            format!("{}=0x{v:X}", f.name)
                        } else {
                            format!("{}={v}", f.name)
                        }
                    })
                    .collect();
                s += &format!(
                    "  {i:>2} {:<12} {:<18} {}\n",
                    m.name,
                    m.block.info.name,
                    vals.join(" ")
                );
            }
            for l in &g.links {
                s += &format!(
                    "     link {}.{} -> {}.{} ({})\n",
                    g.members[l.src].name,
                    l.src_field.name,
                    g.members[l.dst].name,
                    l.dst_field.name,
                    kind_name(l.src_field.kind)
                );
            }
        }
        for sig in &self.inputs {
            let places: Vec<String> = sig.places.iter().map(|p| self.place_name(p)).collect();
            s += &format!(
                "input  {:<14} -> {} ({})\n",
                sig.name,
                places.join(", "),
                kind_name(sig.kind)
            );
        }
        for sig in &self.outputs {
            s += &format!(
                "output {:<14} <- {} ({})\n",
                sig.name,
                self.place_name(&sig.places[0]),
                kind_name(sig.kind)
            );
        }
        s += &format!("project CRC 0x{:08X}\n", self.crc);
        s
    }
}

impl Member {
    /// A block of this member's type with its values written and `init` called.
    pub fn build(&self) -> Result<AnyBlock, String> {
        self.build_with(None)
    }

    /// [`Member::build`] with the value of one field replaced (`Some((field, value))`; a
    /// value the field's type cannot hold is refused like a refused init).
    fn build_with(&self, replace: Option<(&Field, i64)>) -> Result<AnyBlock, String> {
        let mut b = AnyBlock::new(self.block.info.tag).ok_or("unregistered type")?;
        for (f, v) in &self.values {
            let v = match replace {
                Some((r, x)) if r == *f => x,
                _ => *v,
            };
            b.set(f.name, v)
                .map_err(|_| format!("{} cannot be written", f.name))?;
        }
        let rc = b.init();
        if rc != safelogic::SL_OK {
            return Err(format!(
                "out-of-range parameter: {} refuses these parameters (init returned {}); see its parameter limits in the manual",
                self.block.info.name,
                safelogic::base::types::status_str(rc)
            ));
        }
        Ok(b)
    }
}

/// Where each value of a member is written (by field offset).
type Spans = BTreeMap<u16, Range<usize>>;

fn parse_member(src: &Source, t: &Spanned<Table>) -> Result<(Member, Spans), Error> {
    let get = |key: &str| {
        t.get_ref()
            .iter()
            .find(|(k, _)| k.get_ref() == key)
            .map(|(_, v)| v)
    };
    let name = match get("name") {
        Some(v) => v.get_ref().as_str().map(str::to_string).ok_or_else(|| {
            src.error(v.span(), "member name: wrong value type; expected a string")
        })?,
        None => return Err(src.error(t.span(), "member without `name`; expected name = \"...\"")),
    };
    let ty = get("type").ok_or_else(|| {
        src.error(
            t.span(),
            format!("member `{name}` has no `type`; expected type = \"ESTOP\", \"ADD_INT\", …"),
        )
    })?;
    let ty_name = ty.get_ref().as_str().ok_or_else(|| {
        src.error(
            ty.span(),
            "type: wrong value type; expected a string like \"ESTOP\"",
        )
    })?;
    let block = block_type_named(ty_name).ok_or_else(|| {
        src.error(
            ty.span(),
            format!(
                "unknown type `{ty_name}`; expected a block type of the registry{}",
                near(ty_name, BLOCKS.iter().map(|b| b.info.name))
            ),
        )
    })?;
    let mut values: BTreeMap<u16, (&'static Field, i64)> = BTreeMap::new();
    let mut spans = Spans::new();
    let mut entries: Vec<_> = t.get_ref().iter().collect();
    entries.sort_by_key(|(k, _)| k.span().start);
    for (k, v) in entries {
        let key = k.get_ref().as_str();
        match key {
            "name" | "type" => {}
            "active" | "negated" => {
                let field = if key == "active" {
                    "wInputActive"
                } else {
                    "wInputNegated"
                };
                let f = block.field(field).ok_or_else(|| {
                    src.error(k.span(), format!("{} has no {field}", block.info.name))
                })?;
                values.insert(f.offset, (f, input_mask(src, block, key, v)?));
                spans.insert(f.offset, v.span());
            }
            _ => {
                let f = block.field(key).ok_or_else(|| {
                    src.error(
                        k.span(),
                        format!(
                            "unknown field `{key}` of {}; expected a parameter or input{}",
                            block.info.name,
                            near(key, block.fields.iter().map(|f| f.name))
                        ),
                    )
                })?;
                match f.dir {
                    Dir::Param if matches!(key, "wInputActive" | "wInputNegated") => {
                        return Err(src.error(
                            k.span(),
                            format!(
                                "give {key} by input names: {} = [\"...\"]",
                                if key == "wInputActive" {
                                    "active"
                                } else {
                                    "negated"
                                }
                            ),
                        ));
                    }
                    Dir::Param | Dir::Input => {
                        values.insert(f.offset, (f, field_value(src, f, v, block.info.name)?));
                        spans.insert(f.offset, v.span());
                    }
                    _ => {
                        return Err(src.error(k.span(), format!("`{key}` is an output, info or group-driven field of {}; expected a parameter or an input", block.info.name)));
                    }
                }
            }
        }
    }
    // Field-table order (inputs, parameters).
    let mut values: Vec<_> = values.into_values().collect();
    values.sort_by_key(|(f, _)| block.fields.iter().position(|g| g == *f));
    Ok((
        Member {
            name,
            pos: Pos::default(),
            block,
            values,
        },
        spans,
    ))
}

impl Member {
    /// The library's reason for refusing the member's parameters (`sl_reason_text`'s
    /// sentence) and the field it names, when that is one field of the block.
    fn reason(&self) -> Option<(Option<&'static Field>, String)> {
        let mut b = AnyBlock::new(self.block.info.tag)?;
        for (f, v) in &self.values {
            b.set(f.name, *v).ok()?;
        }
        let r = b.refusal()?;
        let name = if r.hit.field.is_empty() {
            r.info.field
        } else {
            r.hit.field
        };
        Some((self.block.field(name), b.reason()))
    }

    /// Which value the block's init refuses, and what it would accept: the first parameter
    /// (in field-table order) whose value alone, set to its zero default, makes the init
    /// accept, with the interval of values around that default the init accepts with the
    /// other parameters as given (found by bisection, so an interval: every parameter
    /// limit of the manual is a bound or a relation to another parameter). `None` when no
    /// single parameter is the cause.
    /// Returns the field, "<field> = <value> is refused by <block>'s init" and the interval.
    fn refused_value(&self) -> Option<(&'static Field, String, String)> {
        let accepts = |f: &Field, v: i64| self.build_with(Some((f, v))).is_ok();
        let (f, given) = self
            .values
            .iter()
            .find(|(f, _)| matches!(f.dir, Dir::Param) && accepts(f, 0))
            .copied()?;
        let (min, max) = kind_bounds(f.kind);
        // The bound between an accepted value `ok` and a refused one `bad`: the last accepted.
        let edge = |mut ok: i64, mut bad: i64| {
            while (bad - ok).abs() > 1 {
                let mid = ok + (bad - ok) / 2;
                if accepts(f, mid) {
                    ok = mid;
                } else {
                    bad = mid;
                }
            }
            ok
        };
        let lo = if accepts(f, min) { min } else { edge(0, min) };
        let hi = if accepts(f, max) { max } else { edge(0, max) };
        let show = |v: i64| {
            if is_time(f) {
                format!("{v} ms")
            } else if f.name.starts_with('w') || f.name.starts_with("dw") {
                format!("0x{v:X}")
            } else {
                v.to_string()
            }
        };
        let name = self.block.info.name;
        // `active` / `negated` are written as input lists; the mask is what init sees.
        let label = match f.name {
            "wInputActive" => "active (wInputActive)".to_string(),
            "wInputNegated" => "negated (wInputNegated)".to_string(),
            n => format!("{name}.{n}"),
        };
        let range = if given < lo || given > hi {
            format!(
                "allowed with the other parameters as given: {} … {}",
                show(lo),
                show(hi)
            )
        } else {
            // Inside the interval around the default, yet refused: a rule the interval does
            // not describe (e.g. a bit pattern); say which value to change.
            "refused with the other parameters as given; 0 is accepted".to_string()
        };
        Some((
            f,
            format!("{label} = {} is refused by {name}'s init", show(given)),
            range,
        ))
    }
}

/// The smallest and largest value of an IEC type.
fn kind_bounds(k: Kind) -> (i64, i64) {
    match k {
        Kind::Bool => (0, 1),
        Kind::U8 => (0, i64::from(u8::MAX)),
        Kind::U16 => (0, i64::from(u16::MAX)),
        Kind::I16 => (i64::from(i16::MIN), i64::from(i16::MAX)),
        Kind::U32 => (0, i64::from(u32::MAX)),
        Kind::I32 => (i64::from(i32::MIN), i64::from(i32::MAX)),
    }
}

/// CRC-32 (ISO-HDLC, the zip / Ethernet CRC) of a text.
pub fn crc32(s: &str) -> u32 {
    crc::Crc::<u32>::new(&crc::CRC_32_ISO_HDLC).checksum(s.as_bytes())
}
