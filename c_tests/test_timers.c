/*
 * FB_TON (manual §4.12), FB_TON2 (§4.13) and FB_TOF (§4.14) behaviour scenarios through the
 * C ABI (ABI.md §2, §4, §5, §7, §9; docs/semantics.md rows T1-T17, C1-C12), including the
 * TON2 elapsed-time persistence across a simulated power cycle (sl_ton2_get_elapsed /
 * sl_ton2_restore_elapsed).
 *
 * Every step calls sl_<name>_cycle once and checks the status code, nState, nDiag and the
 * one output: bit 0 of the expected set (TMR_OUT) = bTonOut / bTofOut.
 */
#include "harness.h"

/* ---- helpers (prefixed ton_ / ton2_ / tof_) ---- */

#define TMR_OUT 1u

static void ton_step(FB_TON *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                     uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_ton_cycle(fb, t);
    h_check_fb(file, line, "TON", SL_TYPE_TON, t, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bTonOut, 0), xrc, xst, xdiag, xouts);
}

static void ton2_step(FB_TON2 *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                      uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_ton2_cycle(fb, t);
    h_check_fb(file, line, "TON2", SL_TYPE_TON2, t, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bTonOut, 0), xrc, xst, xdiag, xouts);
}

static void tof_step(FB_TOF *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                     uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_tof_cycle(fb, t);
    h_check_fb(file, line, "TOF", SL_TYPE_TOF, t, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bTofOut, 0), xrc, xst, xdiag, xouts);
}

