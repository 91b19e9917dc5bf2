/*
 * FB_SCALE (manual §4.23, ABI-2 §11.6; docs/semantics.md SC1-SC5) and FB_SPEED (manual
 * §4.24, ABI-2 §11.7; semantics SP1-SP4) through the C ABI: a sensor value scaled with
 * rounding and offset, the 32-bit multiplication overflow 0x40B2 and its acknowledgement,
 * the StuckAt watchdog; an encoder's speed per interval across the wrap of tNow, the
 * overflow check on a wrapping counter, the underflow 0x4088; and an encoder chain
 * SPEED -> SCALE -> LIMIT linked in a group.
 */
#include "harness.h"

static void scale_int_rounding_overflow_and_ack(void)
{
    FB_SCALE_INT s;
    memset(&s, 0, sizeof s);
    h_begin("SCALE_INT: x*3/4+5 rounded, overflow 0x40B2 -> ERROR, ack once in range (SC1, SC5)");
    s.wInputActive = SL_SCALE_ACTIVE_ANALOGIN;
    s.nNumerator = 3;
    s.nDenominator = 4;
    s.nOffset = 5;
    s.nRounding = SL_ROUNDING_ROUND;
    CHECK_INT(sl_scale_int_init(&s), SL_OK);
    s.bRun = 1;
    s.nAnalogIn = 10; /* 30 / 4 = 7.5 -> 8, + 5 */
    CHECK_INT(sl_scale_int_cycle(&s, 0), SL_OK);
    CHECK_INT(s.nState, SL_STATE_RUN);
    CHECK_INT(s.nAnalogOut, 13);
    s.nAnalogIn = -10; /* -7.5 -> -8 (half away from zero), + 5 */
    CHECK_INT(sl_scale_int_cycle(&s, 1), SL_OK);
    CHECK_INT(s.nAnalogOut, -3);
    s.nAnalogIn = 32767; /* 98301 / 4 = 24575.25 -> 24575, + 5 */
    CHECK_INT(sl_scale_int_cycle(&s, 2), SL_OK);
    CHECK_INT(s.nAnalogOut, 24580);

    /* A numerator that overflows the 32-bit product: a parameter, so STOP -> run latches. */
    s.bRun = 0;
    sl_scale_int_cycle(&s, 3);
    s.nNumerator = 100000;
    s.nDenominator = 100000;
    s.nOffset = 0;
    s.bRun = 1;
    s.nAnalogIn = 21475; /* 2 147 500 000 > INT32 max */
    CHECK_INT(sl_scale_int_cycle(&s, 4), SL_OK);
    CHECK_INT(s.nState, SL_STATE_ERROR);
    CHECK_INT(s.bError, 1);
    CHECK_INT(s.nAnalogOut, 0);
    CHECK_INT(s.nDiag, SL_DIAG_SCALE_MUL_OVERFLOW);
    CHECK_INT(s.nDiagTextId, 0x40B2);
    CHECK_INT(s.dwDiagPar2, 21475);
    CHECK_INT(s.dwDiagPar3, 0);
    CHECK_DIAG_TEXT(SL_TYPE_SCALE_INT, 3, "A 32-bit overflow occurred during the multiplication.");
    s.bErrAck = 1;
    sl_scale_int_cycle(&s, 5);
    CHECK_INT(s.nState, SL_STATE_ERROR); /* the input still overflows */
    s.bErrAck = 0;
    s.nAnalogIn = 21474;
    sl_scale_int_cycle(&s, 6);
    s.bErrAck = 1;
    sl_scale_int_cycle(&s, 7);
    CHECK_INT(s.nState, SL_STATE_RESET);
    CHECK_INT(s.nDiagTextId, 0);
    s.bErrAck = 0;
    sl_scale_int_cycle(&s, 8);
    CHECK_INT(s.nState, SL_STATE_RUN);
    CHECK_INT(s.nAnalogOut, 21474);

    /* Denominator 0 is refused when the parameters are latched. */
    s.nDenominator = 0;
    CHECK_INT(sl_scale_int_init(&s), SL_E_CONFIG);
    h_end();
}

