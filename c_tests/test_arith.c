/*
 * The blocks with analog signals through the C ABI. FB_ADD/SUB/MUL/DIV in their integer
 * variants (manual §4.16-§4.19, ABI-2 §11.2, §12; docs/semantics.md A1-A6, RG2): results,
 * range errors with diag value, Text ID and parameters, DIV rounding and division by 0,
 * acknowledgement, and an analog chain ADD -> MUL -> DIV linked in a group beside a Boolean
 * link. FB_LIMIT (manual §4.21, ABI-2 §11.4; semantics L1-L4): RUN / SAFE with BelowMin and
 * AboveMax, MinValue > MaxValue (ERROR 0x4090 from inputs, SL_E_CONFIG from parameters),
 * and an analog value gating a Boolean AND in a group. FB_COUNTER (manual §4.22, ABI-2
 * §11.5; semantics K1-K4): Reset level, edges, CounterOut/CounterZero, overflow 0x40B9.
 * FB_VIOLATIONCOUNTER (manual §4.33, ABI-2 §11.12; semantics V1-V4): weighted counting,
 * the limit, START. FB_COMPARE (manual §4.20, ABI-2 §11.3; semantics CP1-CP4): 2oo3
 * majority, DELAYOUT for the tolerance time, SAFE.
 */
#include "harness.h"

static void arith_add_int_overflow_and_ack(void)
{
    FB_ADD_INT a;
    memset(&a, 0, sizeof a);
    h_begin("ADD_INT: RUN, overflow -> ERROR 0x4081, ack once in range (A1, A5)");
    a.wInputActive = 0x0300;
    CHECK_INT(sl_add_int_init(&a), SL_OK);
    a.bRun = 1;
    a.nAnalogIn1 = 30000;
    a.nAnalogIn2 = 2767;
    CHECK_INT(sl_add_int_cycle(&a, 0), SL_OK);
    CHECK_INT(a.nState, SL_STATE_RUN);
    CHECK_INT(a.nAnalogOut, 32767);
    a.nAnalogIn2 = 2768;
    CHECK_INT(sl_add_int_cycle(&a, 1), SL_OK);
    CHECK_INT(a.nState, SL_STATE_ERROR);
    CHECK_INT(a.bError, 1);
    CHECK_INT(a.nAnalogOut, 0);
    CHECK_INT(a.nDiag, SL_DIAG_VALUE_OVERFLOW);
    CHECK_INT(a.nDiagTextId, 0x4081);
    CHECK_INT(a.dwDiagPar2, 30000);
    CHECK_INT(a.dwDiagPar3, 2768);
    a.bErrAck = 1;
    sl_add_int_cycle(&a, 2);
    CHECK_INT(a.nState, SL_STATE_ERROR); /* still out of range */
    a.bErrAck = 0;
    sl_add_int_cycle(&a, 3);
    a.nAnalogIn1 = -5;
    a.bErrAck = 1;
    sl_add_int_cycle(&a, 4);
    CHECK_INT(a.nState, SL_STATE_RESET);
    CHECK_INT(a.nDiagTextId, 0);
    a.bErrAck = 0;
    sl_add_int_cycle(&a, 5);
    CHECK_INT(a.nState, SL_STATE_RUN);
    CHECK_INT(a.nAnalogOut, 2763);
    CHECK_DIAG_TEXT(SL_TYPE_ADD_INT, 2,
                    "The output AnalogOut has an overflow (is greater than the largest possible value)");
    h_end();
}

static void arith_sub_uint_underflow(void)
{
    FB_SUB_UDINT s;
    memset(&s, 0, sizeof s);
    h_begin("SUB_UDINT: a negative difference is an underflow, 0x4080 (A4)");
    s.wInputActive = 0x0300;
    CHECK_INT(sl_sub_udint_init(&s), SL_OK);
    s.bRun = 1;
    s.nAnalogIn1 = 4000000000u;
    s.nAnalogIn2 = 1u;
    sl_sub_udint_cycle(&s, 0);
    CHECK_INT(s.nAnalogOut, 3999999999u);
    s.nAnalogIn1 = 0u;
    sl_sub_udint_cycle(&s, 1);
    CHECK_INT(s.nState, SL_STATE_ERROR);
    CHECK_INT(s.nDiag, SL_DIAG_VALUE_UNDERFLOW);
    CHECK_INT(s.nDiagTextId, 0x4080);
    h_end();
}

