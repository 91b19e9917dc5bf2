//! The one list of block types, and what every entry brings along.
//!
//! A block type is declared once, as a row of [`for_each_block!`](crate::for_each_block): its struct and its two C
//! function names. From that row come the exported `sl_<name>_init` / `sl_<name>_cycle`
//! (`ffi`), the group's dispatch from type tag to block (`ffi`), the table [`BLOCKS`]
//! behind `sl_state_str` / `sl_diag_text`, and the header's prototypes (build.rs reads the
//! rows of this file). The block's file supplies the rest through `impl_member!`: its
//! [`BlockInfo`] (tag, name, states, diag texts) and its field table ([`Field`]: name,
//! offset, type, direction), which the group's link checks, the PLC generator and the
//! project loader read.

use crate::blocks::BlockInfo;

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
/// call. `impl_member!` implements it with the TwinSAFE envelope (`prim::envelope`),
/// `impl_sf_member!` with the PLCopen one (`prim::sf`).
pub trait Cyclic {
    /// Type tag stored in the private header.
    const MAGIC: u16;
    /// `sl_<name>_init`.
    fn init_fb(&mut self) -> crate::types::Status;
    /// `sl_<name>_cycle`.
    fn cycle_fb(&mut self, now: u32) -> crate::types::Status;
    /// The steady-state fast path of `cycle_fb` (`prim::envelope::fast`): whether it
    /// served the call; [`Self::cycle_rest`] finishes a call it did not serve.
    #[inline(always)]
    fn cycle_fast(&mut self, _now: u32) -> bool {
        false
    }
    /// The rest of a `cycle_fb` call that [`Self::cycle_fast`] did not serve.
    fn cycle_rest(&mut self, now: u32) -> crate::types::Status;
    /// After a caught panic: the safe state with every output FALSE.
    fn force_safe(&mut self);
    /// The block is in an error state (TwinSAFE ERROR; PLCopen DiagCode ≥ 0xC000).
    fn in_error(&self) -> bool;
}

/// The two block families of the registry, told apart by the type tag.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// TwinSAFE blocks (`FB_<NAME>`, tags below 256): bRun/bErrAck at 16/17, nState/nDiag.
    TwinSafe,
    /// PLCopen Safety blocks (`SF_<Name>`, tags from [`SF_TAG_BASE`]): Activate, Ready,
    /// Error, DiagCode (`prim::sf`).
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

/// One registered block type.
#[derive(Clone, Copy, Debug)]
pub struct BlockType {
    /// Tag, name, states and diag texts.
    pub info: BlockInfo,
    /// The field table.
    pub fields: &'static [Field],
    /// Array parameters left out of the field table (offset, bytes).
    pub table_params: &'static [(usize, usize)],
    /// `sizeof(FB_<NAME>)`.
    pub size: usize,
    /// The C function prefix (`sl_estop`, `sl_add_int`).
    pub c_prefix: &'static str,
}

impl BlockType {
    /// The entry of a registered type.
    pub const fn of<B: Registered>(c_prefix: &'static str) -> Self {
        Self {
            info: B::INFO,
            fields: B::FIELDS,
            table_params: B::TABLE_PARAMS,
            size: core::mem::size_of::<B>(),
            c_prefix,
        }
    }

    /// What precedes the name in the C struct's name: `FB_` for `FB_<NAME>` (TwinSAFE),
    /// nothing for a PLCopen block (`SF_EmergencyStop` is its own struct's name).
    pub const fn struct_prefix(&self) -> &'static str {
        match family(self.info.tag) {
            Family::TwinSafe => "FB_",
            Family::PlcOpen => "",
        }
    }

    /// The field with this name.
    pub fn field(&self, name: &str) -> Option<&'static Field> {
        self.fields.iter().find(|f| f.name == name)
    }

    /// The field at this offset.
    pub fn field_at(&self, offset: u16) -> Option<&'static Field> {
        self.fields.iter().find(|f| f.offset == offset)
    }
}

/// The registry: one row per block type (struct => C init, C cycle), in tag order: the
/// TwinSAFE rows ([`for_each_twinsafe_block!`](crate::for_each_twinsafe_block)), then the
/// PLCopen rows ([`for_each_sf_block!`](crate::for_each_sf_block)). Calls `$m! { rows }`;
/// build.rs reads the rows between the markers to write the prototypes. A generator that
/// touches a family's own fields (`bRun`, `Activate`) takes that family's macro.
#[doc(hidden)]
#[macro_export]
macro_rules! for_each_block {
    ($m:ident) => {
        $crate::for_each_twinsafe_block! { @rows [all] $m }
    };
}

