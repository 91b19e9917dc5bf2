/*
 * FB_MON behaviour scenarios (manual §4.5, ABI.md §2, §5, §7, §8, docs/semantics.md).
 *
 * Every step calls sl_mon_cycle once and checks the status code, nState, nDiag and all
 * three outputs (bError, bMonOut, bMonDelOut). Times are simulated milliseconds.
 * Semantics row IDs (C1..C12, G1..G15) refer to docs/semantics.md.
 */
#include "harness.h"

/* ---- helpers (names prefixed mon_: all scenario files share one TU in the C++ build) ---- */

static void mon_step(FB_MON *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                     uint8_t xerr, uint8_t xout, uint8_t xdel, const char *file, int line)
{
    int32_t rc = sl_mon_cycle(fb, t);
    h_check_step(file, line, "MON", t, rc, fb->nState, fb->nDiag, fb->bError, fb->bMonOut,
                 fb->bMonDelOut, xrc, xst, xdiag, xerr, xout, xdel);
}

/* MS(t, rc, state, diag, bError, bMonOut, bMonDelOut): one cycle of `fb` at time t. */
#define MS(t_, rc_, st_, diag_, err_, out_, del_) \
    mon_step(fb, (t_), (rc_), (st_), (diag_), (err_), (out_), (del_), __FILE__, __LINE__)
#define MS_RUN(t_) MS((t_), SL_OK, SL_STATE_RUN, 0, 0, 1, 1)
#define MS_STOP(t_) MS((t_), SL_OK, SL_STATE_STOP, 0, 0, 0, 0)
#define MS_SAFE(t_) MS((t_), SL_OK, SL_STATE_SAFE, 0, 0, 0, 0)
#define MS_START(t_) MS((t_), SL_OK, SL_STATE_START, 0, 0, 0, 0)
#define MS_RESET(t_) MS((t_), SL_OK, SL_STATE_RESET, 0, 0, 0, 0)
#define MS_FUNCTEST(t_) MS((t_), SL_OK, SL_STATE_FUNCTEST, 0, 0, 0, 0)
#define MS_DELAYOUT(t_) MS((t_), SL_OK, SL_STATE_DELAYOUT, 0, 0, 0, 1)
#define MS_ERRORDELAY(t_, diag_) MS((t_), SL_OK, SL_STATE_ERRORDELAY, (diag_), 0, 0, 1)
#define MS_ERROR(t_, diag_) MS((t_), SL_OK, SL_STATE_ERROR, (diag_), 1, 0, 0)

static void mon_inputs(FB_MON *fb, uint8_t v)
{
    fb->bMonIn1 = v;
    fb->bMonIn2 = v;
    fb->bMonIn3 = v;
    fb->bMonIn4 = v;
}

/* A zeroed instance: MonIn TRUE (door closed), Secure FALSE (no bypass), EDM TRUE
 * (contactors released), bRun TRUE. */
static void mon_setup(FB_MON *fb, uint16_t active, uint32_t options)
{
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = active;
    fb->dwOptions = options;
    fb->bRun = 1;
    mon_inputs(fb, 1);
    fb->bSecure1 = 0;
    fb->bSecure2 = 0;
    fb->bEDM1 = 1;
    fb->bEDM2 = 1;
}

