/*
 * FB_ESTOP behaviour scenarios (manual §4.4, ABI.md §2, §5, §7, §8, docs/semantics.md).
 *
 * Every step calls sl_estop_cycle once and checks the status code, nState, nDiag and all
 * three outputs (bError, bEStopOut, bEStopDelOut). Times are simulated milliseconds.
 * Semantics row IDs (C1..C12, G1..G15) refer to docs/semantics.md.
 */
#include "harness.h"

/* ---- helpers (names prefixed es_: all scenario files share one TU in the C++ build) ---- */

static void es_step(FB_ESTOP *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                    uint8_t xerr, uint8_t xout, uint8_t xdel, const char *file, int line)
{
    int32_t rc = sl_estop_cycle(fb, t);
    h_check_step(file, line, "ESTOP", t, rc, fb->nState, fb->nDiag, fb->bError, fb->bEStopOut,
                 fb->bEStopDelOut, xrc, xst, xdiag, xerr, xout, xdel);
}

/* Checks the instance without calling the block (e.g. right after init). */
static void es_expect(FB_ESTOP *fb, uint8_t xst, uint16_t xdiag, uint8_t xerr, uint8_t xout,
                      uint8_t xdel, const char *file, int line)
{
    h_check_step(file, line, "ESTOP(no call)", 0, SL_OK, fb->nState, fb->nDiag, fb->bError,
                 fb->bEStopOut, fb->bEStopDelOut, SL_OK, xst, xdiag, xerr, xout, xdel);
}

/* ES(t, rc, state, diag, bError, bEStopOut, bEStopDelOut): one cycle of `fb` at time t. */
#define ES(t_, rc_, st_, diag_, err_, out_, del_) \
    es_step(fb, (t_), (rc_), (st_), (diag_), (err_), (out_), (del_), __FILE__, __LINE__)
#define ES_RUN(t_) ES((t_), SL_OK, SL_STATE_RUN, 0, 0, 1, 1)
#define ES_STOP(t_) ES((t_), SL_OK, SL_STATE_STOP, 0, 0, 0, 0)
#define ES_SAFE(t_) ES((t_), SL_OK, SL_STATE_SAFE, 0, 0, 0, 0)
#define ES_START(t_) ES((t_), SL_OK, SL_STATE_START, 0, 0, 0, 0)
#define ES_RESET(t_) ES((t_), SL_OK, SL_STATE_RESET, 0, 0, 0, 0)
#define ES_DELAYOUT(t_) ES((t_), SL_OK, SL_STATE_DELAYOUT, 0, 0, 0, 1)
#define ES_ERROR(t_, diag_) ES((t_), SL_OK, SL_STATE_ERROR, (diag_), 1, 0, 0)

/* Sets every EStopIn input to v (inactive inputs are ignored by the block anyway). */
static void es_inputs(FB_ESTOP *fb, uint8_t v)
{
    fb->bEStopIn1 = v;
    fb->bEStopIn2 = v;
    fb->bEStopIn3 = v;
    fb->bEStopIn4 = v;
    fb->bEStopIn5 = v;
    fb->bEStopIn6 = v;
    fb->bEStopIn7 = v;
    fb->bEStopIn8 = v;
}

/* A zeroed (never initialised) instance with the given parameters; all inputs TRUE (break
 * contacts closed, EDM contacts of released contactors closed), bRun TRUE. */
static void es_setup(FB_ESTOP *fb, uint16_t active, uint32_t options)
{
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = active;
    fb->dwOptions = options;
    fb->bRun = 1;
    es_inputs(fb, 1);
    fb->bEDM1 = 1;
    fb->bEDM2 = 1;
}

/* sl_estop_init: SL_OK, power-up image (C1: STOP, diag 0, outputs FALSE), and no input or
 * parameter byte modified (ABI §4). */
static void es_init_ok(FB_ESTOP *fb, const char *file, int line)
{
    unsigned char before[offsetof(FB_ESTOP, bError)];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_estop_init(fb);
    h_check_int(rc, SL_OK, file, line, "sl_estop_init");
    es_expect(fb, SL_STATE_STOP, 0, 0, 0, 0, file, line);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_estop_init modified a VAR_INPUT byte (ABI §4)");
}
#define ES_INIT() es_init_ok(fb, __FILE__, __LINE__)

/* From STOP (just initialised, inputs TRUE, Restart FALSE) to RUN in three calls (G12, C12):
 * STOP -> SAFE, Restart TRUE -> START, Restart falling edge -> RUN. */
static void es_to_run(FB_ESTOP *fb, uint32_t *t, const char *file, int line)
{
    es_step(fb, *t += 10, SL_OK, SL_STATE_SAFE, 0, 0, 0, 0, file, line);
    fb->bRestart = 1;
    es_step(fb, *t += 10, SL_OK, SL_STATE_START, 0, 0, 0, 0, file, line);
    fb->bRestart = 0;
    es_step(fb, *t += 10, SL_OK, SL_STATE_RUN, 0, 0, 1, 1, file, line);
}
#define ES_TO_RUN() es_to_run(fb, &t, __FILE__, __LINE__)

/* From SAFE with the inputs TRUE: Restart pulse -> START -> RUN. */
static void es_restart(FB_ESTOP *fb, uint32_t *t, const char *file, int line)
{
    fb->bRestart = 1;
    es_step(fb, *t += 10, SL_OK, SL_STATE_START, 0, 0, 0, 0, file, line);
    fb->bRestart = 0;
    es_step(fb, *t += 10, SL_OK, SL_STATE_RUN, 0, 0, 1, 1, file, line);
}
#define ES_RESTART() es_restart(fb, &t, __FILE__, __LINE__)