static int16_t arith_div(int16_t a, int16_t b, uint16_t rounding)
{
    FB_DIV_INT d;
    memset(&d, 0, sizeof d);
    d.wInputActive = 0x0300;
    d.nRounding = rounding;
    d.nAnalogIn1 = a;
    d.nAnalogIn2 = b;
    d.bRun = 1;
    sl_div_int_init(&d);
    sl_div_int_cycle(&d, 0);
    return d.nAnalogOut;
}

static void arith_div_rounding(void)
{
    FB_DIV_DINT d;
    h_begin("DIV: Floor/Ceil/Round incl. negative quotients, /0 = 0, MIN / -1 (A2, A3)");
    CHECK_INT(arith_div(5, 2, SL_ROUNDING_FLOOR), 2);
    CHECK_INT(arith_div(5, 2, SL_ROUNDING_CEIL), 3);
    CHECK_INT(arith_div(5, 2, SL_ROUNDING_ROUND), 3);
    CHECK_INT(arith_div(-5, 2, SL_ROUNDING_FLOOR), -3);
    CHECK_INT(arith_div(-5, 2, SL_ROUNDING_CEIL), -2);
    CHECK_INT(arith_div(-5, 2, SL_ROUNDING_ROUND), -3);
    CHECK_INT(arith_div(-7, 3, SL_ROUNDING_ROUND), -2);
    CHECK_INT(arith_div(99, 0, SL_ROUNDING_ROUND), 0);
    memset(&d, 0, sizeof d);
    d.wInputActive = 0x0300;
    d.nRounding = 3;
    CHECK_INT(sl_div_dint_init(&d), SL_E_CONFIG);
    d.nRounding = 0;
    CHECK_INT(sl_div_dint_init(&d), SL_OK);
    d.bRun = 1;
    d.nAnalogIn1 = INT32_MIN;
    d.nAnalogIn2 = -1;
    sl_div_dint_cycle(&d, 0);
    CHECK_INT(d.nState, SL_STATE_ERROR);
    CHECK_INT(d.nDiag, SL_DIAG_VALUE_OVERFLOW);
    CHECK_INT(d.dwDiagPar2, 0x80000000u);
    h_end();
}

static void arith_chain_in_a_group(void)
{
    SL_GROUP g;
    SL_MEMBER members[4];
    SL_LINK links[3];
    FB_ADD_INT add;
    FB_MUL_INT mul;
    FB_DIV_INT div;
    FB_ADD_UINT uadd;
    memset(&g, 0, sizeof g);
    memset(&add, 0, sizeof add);
    memset(&mul, 0, sizeof mul);
    memset(&div, 0, sizeof div);
    memset(&uadd, 0, sizeof uadd);
    h_begin("group: analog links ADD -> MUL -> DIV; INT -> UINT refused (RG2)");
    add.wInputActive = mul.wInputActive = div.wInputActive = uadd.wInputActive = 0x0300;
    CHECK_INT(sl_group_init(&g, members, 4, links, 3), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_ADD_INT, &add, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_MUL_INT, &mul, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_DIV_INT, &div, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_ADD_UINT, &uadd, NULL), SL_OK);
    CHECK_INT(sl_group_add_link(&g, members, links, 0, offsetof(FB_ADD_INT, nAnalogOut), 1,
                                offsetof(FB_MUL_INT, nAnalogIn1)), SL_OK);
    CHECK_INT(sl_group_add_link(&g, members, links, 1, offsetof(FB_MUL_INT, nAnalogOut), 2,
                                offsetof(FB_DIV_INT, nAnalogIn1)), SL_OK);
    CHECK_INT(links[0].nKind, SL_LINK_ANALOG16);
    CHECK_INT(sl_group_add_link(&g, members, links, 0, offsetof(FB_ADD_INT, nAnalogOut), 3,
                                offsetof(FB_ADD_UINT, nAnalogIn1)), SL_E_CONFIG);
    add.nAnalogIn1 = 7;
    add.nAnalogIn2 = 3;
    mul.nAnalogIn2 = -4;
    div.nAnalogIn2 = 3;
    uadd.nAnalogIn1 = 1;
    g.bRun = 1;
    CHECK_INT(sl_group_cycle(&g, members, links, 0), SL_OK);
    CHECK_INT(mul.nAnalogOut, -40);
    CHECK_INT(div.nAnalogOut, -14); /* -13.33, Floor */
    CHECK_INT(g.nState, SL_STATE_RUN);
    h_end();
}