static void mon_init_ok(FB_MON *fb, const char *file, int line)
{
    unsigned char before[offsetof(FB_MON, bError)];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_mon_init(fb);
    h_check_int(rc, SL_OK, file, line, "sl_mon_init");
    h_check_step(file, line, "MON(no call)", 0, SL_OK, fb->nState, fb->nDiag, fb->bError,
                 fb->bMonOut, fb->bMonDelOut, SL_OK, SL_STATE_STOP, 0, 0, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_mon_init modified a VAR_INPUT byte (ABI §4)");
}
#define MS_INIT() mon_init_ok(fb, __FILE__, __LINE__)

/* Manual restart: STOP -> SAFE -> START -> RUN (G12). */
static void mon_to_run_manual(FB_MON *fb, uint32_t *t, const char *file, int line)
{
    mon_step(fb, *t += 10, SL_OK, SL_STATE_SAFE, 0, 0, 0, 0, file, line);
    fb->bRestart = 1;
    mon_step(fb, *t += 10, SL_OK, SL_STATE_START, 0, 0, 0, 0, file, line);
    fb->bRestart = 0;
    mon_step(fb, *t += 10, SL_OK, SL_STATE_RUN, 0, 0, 1, 1, file, line);
}
#define MS_TO_RUN_MANUAL() mon_to_run_manual(fb, &t, __FILE__, __LINE__)

/* Automatic restart: STOP -> SAFE, one cycle later RUN (G12). */
static void mon_to_run_auto(FB_MON *fb, uint32_t *t, const char *file, int line)
{
    mon_step(fb, *t += 10, SL_OK, SL_STATE_SAFE, 0, 0, 0, 0, file, line);
    mon_step(fb, *t += 10, SL_OK, SL_STATE_RUN, 0, 0, 1, 1, file, line);
}
#define MS_TO_RUN_AUTO() mon_to_run_auto(fb, &t, __FILE__, __LINE__)

static void mon_restart(FB_MON *fb, uint32_t *t, const char *file, int line)
{
    fb->bRestart = 1;
    mon_step(fb, *t += 10, SL_OK, SL_STATE_START, 0, 0, 0, 0, file, line);
    fb->bRestart = 0;
    mon_step(fb, *t += 10, SL_OK, SL_STATE_RUN, 0, 0, 1, 1, file, line);
}
#define MS_RESTART() mon_restart(fb, &t, __FILE__, __LINE__)

/* ERROR -> RESET -> start state (SAFE here; FUNCTEST with the function test, G9). */
static void mon_ack(FB_MON *fb, uint32_t *t, uint8_t start_state, const char *file, int line)
{
    fb->bErrAck = 1;
    mon_step(fb, *t += 10, SL_OK, SL_STATE_RESET, 0, 0, 0, 0, file, line);
    fb->bErrAck = 0;
    mon_step(fb, *t += 10, SL_OK, start_state, 0, 0, 0, 0, file, line);
}
#define MS_ACK() mon_ack(fb, &t, SL_STATE_SAFE, __FILE__, __LINE__)

/* ---- manual §4.5.4 restart samples (manual restart active, EDM1 active) ---- */

static void mon_sample1(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000;
    h_begin("MON §4.5.4 sample 1: door opened and closed, restart (EDM1 active)");
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART | SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    MS_INIT();
    MS_SAFE(t += 10);
    MS_SAFE(t += 10);
    fb->bRestart = 1;
    MS_START(t += 10);
    fb->bRestart = 0;
    MS_RUN(t += 10);
    fb->bEDM1 = 0;
    MS_RUN(t += 10);
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);
    fb->bEDM1 = 1;
    MS_SAFE(t += 10);
    mon_inputs(fb, 1);
    MS_SAFE(t += 10);               /* manual restart: stays SAFE */
    MS_SAFE(t += 100);
    fb->bRestart = 1;
    MS_START(t += 10);
    MS_START(t += 10);
    fb->bRestart = 0;
    MS_RUN(t += 10);
    h_end();
}

static void mon_sample2(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000;
    h_begin("MON §4.5.4 sample 2: Restart rises before the MonIn inputs");
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART | SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    MS_INIT();
    MS_TO_RUN_MANUAL();
    fb->bEDM1 = 0;
    MS_RUN(t += 10);
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);
    fb->bEDM1 = 1;
    MS_SAFE(t += 10);
    fb->bRestart = 1;
    MS_SAFE(t += 10);
    MS_SAFE(t += 10);
    mon_inputs(fb, 1);
    MS_START(t += 10);              /* both TRUE: START */
    fb->bRestart = 0;
    MS_RUN(t += 10);                /* falling edge */
    h_end();
}

