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

// The vocabulary of a row (what a block declares about itself), public here as well: a
// user of the registry reads rows without reaching into the core layer.
pub use crate::base::block::{
    family, BlockInfo, BlockState, Cyclic, Dir, Family, Field, FieldType, Kind, Registered,
    SF_TAG_BASE,
};
pub use crate::base::reason::{Refusal, Rule, RuleInfo};

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
    /// The `i`-th of the type's parameter rules (`base::reason`), in the order checked.
    pub rule: fn(usize) -> Option<RuleInfo>,
}

impl BlockType {
    /// The entry of a registered type.
    pub const fn of<B: Registered + Cyclic>(c_prefix: &'static str) -> Self {
        Self {
            info: B::INFO,
            fields: B::FIELDS,
            table_params: B::TABLE_PARAMS,
            size: core::mem::size_of::<B>(),
            c_prefix,
            rule: <B as Cyclic>::rule,
        }
    }

    /// The type's parameter rules, in the order they are checked.
    pub fn rules(&self) -> impl Iterator<Item = RuleInfo> + '_ {
        (0..).map_while(|i| (self.rule)(i))
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
            $crate::blocks::boolean::estop::FB_ESTOP => sl_estop_init, sl_estop_cycle;
            $crate::blocks::boolean::mon::FB_MON => sl_mon_init, sl_mon_cycle;
            $crate::blocks::boolean::and::FB_AND => sl_and_init, sl_and_cycle;
            $crate::blocks::boolean::or::FB_OR => sl_or_init, sl_or_cycle;
            $crate::blocks::boolean::xor::FB_XOR => sl_xor_init, sl_xor_cycle;
            $crate::blocks::boolean::decouple::FB_DECOUPLE => sl_decouple_init, sl_decouple_cycle;
            $crate::blocks::boolean::opmode::FB_OPMODE => sl_opmode_init, sl_opmode_cycle;
            $crate::blocks::boolean::twohand::FB_TWOHAND => sl_twohand_init, sl_twohand_cycle;
            $crate::blocks::boolean::muting::FB_MUTING => sl_muting_init, sl_muting_cycle;
            $crate::blocks::boolean::edm::FB_EDM => sl_edm_init, sl_edm_cycle;
            $crate::blocks::boolean::rs::FB_RS => sl_rs_init, sl_rs_cycle;
            $crate::blocks::boolean::sr::FB_SR => sl_sr_init, sl_sr_cycle;
            $crate::blocks::boolean::ton::FB_TON => sl_ton_init, sl_ton_cycle;
            $crate::blocks::boolean::ton2::FB_TON2 => sl_ton2_init, sl_ton2_cycle;
            $crate::blocks::boolean::tof::FB_TOF => sl_tof_init, sl_tof_cycle;
            $crate::blocks::analog::arith::FB_ADD_INT => sl_add_int_init, sl_add_int_cycle;
            $crate::blocks::analog::arith::FB_ADD_UINT => sl_add_uint_init, sl_add_uint_cycle;
            $crate::blocks::analog::arith::FB_ADD_DINT => sl_add_dint_init, sl_add_dint_cycle;
            $crate::blocks::analog::arith::FB_ADD_UDINT => sl_add_udint_init, sl_add_udint_cycle;
            $crate::blocks::analog::arith::FB_SUB_INT => sl_sub_int_init, sl_sub_int_cycle;
            $crate::blocks::analog::arith::FB_SUB_UINT => sl_sub_uint_init, sl_sub_uint_cycle;
            $crate::blocks::analog::arith::FB_SUB_DINT => sl_sub_dint_init, sl_sub_dint_cycle;
            $crate::blocks::analog::arith::FB_SUB_UDINT => sl_sub_udint_init, sl_sub_udint_cycle;
            $crate::blocks::analog::arith::FB_MUL_INT => sl_mul_int_init, sl_mul_int_cycle;
            $crate::blocks::analog::arith::FB_MUL_UINT => sl_mul_uint_init, sl_mul_uint_cycle;
            $crate::blocks::analog::arith::FB_MUL_DINT => sl_mul_dint_init, sl_mul_dint_cycle;
            $crate::blocks::analog::arith::FB_MUL_UDINT => sl_mul_udint_init, sl_mul_udint_cycle;
            $crate::blocks::analog::arith::FB_DIV_INT => sl_div_int_init, sl_div_int_cycle;
            $crate::blocks::analog::arith::FB_DIV_UINT => sl_div_uint_init, sl_div_uint_cycle;
            $crate::blocks::analog::arith::FB_DIV_DINT => sl_div_dint_init, sl_div_dint_cycle;
            $crate::blocks::analog::arith::FB_DIV_UDINT => sl_div_udint_init, sl_div_udint_cycle;
            $crate::blocks::analog::compare::FB_COMPARE_INT => sl_compare_int_init, sl_compare_int_cycle;
            $crate::blocks::analog::compare::FB_COMPARE_UINT => sl_compare_uint_init, sl_compare_uint_cycle;
            $crate::blocks::analog::compare::FB_COMPARE_DINT => sl_compare_dint_init, sl_compare_dint_cycle;
            $crate::blocks::analog::compare::FB_COMPARE_UDINT => sl_compare_udint_init, sl_compare_udint_cycle;
            $crate::blocks::analog::limit::FB_LIMIT_INT => sl_limit_int_init, sl_limit_int_cycle;
            $crate::blocks::analog::limit::FB_LIMIT_UINT => sl_limit_uint_init, sl_limit_uint_cycle;
            $crate::blocks::analog::limit::FB_LIMIT_DINT => sl_limit_dint_init, sl_limit_dint_cycle;
            $crate::blocks::analog::limit::FB_LIMIT_UDINT => sl_limit_udint_init, sl_limit_udint_cycle;
            $crate::blocks::analog::scale::FB_SCALE_INT => sl_scale_int_init, sl_scale_int_cycle;
            $crate::blocks::analog::scale::FB_SCALE_UINT => sl_scale_uint_init, sl_scale_uint_cycle;
            $crate::blocks::analog::scale::FB_SCALE_DINT => sl_scale_dint_init, sl_scale_dint_cycle;
            $crate::blocks::analog::scale::FB_SCALE_UDINT => sl_scale_udint_init, sl_scale_udint_cycle;
            $crate::blocks::analog::speed::FB_SPEED_INT => sl_speed_int_init, sl_speed_int_cycle;
            $crate::blocks::analog::speed::FB_SPEED_UINT => sl_speed_uint_init, sl_speed_uint_cycle;
            $crate::blocks::analog::speed::FB_SPEED_DINT => sl_speed_dint_init, sl_speed_dint_cycle;
            $crate::blocks::analog::speed::FB_SPEED_UDINT => sl_speed_udint_init, sl_speed_udint_cycle;
            $crate::blocks::analog::loadsensing::FB_LOADSENSING_INT => sl_loadsensing_int_init, sl_loadsensing_int_cycle;
            $crate::blocks::analog::loadsensing::FB_LOADSENSING_UINT => sl_loadsensing_uint_init, sl_loadsensing_uint_cycle;
            $crate::blocks::analog::loadsensing::FB_LOADSENSING_DINT => sl_loadsensing_dint_init, sl_loadsensing_dint_cycle;
            $crate::blocks::analog::loadsensing::FB_LOADSENSING_UDINT => sl_loadsensing_udint_init, sl_loadsensing_udint_cycle;
            $crate::blocks::analog::envelope::FB_ENVELOPE_INT => sl_envelope_int_init, sl_envelope_int_cycle;
            $crate::blocks::analog::envelope::FB_ENVELOPE_UINT => sl_envelope_uint_init, sl_envelope_uint_cycle;
            $crate::blocks::analog::envelope::FB_ENVELOPE_DINT => sl_envelope_dint_init, sl_envelope_dint_cycle;
            $crate::blocks::analog::envelope::FB_ENVELOPE_UDINT => sl_envelope_udint_init, sl_envelope_udint_cycle;
            $crate::blocks::analog::counter::FB_COUNTER_INT => sl_counter_int_init, sl_counter_int_cycle;
            $crate::blocks::analog::counter::FB_COUNTER_UINT => sl_counter_uint_init, sl_counter_uint_cycle;
            $crate::blocks::analog::counter::FB_COUNTER_DINT => sl_counter_dint_init, sl_counter_dint_cycle;
            $crate::blocks::analog::counter::FB_COUNTER_UDINT => sl_counter_udint_init, sl_counter_udint_cycle;
            $crate::blocks::analog::sli::FB_SLI_INT => sl_sli_int_init, sl_sli_int_cycle;
            $crate::blocks::analog::sli::FB_SLI_UINT => sl_sli_uint_init, sl_sli_uint_cycle;
            $crate::blocks::analog::sli::FB_SLI_DINT => sl_sli_dint_init, sl_sli_dint_cycle;
            $crate::blocks::analog::sli::FB_SLI_UDINT => sl_sli_udint_init, sl_sli_udint_cycle;
            $crate::blocks::analog::sli2::FB_SLI2_INT => sl_sli2_int_init, sl_sli2_int_cycle;
            $crate::blocks::analog::sli2::FB_SLI2_UINT => sl_sli2_uint_init, sl_sli2_uint_cycle;
            $crate::blocks::analog::sli2::FB_SLI2_DINT => sl_sli2_dint_init, sl_sli2_dint_cycle;
            $crate::blocks::analog::sli2::FB_SLI2_UDINT => sl_sli2_udint_init, sl_sli2_udint_cycle;
            $crate::blocks::analog::violationcounter::FB_VIOLATIONCOUNTER_UINT => sl_violationcounter_uint_init, sl_violationcounter_uint_cycle;
            $crate::blocks::analog::violationcounter::FB_VIOLATIONCOUNTER_UDINT => sl_violationcounter_udint_init, sl_violationcounter_udint_cycle;
            $crate::blocks::motion::cammonitor::FB_CAMMONITOR_UINT => sl_cammonitor_uint_init, sl_cammonitor_uint_cycle;
            $crate::blocks::motion::cammonitor::FB_CAMMONITOR_UDINT => sl_cammonitor_udint_init, sl_cammonitor_udint_cycle;
            $crate::blocks::motion::slp::FB_SLP => sl_slp_init, sl_slp_cycle;
            $crate::blocks::motion::sbt::FB_SBT => sl_sbt_init, sl_sbt_cycle;
            $crate::blocks::motion::advposmon::FB_ADVPOSMON => sl_advposmon_init, sl_advposmon_cycle;
            $crate::blocks::connection::connshutdown::FB_CONNECTION_SHUTDOWN => sl_connection_shutdown_init, sl_connection_shutdown_cycle;
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
            $crate::blocks::plcopen::emergencystop::SF_EmergencyStop => sl_sf_emergencystop_init, sl_sf_emergencystop_cycle;
            $crate::blocks::plcopen::espe::SF_ESPE => sl_sf_espe_init, sl_sf_espe_cycle;
            $crate::blocks::plcopen::pse::SF_PSE => sl_sf_pse_init, sl_sf_pse_cycle;
            $crate::blocks::plcopen::equivalent::SF_Equivalent => sl_sf_equivalent_init, sl_sf_equivalent_cycle;
            $crate::blocks::plcopen::antivalent::SF_Antivalent => sl_sf_antivalent_init, sl_sf_antivalent_cycle;
            $crate::blocks::plcopen::guard::SF_Guard => sl_sf_guard_init, sl_sf_guard_cycle;
            $crate::blocks::plcopen::safetyrequest::SF_SafetyRequest => sl_sf_safetyrequest_init, sl_sf_safetyrequest_cycle;
            $crate::blocks::plcopen::outcontrol::SF_OutControl => sl_sf_outcontrol_init, sl_sf_outcontrol_cycle;
            $crate::blocks::plcopen::resetbutton::SF_ResetButton => sl_sf_resetbutton_init, sl_sf_resetbutton_cycle;
            $crate::blocks::plcopen::edm::SF_EDM => sl_sf_edm_init, sl_sf_edm_cycle;
            $crate::blocks::plcopen::testablesafetysensor::SF_TestableSafetySensor => sl_sf_testablesafetysensor_init, sl_sf_testablesafetysensor_cycle;
            $crate::blocks::plcopen::enableswitch::SF_EnableSwitch => sl_sf_enableswitch_init, sl_sf_enableswitch_cycle;
            $crate::blocks::plcopen::twohandcontroltypeii::SF_TwoHandControlTypeII => sl_sf_twohandcontroltypeii_init, sl_sf_twohandcontroltypeii_cycle;
            $crate::blocks::plcopen::twohandcontroltypeiii::SF_TwoHandControlTypeIII => sl_sf_twohandcontroltypeiii_init, sl_sf_twohandcontroltypeiii_cycle;
            $crate::blocks::plcopen::modeselector::SF_ModeSelector => sl_sf_modeselector_init, sl_sf_modeselector_cycle;
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

/// The block type with this tag.
pub fn info(tag: u16) -> Option<&'static BlockInfo> {
    crate::registry::block_type(tag).map(|b| &b.info)
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