static void limit_int_window_and_error(void)
{
    FB_LIMIT_INT l;
    FB_LIMIT_UDINT u;
    memset(&l, 0, sizeof l);
    memset(&u, 0, sizeof u);
    h_begin("LIMIT_INT: RUN/SAFE, MinValue > MaxValue -> ERROR 0x4090 (L1-L3)");
    l.wInputActive = SL_LIMIT_ACTIVE_ANALOGIN | SL_LIMIT_ACTIVE_MINVALUE;
    l.nMaximumValue = 100; /* parameter */
    CHECK_INT(sl_limit_int_init(&l), SL_OK);
    l.bRun = 1;
    l.nMinValue = -20; /* input */
    l.nAnalogIn = 100;
    CHECK_INT(sl_limit_int_cycle(&l, 0), SL_OK);
    CHECK_INT(l.nState, SL_STATE_RUN);
    CHECK_INT(l.bInLimit, 1);
    l.nAnalogIn = -21;
    CHECK_INT(sl_limit_int_cycle(&l, 1), SL_OK);
    CHECK_INT(l.nState, SL_STATE_SAFE);
    CHECK_INT(l.bInLimit + 2 * l.bBelowMin + 4 * l.bAboveMax, 2);
    l.nMinValue = 101;
    CHECK_INT(sl_limit_int_cycle(&l, 2), SL_OK);
    CHECK_INT(l.nState, SL_STATE_ERROR);
    CHECK_INT(l.bError, 1);
    CHECK_INT(l.nDiag, SL_DIAG_LIMIT_MIN_ABOVE_MAX);
    CHECK_INT(l.nDiagTextId, SL_TEXT_LIMIT_MIN_ABOVE_MAX);
    CHECK_INT(l.dwDiagPar2, 101);
    CHECK_INT(l.dwDiagPar3, 100);
    l.bErrAck = 1;
    sl_limit_int_cycle(&l, 3);
    CHECK_INT(l.nState, SL_STATE_ERROR); /* the limits still cross */
    l.bErrAck = 0;
    l.nMinValue = -1;
    sl_limit_int_cycle(&l, 4);
    l.bErrAck = 1;
    sl_limit_int_cycle(&l, 5);
    CHECK_INT(l.nState, SL_STATE_RESET);
    CHECK_INT(l.nDiagTextId, 0);
    l.bErrAck = 0;
    l.nAnalogIn = -1;
    sl_limit_int_cycle(&l, 6);
    CHECK_INT(l.nState, SL_STATE_RUN);
    CHECK_DIAG_TEXT(SL_TYPE_LIMIT_INT, 1, "MinValue is greater than MaxValue");
    /* both limits from the parameters, crossed: a configuration error */
    u.wInputActive = SL_LIMIT_ACTIVE_ANALOGIN;
    u.nMinimumValue = 4000000000u;
    u.nMaximumValue = 3999999999u;
    CHECK_INT(sl_limit_udint_init(&u), SL_E_CONFIG);
    u.bRun = 1;
    CHECK_INT(sl_limit_udint_cycle(&u, 0), SL_E_CONFIG);
    CHECK_INT(u.nState, SL_STATE_STOP);
    CHECK_INT(u.bInLimit, 0);
    h_end();
}

