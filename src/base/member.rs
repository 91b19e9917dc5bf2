//! A block as a group member: the [`Member`] interface the group runs every block and
//! connection through, what a member reports after a cycle ([`Ran`], [`RanWord`],
//! [`ConnReport`]), the FSoE wiring of one group cycle ([`Wiring`]), and the macros that
//! implement it for a block struct (`impl_member!`, `impl_sf_member!`). It lives below the
//! blocks so that blocks, the FSoE connection and the group all build on it; the group
//! itself (`crate::group`) is the layer that runs members.

use crate::base::block::Field;
use crate::base::types::*;

/// A block as a member of a group. Implemented for every block by `impl_member!`.
pub trait Member {
    /// Drives bRun and bErrAck from the group.
    fn drive(&mut self, run: u8, ack: u8);
    /// One cycle of the block (`sl_<name>_cycle`).
    fn execute(&mut self, now: u32) -> Status;
    /// The block's nState.
    fn state(&self) -> u8;
    /// The block's field table (the registry's).
    fn fields(&self) -> &'static [Field];
    /// The BOOL input at this byte offset, if the block has one there.
    fn input_mut(&mut self, offset: u16) -> Option<&mut u8>;
    /// The BOOL output at this byte offset, if the block has one there.
    fn output(&self, offset: u16) -> Option<u8>;
    /// The output at this byte offset as a 32-bit pattern, if the block has one there.
    fn output_bits(&self, offset: u16) -> Option<u32>;
    /// Writes the input at this byte offset from a pattern of the same type; false when the
    /// block has no input there.
    fn set_input_bits(&mut self, offset: u16, bits: u32) -> bool;
    /// Any named field (the field table's) at this byte offset as a 32-bit pattern.
    fn field_bits(&self, offset: u16) -> Option<u32>;
    /// Writes the parameter at this byte offset; false when the block has none there.
    fn set_param_bits(&mut self, offset: u16, bits: u32) -> bool;
    /// One cycle as a member: bRun/bErrAck from the group, then the block's cycle; returns
    /// the status, the new nState and, for an FSoE connection, what the group reads of it
    /// (one dynamic call instead of several). `w` carries the FSoE wiring of the cycle
    /// (connections seen so far, a CONNECTION SHUTDOWN block's request).
    fn run_in_group(&mut self, run: u8, ack: u8, now: u32, w: &mut Wiring) -> Ran {
        let _ = w;
        self.drive(run, ack);
        let status = self.execute(now);
        Ran {
            status,
            state: self.state(),
            conn: None,
        }
    }
    /// [`Member::run_in_group`] as the sealed schedule's runners return it ([`RanWord`]).
    /// A block's own form runs the fast path inline and reaches the rest of the cycle by a
    /// tail call ([`settle_word`]), so the runner needs no stack frame when the fast path
    /// serves the call.
    fn run_word(&mut self, run: u8, ack: u8, now: u32, w: &mut Wiring) -> RanWord {
        let r = self.run_in_group(run, ack, now, w);
        Ran::word(r.status, r.state)
    }
    /// The (received, sent) SafeData bits an RXBIT / TXBIT link may name: those of an FSoE
    /// connection; none of a block.
    fn safe_data_bits(&self) -> (u16, u16) {
        (0, 0)
    }
    /// Bit `bit` of a connection's received SafeData (0/1; 0 unless the data are valid);
    /// nothing of a block.
    fn rx_bit(&self, _bit: u16) -> Option<u8> {
        None
    }
    /// Writes bit `bit` of a connection's SafeData to send (nothing for a block, or beyond
    /// the SafeData).
    fn set_tx_bit(&mut self, _bit: u16, _value: u8) {}
}

/// What a member reports after one cycle in a group.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ran {
    /// The cycle's status.
    pub status: Status,
    /// The new nState.
    pub state: u8,
    /// An FSoE connection's report (`None` for a block).
    pub conn: Option<ConnReport>,
}

