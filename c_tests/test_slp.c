/*
 * FB_SLP through the C ABI (manual §4.29, ABI-2 §11.14; docs/semantics.md PL1-PL6): a
 * multi-turn window across a turn boundary (RUN / SAFE with BelowMin, AboveMax), START on an
 * invalid position, the live limit error 0x40D0 with its parameters and its acknowledgement,
 * crossing parameter limits refused with their Text ID, and a single-turn window that wraps.
 */
#include "harness.h"

static FB_SLP slp_multiturn(void)
{
    FB_SLP s;
    memset(&s, 0, sizeof s);
    s.wInputActive = SL_SLP_ACTIVE_SAFEPOSVALID | SL_SLP_ACTIVE_SINGLETURNPOS | SL_SLP_ACTIVE_MULTITURNPOS;
    s.nMultiturnPosLLFix = -1;
    s.nSingleturnPosLLFix = 0xFFFFFF00u;
    s.nMultiturnPosULFix = 0;
    s.nSingleturnPosULFix = 0x100u;
    return s;
}

static void slp_window_across_a_turn(void)
{
    FB_SLP s = slp_multiturn();
    h_begin("SLP: multi-turn window (-1, 0xFFFFFF00) .. (0, 0x100): RUN, SAFE below/above, START (PL1, PL2)");
    CHECK_INT(sl_slp_init(&s), SL_OK);
    s.bRun = 1;
    s.bSafePosValid = 1;
    s.nMultiturnPos = -1;
    s.nSingleturnPos = 0xFFFFFFFFu;
    CHECK_INT(sl_slp_cycle(&s, 0), SL_OK);
    CHECK_INT(s.nState, SL_STATE_RUN);
    CHECK_INT(s.bPositionInLimit, 1);
    s.nSingleturnPos = 0xFFFFFEFFu;
    sl_slp_cycle(&s, 1);
    CHECK_INT(s.nState, SL_STATE_SAFE);
    CHECK_INT(s.bBelowMin, 1);
    CHECK_INT(s.bAboveMax, 0);
    s.nMultiturnPos = 0;
    s.nSingleturnPos = 0x101u;
    sl_slp_cycle(&s, 2);
    CHECK_INT(s.bAboveMax, 1);
    CHECK_INT(s.bPositionInLimit, 0);
    s.bSafePosValid = 0;
    sl_slp_cycle(&s, 3);
    CHECK_INT(s.nState, SL_STATE_START);
    CHECK_INT(s.bAboveMax, 0);
    CHECK_STR(sl_state_str(SL_TYPE_SLP, s.nState), "START");
    h_end();
}

static void slp_live_limit_error(void)
{
    FB_SLP s = slp_multiturn();
    h_begin("SLP: UL from the inputs below LL -> ERROR 0x40D0, ack once fixed (PL3)");
    s.wInputActive |= SL_SLP_ACTIVE_SINGLETURNPOSUL | SL_SLP_ACTIVE_MULTITURNPOSUL;
    CHECK_INT(sl_slp_init(&s), SL_OK);
    s.bRun = 1;
    s.bSafePosValid = 1;
    s.nMultiturnPosUL = -2;
    CHECK_INT(sl_slp_cycle(&s, 0), SL_OK);
    CHECK_INT(s.nState, SL_STATE_ERROR);
    CHECK_INT(s.bError, 1);
    CHECK_INT(s.nDiag, SL_DIAG_SLP_MULTITURN_LL_ABOVE_UL);
    CHECK_INT(s.nDiagTextId, 0x40D0);
    CHECK_INT(s.dwDiagPar2, 0xFFFFFFFFu);
    CHECK_INT(s.dwDiagPar3, 0xFFFFFFFEu);
    CHECK_DIAG_TEXT(SL_TYPE_SLP, 1, "MultiturnPos_LL>MultiturnPos_UL");
    s.nMultiturnPosUL = 0;
    s.nSingleturnPosUL = 5;
    s.bErrAck = 1;
    sl_slp_cycle(&s, 1);
    CHECK_INT(s.nState, SL_STATE_RESET);
    CHECK_INT(s.nDiagTextId, 0);
    s.bErrAck = 0;
    sl_slp_cycle(&s, 2);
    CHECK_INT(s.nState, SL_STATE_RUN);
    h_end();
}

static void slp_fixed_limits_refused_and_single_turn(void)
{
    FB_SLP s = slp_multiturn();
    h_begin("SLP: crossing parameter limits SL_E_CONFIG with 0x40D1; single-turn wrap window (PL3, PL4)");
    s.nMultiturnPosLLFix = 0;
    s.nSingleturnPosLLFix = 0x200u;
    CHECK_INT(sl_slp_init(&s), SL_E_CONFIG);
    CHECK_INT(s.nState, SL_STATE_STOP);
    CHECK_INT(s.nDiagTextId, 0x40D1);
    CHECK_INT(s.dwDiagPar2, 0x200u);
    CHECK_INT(s.dwDiagPar3, 0x100u);
    s.dwOptions = SL_OPT_SLP_SINGLETURN;
    CHECK_INT(sl_slp_init(&s), SL_OK);
    s.bRun = 1;
    s.bSafePosValid = 1;
    s.nSingleturnPos = 0x150u;
    sl_slp_cycle(&s, 0);
    CHECK_INT(s.nState, SL_STATE_SAFE);
    CHECK_INT(s.bBelowMin, 0);
    s.nSingleturnPos = 0xFFFFFFFFu;
    sl_slp_cycle(&s, 1);
    CHECK_INT(s.nState, SL_STATE_RUN);
    h_end();
}

void run_slp_scenarios(void)
{
    slp_window_across_a_turn();
    slp_live_limit_error();
    slp_fixed_limits_refused_and_single_turn();
}
