/*
 * FB_SLI and FB_SLI2 through the C ABI (manual §4.27, §4.28; ABI-2 §11.9, §11.10, §12;
 * docs/semantics.md SI1-SI8): the latch on SLI's rising edge, the window with PositionDiff,
 * overflow -> ERROR 0x40C1 with Position and LatchPosition, RESET held while SLI is TRUE,
 * the limit bound (SL_E_CONFIG), SLI2's EXCEEDED with BelowMin/AboveMax and the modular
 * difference, and a standstill window in a group: an analog link into Position, SLIActive
 * gating an AND.
 */
#include "harness.h"

static void sli_int_window_error_and_reset(void)
{
    FB_SLI_INT s;
    memset(&s, 0, sizeof s);
    h_begin("SLI_INT: latch, window, overflow -> ERROR 0x40C1, RESET held by SLI (SI2-SI4)");
    s.wInputActive = SL_SLI_ACTIVE;
    s.nLimitPos = 32768; /* above INT16's maximum */
    CHECK_INT(sl_sli_int_init(&s), SL_E_CONFIG);
    s.nLimitPos = 100;
    s.nLimitNeg = 50;
    CHECK_INT(sl_sli_int_init(&s), SL_OK);
    s.bRun = 1;
    s.nPosition = -1000;
    CHECK_INT(sl_sli_int_cycle(&s, 0), SL_OK);
    CHECK_INT(s.nState, SL_STATE_SAFE);
    s.bSLI = 1;
    CHECK_INT(sl_sli_int_cycle(&s, 1), SL_OK);
    CHECK_INT(s.nState, SL_STATE_RUN);
    CHECK_INT(s.bSLIActive, 1);
    CHECK_INT(s.nPositionDiff, 0);
    s.nPosition = -1050;
    CHECK_INT(sl_sli_int_cycle(&s, 2), SL_OK);
    CHECK_INT(s.nPositionDiff, -50);
    s.nPosition = -900;
    CHECK_INT(sl_sli_int_cycle(&s, 3), SL_OK);
    CHECK_INT(s.nPositionDiff, 100);
    s.nPosition = -899;
    CHECK_INT(sl_sli_int_cycle(&s, 4), SL_OK);
    CHECK_INT(s.nState, SL_STATE_ERROR);
    CHECK_INT(s.bError, 1);
    CHECK_INT(s.bSLIActive, 0);
    CHECK_INT(s.nPositionDiff, 0);
    CHECK_INT(s.nDiag, SL_DIAG_VALUE_OVERFLOW);
    CHECK_INT(s.nDiagTextId, SL_TEXT_SLI_OVERFLOW);
    CHECK_INT(s.dwDiagPar2, (uint32_t)-899);
    CHECK_INT(s.dwDiagPar3, (uint32_t)-1000);
    s.bErrAck = 1; /* an event: acknowledged at once */
    sl_sli_int_cycle(&s, 5);
    CHECK_INT(s.nState, SL_STATE_RESET);
    CHECK_INT(s.nDiagTextId, 0);
    s.bErrAck = 0;
    sl_sli_int_cycle(&s, 6);
    CHECK_INT(s.nState, SL_STATE_RESET); /* SLI still TRUE */
    s.bSLI = 0;
    sl_sli_int_cycle(&s, 7);
    CHECK_INT(s.nState, SL_STATE_SAFE);
    CHECK_STR(sl_state_str(SL_TYPE_SLI_INT, SL_STATE_SAFE), "SAFE");
    CHECK_STR(sl_state_str(SL_TYPE_SLI_INT, SL_STATE_SLI2_EXCEEDED), "?");
    CHECK_DIAG_TEXT(SL_TYPE_SLI_INT, 1, "Underflow (PositionDiff < -NegLimit)");
    CHECK_DIAG_TEXT(SL_TYPE_SLI_UDINT, 2, "Overflow (PositionDiff > PosLimit)");
    h_end();
}