/// A block's [`Ran`] as one word, as the sealed schedule's runners return it (in a
/// register, where `Option<Ran>` goes through memory): the state in bits 0–7, the low byte
/// of the status code in bits 8–15 (0: SL_OK), or one of the flags above them.
pub type RanWord = u32;

/// [`RanWord`] flag: the member's block failed its pointer check (not run).
pub const RAN_UNREACHABLE: RanWord = 1 << 16;
/// [`RanWord`] flag: the member is not a block the schedule runs straight (an FSoE
/// connection, or storage without runners): not run, the member loop runs it.
pub const RAN_NOT_RUN: RanWord = 1 << 17;
/// [`RanWord`] flag: the block ran and its outcome is in the word, but the member loop
/// must see it (a CONNECTION SHUTDOWN block: it may have left a request for the group).
pub const RAN_HAND_BACK: RanWord = 1 << 18;
// Three distinct flags above the status byte: `run_straight` tells a flag or a status other
// than SL_OK from every plain outcome by one `word >> 8 != 0`.
const _: () =
    assert!(RAN_UNREACHABLE >> 16 == 1 && RAN_NOT_RUN >> 16 == 2 && RAN_HAND_BACK >> 16 == 4);

impl Ran {
    /// The word of a block's outcome (a block reports no connection). Every status code
    /// is in -12..=0, so its low byte gives it back.
    #[inline(always)]
    pub const fn word(status: Status, state: u8) -> RanWord {
        state as u32 | (status.code() as u8 as u32) << 8
    }

    /// The outcome of a word that is not [`RAN_NOT_RUN`]: `None` for [`RAN_UNREACHABLE`].
    pub const fn of_word(word: RanWord) -> Option<Ran> {
        if word & RAN_UNREACHABLE != 0 {
            return None;
        }
        Some(Ran {
            status: Status::from_code((word >> 8) as u8 as i8 as i32),
            state: word as u8,
            conn: None,
        })
    }
}

/// The rest of a block's cycle when its fast path did not serve the call, with the outcome
/// as a [`RanWord`]: out of line, so that the runner reaches it by a tail call.
#[inline(never)]
pub fn settle_word<B: crate::base::envelope::Block + Member>(fb: &mut B, now: u32) -> RanWord {
    let status = fb.settle(now);
    Ran::word(status, fb.state())
}

/// What the group reads of an FSoE connection after its cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ConnReport {
    /// bComErr.
    pub com_err: bool,
    /// bComStartup.
    pub startup: bool,
    /// bShutdown (105/106 until DATA again).
    pub shutdown: bool,
    /// The latched Connection ID.
    pub id: u16,
}

/// Largest number of FSoE connections in one group whose shutdown is wired to a
/// FB_CONNECTION_SHUTDOWN (`sl_group_add_member` refuses more with SL_E_FULL).
pub const SL_GROUP_CONN_MAX: u16 = 16;

/// The FSoE wiring of one group cycle (ABI-2 §13.5): the connections that ran so far
/// (member index, Connection ID, bShutdown) and the request of the CONNECTION SHUTDOWN block
/// that just ran, which the group copies to the connection(s) with its Connection ID.
#[derive(Clone, Copy, Debug, Default)]
pub struct Wiring {
    conns: [(u16, u16, bool); SL_GROUP_CONN_MAX as usize],
    n: usize,
    request: Option<(u16, u8)>,
}