/// Hands a family's rows on: to `$m` alone, or (`all`) after the TwinSAFE rows to the
/// PLCopen macro, which appends its own.
#[doc(hidden)]
#[macro_export]
macro_rules! __sl_rows {
    ([] $m:ident [$($rows:tt)*]) => {
        $m! { $($rows)* }
    };
    ([all] $m:ident [$($rows:tt)*]) => {
        $crate::for_each_sf_block! { $m [$($rows)*] }
    };
}

/// The TwinSAFE rows (`FB_<NAME>`, tags below 256).
#[doc(hidden)]
#[macro_export]
macro_rules! for_each_twinsafe_block {
    ($m:ident) => {
        $crate::for_each_twinsafe_block! { @rows [] $m }
    };
    (@rows [$($all:ident)?] $m:ident) => {
        $crate::__sl_rows! { [$($all)?] $m [
            // registry:begin
            $crate::blocks::estop::FB_ESTOP => sl_estop_init, sl_estop_cycle;
            $crate::blocks::mon::FB_MON => sl_mon_init, sl_mon_cycle;
            $crate::blocks::and::FB_AND => sl_and_init, sl_and_cycle;
            $crate::blocks::or::FB_OR => sl_or_init, sl_or_cycle;
            $crate::blocks::xor::FB_XOR => sl_xor_init, sl_xor_cycle;
            $crate::blocks::decouple::FB_DECOUPLE => sl_decouple_init, sl_decouple_cycle;
            $crate::blocks::opmode::FB_OPMODE => sl_opmode_init, sl_opmode_cycle;
            $crate::blocks::twohand::FB_TWOHAND => sl_twohand_init, sl_twohand_cycle;
            $crate::blocks::muting::FB_MUTING => sl_muting_init, sl_muting_cycle;
            $crate::blocks::edm::FB_EDM => sl_edm_init, sl_edm_cycle;
            $crate::blocks::rs::FB_RS => sl_rs_init, sl_rs_cycle;
            $crate::blocks::sr::FB_SR => sl_sr_init, sl_sr_cycle;
            $crate::blocks::ton::FB_TON => sl_ton_init, sl_ton_cycle;
            $crate::blocks::ton2::FB_TON2 => sl_ton2_init, sl_ton2_cycle;
            $crate::blocks::tof::FB_TOF => sl_tof_init, sl_tof_cycle;
            $crate::blocks::arith::FB_ADD_INT => sl_add_int_init, sl_add_int_cycle;
            $crate::blocks::arith::FB_ADD_UINT => sl_add_uint_init, sl_add_uint_cycle;
            $crate::blocks::arith::FB_ADD_DINT => sl_add_dint_init, sl_add_dint_cycle;
            $crate::blocks::arith::FB_ADD_UDINT => sl_add_udint_init, sl_add_udint_cycle;
            $crate::blocks::arith::FB_SUB_INT => sl_sub_int_init, sl_sub_int_cycle;
            $crate::blocks::arith::FB_SUB_UINT => sl_sub_uint_init, sl_sub_uint_cycle;
            $crate::blocks::arith::FB_SUB_DINT => sl_sub_dint_init, sl_sub_dint_cycle;
            $crate::blocks::arith::FB_SUB_UDINT => sl_sub_udint_init, sl_sub_udint_cycle;
            $crate::blocks::arith::FB_MUL_INT => sl_mul_int_init, sl_mul_int_cycle;
            $crate::blocks::arith::FB_MUL_UINT => sl_mul_uint_init, sl_mul_uint_cycle;
            $crate::blocks::arith::FB_MUL_DINT => sl_mul_dint_init, sl_mul_dint_cycle;
            $crate::blocks::arith::FB_MUL_UDINT => sl_mul_udint_init, sl_mul_udint_cycle;
            $crate::blocks::arith::FB_DIV_INT => sl_div_int_init, sl_div_int_cycle;
            $crate::blocks::arith::FB_DIV_UINT => sl_div_uint_init, sl_div_uint_cycle;
            $crate::blocks::arith::FB_DIV_DINT => sl_div_dint_init, sl_div_dint_cycle;
            $crate::blocks::arith::FB_DIV_UDINT => sl_div_udint_init, sl_div_udint_cycle;
            $crate::blocks::compare::FB_COMPARE_INT => sl_compare_int_init, sl_compare_int_cycle;
            $crate::blocks::compare::FB_COMPARE_UINT => sl_compare_uint_init, sl_compare_uint_cycle;
            $crate::blocks::compare::FB_COMPARE_DINT => sl_compare_dint_init, sl_compare_dint_cycle;
            $crate::blocks::compare::FB_COMPARE_UDINT => sl_compare_udint_init, sl_compare_udint_cycle;
            $crate::blocks::limit::FB_LIMIT_INT => sl_limit_int_init, sl_limit_int_cycle;
            $crate::blocks::limit::FB_LIMIT_UINT => sl_limit_uint_init, sl_limit_uint_cycle;
            $crate::blocks::limit::FB_LIMIT_DINT => sl_limit_dint_init, sl_limit_dint_cycle;
            $crate::blocks::limit::FB_LIMIT_UDINT => sl_limit_udint_init, sl_limit_udint_cycle;
            $crate::blocks::scale::FB_SCALE_INT => sl_scale_int_init, sl_scale_int_cycle;
            $crate::blocks::scale::FB_SCALE_UINT => sl_scale_uint_init, sl_scale_uint_cycle;
            $crate::blocks::scale::FB_SCALE_DINT => sl_scale_dint_init, sl_scale_dint_cycle;
            $crate::blocks::scale::FB_SCALE_UDINT => sl_scale_udint_init, sl_scale_udint_cycle;
            $crate::blocks::speed::FB_SPEED_INT => sl_speed_int_init, sl_speed_int_cycle;
            $crate::blocks::speed::FB_SPEED_UINT => sl_speed_uint_init, sl_speed_uint_cycle;
            $crate::blocks::speed::FB_SPEED_DINT => sl_speed_dint_init, sl_speed_dint_cycle;
            $crate::blocks::speed::FB_SPEED_UDINT => sl_speed_udint_init, sl_speed_udint_cycle;
            $crate::blocks::loadsensing::FB_LOADSENSING_INT => sl_loadsensing_int_init, sl_loadsensing_int_cycle;
            $crate::blocks::loadsensing::FB_LOADSENSING_UINT => sl_loadsensing_uint_init, sl_loadsensing_uint_cycle;
            $crate::blocks::loadsensing::FB_LOADSENSING_DINT => sl_loadsensing_dint_init, sl_loadsensing_dint_cycle;
            $crate::blocks::loadsensing::FB_LOADSENSING_UDINT => sl_loadsensing_udint_init, sl_loadsensing_udint_cycle;
            $crate::blocks::envelope::FB_ENVELOPE_INT => sl_envelope_int_init, sl_envelope_int_cycle;
            $crate::blocks::envelope::FB_ENVELOPE_UINT => sl_envelope_uint_init, sl_envelope_uint_cycle;
            $crate::blocks::envelope::FB_ENVELOPE_DINT => sl_envelope_dint_init, sl_envelope_dint_cycle;
            $crate::blocks::envelope::FB_ENVELOPE_UDINT => sl_envelope_udint_init, sl_envelope_udint_cycle;
            $crate::blocks::counter::FB_COUNTER_INT => sl_counter_int_init, sl_counter_int_cycle;
            $crate::blocks::counter::FB_COUNTER_UINT => sl_counter_uint_init, sl_counter_uint_cycle;
            $crate::blocks::counter::FB_COUNTER_DINT => sl_counter_dint_init, sl_counter_dint_cycle;
            $crate::blocks::counter::FB_COUNTER_UDINT => sl_counter_udint_init, sl_counter_udint_cycle;
            $crate::blocks::sli::FB_SLI_INT => sl_sli_int_init, sl_sli_int_cycle;
            $crate::blocks::sli::FB_SLI_UINT => sl_sli_uint_init, sl_sli_uint_cycle;
            $crate::blocks::sli::FB_SLI_DINT => sl_sli_dint_init, sl_sli_dint_cycle;
            $crate::blocks::sli::FB_SLI_UDINT => sl_sli_udint_init, sl_sli_udint_cycle;
            $crate::blocks::sli2::FB_SLI2_INT => sl_sli2_int_init, sl_sli2_int_cycle;
            $crate::blocks::sli2::FB_SLI2_UINT => sl_sli2_uint_init, sl_sli2_uint_cycle;
            $crate::blocks::sli2::FB_SLI2_DINT => sl_sli2_dint_init, sl_sli2_dint_cycle;
            $crate::blocks::sli2::FB_SLI2_UDINT => sl_sli2_udint_init, sl_sli2_udint_cycle;
            $crate::blocks::violationcounter::FB_VIOLATIONCOUNTER_UINT => sl_violationcounter_uint_init, sl_violationcounter_uint_cycle;
            $crate::blocks::violationcounter::FB_VIOLATIONCOUNTER_UDINT => sl_violationcounter_udint_init, sl_violationcounter_udint_cycle;
            $crate::blocks::cammonitor::FB_CAMMONITOR_UINT => sl_cammonitor_uint_init, sl_cammonitor_uint_cycle;
            $crate::blocks::cammonitor::FB_CAMMONITOR_UDINT => sl_cammonitor_udint_init, sl_cammonitor_udint_cycle;
            $crate::blocks::slp::FB_SLP => sl_slp_init, sl_slp_cycle;
            $crate::blocks::sbt::FB_SBT => sl_sbt_init, sl_sbt_cycle;
            $crate::blocks::advposmon::FB_ADVPOSMON => sl_advposmon_init, sl_advposmon_cycle;
            $crate::blocks::connshutdown::FB_CONNECTION_SHUTDOWN => sl_connection_shutdown_init, sl_connection_shutdown_cycle;
            // registry:end
        ] }
    };
}