/* ERROR -> (ErrAck rising) RESET -> (ErrAck falling) SAFE, the condition being gone. */
static void es_ack(FB_ESTOP *fb, uint32_t *t, const char *file, int line)
{
    fb->bErrAck = 1;
    es_step(fb, *t += 10, SL_OK, SL_STATE_RESET, 0, 0, 0, 0, file, line);
    fb->bErrAck = 0;
    es_step(fb, *t += 10, SL_OK, SL_STATE_SAFE, 0, 0, 0, 0, file, line);
}
#define ES_ACK() es_ack(fb, &t, __FILE__, __LINE__)

/* ---- manual §4.4.4 restart samples ---- */

/* Sample 1: e-stop via EStopIn, then restart via the Restart input; EDM1 active. */
static void estop_sample1(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP §4.4.4 sample 1: e-stop, release, restart (EDM1 active)");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_SAFE(t += 10);               /* start-up: STOP -> SAFE, a restart is required (G12) */
    ES_SAFE(t += 10);               /* no Restart, no START */
    fb->bRestart = 1;
    ES_START(t += 10);              /* inputs and EDM1 TRUE, Restart TRUE -> START (G1) */
    ES_START(t += 10);              /* held */
    fb->bRestart = 0;
    ES_RUN(t += 10);                /* falling edge -> outputs on */
    fb->bEDM1 = 0;
    ES_RUN(t += 10);                /* contactors picked up: EDM not checked in RUN */
    es_inputs(fb, 0);
    ES_SAFE(t += 10);               /* e-stop: both outputs off at once (delay 0) */
    fb->bEDM1 = 1;
    ES_SAFE(t += 10);               /* contactors dropped */
    es_inputs(fb, 1);
    ES_SAFE(t += 10);               /* e-stop released: still SAFE until restart */
    ES_SAFE(t += 100);
    fb->bRestart = 1;
    ES_START(t += 10);
    fb->bRestart = 0;
    ES_RUN(t += 10);
    h_end();
}

/* Sample 2: Restart rises before the EStop inputs; START only when both are TRUE. */
static void estop_sample2(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP §4.4.4 sample 2: Restart TRUE before the EStop inputs (EDM1 active)");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    fb->bEDM1 = 0;
    ES_RUN(t += 10);
    es_inputs(fb, 0);
    ES_SAFE(t += 10);
    fb->bEDM1 = 1;
    ES_SAFE(t += 10);
    fb->bRestart = 1;
    ES_SAFE(t += 10);               /* Restart TRUE, inputs still FALSE: stays SAFE */
    ES_SAFE(t += 10);               /* EDM1 TRUE: the restart EDM check passes (G2) */
    es_inputs(fb, 1);
    ES_START(t += 10);              /* both TRUE -> START (Restart level, G1) */
    ES_START(t += 10);
    fb->bRestart = 0;
    ES_RUN(t += 10);                /* enabled on the falling edge */
    h_end();
}

/* Sample 3: Restart TRUE before the e-stop: EDM checked at once -> EDM error. */
static void estop_sample3(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP §4.4.4 sample 3: Restart held through the e-stop -> EDM error");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    fb->bEDM1 = 0;
    ES_RUN(t += 10);                /* contactors energised */
    fb->bRestart = 1;
    ES_RUN(t += 10);                /* Restart in RUN changes nothing */
    es_inputs(fb, 0);
    ES_SAFE(t += 10);               /* RUN -> SAFE call switches off; check from next call (G2) */
    ES_ERROR(t += 10, SL_DIAG_EDM1); /* Restart TRUE, EDM1 FALSE in SAFE -> ERROR bit 4 */
    fb->bEDM1 = 1;
    fb->bRestart = 0;
    es_inputs(fb, 1);
    ES_ERROR(t += 10, SL_DIAG_EDM1); /* ERROR is left only through ErrAck */
    ES_ACK();
    ES_RESTART();
    h_end();
}

/* Sample 4: no EDM evaluated; Restart TRUE before the e-stop is not monitored. */
static void estop_sample4(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP §4.4.4 sample 4: no EDM, Restart TRUE before the e-stop");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    fb->bEDM1 = 0;                  /* inactive EDM inputs are ignored */
    fb->bEDM2 = 0;
    ES_INIT();
    ES_TO_RUN();
    fb->bRestart = 1;
    ES_RUN(t += 10);
    es_inputs(fb, 0);
    ES_SAFE(t += 10);
    ES_SAFE(t += 10);               /* no EDM active: no error */
    ES_SAFE(t += 200);
    es_inputs(fb, 1);
    ES_START(t += 10);              /* Restart still TRUE: START */
    fb->bRestart = 0;
    ES_RUN(t += 10);                /* enabled on the falling edge */
    h_end();
}

/* ---- discrepancy (ABI §7 Pairs, Timers; G4, G5, G14) ---- */

static void estop_disc_below_limit(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("ESTOP discrepancy just below the limit: no error");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    d = t += 10;
    fb->bEStopIn1 = 0;
    ES_SAFE(d);                     /* one channel requests: outputs off */
    ES_SAFE(d + 50);
    fb->bEStopIn2 = 0;
    ES_SAFE(d + 99);                /* channels agree after 99 ms < 100 ms */
    ES_SAFE(d + 100);
    ES_SAFE(d + 500);               /* timer stopped: never an error */
    fb->bEStopIn1 = 1;
    ES_SAFE(d + 510);               /* differ again: timer restarts at d+510 */
    fb->bEStopIn2 = 1;
    ES_SAFE(d + 609);               /* agree after 99 ms */
    ES_SAFE(d + 700);
    t = d + 700;
    ES_RESTART();
    h_end();
}