impl Wiring {
    /// Records connection member `index` (each connection reports once per cycle, in the
    /// member loop; at most SL_GROUP_CONN_MAX are wired).
    pub fn connection(&mut self, index: u16, r: &ConnReport) {
        if let Some(e) = self.conns.get_mut(self.n) {
            *e = (index, r.id, r.shutdown);
            self.n += 1;
        }
    }
    /// bShutdown of the connection(s) with Connection ID `id` (FALSE when none ran yet).
    pub fn conn_shutdown(&self, id: u16) -> u8 {
        u8::from(self.conns[..self.n].iter().any(|e| e.1 == id && e.2))
    }
    /// A CONNECTION SHUTDOWN block's bShutdownRequest for Connection ID `id`.
    pub fn request(&mut self, id: u16, value: u8) {
        self.request = Some((id, value));
    }
    /// A CONNECTION SHUTDOWN block left a request in this cycle.
    #[inline(always)]
    pub fn has_request(&self) -> bool {
        self.request.is_some()
    }
    /// The pending request with the member indices of its connections.
    pub(crate) fn take_request(
        &mut self,
    ) -> Option<(u8, [u16; SL_GROUP_CONN_MAX as usize], usize)> {
        let (id, v) = self.request.take()?;
        let mut idx = [0u16; SL_GROUP_CONN_MAX as usize];
        let mut k = 0;
        for e in self.conns[..self.n].iter().filter(|e| e.1 == id) {
            idx[k] = e.0;
            k += 1;
        }
        Some((v, idx, k))
    }
}

/// The `Cyclic` impl of a member: its magic and the five cycle entry points from the
/// family's envelope (`base::envelope` or `base::sf`), then the block's own methods. The
/// same code as written out: the entry points stay `#[inline(always)]` calls.
macro_rules! impl_cyclic {
    ([$($gen:tt)*] $ty:ty {
        magic: $magic:expr,
        init: $init:path,
        cycle: $cycle:path,
        fast: $fast:path,
        settle: $settle:path,
        force: $force:path,
        $($own:tt)*
    }) => {
        impl<$($gen)*> $crate::base::block::Cyclic for $ty {
            const MAGIC: u16 = $magic;
            fn init_fb(&mut self) -> $crate::base::types::Status {
                $init(self)
            }
            #[inline(always)]
            fn cycle_fb(&mut self, now: u32) -> $crate::base::types::Status {
                $cycle(self, now)
            }
            #[inline(always)]
            fn cycle_fast(&mut self, now: u32) -> bool {
                $fast(self, now)
            }
            #[inline(always)]
            fn cycle_rest(&mut self, now: u32) -> $crate::base::types::Status {
                $settle(self, now)
            }
            fn force_safe(&mut self) {
                $force(self)
            }
            $($own)*
        }
    };
}
pub(crate) use impl_cyclic;

