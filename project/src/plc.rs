//! The `[plc]` table of a project: where each process-image signal sits in a PLC's address
//! space (IEC 61131-3 direct addresses: `%IX0.0`, `%QW3`, `%MD0`), the optional program clock
//! and state words, the defaults for what the file does not state, and the Modbus TCP address
//! OpenPLC v3 serves each location at. `export-st` uses it; the simulation does not.

use crate::error::{Error, Source};
use crate::project::{kind_name, Pos, Project, Signal};
use safelogic::registry::Kind;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::fmt;
use toml::Spanned;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPlc {
    clock: Option<Spanned<String>>,
    states: Option<Spanned<String>>,
    start: Option<Spanned<String>>,
    #[serde(default)]
    locations: BTreeMap<Spanned<String>, Spanned<String>>,
}

/// The memory area of a direct address.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Area {
    /// `%I`: the input image.
    I,
    /// `%Q`: the output image.
    Q,
    /// `%M`: memory.
    M,
}

/// The size of a direct address.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Size {
    /// `X`: one bit (BOOL).
    X,
    /// `B`: 8 bits.
    B,
    /// `W`: 16 bits.
    W,
    /// `D`: 32 bits.
    D,
}

/// An IEC 61131-3 direct address such as `%IX0.1`, `%QW2`, `%MD0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Location {
    /// Its area.
    pub area: Area,
    /// Its size.
    pub size: Size,
    /// The index (for `X` the byte).
    pub index: u32,
    /// The bit within the byte (`X` only, 0..=7).
    pub bit: u8,
}

/// A place in OpenPLC's Modbus TCP server (0-based protocol addresses).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Modbus {
    /// "coil", "discrete input", "input register" or "holding register".
    pub table: &'static str,
    /// The first address.
    pub address: u32,
    /// Registers it takes (1 for bits and words, 2 for a 32-bit value: high word first).
    pub words: u32,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = match self.area {
            Area::I => 'I',
            Area::Q => 'Q',
            Area::M => 'M',
        };
        let s = match self.size {
            Size::X => 'X',
            Size::B => 'B',
            Size::W => 'W',
            Size::D => 'D',
        };
        if self.size == Size::X {
            write!(f, "%{a}{s}{}.{}", self.index, self.bit)
        } else {
            write!(f, "%{a}{s}{}", self.index)
        }
    }
}

/// The size that carries a value of `kind`.
pub fn size_of(kind: Kind) -> Size {
    match kind {
        Kind::Bool => Size::X,
        Kind::U8 => Size::B,
        Kind::U16 | Kind::I16 => Size::W,
        Kind::U32 | Kind::I32 => Size::D,
    }
}

impl Location {
    /// Parses `%<I|Q|M><X|B|W|D><n>[.<bit>]` (the bit for `X` only, 0-7).
    pub fn parse(s: &str) -> Option<Location> {
        let rest = s.strip_prefix('%')?;
        let mut c = rest.chars();
        let area = match c.next()? {
            'I' => Area::I,
            'Q' => Area::Q,
            'M' => Area::M,
            _ => return None,
        };
        let size = match c.next()? {
            'X' => Size::X,
            'B' => Size::B,
            'W' => Size::W,
            'D' => Size::D,
            _ => return None,
        };
        let num = c.as_str();
        let digits =
            |t: &str| !t.is_empty() && t.len() <= 9 && t.bytes().all(|b| b.is_ascii_digit());
        let (index, bit) = if size == Size::X {
            let (i, b) = num.split_once('.')?;
            if !digits(i) || !digits(b) {
                return None;
            }
            let bit: u8 = b.parse().ok().filter(|b| *b < 8)?;
            (i.parse().ok()?, bit)
        } else {
            if !digits(num) {
                return None;
            }
            (num.parse().ok()?, 0)
        };
        Some(Location {
            area,
            size,
            index,
            bit,
        })
    }

    /// Where OpenPLC v3's Modbus TCP server serves this location (its `modbus.cpp` and
    /// `glue_generator`), or `None` when it does not (`%IB`, `%QB`, `%MB`, `%ID`, `%QD`,
    /// `%MX`, and addresses beyond its tables).
    pub fn modbus(&self) -> Option<Modbus> {
        let (table, address, words, limit) = match (self.area, self.size) {
            (Area::Q, Size::X) => ("coil", self.index * 8 + u32::from(self.bit), 1, 8192),
            (Area::I, Size::X) => (
                "discrete input",
                self.index * 8 + u32::from(self.bit),
                1,
                8192,
            ),
            (Area::I, Size::W) => ("input register", self.index, 1, 1024),
            (Area::Q, Size::W) => ("holding register", self.index, 1, 1024),
            (Area::M, Size::W) => ("holding register", 1024 + self.index, 1, 2048),
            (Area::M, Size::D) => ("holding register", 2048 + 2 * self.index, 2, 4096),
            _ => return None,
        };
        (address + words <= limit).then_some(Modbus {
            table,
            address,
            words,
        })
    }
}

