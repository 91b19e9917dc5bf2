//! The C ABI (ABI.md §4, §5). Every exported function runs inside `ffi_boundary!`, the one
//! place that catches panics; instance pointers pass through `instance`, the one place that
//! checks NULL and alignment. Nothing else in the crate is `unsafe`.
#![allow(unsafe_code)]

use crate::prim::envelope::{self, Block};
use crate::types::*;
use crate::{FB_ESTOP, FB_MON};
use core::ffi::c_char;

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

/// One call of a block function behind the panic boundary. After a caught panic the
/// instance is forced into ERROR with safe outputs.
fn block_call<B: Block>(p: *mut B, f: impl FnOnce(&mut B) -> i32) -> i32 {
    let fb = match instance(p) {
        Ok(fb) => fb,
        Err(e) => return e,
    };
    ffi_boundary!(
        {
            ffi_boundary!((), envelope::force_error(&mut *fb));
            SL_E_INTERNAL
        },
        f(&mut *fb)
    )
}

/// Validates and latches the parameters of an FB_ESTOP and resets it to power-up (STOP,
/// outputs FALSE). Does not modify any input field. Returns SL_OK or SL_E_CONFIG.
#[no_mangle]
pub extern "C" fn sl_estop_init(fb: *mut FB_ESTOP) -> i32 {
    block_call(fb, envelope::init)
}

/// One task cycle of an FB_ESTOP at `tNow` (monotonic ms, may wrap at 2^32).
#[no_mangle]
#[allow(non_snake_case)]
pub extern "C" fn sl_estop_cycle(fb: *mut FB_ESTOP, tNow: u32) -> i32 {
    block_call(fb, |fb| envelope::cycle(fb, tNow))
}

/// Validates and latches the parameters of an FB_MON and resets it to power-up (STOP,
/// outputs FALSE). Does not modify any input field. Returns SL_OK or SL_E_CONFIG.
#[no_mangle]
pub extern "C" fn sl_mon_init(fb: *mut FB_MON) -> i32 {
    block_call(fb, envelope::init)
}

/// One task cycle of an FB_MON at `tNow` (monotonic ms, may wrap at 2^32).
#[no_mangle]
#[allow(non_snake_case)]
pub extern "C" fn sl_mon_cycle(fb: *mut FB_MON, tNow: u32) -> i32 {
    block_call(fb, |fb| envelope::cycle(fb, tNow))
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

/// Static, NUL-terminated name of a state value ("RUN", "STOP", ...; never NULL).
#[no_mangle]
pub extern "C" fn sl_state_str(state: u8) -> *const c_char {
    ffi_boundary!(state_text(0).as_ptr(), state_text(state).as_ptr()).cast()
}

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