/// The PLCopen Safety rows (`SF_<Name>`, tags from [`SF_TAG_BASE`]), after `$pre` (the
/// TwinSAFE rows when called for every block).
#[doc(hidden)]
#[macro_export]
macro_rules! for_each_sf_block {
    ($m:ident $([$($pre:tt)*])?) => {
        $m! {
            $($($pre)*)?
            // registry:begin
            $crate::blocks::sf_emergencystop::SF_EmergencyStop => sl_sf_emergencystop_init, sl_sf_emergencystop_cycle;
            $crate::blocks::sf_espe::SF_ESPE => sl_sf_espe_init, sl_sf_espe_cycle;
            $crate::blocks::sf_pse::SF_PSE => sl_sf_pse_init, sl_sf_pse_cycle;
            $crate::blocks::sf_equivalent::SF_Equivalent => sl_sf_equivalent_init, sl_sf_equivalent_cycle;
            $crate::blocks::sf_antivalent::SF_Antivalent => sl_sf_antivalent_init, sl_sf_antivalent_cycle;
            $crate::blocks::sf_guard::SF_Guard => sl_sf_guard_init, sl_sf_guard_cycle;
            $crate::blocks::sf_safetyrequest::SF_SafetyRequest => sl_sf_safetyrequest_init, sl_sf_safetyrequest_cycle;
            $crate::blocks::sf_outcontrol::SF_OutControl => sl_sf_outcontrol_init, sl_sf_outcontrol_cycle;
            $crate::blocks::sf_resetbutton::SF_ResetButton => sl_sf_resetbutton_init, sl_sf_resetbutton_cycle;
            $crate::blocks::sf_edm::SF_EDM => sl_sf_edm_init, sl_sf_edm_cycle;
            $crate::blocks::sf_testablesafetysensor::SF_TestableSafetySensor => sl_sf_testablesafetysensor_init, sl_sf_testablesafetysensor_cycle;
            $crate::blocks::sf_enableswitch::SF_EnableSwitch => sl_sf_enableswitch_init, sl_sf_enableswitch_cycle;
            $crate::blocks::sf_twohandcontroltypeii::SF_TwoHandControlTypeII => sl_sf_twohandcontroltypeii_init, sl_sf_twohandcontroltypeii_cycle;
            $crate::blocks::sf_twohandcontroltypeiii::SF_TwoHandControlTypeIII => sl_sf_twohandcontroltypeiii_init, sl_sf_twohandcontroltypeiii_cycle;
            $crate::blocks::sf_modeselector::SF_ModeSelector => sl_sf_modeselector_init, sl_sf_modeselector_cycle;
            // registry:end
        }
    };
}