static void mon_sample3(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000;
    h_begin("MON §4.5.4 sample 3: Restart held through the MonIn event -> EDM error");
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART | SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    MS_INIT();
    MS_TO_RUN_MANUAL();
    fb->bEDM1 = 0;
    MS_RUN(t += 10);
    fb->bRestart = 1;
    MS_RUN(t += 10);
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);               /* outputs off in this call; EDM checked from the next */
    MS_ERROR(t += 10, SL_DIAG_EDM1);
    fb->bEDM1 = 1;
    fb->bRestart = 0;
    mon_inputs(fb, 1);
    MS_ERROR(t += 10, SL_DIAG_EDM1);
    MS_ACK();
    MS_RESTART();
    h_end();
}

/* ---- automatic restart (G3, G12) ---- */

static void mon_auto_restart(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000;
    h_begin("MON automatic restart; FALSE EDM keeps SAFE without error (G3)");
    mon_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    MS_INIT();
    MS_TO_RUN_AUTO();
    fb->bEDM1 = 0;
    MS_RUN(t += 10);
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);
    mon_inputs(fb, 1);
    MS_SAFE(t += 10);               /* EDM1 still FALSE (welded): stays SAFE, no error */
    MS_SAFE(t += 100);
    fb->bEDM1 = 1;
    MS_RUN(t += 10);                /* nothing requests, EDM TRUE: RUN by itself */
    fb->bRestart = 7;               /* Restart not used without manual restart (C7) */
    MS_RUN(t += 10);
    fb->bRestart = 1;
    MS_RUN(t += 10);
    fb->bRestart = 0;
    fb->bRun = 0;
    MS_STOP(t += 10);
    fb->bRun = 1;
    MS_SAFE(t += 10);
    MS_RUN(t += 10);
    h_end();
}

/* ---- discrepancy (pairs MonIn3/4 and Secure1/2, Safe Inputs after Disc Error) ---- */