static void estop_disc_at_limit(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("ESTOP discrepancy at the limit: ERROR, acknowledgement needs agreeing channels");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    d = t += 10;
    fb->bEStopIn1 = 0;
    ES_SAFE(d);
    ES_SAFE(d + 99);
    ES_ERROR(d + 100, SL_DIAG_DISC1);   /* first cycle with tNow - t0 >= 100 */
    t = d + 100;
    fb->bErrAck = 1;
    ES_ERROR(t += 10, SL_DIAG_DISC1);   /* channels still differ: edge consumed (G4, C8) */
    fb->bEStopIn1 = 1;
    ES_ERROR(t += 10, SL_DIAG_DISC1);   /* agree now, but no new edge */
    fb->bErrAck = 0;
    ES_ERROR(t += 10, SL_DIAG_DISC1);
    ES_ACK();                           /* RESET (diag cleared, C9), then SAFE */
    ES_SAFE(t += 10);
    ES_RESTART();
    h_end();
}

static void estop_disc_safe_inputs(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    const uint16_t diag = SL_DIAG_DISC1 | SL_DIAG_SAFE_IN_DISC1;
    h_begin("ESTOP discrepancy with Safe Inputs after Disc Error (diag bits 0+8)");
    es_setup(fb, 0x03, SL_OPT_SAFE_INPUTS_AFTER_DISC);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    d = t += 10;
    fb->bEStopIn2 = 0;
    ES_SAFE(d);
    ES_ERROR(d + 100, diag);
    t = d + 100;
    fb->bEStopIn2 = 1;
    ES_ERROR(t += 10, diag);            /* channels agree (TRUE) ... */
    fb->bErrAck = 1;
    ES_ERROR(t += 10, diag);            /* ... but never both safe since the error (G4) */
    fb->bErrAck = 0;
    ES_ERROR(t += 10, diag);
    es_inputs(fb, 0);
    ES_ERROR(t += 10, diag);            /* both channels request the safe state together */
    es_inputs(fb, 1);
    ES_ERROR(t += 10, diag);
    ES_ACK();
    ES_RESTART();
    h_end();
}

static void estop_disc_pairs(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("ESTOP discrepancy: pair 4 (bit 3), single channels without a time");
    es_setup(fb, 0xFF, 0);
    fb->tDiscTime12 = 100;
    fb->tDiscTime78 = 40;           /* pairs 3/4 and 5/6: time 0 = single channels */
    ES_INIT();
    ES_TO_RUN();
    d = t += 10;
    fb->bEStopIn3 = 0;
    ES_SAFE(d);
    ES_SAFE(d + 1000);              /* EStopIn3/4 are no pair: no discrepancy error */
    fb->bEStopIn3 = 1;
    t = d + 1010;
    ES_SAFE(t);
    ES_RESTART();
    d = t += 10;
    fb->bEStopIn8 = 0;
    ES_SAFE(d);
    ES_SAFE(d + 39);
    ES_ERROR(d + 40, SL_DIAG_DISC4);
    t = d + 40;
    fb->bEStopIn8 = 1;
    ES_ERROR(t += 10, SL_DIAG_DISC4);
    ES_ACK();
    h_end();
}

/* ---- EDM (ABI §7 EDM with manual restart, EDM reset time; G2, G4, G6) ---- */

static void estop_edm_restart(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP EDM error at restart (SAFE, START, falling edge)");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_SAFE(t += 10);
    fb->bEDM1 = 0;                  /* welded contactor */
    ES_SAFE(t += 10);               /* no Restart: no check */
    fb->bRestart = 1;
    ES_ERROR(t += 10, SL_DIAG_EDM1); /* Restart TRUE while outputs safe, EDM1 FALSE */
    fb->bErrAck = 1;
    ES_ERROR(t += 10, SL_DIAG_EDM1); /* EDM1 still FALSE: condition remains (G4) */
    fb->bErrAck = 0;
    fb->bRestart = 0;
    ES_ERROR(t += 10, SL_DIAG_EDM1);
    fb->bEDM1 = 1;
    ES_ERROR(t += 10, SL_DIAG_EDM1);
    ES_ACK();
    /* EDM1 drops while in START with Restart held */
    fb->bRestart = 1;
    ES_START(t += 10);
    fb->bEDM1 = 0;
    ES_ERROR(t += 10, SL_DIAG_EDM1);
    fb->bEDM1 = 1;
    fb->bRestart = 0;
    ES_ERROR(t += 10, SL_DIAG_EDM1);
    ES_ACK();
    /* EDM1 FALSE exactly at the falling edge of Restart (§4.4.4: check at the falling edge) */
    fb->bRestart = 1;
    ES_START(t += 10);
    fb->bRestart = 0;
    fb->bEDM1 = 0;
    ES_ERROR(t += 10, SL_DIAG_EDM1);
    fb->bEDM1 = 1;
    ES_ACK();
    ES_RESTART();
    h_end();
}

static void estop_edm2_restart(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP EDM2 error at restart (bit 5), both EDMs (bits 4+5)");
    es_setup(fb, 0x03, SL_OPT_EDM1 | SL_OPT_EDM2);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_SAFE(t += 10);
    fb->bEDM2 = 0;
    fb->bRestart = 1;
    ES_ERROR(t += 10, SL_DIAG_EDM2);
    fb->bEDM2 = 1;
    fb->bRestart = 0;
    ES_ACK();
    fb->bEDM1 = 0;
    fb->bEDM2 = 0;
    fb->bRestart = 1;
    ES_ERROR(t += 10, SL_DIAG_EDM1 | SL_DIAG_EDM2);
    fb->bEDM1 = 1;
    fb->bRestart = 0;
    fb->bErrAck = 1;
    ES_ERROR(t += 10, SL_DIAG_EDM1 | SL_DIAG_EDM2); /* EDM2 still FALSE */
    fb->bErrAck = 0;
    fb->bEDM2 = 1;
    ES_ERROR(t += 10, SL_DIAG_EDM1 | SL_DIAG_EDM2);
    ES_ACK();
    ES_RESTART();
    h_end();
}

