//! The C ABI (ABI.md §4, §5). Every exported function runs inside `ffi_boundary!`, the one
//! place that catches panics; instance pointers pass through `instance`, the one place that
//! checks NULL and alignment. Nothing else in the crate is `unsafe`.
#![allow(unsafe_code)]

use crate::group::{self, Member, Members, SL_LINK_BOOL};
use crate::prim::envelope::{self, Block};
use crate::registry::Registered;
use crate::types::*;
use crate::{FB_TON2, SL_GROUP, SL_LINK, SL_MEMBER};
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
    if p.is_null() {
        return Err(SL_E_NULL);
    }
    if (p as usize) % core::mem::align_of::<B>() != 0 {
        return Err(SL_E_ALIGNMENT);
    }
    // SAFETY: `p` is non-null and aligned; the caller guarantees (ABI §4) that it points to
    // a live instance of `B` that nothing else accesses during the call. `B` holds only
    // integer fields, so every byte pattern in it is a valid value.
    Ok(unsafe { &mut *p })
}

/// Turns a read-only instance pointer into a shared reference, or the status code that
/// refuses it (NULL, misaligned).
fn instance_ref<'a, B>(p: *const B) -> Result<&'a B, i32> {
    if p.is_null() {
        return Err(SL_E_NULL);
    }
    if (p as usize) % core::mem::align_of::<B>() != 0 {
        return Err(SL_E_ALIGNMENT);
    }
    // SAFETY: `p` is non-null and aligned; the caller guarantees (ABI §4) that it points to
    // a live instance of `B` that nobody writes during the call. `B` holds only integer
    // fields, so every byte pattern in it is a valid value.
    Ok(unsafe { &*p })
}

/// One call of a block function behind the panic boundary. After a caught panic the
/// instance is forced into ERROR with safe outputs.
fn block_call<B: Block>(p: *mut B, f: impl FnOnce(&mut B) -> Status) -> i32 {
    let fb = match instance(p) {
        Ok(fb) => fb,
        Err(e) => return e,
    };
    ffi_boundary!(
        {
            ffi_boundary!((), envelope::force_error(&mut *fb));
            SL_E_INTERNAL
        },
        f(&mut *fb).code()
    )
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
/// (`SL_TYPE_<NAME>`): "RUN", "STOP", "DELAYOUT", ... ; "?" for a value the block does not
/// have. Never NULL.
#[no_mangle]
#[allow(non_snake_case)]
pub extern "C" fn sl_state_str(nType: u16, nState: u8) -> *const c_char {
    ffi_boundary!(
        UNKNOWN_STATE.as_ptr(),
        crate::blocks::info(nType)
            .and_then(|b| b.states.iter().find(|(v, _)| *v == nState))
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
            let fb = instance_ref(fb)?;
            let out = instance(pElapsedMs)?;
            *out = crate::blocks::ton2::elapsed(fb).map_err(Status::code)?;
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
        crate::blocks::ton2::restore_elapsed(fb, nElapsedMs)
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
                block_call(fb, envelope::init)
            }

            #[doc = concat!("`", stringify!($cycle), "`: one task cycle at `tNow` (monotonic ms, may wrap at 2^32).")]
            ///
            /// # Safety
            /// As for the init function.
            #[no_mangle]
            #[allow(non_snake_case)]
            pub unsafe extern "C" fn $cycle(fb: *mut $ty, tNow: u32) -> i32 {
                block_call(fb, |fb| envelope::cycle(fb, tNow))
            }
        )*

        /// The one dispatch from a block type tag to the block: every group operation on a
        /// member goes through here.
        fn member_dyn<'a>(ty: u16, p: *mut c_void) -> Option<&'a mut dyn Member> {
            $(if ty == <$ty as Registered>::INFO.tag {
                return instance(p.cast::<$ty>()).ok().map(|b| b as &mut dyn Member);
            })*
            None
        }
    };
}

crate::for_each_block!(ffi_functions);

/// The caller's member table seen as group members.
struct CMembers<'a>(&'a [SL_MEMBER]);

impl Members for CMembers<'_> {
    fn with<R>(&mut self, i: usize, f: impl FnOnce(&mut dyn Member) -> R) -> Option<R> {
        let e = self.0.get(i)?;
        member_dyn(e.nType, e.pBlock).map(f)
    }
}

/// A caller array as a slice; NULL is allowed only for an empty one.
fn storage<'a, T>(p: *mut T, len: usize) -> Result<&'a mut [T], i32> {
    if len == 0 {
        return Ok(&mut []);
    }
    if p.is_null() {
        return Err(SL_E_NULL);
    }
    if (p as usize) % core::mem::align_of::<T>() != 0 {
        return Err(SL_E_ALIGNMENT);
    }
    // SAFETY: `p` is non-null and aligned; the caller guarantees (sl_group_init contract)
    // that it points to at least `len` elements it owns and does not touch during the
    // call. The slice is built from the raw pointer itself, never from a reference to its
    // first element, so it may cover all `len` elements.
    Ok(unsafe { core::slice::from_raw_parts_mut(p, len) })
}