/// The `[plc]` table as stated in the file.
#[derive(Clone, Debug, Default)]
pub struct Plc {
    /// `clock`: the program time (ms, UDINT) of the next cycle: 0 until the first cycle ran,
    /// then n × cycle after n cycles.
    pub clock: Option<(Location, Pos)>,
    /// `start`: a BOOL the program waits for: its first cycle (setup, time 0) runs in the
    /// first scan that reads it TRUE.
    pub start: Option<(Location, Pos)>,
    /// `states`: the first of the state words (every group, then its members, in order).
    pub states: Option<(Location, Pos)>,
    /// `locations`, in file order: (input?, signal index, location, where it is written).
    pub stated: Vec<(bool, usize, Location, Pos)>,
}

/// Every signal's location, stated or by default.
#[derive(Clone, Debug)]
pub struct Layout {
    /// The process-image inputs, in the project's order.
    pub inputs: Vec<Location>,
    /// The process-image outputs, in the project's order.
    pub outputs: Vec<Location>,
    /// The program clock, if stated.
    pub clock: Option<Location>,
    /// The start input, if stated.
    pub start: Option<Location>,
    /// The state words: (label such as `safety.state` / `estop.state`, location), every group
    /// followed by its members.
    pub states: Vec<(String, Location)>,
}

