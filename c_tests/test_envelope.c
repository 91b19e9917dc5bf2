/*
 * FB_ENVELOPE through the C ABI (manual §4.32, fb-envelope-states.txt, ABI-2 §11.11, §12;
 * docs/semantics.md EV1-EV7): a monitored stop RUN -> MONITOR -> DELAYOUT -> SAFE, the
 * envelope violation with diag value, Text ID and parameters and its acknowledgement,
 * MaxTime ending in SAFE without an error, the parameter limits, and an AND driving
 * SafeFunction in a group.
 */
#include "harness.h"

static void envelope_dint_monitored_stop(void)
{
    FB_ENVELOPE_DINT e;
    memset(&e, 0, sizeof e);
    h_begin("ENVELOPE_DINT: RUN -> MONITOR -> DELAYOUT -> SAFE (EV1-EV4)");
    e.wInputActive = SL_ENVELOPE_ACTIVE;
    e.tTimeAfterInTarget = 50;
    e.tMaxTime = 1000;
    e.nTargetValue = 10;
    e.nOffset = 100;
    CHECK_INT(sl_envelope_dint_init(&e), SL_OK);
    e.bRun = 1;
    e.bSafeFunction = 1;
    e.nInValue = -1000;
    CHECK_INT(sl_envelope_dint_cycle(&e, 0), SL_OK);
    CHECK_INT(e.nState, SL_STATE_RUN);
    CHECK_INT(e.bSafeFunctionOut, 1);
    e.bSafeFunction = 0; /* latch |-1000|: the envelope falls from 1100 to 10 in 1000 ms */
    sl_envelope_dint_cycle(&e, 100);
    CHECK_INT(e.nState, SL_STATE_ENVELOPE_MONITOR);
    CHECK_INT(e.bSafeFunctionOut, 1);
    CHECK_STR(sl_state_str(SL_TYPE_ENVELOPE_DINT, e.nState), "MONITOR");
    e.nInValue = -555; /* E(500 ms) = (1100 * 500 + 10 * 500) / 1000 = 555 */
    CHECK_INT(sl_envelope_dint_cycle(&e, 600), SL_OK);
    CHECK_INT(e.nState, SL_STATE_ENVELOPE_MONITOR);
    e.nInValue = 10;
    sl_envelope_dint_cycle(&e, 700);
    CHECK_INT(e.nState, SL_STATE_DELAYOUT);
    CHECK_INT(e.bSafeFunctionOut, 1);
    sl_envelope_dint_cycle(&e, 749);
    CHECK_INT(e.nState, SL_STATE_DELAYOUT);
    sl_envelope_dint_cycle(&e, 750);
    CHECK_INT(e.nState, SL_STATE_SAFE);
    CHECK_INT(e.bSafeFunctionOut, 0);
    CHECK_INT(e.bError, 0);
    h_end();
}