static void mon_disc(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("MON discrepancy: MonIn1/2 below/at limit, MonIn3/4 (bit 1), Secure (bit 2)");
    mon_setup(fb, 0x0F, SL_OPT_MANUAL_RESTART);
    fb->tDiscTime12 = 100;
    fb->tDiscTime34 = 80;
    MS_INIT();
    MS_TO_RUN_MANUAL();
    d = t += 10;
    fb->bMonIn1 = 0;
    MS_SAFE(d);
    fb->bMonIn2 = 0;
    MS_SAFE(d + 99);                /* agree after 99 ms */
    MS_SAFE(d + 300);
    mon_inputs(fb, 1);
    t = d + 310;
    MS_SAFE(t);
    MS_RESTART();
    d = t += 10;
    fb->bMonIn4 = 0;
    MS_SAFE(d);
    MS_SAFE(d + 79);
    MS_ERROR(d + 80, SL_DIAG_DISC2);
    t = d + 80;
    fb->bErrAck = 1;
    MS_ERROR(t += 10, SL_DIAG_DISC2); /* still differ */
    fb->bErrAck = 0;
    fb->bMonIn4 = 1;
    MS_ERROR(t += 10, SL_DIAG_DISC2);
    MS_ACK();
    MS_RESTART();

    /* Secure pair, automatic restart, no output delay: ERROR directly */
    mon_setup(fb, 0x33, 0);
    fb->tDiscTimeSecure12 = 60;
    MS_INIT();
    MS_TO_RUN_AUTO();
    d = t += 10;
    fb->bSecure1 = 1;               /* Secure2 FALSE: no bypass, nothing requests */
    MS_RUN(d);
    MS_RUN(d + 59);
    MS_ERROR(d + 60, SL_DIAG_DISC3);
    t = d + 60;
    fb->bSecure1 = 0;
    MS_ERROR(t += 10, SL_DIAG_DISC3);
    MS_ACK();
    MS_RUN(t += 10);                /* automatic restart after RESET -> SAFE */

    /* Safe Inputs after Disc Error (bits 0 + 8) */
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART | SL_OPT_SAFE_INPUTS_AFTER_DISC);
    fb->tDiscTime12 = 100;
    MS_INIT();
    MS_TO_RUN_MANUAL();
    d = t += 10;
    fb->bMonIn1 = 0;
    MS_SAFE(d);
    MS_ERROR(d + 100, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    t = d + 100;
    fb->bMonIn1 = 1;
    fb->bErrAck = 1;
    MS_ERROR(t += 10, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1); /* never both safe yet */
    fb->bErrAck = 0;
    mon_inputs(fb, 0);
    MS_ERROR(t += 10, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    mon_inputs(fb, 1);
    MS_ERROR(t += 10, SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1);
    MS_ACK();
    MS_RESTART();
    h_end();
}

/* ---- delayed output: DELAYOUT (G10) and ERRORDELAY (G7) ---- */

static void mon_delayout(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("MON DELAYOUT with automatic restart runs to the end of the delay");
    mon_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    fb->tMonDelOutDelay = 200;
    MS_INIT();
    MS_TO_RUN_AUTO();
    d = t += 10;
    mon_inputs(fb, 0);
    MS_DELAYOUT(d);
    MS_DELAYOUT(d + 20);
    mon_inputs(fb, 1);
    MS_DELAYOUT(d + 50);            /* request gone: the delay still runs out */
    MS_DELAYOUT(d + 199);
    MS_SAFE(d + 200);
    MS_RUN(d + 210);                /* automatic restart, one transition per call */
    h_end();
}

static void mon_errordelay(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("MON ERRORDELAY: discrepancy with MonDelOut delay (from RUN and from DELAYOUT)");
    /* from RUN: MonIn bypassed by the Secure inputs, so the discrepancy arises in RUN */
    mon_setup(fb, 0x33, 0);
    fb->tDiscTime12 = 50;
    fb->tMonDelOutDelay = 200;
    fb->bSecure1 = 1;
    fb->bSecure2 = 1;
    MS_INIT();
    MS_TO_RUN_AUTO();
    d = t += 10;
    fb->bMonIn1 = 0;
    MS_RUN(d);                      /* bypassed: no request, discrepancy timer runs (G14) */
    MS_RUN(d + 49);
    MS_ERRORDELAY(d + 50, SL_DIAG_DISC1); /* MonOut off, MonDelOut on, Error FALSE */
    MS_ERRORDELAY(d + 100, SL_DIAG_DISC1);
    MS_ERRORDELAY(d + 249, SL_DIAG_DISC1);
    MS_ERROR(d + 250, SL_DIAG_DISC1);     /* delay elapsed since the error */
    t = d + 250;
    fb->bMonIn1 = 1;
    MS_ERROR(t += 10, SL_DIAG_DISC1);
    MS_ACK();
    MS_RUN(t += 10);

    /* from DELAYOUT: the running delay is kept */
    mon_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 50;
    fb->tMonDelOutDelay = 200;
    MS_INIT();
    MS_TO_RUN_AUTO();
    d = t += 10;
    fb->bMonIn1 = 0;
    MS_DELAYOUT(d);
    MS_DELAYOUT(d + 49);
    MS_ERRORDELAY(d + 50, SL_DIAG_DISC1);
    MS_ERRORDELAY(d + 199, SL_DIAG_DISC1);
    MS_ERROR(d + 200, SL_DIAG_DISC1);

    /* bRun FALSE in ERRORDELAY -> ERROR */
    mon_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 50;
    fb->tMonDelOutDelay = 200;
    MS_INIT();
    MS_TO_RUN_AUTO();
    d = t += 10;
    fb->bMonIn2 = 0;
    MS_DELAYOUT(d);
    MS_ERRORDELAY(d + 50, SL_DIAG_DISC1);
    fb->bRun = 0;
    MS_ERROR(d + 60, SL_DIAG_DISC1);

    /* EDM reset-time error in RUN goes to ERROR directly, even with a delay */
    mon_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 50;
    fb->tMonDelOutDelay = 200;
    fb->tEDM1ResetTime = 30;
    MS_INIT();
    MS_TO_RUN_AUTO();
    d = t;
    MS_RUN(d + 29);
    MS_ERROR(d + 30, SL_DIAG_EDM1);
    h_end();
}

/* ---- Secure bypass (ABI §8, G8) ---- */

static void mon_secure(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000;
    h_begin("MON Secure bypass: every active Secure TRUE bypasses the MonIn inputs");
    mon_setup(fb, 0x33, 0);
    MS_INIT();
    MS_TO_RUN_AUTO();
    fb->bSecure1 = 1;
    fb->bSecure2 = 1;
    MS_RUN(t += 10);
    mon_inputs(fb, 0);
    MS_RUN(t += 10);                /* bypassed */
    MS_RUN(t += 100);
    fb->bSecure2 = 0;
    MS_SAFE(t += 10);               /* one Secure alone does not bypass */
    fb->bSecure2 = 1;
    MS_RUN(t += 10);                /* bypass again: nothing requests, automatic restart */
    fb->bSecure1 = 0;
    fb->bSecure2 = 0;
    MS_SAFE(t += 10);
    mon_inputs(fb, 1);
    MS_RUN(t += 10);                /* Secure FALSE alone is no request */
    /* Secure inputs as make contacts: bypass while raw FALSE */
    mon_setup(fb, 0x33, 0);
    fb->wInputNegated = 0x30;
    fb->bSecure1 = 1;               /* make contacts closed: logical FALSE, no bypass */
    fb->bSecure2 = 1;
    MS_INIT();
    MS_TO_RUN_AUTO();
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);
    fb->bSecure1 = 0;
    fb->bSecure2 = 0;
    MS_RUN(t += 10);
    fb->bSecure1 = 3;               /* invalid Secure byte: no bypass (ABI §2) */
    MS(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0, 0, 0);
    /* manual restart: a bypassed MonIn does not prevent START (G8) */
    mon_setup(fb, 0x33, SL_OPT_MANUAL_RESTART);
    MS_INIT();
    MS_TO_RUN_MANUAL();
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);
    fb->bSecure1 = 1;
    fb->bSecure2 = 1;
    MS_SAFE(t += 10);               /* manual restart: bypass alone does not restart */
    MS_RESTART();
    h_end();
}

