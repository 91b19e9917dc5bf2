//! FB_CONNECTION_SHUTDOWN on its own (manual §4.15, ABI-2 §11.1, docs/semantics.md CS1–CS8):
//! every state (RUN, STOP, SAFE, ERROR, RESET), the request, the discrepancy error (diag
//! bit 0), invalid bytes, parameters. Its wiring to a connection in a group:
//! tests/fsoe_group.rs.

use safelogic::*;

fn block(active: u16, negated: u16, disc: u32) -> FB_CONNECTION_SHUTDOWN {
    let mut b = FB_CONNECTION_SHUTDOWN {
        nConnectionId: 7,
        wInputActive: active,
        wInputNegated: negated,
        tDiscTime12: disc,
        ..Default::default()
    };
    assert_eq!(b.init(), SL_OK);
    b.bRun = 1;
    b
}

fn outs(b: &FB_CONNECTION_SHUTDOWN) -> (u8, u8, u8, u8, u16) {
    (
        b.nState,
        b.bError,
        b.bDeactivated,
        b.bShutdownRequest,
        b.nDiag,
    )
}

#[test]
fn parameters() {
    let ok = |active, negated, disc, id| {
        let mut b = FB_CONNECTION_SHUTDOWN {
            nConnectionId: id,
            wInputActive: active,
            wInputNegated: negated,
            tDiscTime12: disc,
            ..Default::default()
        };
        b.init()
    };
    assert_eq!(ok(0b01, 0, 0, 7), SL_OK);
    assert_eq!(
        ok(0, 0, 0, 7),
        SL_OK,
        "no active input: the partner's side (CS4)"
    );
    assert_eq!(ok(0b11, 0b11, 65_535, 65_535), SL_OK);
    assert_eq!(ok(0b01, 0, 0, 0), SL_E_CONFIG, "Connection ID 0");
    assert_eq!(
        ok(0b01, 0, 100, 7),
        SL_E_CONFIG,
        "discrepancy time needs the pair"
    );
    assert_eq!(ok(0b11, 0, 65_536, 7), SL_E_CONFIG);
    assert_eq!(ok(0b111, 0, 0, 7), SL_E_CONFIG);
    assert_eq!(ok(0b01, 0b100, 0, 7), SL_E_CONFIG);
}

#[test]
fn stop_safe_run_and_the_request() {
    let mut b = block(0b01, 0, 0);
    b.bRun = 0;
    assert_eq!(b.cycle(0), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_STOP, 0, 0, 0, 0));
    assert_eq!(b.state_name(), "STOP");
    b.bDeactivate1 = 1;
    assert_eq!(b.cycle(10), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_STOP, 0, 0, 0, 0), "no request in STOP");
    b.bRun = 1;
    assert_eq!(b.cycle(20), SL_OK);
    assert_eq!(
        outs(&b),
        (SL_STATE_SAFE, 0, 0, 1, 0),
        "SAFE with the request"
    );
    // RUN only once the connection reports its shutdown (CS1).
    b.bConnShutdown = 1;
    assert_eq!(b.cycle(30), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_RUN, 0, 1, 1, 0));
    assert_eq!(b.state_name(), "RUN");
    // Request released: RUN until the connection is back in DATA (bConnShutdown FALSE).
    b.bDeactivate1 = 0;
    assert_eq!(b.cycle(40), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_RUN, 0, 1, 0, 0));
    b.bConnShutdown = 0;
    assert_eq!(b.cycle(50), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_SAFE, 0, 0, 0, 0));
    // bRun FALSE in RUN: STOP, every output FALSE.
    b.bConnShutdown = 1;
    b.bDeactivate1 = 1;
    assert_eq!(b.cycle(60), SL_OK);
    assert_eq!(b.nState, SL_STATE_RUN);
    b.bRun = 0;
    assert_eq!(b.cycle(70), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_STOP, 0, 0, 0, 0));
    // Started with the connection already shut down: RUN at once.
    b.bRun = 1;
    assert_eq!(b.cycle(80), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_RUN, 0, 1, 1, 0));
}

#[test]
fn every_active_input_must_request_and_negation() {
    let mut b = block(0b11, 0b10, 0);
    // Input 2 negated: its logical value is TRUE when the byte is 0.
    b.bDeactivate1 = 1;
    b.bDeactivate2 = 1;
    assert_eq!(b.cycle(0), SL_OK);
    assert_eq!(b.bShutdownRequest, 0);
    b.bDeactivate2 = 0;
    assert_eq!(b.cycle(10), SL_OK);
    assert_eq!(b.bShutdownRequest, 1);
    b.bDeactivate1 = 0;
    assert_eq!(b.cycle(20), SL_OK);
    assert_eq!(b.bShutdownRequest, 0);
    // No active input: never a request; a partner's shutdown still gives RUN (CS4).
    let mut p = block(0, 0, 0);
    p.bDeactivate1 = 1;
    p.bDeactivate2 = 1;
    assert_eq!(p.cycle(0), SL_OK);
    assert_eq!(outs(&p), (SL_STATE_SAFE, 0, 0, 0, 0));
    p.bConnShutdown = 1;
    assert_eq!(p.cycle(10), SL_OK);
    assert_eq!(outs(&p), (SL_STATE_RUN, 0, 1, 0, 0));
}

