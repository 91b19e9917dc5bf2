/*
 * FB_OPMODE behaviour scenarios (manual §4.3, restart samples 1 and 2 of §4.3.4; ABI.md §2,
 * §4, §5, §7, §9; docs/semantics.md rows O1-O12, C1-C12).
 *
 * Every step calls sl_opmode_cycle once and checks the status code, nState, nDiag and all
 * nine outputs: bit n-1 of the expected set = bOpOutn, bit 8 (OPM_ERR) = bError.
 */
#include "harness.h"

/* ---- helpers (prefixed opm_) ---- */

#define OPM_OUT(n) (1u << ((n) - 1))
#define OPM_ERR (1u << 8)

static uint32_t opm_outs(const FB_OPMODE *fb)
{
    uint32_t o = 0;
    o = h_pack_bool(o, fb->bOpOut1, 0);
    o = h_pack_bool(o, fb->bOpOut2, 1);
    o = h_pack_bool(o, fb->bOpOut3, 2);
    o = h_pack_bool(o, fb->bOpOut4, 3);
    o = h_pack_bool(o, fb->bOpOut5, 4);
    o = h_pack_bool(o, fb->bOpOut6, 5);
    o = h_pack_bool(o, fb->bOpOut7, 6);
    o = h_pack_bool(o, fb->bOpOut8, 7);
    o = h_pack_bool(o, fb->bError, 8);
    return o;
}

static void opm_step(FB_OPMODE *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                     uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_opmode_cycle(fb, t);
    h_check_fb(file, line, "OPMODE", SL_TYPE_OPMODE, t, rc, fb->nState, fb->nDiag,
               opm_outs(fb), xrc, xst, xdiag, xouts);
}