static void estop_edm_reset_time(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, r;
    h_begin("ESTOP EDM reset time (§4.4.5, G6)");
    es_setup(fb, 0x03, SL_OPT_EDM1 | SL_OPT_EDM2);
    fb->tDiscTime12 = 100;
    fb->tEDM1ResetTime = 100;
    ES_INIT();
    ES_TO_RUN();
    r = t;                          /* RUN entered at r: EDM1 timer armed */
    fb->bEDM1 = 0;
    fb->bEDM2 = 0;
    ES_RUN(r + 50);                 /* EDM1 FALSE within the time: satisfied */
    ES_RUN(r + 100);
    fb->bEDM1 = 1;
    ES_RUN(r + 150);                /* later EDM changes in RUN are not monitored (G6) */
    fb->bEDM1 = 0;
    ES_RUN(r + 400);
    t = r + 400;
    es_inputs(fb, 0);
    ES_SAFE(t += 10);
    fb->bEDM1 = 1;
    fb->bEDM2 = 1;
    ES_SAFE(t += 10);
    es_inputs(fb, 1);
    ES_SAFE(t += 10);
    ES_RESTART();
    r = t;                          /* EDM1 stays TRUE this time (contactor does not pick up) */
    fb->bEDM2 = 0;
    ES_RUN(r + 50);
    ES_RUN(r + 99);
    ES_ERROR(r + 100, SL_DIAG_EDM1);
    t = r + 100;
    fb->bEDM2 = 1;
    ES_ACK();                       /* EDM1 reads TRUE: no condition remains (G4) */
    /* EDM2 reset time (bit 5) */
    fb->tEDM2ResetTime = 60;        /* parameters may change in STOP only */
    fb->bRun = 0;
    ES_STOP(t += 10);
    fb->bRun = 1;
    ES_SAFE(t += 10);
    ES_RESTART();
    r = t;
    fb->bEDM1 = 0;
    ES_RUN(r + 10);                 /* EDM1 satisfied; EDM2 stays TRUE */
    ES_RUN(r + 59);
    ES_ERROR(r + 60, SL_DIAG_EDM2);
    t = r + 60;
    fb->bEDM1 = 1;
    ES_ACK();
    /* leaving RUN ends the reset-time check (G6) */
    ES_RESTART();
    r = t;
    es_inputs(fb, 0);
    ES_SAFE(r + 30);                /* EDM1/EDM2 still TRUE: no error in SAFE */
    ES_SAFE(r + 60);
    ES_SAFE(r + 100);
    ES_SAFE(r + 500);
    h_end();
}

/* ---- delayed output (DELAYOUT, G10) ---- */

static void estop_delayout(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("ESTOP delayed output (DELAYOUT) runs to the end of the delay");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    fb->tEStopDelOutDelay = 200;
    ES_INIT();
    ES_TO_RUN();
    d = t += 10;
    es_inputs(fb, 0);
    ES_DELAYOUT(d);                 /* EStopOut off at once, EStopDelOut still on */
    ES_DELAYOUT(d + 50);
    es_inputs(fb, 1);
    fb->bRestart = 1;
    ES_DELAYOUT(d + 100);           /* request gone, Restart TRUE: ignored in DELAYOUT */
    fb->bRestart = 0;
    ES_DELAYOUT(d + 150);           /* falling edge ignored */
    ES_DELAYOUT(d + 199);
    ES_SAFE(d + 200);               /* delay elapsed */
    ES_SAFE(d + 210);               /* no restart without a new Restart sequence */
    t = d + 210;
    ES_RESTART();
    /* discrepancy during DELAYOUT: ESTOP has no ERRORDELAY, both outputs go off (G7) */
    d = t += 10;
    fb->bEStopIn1 = 0;
    ES_DELAYOUT(d);
    ES_DELAYOUT(d + 99);
    ES_ERROR(d + 100, SL_DIAG_DISC1);
    h_end();
}

static void estop_delayout_edm2(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("ESTOP DELAYOUT with EDM2 and Restart held: no EDM check in DELAYOUT (G2)");
    es_setup(fb, 0x03, SL_OPT_EDM1 | SL_OPT_EDM2);
    fb->tDiscTime12 = 100;
    fb->tEStopDelOutDelay = 200;
    ES_INIT();
    ES_TO_RUN();
    fb->bEDM1 = 0;
    fb->bEDM2 = 0;
    ES_RUN(t += 10);
    fb->bRestart = 1;
    ES_RUN(t += 10);
    d = t += 10;
    es_inputs(fb, 0);
    ES_DELAYOUT(d);
    fb->bEDM1 = 1;                  /* K1 dropped, K2 still held by EStopDelOut */
    ES_DELAYOUT(d + 10);
    ES_DELAYOUT(d + 199);
    ES_SAFE(d + 200);               /* EStopDelOut off in this call */
    fb->bEDM2 = 1;                  /* K2 dropped before the next call */
    ES_SAFE(d + 210);               /* Restart TRUE, both EDM TRUE, inputs FALSE: SAFE */
    es_inputs(fb, 0);
    t = d + 210;
    es_inputs(fb, 1);
    ES_START(t += 10);
    fb->bRestart = 0;
    ES_RUN(t += 10);
    h_end();
}

/* ---- Run, ErrAck ---- */

