//! The C ABI (ABI.md §4, §5). Every exported function runs inside `ffi_boundary!`, the one
//! place that catches panics; instance pointers pass through `instance`, the one place that
//! checks NULL and alignment. Nothing else in the crate is `unsafe`.
#![allow(unsafe_code)]

use crate::base::block::{family, Cyclic, Family, Registered};
use crate::base::header::SL_PRIVATE_HEADER;
use crate::base::member::Member;
use crate::base::types::*;
use crate::blocks::boolean::ton2::FB_TON2;
use crate::blocks::plcopen::{antivalent::SF_Antivalent, resetbutton::SF_ResetButton};
use crate::fsoe::SL_TYPE_FSOE_CONN;
use crate::fsoe::{conn::SL_FSOE_CONN, frame::SL_FSOE_FRAME};
use crate::group::{self, Members, SL_LINK_BOOL};
use crate::group::{SL_GROUP, SL_LINK, SL_MEMBER};
use core::ffi::{c_char, c_void};

/// Runs `$body`; a panic becomes `$on_panic` instead of unwinding into C.
macro_rules! ffi_boundary {
    ($on_panic:expr, $body:expr) => {
        match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| $body)) {
            Ok(v) => v,
            Err(_) => $on_panic,
        }
    };
}

/// Turns an instance pointer into a reference, or the status code that refuses it.
fn instance<'a, B>(p: *mut B) -> Result<&'a mut B, i32> {
    if p.is_null() || !p.is_aligned() {
        return Err(refusal(p as usize));
    }
    // SAFETY: `p` is non-null and aligned; the caller guarantees (ABI §4) that it points to
    // a live instance of `B` that nothing else accesses during the call. `B` holds only
    // integer fields, so every byte pattern in it is a valid value.
    Ok(unsafe { &mut *p })
}

/// The status code of a refused instance pointer (NULL or misaligned): out of line, so the
/// accepted pointer costs one test of each kind and no code for the choice.
#[cold]
#[inline(never)]
fn refusal(addr: usize) -> i32 {
    if addr == 0 {
        SL_E_NULL
    } else {
        SL_E_ALIGNMENT
    }
}

/// Turns a read-only instance pointer into a shared reference, or the status code that
/// refuses it (NULL, misaligned).
fn instance_ref<'a, B>(p: *const B) -> Result<&'a B, i32> {
    if p.is_null() || !p.is_aligned() {
        return Err(refusal(p as usize));
    }
    // SAFETY: `p` is non-null and aligned; the caller guarantees (ABI §4) that it points to
    // a live instance of `B` that nobody writes during the call. `B` holds only integer
    // fields, so every byte pattern in it is a valid value.
    Ok(unsafe { &*p })
}

/// One call of a block function behind the panic boundary ([`guarded`]), after the
/// pointer check.
fn block_call<B: Cyclic>(p: *mut B, f: impl FnOnce(&mut B) -> i32) -> i32 {
    match instance(p) {
        Ok(fb) => guarded(fb, f),
        Err(e) => e,
    }
}

/// Runs `f` on the instance behind the panic boundary. After a caught panic the instance is
/// forced into ERROR with safe outputs.
#[inline(always)]
fn guarded<B: Cyclic>(fb: &mut B, f: impl FnOnce(&mut B) -> i32) -> i32 {
    ffi_boundary!(
        {
            ffi_boundary!((), fb.force_safe());
            SL_E_INTERNAL
        },
        f(&mut *fb)
    )
}

/// `sl_<name>_cycle`: the fast path inline, the rest of the cycle through [`cycle_rest`]
/// (a type without a fast path goes there at once). The fast path cannot panic and
/// `cycle_rest` cannot unwind (an `extern "C"` function), so the boundary costs nothing
/// here and the fast path needs no stack frame; a panic of the full cycle is caught inside
/// `cycle_rest`, with the same reaction.
#[inline(always)]
fn block_cycle<B: Cyclic>(p: *mut B, now: u32) -> i32 {
    block_call(p, |fb| {
        if fb.cycle_fast(now) {
            SL_OK
        } else {
            cycle_rest(fb, now)
        }
    })
}

/// The part of a cycle the fast path did not serve, behind its own panic boundary.
#[inline(never)]
extern "C" fn cycle_rest<B: Cyclic>(fb: &mut B, now: u32) -> i32 {
    guarded(fb, |fb| fb.cycle_rest(now).code())
}

/// Static, NUL-terminated text for a status code (never NULL).
#[no_mangle]
pub extern "C" fn sl_status_str(status: i32) -> *const c_char {
    ffi_boundary!(
        status_text(SL_E_INTERNAL).as_ptr(),
        status_text(status).as_ptr()
    )
    .cast()
}

/// Static, NUL-terminated name of state `nState` of a block of type `nType`
/// (`SL_TYPE_<NAME>`): "RUN", "STOP", "DELAYOUT", ... , or of an FSoE connection
/// (`SL_TYPE_FSOE_CONN`: "RESET" … "SHUTDOWN-DEACTIVE"); "?" for a value the type does not
/// have. Never NULL.
#[no_mangle]
#[allow(non_snake_case)]
pub extern "C" fn sl_state_str(nType: u16, nState: u8) -> *const c_char {
    ffi_boundary!(
        UNKNOWN_STATE.as_ptr(),
        crate::group::states(nType)
            .and_then(|s| s.iter().find(|(v, _)| *v == nState))
            .map_or(UNKNOWN_STATE.as_ptr(), |(_, name)| name.as_ptr())
    )
    .cast()
}

const UNKNOWN_STATE: &str = "?\0";

/// Monotonic milliseconds (CLOCK_MONOTONIC), wrapping at 2^32, for hosts without a clock.
#[no_mangle]
pub extern "C" fn sl_time_now_ms() -> u32 {
    ffi_boundary!(0, {
        let mut ts = libc::timespec {
            tv_sec: 0,
            tv_nsec: 0,
        };
        // SAFETY: `ts` is a valid, writable timespec; CLOCK_MONOTONIC exists on every
        // platform this library builds for.
        let rc = unsafe { libc::clock_gettime(libc::CLOCK_MONOTONIC, &mut ts) };
        if rc != 0 {
            0
        } else {
            (ts.tv_sec as u64)
                .wrapping_mul(1000)
                .wrapping_add(ts.tv_nsec as u64 / 1_000_000) as u32
        }
    })
}

/// Library version, static and NUL-terminated ("MAJOR.MINOR.PATCH").
#[no_mangle]
pub extern "C" fn sl_version() -> *const c_char {
    ffi_boundary!(VERSION.as_ptr(), VERSION.as_ptr()).cast()
}

const VERSION: &str = concat!(env!("CARGO_PKG_VERSION"), "\0");

/// Whether this library serves a program compiled against the header of version
/// `major`.`minor`: pass `SL_VERSION_MAJOR, SL_VERSION_MINOR`. 1 when the majors are equal
/// and the header's minor is not newer than the library's (every function, struct layout
/// and constant of that header exists here unchanged: semver of the C ABI); 0 otherwise.
#[no_mangle]
pub extern "C" fn sl_version_compatible(major: u32, minor: u32) -> SL_BOOL {
    // `cmp`, not `<=`: with the minor 0 of an X.0 release, clippy rejects `minor <= 0` as an
    // absurd comparison, though the value comes from Cargo.toml and changes.
    ffi_boundary!(
        0,
        SL_BOOL::from(major == VERSION_MAJOR && minor.cmp(&VERSION_MINOR).is_le())
    )
}

const VERSION_MAJOR: u32 = decimal(env!("CARGO_PKG_VERSION_MAJOR"));
const VERSION_MINOR: u32 = decimal(env!("CARGO_PKG_VERSION_MINOR"));

/// A Cargo version part ("0", "12") as a number, at compile time.
const fn decimal(digits: &str) -> u32 {
    let b = digits.as_bytes();
    let mut v = 0;
    let mut i = 0;
    while i < b.len() {
        v = v * 10 + (b[i] - b'0') as u32;
        i += 1;
    }
    v
}

/// Writes the elapsed time an FB_TON2 has stored (ms; the manual's "ExpiredTime") to
/// `*pElapsedMs`, for the host to persist across a power cycle. Call it after
/// `sl_ton2_cycle` (every cycle, or whenever the value changed) and write the value to
/// non-volatile memory. Any state; a never-initialised instance gives 0. Returns SL_OK;
/// SL_E_NULL / SL_E_ALIGNMENT for a bad pointer; SL_E_CORRUPT (nothing written) when the
/// private state or the stored value fails its integrity check. Does not modify the block.
///
/// # Safety
/// `fb` and `pElapsedMs` are NULL or point to a live FB_TON2 / `uint32_t` that nothing writes during the call.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_ton2_get_elapsed(fb: *const FB_TON2, pElapsedMs: *mut u32) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        let run = || -> Result<i32, i32> {
            // Both pointers are checked first; the block is read through a reference that
            // ends before the result is written through the raw output pointer, so an
            // output inside the block (a caller's choice) is no aliasing.
            instance_ref(pElapsedMs.cast_const())?;
            let v =
                crate::blocks::boolean::ton2::elapsed(instance_ref(fb)?).map_err(Status::code)?;
            // SAFETY: non-null and aligned (checked above); writable by the contract.
            unsafe { pElapsedMs.write(v) };
            Ok(SL_OK)
        };
        run().unwrap_or_else(|e| e)
    })
}