static void limit_gates_an_and_in_a_group(void)
{
    SL_GROUP g;
    SL_MEMBER members[3];
    SL_LINK links[2];
    FB_ADD_DINT add;
    FB_LIMIT_DINT lim;
    FB_AND and_;
    memset(&g, 0, sizeof g);
    memset(&add, 0, sizeof add);
    memset(&lim, 0, sizeof lim);
    memset(&and_, 0, sizeof and_);
    h_begin("group: ADD_DINT -> LIMIT_DINT (analog link), InLimit -> AND (Boolean link)");
    add.wInputActive = 0x0300;
    lim.wInputActive = SL_LIMIT_ACTIVE_ANALOGIN;
    lim.nMinimumValue = 0;
    lim.nMaximumValue = 1000;
    and_.wInputActive = 0x3;
    CHECK_INT(sl_group_init(&g, members, 3, links, 2), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_ADD_DINT, &add, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_LIMIT_DINT, &lim, NULL), SL_OK);
    CHECK_INT(sl_group_add_member(&g, members, SL_TYPE_AND, &and_, NULL), SL_OK);
    CHECK_INT(sl_group_add_link(&g, members, links, 0, offsetof(FB_ADD_DINT, nAnalogOut), 1,
                                offsetof(FB_LIMIT_DINT, nAnalogIn)), SL_OK);
    CHECK_INT(links[0].nKind, SL_LINK_ANALOG32);
    CHECK_INT(sl_group_add_link(&g, members, links, 1, offsetof(FB_LIMIT_DINT, bInLimit), 2,
                                offsetof(FB_AND, bAndIn1)), SL_OK);
    CHECK_INT(links[1].nKind, SL_LINK_BOOL);
    add.nAnalogIn1 = 600;
    add.nAnalogIn2 = 400;
    and_.bAndIn2 = 1;
    g.bRun = 1;
    CHECK_INT(sl_group_cycle(&g, members, links, 0), SL_OK);
    CHECK_INT(lim.nAnalogIn, 1000);
    CHECK_INT(lim.bInLimit, 1);
    CHECK_INT(and_.bAndOut, 1);
    add.nAnalogIn2 = 401; /* 1001: above the maximum, in the same cycle */
    CHECK_INT(sl_group_cycle(&g, members, links, 10), SL_OK);
    CHECK_INT(lim.bAboveMax, 1);
    CHECK_INT(and_.bAndOut, 0);
    CHECK_INT(g.nState, SL_STATE_RUN);
    h_end();
}

static void counter_uint_counts_and_overflows(void)
{
    FB_COUNTER_UINT c;
    memset(&c, 0, sizeof c);
    h_begin("COUNTER_UINT: Reset level, edges, CounterOut/Zero, overflow 0x40B9 (K1-K3)");
    c.wInputActive = SL_COUNTER_ACTIVE_INPUTS;
    c.nPresetValue = 65534;
    c.nCounterLimit = 65535;
    CHECK_INT(sl_counter_uint_init(&c), SL_OK);
    c.bRun = 1;
    CHECK_INT(sl_counter_uint_cycle(&c, 0), SL_OK);
    CHECK_INT(c.nState, SL_STATE_RUN);
    CHECK_INT(c.nActValue, 0);
    CHECK_INT(c.bCounterZero, 1);
    c.bReset = 1;
    sl_counter_uint_cycle(&c, 1);
    CHECK_INT(c.nActValue, 65534);
    c.bReset = 0;
    c.bCountUp = 1;
    sl_counter_uint_cycle(&c, 2);
    CHECK_INT(c.nActValue, 65535);
    CHECK_INT(c.bCounterOut, 1);
    sl_counter_uint_cycle(&c, 3); /* held: no edge */
    CHECK_INT(c.nActValue, 65535);
    c.bCountUp = 0;
    sl_counter_uint_cycle(&c, 4);
    c.bCountUp = 1;
    CHECK_INT(sl_counter_uint_cycle(&c, 5), SL_OK);
    CHECK_INT(c.nState, SL_STATE_ERROR);
    CHECK_INT(c.bError, 1);
    CHECK_INT(c.nActValue, 0);
    CHECK_INT(c.bCounterOut, 0);
    CHECK_INT(c.nDiag, SL_DIAG_VALUE_OVERFLOW);
    CHECK_INT(c.nDiagTextId, SL_TEXT_COUNTER_OVERFLOW);
    CHECK_INT(c.dwDiagPar2, 65535);
    CHECK_INT(c.dwDiagPar3, 65535);
    c.bErrAck = 1;
    sl_counter_uint_cycle(&c, 6);
    CHECK_INT(c.nState, SL_STATE_RESET);
    c.bErrAck = 0;
    sl_counter_uint_cycle(&c, 7);
    CHECK_INT(c.nState, SL_STATE_RUN);
    CHECK_INT(c.nActValue, 0);
    CHECK_DIAG_TEXT(SL_TYPE_COUNTER_UINT, 2,
                    "The output ActValue has an overflow (is greater than the largest possible value)");
    h_end();
}

