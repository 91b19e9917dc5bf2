/*
 * FB_CAMMONITOR_UINT / _UDINT through the C ABI (manual §4.26, ABI-2 §11.13;
 * docs/semantics.md CM1-CM20): an excentric stroke from WAIT-FOR-RESET through every MOVE
 * state with its outputs, an overrun past OverrunMax (0x400D) and its acknowledgement, a
 * refused configuration with its Text ID, a hardware cam that fails (0x4003), and a
 * pendulum swing in the UDINT variant.
 */
#include "harness.h"

static FB_CAMMONITOR_UINT cam_excentric(void)
{
    FB_CAMMONITOR_UINT c;
    memset(&c, 0, sizeof c);
    c.wInputActive = SL_CAMMONITOR_ACTIVE_RESET | SL_CAMMONITOR_ACTIVE_POSITION;
    c.tStopDetectionTime = 50;
    c.nAllowedPositionJitter = 4;
    c.nMaxPosition = 8192;
    c.nTDC1LowerLimitFix = 8092;
    c.nTDC1UpperLimitFix = 100;
    c.nBDCLowerLimitFix = 3896;
    c.nBDCUpperLimitFix = 4296;
    c.nOverrunMaxFix = 800;
    return c;
}

static uint32_t cam_now;

/* Clockwise in steps of 40 to `target` (wrapping at 8193 positions). */
static void cam_cw_to(FB_CAMMONITOR_UINT *c, uint16_t target)
{
    while (c->nPosition != target && c->nState != SL_STATE_ERROR) {
        uint32_t d = (target + 8193u - c->nPosition) % 8193u;
        c->nPosition = (uint16_t)((c->nPosition + (d < 40u ? d : 40u)) % 8193u);
        cam_now += 10;
        sl_cammonitor_uint_cycle(c, cam_now);
    }
}

static void cam_hold(FB_CAMMONITOR_UINT *c, int calls)
{
    for (int i = 0; i < calls; i++) {
        cam_now += 10;
        sl_cammonitor_uint_cycle(c, cam_now);
    }
}

static void cam_excentric_stroke(void)
{
    FB_CAMMONITOR_UINT c = cam_excentric();
    h_begin("CAMMONITOR_UINT: excentric stroke WAIT-FOR-RESET, START, RUN, MOVE-DOWN/UP/TDC/STOP/START (CM4, CM6)");
    cam_now = 0;
    CHECK_INT(sl_cammonitor_uint_init(&c), SL_OK);
    CHECK_INT(c.nState, SL_STATE_STOP);
    c.bRun = 1;
    c.nPosition = 50;
    CHECK_INT(sl_cammonitor_uint_cycle(&c, cam_now), SL_OK);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_WAIT_FOR_RESET);
    CHECK_INT(c.bCamMonOK, 0);
    c.bReset = 1;
    cam_hold(&c, 1);
    CHECK_INT(c.nState, SL_STATE_START);
    c.bReset = 0;
    cam_hold(&c, 1);
    CHECK_INT(c.nState, SL_STATE_RUN);
    CHECK_INT(c.bCamMonOK, 1);
    CHECK_INT(c.bTDC, 1);
    cam_cw_to(&c, 4000);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_DOWN);
    CHECK_INT(c.bBDC, 1);
    cam_cw_to(&c, 5000);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_UP);
    CHECK_INT(c.bUpwardsMove, 1);
    cam_cw_to(&c, 8100);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_TDC);
    CHECK_INT(c.nOverrunTDC, 8);
    cam_cw_to(&c, 300);
    cam_hold(&c, 6);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_STOP);
    CHECK_INT(c.nOverrunTDC, 401);
    CHECK_STR(sl_state_str(SL_TYPE_CAMMONITOR_UINT, c.nState), "MOVE-STOP");
    c.bReset = 1;
    cam_hold(&c, 1);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_START);
    c.bReset = 0;
    cam_hold(&c, 1);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_DOWN);
    h_end();
}

static void cam_overrun_and_ack(void)
{
    FB_CAMMONITOR_UINT c = cam_excentric();
    h_begin("CAMMONITOR_UINT: past OverrunMax in MOVE-TDC -> ERROR 0x400D, ErrAck -> RESET -> WAIT-FOR-RESET");
    cam_now = 0;
    CHECK_INT(sl_cammonitor_uint_init(&c), SL_OK);
    c.bRun = 1;
    c.nPosition = 50;
    cam_hold(&c, 1);
    c.bReset = 1;
    cam_hold(&c, 1);
    c.bReset = 0;
    cam_hold(&c, 1);
    cam_cw_to(&c, 8100);
    cam_cw_to(&c, 900);
    CHECK_INT(c.nState, SL_STATE_ERROR);
    CHECK_INT(c.bError, 1);
    CHECK_INT(c.bCamMonOK, 0);
    CHECK_INT(c.nDiagTextId, SL_TEXT_CAMMONITOR_LEFT_TDC);
    CHECK_INT(c.nDiag, 0x0D);
    CHECK_INT(c.dwDiagPar2, 827);
    CHECK_DIAG_TEXT(SL_TYPE_CAMMONITOR_UINT, 0x0D, "The Position has left the top dead center while waiting for a stop");
    c.bErrAck = 1;
    cam_hold(&c, 1);
    CHECK_INT(c.nState, SL_STATE_RESET);
    CHECK_INT(c.nDiagTextId, 0);
    c.bErrAck = 0;
    cam_hold(&c, 1);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_WAIT_FOR_RESET);
    h_end();
}