/// Hands an FB_TON2 the elapsed time persisted before a power cycle. Call it after
/// `sl_ton2_init` (which resets the stored value to 0) and before the first `sl_ton2_cycle`
/// with bRun TRUE (the block must be in STOP). The value is used when TonIn next rises with Enable TRUE and
/// SL_OPT_TON2_REMAINING_TIME set: the delay then starts with tDelay - nElapsedMs.
/// Returns SL_OK (stored); SL_E_CONFIG (latched parameters invalid, nothing stored);
/// SL_E_RESTORE (nElapsedMs > the latched tDelay, the manual's global shutdown 0x3510, or
/// the block not in STOP: ERROR, diag bit 12, stored value 0); SL_E_CORRUPT (ERROR, diag
/// bit 15); SL_E_NULL / SL_E_ALIGNMENT for a bad pointer.
///
/// # Safety
/// `fb` is NULL or points to a live, caller-owned FB_TON2 that nothing else accesses during the call.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_ton2_restore_elapsed(fb: *mut FB_TON2, nElapsedMs: u32) -> i32 {
    block_call(fb, |fb| {
        crate::blocks::boolean::ton2::restore_elapsed(fb, nElapsedMs).code()
    })
}

/// The C functions of every registered block type, and the group's dispatch from type tag
/// to block: both generated from the registry's rows.
macro_rules! ffi_functions {
    ($($ty:ty => $init:ident, $cycle:ident;)*) => {
        $(
            #[doc = concat!("`", stringify!($init), "`: validates and latches the parameters and resets the block to power-up (STOP, outputs FALSE). Never modifies an input field. SL_OK or SL_E_CONFIG.")]
            ///
            /// # Safety
            /// `fb` is NULL or points to a live, caller-owned instance of the struct that
            /// nothing else accesses during the call (ABI §4).
            #[no_mangle]
            pub unsafe extern "C" fn $init(fb: *mut $ty) -> i32 {
                block_call(fb, |fb| fb.init_fb().code())
            }

            #[doc = concat!("`", stringify!($cycle), "`: one task cycle at `tNow` (monotonic ms, may wrap at 2^32).")]
            ///
            /// # Safety
            /// As for the init function.
            #[no_mangle]
            #[allow(non_snake_case)]
            pub unsafe extern "C" fn $cycle(fb: *mut $ty, tNow: u32) -> i32 {
                block_cycle(fb, tNow)
            }
        )*

        /// The dispatch from a block type tag to the block (`member_dyn` adds the FSoE
        /// connection).
        fn block_dyn<'a>(ty: u16, p: *mut c_void) -> Option<&'a mut dyn Member> {
            $(if ty == <$ty as Registered>::INFO.tag {
                return instance(p.cast::<$ty>()).ok().map(|b| b as &mut dyn Member);
            })*
            None
        }

        /// The reason sentence of the block of type `ty` at `p` (`sl_reason_text`): its
        /// length in `out`, `Err(SL_E_CONFIG)` for an unknown type, or the status of a
        /// refused pointer.
        fn reason_of(ty: u16, p: *const c_void, out: &mut [u8]) -> Result<usize, i32> {
            $(if ty == <$ty as Registered>::INFO.tag {
                let fb = instance_ref(p.cast::<$ty>())?;
                return Ok($crate::any::FunctionBlock::reason_text(fb, out));
            })*
            Err(SL_E_CONFIG)
        }

        /// [`RUNNERS`]' length: one slot per tag up to the largest.
        const RUNNER_SLOTS: usize = {
            let tags = [$(<$ty as Registered>::INFO.tag),*];
            let mut max = 0;
            let mut i = 0;
            while i < tags.len() {
                if tags[i] > max {
                    max = tags[i];
                }
                i += 1;
            }
            max as usize + 1
        };

        /// The sealed schedule's dispatch: type tag → runner (a table, not a search; a tag
        /// without a type runs nothing).
        static RUNNERS: [Runner; RUNNER_SLOTS] = {
            let mut t = [not_run as Runner; RUNNER_SLOTS];
            $(t[<$ty as Registered>::INFO.tag as usize] = run_as::<$ty> as Runner;)*
            t
        };

        /// The memory layout of every registered type, for the checks of a new member.
        fn layouts() -> [TypeLayout; [$(stringify!($ty)),*].len()] {
            [$(TypeLayout {
                tag: <$ty as Registered>::INFO.tag,
                size: core::mem::size_of::<$ty>(),
                align: core::mem::align_of::<$ty>(),
                header: {
                    let u = core::mem::MaybeUninit::<$ty>::uninit();
                    let base = u.as_ptr();
                    // SAFETY: only the address of the field is taken, nothing is read.
                    let h = unsafe { core::ptr::addr_of!((*base).stPrivate.stHeader) };
                    h as usize - base as usize
                },
                magic: <$ty as Cyclic>::MAGIC,
                init: |p| {
                    // SAFETY: `p` is a checked block of this type (add_member).
                    unsafe { $init(p.cast::<$ty>()) }
                },
            }),*]
        }
    };
}

crate::for_each_block!(ffi_functions);

/// The one dispatch from a member type tag to the member: every group operation on a
/// member goes through here.
fn member_dyn<'a>(ty: u16, p: *mut c_void) -> Option<&'a mut dyn Member> {
    if ty == SL_TYPE_FSOE_CONN {
        return instance(p.cast::<SL_FSOE_CONN>())
            .ok()
            .map(|c| c as &mut dyn Member);
    }
    block_dyn(ty, p)
}

/// What the group's member checks need of a registered type.
#[derive(Clone, Copy)]
struct TypeLayout {
    tag: u16,
    size: usize,
    align: usize,
    /// Offset of the private header (`stPrivate.stHeader`).
    header: usize,
    magic: u16,
    init: fn(*mut c_void) -> i32,
}

fn layout(ty: u16) -> Option<TypeLayout> {
    if ty == SL_TYPE_FSOE_CONN {
        // Size and alignment only: a connection is checked by its own private state
        // (`add_connection`), never by a block header.
        return Some(TypeLayout {
            tag: ty,
            size: core::mem::size_of::<SL_FSOE_CONN>(),
            align: core::mem::align_of::<SL_FSOE_CONN>(),
            header: 0,
            magic: 0,
            init: |_| SL_E_CONFIG,
        });
    }
    layouts().into_iter().find(|l| l.tag == ty)
}

/// Byte range `[p, p + len)`; `None` when it wraps the address space.
fn span(p: usize, len: usize) -> Option<(usize, usize)> {
    Some((p, p.checked_add(len)?))
}

/// Two byte ranges share no byte (either may lie below the other).
fn disjoint(a: (usize, usize), b: (usize, usize)) -> bool {
    a.0 == a.1 || b.0 == b.1 || a.1 <= b.0 || b.1 <= a.0
}

/// The caller's member table seen as group members: entries are read by value through the
/// raw pointer (no reference to the table is held while a member runs), and each entry must
/// pass its check before its block is reached.
struct CMembers {
    base: *mut SL_MEMBER,
    count: u16,
    cap: u16,
    /// The link table's capacity from the same private state, bound by every entry's check.
    link_cap: u16,
    group: usize,
}

impl CMembers {
    /// The table of `count` entries (room for `cap`) at `base` of the group at `group` whose
    /// link table has room for `link_cap`, once `storage(base, count)` accepted it.
    fn at(base: *mut SL_MEMBER, count: u16, cap: u16, link_cap: u16, group: usize) -> Self {
        CMembers {
            base,
            count,
            cap,
            link_cap,
            group,
        }
    }

    /// The shape every entry's check binds: count, capacity, link capacity.
    fn shape(&self) -> [u16; 3] {
        [self.count, self.cap, self.link_cap]
    }