static void sli2_uint_exceeded_and_wrap(void)
{
    FB_SLI2_UINT s;
    memset(&s, 0, sizeof s);
    h_begin("SLI2_UINT: EXCEEDED with BelowMin, left by SLI FALSE; OverflowAllowed (SI6, SI7)");
    s.wInputActive = SL_SLI_ACTIVE;
    s.nLimitPos = 10;
    s.nLimitNeg = 10;
    s.dwOptions = SL_OPT_SLI2_EXCEEDED_SUPPORT | SL_OPT_SLI2_OVERFLOW_ALLOWED;
    CHECK_INT(sl_sli2_uint_init(&s), SL_OK);
    s.bRun = 1;
    s.nPosition = 65530;
    s.bSLI = 1; /* rising with the start: an edge */
    CHECK_INT(sl_sli2_uint_cycle(&s, 0), SL_OK);
    CHECK_INT(s.nState, SL_STATE_RUN);
    s.nPosition = 3; /* the counter wrapped: 9 increments */
    CHECK_INT(sl_sli2_uint_cycle(&s, 1), SL_OK);
    CHECK_INT(s.nPositionDiff, 9);
    CHECK_INT(s.bSLIActive, 1);
    s.nPosition = 65519;
    CHECK_INT(sl_sli2_uint_cycle(&s, 2), SL_OK);
    CHECK_INT(s.nState, SL_STATE_SLI2_EXCEEDED);
    CHECK_INT(s.bError, 0);
    CHECK_INT(s.bSLIActive, 0);
    CHECK_INT(s.bBelowMin, 1);
    CHECK_INT(s.bAboveMax, 0);
    CHECK_INT(s.nPositionDiff, -11);
    CHECK_INT(s.nDiagTextId, 0);
    s.bSLI = 0;
    CHECK_INT(sl_sli2_uint_cycle(&s, 3), SL_OK);
    CHECK_INT(s.nState, SL_STATE_SAFE);
    CHECK_INT(s.bBelowMin, 0);
    CHECK_STR(sl_state_str(SL_TYPE_SLI2_UINT, SL_STATE_SLI2_EXCEEDED), "EXCEEDED");
    s.dwOptions = 1u << 10;
    CHECK_INT(sl_sli2_uint_init(&s), SL_E_CONFIG);
    h_end();
}

static void sli_standstill_window_in_a_group(void)
{
    SL_GROUP g;
    SL_MEMBER members[3];
    SL_LINK links[2];
    FB_ADD_DINT add;
    FB_SLI_DINT sli;
    FB_AND and_;
    memset(&g, 0, sizeof g);
    memset(&add, 0, sizeof add);
    memset(&sli, 0, sizeof sli);
    memset(&and_, 0, sizeof and_);
    h_begin("group: ADD_DINT -> SLI_DINT Position (analog link), SLIActive -> AND (Boolean)");
    add.wInputActive = 0x0300;
    sli.wInputActive = SL_SLI_ACTIVE;
    sli.nLimitPos = 5;
    sli.nLimitNeg = 5;
    and_.wInputActive = 0x3;
    CHECK_INT(sl_group_init(&g, members, 3, links, 2), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_ADD_DINT, &add, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_SLI_DINT, &sli, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_AND, &and_, NULL), SL_OK);
    CHECK_INT(sl_group_add_link(&g, members, links, 0, offsetof(FB_ADD_DINT, nAnalogOut), 1,
                                offsetof(FB_SLI_DINT, nPosition)), SL_OK);
    CHECK_INT(links[0].nKind, SL_LINK_ANALOG32);
    CHECK_INT(sl_group_add_link(&g, members, links, 1, offsetof(FB_SLI_DINT, bSLIActive), 2,
                                offsetof(FB_AND, bAndIn1)), SL_OK);
    add.nAnalogIn1 = 100000;
    add.nAnalogIn2 = 1;
    and_.bAndIn2 = 1;
    g.bRun = 1;
    CHECK_INT(sl_group_cycle(&g, members, links, 0), SL_OK);
    CHECK_INT(sli.nState, SL_STATE_SAFE);
    sli.bSLI = 1;
    CHECK_INT(sl_group_cycle(&g, members, links, 10), SL_OK);
    CHECK_INT(sli.bSLIActive, 1);
    CHECK_INT(and_.bAndOut, 1);
    add.nAnalogIn2 = 6; /* drifted by 5: still standing */
    CHECK_INT(sl_group_cycle(&g, members, links, 20), SL_OK);
    CHECK_INT(sli.nPositionDiff, 5);
    CHECK_INT(and_.bAndOut, 1);
    add.nAnalogIn2 = -5; /* 6 the other way */
    sl_group_cycle(&g, members, links, 30);
    CHECK_INT(sli.nState, SL_STATE_ERROR);
    CHECK_INT(sli.nDiagTextId, SL_TEXT_SLI_UNDERFLOW);
    CHECK_INT(sli.dwDiagPar2, 99995);
    CHECK_INT(sli.dwDiagPar3, 100001);
    CHECK_INT(and_.bAndOut, 0);
    h_end();
}

void run_sli_scenarios(void)
{
    sli_int_window_error_and_reset();
    sli2_uint_exceeded_and_wrap();
    sli_standstill_window_in_a_group();
}