macro_rules! block_table {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        /// Every registered block type, in tag order.
        pub static BLOCKS: &[BlockType] = &[$(BlockType::of::<$ty>(c_prefix(stringify!($init)))),*];
    };
}

/// `sl_estop_init` → `sl_estop`.
const fn c_prefix(init: &'static str) -> &'static str {
    let (prefix, _) = init.as_bytes().split_at(init.len() - "_init".len());
    match core::str::from_utf8(prefix) {
        Ok(p) => p,
        Err(_) => panic!("registry: C names are ASCII"),
    }
}

crate::for_each_block!(block_table);

/// Every block with analog signals (tags from 16, `analog::has_analog_layout`) follows ABI-2 §10.2's layout rule, checked
/// at compile time on its field table (a new registry row is checked by being a row).
macro_rules! analog_layout_rule {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {$(
        const _: () = {
            if crate::blocks::analog::has_analog_layout(<$ty as Registered>::INFO.tag) {
                if let Err(broken) = crate::blocks::analog::layout_rule(
                    <$ty as Registered>::FIELDS,
                    core::mem::size_of::<$ty>(),
                    <$ty as Registered>::TABLE_PARAMS,
                ) {
                    panic!("{}", broken);
                }
            }
        };
    )*};
}
crate::for_each_block!(analog_layout_rule);

/// The block type with this tag.
pub fn block_type(tag: u16) -> Option<&'static BlockType> {
    BLOCKS.iter().find(|b| b.info.tag == tag)
}