static void estop_run_input(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP bRun FALSE -> STOP; start-up needs a restart; Restart held through start-up");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    fb->bRun = 0;
    ES_INIT();
    ES_STOP(t += 10);
    ES_STOP(t += 10);
    fb->bRun = 1;
    ES_SAFE(t += 10);
    ES_RESTART();
    fb->bRun = 0;
    ES_STOP(t += 10);               /* outputs off at once */
    fb->bRestart = 1;
    ES_STOP(t += 10);
    fb->bRun = 1;
    ES_SAFE(t += 10);               /* STOP -> SAFE (one transition per call, C12) */
    ES_START(t += 10);              /* Restart held through start-up (G12) */
    fb->bRestart = 0;
    ES_RUN(t += 10);
    h_end();
}

static void estop_errack_sequence(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("ESTOP ErrAck: ERROR -> RESET -> SAFE; held ErrAck does not acknowledge");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    fb->bErrAck = 1;
    ES_RUN(t += 10);                /* ErrAck without an error changes nothing */
    d = t += 10;
    fb->bEStopIn1 = 0;
    ES_SAFE(d);
    ES_ERROR(d + 100, SL_DIAG_DISC1);
    t = d + 100;
    fb->bEStopIn1 = 1;
    ES_ERROR(t += 10, SL_DIAG_DISC1); /* ErrAck was TRUE when the error occurred */
    ES_ERROR(t += 10, SL_DIAG_DISC1);
    fb->bErrAck = 0;
    ES_ERROR(t += 10, SL_DIAG_DISC1);
    fb->bErrAck = 1;
    ES_RESET(t += 10);              /* rising edge, no condition: RESET, diag cleared */
    ES_RESET(t += 10);              /* stays while ErrAck held */
    fb->bErrAck = 0;
    ES_SAFE(t += 10);               /* falling edge: start state SAFE */
    ES_RESTART();
    /* ErrAck rising in the very call that enters ERROR (C8) */
    d = t += 10;
    fb->bEStopIn1 = 0;
    ES_SAFE(d);
    fb->bErrAck = 1;
    ES_ERROR(d + 100, SL_DIAG_DISC1);
    t = d + 100;
    fb->bEStopIn1 = 1;
    ES_ERROR(t += 10, SL_DIAG_DISC1);
    fb->bErrAck = 0;
    ES_ERROR(t += 10, SL_DIAG_DISC1);
    ES_ACK();
    /* acknowledgement with bRun FALSE: ERROR persists, RESET, then STOP (C9) */
    ES_RESTART();
    d = t += 10;
    fb->bEStopIn2 = 0;
    ES_SAFE(d);
    ES_ERROR(d + 100, SL_DIAG_DISC1);
    t = d + 100;
    fb->bEStopIn2 = 1;
    fb->bRun = 0;
    ES_ERROR(t += 10, SL_DIAG_DISC1);
    ES_ERROR(t += 10, SL_DIAG_DISC1);
    fb->bErrAck = 1;
    ES_RESET(t += 10);
    fb->bErrAck = 0;
    ES_STOP(t += 10);
    fb->bRun = 1;
    ES_SAFE(t += 10);
    h_end();
}

/* ---- envelope: invalid BOOL, corruption, clock, parameters, configuration ---- */

static void estop_invalid_bool(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP invalid BOOL bytes (SL_E_INVALID_BOOL, ABI §2, C7)");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    fb->bEStopIn1 = 2;              /* safety input: reads as a safe-state request */
    ES(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0, 0, 0);
    fb->bEStopIn1 = 1;
    ES_SAFE(t += 10);
    fb->bRestart = 1;
    ES_START(t += 10);
    fb->bRestart = 2;               /* 1 -> invalid: reads FALSE, no falling edge: abort */
    ES(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0, 0, 0);
    fb->bRestart = 0;
    ES_SAFE(t += 10);
    ES_RESTART();
    fb->bEStopIn5 = 9;              /* inactive input: ignored, also for the status */
    fb->bEDM2 = 200;                /* inactive EDM2: ignored */
    ES_RUN(t += 10);
    fb->bRun = 3;                   /* Run reads FALSE */
    ES(t += 10, SL_E_INVALID_BOOL, SL_STATE_STOP, 0, 0, 0, 0);
    fb->bRun = 1;
    ES_SAFE(t += 10);
    /* invalid EDM byte: not TRUE, so the restart EDM check fails */
    fb->bEDM1 = 2;
    fb->bRestart = 1;
    ES(t += 10, SL_E_INVALID_BOOL, SL_STATE_ERROR, SL_DIAG_EDM1, 1, 0, 0);
    fb->bRestart = 0;
    fb->bErrAck = 1;                /* invalid EDM keeps the EDM error */
    ES(t += 10, SL_E_INVALID_BOOL, SL_STATE_ERROR, SL_DIAG_EDM1, 1, 0, 0);
    fb->bErrAck = 0;
    fb->bEDM1 = 1;
    ES_ERROR(t += 10, SL_DIAG_EDM1);
    fb->bErrAck = 0xFF;             /* invalid ErrAck reads FALSE */
    ES(t += 10, SL_E_INVALID_BOOL, SL_STATE_ERROR, SL_DIAG_EDM1, 1, 0, 0);
    fb->bErrAck = 0;
    ES_ERROR(t += 10, SL_DIAG_EDM1);
    ES_ACK();
    ES_RESTART();
    h_end();
}

static void estop_invalid_bool_negated(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP invalid BOOL on a negated (make contact) input");
    es_setup(fb, 0x01, 0);
    fb->wInputNegated = 0x01;
    fb->bEStopIn1 = 0;              /* make contact open: logical TRUE */
    ES_INIT();
    ES_TO_RUN();
    fb->bEStopIn1 = 1;              /* make contact closed: safe state requested */
    ES_SAFE(t += 10);
    fb->bEStopIn1 = 0;
    ES_SAFE(t += 10);
    ES_RESTART();
    fb->bEStopIn1 = 0x80;           /* invalid: logical FALSE whatever its negation bit */
    ES(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0, 0, 0);
    fb->bEStopIn1 = 0;
    ES_SAFE(t += 10);
    h_end();
}