    /// Entry `i`, if it is inside the count and passes its check. The count and capacity
    /// come from the group's private state: entry 0's check binds both, so entry 0 is
    /// checked before any entry past it is read (a forged count, semantics GR14, would
    /// otherwise point the read past the caller's table).
    fn entry(&self, i: usize) -> Option<SL_MEMBER> {
        if i >= usize::from(self.count) || (i > 0 && self.entry(0).is_none()) {
            return None;
        }
        // SAFETY: `base` is non-null and aligned (checked by `storage`) and points to at
        // least `cap >= count > i` entries (sl_group_init contract); read by value.
        let e = unsafe { self.base.add(i).read() };
        let check = group::member_check(
            self.group,
            self.base.wrapping_add(i) as usize,
            i as u16,
            self.shape(),
            e.pBlock as usize,
            e.nType,
        );
        (e.aReserved == check).then_some(e)
    }

    /// Entry `i` in a sealed cycle, if it is inside the count: the entry is one a fully
    /// checked cycle found intact, so its own check is not repeated.
    #[inline(always)]
    fn sealed_entry(&self, i: usize) -> Option<SL_MEMBER> {
        // SAFETY: `i < count`, and a sealed cycle's check read every entry `0..count` of
        // this table in this call (`entries`, after entry 0's own check); read by value.
        (i < usize::from(self.count)).then(|| unsafe { self.base.add(i).read() })
    }

    /// The entries `0..count` as a slice (the blocks, which run while a sealed cycle holds
    /// it, share no byte with the table: sl_group_add_member); empty when entry 0 fails its
    /// own check. The count and capacity come from the group's private state: entry 0's
    /// check binds both (and the group's and the table's addresses), so a forged count or
    /// capacity (semantics GR14) is found by reading the one entry every non-empty table
    /// has, and no slice longer than the caller's table is ever formed.
    fn entries(&self) -> &[SL_MEMBER] {
        if self.count == 0 || self.entry(0).is_none() {
            return &[];
        }
        // SAFETY: `base` is non-null and aligned (checked by `storage`) and points to at
        // least `cap >= count` entries (sl_group_init contract), which the caller does not
        // touch during the cycle; a block's bytes are none of them (checked when it was
        // added), so no write through a block pointer reaches the slice.
        unsafe { core::slice::from_raw_parts(self.base, usize::from(self.count)) }
    }

    /// The byte range of member `i`'s block.
    fn span_of(&self, i: usize) -> Option<(usize, usize)> {
        let e = self.entry(i)?;
        span(e.pBlock as usize, layout(e.nType)?.size)
    }
}

impl Members for CMembers {
    fn with<R>(&mut self, i: usize, f: impl FnOnce(&mut dyn Member) -> R) -> Option<R> {
        let e = self.entry(i)?;
        member_dyn(e.nType, e.pBlock).map(f)
    }

    /// Binds the group's address, both tables' addresses, counts and capacities and every
    /// byte of every entry and link (their own checks included), in order.
    #[inline(always)]
    fn schedule_check<L: group::Links + ?Sized>(&self, links: &L) -> Option<u64> {
        let lanes = group::schedule_start(
            self.group,
            self.base as usize,
            self.count,
            self.cap,
            links.count(),
        );
        let lanes = group::schedule_table(lanes, self.entries(), group::member_words);
        let lanes = group::schedule_table(lanes, links.as_slice(), group::link_words);
        Some(group::schedule_end(lanes))
    }

    fn run_sealed(
        &mut self,
        i: usize,
        run: u8,
        ack: u8,
        now: u32,
        w: &mut crate::base::member::Wiring,
    ) -> Option<crate::base::member::Ran> {
        let e = self.sealed_entry(i)?;
        match run_entry(&e, u16::from_le_bytes([run, ack]), now, w) {
            // A type without a runner (an FSoE connection): through the type dispatch.
            crate::base::member::RAN_NOT_RUN => {
                member_dyn(e.nType, e.pBlock).map(|b| b.run_in_group(run, ack, now, w))
            }
            word => crate::base::member::Ran::of_word(word),
        }
    }

    // Out of line: the loop keeps its counters in callee-saved registers across the
    // runners' calls instead of on the enclosing cycle's stack (docs/performance.md).
    #[inline(never)]
    fn run_straight<L: group::Links + ?Sized>(
        &mut self,
        links: &L,
        link_count: usize,
        at: (usize, usize),
        members: usize,
        drive: u16,
        now: u32,
        w: &mut crate::base::member::Wiring,
    ) -> group::Straight {
        let entries = self.entries();
        let entries = entries.get(..members).unwrap_or(entries);
        let links = links.as_slice();
        let links = links.get(..link_count).unwrap_or(links);
        let mut i = at.0;
        // The links not copied yet.
        let mut rest = links.get(at.1..).unwrap_or_default();
        // A bit of any state but RUN: the members that ran straight all ended in RUN iff 0.
        let mut not_run = 0u8;
        // The outcome the loop takes (RAN_NOT_RUN: none, member `i` did not run yet).
        let mut handed_back = crate::base::member::RAN_NOT_RUN;
        'members: while let Some(&e) = entries.get(i) {
            // The entry by value: the copies below write through raw pointers, which could
            // otherwise be the entry's bytes for all the compiler knows (they are not: a
            // block shares no byte with the tables), and would make it read the entry again.
            while let [l, tail @ ..] = rest {
                if usize::from(l.nDstMember) != i {
                    break;
                }
                let Some(width) = copy_width(l.nKind) else {
                    break 'members;
                };
                if let Some(src) = entries.get(usize::from(l.nSrcMember)) {
                    copy_field(src.pBlock, e.pBlock, l, width);
                }
                rest = tail;
            }
            let word = run_entry(&e, drive, now, w);
            // A status other than SL_OK or a flag (bits 8 and up), or ERROR: the loop takes
            // the outcome (RAN_NOT_RUN: its links are copied, the loop runs it).
            if word >> 8 != 0 || word as u8 == SL_STATE_ERROR {
                handed_back = word;
                break;
            }
            not_run |= word as u8 ^ SL_STATE_RUN;
            i += 1;
        }
        let k = links.len() - rest.len();
        // Both below 2^16: the counts are 16-bit.
        group::Straight {
            member: i as u32,
            link: k as u32,
            word: handed_back,
            all_run: not_run == 0,
        }
    }

    fn copy_sealed(&mut self, l: &SL_LINK) {
        // Both ends were checked to be members when the link was added.
        let block = |m: u16| self.sealed_entry(usize::from(m)).map(|e| e.pBlock);
        if let (Some(src), Some(dst), Some(width)) = (
            block(l.nSrcMember),
            block(l.nDstMember),
            copy_width(l.nKind),
        ) {
            copy_field(src, dst, l, width);
        }
    }
}

/// Member `e` of a sealed cycle through the runner of its type ([`crate::base::member::RAN_NOT_RUN`]: a
/// type without one); `drive`: its bRun and bErrAck, `run | ack << 8`.
#[inline(always)]
fn run_entry(
    e: &SL_MEMBER,
    drive: u16,
    now: u32,
    w: &mut crate::base::member::Wiring,
) -> crate::base::member::RanWord {
    match RUNNERS.get(usize::from(e.nType)) {
        Some(runner) => runner(e.pBlock, drive, now, w),
        None => crate::base::member::RAN_NOT_RUN,
    }
}

/// The width of what a link copies: a BOOL, a 16-bit or a 32-bit analog value.
#[derive(Clone, Copy)]
enum Width {
    Byte,
    Half,
    Word,
}

/// The width a link of this kind copies; `None`: not a copy (an RXBIT / TXBIT link).
#[inline(always)]
fn copy_width(kind: u8) -> Option<Width> {
    match kind {
        SL_LINK_BOOL => Some(Width::Byte),
        group::SL_LINK_ANALOG16 => Some(Width::Half),
        group::SL_LINK_ANALOG32 => Some(Width::Word),
        _ => None,
    }
}

/// A BOOL or analog link of a sealed cycle (`width`: its kind's): its value from block
/// `src` to block `dst`.
#[inline(always)]
fn copy_field(src: *mut c_void, dst: *mut c_void, l: &SL_LINK, width: Width) {
    // SAFETY: the link's fields were checked when it was added (an output of the source's
    // type at nSrcOffset, an input of the same type and width at nDstOffset), inside blocks
    // that are live and share no byte with the tables (sl_group_add_member); the tables are
    // those a fully checked cycle saw. The value is read completely before it is written (a
    // link may go from a block to itself); unaligned accesses need no alignment proof.
    unsafe {
        let from = src.cast::<u8>().add(usize::from(l.nSrcOffset));
        let to = dst.cast::<u8>().add(usize::from(l.nDstOffset));
        match width {
            Width::Byte => to.write(from.read()),
            Width::Half => to
                .cast::<u16>()
                .write_unaligned(from.cast::<u16>().read_unaligned()),
            Width::Word => to
                .cast::<u32>()
                .write_unaligned(from.cast::<u32>().read_unaligned()),
        }
    }
}

