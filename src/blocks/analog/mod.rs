//! What every block with analog signals shares (ABI-2 §10, §12): the integer type of a
//! variant and the magic of its private header. The blocks themselves are generic over
//! [`Analog`]; their variants are type aliases (`FB_ADD_INT`, `FB_LIMIT_UDINT` …).

pub mod arith;
pub mod compare;
pub mod counter;
pub mod envelope;
pub mod limit;
pub mod loadsensing;
pub mod scale;
pub mod sli;
pub mod sli2;
pub mod speed;
pub mod violationcounter;
pub mod window;

use crate::base::block::{Dir, Field, FieldType};
use crate::base::header::SL_PRIVATE_HEADER;
use crate::base::layout::Zeroed;
use crate::base::types::{LIBRARY_DIAG_BITS, SL_STATE_ERROR, SL_STATE_RUN, SL_STATE_SAFE};

/// An integer type of the analog variants (ABI-2 §10.3).
pub trait Analog:
    FieldType + Zeroed + Copy + Default + PartialEq + core::fmt::Debug + 'static
{
    /// Index of the variant: 0 INT, 1 UINT, 2 DINT, 3 UDINT.
    const VARIANT: usize;
    /// Smallest value.
    const MIN: i128;
    /// Largest value.
    const MAX: i128;
    /// The exact value.
    fn wide(self) -> i128;
    /// The value of an `i128` known to lie in `MIN..=MAX`.
    fn narrow(v: i128) -> Self;
}

macro_rules! analog {
    ($($t:ty => $i:literal),*) => {$(
        impl Analog for $t {
            const VARIANT: usize = $i;
            const MIN: i128 = <$t>::MIN as i128;
            const MAX: i128 = <$t>::MAX as i128;
            #[inline(always)]
            fn wide(self) -> i128 {
                self as i128
            }
            #[inline(always)]
            fn narrow(v: i128) -> Self {
                v as $t
            }
        }
    )*};
}
analog!(i16 => 0, u16 => 1, i32 => 2, u32 => 3);

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/mod.rs"));

/// `v` as a value of `T`, or the diag value of the range error it makes (ABI-2 §12.1:
/// exact result, nothing wraps, nothing saturates): underflow below `T::MIN`, overflow
/// above `T::MAX`.
#[inline(always)]
pub fn in_range<T: Analog>(v: i128) -> Result<T, u16> {
    if v < T::MIN {
        Err(SL_DIAG_VALUE_UNDERFLOW)
    } else if v > T::MAX {
        Err(SL_DIAG_VALUE_OVERFLOW)
    } else {
        Ok(T::narrow(v))
    }
}

/// The state and output of a block whose output is a computed value (the arithmetic blocks,
/// SCALE): RUN with the value in `out`, or ERROR with the diag value of its range error and
/// `out` 0.
#[inline(always)]
pub fn set_computed(
    h: &mut SL_PRIVATE_HEADER,
    out: &mut u32,
    result: Result<u32, u16>,
) -> Result<(), u16> {
    match result {
        Ok(v) => {
            *out = v;
            h.nState = SL_STATE_RUN;
            Ok(())
        }
        Err(diag) => {
            *out = 0;
            h.enter_error(diag);
            Err(diag)
        }
    }
}

/// `wAux` of a limit monitor (LIMIT, SLP) in SAFE: the value is below the lower limit.
pub(crate) const LIMIT_BELOW: u16 = 1;
/// `wAux` of a limit monitor in SAFE: the value is above the upper limit.
pub(crate) const LIMIT_ABOVE: u16 = 2;

/// The BOOL outputs of a limit monitor (LIMIT, SLP) from its header: Error (ERROR), in
/// limit (RUN), BelowMin and AboveMax (SAFE, by `wAux`).
#[inline(always)]
pub fn limit_outputs(h: &SL_PRIVATE_HEADER) -> [u8; 4] {
    let (error, run, safe) = match h.nState {
        SL_STATE_ERROR => (true, false, false),
        SL_STATE_RUN => (false, true, false),
        SL_STATE_SAFE => (false, false, true),
        _ => (false, false, false),
    };
    [
        u8::from(error),
        u8::from(run),
        u8::from(safe && h.wAux == LIMIT_BELOW),
        u8::from(safe && h.wAux == LIMIT_ABOVE),
    ]
}