/* TON_S / TON2_S / TOF_S(t, rc, state, diag, outputs): one cycle at time t. */
#define TON_S(t_, rc_, st_, diag_, outs_) \
    ton_step(ton, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define TON_RUN(t_) TON_S((t_), SL_OK, SL_STATE_RUN, 0, TMR_OUT)
#define TON_SAFE(t_) TON_S((t_), SL_OK, SL_STATE_SAFE, 0, 0)
#define TON_STOP(t_) TON_S((t_), SL_OK, SL_STATE_STOP, 0, 0)
#define TON_DELAYIN(t_) TON_S((t_), SL_OK, SL_STATE_TON_DELAYIN, 0, 0)
#define TON2_S(t_, rc_, st_, diag_, outs_) \
    ton2_step(ton2, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define TON2_RUN(t_) TON2_S((t_), SL_OK, SL_STATE_RUN, 0, TMR_OUT)
#define TON2_SAFE(t_) TON2_S((t_), SL_OK, SL_STATE_SAFE, 0, 0)
#define TON2_STOP(t_) TON2_S((t_), SL_OK, SL_STATE_STOP, 0, 0)
#define TON2_DELAYIN(t_) TON2_S((t_), SL_OK, SL_STATE_TON2_DELAYIN, 0, 0)
#define TOF_S(t_, rc_, st_, diag_, outs_) \
    tof_step(tof, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define TOF_RUN(t_) TOF_S((t_), SL_OK, SL_STATE_RUN, 0, TMR_OUT)
#define TOF_SAFE(t_) TOF_S((t_), SL_OK, SL_STATE_SAFE, 0, 0)
#define TOF_STOP(t_) TOF_S((t_), SL_OK, SL_STATE_STOP, 0, 0)
#define TOF_DELAYOUT(t_) TOF_S((t_), SL_OK, SL_STATE_DELAYOUT, 0, TMR_OUT)

static void ton_setup(FB_TON *fb, uint32_t delay, uint16_t timebase)
{
    memset(fb, 0, sizeof *fb);
    fb->tDelay = delay;
    fb->nTimeBase = timebase;
    fb->wInputActive = 0x01;
}

static void ton2_setup(FB_TON2 *fb, uint32_t delay, uint32_t options)
{
    memset(fb, 0, sizeof *fb);
    fb->tDelay = delay;
    fb->dwOptions = options;
    fb->wInputActive = 0x01;
}

static void tof_setup(FB_TOF *fb, uint32_t delay, uint16_t timebase)
{
    memset(fb, 0, sizeof *fb);
    fb->tDelay = delay;
    fb->nTimeBase = timebase;
    fb->wInputActive = 0x01;
}

/* init: status, power-up image (C1), VAR_INPUT bytes before the output base untouched. */
static void ton_init_check(FB_TON *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[32];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_ton_init(fb);
    h_check_int(rc, xrc, file, line, "sl_ton_init");
    h_check_fb(file, line, "TON(init)", SL_TYPE_TON, 0, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bTonOut, 0), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_ton_init modified a VAR_INPUT byte (ABI §4)");
}
#define TON_INIT(rc_) ton_init_check(ton, (rc_), __FILE__, __LINE__)

static void ton2_init_check(FB_TON2 *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[40];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_ton2_init(fb);
    h_check_int(rc, xrc, file, line, "sl_ton2_init");
    h_check_fb(file, line, "TON2(init)", SL_TYPE_TON2, 0, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bTonOut, 0), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_ton2_init modified a VAR_INPUT byte (ABI §4)");
}
#define TON2_INIT(rc_) ton2_init_check(ton2, (rc_), __FILE__, __LINE__)

static void tof_init_check(FB_TOF *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[32];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_tof_init(fb);
    h_check_int(rc, xrc, file, line, "sl_tof_init");
    h_check_fb(file, line, "TOF(init)", SL_TYPE_TOF, 0, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bTofOut, 0), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_tof_init modified a VAR_INPUT byte (ABI §4)");
}
#define TOF_INIT(rc_) tof_init_check(tof, (rc_), __FILE__, __LINE__)

/* sl_ton2_get_elapsed returns SL_OK and `expected`. */
static void ton2_elapsed_is(const FB_TON2 *fb, uint32_t expected, const char *file, int line)
{
    uint32_t v = 0xDEADBEEFu;
    int32_t rc = sl_ton2_get_elapsed(fb, &v);
    h_check_int(rc, SL_OK, file, line, "sl_ton2_get_elapsed status");
    h_check_int(v, expected, file, line, "sl_ton2_get_elapsed value");
}
#define TON2_ELAPSED(x_) ton2_elapsed_is(ton2, (x_), __FILE__, __LINE__)

/* sl_ton2_restore_elapsed: status, then nState, nDiag and the output. */
static void ton2_restore(FB_TON2 *fb, uint32_t ms, int32_t xrc, uint8_t xst, uint16_t xdiag,
                         const char *file, int line)
{
    int32_t rc = sl_ton2_restore_elapsed(fb, ms);
    h_check_fb(file, line, "TON2(restore)", SL_TYPE_TON2, 0, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bTonOut, 0), xrc, xst, xdiag, 0);
}
#define TON2_RESTORE(ms_, rc_, st_, diag_) \
    ton2_restore(ton2, (ms_), (rc_), (st_), (diag_), __FILE__, __LINE__)

/* Config check of one (tDelay, nTimeBase) pair for TON and TOF. */
static void tmr_config(uint32_t delay, uint16_t timebase, int32_t xrc, const char *file,
                       int line)
{
    FB_TON a;
    FB_TOF b;
    ton_setup(&a, delay, timebase);
    tof_setup(&b, delay, timebase);
    h_check_int(sl_ton_init(&a), xrc, file, line, "sl_ton_init (tDelay, nTimeBase)");
    h_check_int(sl_tof_init(&b), xrc, file, line, "sl_tof_init (tDelay, nTimeBase)");
    h_check(a.nState == SL_STATE_STOP && a.bTonOut == 0 && b.nState == SL_STATE_STOP &&
                b.bTofOut == 0,
            file, line, "init: STOP with the output FALSE");
}
#define TMR_CONFIG(d_, tb_, rc_) tmr_config((d_), (tb_), (rc_), __FILE__, __LINE__)

/* ---- FB TON ---- */

static void ton_delay(void)
{
    FB_TON inst;
    FB_TON *ton = &inst;
    uint32_t t = 1000, d;
    h_begin("TON §4.12: switch-on delay just below and at the limit (T3, T5, T6)");
    ton_setup(ton, 100, SL_TIMEBASE_AUTO);
    TON_INIT(SL_OK);
    TON_STOP(t += 10);
    ton->bRun = 1;
    TON_SAFE(t += 10);
    d = t += 10;
    ton->bTonIn1 = 1;
    TON_DELAYIN(d);                     /* the delay starts in this call */
    TON_DELAYIN(d + 50);
    TON_DELAYIN(d + 99);                /* just below */
    TON_RUN(d + 100);                   /* at the limit */
    TON_RUN(d + 5000);
    t = d + 5000;
    ton->bTonIn1 = 0;
    TON_SAFE(t += 10);                  /* output off in the same call */
    d = t += 10;
    ton->bTonIn1 = 1;
    TON_DELAYIN(d);
    ton->bTonIn1 = 0;
    TON_SAFE(d + 50);                   /* set to 0 before the delay: not activated */
    ton->bTonIn1 = 1;
    TON_DELAYIN(d + 60);                /* a full delay from scratch */
    TON_DELAYIN(d + 159);
    TON_RUN(d + 160);
    t = d + 160;
    ton->bTonIn1 = 0;
    TON_SAFE(t += 10);
    d = t += 10;
    ton->bTonIn1 = 1;
    TON_DELAYIN(d);
    ton->bTonIn1 = 0;
    TON_SAFE(d + 100);                  /* FALSE in the very call the delay is reached (T6) */
    t = d + 100;
    ton->bRun = 0;
    TON_STOP(t += 10);
    ton->bTonIn1 = 1;                   /* TRUE at start-up (T5) */
    TON_STOP(t += 10);
    ton->bRun = 1;
    d = t += 10;
    TON_SAFE(d);                        /* leaves STOP only */
    TON_DELAYIN(d + 10);                /* the level counts as the change to 1 */
    TON_DELAYIN(d + 109);
    TON_RUN(d + 110);
    t = d + 110;
    ton->bRun = 0;
    TON_STOP(t += 10);                  /* bRun FALSE: STOP, output 0 */
    h_end();
}

static void ton_timebase(void)
{
    FB_TON inst;
    FB_TON *ton = &inst;
    uint32_t t = 1000, d;
    h_begin("TON timebase 100 ms: the delay counts exact ms (T1, T3); across the 2^32 wrap");
    ton_setup(ton, 1500, SL_TIMEBASE_100MS);
    TON_INIT(SL_OK);
    ton->bRun = 1;
    TON_SAFE(t += 10);
    d = t += 10;
    ton->bTonIn1 = 1;
    TON_DELAYIN(d);
    TON_DELAYIN(d + 1499);
    TON_RUN(d + 1500);
    ton_setup(ton, 100, SL_TIMEBASE_1MS);
    TON_INIT(SL_OK);
    ton->bRun = 1;
    TON_SAFE(0xFFFFFFA0u);
    ton->bTonIn1 = 1;
    TON_DELAYIN(0xFFFFFFC0u);
    TON_DELAYIN(0x00000023u);           /* 99 ms later, across the wrap */
    TON_RUN(0x00000024u);               /* 100 ms */
    h_end();

    h_begin("TON/TOF delay limits per timebase: whole steps, 1..60000 steps (T1, T2, T4)");
    TMR_CONFIG(0, SL_TIMEBASE_AUTO, SL_E_CONFIG);
    TMR_CONFIG(1, SL_TIMEBASE_AUTO, SL_OK);
    TMR_CONFIG(60000u, SL_TIMEBASE_AUTO, SL_OK);
    TMR_CONFIG(60001u, SL_TIMEBASE_AUTO, SL_E_CONFIG); /* 10 ms timebase, not a multiple */
    TMR_CONFIG(60010u, SL_TIMEBASE_AUTO, SL_OK);
    TMR_CONFIG(600000u, SL_TIMEBASE_AUTO, SL_OK);
    TMR_CONFIG(600010u, SL_TIMEBASE_AUTO, SL_E_CONFIG); /* 100 ms timebase */
    TMR_CONFIG(60000000u, SL_TIMEBASE_AUTO, SL_OK);
    TMR_CONFIG(60001000u, SL_TIMEBASE_AUTO, SL_E_CONFIG); /* above 60,000 s */
    TMR_CONFIG(60000u, SL_TIMEBASE_1MS, SL_OK);
    TMR_CONFIG(60001u, SL_TIMEBASE_1MS, SL_E_CONFIG);
    TMR_CONFIG(1005u, SL_TIMEBASE_10MS, SL_E_CONFIG);
    TMR_CONFIG(600000u, SL_TIMEBASE_10MS, SL_OK);
    TMR_CONFIG(600010u, SL_TIMEBASE_10MS, SL_E_CONFIG);
    TMR_CONFIG(6000000u, SL_TIMEBASE_100MS, SL_OK);
    TMR_CONFIG(6000100u, SL_TIMEBASE_100MS, SL_E_CONFIG);
    TMR_CONFIG(60000000u, SL_TIMEBASE_1000MS, SL_OK);
    TMR_CONFIG(1500u, SL_TIMEBASE_1000MS, SL_E_CONFIG);
    TMR_CONFIG(1000u, 5, SL_E_CONFIG);  /* no such timebase */
    h_end();
}

static void ton_invalid_envelope(void)
{
    FB_TON inst;
    FB_TON *ton = &inst;
    uint32_t t = 1000, d;
    h_begin("TON invalid BOOL: TonIn1 reads FALSE, delay discarded (T8); make contact");
    ton_setup(ton, 100, SL_TIMEBASE_AUTO);
    TON_INIT(SL_OK);
    ton->bRun = 1;
    TON_SAFE(t += 10);
    d = t += 10;
    ton->bTonIn1 = 1;
    TON_DELAYIN(d);
    ton->bTonIn1 = 2;
    TON_S(d + 50, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    ton->bTonIn1 = 1;
    TON_DELAYIN(d + 60);
    TON_DELAYIN(d + 159);
    TON_RUN(d + 160);
    t = d + 160;
    ton->bTonIn1 = 0x80;
    TON_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    ton_setup(ton, 100, SL_TIMEBASE_AUTO);
    ton->wInputNegated = 0x01;          /* make contact: raw 0 = logical TRUE */
    ton->bTonIn1 = 1;
    TON_INIT(SL_OK);
    ton->bRun = 1;
    TON_SAFE(t += 10);
    TON_SAFE(t += 10);
    d = t += 10;
    ton->bTonIn1 = 0;
    TON_DELAYIN(d);
    TON_RUN(d + 100);
    ton->bTonIn1 = 3;                   /* invalid: FALSE whatever the negation */
    TON_S(d + 110, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    t = d + 110;
    h_end();

    h_begin("TON library errors without bError: nState 4, output FALSE (ABI §5, T16)");
    ton->bTonIn1 = 0;
    TON_DELAYIN(t += 10);
    TON_S(t - 20, SL_E_CLOCK, SL_STATE_ERROR, SL_DIAG_CLOCK, 0);
    t -= 20;
    ton->bErrAck = 1;
    TON_S(t += 10, SL_OK, SL_STATE_RESET, 0, 0);
    ton->bErrAck = 0;
    TON_SAFE(t += 10);                  /* start state SAFE (T5) */
    TON_DELAYIN(t += 10);
    ton->tDelay = 200;                  /* parameter change while running (C5) */
    TON_S(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 0);
    h_end();
}

static void ton_config_null_names(void)
{
    FB_TON inst;
    FB_TON *ton = &inst;
    uint32_t t = 1000;
    h_begin("TON configuration errors (SL_E_CONFIG, T6, C6), NULL, names");
    ton_setup(ton, 100, SL_TIMEBASE_AUTO);
    ton->wInputActive = 0;              /* TonIn1 must be active */
    TON_INIT(SL_E_CONFIG);
    ton->bRun = 1;
    ton->bTonIn1 = 1;
    TON_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    TON_S(t += 200, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    ton_setup(ton, 100, SL_TIMEBASE_AUTO);
    ton->wInputActive = 0x03;
    TON_INIT(SL_E_CONFIG);
    ton_setup(ton, 100, SL_TIMEBASE_AUTO);
    ton->wInputNegated = 0x02;
    TON_INIT(SL_E_CONFIG);
    CHECK_INT(sl_ton_init(NULL), SL_E_NULL);
    CHECK_INT(sl_ton_cycle(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_TON, SL_STATE_TON_DELAYIN), "DELAYIN");
    CHECK_STR(sl_state_str(SL_TYPE_TON, SL_STATE_SAFE), "SAFE");
    CHECK_STR(sl_state_str(SL_TYPE_TON, SL_STATE_RUN), "RUN");
    CHECK_STR(sl_state_str(SL_TYPE_TON, SL_STATE_DELAYOUT), "?");
    CHECK_DIAG_TEXT_HAS(SL_TYPE_TON, SL_DIAG_CLOCK, "clock");
    h_end();
}

/* ---- FB TOF ---- */

static void tof_delay(void)
{
    FB_TOF inst;
    FB_TOF *tof = &inst;
    uint32_t t = 1000, d;
    h_begin("TOF §4.14: switch-off delay just below and at the limit, re-trigger (T5, T7)");
    tof_setup(tof, 200, SL_TIMEBASE_AUTO);
    TOF_INIT(SL_OK);
    TOF_STOP(t += 10);
    tof->bRun = 1;
    TOF_SAFE(t += 10);                  /* start-up with TofIn1 FALSE: SAFE, not DELAYOUT */
    TOF_SAFE(t += 1000);
    tof->bTofIn1 = 1;
    TOF_RUN(t += 10);                   /* on in the same call */
    d = t += 10;
    tof->bTofIn1 = 0;
    TOF_DELAYOUT(d);                    /* output stays TRUE */
    TOF_DELAYOUT(d + 199);              /* just below */
    TOF_SAFE(d + 200);                  /* at the limit */
    t = d + 200;
    tof->bTofIn1 = 1;
    TOF_RUN(t += 10);
    d = t += 10;
    tof->bTofIn1 = 0;
    TOF_DELAYOUT(d);
    tof->bTofIn1 = 1;
    TOF_RUN(d + 100);                   /* set to 1 again: remains activated */
    tof->bTofIn1 = 0;
    TOF_DELAYOUT(d + 150);              /* a full delay from here */
    TOF_DELAYOUT(d + 349);
    TOF_SAFE(d + 350);
    t = d + 350;
    tof->bTofIn1 = 1;
    TOF_RUN(t += 10);
    d = t += 10;
    tof->bTofIn1 = 0;
    TOF_DELAYOUT(d);
    tof->bTofIn1 = 1;
    TOF_RUN(d + 200);                   /* TRUE in the call the delay is reached wins */
    t = d + 200;
    tof->bTofIn1 = 0;
    TOF_DELAYOUT(t += 10);
    tof->bRun = 0;
    TOF_STOP(t += 10);                  /* group stop: output FALSE at once (T7) */
    tof->bTofIn1 = 1;
    tof->bRun = 1;
    TOF_SAFE(t += 10);                  /* leaves STOP only (T5) */
    TOF_RUN(t += 10);
    h_end();

    h_begin("TOF 10 ms timebase (automatic): 60010 ms delay to the ms (T1, T3)");
    tof_setup(tof, 60010u, SL_TIMEBASE_AUTO);
    TOF_INIT(SL_OK);
    tof->bRun = 1;
    tof->bTofIn1 = 1;
    TOF_SAFE(t += 10);
    TOF_RUN(t += 10);
    d = t += 10;
    tof->bTofIn1 = 0;
    TOF_DELAYOUT(d);
    TOF_DELAYOUT(d + 60009u);
    TOF_SAFE(d + 60010u);
    h_end();
}

static void tof_invalid_config_names(void)
{
    FB_TOF inst;
    FB_TOF *tof = &inst;
    uint32_t t = 1000, d;
    h_begin("TOF invalid BOOL: the switch-off delay starts, never switches on (T8)");
    tof_setup(tof, 200, SL_TIMEBASE_AUTO);
    TOF_INIT(SL_OK);
    tof->bRun = 1;
    tof->bTofIn1 = 1;
    TOF_SAFE(t += 10);
    TOF_RUN(t += 10);
    d = t += 10;
    tof->bTofIn1 = 3;
    TOF_S(d, SL_E_INVALID_BOOL, SL_STATE_DELAYOUT, 0, TMR_OUT);
    TOF_S(d + 199, SL_E_INVALID_BOOL, SL_STATE_DELAYOUT, 0, TMR_OUT);
    TOF_S(d + 200, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    TOF_S(d + 300, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    t = d + 300;
    tof->bTofIn1 = 1;
    TOF_RUN(t += 10);
    h_end();

    h_begin("TOF configuration errors (SL_E_CONFIG, C6), NULL, names");
    tof_setup(tof, 200, SL_TIMEBASE_AUTO);
    tof->wInputActive = 0;
    TOF_INIT(SL_E_CONFIG);
    tof->bRun = 1;
    tof->bTofIn1 = 1;
    TOF_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    tof_setup(tof, 0, SL_TIMEBASE_AUTO);
    TOF_INIT(SL_E_CONFIG);
    tof_setup(tof, 200, 2);
    TOF_INIT(SL_E_CONFIG);
    tof_setup(tof, 200, SL_TIMEBASE_AUTO);
    tof->wInputNegated = 0x01;
    TOF_INIT(SL_OK);
    CHECK_INT(sl_tof_init(NULL), SL_E_NULL);
    CHECK_INT(sl_tof_cycle(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_TOF, SL_STATE_DELAYOUT), "DELAYOUT");
    CHECK_STR(sl_state_str(SL_TYPE_TOF, SL_STATE_RUN), "RUN");
    CHECK_STR(sl_state_str(SL_TYPE_TOF, SL_STATE_TON_DELAYIN), "?");
    CHECK_DIAG_TEXT_HAS(SL_TYPE_TOF, SL_DIAG_PARAM_CHANGED, "parameter");
    h_end();
}

/* ---- FB TON2 ---- */

static void ton2_power_cycle(void)
{
    FB_TON2 before_off, after_on;
    FB_TON2 *ton2 = &before_off;
    uint32_t t = 1000, d, r;
    h_begin("TON2 §4.13 Fig. 83: elapsed time kept across a power cycle (T10-T12, T14, T15)");
    ton2_setup(ton2, 120000u, SL_OPT_TON2_REMAINING_TIME);
    ton2->bEnable = 1;
    TON2_INIT(SL_OK);
    TON2_ELAPSED(0);
    ton2->bRun = 1;
    TON2_SAFE(t += 10);
    d = t += 10;
    ton2->bTonIn1 = 1;
    TON2_DELAYIN(d);                    /* nothing stored: the full delay */
    TON2_ELAPSED(0);
    TON2_DELAYIN(d + 35000u);
    TON2_ELAPSED(35000u);               /* the host persists this value */

    /* power cycle: a fresh instance, init, restore, then the connections start up */
    ton2 = &after_on;
    ton2_setup(ton2, 120000u, SL_OPT_TON2_REMAINING_TIME);
    TON2_INIT(SL_OK);
    TON2_ELAPSED(0);
    TON2_RESTORE(35000u, SL_OK, SL_STATE_STOP, 0);
    TON2_ELAPSED(35000u);
    t = 5000;                           /* a new clock */
    ton2->bRun = 1;
    ton2->bEnable = 1;
    TON2_SAFE(t += 10);                 /* TonIn still FALSE after start-up */
    TON2_SAFE(t += 10);
    TON2_ELAPSED(35000u);               /* not changed in SAFE (T11) */
    r = t += 10;
    ton2->bTonIn1 = 1;
    TON2_DELAYIN(r);                    /* starts with 120000 - 35000 ms remaining */
    TON2_ELAPSED(35000u);
    TON2_DELAYIN(r + 84999u);
    TON2_ELAPSED(119999u);
    TON2_RUN(r + 85000u);               /* 120 s in total */
    TON2_ELAPSED(120000u);
    t = r + 85000u;
    ton2->bTonIn1 = 0;
    TON2_SAFE(t += 10);
    TON2_ELAPSED(0);                    /* aborted: 0 (T11) */
    h_end();

    h_begin("TON2 bRun FALSE: STOP keeps the stored time, the delay continues (T11); invalid");
    r = t += 10;
    ton2->bTonIn1 = 1;
    TON2_DELAYIN(r);
    TON2_DELAYIN(r + 40000u);
    TON2_ELAPSED(40000u);
    ton2->bRun = 0;
    TON2_STOP(r + 40000u);              /* same tNow: output FALSE, STOP */
    TON2_ELAPSED(40000u);               /* not changed in STOP */
    TON2_STOP(r + 50000u);
    TON2_ELAPSED(40000u);
    ton2->bRun = 1;
    d = r + 50010u;
    TON2_SAFE(d);                       /* leaves STOP only (T5) */
    TON2_DELAYIN(d + 10);               /* Enable TRUE: continues with 80000 ms remaining */
    TON2_DELAYIN(d + 10 + 79999u);
    TON2_RUN(d + 10 + 80000u);
    t = d + 10 + 80000u;
    ton2->bTonIn1 = 0;
    TON2_SAFE(t += 10);
    r = t += 10;
    ton2->bTonIn1 = 1;
    TON2_DELAYIN(r);
    ton2->bTonIn1 = 2;                  /* invalid TonIn1: FALSE, delay discarded (T8) */
    TON2_S(r + 100, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    TON2_ELAPSED(0);
    t = r + 100;
    h_end();

    h_begin("TON2 Enable FALSE / invalid at the rise: the full delay (T10)");
    ton2_setup(ton2, 120000u, SL_OPT_TON2_REMAINING_TIME);
    TON2_INIT(SL_OK);
    TON2_RESTORE(35000u, SL_OK, SL_STATE_STOP, 0);
    ton2->bRun = 1;
    TON2_SAFE(t += 10);
    r = t += 10;
    ton2->bEnable = 0;
    ton2->bTonIn1 = 1;
    TON2_DELAYIN(r);
    ton2->bEnable = 1;                  /* changing Enable while the delay runs: no effect */
    TON2_DELAYIN(r + 85000u);
    TON2_DELAYIN(r + 119999u);
    TON2_RUN(r + 120000u);
    ton2_setup(ton2, 120000u, SL_OPT_TON2_REMAINING_TIME);
    TON2_INIT(SL_OK);
    TON2_RESTORE(35000u, SL_OK, SL_STATE_STOP, 0);
    ton2->bRun = 1;
    TON2_SAFE(t += 10);
    r = t += 10;
    ton2->bEnable = 2;                  /* invalid Enable: full delay, reported */
    ton2->bTonIn1 = 1;
    TON2_S(r, SL_E_INVALID_BOOL, SL_STATE_TON2_DELAYIN, 0, 0);
    ton2->bEnable = 1;
    TON2_DELAYIN(r + 119999u);
    TON2_RUN(r + 120000u);
    /* without the option Enable is not read and the stored value not used */
    ton2_setup(ton2, 1000u, 0);
    TON2_INIT(SL_OK);
    TON2_RESTORE(900u, SL_OK, SL_STATE_STOP, 0);
    ton2->bRun = 1;
    ton2->bEnable = 9;
    TON2_SAFE(t += 10);
    r = t += 10;
    ton2->bTonIn1 = 1;
    TON2_DELAYIN(r);
    TON2_DELAYIN(r + 999u);
    TON2_RUN(r + 1000u);
    h_end();
}

static void ton2_restore_rules(void)
{
    FB_TON2 inst;
    FB_TON2 *ton2 = &inst;
    uint32_t t = 1000, r;
    uint32_t v = 0;
    h_begin("TON2 restore equal to the delay: remaining time 0 (T12)");
    ton2_setup(ton2, 1000u, SL_OPT_TON2_REMAINING_TIME);
    TON2_INIT(SL_OK);
    TON2_RESTORE(1000u, SL_OK, SL_STATE_STOP, 0);
    TON2_ELAPSED(1000u);
    ton2->bRun = 1;
    ton2->bEnable = 1;
    TON2_SAFE(t += 10);
    r = t += 10;
    ton2->bTonIn1 = 1;
    TON2_DELAYIN(r);                    /* DELAYIN for this one call ... */
    TON2_RUN(r + 10);                   /* ... RUN in the next */
    h_end();

    h_begin("TON2 refused restore > delay: SL_E_RESTORE, ERROR, diag bit 12 (T13)");
    ton2_setup(ton2, 1000u, SL_OPT_TON2_REMAINING_TIME);
    TON2_INIT(SL_OK);
    TON2_RESTORE(1001u, SL_E_RESTORE, SL_STATE_ERROR, SL_DIAG_TON2_RESTORE);
    TON2_ELAPSED(0);                    /* discarded */
    TON2_S(t += 10, SL_OK, SL_STATE_ERROR, SL_DIAG_TON2_RESTORE, 0); /* bRun FALSE */
    ton2->bRun = 1;
    ton2->bEnable = 1;
    TON2_S(t += 10, SL_OK, SL_STATE_ERROR, SL_DIAG_TON2_RESTORE, 0);
    ton2->bErrAck = 1;
    TON2_S(t += 10, SL_OK, SL_STATE_RESET, 0, 0);
    ton2->bErrAck = 0;
    TON2_SAFE(t += 10);
    r = t += 10;
    ton2->bTonIn1 = 1;
    TON2_DELAYIN(r);                    /* the next delay is a full one */
    TON2_DELAYIN(r + 999u);
    TON2_RUN(r + 1000u);
    t = r + 1000u;
    TON2_RESTORE(10u, SL_E_RESTORE, SL_STATE_ERROR, SL_DIAG_TON2_RESTORE); /* not in STOP */
    TON2_ELAPSED(0);
    h_end();

    h_begin("TON2 stored value above a delay latched later: SL_E_RESTORE at the rise (T13, T17)");
    ton2_setup(ton2, 120000u, SL_OPT_TON2_REMAINING_TIME);
    TON2_INIT(SL_OK);
    TON2_RESTORE(100000u, SL_OK, SL_STATE_STOP, 0);
    ton2->tDelay = 60000u;              /* changed in STOP: latched at STOP -> run */
    TON2_STOP(t += 10);
    ton2->bRun = 1;
    ton2->bEnable = 1;
    TON2_SAFE(t += 10);
    ton2->bTonIn1 = 1;
    TON2_S(t += 10, SL_E_RESTORE, SL_STATE_ERROR, SL_DIAG_TON2_RESTORE, 0);
    TON2_ELAPSED(0);
    h_end();

    h_begin("TON2 configuration errors, restore with invalid parameters, NULL, names");
    ton2_setup(ton2, 1000u, SL_OPT_EDM1);
    TON2_INIT(SL_E_CONFIG);
    TON2_RESTORE(10u, SL_E_CONFIG, SL_STATE_STOP, 0); /* nothing stored (T14) */
    ton2->bRun = 1;
    ton2->bTonIn1 = 1;
    TON2_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    ton2_setup(ton2, 1000u, SL_OPT_TON2_REMAINING_TIME);
    ton2->wInputActive = 0x03;          /* Enable has no active bit (T10) */
    TON2_INIT(SL_E_CONFIG);
    ton2_setup(ton2, 0, SL_OPT_TON2_REMAINING_TIME);
    TON2_INIT(SL_E_CONFIG);
    ton2_setup(ton2, 60000000u, SL_OPT_TON2_REMAINING_TIME);
    TON2_INIT(SL_OK);
    CHECK_INT(sl_ton2_init(NULL), SL_E_NULL);
    CHECK_INT(sl_ton2_cycle(NULL, 0), SL_E_NULL);
    CHECK_INT(sl_ton2_get_elapsed(NULL, &v), SL_E_NULL);
    CHECK_INT(sl_ton2_get_elapsed(ton2, NULL), SL_E_NULL);
    CHECK_INT(sl_ton2_restore_elapsed(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_TON2, SL_STATE_TON2_DELAYIN), "DELAYIN");
    CHECK_STR(sl_state_str(SL_TYPE_TON2, SL_STATE_ERROR), "ERROR");
    CHECK_DIAG_TEXT_HAS(SL_TYPE_TON2, SL_DIAG_TON2_RESTORE, "0x3510");
    CHECK(sl_status_str(SL_E_RESTORE) != NULL && sl_status_str(SL_E_RESTORE)[0] != '\0',
          "sl_status_str(SL_E_RESTORE) is a text");
    h_end();
}

void run_timer_scenarios(void)
{
    ton_delay();
    ton_timebase();
    ton_invalid_envelope();
    ton_config_null_names();
    tof_delay();
    tof_invalid_config_names();
    ton2_power_cycle();
    ton2_restore_rules();
}