/// Runs the block of type `B` at `p` as a group member (the sealed schedule's dispatch); a
/// block reports no connection, so its outcome is a [`crate::base::member::RanWord`].
/// The group's bRun and bErrAck for the member come as one word (`run | ack << 8`): one
/// argument, and the block's two adjacent bytes written as one 16-bit store, which a
/// following read of the same two bytes can take from the store buffer.
type Runner =
    fn(*mut c_void, u16, u32, &mut crate::base::member::Wiring) -> crate::base::member::RanWord;

fn run_as<B: Member + Registered>(
    p: *mut c_void,
    drive: u16,
    now: u32,
    w: &mut crate::base::member::Wiring,
) -> crate::base::member::RanWord {
    match instance(p.cast::<B>()) {
        Ok(b) => {
            let [run, ack] = drive.to_le_bytes();
            let word = b.run_word(run, ack, now, w);
            // Only a CONNECTION SHUTDOWN block can leave a request for the group (a constant
            // test for every other type): the member loop takes it.
            if B::INFO.tag == crate::blocks::connection::connshutdown::SL_TYPE_CONNECTION_SHUTDOWN {
                word | crate::base::member::RAN_HAND_BACK
            } else {
                word
            }
        }
        Err(_) => crate::base::member::RAN_UNREACHABLE,
    }
}

/// The runner of a tag without a type: nothing runs straight (an FSoE connection, run by
/// the member loop through the type dispatch, or a tag no entry can hold).
fn not_run(
    _: *mut c_void,
    _: u16,
    _: u32,
    _: &mut crate::base::member::Wiring,
) -> crate::base::member::RanWord {
    crate::base::member::RAN_NOT_RUN
}

/// Link storage read by value through the raw pointer.
struct CLinks {
    base: *const SL_LINK,
    count: usize,
    /// The table's capacity (sl_group_init contract: that many entries at `base`).
    cap: usize,
}

impl CLinks {
    /// The link table of the group whose member table is `t`, as the group's private state
    /// gives it (`count` links, room for `cap`). The capacity is trusted only when entry 0
    /// of the member table vouches for it (its check binds the link capacity): a forged
    /// capacity with valid complements (semantics GR14) would otherwise point reads past the
    /// caller's table. Untrusted, no link is read; every member entry then fails too (each
    /// is read only after entry 0), so the group stops. Without members nothing reads a link.
    fn of(t: &CMembers, base: *const SL_LINK, count: u16, cap: u16) -> Self {
        let trusted = cap > 0 && t.count > 0 && t.entry(0).is_some();
        let (count, cap) = if trusted { (count, cap) } else { (0, 0) };
        CLinks {
            base,
            count: usize::from(count),
            cap: usize::from(cap),
        }
    }
}

impl group::Links for CLinks {
    fn count(&self) -> usize {
        self.count
    }
    fn get(&self, i: usize) -> Option<SL_LINK> {
        // SAFETY: non-null and aligned (checked by `storage`), at least `count` entries
        // (sl_group_init contract; `count <= cap`, vouched for in `CLinks::of`); read by
        // value.
        (i < self.count).then(|| unsafe { self.base.add(i).read() })
    }
    fn as_slice(&self) -> &[SL_LINK] {
        // Link 0's own check binds the link count from the group's private state: a forged
        // count is found before a slice of that length is formed.
        let first_intact = self
            .get(0)
            .is_some_and(|l| l.aReserved == group::link_check(&l, 0, self.count as u16));
        if !first_intact {
            return &[];
        }
        // SAFETY: non-null and aligned (checked by `storage`), at least `count` entries
        // (sl_group_init contract) that the caller does not touch during the cycle; no
        // block's bytes are among them (sl_group_add_member).
        unsafe { core::slice::from_raw_parts(self.base, self.count) }
    }
    fn dst(&self, i: usize) -> Option<u16> {
        // SAFETY: as in `get`; only the (2-aligned) nDstMember field is read.
        (i < self.count)
            .then(|| unsafe { core::ptr::addr_of!((*self.base.add(i)).nDstMember).read() })
    }
    fn unused(&self, i: usize) -> bool {
        if self.base.is_null() || i >= self.cap {
            return true;
        }
        // SAFETY: non-null, `i < cap` entries at `base` (sl_group_init contract; `cap`
        // vouched for in `CLinks::of`); read by value, unaligned (with no link left,
        // `storage` checked no alignment).
        unsafe { self.base.add(i).read_unaligned() == SL_LINK::default() }
    }
}

/// Checks a caller array of `len` elements (NULL is allowed only for an empty one) and
/// returns its byte range.
fn storage<T>(p: *mut T, len: usize) -> Result<(usize, usize), i32> {
    if len == 0 {
        return Ok((p as usize, p as usize));
    }
    if p.is_null() {
        return Err(SL_E_NULL);
    }
    if (p as usize) % core::mem::align_of::<T>() != 0 {
        return Err(SL_E_ALIGNMENT);
    }
    len.checked_mul(core::mem::size_of::<T>())
        .and_then(|n| span(p as usize, n))
        .ok_or(SL_E_CONFIG)
}

/// A caller array as a slice, after `storage` accepted it.
///
/// # Safety
/// `storage(p, len)` returned `Ok`; the caller owns `len` elements at `p` and does not
/// touch them during the call, and no live reference covers them.
unsafe fn slice_mut<'a, T>(p: *mut T, len: usize) -> &'a mut [T] {
    if len == 0 {
        return &mut [];
    }
    // SAFETY: by the function's contract. The slice is built from the raw pointer itself,
    // never from a reference to its first element, so it may cover all `len` elements.
    unsafe { core::slice::from_raw_parts_mut(p, len) }
}

/// The group and its two tables share no byte.
fn tables_disjoint(
    g: *const SL_GROUP,
    members: (usize, usize),
    links: Option<(usize, usize)>,
) -> Result<(), i32> {
    let group = span(g as usize, core::mem::size_of::<SL_GROUP>()).ok_or(SL_E_CONFIG)?;
    let ok = disjoint(group, members)
        && links.map_or(true, |l| disjoint(group, l) && disjoint(members, l));
    ok.then_some(()).ok_or(SL_E_CONFIG)
}

/// The member table of `g` (count and capacity from its private state) at `table`.
fn member_table(g: &SL_GROUP, g_addr: usize, table: *mut SL_MEMBER) -> Result<CMembers, i32> {
    let (count, cap) = group::member_counts(g).ok_or(SL_E_CORRUPT)?;
    let (_, link_cap) = group::link_counts(g).ok_or(SL_E_CORRUPT)?;
    storage(table, usize::from(count))?;
    Ok(CMembers::at(table, count, cap, link_cap, g_addr))
}

/// Rewrites the check of every entry (after the count changed).
fn seal_members(t: &CMembers) {
    for i in 0..usize::from(t.count) {
        let p = t.base.wrapping_add(i);
        // SAFETY: `i < count <= cap`: inside the caller's table (sl_group_init contract),
        // which no live reference covers (checked disjoint from the group).
        let e = unsafe { p.read() };
        let check = group::member_check(
            t.group,
            p as usize,
            i as u16,
            t.shape(),
            e.pBlock as usize,
            e.nType,
        );
        // SAFETY: as above.
        unsafe { core::ptr::addr_of_mut!((*p).aReserved).write(check) };
    }
}

/// Reads the private header a block of type `l` has at its place in the block at `p`.
///
/// # Safety
/// At least `header_end(l)` bytes at `p` are readable.
unsafe fn header_at(p: *mut c_void, l: &TypeLayout) -> SL_PRIVATE_HEADER {
    // SAFETY: the caller's bound covers the header; every byte of a block struct is
    // initialised (no padding).
    unsafe {
        p.cast::<u8>()
            .add(l.header)
            .cast::<SL_PRIVATE_HEADER>()
            .read_unaligned()
    }
}

/// The end of a type's private header: the bytes `header_at` reads.
fn header_end(l: &TypeLayout) -> usize {
    l.header + core::mem::size_of::<SL_PRIVATE_HEADER>()
}

/// Checks that the block at `p` is a block of type `claimed` by its own private header
/// (docs/semantics.md GR14). `Ok(true)`: an all-zero header, a never-initialised block.
/// Every registered type whose header lies within the claimed size is tried, from the
/// smallest type, so no read leaves the block when it is an initialised block of any
/// registered type, and an initialised block of a larger type whose header is in reach
/// (MUTING offered as COMPARE_DINT) is recognised instead of being taken for a zeroed one.
fn identify(p: *mut c_void, claimed: &TypeLayout) -> Result<bool, i32> {
    let mut all = layouts();
    all.sort_unstable_by_key(|l| (l.size, l.tag));
    for l in all.iter().filter(|l| header_end(l) <= claimed.size) {
        // SAFETY: `header_end(l) <= claimed.size` bytes at `p`: inside the block (caller's
        // duty for a block of the claimed size; inside any smaller registered block tried
        // first).
        if unsafe { header_at(p, l) }.intact(l.magic) {
            return if l.tag == claimed.tag {
                Ok(false)
            } else {
                Err(SL_E_CONFIG)
            };
        }
    }
    // SAFETY: as above, `claimed.size` bytes.
    let h = unsafe { header_at(p, claimed) };
    if h.is_zero() {
        Ok(true)
    } else if h.wMagic == claimed.magic {
        Err(SL_E_CORRUPT)
    } else {
        Err(SL_E_CONFIG)
    }
}