static void violationcounter_udint_limit(void)
{
    FB_VIOLATIONCOUNTER_UDINT v;
    memset(&v, 0, sizeof v);
    h_begin("VIOLATIONCOUNTER_UDINT: +3 per violation, -1 per good call, limit 7, START (V1, V2)");
    v.wInputActive = SL_VIOLATIONCOUNTER_ACTIVE;
    v.nIncrementError = 3;
    v.nDecrementNoError = 1;
    v.nCounterLimit = 7;
    CHECK_INT(sl_violationcounter_udint_init(&v), SL_OK);
    v.bRun = 1;
    v.bEnable = 1;
    v.bInput = 0;
    CHECK_INT(sl_violationcounter_udint_cycle(&v, 0), SL_OK);
    CHECK_INT(v.nActViolationCnt, 3);
    CHECK_INT(v.bInputOK, 1);
    CHECK_INT(v.nState, SL_STATE_RUN);
    sl_violationcounter_udint_cycle(&v, 1);
    sl_violationcounter_udint_cycle(&v, 2);
    CHECK_INT(v.nActViolationCnt, 9);
    CHECK_INT(v.bInputOK, 0);
    CHECK_INT(v.nState, SL_STATE_SAFE);
    v.bInput = 1;
    sl_violationcounter_udint_cycle(&v, 3);
    sl_violationcounter_udint_cycle(&v, 4);
    CHECK_INT(v.nActViolationCnt, 7);
    CHECK_INT(v.bInputOK, 0); /* reaching the limit is not OK */
    sl_violationcounter_udint_cycle(&v, 5);
    CHECK_INT(v.bInputOK, 1);
    v.bEnable = 0;
    sl_violationcounter_udint_cycle(&v, 6);
    CHECK_INT(v.nState, SL_STATE_START);
    CHECK_INT(v.nActViolationCnt, 0);
    CHECK_INT(v.bInputOK, 0);
    CHECK_INT(v.nDiagTextId, 0);
    h_end();
}

static void compare_dint_two_out_of_three(void)
{
    FB_COMPARE_DINT c;
    memset(&c, 0, sizeof c);
    h_begin("COMPARE_DINT 2oo3: majority, DELAYOUT for the tolerance time, SAFE (CP1, CP2)");
    c.nArchitecture = SL_ARCH_2OO3;
    c.wInputActive = 0x0700;
    c.nAllowedDeviation = 10;
    c.tToleranceTime = 100;
    CHECK_INT(sl_compare_dint_init(&c), SL_OK);
    c.bRun = 1;
    c.nCompIn1 = -70000;
    c.nCompIn2 = 1000;
    c.nCompIn3 = 1010;
    CHECK_INT(sl_compare_dint_cycle(&c, 0), SL_OK);
    CHECK_INT(c.nState, SL_STATE_RUN);
    CHECK_INT(c.bIsValid, 1);
    CHECK_INT(c.nCompOut, 1000);
    c.nCompIn3 = 1011;
    CHECK_INT(sl_compare_dint_cycle(&c, 10), SL_OK);
    CHECK_INT(c.nState, SL_STATE_DELAYOUT);
    CHECK_INT(c.bIsValid, 1);
    CHECK_INT(c.nCompOut, 1000);
    CHECK_INT(sl_compare_dint_cycle(&c, 110), SL_OK);
    CHECK_INT(c.nState, SL_STATE_SAFE);
    CHECK_INT(c.bIsValid, 0);
    CHECK_INT(c.nCompOut, 0);
    c.nCompIn1 = 1011;
    CHECK_INT(sl_compare_dint_cycle(&c, 120), SL_OK);
    CHECK_INT(c.nState, SL_STATE_RUN);
    CHECK_INT(c.nCompOut, 1011);
    CHECK_INT(c.bError, 0);
    h_end();
}

void run_arith_scenarios(void)
{
    compare_dint_two_out_of_three();
    violationcounter_udint_limit();
    counter_uint_counts_and_overflows();
    limit_int_window_and_error();
    limit_gates_an_and_in_a_group();
    arith_add_int_overflow_and_ack();
    arith_sub_uint_underflow();
    arith_div_rounding();
    arith_chain_in_a_group();
}