/* OPM_S(t, rc, state, diag, outputs): one cycle of `fb` at time t. */
#define OPM_S(t_, rc_, st_, diag_, outs_) \
    opm_step(fb, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define OPM_RUN(t_, mode_) OPM_S((t_), SL_OK, SL_STATE_RUN, 0, OPM_OUT(mode_))
#define OPM_STOP(t_) OPM_S((t_), SL_OK, SL_STATE_STOP, 0, 0)
#define OPM_SAFE(t_) OPM_S((t_), SL_OK, SL_STATE_SAFE, 0, 0)
#define OPM_START(t_) OPM_S((t_), SL_OK, SL_STATE_START, 0, 0)
#define OPM_RESET(t_) OPM_S((t_), SL_OK, SL_STATE_RESET, 0, 0)
#define OPM_ERROR(t_) OPM_S((t_), SL_OK, SL_STATE_ERROR, SL_DIAG_OPMODE_DISC, OPM_ERR)

static void opm_setup(FB_OPMODE *fb, uint16_t active, uint32_t disc, uint32_t options)
{
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = active;
    fb->tDiscTime = disc;
    fb->dwOptions = options;
}

/* sl_opmode_init: status, power-up image (C1), VAR_INPUT bytes 0..31 untouched (ABI §4). */
static void opm_init_check(FB_OPMODE *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[32];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_opmode_init(fb);
    h_check_int(rc, xrc, file, line, "sl_opmode_init");
    h_check_fb(file, line, "OPMODE(init)", SL_TYPE_OPMODE, 0, rc, fb->nState, fb->nDiag,
               opm_outs(fb), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_opmode_init modified a VAR_INPUT byte (ABI §4)");
}
#define OPM_INIT(rc_) opm_init_check(fb, (rc_), __FILE__, __LINE__)

/* Manual restart from SAFE: Restart TRUE -> START, falling edge -> RUN with `mode` (O8). */
static void opm_restart(FB_OPMODE *fb, uint32_t *t, int mode, const char *file, int line)
{
    fb->bRestart = 1;
    opm_step(fb, *t += 10, SL_OK, SL_STATE_START, 0, 0, file, line);
    fb->bRestart = 0;
    opm_step(fb, *t += 10, SL_OK, SL_STATE_RUN, 0, OPM_OUT(mode), file, line);
}
#define OPM_RESTART(mode_) opm_restart(fb, &t, (mode_), __FILE__, __LINE__)

/* ---- automatic operation (no restart input) ---- */

static void opm_auto(void)
{
    FB_OPMODE inst;
    FB_OPMODE *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("OPMODE §4.3.1 automatic: exactly one input selects its output (O1, O4, O7, O9)");
    opm_setup(fb, 0x0F, 100, 0);
    OPM_INIT(SL_OK);
    OPM_STOP(t += 10);                  /* bRun FALSE */
    fb->bOpIn1 = 1;
    OPM_STOP(t += 10);
    fb->bRun = 1;
    OPM_SAFE(t += 10);                  /* STOP -> run enters SAFE (O7) */
    OPM_RUN(t += 10, 1);                /* next call: RUN with mode 1 */
    fb->bOpIn1 = 0;
    fb->bOpIn2 = 1;
    OPM_RUN(t += 10, 2);                /* direct change: off/on in the same call (O9) */
    fb->bOpIn5 = 1;                     /* inactive input ignored (O1) */
    OPM_RUN(t += 10, 2);
    fb->bOpIn5 = 7;                     /* inactive: not read, no SL_E_INVALID_BOOL */
    OPM_RUN(t += 10, 2);
    fb->bOpIn5 = 0;
    fb->bRestart = 5;                   /* not read without SL_OPT_MANUAL_RESTART (O10) */
    OPM_RUN(t += 10, 2);
    fb->bRestart = 0;
    d = t += 10;
    fb->bOpIn3 = 1;                     /* two modes: all outputs safe */
    OPM_SAFE(d);
    fb->bOpIn2 = 0;
    OPM_RUN(d + 50, 3);                 /* exactly one again */
    d += 60;
    fb->bOpIn4 = 1;
    OPM_SAFE(d);
    OPM_SAFE(d + 98);
    fb->bOpIn3 = 0;
    OPM_RUN(d + 99, 4);                 /* 99 ms without a single mode: below the limit */
    t = d + 99;
    fb->bOpIn1 = 2;                     /* invalid byte on an active input (O5) */
    OPM_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    fb->bOpIn1 = 0;
    OPM_RUN(t += 10, 4);
    fb->bOpIn4 = 0;
    fb->bOpIn8 = 1;                     /* inactive */
    OPM_SAFE(t += 10);                  /* no active input set */
    fb->bRun = 0;
    OPM_STOP(t += 10);                  /* bRun FALSE: STOP, outputs 0 */
    h_end();
}

static void opm_disc(void)
{
    FB_OPMODE inst;
    FB_OPMODE *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("OPMODE mode-change discrepancy: at the limit -> ERROR, ack needs a mode (O3, O6)");
    opm_setup(fb, 0x03, 100, 0);
    OPM_INIT(SL_OK);
    fb->bOpIn1 = 1;
    fb->bRun = 1;
    OPM_SAFE(t += 10);
    OPM_RUN(t += 10, 1);
    d = t += 10;
    fb->bOpIn1 = 0;                     /* no mode: the timer starts */
    OPM_SAFE(d);
    OPM_SAFE(d + 99);
    OPM_ERROR(d + 100);                 /* at the limit */
    t = d + 100;
    fb->bErrAck = 1;                    /* still no mode: edge consumed (O6, C8) */
    OPM_ERROR(t += 10);
    fb->bErrAck = 0;
    fb->bOpIn1 = 1;
    fb->bOpIn2 = 1;                     /* two modes: still no single mode */
    OPM_ERROR(t += 10);
    fb->bErrAck = 1;
    OPM_ERROR(t += 10);
    fb->bErrAck = 0;
    fb->bOpIn2 = 0;
    OPM_ERROR(t += 10);                 /* no edge: stays ERROR */
    fb->bRun = 0;
    OPM_ERROR(t += 10);                 /* ERROR stays with bRun FALSE (ABI §7) */
    fb->bRun = 1;
    OPM_ERROR(t += 10);
    fb->bErrAck = 1;
    OPM_RESET(t += 10);                 /* nDiag cleared (C9) */
    fb->bErrAck = 0;
    OPM_SAFE(t += 10);                  /* RESET -> SAFE (O7) */
    OPM_RUN(t += 10, 1);
    h_end();

    h_begin("OPMODE start-up with no mode selected: timer from the call after STOP (O3, O7)");
    opm_setup(fb, 0x03, 100, 0);
    OPM_INIT(SL_OK);
    fb->bRun = 1;
    d = t += 10;
    OPM_SAFE(d);                        /* leaves STOP only */
    OPM_SAFE(d + 10);                   /* timer starts here */
    OPM_SAFE(d + 109);
    OPM_ERROR(d + 110);
    h_end();

    h_begin("OPMODE tDiscTime 0: no mode-change monitoring (O3)");
    opm_setup(fb, 0x03, 0, 0);
    OPM_INIT(SL_OK);
    fb->bRun = 1;
    OPM_SAFE(t += 10);
    OPM_SAFE(t += 100000);
    fb->bOpIn2 = 1;
    OPM_RUN(t += 10, 2);
    h_end();
}

/* ---- manual restart: samples 1 and 2 of §4.3.4 ---- */

static void opm_sample1(void)
{
    FB_OPMODE inst;
    FB_OPMODE *fb = &inst;
    uint32_t t = 1000;
    h_begin("OPMODE §4.3.4 sample 1: mode change acknowledged with the Restart input");
    opm_setup(fb, 0x03, 100, SL_OPT_MANUAL_RESTART);
    OPM_INIT(SL_OK);
    fb->bOpIn1 = 1;
    fb->bRun = 1;
    OPM_SAFE(t += 10);
    OPM_SAFE(t += 10);                  /* start-up needs the restart sequence */
    OPM_SAFE(t += 500);                 /* waiting with one mode: no timer (O4) */
    OPM_RESTART(1);
    fb->bOpIn1 = 0;                     /* operation mode change 1 -> 2 */
    OPM_SAFE(t += 10);
    fb->bOpIn2 = 1;
    OPM_SAFE(t += 40);                  /* new mode: safe until the restart (O9) */
    OPM_SAFE(t += 500);
    OPM_RESTART(2);
    h_end();
}

static void opm_sample2(void)
{
    FB_OPMODE inst;
    FB_OPMODE *fb = &inst;
    uint32_t t = 1000;
    h_begin("OPMODE §4.3.4 sample 2: Restart TRUE before the mode change (O12)");
    opm_setup(fb, 0x03, 100, SL_OPT_MANUAL_RESTART);
    OPM_INIT(SL_OK);
    fb->bOpIn1 = 1;
    fb->bRun = 1;
    OPM_SAFE(t += 10);
    OPM_SAFE(t += 10);
    OPM_RESTART(1);
    fb->bRestart = 1;
    OPM_RUN(t += 10, 1);                /* Restart edges in RUN are ignored (O9) */
    fb->bOpIn1 = 0;
    OPM_SAFE(t += 10);                  /* "results in a switch to state 3" */
    fb->bOpIn2 = 1;
    OPM_START(t += 10);                 /* Restart already TRUE: Start state 6 */
    OPM_START(t += 10);
    fb->bRestart = 0;
    OPM_RUN(t += 10, 2);                /* falling edge: OpOut2 */
    h_end();
}

static void opm_start_rules(void)
{
    FB_OPMODE inst;
    FB_OPMODE *fb = &inst;
    uint32_t t = 1000;
    h_begin("OPMODE START: the confirmed mode must still be the only one (O8, O9, C7)");
    opm_setup(fb, 0x07, 200, SL_OPT_MANUAL_RESTART);
    OPM_INIT(SL_OK);
    fb->bOpIn2 = 1;
    fb->bRun = 1;
    OPM_SAFE(t += 10);
    OPM_SAFE(t += 10);
    OPM_RESTART(2);
    fb->bOpIn2 = 0;
    fb->bOpIn1 = 1;                     /* direct change with manual restart -> SAFE (O9) */
    OPM_SAFE(t += 10);
    fb->bRestart = 1;
    OPM_START(t += 10);                 /* mode 1 latched */
    fb->bOpIn1 = 0;
    fb->bOpIn3 = 1;                     /* another mode while START -> SAFE */
    OPM_SAFE(t += 10);
    OPM_START(t += 10);                 /* Restart still TRUE, one mode (3): START again */
    fb->bRestart = 3;                   /* invalid: FALSE without a falling edge (C7) */
    OPM_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    fb->bRestart = 0;
    OPM_SAFE(t += 10);                  /* no edge */
    fb->bRestart = 1;
    OPM_START(t += 10);
    fb->bOpIn2 = 1;                     /* two modes while START */
    OPM_SAFE(t += 10);
    fb->bOpIn2 = 0;
    OPM_START(t += 10);
    fb->bRestart = 0;
    OPM_RUN(t += 10, 3);
    fb->bRun = 0;
    OPM_STOP(t += 10);
    fb->bRun = 1;
    OPM_SAFE(t += 10);                  /* start-up: restart required again */
    OPM_SAFE(t += 10);
    OPM_RESTART(3);
    h_end();
}

static void opm_config_null_names(void)
{
    FB_OPMODE inst;
    FB_OPMODE *fb = &inst;
    uint32_t t = 1000;
    h_begin("OPMODE configuration errors (SL_E_CONFIG, O2, C6), NULL, names");
    opm_setup(fb, 0x01, 0, 0);          /* one active input: at least two (§4.3.1) */
    OPM_INIT(SL_E_CONFIG);
    fb->bRun = 1;
    fb->bOpIn1 = 1;
    OPM_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    OPM_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    opm_setup(fb, 0x00, 0, 0);
    OPM_INIT(SL_E_CONFIG);
    opm_setup(fb, 0x103, 0, 0);         /* bit 8: no OpIn9 */
    OPM_INIT(SL_E_CONFIG);
    opm_setup(fb, 0x03, SL_TIME_PARAM_MAX + 1u, 0);
    OPM_INIT(SL_E_CONFIG);
    opm_setup(fb, 0x03, 0, SL_OPT_EDM1);
    OPM_INIT(SL_E_CONFIG);
    opm_setup(fb, 0x03, 0, SL_OPT_FUNCTION_TEST);
    OPM_INIT(SL_E_CONFIG);
    opm_setup(fb, 0x81, SL_TIME_PARAM_MAX, SL_OPT_MANUAL_RESTART);
    OPM_INIT(SL_OK);
    opm_setup(fb, 0xFF, 1, 0);
    OPM_INIT(SL_OK);
    CHECK_INT(sl_opmode_init(NULL), SL_E_NULL);
    CHECK_INT(sl_opmode_cycle(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_OPMODE, SL_STATE_RUN), "RUN");
    CHECK_STR(sl_state_str(SL_TYPE_OPMODE, SL_STATE_SAFE), "SAFE");
    CHECK_STR(sl_state_str(SL_TYPE_OPMODE, SL_STATE_START), "START");
    CHECK_STR(sl_state_str(SL_TYPE_OPMODE, SL_STATE_DELAYOUT), "?");
    CHECK_DIAG_TEXT(SL_TYPE_OPMODE, SL_DIAG_OPMODE_DISC, "Discrepancy monitoring error");
    h_end();
}

void run_opmode_scenarios(void)
{
    opm_auto();
    opm_disc();
    opm_sample1();
    opm_sample2();
    opm_start_rules();
    opm_config_null_names();
}