#[test]
fn invalid_bytes_read_as_no_shutdown() {
    let mut b = block(0b01, 0, 0);
    b.bDeactivate1 = 2;
    assert_eq!(b.cycle(0), SL_E_INVALID_BOOL);
    assert_eq!(outs(&b), (SL_STATE_SAFE, 0, 0, 0, 0));
    // Negated: an invalid byte is still no request.
    let mut n = block(0b01, 0b01, 0);
    n.bDeactivate1 = 0xFF;
    assert_eq!(n.cycle(0), SL_E_INVALID_BOOL);
    assert_eq!(n.bShutdownRequest, 0);
    b.bDeactivate1 = 1;
    b.bConnShutdown = 2;
    assert_eq!(b.cycle(10), SL_E_INVALID_BOOL);
    assert_eq!(
        outs(&b),
        (SL_STATE_SAFE, 0, 0, 1, 0),
        "not RUN on an invalid byte"
    );
}

#[test]
fn discrepancy_error_reset_and_acknowledgement() {
    let mut b = block(0b11, 0, 100);
    assert_eq!(b.cycle(0), SL_OK);
    b.bDeactivate1 = 1;
    assert_eq!(b.cycle(10), SL_OK);
    assert_eq!(b.cycle(109), SL_OK);
    assert_eq!(b.nState, SL_STATE_SAFE);
    assert_eq!(b.bShutdownRequest, 0, "one of the pair only: no request");
    assert_eq!(b.cycle(110), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_ERROR, 1, 0, 0, SL_DIAG_DISC1));
    assert_eq!(b.state_name(), "ERROR");
    let mut text = [0 as core::ffi::c_char; 64];
    // SAFETY: a 64-byte buffer.
    let rc = unsafe {
        safelogic::ffi::sl_diag_text(SL_TYPE_CONNECTION_SHUTDOWN, b.nDiag, text.as_mut_ptr(), 64)
    };
    assert_eq!(rc, SL_OK);
    // SAFETY: NUL-terminated by sl_diag_text.
    let s = unsafe { core::ffi::CStr::from_ptr(text.as_ptr()) };
    assert_eq!(s.to_str().unwrap(), "discrepancy error input group 1");
    // ErrAck while the pair still differs: stays in ERROR (CS6).
    b.bErrAck = 1;
    assert_eq!(b.cycle(120), SL_OK);
    b.bErrAck = 0;
    assert_eq!(b.cycle(130), SL_OK);
    assert_eq!(b.nState, SL_STATE_ERROR);
    // Agreeing again, then ErrAck: RESET, and SAFE after its falling edge.
    b.bDeactivate2 = 1;
    b.bConnShutdown = 1;
    assert_eq!(b.cycle(140), SL_OK);
    assert_eq!(b.bShutdownRequest, 0, "no request in ERROR");
    b.bErrAck = 1;
    assert_eq!(b.cycle(150), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_RESET, 0, 0, 0, 0));
    assert_eq!(b.state_name(), "RESET");
    b.bErrAck = 0;
    assert_eq!(b.cycle(160), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_RUN, 0, 1, 1, 0));
    // Back to SAFE when both are released and the connection is in DATA again.
    b.bDeactivate1 = 0;
    b.bDeactivate2 = 0;
    b.bConnShutdown = 0;
    assert_eq!(b.cycle(170), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_SAFE, 0, 0, 0, 0));
    // A pair that differs shorter than the time: no error.
    b.bDeactivate1 = 1;
    assert_eq!(b.cycle(180), SL_OK);
    b.bDeactivate2 = 1;
    assert_eq!(b.cycle(279), SL_OK);
    assert_eq!(outs(&b), (SL_STATE_SAFE, 0, 0, 1, 0));
}

#[test]
fn a_parameter_changed_while_running_is_an_error() {
    let mut b = block(0b01, 0, 0);
    assert_eq!(b.cycle(0), SL_OK);
    b.nConnectionId = 8;
    assert_eq!(b.cycle(10), SL_E_PARAM_CHANGED);
    assert_eq!(b.nState, SL_STATE_ERROR);
    assert_eq!(b.bShutdownRequest, 0);
}