/// Implements the envelope's `Instance`, the group's [`Member`] and the registry's
/// `Registered` for a block struct, from its info and the lists of its fields by direction
/// (`bRun`/`bErrAck` and `nState`/`nDiag` are added: every block has them at the same
/// names). `[generics]` are the impl's generic parameters (empty for a plain struct).
#[doc(hidden)]
#[macro_export]
macro_rules! impl_member {
    ([$($gen:tt)*] $ty:ty {
        info: $info:expr,
        state: $state:ty,
        private: $private:ty,
        $(table_params: [$($t:ident),* $(,)?],)?
        input: [$($i:ident),* $(,)?],
        param: [$($p:ident),* $(,)?],
        output: [$($o:ident),* $(,)?],
        info_fields: [$($n:ident),* $(,)?] $(,)?
        $(wiring: ($before:path, $after:path) $(,)?)?
    }) => {
        impl<$($gen)*> $crate::base::envelope::Instance for $ty {
            #[inline(always)]
            fn header(&self) -> &$crate::base::header::SL_PRIVATE_HEADER {
                &self.stPrivate.stHeader
            }
            #[inline(always)]
            fn header_mut(&mut self) -> &mut $crate::base::header::SL_PRIVATE_HEADER {
                &mut self.stPrivate.stHeader
            }
            fn clear_private(&mut self) {
                self.stPrivate = Default::default();
            }
            #[inline(always)]
            fn run_raw(&self) -> u8 {
                self.bRun
            }
            #[inline(always)]
            fn errack_raw(&self) -> u8 {
                self.bErrAck
            }
        }
        $crate::base::member::impl_cyclic!([$($gen)*] $ty {
            magic: <Self as $crate::base::envelope::Block>::MAGIC,
            init: $crate::base::envelope::init,
            cycle: $crate::base::envelope::cycle,
            fast: $crate::base::envelope::Block::fast,
            settle: $crate::base::envelope::Block::settle,
            force: $crate::base::envelope::force_error,
            fn in_error(&self) -> bool {
                self.nState == $crate::base::types::SL_STATE_ERROR
            }
            fn refusal(&self) -> Option<$crate::base::reason::Refusal> {
                $crate::base::reason::check(
                    <Self as $crate::base::envelope::Block>::RULES,
                    &$crate::base::envelope::Block::live_params(self),
                )
            }
            fn rule(i: usize) -> Option<$crate::base::reason::RuleInfo> {
                <Self as $crate::base::envelope::Block>::RULES.get(i).map(|r| r.info)
            }
        });
        impl<$($gen)*> $crate::base::block::Private for $ty {
            type P = $private;
            #[inline(always)]
            fn private(&self) -> &$private {
                &self.stPrivate
            }
            #[inline(always)]
            fn private_mut(&mut self) -> &mut $private {
                &mut self.stPrivate
            }
        }
        impl<$($gen)*> $crate::base::block::Registered for $ty {
            const INFO: $crate::base::block::BlockInfo = $info;
            type State = $state;
            const FIELDS: &'static [$crate::base::block::Field] = &[
                $($crate::impl_member!(@field $i, Input, io_kind)),*
                , $crate::impl_member!(@field bRun, Control, io_kind)
                , $crate::impl_member!(@field bErrAck, Control, io_kind)
                $(, $crate::impl_member!(@field $p, Param, same))*
                $(, $crate::impl_member!(@field $o, Output, io_kind))*
                , $crate::impl_member!(@field nState, Info, same)
                , $crate::impl_member!(@field nDiag, Info, same)
                $(, $crate::impl_member!(@field $n, Info, same))*
            ];
            $(const TABLE_PARAMS: &'static [(usize, usize)] = &[$((
                core::mem::offset_of!(Self, $t),
                $crate::base::block::size_of_field(|s: &Self| &s.$t),
            )),*];)?
        }
        impl<$($gen)*> $crate::base::member::Member for $ty {
            fn drive(&mut self, run: u8, ack: u8) {
                self.bRun = run;
                self.bErrAck = ack;
            }
            fn execute(&mut self, now: u32) -> $crate::base::types::Status {
                $crate::base::envelope::cycle(self, now)
            }
            fn state(&self) -> u8 {
                self.nState
            }
            $crate::impl_member!(@access [$($i),*] [$($p),*] [$($o),*]);
            fn field_bits(&self, offset: u16) -> Option<u32> {
                $crate::impl_member!(@read self, offset,
                    $($i,)* bRun, bErrAck, $($p,)* $($o,)* nState, nDiag $(, $n)*)
            }
            // Always inline: the sealed schedule's runner (`run_as`) is then one function,
            // the block's fast path included.
            #[inline(always)]
            fn run_in_group(
                &mut self,
                run: u8,
                ack: u8,
                now: u32,
                w: &mut $crate::base::member::Wiring,
            ) -> $crate::base::member::Ran {
                // A block wired to its connection by Connection ID (FB_CONNECTION_SHUTDOWN,
                // ABI-2 §13.5) names what it does before and after its cycle.
                let _ = &w;
                $($before(self, w);)?
                self.drive(run, ack);
                // The envelope's cycle itself (not `execute`): its fast path then inlines
                // into the sealed schedule's runner, as into the C function.
                let status = $crate::base::envelope::cycle(self, now);
                $($after(self, w);)?
                $crate::base::member::Ran {
                    status,
                    state: self.nState,
                    conn: None,
                }
            }
            #[inline(always)]
            fn run_word(
                &mut self,
                run: u8,
                ack: u8,
                now: u32,
                w: &mut $crate::base::member::Wiring,
            ) -> $crate::base::member::RanWord {
                // A wired block runs through `run_in_group` (its wiring around the cycle).
                let _ = &w;
                $(if $crate::impl_member!(@wired $before) {
                    let r = self.run_in_group(run, ack, now, w);
                    return $crate::base::member::Ran::word(r.status, r.state);
                })?
                self.drive(run, ack);
                if $crate::base::envelope::Block::fast(self, now) {
                    return $crate::base::member::Ran::word($crate::base::types::Status::Ok, self.nState);
                }
                $crate::base::member::settle_word(self, now)
            }
        }
    };
    (@wired $before:path) => {
        true
    };
    (@read $s:ident, $offset:ident, $($f:ident),*) => {{
        $(if usize::from($offset) == core::mem::offset_of!(Self, $f) {
            return Some($crate::base::block::FieldType::to_bits($s.$f));
        })*
        None
    }};
    // The field accessors of `Member` from the field lists, the same in both families
    // (`impl_sf_member!` uses them too).
    (@access [$($i:ident),*] [$($p:ident),*] [$($o:ident),*]) => {
        fn fields(&self) -> &'static [$crate::base::block::Field] {
            <Self as $crate::base::block::Registered>::FIELDS
        }
        fn input_mut(&mut self, offset: u16) -> Option<&mut u8> {
            $(if usize::from(offset) == core::mem::offset_of!(Self, $i) {
                return $crate::base::block::FieldType::as_bool_mut(&mut self.$i);
            })*
            None
        }
        fn output(&self, offset: u16) -> Option<u8> {
            $(if usize::from(offset) == core::mem::offset_of!(Self, $o) {
                return $crate::base::block::FieldType::as_bool(self.$o);
            })*
            None
        }
        fn output_bits(&self, offset: u16) -> Option<u32> {
            $(if usize::from(offset) == core::mem::offset_of!(Self, $o) {
                return Some($crate::base::block::FieldType::to_bits(self.$o));
            })*
            None
        }
        fn set_input_bits(&mut self, offset: u16, bits: u32) -> bool {
            $(if usize::from(offset) == core::mem::offset_of!(Self, $i) {
                self.$i = $crate::base::block::FieldType::from_bits(bits);
                return true;
            })*
            false
        }
        fn set_param_bits(&mut self, offset: u16, bits: u32) -> bool {
            $(if usize::from(offset) == core::mem::offset_of!(Self, $p) {
                self.$p = $crate::base::block::FieldType::from_bits(bits);
                return true;
            })*
            false
        }
    };
    (@field $f:ident, $dir:ident, $k:ident) => {
        $crate::base::block::Field {
            name: stringify!($f),
            offset: core::mem::offset_of!(Self, $f) as u16,
            kind: $crate::base::block::$k(stringify!($f), $crate::base::block::kind_of(|s: &Self| &s.$f)),
            dir: $crate::base::block::Dir::$dir,
        }
    };
}