/// The block type with this manual name (`ESTOP`, `ADD_INT`).
pub fn block_type_named(name: &str) -> Option<&'static BlockType> {
    BLOCKS.iter().find(|b| b.info.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_and_names_are_unique_and_in_order() {
        assert!(BLOCKS.windows(2).all(|w| w[0].info.tag < w[1].info.tag));
        for (i, a) in BLOCKS.iter().enumerate() {
            assert!(BLOCKS[i + 1..].iter().all(|b| b.info.name != a.info.name));
            assert_eq!(
                a.info.name.starts_with("SF_"),
                family(a.info.tag) == Family::PlcOpen
            );
            assert!(a.info.states.iter().all(|(_, n)| n.ends_with('\0')));
            assert_eq!(a.c_prefix, alloc_free_lower(a.info.name).as_str());
        }
    }

    #[test]
    fn states_come_from_the_state_enum() {
        macro_rules! check {
            ($($ty:ty => $init:ident, $cycle:ident;)*) => {$({
                type S = <$ty as Registered>::State;
                let info = <$ty as Registered>::INFO;
                assert_eq!(info.states, S::TABLE, "{}", info.name);
                for v in 0..=u8::MAX {
                    let known = S::TABLE.iter().any(|(s, _)| *s == v);
                    assert_eq!(S::decode(v).map(S::value), known.then_some(v), "{}", info.name);
                    assert_eq!(<$ty as Registered>::STATES.has(v), known, "{}", info.name);
                }
            })*};
        }
        crate::for_each_block!(check);
    }

    fn alloc_free_lower(name: &str) -> String {
        format!("sl_{}", name.to_ascii_lowercase())
    }

    #[test]
    fn fields_lie_inside_the_struct_and_do_not_overlap() {
        for b in BLOCKS {
            let mut spans: Vec<_> = b
                .fields
                .iter()
                .map(|f| (usize::from(f.offset), usize::from(f.offset) + f.kind.size()))
                .collect();
            spans.sort();
            assert!(
                spans.windows(2).all(|w| w[0].1 <= w[1].0),
                "{}",
                b.info.name
            );
            assert!(spans.last().is_some_and(|s| s.1 <= b.size));
            match family(b.info.tag) {
                Family::TwinSafe => {
                    for name in ["bRun", "bErrAck", "nState", "nDiag"] {
                        assert!(b.field(name).is_some(), "{} has {name}", b.info.name);
                    }
                    assert_eq!(b.field("bRun").map(|f| f.offset), Some(16));
                    assert_eq!(b.field("bErrAck").map(|f| f.offset), Some(17));
                }
                Family::PlcOpen => {
                    // The PLCopen envelope: Activate first, the generic outputs, no
                    // group control fields (the group halts a block through its private
                    // state).
                    // SF_ResetButton's activation is ResetRequested (it has no Activate).
                    let act = if b.info.name == "SF_ResetButton" {
                        "ResetRequested"
                    } else {
                        "Activate"
                    };
                    assert_eq!(b.field(act).map(|f| f.offset), Some(0));
                    for (name, kind) in [
                        (act, Kind::Bool),
                        ("Ready", Kind::Bool),
                        ("Error", Kind::Bool),
                        ("DiagCode", Kind::U16),
                        ("nDiagProfile", Kind::U8),
                    ] {
                        assert_eq!(
                            b.field(name).map(|f| f.kind),
                            Some(kind),
                            "{} {name}",
                            b.info.name
                        );
                    }
                    assert!(b.fields.iter().all(|f| f.dir != Dir::Control));
                    assert!(b.info.name.starts_with("SF_"));
                }
            }
        }
    }
}
