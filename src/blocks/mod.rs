//! The function blocks. One file per block, citing its manual section; blocks that share a
//! state machine share it: ESTOP and MON (manual §4.4, §4.5) in `guard`, the
//! combinational blocks (AND, OR, XOR, DECOUPLE) in `logic`, RS and SR (§4.10, §4.11) in
//! `flipflop`, the timers TON, TON2 and TOF (§4.12–§4.14) in `timer`, SLI and SLI2
//! (§4.27, §4.28) in `window`. OPMODE (§4.3), TWOHAND (§4.7), MUTING (§4.8) and EDM (§4.9)
//! have state machines of their own. The PLCopen Safety blocks (`sf_*`, struct names
//! `SF_<Name>`) run in the PLCopen envelope (`prim::sf`); SF_EmergencyStop, SF_ESPE and
//! SF_PSE share the restart-interlock machine of `sf_restart`, SF_Equivalent and
//! SF_Antivalent the two-channel machine of `sf_pair`, SF_TwoHandControlTypeII and
//! SF_TwoHandControlTypeIII the two-hand machine of `sf_twohand`; SF_Guard,
//! SF_SafetyRequest, SF_OutControl, SF_EnableSwitch and SF_ModeSelector have machines of
//! their own.

pub mod advposmon;
pub mod analog;
pub mod and;
pub mod arith;
pub mod cammonitor;
pub mod compare;
pub mod connshutdown;
pub mod counter;
pub mod decouple;
pub mod edm;
pub mod envelope;
pub mod estop;
pub mod flipflop;
pub mod guard;
pub mod limit;
pub mod loadsensing;
pub mod logic;
pub mod mon;
pub mod muting;
pub mod opmode;
pub mod or;
pub mod rs;
pub mod sbt;
pub mod scale;
pub mod sf_antivalent;
pub mod sf_edm;
pub mod sf_emergencystop;
pub mod sf_enableswitch;
pub mod sf_equivalent;
pub mod sf_espe;
pub mod sf_guard;
pub mod sf_modeselector;
pub mod sf_outcontrol;
pub mod sf_pair;
pub mod sf_pse;
pub mod sf_resetbutton;
pub mod sf_restart;
pub mod sf_safetyrequest;
pub mod sf_testablesafetysensor;
pub mod sf_twohand;
pub mod sf_twohandcontroltypeii;
pub mod sf_twohandcontroltypeiii;
pub mod sli;
pub mod sli2;
pub mod slp;
pub mod speed;
pub mod sr;
pub mod timer;
pub mod tof;
pub mod ton;
pub mod ton2;
pub mod twohand;
pub mod violationcounter;
pub mod window;
pub mod xor;

/// The names a family's `Block` impl uses, for its expansion in a member's file.
macro_rules! family_prelude {
    ($family:ident) => {
        use $crate::blocks::$family::*;
        #[allow(unused_imports)]
        use $crate::prim::envelope::{Block, Instance};
        #[allow(unused_imports)]
        use $crate::prim::{
            bools, bools::Edge, edm, edm::Edm, header::*, pair, restart, restart::Restart, time,
        };
        use $crate::registry::Private;
        use $crate::types::*;
    };
}
pub(crate) use family_prelude;

/// What the C ABI and HMIs need to know about a block type without an instance.
#[derive(Clone, Copy, Debug)]
pub struct BlockInfo {
    /// `SL_TYPE_<NAME>` (group member tag).
    pub tag: u16,
    /// The manual's block name.
    pub name: &'static str,
    /// The block's states (the manual's status values) with NUL-terminated names.
    pub states: &'static [(u8, &'static str)],
    /// Diagnostic bits the manual defines for the block, with their manual text.
    pub diag: &'static [(u16, &'static str)],
    /// For blocks whose `nDiag` carries a value (ADD …): the values with their manual
    /// text; the library bits 13-15 are bits in every block.
    pub diag_values: &'static [(u16, &'static str)],
}