/// Resets a group to power-up (STOP, or STOPERROR with bConnections) with the caller's
/// storage for `nMemberCap` members and `nLinkCap` links. The same arrays must be passed to
/// every later sl_group_* call. Does not modify the group's input fields. Checks before it
/// writes: a refused init (SL_E_NULL, SL_E_ALIGNMENT, SL_E_CONFIG for bConnections > 1 or
/// a group still in RUN/START) changes nothing.
///
/// # Safety
/// `g` is NULL or points to a live SL_GROUP; `aMembers` / `aLinks` are NULL or point to at least `nMemberCap` / `nLinkCap` entries; the caller keeps all of them alive and untouched for as long as the group is used.
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
            let g = instance(g)?;
            let members = storage(aMembers, usize::from(nMemberCap))?;
            let links = storage(aLinks, usize::from(nLinkCap))?;
            // A refused init changes nothing: a running group keeps its members.
            if !group::init_valid(g) {
                return Err(SL_E_CONFIG);
            }
            members.fill(SL_MEMBER::default());
            links.fill(SL_LINK::default());
            Ok(group::init(g, nMemberCap, nLinkCap))
        };
        run().unwrap_or_else(|e| e)
    })
}

/// Adds a block as the next member (execution order) while the group is stopped.
/// `nType` is `SL_TYPE_<NAME>`; the index is written to `*pIndex` unless it is NULL.
/// A block can be a member once; SL_E_FULL when the member storage is full.
///
/// # Safety
/// As for `sl_group_init`, with the same tables; `pBlock` points to a live block of type `nType` that stays alive while it is a member; `pIndex` is NULL or writable.
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
        let run = || -> Result<i32, i32> {
            let group_addr = g as usize;
            let g = instance(g)?;
            member_dyn(nType, pBlock).ok_or(if pBlock.is_null() {
                SL_E_NULL
            } else {
                SL_E_CONFIG
            })?;
            let overlaps_group =
                (pBlock as usize).abs_diff(group_addr) < core::mem::size_of::<SL_GROUP>();
            let (members, _) = group::storage_len(g).ok_or(SL_E_CORRUPT)?;
            let table = storage(aMembers, members + 1)?;
            if overlaps_group || table[..members].iter().any(|m| m.pBlock == pBlock) {
                return Err(SL_E_CONFIG);
            }
            let index = group::reserve_member(g)?;
            table[usize::from(index)] = SL_MEMBER {
                pBlock,
                nType,
                aReserved: [0; 6],
            };
            if let Ok(out) = instance(pIndex) {
                *out = index;
            }
            Ok(SL_OK)
        };
        run().unwrap_or_else(|e| e)
    })
}

/// Links the output at byte `nSrcOffset` of member `nSrcMember` to the input at byte
/// `nDstOffset` of member `nDstMember` (offsets as in the `FB_<NAME>` structs). Both fields
/// must have the same IEC type: BOOL to BOOL (SL_LINK_BOOL), INT/UINT to the same
/// (SL_LINK_ANALOG16), DINT/UDINT to the same (SL_LINK_ANALOG32). The value is
/// copied just before the destination executes: a link from an earlier member carries this
/// cycle's value, one from a later member the previous cycle's. SL_E_CONFIG for a field
/// that is not a linkable output / input of a member, or an input that is already linked.
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
    ffi_boundary!(SL_E_INTERNAL, {
        let run = || -> Result<i32, i32> {
            let g = instance(g)?;
            let (members, _) = group::storage_len(g).ok_or(SL_E_CORRUPT)?;
            let table = storage(aMembers, members)?;
            let links = storage(aLinks, group::link_capacity(g).ok_or(SL_E_CORRUPT)?)?;
            // The kind follows from the source field's type; add_link refuses a
            // destination of another type.
            let kind = CMembers(table)
                .with(usize::from(nSrcMember), |b| {
                    b.fields()
                        .iter()
                        .find(|f| f.offset == nSrcOffset)
                        .and_then(|f| group::link_kind(f.kind))
                })
                .flatten()
                .unwrap_or(SL_LINK_BOOL);
            let link = SL_LINK {
                nSrcMember,
                nSrcOffset,
                nDstMember,
                nDstOffset,
                nKind: kind,
                aReserved: [0; 3],
            };
            Ok(group::add_link(g, &mut CMembers(table), links, link))
        };
        run().unwrap_or_else(|e| e)
    })
}

/// One group cycle at `tNow`: group state, then every member in order (links first), all
/// with the same `tNow`. Returns the group's status or the worst status of a member.
///
/// # Safety
/// As for `sl_group_init`, with the same tables; every member block is still alive.
#[no_mangle]
#[allow(non_snake_case)]
pub unsafe extern "C" fn sl_group_cycle(
    g: *mut SL_GROUP,
    aMembers: *mut SL_MEMBER,
    aLinks: *mut SL_LINK,
    tNow: u32,
) -> i32 {
    ffi_boundary!(SL_E_INTERNAL, {
        let run = || -> Result<i32, i32> {
            let g = instance(g)?;
            let Some((members, links)) = group::storage_len(g) else {
                return Ok(group::cycle(g, &mut CMembers(&[]), &[], tNow));
            };
            let table = storage(aMembers, members)?;
            let links = storage(aLinks, links)?;
            Ok(group::cycle(g, &mut CMembers(table), links, tNow))
        };
        run().unwrap_or_else(|e| e)
    })
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
        let run = || -> Result<i32, i32> {
            if nLen == 0 {
                return Ok(if buf.is_null() { SL_E_NULL } else { SL_OK });
            }
            let out = storage(buf.cast::<u8>(), nLen)?;
            let Some(info) = crate::blocks::info(nType) else {
                out[0] = 0;
                return Err(SL_E_CONFIG);
            };
            let (text, nul) = out.split_at_mut(nLen - 1);
            let n = crate::blocks::diag_text(info, nDiag, text);
            // `n < nLen`, so index n is inside `text` or is `nul[0]`.
            match text.get_mut(n) {
                Some(b) => *b = 0,
                None => nul[0] = 0,
            }
            Ok(SL_OK)
        };
        run().unwrap_or_else(|e| e)
    })
}