/* ---- manual function test (G9) ---- */

static void mon_function_test(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000;
    h_begin("MON manual function test (FUNCTEST, G9)");
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART | SL_OPT_FUNCTION_TEST);
    MS_INIT();
    MS_FUNCTEST(t += 10);           /* start state with the function test */
    fb->bRestart = 1;
    MS_FUNCTEST(t += 10);           /* Restart ignored */
    fb->bRestart = 0;
    MS_FUNCTEST(t += 10);
    fb->bMonIn1 = 0;
    MS_FUNCTEST(t += 10);           /* MonIn2 not tested yet */
    fb->bMonIn1 = 1;
    MS_FUNCTEST(t += 10);
    fb->bMonIn2 = 0;
    MS_SAFE(t += 10);               /* every active MonIn has requested: SAFE */
    fb->bMonIn2 = 1;
    MS_SAFE(t += 10);
    MS_RESTART();
    /* again after every RESET */
    MS(t - 1, SL_E_CLOCK, SL_STATE_ERROR, SL_DIAG_CLOCK, 1, 0, 0);
    t -= 1;
    mon_ack(fb, &t, SL_STATE_FUNCTEST, __FILE__, __LINE__);
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);               /* both in one cycle */
    mon_inputs(fb, 1);
    MS_SAFE(t += 10);
    MS_RESTART();
    /* with automatic restart */
    mon_setup(fb, 0x03, SL_OPT_FUNCTION_TEST);
    MS_INIT();
    MS_FUNCTEST(t += 10);
    MS_FUNCTEST(t += 10);           /* inputs TRUE but not tested: no automatic RUN */
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);
    mon_inputs(fb, 1);
    MS_RUN(t += 10);
    /* EDM check while Restart is TRUE in FUNCTEST (G2); bRun FALSE in FUNCTEST -> STOP */
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART | SL_OPT_FUNCTION_TEST | SL_OPT_EDM1);
    MS_INIT();
    MS_FUNCTEST(t += 10);
    fb->bRun = 0;
    MS_STOP(t += 10);
    fb->bRun = 1;
    MS_FUNCTEST(t += 10);
    fb->bEDM1 = 0;
    MS_FUNCTEST(t += 10);           /* no Restart: no check */
    fb->bRestart = 1;
    MS_ERROR(t += 10, SL_DIAG_EDM1);
    fb->bRestart = 0;
    fb->bEDM1 = 1;
    mon_ack(fb, &t, SL_STATE_FUNCTEST, __FILE__, __LINE__);
    h_end();
}