/// Declares a block's states once: `pub enum $name` whose values are the manual's status
/// values, and its table (value, NUL-terminated name) that `BlockInfo::states`,
/// `sl_state_str` and the envelope's state check read. The common states are named by
/// their variant alone; a block's own state gives its value and name:
/// `block_states!(TonState: Run, Stop, Safe, Error, Reset, DelayIn = SL_STATE_TON_DELAYIN, "DELAYIN");`
macro_rules! block_states {
    (@value Run) => { $crate::types::SL_STATE_RUN };
    (@value Stop) => { $crate::types::SL_STATE_STOP };
    (@value Safe) => { $crate::types::SL_STATE_SAFE };
    (@value Error) => { $crate::types::SL_STATE_ERROR };
    (@value Reset) => { $crate::types::SL_STATE_RESET };
    (@value Start) => { $crate::types::SL_STATE_START };
    (@value DelayOut) => { $crate::types::SL_STATE_DELAYOUT };
    (@value $v:ident $value:path) => { $value };
    (@name Run) => { "RUN" };
    (@name Stop) => { "STOP" };
    (@name Safe) => { "SAFE" };
    (@name Error) => { "ERROR" };
    (@name Reset) => { "RESET" };
    (@name Start) => { "START" };
    (@name DelayOut) => { "DELAYOUT" };
    (@name $v:ident $name:literal) => { $name };
    ($(#[$meta:meta])* $enum:ident: $($v:ident $(= $value:path, $name:literal)?),+ $(,)?) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[repr(u8)]
        pub enum $enum {
            $(
                #[doc = concat!("The manual's state ", $crate::blocks::block_states!(@name $v $($name)?), ".")]
                $v = $crate::blocks::block_states!(@value $v $($value)?),
            )+
        }
        impl $crate::registry::BlockState for $enum {
            const TABLE: &'static [(u8, &'static str)] = &[$((
                $enum::$v as u8,
                concat!($crate::blocks::block_states!(@name $v $($name)?), "\0"),
            )),+];
            #[inline]
            fn decode(value: u8) -> Option<Self> {
                $(if value == $enum::$v as u8 {
                    return Some($enum::$v);
                })+
                None
            }
            #[inline]
            fn value(self) -> u8 {
                self as u8
            }
        }
    };
}
pub(crate) use block_states;

/// The block type with this tag.
pub fn info(tag: u16) -> Option<&'static BlockInfo> {
    crate::registry::block_type(tag).map(|b| &b.info)
}

/// The states (value, NUL-terminated name) of a group member type: a block's, or an FSoE
/// connection's (`SL_TYPE_FSOE_CONN`).
pub fn states(tag: u16) -> Option<&'static [(u8, &'static str)]> {
    if tag == crate::fsoe::SL_TYPE_FSOE_CONN {
        return Some(crate::fsoe::STATE_NAMES);
    }
    info(tag).map(|b| b.states)
}

/// Name of state `state` of member type `tag` ("?" for a value the type does not have).
pub fn state_name(tag: u16, state: u8) -> &'static str {
    states(tag)
        .and_then(|s| s.iter().find(|(v, _)| *v == state))
        .map_or("?", |(_, name)| name.trim_end_matches('\0'))
}

/// Library diag bits common to every block (docs/semantics.md C11).
pub const LIBRARY_DIAG: &[(u16, &str)] = &[
    (
        crate::types::SL_DIAG_PARAM_CHANGED,
        "parameter changed while running",
    ),
    (crate::types::SL_DIAG_CLOCK, "clock went backwards"),
    (crate::types::SL_DIAG_CORRUPT, "private state corrupt"),
];

/// Writes the names of the bits set in `diag` into `out` (a PLCopen block: the text of the
/// DiagCode `diag`), separated by "; ", truncated to
/// fit; returns the number of bytes written (no NUL).
pub fn diag_text(block: &BlockInfo, diag: u16, out: &mut [u8]) -> usize {
    let mut w = Writer { out, len: 0 };
    // A PLCopen DiagCode is one value (state or error) of either profile, never bits.
    if crate::registry::family(block.tag) == crate::registry::Family::PlcOpen {
        w.push(crate::prim::sf::diag_text(block.diag_values, diag).unwrap_or("unknown DiagCode"));
        return w.len;
    }
    let mut bits = diag;
    if !block.diag_values.is_empty() {
        let value = diag & !crate::types::LIBRARY_DIAG_BITS;
        match block.diag_values.iter().find(|(v, _)| *v == value) {
            Some((_, text)) => w.push(text),
            None => w.push("unknown diag value"),
        }
        bits &= crate::types::LIBRARY_DIAG_BITS;
    }
    for bit in 0..16u16 {
        let mask = 1u16 << bit;
        if bits & mask == 0 {
            continue;
        }
        if w.len > 0 {
            w.push("; ");
        }
        match block
            .diag
            .iter()
            .chain(LIBRARY_DIAG)
            .find(|(m, _)| *m == mask)
        {
            Some((_, text)) => w.push(text),
            None => {
                w.push("bit ");
                w.push(DIGITS[usize::from(bit)]);
            }
        }
    }
    w.len
}

const DIGITS: [&str; 16] = [
    "0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13", "14", "15",
];

struct Writer<'a> {
    out: &'a mut [u8],
    len: usize,
}

impl Writer<'_> {
    fn push(&mut self, s: &str) {
        let room = self.out.len().saturating_sub(self.len);
        let n = s.len().min(room);
        if let (Some(dst), Some(src)) = (
            self.out.get_mut(self.len..self.len + n),
            s.as_bytes().get(..n),
        ) {
            dst.copy_from_slice(src);
            self.len += n;
        }
    }
}
