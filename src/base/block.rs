//! What every block type declares about itself: its info (tag, name, states, diag texts),
//! its states as an enum (`block_states!`), its field table ([`Field`]: name, offset, type,
//! direction), and the traits the envelopes, the registry and the group read ([`Registered`],
//! [`Cyclic`], [`BlockState`], [`Private`]). The registry (`crate::registry`) lists the types;
//! this module is what a block needs to be listed, so blocks never import the registry.

/// Which way a field of a block struct goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    /// A VAR_INPUT the host or a link writes.
    Input,
    /// `bRun` / `bErrAck`, driven by the owning group (never linkable).
    Control,
    /// A parameter, latched at init and STOP→run.
    Param,
    /// A VAR_OUTPUT the block writes.
    Output,
    /// Info data (`nState`, `nDiag`, diag message).
    Info,
}

/// The IEC type of a field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// BOOL (one byte, 0 or 1).
    Bool,
    /// BYTE / USINT.
    U8,
    /// WORD / UINT.
    U16,
    /// INT.
    I16,
    /// DWORD / UDINT / TIME (ms).
    U32,
    /// DINT.
    I32,
}

impl Kind {
    /// Bytes the field occupies.
    pub const fn size(self) -> usize {
        match self {
            Kind::Bool | Kind::U8 => 1,
            Kind::U16 | Kind::I16 => 2,
            Kind::U32 | Kind::I32 => 4,
        }
    }

    /// The C type of the header.
    pub const fn c_type(self) -> &'static str {
        match self {
            Kind::Bool => "SL_BOOL",
            Kind::U8 => "uint8_t",
            Kind::U16 => "uint16_t",
            Kind::I16 => "int16_t",
            Kind::U32 => "uint32_t",
            Kind::I32 => "int32_t",
        }
    }
}

/// One named field of a block struct.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Field {
    /// The C / PLC name (`bEStopIn1`, `tDiscTime12`, `nAnalogIn1`).
    pub name: &'static str,
    /// Byte offset in the struct.
    pub offset: u16,
    /// IEC type.
    pub kind: Kind,
    /// Direction.
    pub dir: Dir,
}

/// A scalar field type of a block struct.
pub trait FieldType: Copy {
    /// Its IEC type (a `u8` input or output is a BOOL: see [`io_kind`]).
    const KIND: Kind;
    /// The value as a 32-bit pattern (sign-extended for signed types).
    fn to_bits(self) -> u32;
    /// The value from a pattern written by [`Self::to_bits`] of the same type.
    fn from_bits(bits: u32) -> Self;
    /// The field as a BOOL byte (only a one-byte field is one).
    fn as_bool_mut(&mut self) -> Option<&mut u8> {
        None
    }
    /// The value of a BOOL byte.
    fn as_bool(self) -> Option<u8> {
        None
    }
}

macro_rules! field_type {
    ($($t:ty => $k:ident),*) => {$(
        impl FieldType for $t {
            const KIND: Kind = Kind::$k;
            #[inline(always)]
            fn to_bits(self) -> u32 {
                self as u32
            }
            #[inline(always)]
            fn from_bits(bits: u32) -> Self {
                bits as $t
            }
        }
    )*};
}
field_type!(u16 => U16, i16 => I16, u32 => U32, i32 => I32);

impl FieldType for u8 {
    const KIND: Kind = Kind::U8;
    #[inline(always)]
    fn to_bits(self) -> u32 {
        u32::from(self)
    }
    #[inline(always)]
    fn from_bits(bits: u32) -> Self {
        bits as u8
    }
    #[inline(always)]
    fn as_bool_mut(&mut self) -> Option<&mut u8> {
        Some(self)
    }
    #[inline(always)]
    fn as_bool(self) -> Option<u8> {
        Some(self)
    }
}

/// The [`Kind`] of the field a projection reaches (type inference does the work).
pub const fn kind_of<S, F: FieldType>(_: fn(&S) -> &F) -> Kind {
    F::KIND
}