/* ---- EDM ---- */

static void mon_edm(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000, r;
    h_begin("MON EDM error at restart and EDM reset time");
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART | SL_OPT_EDM1 | SL_OPT_EDM2);
    fb->tDiscTime12 = 100;
    fb->tEDM2ResetTime = 100;
    MS_INIT();
    MS_SAFE(t += 10);
    fb->bEDM1 = 0;
    fb->bRestart = 1;
    MS_ERROR(t += 10, SL_DIAG_EDM1);
    fb->bRestart = 0;
    fb->bEDM1 = 1;
    MS_ACK();
    MS_RESTART();
    r = t;
    fb->bEDM1 = 0;
    MS_RUN(r + 30);
    MS_RUN(r + 99);                 /* EDM2 still TRUE */
    MS_ERROR(r + 100, SL_DIAG_EDM2);
    t = r + 100;
    fb->bEDM1 = 1;
    MS_ACK();
    MS_RESTART();
    r = t;
    fb->bEDM1 = 0;
    fb->bEDM2 = 0;
    MS_RUN(r + 99);
    MS_RUN(r + 500);                /* satisfied */
    h_end();
}

/* ---- envelope ---- */

static void mon_envelope(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000;
    h_begin("MON invalid BOOL, corruption, clock, parameter change, configuration");
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART);
    fb->tDiscTime12 = 100;
    MS_INIT();
    MS_TO_RUN_MANUAL();
    fb->bMonIn2 = 2;
    MS(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0, 0, 0);
    fb->bMonIn2 = 1;
    MS_SAFE(t += 10);
    fb->bMonIn3 = 5;                /* inactive */
    fb->bEDM1 = 5;                  /* inactive */
    MS_SAFE(t += 10);
    MS_RESTART();
    fb->bMonIn3 = 1;
    fb->bEDM1 = 1;
    memset(&fb->stPrivate, 0xFF, sizeof fb->stPrivate);
    MS(t += 10, SL_E_CORRUPT, SL_STATE_ERROR, SL_DIAG_CORRUPT, 1, 0, 0);
    MS_ERROR(t += 10, SL_DIAG_CORRUPT);
    MS_ACK();
    MS_RESTART();
    MS(t - 5, SL_E_CLOCK, SL_STATE_ERROR, SL_DIAG_CLOCK, 1, 0, 0);
    t -= 5;
    MS_ACK();
    MS_RESTART();
    fb->tMonDelOutDelay = 10;
    MS(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    fb->tMonDelOutDelay = 0;
    MS_ERROR(t += 10, SL_DIAG_PARAM_CHANGED);
    MS_ACK();
    fb->dwOptions = 0;              /* switching to automatic restart needs a STOP */
    MS(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    h_end();

    h_begin("MON invalid parameters (SL_E_CONFIG, C6, G13)");
    mon_setup(fb, 0x30, 0);         /* Secure inputs only */
    fb->bSecure1 = 1;
    fb->bSecure2 = 1;
    CHECK_INT(sl_mon_init(fb), SL_E_CONFIG);
    MS(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0, 0, 0);
    mon_setup(fb, 0x43, 0);         /* bit 6: no such input */
    CHECK_INT(sl_mon_init(fb), SL_E_CONFIG);
    mon_setup(fb, 0x13, 0);         /* Secure1 only, but a Secure discrepancy time */
    fb->tDiscTimeSecure12 = 50;
    CHECK_INT(sl_mon_init(fb), SL_E_CONFIG);
    mon_setup(fb, 0x03, 0);
    fb->tMonDelOutDelay = SL_TIME_PARAM_MAX + 1u;
    CHECK_INT(sl_mon_init(fb), SL_E_CONFIG);
    mon_setup(fb, 0x03, SL_OPT_FUNCTION_TEST | SL_OPT_MANUAL_RESTART | SL_OPT_EDM1 |
                            SL_OPT_EDM2 | SL_OPT_SAFE_INPUTS_AFTER_DISC);
    CHECK_INT(sl_mon_init(fb), SL_OK);
    mon_setup(fb, 0x03, 0);
    fb->tEDM2ResetTime = 10;        /* EDM2 inactive */
    CHECK_INT(sl_mon_init(fb), SL_E_CONFIG);
    h_end();
}

static void mon_time_wrap(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t;
    h_begin("MON DELAYOUT/ERRORDELAY across the 2^32 wrap of tNow");
    mon_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 50;
    fb->tMonDelOutDelay = 200;
    MS_INIT();
    t = 0xFFFFFF80u;
    MS_TO_RUN_AUTO();               /* RUN at 0xFFFFFF94 */
    fb->bMonIn1 = 0;
    MS_DELAYOUT(0xFFFFFFF0u);
    MS_DELAYOUT(0x0000001Fu);       /* 47 ms */
    MS_ERRORDELAY(0x00000022u, SL_DIAG_DISC1); /* 50 ms */
    MS_ERRORDELAY(0x000000B7u, SL_DIAG_DISC1); /* 199 ms */
    MS_ERROR(0x000000B8u, SL_DIAG_DISC1);      /* 200 ms */
    h_end();
}

static void mon_start_aborted(void)
{
    FB_MON inst;
    FB_MON *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("MON START left for SAFE on a request; Secure pair with Safe Inputs after Disc");
    mon_setup(fb, 0x03, SL_OPT_MANUAL_RESTART | SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    MS_INIT();
    MS_SAFE(t += 10);
    fb->bRestart = 1;
    MS_START(t += 10);
    mon_inputs(fb, 0);
    MS_SAFE(t += 10);
    mon_inputs(fb, 1);
    MS_START(t += 10);
    fb->bRestart = 0;
    fb->bMonIn2 = 0;
    MS_SAFE(t += 10);               /* falling edge while MonIn2 requests: no RUN */
    fb->bMonIn2 = 1;
    MS_SAFE(t += 10);
    MS_RESTART();
    /* Secure pair discrepancy with Safe Inputs after Disc Error: bits 2 + 10 */
    mon_setup(fb, 0x33, SL_OPT_SAFE_INPUTS_AFTER_DISC);
    fb->tDiscTimeSecure12 = 60;
    MS_INIT();
    MS_TO_RUN_AUTO();
    d = t += 10;
    fb->bSecure2 = 1;
    MS_RUN(d);
    MS_ERROR(d + 60, SL_DIAG_DISC3 | SL_DIAG_SAFE_IN_DISC3);
    t = d + 60;
    fb->bSecure2 = 0;               /* both FALSE (= both request "no bypass") together */
    MS_ERROR(t += 10, SL_DIAG_DISC3 | SL_DIAG_SAFE_IN_DISC3);
    MS_ACK();
    MS_RUN(t += 10);
    h_end();
}

void run_mon_scenarios(void)
{
    mon_sample1();
    mon_sample2();
    mon_sample3();
    mon_auto_restart();
    mon_disc();
    mon_delayout();
    mon_errordelay();
    mon_secure();
    mon_function_test();
    mon_edm();
    mon_envelope();
    mon_time_wrap();
    mon_start_aborted();
}