static void estop_corrupt(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP garbage private state (SL_E_CORRUPT, C3)");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    memset(&fb->stPrivate, 0xA5, sizeof fb->stPrivate);
    ES(t += 10, SL_E_CORRUPT, SL_STATE_ERROR, SL_DIAG_CORRUPT, 1, 0, 0);
    ES_ERROR(t += 10, SL_DIAG_CORRUPT); /* rebuilt: consistent again, stays in ERROR */
    ES_ACK();                       /* corruption does not remain (G4) */
    ES_RESTART();
    /* forged state: SAFE -> "RUN" in the private copy must not enable the outputs */
    es_inputs(fb, 0);
    ES_SAFE(t += 10);
    fb->stPrivate.stHeader.nState = SL_STATE_RUN;
    ES(t += 10, SL_E_CORRUPT, SL_STATE_ERROR, SL_DIAG_CORRUPT, 1, 0, 0);
    es_inputs(fb, 1);
    ES_ERROR(t += 10, SL_DIAG_CORRUPT);
    ES_ACK();
    ES_RESTART();
    /* latched parameter copy altered (CRC no longer matches) */
    fb->stPrivate.adwTime[0] ^= 0x0001u;
    ES(t += 10, SL_E_CORRUPT, SL_STATE_ERROR, SL_DIAG_CORRUPT, 1, 0, 0);
    ES_ACK();
    /* an all-zero private area is a never-initialised instance: initialised, then the
     * cycle runs normally (C2): STOP -> SAFE in the same call */
    ES_RESTART();
    memset(&fb->stPrivate, 0, sizeof fb->stPrivate);
    ES_SAFE(t += 10);
    ES_RESTART();
    /* garbage before the first call of a never-initialised instance */
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    memset(&fb->stPrivate, 0x5A, sizeof fb->stPrivate);
    ES(t += 10, SL_E_CORRUPT, SL_STATE_ERROR, SL_DIAG_CORRUPT, 1, 0, 0);
    h_end();
}

static void estop_clock(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP clock going backwards (SL_E_CLOCK, C4)");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_SAFE(0xDEADBEEFu);           /* first call after init: any time is fine */
    t = 0xDEADBEEFu;
    ES_RESTART();
    ES_RUN(t);                      /* same time again: difference 0 is not backwards */
    ES(t - 1, SL_E_CLOCK, SL_STATE_ERROR, SL_DIAG_CLOCK, 1, 0, 0);
    t -= 1;                         /* clock resynchronised to t-1 */
    ES_ERROR(t += 10, SL_DIAG_CLOCK);
    ES_ACK();                       /* a clock error does not remain */
    ES_RESTART();
    /* in STOP as well; a forward jump of 2^31-1 is fine, of 2^31 is "backwards" */
    fb->bRun = 0;
    ES_STOP(t += 10);
    t += 0x7FFFFFFFu;
    ES_STOP(t);
    t += 0x80000000u;
    ES(t, SL_E_CLOCK, SL_STATE_ERROR, SL_DIAG_CLOCK, 1, 0, 0);
    ES_ERROR(t += 10, SL_DIAG_CLOCK); /* bRun FALSE: ERROR persists (C9) */
    fb->bErrAck = 1;
    ES_RESET(t += 10);
    fb->bErrAck = 0;
    ES_STOP(t += 10);               /* RESET -> STOP with bRun FALSE */
    fb->bRun = 1;
    ES_SAFE(t += 10);
    h_end();
}