/// The checks of a connection offered as a member (docs/semantics.md FS17): connections
/// come before every block (they run first in a group cycle), at most SL_GROUP_CONN_MAX of
/// them; it must have been initialised (SL_E_CONFIG: init refused or never done) and pass
/// its private state's check (SL_E_CORRUPT).
fn check_connection(t: &CMembers, c: *mut SL_FSOE_CONN) -> Result<(), i32> {
    let mut conns = 0u16;
    for i in 0..usize::from(t.count) {
        let e = t.entry(i).ok_or(SL_E_CORRUPT)?;
        if e.nType != SL_TYPE_FSOE_CONN {
            return Err(SL_E_CONFIG);
        }
        conns += 1;
    }
    if conns >= crate::base::member::SL_GROUP_CONN_MAX {
        return Err(SL_E_FULL);
    }
    let c = instance_ref(c.cast_const()).map_err(|_| SL_E_CONFIG)?;
    match crate::fsoe::conn::integrity(c) {
        Some(true) => Ok(()),
        Some(false) => Err(SL_E_CORRUPT),
        None => Err(SL_E_CONFIG),
    }
}

/// Resets a group to power-up (STOP, or STOPERROR with bConnections) with the caller's
/// storage for `nMemberCap` members and `nLinkCap` links. The same arrays must be passed to
/// every later sl_group_* call. Does not modify the group's input fields. Checks before it
/// writes: a refused init (SL_E_NULL, SL_E_ALIGNMENT, SL_E_CONFIG for bConnections > 1, a
/// group still in RUN/START, or tables that share a byte with each other or the group)
/// changes nothing. An accepted init zeroes both tables; the link entry after the last link
/// stays zero (a cycle that finds it written stops the group with SL_E_CORRUPT, as a link
/// that fails its check: a link count forged lower is found that way).
///
/// # Safety
/// `g` is NULL or points to a live SL_GROUP; `aMembers` / `aLinks` are NULL or point to at
/// least `nMemberCap` / `nLinkCap` entries; the caller keeps all of them alive, in place and
/// untouched for as long as the group is used (a table that is freed, moved or written by
/// the caller cannot be told from a valid one until its entries fail their checks).
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_group_init(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    nMemberCap: u16,
    aLinks: *mut SL_LINK,
    nLinkCap: u16,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        let run = || -> Result<i32, i32> {
            let g_ptr = g;
            let g = instance(g)?;
            let members = storage(aMembers, usize::from(nMemberCap))?;
            let links = storage(aLinks, usize::from(nLinkCap))?;
            tables_disjoint(g_ptr, members, Some(links))?;
            // A refused init changes nothing: a running group keeps its members.
            if !group::init_valid(g) {
                return Err(SL_E_CONFIG);
            }
            // SAFETY: both arrays were checked (non-null, aligned, disjoint from the group
            // and from each other); the caller owns them (contract above).
            unsafe {
                slice_mut(aMembers, usize::from(nMemberCap)).fill(SL_MEMBER::default());
                slice_mut(aLinks, usize::from(nLinkCap)).fill(SL_LINK::default());
            }
            Ok(group::init(g, nMemberCap, nLinkCap))
        };
        run().unwrap_or_else(|e| e)
    })
}

/// Adds a block as the next member (execution order) while the group is stopped.
/// `nType` is `SL_TYPE_<NAME>`; the index is written to `*pIndex` unless it is NULL.
/// The block is checked before anything is written: SL_E_NULL for a NULL block; SL_E_FULL
/// when the member storage is full; SL_E_CONFIG for an unknown type, a misaligned block, a
/// block that shares a byte with the group, its member table or another member (a block
/// can be a member once), or a block whose private header is that of another type;
/// SL_E_CORRUPT for a block of this type whose private state fails its check, or a member
/// table whose entries fail theirs. A block with an all-zero private state (never
/// initialised) is initialised here with its type's init; initialise blocks before adding
/// them to have their type checked (docs/semantics.md GR14).
/// An FSoE connection is added with `nType` = SL_TYPE_FSOE_CONN (docs/semantics.md FS17):
/// connections come before every block (SL_E_CONFIG after a block), at most
/// SL_GROUP_CONN_MAX per group (SL_E_FULL), initialised with `sl_fsoe_init` first
/// (SL_E_CONFIG otherwise; SL_E_CORRUPT when its private state fails its check).
///
/// # Safety
/// As for `sl_group_init`, with the same tables; `pBlock` points to a live block of type
/// `nType` (at least its size readable) that stays alive and in place while it is a member;
/// `pIndex` is NULL or writable.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_group_add_member(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    nType: u16,
    pBlock: *mut c_void,
    pIndex: *mut u16,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        let run = || -> Result<u16, i32> {
            let g_ptr = g;
            let g = instance(g)?;
            if pBlock.is_null() {
                return Err(SL_E_NULL);
            }
            group::configurable(g)?;
            let mut t = member_table(g, g_ptr as usize, aMembers)?;
            let table = storage(aMembers, usize::from(t.cap))?;
            tables_disjoint(g_ptr, table, None)?;
            let lay = layout(nType).ok_or(SL_E_CONFIG)?;
            if (pBlock as usize) % lay.align != 0 {
                return Err(SL_E_CONFIG);
            }
            let block = span(pBlock as usize, lay.size).ok_or(SL_E_CONFIG)?;
            tables_disjoint(g_ptr, table, Some(block))?;
            for i in 0..usize::from(t.count) {
                if !disjoint(t.span_of(i).ok_or(SL_E_CORRUPT)?, block) {
                    return Err(SL_E_CONFIG);
                }
            }
            if nType == SL_TYPE_FSOE_CONN {
                check_connection(&t, pBlock.cast::<SL_FSOE_CONN>())?;
            }
            let never_initialised = if nType == SL_TYPE_FSOE_CONN {
                false
            } else {
                identify(pBlock, &lay)?
            };
            // A PLCopen block joins only initialised (semantics PO8): its 56 bytes are
            // smaller than most other types' headers lie deep, so a zero header there would
            // let many blocks of other types pass as never-initialised SF_ blocks (GR14).
            if never_initialised && family(nType) == Family::PlcOpen {
                return Err(SL_E_CONFIG);
            }
            // Full only now: a duplicate or foreign block is refused as such. Nothing has
            // been written so far, and no slice past the caller's `cap` entries is formed.
            if t.count >= t.cap {
                return Err(SL_E_FULL);
            }
            if never_initialised {
                (lay.init)(pBlock);
            }
            let index = group::reserve_member(g)?;
            let entry = t.base.wrapping_add(usize::from(index));
            // SAFETY: `index < cap`: inside the caller's table, which shares no byte with
            // the group or the block and which no reference covers.
            unsafe {
                entry.write(SL_MEMBER {
                    pBlock,
                    nType,
                    aReserved: [0; 6],
                })
            };
            t.count = index + 1;
            seal_members(&t);
            Ok(index)
        };
        match run() {
            Ok(index) => {
                if !pIndex.is_null() && (pIndex as usize) % core::mem::align_of::<u16>() == 0 {
                    // SAFETY: non-null, aligned, writable by the contract; written last,
                    // after every reference of this call has ended.
                    unsafe { pIndex.write(index) };
                }
                SL_OK
            }
            Err(e) => e,
        }
    })
}

/// Links the output at byte `nSrcOffset` of member `nSrcMember` to the input at byte
/// `nDstOffset` of member `nDstMember` (offsets as in the `FB_<NAME>` structs). Both fields
/// must have the same IEC type: BOOL to BOOL (SL_LINK_BOOL), INT/UINT to the same
/// (SL_LINK_ANALOG16), DINT/UDINT to the same (SL_LINK_ANALOG32). The value is
/// copied just before the destination executes: a link from an earlier member carries this
/// cycle's value, one from a later member the previous cycle's. SL_E_CONFIG for a field
/// that is not a linkable output / input of a member, an input that is already linked, or
/// a link table that shares a byte with the group, the member table or a member;
/// SL_E_CORRUPT for a member entry that fails its check.
///
/// # Safety
/// As for `sl_group_init`, with the same tables.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_group_add_link(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    aLinks: *mut SL_LINK,
    nSrcMember: u16,
    nSrcOffset: u16,
    nDstMember: u16,
    nDstOffset: u16,
) -> i32 {
    // SAFETY: forwarded under this function's contract.
    unsafe {
        add_link(
            g, aMembers, aLinks, None, nSrcMember, nSrcOffset, nDstMember, nDstOffset,
        )
    }
}