/// Magic of the private header of an analog block: its type tag in the analog family's
/// range, so that every variant (the layouts differ) has its own.
pub const fn magic(tag: u16) -> u16 {
    0xA700 | tag
}

/// The diag message of the info data (ABI-2 §10.4): in ERROR with a diag value of `texts`
/// (value, Text ID), that Text ID with the parameters latched at the ERROR entry; otherwise
/// none (0, 0, 0). Cleared with the diag value on ERROR → RESET.
pub fn diag_message(h: &SL_PRIVATE_HEADER, texts: &[(u16, u16)], par: [u32; 2]) -> (u16, u32, u32) {
    let value = h.wDiag & !LIBRARY_DIAG_BITS;
    match texts.iter().find(|(v, _)| *v == value) {
        Some((_, text)) if h.nState == SL_STATE_ERROR => (*text, par[0], par[1]),
        _ => (0, 0, 0),
    }
}

/// [`diag_message`] of a block whose diag values are the range errors: the Text IDs of
/// underflow and overflow.
#[inline(always)]
pub fn range_message(h: &SL_PRIVATE_HEADER, texts: [u16; 2], par: [u32; 2]) -> (u16, u32, u32) {
    let [under, over] = texts;
    diag_message(
        h,
        &[
            (SL_DIAG_VALUE_UNDERFLOW, under),
            (SL_DIAG_VALUE_OVERFLOW, over),
        ],
        par,
    )
}

/// The analog output of a block: the value whose 32-bit pattern is `bits` where it carries
/// one (`on`: RUN), else 0.
#[inline(always)]
pub fn value_if<T: Analog>(on: bool, bits: u32) -> T {
    if on {
        T::from_bits(bits)
    } else {
        T::ZERO
    }
}

/// The unsigned variants (UINT, UDINT): blocks whose manual types are "UINT16 (n=2)
/// UINT32 (n=4)" only, such as VIOLATIONCOUNTER.
pub trait Unsigned: Analog {}
impl Unsigned for u16 {}
impl Unsigned for u32 {}

/// The [`BlockInfo`](crate::base::block::BlockInfo) of the variant `T` of an analog block, from
/// its base name, state enum, diag value texts and the type tag of each variant it has:
/// `variant_info!(T, "SPEED", SpeedState, DIAG_VALUES; INT = SL_TYPE_SPEED_INT, …)`; the
/// name is the base name with the variant's suffix (`SPEED_INT`).
macro_rules! variant_info {
    ($t:ty, $name:literal, $state:ty, $diag_values:expr; $($v:ident = $tag:expr),+ $(,)?) => {{
        let (tag, name) = $crate::blocks::analog::pick::<$t>(&[$((
            $crate::blocks::analog::variant_info!(@index $v),
            $tag,
            concat!($name, "_", stringify!($v)),
        )),+]);
        $crate::base::block::BlockInfo::of::<$state>(tag, name).diag_values($diag_values)
    }};
    (@index INT) => { 0 };
    (@index UINT) => { 1 };
    (@index DINT) => { 2 };
    (@index UDINT) => { 3 };
}
pub(crate) use variant_info;

/// The diag value texts of a block whose output has the range check (ABI-2 §12.1), in the
/// manual's words: value 0 (`$none`), 1 underflow and 2 overflow of the output `$out`
/// (`$end` closes the sentence where the manual's section does), then the block's own
/// values: `range_diag_values!("Speed", "No diagnostic information", "")`.
macro_rules! range_diag_values {
    ($out:literal, $none:literal, $end:literal $(, $extra:expr)* $(,)?) => {
        &[
            (0, $none),
            (
                $crate::blocks::analog::SL_DIAG_VALUE_UNDERFLOW,
                concat!("The output ", $out, " has an underflow (is less than the smallest possible value)", $end),
            ),
            (
                $crate::blocks::analog::SL_DIAG_VALUE_OVERFLOW,
                concat!("The output ", $out, " has an overflow (is greater than the largest possible value)", $end),
            ),
            $($extra),*
        ]
    };
}
pub(crate) use range_diag_values;