/// `impl_member!` for a PLCopen `SF_` block (`base::sf`): the envelope's `SfInstance`, the
/// registry's `Registered` and `Cyclic`, the group's [`Member`]. The block has no
/// bRun/bErrAck: the group halts it through its private state (`nGroupHalt`: DiagCode
/// 0000, as with Activate FALSE) and never acknowledges it; the member state the group
/// reads is the block's [`crate::base::sf::SfPhase`]. `DiagCode` is added as info field.
#[doc(hidden)]
#[macro_export]
macro_rules! impl_sf_member {
    ($ty:ty {
        tag: $tag:expr,
        input: [$($i:ident),* $(,)?],
        param: [$($p:ident),* $(,)?],
        output: [$($o:ident),* $(,)?] $(,)?
        $(activate: $act:ident $(,)?)?
    }) => {
        impl $crate::base::sf::SfInstance for $ty {
            #[inline(always)]
            fn sf_private(&self) -> &$crate::base::sf::SL_SF_PRIVATE {
                &self.stPrivate
            }
            #[inline(always)]
            fn sf_private_mut(&mut self) -> &mut $crate::base::sf::SL_SF_PRIVATE {
                &mut self.stPrivate
            }
            #[inline(always)]
            fn activate_raw(&self) -> u8 {
                $crate::impl_sf_member!(@activate self $(, $act)?)
            }
            fn set_activate_raw(&mut self, v: u8) {
                $crate::impl_sf_member!(@activate self $(, $act)?) = v;
            }
        }
        impl $ty {
            /// The current state (`None`: a library fault, or a corrupt private state).
            pub fn diag_state(&self) -> Option<<Self as $crate::base::sf::SfBlock>::Diag> {
                <<Self as $crate::base::sf::SfBlock>::Diag as $crate::base::sf::DiagState>::decode(
                    self.stPrivate.stHeader.wDiag,
                )
            }
        }
        $crate::base::member::impl_cyclic!([] $ty {
            magic: <Self as $crate::base::sf::SfBlock>::MAGIC,
            init: $crate::base::sf::init,
            cycle: $crate::base::sf::cycle,
            fast: $crate::base::sf::fast,
            settle: $crate::base::sf::settle,
            force: $crate::base::sf::force_fault,
            fn in_error(&self) -> bool {
                self.DiagCode >= 0xC000
            }
            fn refusal(&self) -> Option<$crate::base::reason::Refusal> {
                $crate::base::sf::refusal::<Self>(&$crate::base::sf::SfBlock::live_consts(self))
            }
            fn rule(i: usize) -> Option<$crate::base::reason::RuleInfo> {
                $crate::base::sf::rules::<Self>().nth(i).map(|r| r.info)
            }
        });
        impl $crate::base::block::Registered for $ty {
            // The name is the struct's (the PLCopen FB name), the DiagCode texts are its
            // states'; the group-level states are the family's.
            const INFO: $crate::base::block::BlockInfo =
                $crate::base::block::BlockInfo::of::<$crate::base::sf::SfPhase>($tag, stringify!($ty))
                    .diag_values(<<$ty as $crate::base::sf::SfBlock>::Diag as $crate::base::sf::DiagState>::TEXTS);
            type State = $crate::base::sf::SfPhase;
            const FIELDS: &'static [$crate::base::block::Field] = &[
                $($crate::impl_member!(@field $i, Input, io_kind),)*
                // A one-byte PLCopen constant is a BOOL (StaticControl, AutoSetMode) unless
                // named as a number (nDiagProfile), as inputs and outputs are.
                $($crate::impl_member!(@field $p, Param, io_kind),)*
                $($crate::impl_member!(@field $o, Output, io_kind),)*
                $crate::impl_member!(@field DiagCode, Info, same)
            ];
        }
        impl $crate::base::member::Member for $ty {
            fn drive(&mut self, run: u8, _ack: u8) {
                self.stPrivate.nGroupHalt = u8::from(run != 1);
            }
            fn execute(&mut self, now: u32) -> $crate::base::types::Status {
                $crate::base::sf::cycle(self, now)
            }
            fn state(&self) -> u8 {
                self.stPrivate.stHeader.nState
            }
            $crate::impl_member!(@access [$($i),*] [$($p),*] [$($o),*]);
            fn field_bits(&self, offset: u16) -> Option<u32> {
                $crate::impl_member!(@read self, offset, $($i,)* $($p,)* $($o,)* DiagCode)
            }
        }
    };
    // The field that activates the block: `Activate`, or the one named (SF_ResetButton's
    // `ResetRequested`).
    (@activate $s:ident) => {
        $s.Activate
    };
    (@activate $s:ident, $act:ident) => {
        $s.$act
    };
}