/// The checks and the insertion behind `sl_group_add_link` (`kind` None: the kind follows
/// from the source field's type) and `sl_group_add_link_kind`.
///
/// # Safety
/// As for `sl_group_init`, with the same tables.
#[allow(non_snake_case, clippy::too_many_arguments)]
unsafe fn add_link(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    aLinks: *mut SL_LINK,
    kind: Option<u8>,
    nSrcMember: u16,
    nSrcOffset: u16,
    nDstMember: u16,
    nDstOffset: u16,
) -> i32 {
    // The panic boundary of both entry points: the checks below return their refusal as `Err`.
    let checked = || -> Result<i32, i32> {
        let g_ptr = g;
        let g = instance(g)?;
        let mut t = member_table(g, g_ptr as usize, aMembers)?;
        let (_, link_cap) = group::link_counts(g).ok_or(SL_E_CORRUPT)?;
        let table = storage(aMembers, usize::from(t.cap))?;
        let link_span = storage(aLinks, usize::from(link_cap))?;
        tables_disjoint(g_ptr, table, Some(link_span))?;
        for i in 0..usize::from(t.count) {
            if !disjoint(t.span_of(i).ok_or(SL_E_CORRUPT)?, link_span) {
                return Err(SL_E_CONFIG);
            }
        }
        // SAFETY: checked above: the caller's link table, disjoint from the group, the member
        // table and every member.
        let links = unsafe { slice_mut(aLinks, usize::from(link_cap)) };
        // Without a stated kind it follows from the source field's type; add_link refuses a
        // destination of another type.
        let kind = kind.unwrap_or_else(|| {
            t.with(usize::from(nSrcMember), |b| {
                b.fields()
                    .iter()
                    .find(|f| f.offset == nSrcOffset)
                    .and_then(|f| group::link_kind(f.kind))
            })
            .flatten()
            .unwrap_or(SL_LINK_BOOL)
        });
        let link = SL_LINK {
            nSrcMember,
            nSrcOffset,
            nDstMember,
            nDstOffset,
            nKind: kind,
            aReserved: [0; 3],
        };
        Ok(group::add_link(g, &mut t, links, link))
    };
    ffi_boundary!(SL_E_INTERNAL, checked().unwrap_or_else(|e| e))
}

/// Links as `sl_group_add_link` with the link kind stated: SL_LINK_BOOL, SL_LINK_ANALOG16,
/// SL_LINK_ANALOG32 (both fields of that type), SL_LINK_RXBIT (bit `nSrcOffset` = byte · 8
/// plus bit, of connection member `nSrcMember`'s received SafeData → the BOOL input at byte
/// `nDstOffset` of member `nDstMember`) or SL_LINK_TXBIT (the BOOL output at byte
/// `nSrcOffset` of member `nSrcMember` → bit `nDstOffset` of connection member
/// `nDstMember`'s SafeData to send). A bit must lie within the connection's latched
/// SafeData length. SL_E_CONFIG for an unknown kind, a field or bit that does not fit it,
/// or a destination that is already linked; otherwise as `sl_group_add_link`
/// (docs/semantics.md FS19).
///
/// # Safety
/// As for `sl_group_init`, with the same tables.
#[no_mangle]
#[allow(non_snake_case, clippy::too_many_arguments)]
pub unsafe extern "C" fn sl_group_add_link_kind(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    aLinks: *mut SL_LINK,
    nKind: u8,
    nSrcMember: u16,
    nSrcOffset: u16,
    nDstMember: u16,
    nDstOffset: u16,
) -> i32 {
    let kind = Some(nKind);
    // SAFETY: forwarded under this function's contract.
    unsafe {
        add_link(
            g, aMembers, aLinks, kind, nSrcMember, nSrcOffset, nDstMember, nDstOffset,
        )
    }
}

/// One group cycle at `tNow`: group state, then every member in order (links first), all
/// with the same `tNow`. Returns the group's status or the worst status of a member.
/// A member entry or link that fails its check, or tables that share a byte with the
/// group, are member errors: the group enters ERROR, every reachable member is stopped in
/// this cycle, SL_E_CORRUPT (docs/semantics.md GR13, GR14). A NULL member table (group with
/// members) or link table (group with links): the same safe state, SL_E_NULL (GR16).
///
/// # Safety
/// As for `sl_group_init`, with the same tables; every member block is still alive and in
/// place (a freed block cannot be detected).
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_group_cycle(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    aLinks: *mut SL_LINK,
    tNow: u32,
) -> i32 {
    // SAFETY: the caller's contract is this function's.
    unsafe { sl_group_cycle_traced(g, aMembers, aLinks, tNow, &mut 0) }
}

/// `sl_group_cycle`, also adding to `straight` the members the sealed schedule ran straight
/// (group::cycle_traced): for the tests that pin the sealed schedule; not part of the C API.
///
/// # Safety
/// As for `sl_group_cycle`.
#[doc(hidden)]
#[allow(non_snake_case)]
pub unsafe fn sl_group_cycle_traced(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    aLinks: *mut SL_LINK,
    tNow: u32,
    straight: &mut usize,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        let mut run = || -> Result<i32, i32> {
            let g_ptr = g;
            let g = instance(g)?;
            let mut none: [&mut dyn Member; 0] = [];
            let (Some((members, cap)), Some((links, link_cap))) =
                (group::member_counts(g), group::link_counts(g))
            else {
                return Ok(group::cycle(g, &mut none[..], &[], tNow));
            };
            let checked = storage(aMembers, usize::from(members)).and_then(|table| {
                tables_disjoint(g_ptr, table, Some(storage(aLinks, usize::from(links))?))
            });
            if let Err(e) = checked {
                // No entry can be read (NULL, misaligned, or inside the group): no member is
                // reachable, which stops the group like any unreachable member. A NULL table
                // is the caller's NULL (ABI §5), not corrupt memory: the group still takes
                // its safe state, the status says what was wrong (semantics GR16).
                let status = group::cycle(g, &mut none[..], &[], tNow);
                return Ok(if e == SL_E_NULL { e } else { status });
            }
            // The member table as `member_table` would give it, from the counts and the
            // `storage` check above (not read and checked a second time).
            let mut t = CMembers::at(aMembers, members, cap, link_cap, g_ptr as usize);
            let l = CLinks::of(&t, aLinks, links, link_cap);
            Ok(group::cycle_traced(g, &mut t, &l, tNow, straight))
        };
        run().unwrap_or_else(|e| e)
    })
}

/// Whether the next `sl_group_cycle` with these tables runs the sealed schedule (the
/// tables equal those the last fully checked cycle found intact, docs/performance.md). For
/// the tests that pin the sealed schedule to the checked one; not part of the C API.
///
/// # Safety
/// As for `sl_group_cycle`.
#[doc(hidden)]
#[allow(non_snake_case)]
pub unsafe fn sl_group_schedule_sealed(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    aLinks: *mut SL_LINK,
) -> bool {
    let g_ptr = g;
    let Ok(g) = instance(g) else {
        return false;
    };
    let Some((links, link_cap)) = group::link_counts(g) else {
        return false;
    };
    member_table(g, g_ptr as usize, aMembers).is_ok_and(|t| {
        let l = CLinks::of(&t, aLinks, links, link_cap);
        group::is_sealed(g, &t, &l)
    })
}

/// A NUL-terminated text of at most `len` bytes into `buf`, the frame of the HMI text
/// functions: `len` 0 writes nothing (SL_E_NULL for a NULL buf, else SL_OK); otherwise
/// `buf[0]` is NUL first (an error of `fill` leaves ""), `fill` writes into all but the
/// last byte and returns the length, and the NUL follows the text.
///
/// # Safety
/// `buf` is NULL or points to at least `len` writable bytes.
unsafe fn c_text(
    buf: *mut c_char,
    len: usize,
    fill: impl FnOnce(&mut [u8]) -> Result<usize, i32>,
) -> i32 {
    let run = || -> Result<i32, i32> {
        if len == 0 {
            return Ok(if buf.is_null() { SL_E_NULL } else { SL_OK });
        }
        storage(buf.cast::<u8>(), len)?;
        // SAFETY: checked by `storage`; `buf` points to `len` writable bytes (contract).
        let out = unsafe { slice_mut(buf.cast::<u8>(), len) };
        out[0] = 0;
        let (text, nul) = out.split_at_mut(len - 1);
        let n = fill(text)?;
        // `n < len`, so index n is inside `text` or is `nul[0]`.
        match text.get_mut(n) {
            Some(b) => *b = 0,
            None => nul[0] = 0,
        }
        Ok(SL_OK)
    };
    run().unwrap_or_else(|e| e)
}

