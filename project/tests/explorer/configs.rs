//! The configurations each block type is explored in: parameters from the field table
//! (time parameters small, so that their limits are a few milliseconds), the input mask,
//! and one variant per option bit or BOOL parameter the block's init accepts alone.

use super::{api, is_time, Config, Instance};
use safelogic::any::input_bit;
use safelogic::registry::{BlockType, Dir, Field, Kind};

/// At most this many BOOL inputs are driven besides bRun/bErrAck (2^10 combinations).
pub const MAX_DRIVEN_BOOLS: usize = 8;

/// Times a block needs above the default 2 / 3 ms (its manual's minimum).
const TIME_OVERRIDES: &[(&str, &str, i64)] = &[
    // "absolute minimum 100 ms"; TrailingMaximum above it.
    ("SF_ResetButton", "TrailingMinimum", 100),
    ("SF_ResetButton", "TrailingMaximum", 102),
];

/// Parameters a block family needs to be valid at all (by the name's prefix before `_`).
const PARAM_OVERRIDES: &[(&str, &str, i64)] = &[
    ("COMPARE", "nArchitecture", 2),
    ("SCALE", "nNumerator", 1),
    ("SCALE", "nDenominator", 1),
    ("LIMIT", "nMaximumValue", 10),
    ("COUNTER", "nCounterLimit", 3),
    ("SLI", "nLimitPos", 3),
    ("SLI", "nLimitNeg", 3),
    ("SLI2", "nLimitPos", 3),
    ("SLI2", "nLimitNeg", 3),
];

/// LOADSENSING's value table is no field of the field table (`table_params`): two rows of
/// the manual's Fig. 132 (X 0 and 5, non-negative so that every variant takes them), `aRow`
/// right after `dwOptions`, each row X, Y1, Y2, WY1, WY2 of the analog type. Each value is a
/// parameter to the explorer (a leaked `Field` per table cell), so the analog inputs also
/// take the table's values -1, =, +1.
fn loadsensing_table(ty: &BlockType) -> Vec<(&'static Field, i64)> {
    const ROWS: [[i64; 5]; 2] = [[0, 300, 400, 310, 390], [5, 400, 500, 410, 490]];
    const CELLS: [&str; 10] = [
        "aRow[0].nX",
        "aRow[0].nY1",
        "aRow[0].nY2",
        "aRow[0].nWY1",
        "aRow[0].nWY2",
        "aRow[1].nX",
        "aRow[1].nY1",
        "aRow[1].nY2",
        "aRow[1].nWY1",
        "aRow[1].nWY2",
    ];
    if !ty.info.name.starts_with("LOADSENSING") {
        return vec![];
    }
    let (Some(x), Some(opts), Some(rows)) = (
        ty.field("nAnalogInX"),
        ty.field("dwOptions"),
        ty.field("nRowCount"),
    ) else {
        panic!(
            "{}: the field table lacks nAnalogInX, dwOptions or nRowCount",
            ty.info.name
        )
    };
    let width = x.kind.size() as u16;
    let mut out = vec![(rows, 2)];
    for (i, v) in ROWS.iter().flatten().enumerate() {
        let cell: &'static Field = Box::leak(Box::new(Field {
            name: CELLS[i],
            offset: opts.offset + 4 + i as u16 * width,
            kind: x.kind,
            dir: Dir::Param,
        }));
        out.push((cell, *v));
    }
    out
}

/// A block's fixed times (not parameters), in ms.
fn fixed_limits(ty: &BlockType) -> Vec<u32> {
    match ty.info.name {
        // The PLCopen type III synchronism time: 500 ms.
        "SF_TwoHandControlTypeIII" => vec![500],
        _ => vec![],
    }
}

/// The inputs of a numbered family that a configuration activates (by its field order).
fn family_inputs(ty: &BlockType) -> usize {
    match ty.info.name {
        "TWOHAND" => 4,
        "XOR" => 2,
        "OPMODE" => 3,
        "MUTING" => 4,
        // Reset, CountUp and CountDown.
        n if n.starts_with("COUNTER_") => 3,
        _ => 2,
    }
}