static void cam_refused_and_cam_error(void)
{
    FB_CAMMONITOR_UINT c = cam_excentric();
    h_begin("CAMMONITOR_UINT: BDC_UpperLimit at 180 deg + J refused (0x4017); OverrunCam FALSE in TDC -> 0x4003");
    c.nBDCUpperLimitFix = 4100;
    CHECK_INT(sl_cammonitor_uint_init(&c), SL_E_CONFIG);
    CHECK_INT(c.nDiagTextId, SL_TEXT_CAMMONITOR_BDCUL_HALF);
    CHECK_INT(c.dwDiagPar2, 4100);
    CHECK_INT(c.dwDiagPar3, 4100);
    c.nBDCUpperLimitFix = 4101;
    c.wInputActive |= SL_CAMMONITOR_ACTIVE_OVERRUNCAM;
    CHECK_INT(sl_cammonitor_uint_init(&c), SL_OK);
    c.bRun = 1;
    c.nPosition = 50;
    c.bOverrunCam = 0;
    CHECK_INT(sl_cammonitor_uint_cycle(&c, 0), SL_OK);
    CHECK_INT(c.nState, SL_STATE_ERROR);
    CHECK_INT(c.nDiagTextId, SL_TEXT_CAMMONITOR_OVERRUNCAM_FALSE_TDC);
    CHECK_INT(c.dwDiagPar2, 50);
    h_end();
}

static void cam_pendulum_udint(void)
{
    FB_CAMMONITOR_UDINT c;
    uint32_t now = 0;
    memset(&c, 0, sizeof c);
    h_begin("CAMMONITOR_UDINT: pendulum RUN -> MOVE-DOWN-CLOCKWISE -> MOVE-UP-CLOCKWISE -> MOVE-UP-TDC1 -> MOVE-STOP-TDC1 (CM7)");
    c.wInputActive = SL_CAMMONITOR_ACTIVE_RESET | SL_CAMMONITOR_ACTIVE_POSITION;
    c.dwOptions = SL_OPT_CAMMONITOR_PENDULUM;
    c.tStopDetectionTime = 50;
    c.nAllowedPositionJitter = 4;
    c.nMaxPosition = 8192;
    c.nTDC2UpperLimitFix = 400;
    c.nTDC2LowerLimitFix = 3696;
    c.nBDCLowerLimitFix = 3996;
    c.nBDCUpperLimitFix = 4196;
    c.nTDC1LowerLimitFix = 4496;
    c.nTDC1UpperLimitFix = 7796;
    CHECK_INT(sl_cammonitor_udint_init(&c), SL_OK);
    c.bRun = 1;
    c.nPosition = 1300;
    sl_cammonitor_udint_cycle(&c, now += 10);
    c.bReset = 1;
    sl_cammonitor_udint_cycle(&c, now += 10);
    c.bReset = 0;
    sl_cammonitor_udint_cycle(&c, now += 10);
    CHECK_INT(c.nState, SL_STATE_RUN);
    c.nPosition += 40;
    sl_cammonitor_udint_cycle(&c, now += 10);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_DOWN_CW);
    while (c.nPosition < 4300) {
        c.nPosition += 40;
        sl_cammonitor_udint_cycle(&c, now += 10);
    }
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_UP_CW);
    CHECK_INT(c.bUpwardsMove, 1);
    while (c.nPosition < 6500) {
        c.nPosition += 40;
        sl_cammonitor_udint_cycle(&c, now += 10);
    }
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_UP_TDC1);
    for (int i = 0; i < 6; i++)
        sl_cammonitor_udint_cycle(&c, now += 10);
    CHECK_INT(c.nState, SL_STATE_CAMMONITOR_MOVE_STOP_TDC1);
    CHECK_INT(c.bTDC, 1);
    CHECK_STR(sl_state_str(SL_TYPE_CAMMONITOR_UDINT, c.nState), "MOVE-STOP-TDC1");
    h_end();
}

void run_cammonitor_scenarios(void)
{
    cam_excentric_stroke();
    cam_overrun_and_ack();
    cam_refused_and_cam_error();
    cam_pendulum_udint();
}