static void envelope_int_violation_and_max_time(void)
{
    FB_ENVELOPE_INT e;
    memset(&e, 0, sizeof e);
    h_begin("ENVELOPE_INT: underflow 0x40C8 with InValue and -E(t), ack; MaxTime -> SAFE (EV5-EV7)");
    CHECK_INT(offsetof(FB_ENVELOPE_INT, tTimeAfterInTarget), 28);
    CHECK_INT(offsetof(FB_ENVELOPE_INT, stPrivate), 72);
    e.wInputActive = SL_ENVELOPE_ACTIVE;
    e.tTimeAfterInTarget = 100;
    e.tMaxTime = 0;
    CHECK_INT(sl_envelope_int_init(&e), SL_E_CONFIG);
    e.tMaxTime = 65536;
    CHECK_INT(sl_envelope_int_init(&e), SL_E_CONFIG);
    e.tMaxTime = 200;
    e.nTargetValue = 0;
    e.nOffset = 0;
    CHECK_INT(sl_envelope_int_init(&e), SL_OK);
    e.bRun = 1;
    e.bSafeFunction = 1;
    e.nInValue = -200;
    sl_envelope_int_cycle(&e, 0);
    e.bSafeFunction = 0;
    sl_envelope_int_cycle(&e, 0); /* E(t) = 200 - t */
    CHECK_INT(e.nState, SL_STATE_ENVELOPE_MONITOR);
    e.nInValue = -151; /* E(50) = 150 */
    sl_envelope_int_cycle(&e, 50);
    CHECK_INT(e.nState, SL_STATE_ERROR);
    CHECK_INT(e.bError, 1);
    CHECK_INT(e.bSafeFunctionOut, 0);
    CHECK_INT(e.nDiag, SL_DIAG_ENVELOPE_UNDERFLOW);
    CHECK_INT(e.nDiagTextId, SL_TEXT_ENVELOPE_UNDERFLOW);
    CHECK_INT(e.dwDiagPar2, (uint32_t)-151);
    CHECK_INT(e.dwDiagPar3, (uint32_t)-150);
    CHECK_DIAG_TEXT(SL_TYPE_ENVELOPE_INT, 1, "Underflow (InValue below the envelope)");
    e.bErrAck = 1;
    sl_envelope_int_cycle(&e, 60);
    CHECK_INT(e.nState, SL_STATE_RESET);
    CHECK_INT(e.nDiagTextId, 0);
    e.bErrAck = 0;
    sl_envelope_int_cycle(&e, 70);
    CHECK_INT(e.nState, SL_STATE_SAFE);
    e.bSafeFunction = 1;
    sl_envelope_int_cycle(&e, 80);
    CHECK_INT(e.nState, SL_STATE_RUN);
    e.bSafeFunction = 0;
    e.nInValue = 100;
    sl_envelope_int_cycle(&e, 100);
    CHECK_INT(e.nState, SL_STATE_ENVELOPE_MONITOR);
    e.nInValue = 1; /* above E(200) = 0, but MaxTime has elapsed: SAFE, no error */
    sl_envelope_int_cycle(&e, 300);
    CHECK_INT(e.nState, SL_STATE_SAFE);
    CHECK_INT(e.bError, 0);
    CHECK_INT(e.nDiag, 0);
    h_end();
}

static void envelope_in_a_group(void)
{
    SL_GROUP g;
    SL_MEMBER members[2];
    SL_LINK links[1];
    FB_AND and_;
    FB_ENVELOPE_UINT e;
    memset(&g, 0, sizeof g);
    memset(&and_, 0, sizeof and_);
    memset(&e, 0, sizeof e);
    h_begin("group: AND -> ENVELOPE_UINT SafeFunction (Boolean link)");
    and_.wInputActive = 0x3;
    e.wInputActive = SL_ENVELOPE_ACTIVE;
    e.tTimeAfterInTarget = 20;
    e.tMaxTime = 500;
    e.nTargetValue = 5;
    e.nOffset = 10;
    CHECK_INT(sl_group_init(&g, members, 2, links, 1), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_AND, &and_, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_ENVELOPE_UINT, &e, NULL), SL_OK);
    CHECK_INT(sl_group_add_link(&g, members, links, 0, offsetof(FB_AND, bAndOut), 1,
                                offsetof(FB_ENVELOPE_UINT, bSafeFunction)), SL_OK);
    and_.bAndIn1 = 1;
    and_.bAndIn2 = 1;
    e.nInValue = 300;
    g.bRun = 1;
    CHECK_INT(sl_group_cycle(&g, members, links, 0), SL_OK);
    CHECK_INT(e.nState, SL_STATE_RUN);
    and_.bAndIn2 = 0;
    CHECK_INT(sl_group_cycle(&g, members, links, 10), SL_OK);
    CHECK_INT(e.nState, SL_STATE_ENVELOPE_MONITOR);
    CHECK_INT(e.bSafeFunctionOut, 1);
    e.nInValue = 400; /* above E(10) = 310 - 305 * 10 / 500 = 303.9 -> 303 */
    sl_group_cycle(&g, members, links, 20);
    CHECK_INT(e.nState, SL_STATE_ERROR);
    CHECK_INT(e.nDiagTextId, SL_TEXT_ENVELOPE_OVERFLOW);
    CHECK_INT(e.dwDiagPar2, 400);
    CHECK_INT(e.dwDiagPar3, 303);
    h_end();
}

void run_envelope_scenarios(void)
{
    envelope_dint_monitored_stop();
    envelope_int_violation_and_max_time();
    envelope_in_a_group();
}