impl Plc {
    pub(crate) fn parse(
        src: &Source,
        raw: &RawPlc,
        inputs: &[Signal],
        outputs: &[Signal],
    ) -> Result<Plc, Error> {
        let loc = |v: &Spanned<String>, what: &str| -> Result<Location, Error> {
            Location::parse(v.get_ref()).ok_or_else(|| {
                src.error(
                    v.span(),
                    format!("{what}: `{}` is not a direct address; expected %<I|Q|M><X|B|W|D><n> like \"%IX0.0\", \"%QW2\", \"%MD0\" (a bit 0-7 after X)", v.get_ref()),
                )
            })
        };
        let word = |v: &Option<Spanned<String>>,
                    what: &str,
                    size: Size|
         -> Result<Option<(Location, Pos)>, Error> {
            let Some(v) = v else { return Ok(None) };
            let l = loc(v, what)?;
            if l.size != size || (l.area == Area::I && size != Size::X) {
                let want = match size {
                    Size::D => "%MD or %QD (UDINT)",
                    Size::X => "%IX or %QX (BOOL)",
                    _ => "%MW or %QW (one UINT per state)",
                };
                return Err(src.error(
                    v.span(),
                    format!("plc.{what}: `{l}` cannot hold it; expected {want}"),
                ));
            }
            Ok(Some((l, src.pos(v.span()))))
        };
        let clock = word(&raw.clock, "clock", Size::D)?;
        let states = word(&raw.states, "states", Size::W)?;
        let start = word(&raw.start, "start", Size::X)?;
        let mut stated = Vec::new();
        let mut entries: Vec<_> = raw.locations.iter().collect();
        entries.sort_by_key(|(k, _)| k.span().start);
        for (k, v) in entries {
            let name = k.get_ref();
            let (is_input, i, sig) = if let Some(i) = inputs.iter().position(|s| s.name == *name) {
                (true, i, &inputs[i])
            } else if let Some(i) = outputs.iter().position(|s| s.name == *name) {
                (false, i, &outputs[i])
            } else {
                return Err(src.error(
                    k.span(),
                    format!(
                        "plc.locations: unknown signal `{name}`; expected one of {}",
                        inputs
                            .iter()
                            .chain(outputs)
                            .map(|s| s.name.as_str())
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                ));
            };
            let l = loc(v, &format!("plc.locations.{name}"))?;
            if l.size != size_of(sig.kind) {
                return Err(src.error(
                    v.span(),
                    format!(
                        "plc.locations.{name}: `{l}` does not fit a {} signal; expected a %{} address",
                        kind_name(sig.kind),
                        match size_of(sig.kind) {
                            Size::X => "IX/%QX (a bit)",
                            Size::B => "IB/%QB/%MB (8 bits)",
                            Size::W => "IW/%QW/%MW (16 bits)",
                            Size::D => "ID/%QD/%MD (32 bits)",
                        }
                    ),
                ));
            }
            if !is_input && l.area == Area::I {
                return Err(src.error(
                    v.span(),
                    format!("plc.locations.{name}: `{l}` is in the input image; an output goes to %Q or %M"),
                ));
            }
            stated.push((is_input, i, l, src.pos(v.span())));
        }
        Ok(Plc {
            clock,
            start,
            states,
            stated,
        })
    }

    /// The lines the project CRC covers (none when the file has no `[plc]` table).
    pub fn canonical(&self, inputs: &[Signal], outputs: &[Signal]) -> String {
        let mut s = String::new();
        if let Some((l, _)) = &self.clock {
            s += &format!("plc clock {l}\n");
        }
        if let Some((l, _)) = &self.states {
            s += &format!("plc states {l}\n");
        }
        if let Some((l, _)) = &self.start {
            s += &format!("plc start {l}\n");
        }
        for &(is_input, i, l, _) in &self.stated {
            let name = if is_input {
                &inputs[i].name
            } else {
                &outputs[i].name
            };
            s += &format!("plc location {name} = {l}\n");
        }
        s
    }
}

/// A stated or default location that another one already takes.
fn taken_error(p: &Project, pos: Pos, l: Location, by: &str) -> Error {
    Error {
        file: p.file.clone(),
        line: pos.line,
        col: pos.col,
        msg: format!("`{l}` is already taken by {by}; expected an address of its own"),
    }
}

/// Every signal's location: the stated ones, then the defaults in file order (BOOL inputs
/// `%IX0.0`, `%IX0.1`, …; BOOL outputs `%QX0.0`, …; 8/16/32-bit inputs `%IB`/`%IW`/`%ID`,
/// outputs `%QB`/`%QW`/`%QD`, each numbered from 0), skipping what is taken.
pub fn layout(p: &Project) -> Result<Layout, Error> {
    let mut taken: BTreeMap<Location, String> = BTreeMap::new();
    let mut inputs = vec![None; p.inputs.len()];
    let mut outputs = vec![None; p.outputs.len()];
    for &(is_input, i, l, pos) in &p.plc.stated {
        let name = if is_input {
            &p.inputs[i].name
        } else {
            &p.outputs[i].name
        };
        if let Some(by) = taken.insert(l, format!("signal `{name}`")) {
            return Err(taken_error(p, pos, l, &by));
        }
        if is_input {
            inputs[i] = Some(l);
        } else {
            outputs[i] = Some(l);
        }
    }
    let clock = match p.plc.clock {
        Some((l, pos)) => {
            if let Some(by) = taken.insert(l, "the clock".into()) {
                return Err(taken_error(p, pos, l, &by));
            }
            Some(l)
        }
        None => None,
    };
    let start = match p.plc.start {
        Some((l, pos)) => {
            if let Some(by) = taken.insert(l, "the start input".into()) {
                return Err(taken_error(p, pos, l, &by));
            }
            Some(l)
        }
        None => None,
    };
    let mut states = Vec::new();
    if let Some((first, pos)) = p.plc.states {
        let mut labels = Vec::new();
        for g in &p.groups {
            labels.push(format!("{}.state", g.name));
            labels.extend(g.members.iter().map(|m| format!("{}.state", m.name)));
        }
        for (k, label) in labels.into_iter().enumerate() {
            let l = Location {
                index: first.index + k as u32,
                ..first
            };
            if let Some(by) = taken.insert(l, format!("state word `{label}`")) {
                return Err(taken_error(p, pos, l, &by));
            }
            states.push((label, l));
        }
    }
    let mut next: BTreeMap<(Area, Size), u32> = BTreeMap::new();
    let mut fill = |slots: &mut Vec<Option<Location>>, sigs: &[Signal], area: Area| {
        for (slot, sig) in slots.iter_mut().zip(sigs) {
            if slot.is_some() {
                continue;
            }
            let size = size_of(sig.kind);
            let n = next.entry((area, size)).or_insert(0);
            loop {
                let l = if size == Size::X {
                    Location {
                        area,
                        size,
                        index: *n / 8,
                        bit: (*n % 8) as u8,
                    }
                } else {
                    Location {
                        area,
                        size,
                        index: *n,
                        bit: 0,
                    }
                };
                *n += 1;
                if let std::collections::btree_map::Entry::Vacant(e) = taken.entry(l) {
                    e.insert(format!("signal `{}`", sig.name));
                    *slot = Some(l);
                    break;
                }
            }
        }
    };
    fill(&mut inputs, &p.inputs, Area::I);
    fill(&mut outputs, &p.outputs, Area::Q);
    Ok(Layout {
        inputs: inputs.into_iter().flatten().collect(),
        outputs: outputs.into_iter().flatten().collect(),
        clock,
        start,
        states,
    })
}