/// Writes the readable names of the diag bits `nDiag` of a block of type `nType`
/// (`SL_TYPE_<NAME>`) into `buf` as a NUL-terminated text ("discrepancy error input group 1;
/// EDM monitoring error EDM1"), truncated to `nLen` bytes including the NUL. For an HMI.
/// SL_E_CONFIG for an unknown type (buf then holds ""), SL_E_NULL for a NULL buf.
///
/// # Safety
/// `buf` is NULL or points to at least `nLen` writable bytes.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_diag_text(
    nType: u16,
    nDiag: u16,
    buf: *mut c_char,
    nLen: usize,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        // SAFETY: `buf` is NULL or points to `nLen` writable bytes (contract).
        unsafe {
            c_text(buf, nLen, |text| {
                let info = crate::registry::info(nType).ok_or(SL_E_CONFIG)?;
                Ok(crate::base::diag::diag_text(info, nDiag, text))
            })
        }
    })
}

/// Writes why the block `pBlock` of type `nType` (`SL_TYPE_<NAME>`) refuses its parameters,
/// as one NUL-terminated sentence naming the field, the rule and the offending values
/// ("TWOHAND: tDiscTimePairs (3000 ms) must be <= 500 ms [reason 0xE001]", "LIMIT_INT:
/// nMinimumValue (5) must be <= nMaximumValue (3) [Text ID 0x4090]"), truncated to `nLen`
/// bytes including the NUL. The rules are evaluated again on the struct as it is now (the
/// block's live parameters; nothing is stored by the init or cycle calls). With valid
/// parameters and the block in an error state: the latched diag ("LIMIT_INT: ERROR:
/// MinValue is greater than MaxValue [Text ID 0x4090, Par2 5, Par3 3]"; a PLCopen block:
/// its DiagCode and text); otherwise `"<NAME>: no refusal"`. The codes in brackets are the
/// manual's Text IDs or the library reason codes of docs/c-integration.md. For an HMI or a
/// log after SL_E_CONFIG. SL_OK; SL_E_CONFIG for an unknown type (buf then holds "");
/// SL_E_NULL for a NULL buf or pBlock; SL_E_ALIGNMENT for a misaligned pBlock.
///
/// # Safety
/// `buf` is NULL or points to at least `nLen` writable bytes; `pBlock` is NULL or points to
/// a live instance of the type `nType` names that nobody writes during the call.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_reason_text(
    nType: u16,
    pBlock: *const c_void,
    buf: *mut c_char,
    nLen: usize,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        // SAFETY: `buf` is NULL or points to `nLen` writable bytes (contract).
        unsafe { c_text(buf, nLen, |text| reason_of(nType, pBlock, text)) }
    })
}

/// A caller's read-only byte buffer as a slice (`None` for NULL or length 0).
///
/// # Safety
/// `p` is NULL or points to at least `len` readable bytes that nothing writes during the call.
unsafe fn bytes<'a>(p: *const u8, len: usize) -> Option<&'a [u8]> {
    if p.is_null() || len == 0 {
        return None;
    }
    // SAFETY: by the function's contract; u8 needs no alignment.
    Some(unsafe { core::slice::from_raw_parts(p, len) })
}

/// Validates and latches the parameters of an FSoE connection (ABI-2 §13.1) and resets it
/// to state 100 (Reset); nothing is sent yet. Never modifies an input or parameter field.
/// SL_OK; SL_E_CONFIG for invalid parameters (nConnectionId 0, nRole not 1/2, a SafeData
/// length not 1 or even 2…32, nAppParaLen > 64, tWatchdogTime not 1…65535, unknown option
/// bits); SL_E_NULL / SL_E_ALIGNMENT for a bad pointer.
///
/// # Safety
/// `c` is NULL or points to a live, caller-owned SL_FSOE_CONN that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn sl_fsoe_init(c: *mut SL_FSOE_CONN) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        match instance(c) {
            Ok(c) => crate::fsoe::conn::init(c).code(),
            Err(e) => e,
        }
    })
}

/// One cycle of an FSoE connection at `tNow` (monotonic ms): processes the received frame
/// `pRxFrame`/`nRxLen` (NULL/0: none; a frame equal to the previous one is no event), runs
/// the watchdog, and writes a new frame to `pTxFrame` only when the state machine produces
/// one: `*pTxLen` = its length, else 0 and `pTxFrame` untouched. SL_E_LENGTH: `nTxCap` is
/// below the frame length of nTxDataLen (nothing done) or `nRxLen` is not the frame length
/// of nRxDataLen (the frame is ignored). Protocol errors are not call errors: they show in
/// nState / nDiag / bComErr. SL_E_INVALID_BOOL: an input byte was neither 0 nor 1.
/// SL_E_CONFIG: init refused or never done; SL_E_CORRUPT: the private state failed its
/// check; SL_E_NULL / SL_E_ALIGNMENT for a bad pointer; SL_E_CONFIG when the buffers
/// overlap each other or the connection.
///
/// # Safety
/// `c` as for `sl_fsoe_init`; `pRxFrame` is NULL or points to `nRxLen` readable bytes;
/// `pTxFrame` points to `nTxCap` writable bytes; `pTxLen` points to a writable size_t.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_fsoe_cycle(
    c: *mut SL_FSOE_CONN,
    tNow: u32,
    pRxFrame: *const u8,
    nRxLen: usize,
    pTxFrame: *mut u8,
    nTxCap: usize,
    pTxLen: *mut usize,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        let run = || -> Result<i32, i32> {
            let conn = span(c as usize, core::mem::size_of::<SL_FSOE_CONN>()).ok_or(SL_E_CONFIG)?;
            instance_ref(c.cast_const())?;
            instance_ref(pTxLen.cast_const())?;
            if pTxFrame.is_null() {
                return Err(SL_E_NULL);
            }
            let txs = span(pTxFrame as usize, nTxCap).ok_or(SL_E_CONFIG)?;
            let lens = span(pTxLen as usize, core::mem::size_of::<usize>()).ok_or(SL_E_CONFIG)?;
            let rxs = if pRxFrame.is_null() || nRxLen == 0 {
                (0, 0)
            } else {
                span(pRxFrame as usize, nRxLen).ok_or(SL_E_CONFIG)?
            };
            if !disjoint(conn, txs)
                || !disjoint(conn, rxs)
                || !disjoint(txs, rxs)
                || !disjoint(lens, conn)
                || !disjoint(lens, txs)
                || !disjoint(lens, rxs)
            {
                return Err(SL_E_CONFIG);
            }
            let conn = instance(c)?;
            // SAFETY: checked above: non-null, disjoint from the connection and from the
            // transmit buffer; readable by the contract.
            let rx = unsafe { bytes(pRxFrame, nRxLen) };
            // SAFETY: non-null, disjoint from the connection and the received frame;
            // `nTxCap` writable bytes by the contract.
            let tx = unsafe { slice_mut(pTxFrame, nTxCap) };
            let (status, len) = crate::fsoe::conn::cycle(conn, tNow, rx, tx);
            // SAFETY: non-null and aligned (checked above), disjoint from every reference
            // of this call; writable by the contract.
            unsafe { pTxLen.write(len) };
            Ok(status.code())
        };
        run().unwrap_or_else(|e| e)
    })
}

/// Frame length for `nSafeDataLen` SafeData bytes: 6 for 1, 2n + 3 for even n in 2…32, else 0.
#[no_mangle]
#[allow(non_snake_case)]
pub extern "C" fn sl_fsoe_frame_len(nSafeDataLen: usize) -> usize {
    ffi_boundary!(0, crate::fsoe::frame::frame_len(nSafeDataLen))
}

/// The FSoE CRC of one block (ABI-2 §13.7): `wRecvCrc0`, `nConnId`, `nSeqNo` (LE),
/// `nCmd`, the block index (LE, only when `nIndex` > 0) and the block's `nBlockLen` (1 or
/// 2) bytes, then three zero octets. 0 for a NULL block or `nBlockLen` not 1 or 2.
///
/// # Safety
/// `pBlock` is NULL or points to `nBlockLen` readable bytes.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_fsoe_crc(
    wRecvCrc0: u16,
    nConnId: u16,
    nSeqNo: u16,
    nCmd: u8,
    nIndex: u16,
    pBlock: *const u8,
    nBlockLen: usize,
) -> u16 {
    ffi_boundary!(0, {
        if nBlockLen != 1 && nBlockLen != 2 {
            return 0;
        }
        // SAFETY: by the contract.
        match unsafe { bytes(pBlock, nBlockLen) } {
            Some(b) => crate::fsoe::crc::fsoe_crc(wRecvCrc0, nConnId, nSeqNo, nCmd, nIndex, b),
            None => 0,
        }
    })
}