/// The size of the field a projection reaches.
pub const fn size_of_field<S, F>(_: fn(&S) -> &F) -> usize {
    core::mem::size_of::<F>()
}

/// Parameters and info fields keep their type.
pub const fn same(_name: &str, k: Kind) -> Kind {
    k
}

/// Inputs and outputs of one byte are BOOLs (`b…`), except a byte named as a number
/// (`n…`: FB_ADVPOSMON's `nSdfbInstance`, an instance number written by the drive side).
pub const fn io_kind(name: &str, k: Kind) -> Kind {
    match (k, name.as_bytes()) {
        (Kind::U8, [b'n', ..]) => Kind::U8,
        (Kind::U8, _) => Kind::Bool,
        (k, _) => k,
    }
}

/// The block's private state (`stPrivate`), typed: what a block family's code works on.
pub trait Private {
    /// The private struct of the family.
    type P;
    /// `&self.stPrivate`.
    fn private(&self) -> &Self::P;
    /// `&mut self.stPrivate`.
    fn private_mut(&mut self) -> &mut Self::P;
}

/// A block's states as an enum (declared with `block_states!` in the block's file): the
/// state byte `nState` decoded once.
pub trait BlockState: Copy + core::fmt::Debug + Eq + 'static {
    /// (value, NUL-terminated name) of every state, the manual's status values.
    const TABLE: &'static [(u8, &'static str)];
    /// The state with this value; `None` for a value the block does not have (corrupt).
    fn decode(value: u8) -> Option<Self>;
    /// The manual's status value (`nState`).
    fn value(self) -> u8;
    /// The manual's name ("RUN", "DELAYIN", …).
    fn name(self) -> &'static str {
        let v = self.value();
        Self::TABLE
            .iter()
            .find(|(s, _)| *s == v)
            .map_or("?", |(_, n)| n.trim_end_matches('\0'))
    }
}

/// What a registered block type brings: its info, its states and its field table.
pub trait Registered {
    /// Tag, name, states and diag texts.
    const INFO: BlockInfo;
    /// The block's states.
    type State: BlockState;
    /// Every named field (reserved bytes and the private state excluded).
    const FIELDS: &'static [Field];
    /// Parameters that are arrays of structs, left out of [`Self::FIELDS`] (offset, bytes):
    /// LOADSENSING's value table.
    const TABLE_PARAMS: &'static [(usize, usize)] = &[];
    /// The state values as a set (one test per call, no table walk).
    const STATES: StateSet = StateSet::of(<Self::State as BlockState>::TABLE);
}

/// How a registered type runs: what its C functions, the group and [`crate::FunctionBlock`]
/// call. `impl_member!` implements it with the TwinSAFE envelope (`base::envelope`),
/// `impl_sf_member!` with the PLCopen one (`base::sf`).
pub trait Cyclic {
    /// Type tag stored in the private header.
    const MAGIC: u16;
    /// `sl_<name>_init`.
    fn init_fb(&mut self) -> crate::base::types::Status;
    /// `sl_<name>_cycle`.
    fn cycle_fb(&mut self, now: u32) -> crate::base::types::Status;
    /// The steady-state fast path of `cycle_fb` (`base::envelope::fast`): whether it
    /// served the call; [`Self::cycle_rest`] finishes a call it did not serve.
    #[inline(always)]
    fn cycle_fast(&mut self, _now: u32) -> bool {
        false
    }
    /// The rest of a `cycle_fb` call that [`Self::cycle_fast`] did not serve.
    fn cycle_rest(&mut self, now: u32) -> crate::base::types::Status;
    /// After a caught panic: the safe state with every output FALSE.
    fn force_safe(&mut self);
    /// The block is in an error state (TwinSAFE ERROR; PLCopen DiagCode ≥ 0xC000).
    fn in_error(&self) -> bool;
    /// The first parameter rule the live parameters break (`base::reason`), if any.
    fn refusal(&self) -> Option<crate::base::reason::Refusal>;
    /// The `i`-th of the block's parameter rules, in the order they are checked.
    fn rule(i: usize) -> Option<crate::base::reason::RuleInfo>;
}