/// The boundary values of an analog input: the type's extremes, 0, and each integer
/// parameter's value -1, =, +1 (the block's limits).
fn boundary_values(ty: &BlockType, f: &Field, params: &[(&'static Field, i64)]) -> Vec<i64> {
    let (min, max) = match f.kind {
        Kind::Bool => (0, 1),
        Kind::U8 => (0, 255),
        Kind::U16 => (0, i64::from(u16::MAX)),
        Kind::I16 => (i64::from(i16::MIN), i64::from(i16::MAX)),
        Kind::U32 => (0, i64::from(u32::MAX)),
        Kind::I32 => (i64::from(i32::MIN), i64::from(i32::MAX)),
    };
    let mut v = vec![min, max, 0];
    for (p, x) in params {
        if p.dir == Dir::Param
            && !is_time(p)
            && !p.name.starts_with('w')
            && !p.name.starts_with("dw")
        {
            v.extend([x - 1, *x, x + 1]);
        }
    }
    let _ = ty;
    v.retain(|x| (min..=max).contains(x));
    v.sort_unstable();
    v.dedup();
    v
}

/// `params` made acceptable to init: time parameters set to 0 one by one until init
/// accepts (a delay an option does not use must be 0), then each given back where init
/// still accepts it. `None` if even all times 0 are refused.
fn fit(
    ty: &'static BlockType,
    params: &[(&'static Field, i64)],
) -> Option<Vec<(&'static Field, i64)>> {
    let mut p = params.to_vec();
    let times: Vec<usize> = (0..p.len()).filter(|&i| is_time(p[i].0)).collect();
    let wanted: Vec<i64> = p.iter().map(|x| x.1).collect();
    for &i in &times {
        if init_ok(ty, &p) {
            break;
        }
        p[i].1 = 0;
    }
    if !init_ok(ty, &p) {
        return None;
    }
    for &i in &times {
        if p[i].1 == 0 {
            p[i].1 = wanted[i];
            if !init_ok(ty, &p) {
                p[i].1 = 0;
            }
        }
    }
    Some(p)
}

fn init_ok(ty: &'static BlockType, params: &[(&'static Field, i64)]) -> bool {
    let mut i = Instance::new(ty.size);
    for (f, v) in params {
        i.set(f, *v);
    }
    let p: *mut u8 = i.bytes_mut().as_mut_ptr();
    (api(ty.info.tag).init)(p) == 0
}

/// The configurations of a block type (the first is the base; the others each switch one
/// option on).
pub fn configs(ty: &'static BlockType) -> Vec<Config> {
    let mut params: Vec<(&'static Field, i64)> = Vec::new();
    let mut t = 2;
    for f in ty.fields.iter().filter(|f| f.dir == Dir::Param) {
        if let Some(&(_, _, v)) = TIME_OVERRIDES
            .iter()
            .find(|(b, n, _)| *b == ty.info.name && *n == f.name)
        {
            params.push((f, v));
        } else if is_time(f) {
            params.push((f, t));
            t = 3;
        } else if let Some(&(_, _, v)) = PARAM_OVERRIDES
            .iter()
            .find(|(fam, n, _)| ty.info.name.split('_').next() == Some(*fam) && *n == f.name)
        {
            params.push((f, v));
        } else if f.name == "nConnectionId" {
            // CONNECTION SHUTDOWN names a connection (0 is no connection).
            params.push((f, 1));
        }
    }
    params.extend(loadsensing_table(ty));
    // Which numbered inputs are active: the first few of the family.
    let mapped: Vec<(&'static Field, u8)> = ty
        .fields
        .iter()
        .filter(|f| f.dir == Dir::Input && f.kind == Kind::Bool)
        .filter_map(|f| input_bit(ty.info.name, f.name).map(|b| (f, b)))
        .collect();
    let mut bits: Vec<u8> = mapped.iter().map(|(_, b)| *b).collect();
    bits.sort_unstable();
    bits.dedup();
    bits.truncate(family_inputs(ty));
    let mask: u16 = bits.iter().fold(0, |m, b| m | 1 << b);
    let active = ty.field("wInputActive");
    let mut candidates = vec![mask];
    candidates.extend([0x3, 0x1, 0x7, 0xF, 0x1F, 0x3F, 0xFF, 0xFFFF, 0]);
    // The analog blocks' analog inputs are bits 8.. (ARITH_ACTIVE = 0x0300), their BOOL
    // inputs the low bits: with the family's BOOL inputs first, so that they are driven.
    for analog in [0x0100, 0x0300, 0x0700, 0x0F00, 0x1F00] {
        candidates.extend([analog | mask, analog, analog | 0x1, analog | 0x3]);
    }
    let mut base = None;
    for m in candidates {
        let mut p = params.clone();
        if let Some(a) = active {
            p.push((a, i64::from(m)));
        }
        if let Some(p) = fit(ty, &p) {
            base = Some((p, m));
            break;
        }
        if active.is_none() {
            break;
        }
    }
    let Some((base, mask)) = base else {
        return vec![];
    };
    let mut driven: Vec<(&'static Field, Vec<i64>)> = Vec::new();
    for f in ty
        .fields
        .iter()
        .filter(|f| matches!(f.dir, Dir::Input | Dir::Control))
    {
        if f.kind == Kind::Bool {
            if let Some(b) = input_bit(ty.info.name, f.name) {
                if active.is_some() && mask & (1 << b) == 0 {
                    continue;
                }
            }
            driven.push((f, vec![0, 1, 2]));
        } else {
            driven.push((f, boundary_values(ty, f, &base)));
        }
    }
    // SF_ModeSelector: modes 0..2 driven, modes 3..7 held FALSE (a mode input is one of
    // eight alike; three show every transition between modes, including two at once).
    driven.retain(|(f, _)| {
        !(ty.info.name == "SF_ModeSelector"
            && f.name.starts_with("S_Mode")
            && f.name[6..].parse::<u8>().is_ok_and(|m| m > 2))
    });
    assert!(
        driven.iter().filter(|(f, _)| f.kind == Kind::Bool).count() <= MAX_DRIVEN_BOOLS + 2,
        "{}: too many BOOL inputs to drive",
        ty.info.name
    );
    let mut out = vec![Config {
        label: "base".into(),
        params: base.clone(),
        driven: driven.clone(),
        fixed_limits: fixed_limits(ty),
    }];
    for f in ty.fields.iter().filter(|f| f.dir == Dir::Param) {
        let variants: Vec<(String, i64)> = match (f.name, f.kind) {
            ("dwOptions", _) => (0..16)
                .map(|b| (format!("dwOptions=0x{:X}", 1u32 << b), 1i64 << b))
                .collect(),
            (_, Kind::Bool) => vec![(format!("{}=TRUE", f.name), 1)],
            // The PLCopen v1.0 DiagCodes (profile 1) next to the v2.01 ones.
            ("nDiagProfile", _) => vec![("nDiagProfile=1".to_string(), 1)],
            _ => vec![],
        };
        for (label, v) in variants {
            let mut p = params.clone();
            p.extend(base.iter().filter(|(b, _)| !is_time(b)));
            p.push((f, v));
            if let Some(p) = fit(ty, &p) {
                out.push(Config {
                    label,
                    params: p,
                    driven: driven.clone(),
                    fixed_limits: fixed_limits(ty),
                });
            }
        }
    }
    out
}