static void scale_udint_negation_and_stuck_at(void)
{
    FB_SCALE_UDINT s;
    memset(&s, 0, sizeof s);
    h_begin("SCALE_UDINT: negation = XOR, StuckAtError after the watchdog, not an error (SC3)");
    s.wInputActive = SL_SCALE_ACTIVE_ANALOGIN;
    s.wInputNegated = SL_SCALE_NEGATE_ANALOGIN;
    s.nNumerator = 1;
    s.nDenominator = 1;
    s.tWatchdog = 500;
    CHECK_INT(sl_scale_udint_init(&s), SL_OK);
    s.bRun = 1;
    s.nAnalogIn = 5u;
    CHECK_INT(sl_scale_udint_cycle(&s, 0xFFFFFF00u), SL_OK);
    CHECK_INT(s.nAnalogOut, 0xFFFFFFFAu);
    CHECK_INT(sl_scale_udint_cycle(&s, 0xFFFFFF00u + 499u), SL_OK);
    CHECK_INT(s.bStuckAtError, 0);
    CHECK_INT(sl_scale_udint_cycle(&s, 0xFFFFFF00u + 500u), SL_OK); /* across the wrap */
    CHECK_INT(s.bStuckAtError, 1);
    CHECK_INT(s.nState, SL_STATE_RUN);
    CHECK_INT(s.bError, 0);
    s.nAnalogIn = 6u;
    CHECK_INT(sl_scale_udint_cycle(&s, 0xFFFFFF00u + 501u), SL_OK);
    CHECK_INT(s.bStuckAtError, 0);
    CHECK_INT(s.nAnalogOut, 0xFFFFFFF9u);
    h_end();
}

static void speed_dint_interval_and_wrap(void)
{
    FB_SPEED_DINT v;
    FB_SPEED_UINT u;
    memset(&v, 0, sizeof v);
    memset(&u, 0, sizeof u);
    h_begin("SPEED_DINT: speed per interval across the tNow wrap; UINT overflow check (SP1, SP2)");
    v.wInputActive = SL_SPEED_ACTIVE_POSITION;
    v.tTimeInterval = 100;
    CHECK_INT(sl_speed_dint_init(&v), SL_OK);
    v.bRun = 1;
    v.nPosition = 1000;
    CHECK_INT(sl_speed_dint_cycle(&v, 0xFFFFFFF0u), SL_OK);
    CHECK_INT(v.nState, SL_STATE_RUN);
    CHECK_INT(v.nSpeed, 0);
    v.nPosition = 1250;
    CHECK_INT(sl_speed_dint_cycle(&v, 0xFFFFFFF0u + 99u), SL_OK);
    CHECK_INT(v.nSpeed, 0);
    CHECK_INT(sl_speed_dint_cycle(&v, 0xFFFFFFF0u + 100u), SL_OK);
    CHECK_INT(v.nSpeed, 250);
    v.nPosition = 1200;
    CHECK_INT(sl_speed_dint_cycle(&v, 0xFFFFFFF0u + 200u), SL_OK);
    CHECK_INT(v.nSpeed, -50);

    u.wInputActive = SL_SPEED_ACTIVE_POSITION;
    u.tTimeInterval = 10;
    u.dwOptions = SL_OPT_SPEED_OVERFLOW_CHECK;
    CHECK_INT(sl_speed_uint_init(&u), SL_OK);
    u.bRun = 1;
    u.nPosition = 65530;
    sl_speed_uint_cycle(&u, 0);
    u.nPosition = 4; /* the counter wrapped: 10 increments forwards */
    CHECK_INT(sl_speed_uint_cycle(&u, 10), SL_OK);
    CHECK_INT(u.nSpeed, 10);
    u.nPosition = 2; /* backwards: below the smallest UINT speed */
    CHECK_INT(sl_speed_uint_cycle(&u, 20), SL_OK);
    CHECK_INT(u.nState, SL_STATE_ERROR);
    CHECK_INT(u.nDiag, SL_DIAG_VALUE_UNDERFLOW);
    CHECK_INT(u.nDiagTextId, 0x4088);
    CHECK_INT(u.dwDiagPar2, 2);
    CHECK_INT(u.dwDiagPar3, 4);
    CHECK_INT(u.nSpeed, 0);
    u.bErrAck = 1; /* an event: nothing remains */
    sl_speed_uint_cycle(&u, 21);
    CHECK_INT(u.nState, SL_STATE_RESET);
    u.bErrAck = 0;
    sl_speed_uint_cycle(&u, 22);
    CHECK_INT(u.nState, SL_STATE_RUN);
    CHECK_INT(u.nSpeed, 0);

    u.tTimeInterval = 0;
    CHECK_INT(sl_speed_uint_init(&u), SL_E_CONFIG);
    h_end();
}