/// The two block families of the registry, told apart by the type tag.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// TwinSAFE blocks (`FB_<NAME>`, tags below 256): bRun/bErrAck at 16/17, nState/nDiag.
    TwinSafe,
    /// PLCopen Safety blocks (`SF_<Name>`, tags from [`SF_TAG_BASE`]): Activate, Ready,
    /// Error, DiagCode (`base::sf`).
    PlcOpen,
}

/// First type tag of the PLCopen family.
pub const SF_TAG_BASE: u16 = 512;

/// The family of a type tag.
pub const fn family(tag: u16) -> Family {
    if tag >= SF_TAG_BASE {
        Family::PlcOpen
    } else {
        Family::TwinSafe
    }
}

/// A set of state values 0–63.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateSet(u64);

impl StateSet {
    /// The values of a state table.
    pub const fn of(states: &[(u8, &str)]) -> Self {
        let mut bits = 0u64;
        let mut i = 0;
        while i < states.len() {
            assert!(states[i].0 < 64, "state values are below 64");
            bits |= 1 << states[i].0;
            i += 1;
        }
        Self(bits)
    }

    /// `state` is one of the set.
    #[inline(always)]
    pub const fn has(self, state: u8) -> bool {
        state < 64 && (self.0 >> state) & 1 != 0
    }
}

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

impl BlockInfo {
    /// The info of a block with the states `S`, no diag texts yet: `BlockInfo::of::<TonState>(
    /// SL_TYPE_TON, "TON")`, then `.diag(…)` / `.diag_values(…)` where the manual has texts.
    pub const fn of<S: BlockState>(tag: u16, name: &'static str) -> Self {
        Self {
            tag,
            name,
            states: S::TABLE,
            diag: &[],
            diag_values: &[],
        }
    }
    /// The same info with the manual's diag bit texts.
    pub const fn diag(mut self, diag: &'static [(u16, &'static str)]) -> Self {
        self.diag = diag;
        self
    }
    /// The same info with the manual's diag value texts.
    pub const fn diag_values(mut self, values: &'static [(u16, &'static str)]) -> Self {
        self.diag_values = values;
        self
    }
}

/// Declares a block's states once: `pub enum $name` whose values are the manual's status
/// values, and its table (value, NUL-terminated name) that `BlockInfo::states`,
/// `sl_state_str` and the envelope's state check read. The common states are named by
/// their variant alone; a block's own state gives its value and name:
/// `block_states!(TonState: Run, Stop, Safe, Error, Reset, DelayIn = SL_STATE_TON_DELAYIN, "DELAYIN");`
macro_rules! block_states {
    (@value Run) => { $crate::base::types::SL_STATE_RUN };
    (@value Stop) => { $crate::base::types::SL_STATE_STOP };
    (@value Safe) => { $crate::base::types::SL_STATE_SAFE };
    (@value Error) => { $crate::base::types::SL_STATE_ERROR };
    (@value Reset) => { $crate::base::types::SL_STATE_RESET };
    (@value Start) => { $crate::base::types::SL_STATE_START };
    (@value DelayOut) => { $crate::base::types::SL_STATE_DELAYOUT };
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
                #[doc = concat!("The manual's state ", $crate::base::block::block_states!(@name $v $($name)?), ".")]
                $v = $crate::base::block::block_states!(@value $v $($value)?),
            )+
        }
        impl $crate::base::block::BlockState for $enum {
            const TABLE: &'static [(u8, &'static str)] = &[$((
                $enum::$v as u8,
                concat!($crate::base::block::block_states!(@name $v $($name)?), "\0"),
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
