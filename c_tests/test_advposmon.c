/*
 * FB_ADVPOSMON through the C ABI (manual §4.31, ABI-2 §11.16; docs/semantics.md AP1-AP5):
 * the drive signals written as link inputs, RUN with Active / Wait / OverRange, the restart
 * sequence WAIT-FOR-RESTART -> START -> RUN, SDFB_ERROR -> ERROR 0x38D1 with the instance.
 */
#include "harness.h"

static void advposmon_run_and_restart(void)
{
    FB_ADVPOSMON a;
    memset(&a, 0, sizeof a);
    h_begin("ADVPOSMON: Wait, Active, OverRange -> WAIT-FOR-RESTART, Restart -> START -> RUN (AP2, AP3)");
    a.wInputActive = SL_ADVPOSMON_ACTIVE_ENABLE | SL_ADVPOSMON_ACTIVE_RESTART;
    CHECK_INT(sl_advposmon_init(&a), SL_OK);
    a.bRun = 1;
    a.bEnable = 1;
    CHECK_INT(sl_advposmon_cycle(&a, 0), SL_OK);
    CHECK_INT(a.nState, SL_STATE_RUN);
    CHECK_INT(a.bWait, 1);
    a.bPosRefOk = 1;
    a.bPosCheckOk = 1;
    sl_advposmon_cycle(&a, 1);
    CHECK_INT(a.bActive, 1);
    CHECK_INT(a.bWait, 0);
    a.bPosCheckOk = 0;
    sl_advposmon_cycle(&a, 2);
    CHECK_INT(a.nState, SL_STATE_ADVPOSMON_WAIT_FOR_RESTART);
    CHECK_INT(a.bOverRange, 1);
    CHECK_INT(a.bActive, 0);
    CHECK_STR(sl_state_str(SL_TYPE_ADVPOSMON, a.nState), "WAIT-FOR-RESTART");
    a.bPosCheckOk = 1;
    a.bRestart = 1;
    sl_advposmon_cycle(&a, 3);
    CHECK_INT(a.nState, SL_STATE_START);
    CHECK_INT(a.bOverRange, 1);
    a.bRestart = 0;
    sl_advposmon_cycle(&a, 4);
    CHECK_INT(a.nState, SL_STATE_RUN);
    CHECK_INT(a.bActive, 1);
    a.bEnable = 0;
    sl_advposmon_cycle(&a, 5);
    CHECK_INT(a.nState, SL_STATE_SAFE);
    CHECK_INT(a.bActive, 0);
    h_end();
}

static void advposmon_sdfb_error(void)
{
    FB_ADVPOSMON a;
    memset(&a, 0, sizeof a);
    h_begin("ADVPOSMON: SDFB_ERROR of instance 3 -> ERROR 0x38D1, remains, RESET (AP4, AP5)");
    a.wInputActive = SL_ADVPOSMON_ACTIVE_ENABLE;
    a.nChBPrimaryFeedback = 3;
    CHECK_INT(sl_advposmon_init(&a), SL_OK);
    a.bRun = 1;
    a.bEnable = 1;
    a.bPosRefOk = 1;
    a.bPosCheckOk = 1;
    a.bSdfbError = 1;
    a.nSdfbInstance = 3;
    CHECK_INT(sl_advposmon_cycle(&a, 0), SL_OK);
    CHECK_INT(a.nState, SL_STATE_ERROR);
    CHECK_INT(a.bError, 1);
    CHECK_INT(a.nDiag, 3);
    CHECK_INT(a.nDiagTextId, SL_TEXT_ADVPOSMON_SDFB_ERROR);
    CHECK_DIAG_TEXT(SL_TYPE_ADVPOSMON, 3, "SAFEDRIVEFEEDBACK instance 3 has changed to the ERROR state");
    a.bErrAck = 1;
    sl_advposmon_cycle(&a, 1);
    CHECK_INT(a.nState, SL_STATE_ERROR);
    a.bErrAck = 0;
    a.bSdfbError = 0;
    sl_advposmon_cycle(&a, 2);
    a.bErrAck = 1;
    sl_advposmon_cycle(&a, 3);
    CHECK_INT(a.nState, SL_STATE_RESET);
    a.bErrAck = 0;
    sl_advposmon_cycle(&a, 4);
    CHECK_INT(a.nState, SL_STATE_RUN);
    CHECK_INT(a.bActive, 1);
    a.nChAPrimaryFeedback = 4;
    CHECK_INT(sl_advposmon_init(&a), SL_E_CONFIG);
    h_end();
}

void run_advposmon_scenarios(void)
{
    advposmon_run_and_restart();
    advposmon_sdfb_error();
}
