//! FB_CONNECTION_SHUTDOWN on its own (manual §4.15, ABI-2 §11.1, docs/semantics.md CS1–CS8):
//! every state (RUN, STOP, SAFE, ERROR, RESET), the request, the discrepancy error (diag
//! bit 0), invalid bytes, parameters. Its wiring to a connection in a group:
//! tests/fsoe_group.rs.

mod common;
use common::run_steps;
use safelogic::*;

type Fb = FB_CONNECTION_SHUTDOWN;

/// Connection ID 7, running (bRun TRUE).
fn block(active: u16, negated: u16, disc: u32) -> Fb {
    Fb {
        bRun: 1,
        ..common::ready(Fb {
            nConnectionId: 7,
            wInputActive: active,
            wInputNegated: negated,
            tDiscTime12: disc,
            ..Default::default()
        })
    }
}

/// (nState, bError, bDeactivated, bShutdownRequest, nDiag).
fn outs(b: &Fb) -> (u8, u8, u8, u8, u16) {
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
    const STOP: (u8, u8, u8, u8, u16) = (SL_STATE_STOP, 0, 0, 0, 0);
    #[rustfmt::skip]
    run_steps("STOP, SAFE", &mut b, outs, &[
        (0, |_| {}, SL_OK, Some(STOP), ""),
    ]);
    assert_eq!(b.state_name(), "STOP");
    #[rustfmt::skip]
    run_steps("SAFE, RUN", &mut b, outs, &[
        (10, |b| b.bDeactivate1 = 1, SL_OK, Some(STOP), "no request in STOP"),
        (20, |b| b.bRun = 1, SL_OK, Some((SL_STATE_SAFE, 0, 0, 1, 0)), "SAFE with the request"),
        // RUN only once the connection reports its shutdown (CS1).
        (30, |b| b.bConnShutdown = 1, SL_OK, Some((SL_STATE_RUN, 0, 1, 1, 0)), ""),
    ]);
    assert_eq!(b.state_name(), "RUN");
    #[rustfmt::skip]
    run_steps("release, STOP", &mut b, outs, &[
        // Request released: RUN until the connection is back in DATA (bConnShutdown FALSE).
        (40, |b| b.bDeactivate1 = 0, SL_OK, Some((SL_STATE_RUN, 0, 1, 0, 0)), ""),
        (50, |b| b.bConnShutdown = 0, SL_OK, Some((SL_STATE_SAFE, 0, 0, 0, 0)), ""),
        // bRun FALSE in RUN: STOP, every output FALSE.
        (60, |b| (b.bConnShutdown, b.bDeactivate1) = (1, 1), SL_OK, None, "RUN, below"),
    ]);
    assert_eq!(b.nState, SL_STATE_RUN);
    #[rustfmt::skip]
    run_steps("STOP, start", &mut b, outs, &[
        (70, |b| b.bRun = 0, SL_OK, Some(STOP), ""),
        // Started with the connection already shut down: RUN at once.
        (80, |b| b.bRun = 1, SL_OK, Some((SL_STATE_RUN, 0, 1, 1, 0)), ""),
    ]);
}

#[test]
fn every_active_input_must_request_and_negation() {
    let mut b = block(0b11, 0b10, 0);
    // Input 2 negated: its logical value is TRUE when the byte is 0.
    #[rustfmt::skip]
    run_steps("negated input 2", &mut b, |b| b.bShutdownRequest, &[
        (0, |b| (b.bDeactivate1, b.bDeactivate2) = (1, 1), SL_OK, Some(0), ""),
        (10, |b| b.bDeactivate2 = 0, SL_OK, Some(1), ""),
        (20, |b| b.bDeactivate1 = 0, SL_OK, Some(0), ""),
    ]);
    // No active input: never a request; a partner's shutdown still gives RUN (CS4).
    let mut p = block(0, 0, 0);
    #[rustfmt::skip]
    run_steps("no active input", &mut p, outs, &[
        (0, |b| (b.bDeactivate1, b.bDeactivate2) = (1, 1), SL_OK, Some((SL_STATE_SAFE, 0, 0, 0, 0)), ""),
        (10, |b| b.bConnShutdown = 1, SL_OK, Some((SL_STATE_RUN, 0, 1, 0, 0)), ""),
    ]);
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
    let state_request = |b: &Fb| (b.nState, b.bShutdownRequest);
    #[rustfmt::skip]
    run_steps("one of the pair", &mut b, state_request, &[
        (0, |_| {}, SL_OK, None, ""),
        (10, |b| b.bDeactivate1 = 1, SL_OK, None, ""),
        (109, |_| {}, SL_OK, Some((SL_STATE_SAFE, 0)), "one of the pair only: no request"),
    ]);
    #[rustfmt::skip]
    run_steps("discrepancy", &mut b, outs, &[
        (110, |_| {}, SL_OK, Some((SL_STATE_ERROR, 1, 0, 0, SL_DIAG_DISC1)), ""),
    ]);
    assert_eq!(b.state_name(), "ERROR");
    assert_eq!(
        common::diag_text(SL_TYPE_CONNECTION_SHUTDOWN, b.nDiag),
        "discrepancy error input group 1"
    );
    #[rustfmt::skip]
    run_steps("ErrAck", &mut b, |b| b.nState, &[
        // ErrAck while the pair still differs: stays in ERROR (CS6).
        (120, |b| b.bErrAck = 1, SL_OK, None, ""),
        (130, |b| b.bErrAck = 0, SL_OK, Some(SL_STATE_ERROR), ""),
    ]);
    #[rustfmt::skip]
    run_steps("agreeing", &mut b, |b| b.bShutdownRequest, &[
        // Agreeing again, then ErrAck: RESET, and SAFE after its falling edge.
        (140, |b| (b.bDeactivate2, b.bConnShutdown) = (1, 1), SL_OK, Some(0), "no request in ERROR"),
    ]);
    #[rustfmt::skip]
    run_steps("RESET", &mut b, outs, &[
        (150, |b| b.bErrAck = 1, SL_OK, Some((SL_STATE_RESET, 0, 0, 0, 0)), ""),
    ]);
    assert_eq!(b.state_name(), "RESET");
    #[rustfmt::skip]
    run_steps("acknowledged", &mut b, outs, &[
        (160, |b| b.bErrAck = 0, SL_OK, Some((SL_STATE_RUN, 0, 1, 1, 0)), ""),
        // Back to SAFE when both are released and the connection is in DATA again.
        (170, |b| (b.bDeactivate1, b.bDeactivate2, b.bConnShutdown) = (0, 0, 0), SL_OK, Some((SL_STATE_SAFE, 0, 0, 0, 0)), ""),
        // A pair that differs shorter than the time: no error.
        (180, |b| b.bDeactivate1 = 1, SL_OK, None, ""),
        (279, |b| b.bDeactivate2 = 1, SL_OK, Some((SL_STATE_SAFE, 0, 0, 1, 0)), ""),
    ]);
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