/// A collision-check flag: 0 / 1, else refused.
fn flag(b: SL_BOOL) -> Result<bool, i32> {
    match b {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(SL_E_INVALID_BOOL),
    }
}

/// Encodes a frame (ABI-2 §13.6) into `pFrame`: CRC_0 with `*pSeqNo`; with
/// `bCollisionCheck` and CRC_0 == `wOldCrc0` the sequence number is incremented (65535
/// wraps to 1) until CRC_0 differs; `*pSeqNo` returns the number used, `*pFrameLen` the
/// frame length. SL_E_LENGTH (nothing written) for a SafeData length not 1 or even 2…32 or
/// a capacity below the frame length; SL_E_FRAME for an unknown command; SL_E_INVALID_BOOL
/// for a collision flag not 0/1; SL_E_NULL / SL_E_ALIGNMENT for a bad pointer. Pure.
///
/// # Safety
/// `pFrame` points to `nFrameCap` writable bytes, `pSafeData` to `nSafeDataLen` readable
/// bytes, `pFrameLen` and `pSeqNo` are writable; no two of them overlap.
#[no_mangle]
#[allow(non_snake_case, clippy::too_many_arguments)]
pub unsafe extern "C" fn sl_fsoe_frame_encode(
    pFrame: *mut u8,
    nFrameCap: usize,
    pFrameLen: *mut usize,
    nCmd: u8,
    pSafeData: *const u8,
    nSafeDataLen: usize,
    nConnId: u16,
    wRecvCrc0: u16,
    pSeqNo: *mut u16,
    wOldCrc0: u16,
    bCollisionCheck: SL_BOOL,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        let run = || -> Result<i32, i32> {
            if pFrame.is_null() || pSafeData.is_null() {
                return Err(SL_E_NULL);
            }
            instance_ref(pFrameLen.cast_const())?;
            instance_ref(pSeqNo.cast_const())?;
            let collision = flag(bCollisionCheck)?;
            let n = crate::fsoe::frame::frame_len(nSafeDataLen);
            if n == 0 || nFrameCap < n {
                return Err(SL_E_LENGTH);
            }
            let fs = span(pFrame as usize, n).ok_or(SL_E_CONFIG)?;
            let ds = span(pSafeData as usize, nSafeDataLen).ok_or(SL_E_CONFIG)?;
            let ls = span(pFrameLen as usize, core::mem::size_of::<usize>()).ok_or(SL_E_CONFIG)?;
            let ss = span(pSeqNo as usize, 2).ok_or(SL_E_CONFIG)?;
            if !(disjoint(fs, ds) && disjoint(fs, ls) && disjoint(fs, ss) && disjoint(ls, ss)) {
                return Err(SL_E_CONFIG);
            }
            // SAFETY: non-null, `nSafeDataLen` readable bytes by the contract.
            let data = unsafe { bytes(pSafeData, nSafeDataLen) }.ok_or(SL_E_NULL)?;
            // SAFETY: non-null, aligned; read by value.
            let mut seq = unsafe { pSeqNo.read() };
            // SAFETY: non-null, `n <= nFrameCap` writable bytes, disjoint from `data`.
            let out = unsafe { slice_mut(pFrame, n) };
            let (len, _) = crate::fsoe::frame::encode(
                out, nCmd, data, nConnId, wRecvCrc0, &mut seq, wOldCrc0, collision,
            )
            .map_err(Status::code)?;
            // SAFETY: non-null, aligned, writable, disjoint from the frame (checked above).
            unsafe {
                pSeqNo.write(seq);
                pFrameLen.write(len);
            }
            Ok(SL_OK)
        };
        run().unwrap_or_else(|e| e)
    })
}

/// Decodes and checks a frame of `nSafeDataLen` SafeData bytes (ABI-2 §13.6) into `*pOut`.
/// SL_E_LENGTH: `nFrameLen` is not the frame length of `nSafeDataLen` (`*pOut` untouched);
/// SL_E_FRAME: unknown command (`nResetCode` 2) or CRC mismatch with the same collision
/// rule as the sender (`nResetCode` 4), the other fields still filled; on SL_OK `*pSeqNo`
/// is the sequence number that matched. SL_E_INVALID_BOOL for a collision flag not 0/1;
/// SL_E_NULL / SL_E_ALIGNMENT for a bad pointer. Pure.
///
/// # Safety
/// `pFrame` points to `nFrameLen` readable bytes, `pSeqNo` and `pOut` are writable; no two
/// of them overlap.
#[no_mangle]
#[allow(non_snake_case, clippy::too_many_arguments)]
pub unsafe extern "C" fn sl_fsoe_frame_decode(
    pFrame: *const u8,
    nFrameLen: usize,
    nSafeDataLen: usize,
    wRecvCrc0: u16,
    pSeqNo: *mut u16,
    wOldCrc0: u16,
    bCollisionCheck: SL_BOOL,
    pOut: *mut SL_FSOE_FRAME,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        let run = || -> Result<i32, i32> {
            if pFrame.is_null() {
                return Err(SL_E_NULL);
            }
            instance_ref(pSeqNo.cast_const())?;
            instance_ref(pOut.cast_const())?;
            let collision = flag(bCollisionCheck)?;
            let fs = span(pFrame as usize, nFrameLen).ok_or(SL_E_CONFIG)?;
            let ss = span(pSeqNo as usize, 2).ok_or(SL_E_CONFIG)?;
            let os =
                span(pOut as usize, core::mem::size_of::<SL_FSOE_FRAME>()).ok_or(SL_E_CONFIG)?;
            if !(disjoint(fs, ss) && disjoint(fs, os) && disjoint(ss, os)) {
                return Err(SL_E_CONFIG);
            }
            // SAFETY: non-null, `nFrameLen` readable bytes by the contract.
            let frame = unsafe { bytes(pFrame, nFrameLen) }.unwrap_or(&[]);
            // SAFETY: non-null, aligned; read by value.
            let mut seq = unsafe { pSeqNo.read() };
            let mut out = SL_FSOE_FRAME::default();
            let st = crate::fsoe::frame::decode(
                frame,
                nSafeDataLen,
                wRecvCrc0,
                &mut seq,
                wOldCrc0,
                collision,
                &mut out,
            );
            if st != Status::Length {
                // SAFETY: non-null, aligned, writable, disjoint from the frame (checked above).
                unsafe {
                    pOut.write(out);
                    pSeqNo.write(seq);
                }
            }
            Ok(st.code())
        };
        run().unwrap_or_else(|e| e)
    })
}

/// Writes an instance's initial values (`value`) into `*p`: SL_OK, or the status of a
/// refused pointer (SL_E_NULL / SL_E_ALIGNMENT).
fn write_defaults<B>(p: *mut B, value: fn() -> B) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        match instance(p) {
            Ok(p) => {
                *p = value();
                SL_OK
            }
            Err(e) => e,
        }
    })
}

/// Writes PLCopen's initial values into `*p`: ResetRequested TRUE, TrailingMinimum 350 ms
/// (T#350ms), TrailingMaximum 2000 ms (T#2s); every other field, the private state
/// included, zero (a power-up instance: call `sl_sf_resetbutton_init` next). A zeroed
/// struct is not these defaults (its TrailingMinimum 0 is refused at activation): zero
/// stays "not configured" (docs/semantics.md PO12). SL_OK; SL_E_NULL / SL_E_ALIGNMENT for
/// a bad pointer.
///
/// # Safety
/// `p` is NULL or points to a caller-owned SF_ResetButton that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn sl_sf_resetbutton_defaults(p: *mut SF_ResetButton) -> i32 {
    write_defaults(p, SF_ResetButton::plcopen_defaults)
}

/// Writes PLCopen's initial values into `*p`: S_ChannelNO TRUE (its SAFEBOOL initial
/// value); every other field, the private state included, zero (a power-up instance: call
/// `sl_sf_antivalent_init` next). A zeroed struct has S_ChannelNO FALSE (docs/semantics.md
/// PO12). SL_OK; SL_E_NULL / SL_E_ALIGNMENT for a bad pointer.
///
/// # Safety
/// `p` is NULL or points to a caller-owned SF_Antivalent that nothing else accesses during the call.
#[no_mangle]
pub unsafe extern "C" fn sl_sf_antivalent_defaults(p: *mut SF_Antivalent) -> i32 {
    write_defaults(p, SF_Antivalent::plcopen_defaults)
}