static void speed_scale_limit_in_a_group(void)
{
    SL_GROUP g;
    SL_MEMBER members[3];
    SL_LINK links[2];
    FB_SPEED_DINT v;
    FB_SCALE_DINT s;
    FB_LIMIT_DINT l;
    memset(&g, 0, sizeof g);
    memset(&v, 0, sizeof v);
    memset(&s, 0, sizeof s);
    memset(&l, 0, sizeof l);
    h_begin("group: SPEED_DINT -> SCALE_DINT (increments -> mm/s) -> LIMIT_DINT");
    v.wInputActive = SL_SPEED_ACTIVE_POSITION;
    v.tTimeInterval = 10;
    s.wInputActive = SL_SCALE_ACTIVE_ANALOGIN;
    s.nNumerator = 100; /* 1 increment per 10 ms = 100 increments/s */
    s.nDenominator = 4; /* 4 increments per mm */
    l.wInputActive = SL_LIMIT_ACTIVE_ANALOGIN;
    l.nMinimumValue = -500;
    l.nMaximumValue = 500;
    CHECK_INT(sl_group_init(&g, members, 3, links, 2), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_SPEED_DINT, &v, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_SCALE_DINT, &s, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_LIMIT_DINT, &l, NULL), SL_OK);
    CHECK_INT(sl_group_add_link(&g, members, links, 0, offsetof(FB_SPEED_DINT, nSpeed), 1,
                                offsetof(FB_SCALE_DINT, nAnalogIn)), SL_OK);
    CHECK_INT(sl_group_add_link(&g, members, links, 1, offsetof(FB_SCALE_DINT, nAnalogOut), 2,
                                offsetof(FB_LIMIT_DINT, nAnalogIn)), SL_OK);
    CHECK_INT(links[0].nKind, SL_LINK_ANALOG32);
    g.bRun = 1;
    v.nPosition = 0;
    CHECK_INT(sl_group_cycle(&g, members, links, 0), SL_OK);
    v.nPosition = 12; /* 12 increments in 10 ms = 300 mm/s */
    CHECK_INT(sl_group_cycle(&g, members, links, 10), SL_OK);
    CHECK_INT(v.nSpeed, 12);
    CHECK_INT(s.nAnalogOut, 300);
    CHECK_INT(l.bInLimit, 1);
    v.nPosition = 33; /* 21 increments = 525 mm/s */
    CHECK_INT(sl_group_cycle(&g, members, links, 20), SL_OK);
    CHECK_INT(s.nAnalogOut, 525);
    CHECK_INT(l.nState, SL_STATE_SAFE);
    CHECK_INT(l.bAboveMax, 1);
    CHECK_INT(g.nState, SL_STATE_RUN);
    h_end();
}

void run_scale_speed_scenarios(void)
{
    scale_int_rounding_overflow_and_ack();
    scale_udint_negation_and_stuck_at();
    speed_dint_interval_and_wrap();
    speed_scale_limit_in_a_group();
}