static void estop_param_changed(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("ESTOP parameter change while running (SL_E_PARAM_CHANGED, C5)");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_TO_RUN();
    fb->tEStopDelOutDelay = 50;
    ES(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    ES(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    fb->bErrAck = 1;                /* blocked while the mismatch remains and bRun TRUE */
    ES(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    fb->bErrAck = 0;
    ES(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    fb->tEStopDelOutDelay = 0;      /* restoring the old value clears the condition */
    ES_ERROR(t += 10, SL_DIAG_PARAM_CHANGED);
    ES_ACK();
    /* a change in SAFE (not STOP) is a fault as well */
    fb->wInputNegated = 0x0003;
    ES(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    fb->wInputNegated = 0;
    ES_ERROR(t += 10, SL_DIAG_PARAM_CHANGED);
    ES_ACK();
    fb->dwOptions = SL_OPT_EDM1;
    ES(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    /* adopted via bRun FALSE: still reported (not STOP, ABI 5/7), acknowledged, latched
     * at STOP -> run (C5) */
    fb->bRun = 0;
    ES(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 1, 0, 0);
    fb->bErrAck = 1;
    ES_RESET(t += 10);
    fb->bErrAck = 0;
    ES_STOP(t += 10);
    fb->tDiscTime12 = 50;           /* change in STOP: fine */
    ES_STOP(t += 10);
    fb->bRun = 1;
    ES_SAFE(t += 10);               /* latched: EDM1 active now, discrepancy time 50 */
    ES_RESTART();
    d = t += 10;
    fb->bEStopIn1 = 0;
    ES_SAFE(d);
    ES_SAFE(d + 49);
    ES_ERROR(d + 50, SL_DIAG_DISC1);
    h_end();
}

static void estop_config(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP invalid parameters (SL_E_CONFIG, C6, C10, G11, G13)");
    /* no active input */
    es_setup(fb, 0, 0);
    CHECK_INT(sl_estop_init(fb), SL_E_CONFIG);
    es_expect(fb, SL_STATE_STOP, 0, 0, 0, 0, __FILE__, __LINE__);
    ES(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0, 0, 0);
    fb->bRun = 0;
    ES(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0, 0, 0);
    fb->bRun = 1;
    fb->wInputActive = 0x01;        /* fixed: latched at the next STOP -> run */
    ES_SAFE(t += 10);
    /* time above SL_TIME_PARAM_MAX */
    es_setup(fb, 0x03, 0);
    fb->tEStopDelOutDelay = SL_TIME_PARAM_MAX + 1u;
    CHECK_INT(sl_estop_init(fb), SL_E_CONFIG);
    fb->tEStopDelOutDelay = SL_TIME_PARAM_MAX;
    CHECK_INT(sl_estop_init(fb), SL_OK);
    /* discrepancy time for a pair with one input inactive */
    es_setup(fb, 0x01, 0);
    fb->tDiscTime12 = 100;
    CHECK_INT(sl_estop_init(fb), SL_E_CONFIG);
    /* input bits the block does not have, unknown options */
    es_setup(fb, 0x0103, 0);
    CHECK_INT(sl_estop_init(fb), SL_E_CONFIG);
    es_setup(fb, 0x03, 1u << 7);
    CHECK_INT(sl_estop_init(fb), SL_E_CONFIG);
    /* function test is MON only; manual restart is accepted and changes nothing */
    es_setup(fb, 0x03, SL_OPT_FUNCTION_TEST);
    CHECK_INT(sl_estop_init(fb), SL_E_CONFIG);
    es_setup(fb, 0x03, SL_OPT_MANUAL_RESTART);
    CHECK_INT(sl_estop_init(fb), SL_OK);
    /* EDM reset time for an inactive EDM */
    es_setup(fb, 0x03, 0);
    fb->tEDM1ResetTime = 100;
    CHECK_INT(sl_estop_init(fb), SL_E_CONFIG);
    /* negation bits of inactive inputs are ignored */
    es_setup(fb, 0x03, 0);
    fb->wInputNegated = 0x00F0;
    CHECK_INT(sl_estop_init(fb), SL_OK);
    h_end();
}

static void estop_time_wrap(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t;
    h_begin("ESTOP timers across the 2^32 wrap of tNow");
    /* output delay */
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    fb->tEStopDelOutDelay = 100;
    ES_INIT();
    t = 0xFFFFFFA0u;
    ES_TO_RUN();                    /* RUN at 0xFFFFFFBE */
    es_inputs(fb, 0);
    ES_DELAYOUT(0xFFFFFFF8u);
    ES_DELAYOUT(0x00000010u);       /* 24 ms elapsed */
    ES_DELAYOUT(91u);               /* 99 ms */
    ES_SAFE(92u);                   /* 100 ms */
    /* discrepancy time */
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    ES_INIT();
    t = 0xFFFFFF00u;
    ES_TO_RUN();
    fb->bEStopIn1 = 0;
    ES_SAFE(0xFFFFFFCEu);
    ES_SAFE(10u);
    ES_SAFE(49u);                   /* 99 ms */
    ES_ERROR(50u, SL_DIAG_DISC1);   /* 100 ms */
    /* EDM reset time */
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    fb->tEDM1ResetTime = 100;
    ES_INIT();
    t = 0xFFFFFFD8u;
    ES_TO_RUN();                    /* RUN at 0xFFFFFFF6 */
    ES_RUN(5u);
    ES_RUN(89u);                    /* 99 ms */
    ES_ERROR(90u, SL_DIAG_EDM1);    /* 100 ms */
    h_end();
}


/* ---- more states, start-up, negation ---- */

static void estop_run_false_in_states(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("ESTOP bRun FALSE in DELAYOUT, START and RESET (ABI §7 Run, C9)");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    fb->tEStopDelOutDelay = 500;
    ES_INIT();
    ES_TO_RUN();
    d = t += 10;
    es_inputs(fb, 0);
    ES_DELAYOUT(d);
    fb->bRun = 0;
    ES_STOP(d + 10);                /* all outputs FALSE at once, EStopDelOut included */
    es_inputs(fb, 1);
    t = d + 10;
    fb->bRun = 1;
    ES_SAFE(t += 10);
    fb->bRestart = 1;
    ES_START(t += 10);
    fb->bRun = 0;
    ES_STOP(t += 10);
    fb->bRestart = 0;
    fb->bRun = 1;
    ES_SAFE(t += 10);
    ES_RESTART();
    /* RESET with bRun FALSE persists; the falling ErrAck edge then leads to STOP */
    d = t += 10;
    fb->bEStopIn1 = 0;
    ES_DELAYOUT(d);                 /* tEStopDelOutDelay = 500 */
    ES_ERROR(d + 100, SL_DIAG_DISC1);
    t = d + 100;
    fb->bEStopIn1 = 1;
    fb->bErrAck = 1;
    ES_RESET(t += 10);
    fb->bRun = 0;
    ES_RESET(t += 10);
    ES_RESET(t += 10);
    fb->bErrAck = 2;                /* invalid ErrAck: reads FALSE, but no falling edge (C7) */
    ES(t += 10, SL_E_INVALID_BOOL, SL_STATE_RESET, 0, 0, 0, 0);
    fb->bErrAck = 1;
    ES_RESET(t += 10);
    fb->bErrAck = 0;
    ES_STOP(t += 10);
    /* a clock error in ERROR keeps ERROR and adds diag bit 14 */
    fb->bRun = 1;
    ES_SAFE(t += 10);
    ES_RESTART();
    d = t += 10;
    fb->bEStopIn2 = 0;
    ES_DELAYOUT(d);
    ES_ERROR(d + 100, SL_DIAG_DISC1);
    t = d + 100;
    {
        int32_t rc = sl_estop_cycle(fb, t - 20);
        CHECK_INT(rc, SL_E_CLOCK);
        CHECK_INT(fb->nState, SL_STATE_ERROR);
        CHECK_INT(fb->bError, 1);
        CHECK_INT(fb->bEStopOut, 0);
        CHECK_INT(fb->bEStopDelOut, 0);
        CHECK_INT(fb->nDiag & SL_DIAG_CLOCK, SL_DIAG_CLOCK);
    }
    h_end();
}

static void estop_disc_from_scratch(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000, s;
    h_begin("ESTOP discrepancy not monitored in STOP, starts from scratch at STOP->run (G14)");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    fb->bRun = 0;
    ES_INIT();
    ES_STOP(t += 10);
    fb->bEStopIn1 = 0;
    ES_STOP(t += 10);
    ES_STOP(t += 1000);             /* channels differ for a second in STOP: no error */
    s = t += 10;
    fb->bRun = 1;
    ES_SAFE(s);                     /* STOP -> SAFE: the second in STOP does not count */
    ES_SAFE(s + 1);
    ES_SAFE(s + 99);
    /* G14: the call that leaves STOP only enters SAFE; monitoring starts with the next
     * call (s+1), so the 100 ms are reached at s+101. */
    ES_SAFE(s + 100);
    ES_ERROR(s + 101, SL_DIAG_DISC1);
    h_end();
}

static void estop_antivalent_pair(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP pair of a break and a make contact (negation per input, ABI §7 Signals)");
    es_setup(fb, 0x03, 0);
    fb->tDiscTime12 = 100;
    fb->wInputNegated = 0x02;       /* EStopIn2 is a make contact */
    fb->bEStopIn1 = 1;
    fb->bEStopIn2 = 0;              /* both logically TRUE */
    ES_INIT();
    ES_TO_RUN();
    fb->bEStopIn1 = 0;
    fb->bEStopIn2 = 1;              /* both request the safe state: no discrepancy */
    ES_SAFE(t += 10);
    ES_SAFE(t += 500);
    fb->bEStopIn1 = 1;
    fb->bEStopIn2 = 0;
    ES_SAFE(t += 10);
    ES_RESTART();
    fb->bEStopIn2 = 1;              /* only the make contact: logical FALSE vs TRUE */
    ES_SAFE(t += 10);
    ES_ERROR(t += 100, SL_DIAG_DISC1);
    h_end();
}

static void estop_init_and_first_cycle(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP cycle without init (C2) and init while running (power-up)");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    ES_SAFE(t += 10);               /* never initialised: initialised, then STOP -> SAFE */
    ES_RESTART();
    ES_INIT();                      /* back to the power-up image: STOP, outputs off */
    ES_SAFE(t += 10);               /* restart required again */
    ES_RESTART();
    es_setup(fb, 0, 0);             /* never initialised with invalid parameters */
    ES(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0, 0, 0);
    h_end();
}

static void estop_start_aborted(void)
{
    FB_ESTOP inst;
    FB_ESTOP *fb = &inst;
    uint32_t t = 1000;
    h_begin("ESTOP START left for SAFE when an input requests the safe state (§4.4.4, G1)");
    es_setup(fb, 0x03, SL_OPT_EDM1);
    fb->tDiscTime12 = 100;
    ES_INIT();
    ES_SAFE(t += 10);
    fb->bRestart = 1;
    ES_START(t += 10);
    es_inputs(fb, 0);
    ES_SAFE(t += 10);               /* e-stop while Restart is held: back to SAFE */
    es_inputs(fb, 1);
    ES_START(t += 10);              /* Restart still TRUE, request gone: START again */
    fb->bRestart = 0;
    es_inputs(fb, 0);
    ES_SAFE(t += 10);               /* falling edge while an input requests: no RUN */
    es_inputs(fb, 1);
    ES_SAFE(t += 10);               /* the falling edge is gone: stays SAFE */
    ES_RESTART();
    /* parameter change together with bRun FALSE: tolerated, adopted at STOP -> run (C5) */
    fb->bRun = 0;
    fb->tEStopDelOutDelay = 40;
    ES_STOP(t += 10);
    fb->bRun = 1;
    ES_SAFE(t += 10);
    ES_RESTART();
    es_inputs(fb, 0);
    ES_DELAYOUT(t += 10);           /* the new delay is in effect */
    ES_SAFE(t += 40);
    /* an invalid value set in STOP: SL_E_CONFIG at the STOP -> run latch, safe outputs */
    fb->bRun = 0;
    ES_STOP(t += 10);
    fb->tDiscTime12 = SL_TIME_PARAM_MAX + 1u;
    ES_STOP(t += 10);               /* not latched yet: the latched parameters are valid */
    fb->bRun = 1;
    ES(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0, 0, 0);
    ES(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0, 0, 0);
    fb->tDiscTime12 = 100;
    es_inputs(fb, 1);
    ES_SAFE(t += 10);
    ES_RESTART();
    h_end();
}

void run_estop_scenarios(void)
{
    estop_sample1();
    estop_sample2();
    estop_sample3();
    estop_sample4();
    estop_disc_below_limit();
    estop_disc_at_limit();
    estop_disc_safe_inputs();
    estop_disc_pairs();
    estop_edm_restart();
    estop_edm2_restart();
    estop_edm_reset_time();
    estop_delayout();
    estop_delayout_edm2();
    estop_run_input();
    estop_errack_sequence();
    estop_invalid_bool();
    estop_invalid_bool_negated();
    estop_corrupt();
    estop_clock();
    estop_param_changed();
    estop_config();
    estop_time_wrap();
    estop_run_false_in_states();
    estop_disc_from_scratch();
    estop_antivalent_pair();
    estop_init_and_first_cycle();
    estop_start_aborted();
}