/// Declares the variants of a generic analog block once: for each, its type tag (ABI-2
/// §10.6: sequential from 16 in the order of §10.3) and its type alias, the generic struct
/// with the variant's type and reserved gaps:
/// `analog_variants! { FB_SPEED: INT SL_TYPE_SPEED_INT = 44 => FB_SPEED_INT[i16, 2, 6], … }`.
/// build.rs writes every invocation out for cbindgen (`build_support/expand.rs`).
macro_rules! analog_variants {
    ($name:ident: $($v:ident $tag:ident = $n:literal => $alias:ident [$($arg:tt),*]),+ $(,)?) => {
        $(
            #[doc = concat!(" Type tag of ", stringify!($alias), ".")]
            pub const $tag: u16 = $n;
        )+
        $(
            #[doc = concat!(" ", stringify!($name), ", ", stringify!($v), " variant.")]
            pub type $alias = $name<$($arg),*>;
        )+
    };
}
pub(crate) use analog_variants;

/// The (tag, name) of `T`'s variant in a block's list of (variant index, tag, name).
pub const fn pick<T: Analog>(variants: &[(usize, u16, &'static str)]) -> (u16, &'static str) {
    let mut i = 0;
    while i < variants.len() {
        if variants[i].0 == T::VARIANT {
            return (variants[i].1, variants[i].2);
        }
        i += 1;
    }
    panic!("a variant without a type tag")
}

/// The block types ABI-2 §10.2 lays out: every tag from 16 except FB_CONNECTION_SHUTDOWN,
/// which is BOOL-only with "the 8-byte info of §9" (ABI-2 §10.2, §11.1).
pub const fn has_analog_layout(tag: u16) -> bool {
    tag >= 16
        && tag < crate::base::block::SF_TAG_BASE
        && tag != crate::blocks::connection::connshutdown::SL_TYPE_CONNECTION_SHUTDOWN
}

/// ABI-2 §10.2's layout rule, checked on a block's field table: BOOL inputs in 0–15 (link
/// inputs of a non-block object in 18–23), `bRun`/`bErrAck` at 16/17, the analog inputs
/// from 24 naturally aligned in their order (none: the parameters start at the next
/// 4-byte boundary after the group and link inputs), the parameters naturally aligned in
/// their order, the output base OB at the next multiple of 8, BOOL outputs in OB…OB+7,
/// analog outputs from OB + 8 naturally aligned, the 16-byte info (§10.4) at the next
/// multiple of 8 and the private state after it, a multiple of 8 long. `gaps` are the
/// fields the table leaves out between the parameters (offset, bytes: LOADSENSING's value
/// table). `Err` names what breaks the rule.
pub const fn layout_rule(
    fields: &[Field],
    size: usize,
    gaps: &[(usize, usize)],
) -> Result<(), &'static str> {
    const fn align(n: usize, to: usize) -> usize {
        n.div_ceil(to) * to
    }
    const fn is_bool(f: &Field) -> bool {
        f.kind.size() == 1
    }
    let mut pos = 24;
    let mut links_end = 18;
    let mut any_analog_in = false;
    let mut i = 0;
    // inputs and control
    while i < fields.len() {
        let f = &fields[i];
        let o = f.offset as usize;
        match f.dir {
            Dir::Input if is_bool(f) => {
                if !(o < 16 || (o >= 18 && o < 24)) {
                    return Err("a BOOL input lies outside 0-15 and 18-23");
                }
                if o >= 18 && o + 1 > links_end {
                    links_end = o + 1;
                }
            }
            Dir::Input => {
                if o != align(pos, f.kind.size()) {
                    return Err("an analog input is not at 24 + its naturally aligned offset");
                }
                pos = o + f.kind.size();
                any_analog_in = true;
            }
            Dir::Control => {
                let want = if f.name.len() == 4 { 16 } else { 17 }; // bRun, bErrAck
                if o != want {
                    return Err("bRun/bErrAck are not at 16/17");
                }
            }
            _ => {}
        }
        i += 1;
    }
    if !any_analog_in {
        pos = align(links_end, 4);
    }
    // parameters
    i = 0;
    while i < fields.len() {
        let f = &fields[i];
        if let Dir::Param = f.dir {
            let mut g = 0;
            while g < gaps.len() {
                if gaps[g].0 == align(pos, 2) {
                    pos = gaps[g].0 + gaps[g].1;
                }
                g += 1;
            }
            if f.offset as usize != align(pos, f.kind.size()) {
                return Err("a parameter is not naturally aligned after the one before");
            }
            pos = f.offset as usize + f.kind.size();
        }
        i += 1;
    }
    // outputs
    let ob = align(pos, 8);
    let mut end = ob;
    let mut apos = ob + 8;
    i = 0;
    while i < fields.len() {
        let f = &fields[i];
        let o = f.offset as usize;
        if let Dir::Output = f.dir {
            if is_bool(f) {
                if !(o >= ob && o < ob + 8) {
                    return Err("a BOOL output lies outside OB..OB+7");
                }
            } else {
                if o != align(apos, f.kind.size()) {
                    return Err("an analog output is not at OB + 8 + its aligned offset");
                }
                apos = o + f.kind.size();
            }
            if o + f.kind.size() > end {
                end = o + f.kind.size();
            }
        }
        i += 1;
    }
    // info and private
    let info = align(end, 8);
    let want: [(&str, usize); 5] = [
        ("nState", 0),
        ("nDiag", 2),
        ("nDiagTextId", 4),
        ("dwDiagPar2", 8),
        ("dwDiagPar3", 12),
    ];
    let mut w = 0;
    while w < want.len() {
        let mut found = false;
        i = 0;
        while i < fields.len() {
            let f = &fields[i];
            if let Dir::Info = f.dir {
                if eq(f.name, want[w].0) {
                    if f.offset as usize != info + want[w].1 {
                        return Err("an info field is not at info + its §10.4 offset");
                    }
                    found = true;
                }
            }
            i += 1;
        }
        if !found {
            return Err("an info field of §10.4 is missing");
        }
        w += 1;
    }
    if size <= info + 16 || (size - info - 16) % 8 != 0 {
        return Err("the private state does not follow the info data, a multiple of 8 long");
    }
    Ok(())
}

const fn eq(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::layout_rule;
    use crate::registry::BLOCKS;

    /// The rule (checked at compile time for every registered analog type) accepts what it
    /// must, and each of its clauses refuses a field table that breaks it.
    #[test]
    fn the_layout_rule_refuses_every_kind_of_misplaced_field() {
        for b in BLOCKS
            .iter()
            .filter(|b| super::has_analog_layout(b.info.tag))
        {
            assert_eq!(
                layout_rule(b.fields, b.size, b.table_params),
                Ok(()),
                "{}",
                b.info.name
            );
        }
        let loadsensing = crate::registry::block_type_named("LOADSENSING_DINT").unwrap();
        assert_eq!(loadsensing.table_params, [(36, 500)]);
        assert!(layout_rule(loadsensing.fields, loadsensing.size, &[]).is_err());

        let speed = crate::registry::block_type_named("SPEED_INT").unwrap();
        let moved = |name: &str, by: i32| {
            let mut f = speed.fields.to_vec();
            let i = f.iter().position(|f| f.name == name).unwrap();
            f[i].offset = (i32::from(f[i].offset) + by) as u16;
            layout_rule(&f, speed.size, &[])
        };
        assert_eq!(moved("nPosition", 0), Ok(()));
        for (name, by) in [
            ("nPosition", 2),
            ("bRun", 1),
            ("bErrAck", -1),
            ("tTimeInterval", 4),
            ("wInputActive", -2),
            ("bError", 8),
            ("nSpeed", 2),
            ("nState", 8),
            ("nDiag", 2),
            ("nDiagTextId", -2),
            ("dwDiagPar2", 4),
            ("dwDiagPar3", 4),
        ] {
            assert!(moved(name, by).is_err(), "{name} moved by {by}");
        }
        assert!(layout_rule(speed.fields, speed.size + 4, &[]).is_err());
        assert!(layout_rule(speed.fields, speed.size - speed.size % 8 - 56, &[]).is_err());
        let without_par3: Vec<_> = speed
            .fields
            .iter()
            .copied()
            .filter(|f| f.name != "dwDiagPar3")
            .collect();
        assert!(layout_rule(&without_par3, speed.size, &[]).is_err());
    }
}
