/*
 * FB_EDM behaviour scenarios (manual §4.9; ABI.md §2, §4, §5, §7, §9;
 * docs/semantics.md rows E1-E9, C1-C12).
 *
 * Every step calls sl_edm_cycle once and checks the status code, nState, nDiag and the one
 * output: bit 0 of the expected set (EDM_ERR) = bError.
 * Mon1 = the command, Mon2 = the feedback (TRUE while the device is off).
 */
#include "harness.h"

/* ---- helpers (prefixed edm_) ---- */

#define EDM_ERR 1u

static uint32_t edm_outs(const FB_EDM *fb)
{
    return h_pack_bool(0, fb->bError, 0);
}

static void edm_step(FB_EDM *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                     uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_edm_cycle(fb, t);
    h_check_fb(file, line, "EDM", SL_TYPE_EDM, t, rc, fb->nState, fb->nDiag, edm_outs(fb), xrc,
               xst, xdiag, xouts);
}

/* EDM_S(t, rc, state, diag, outputs): one cycle of `fb` at time t. */
#define EDM_S(t_, rc_, st_, diag_, outs_) \
    edm_step(fb, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define EDM_STOP(t_) EDM_S((t_), SL_OK, SL_STATE_STOP, 0, 0)
#define EDM_MONON(t_) EDM_S((t_), SL_OK, SL_STATE_EDM_MONON, 0, 0)
#define EDM_MONOFF(t_) EDM_S((t_), SL_OK, SL_STATE_EDM_MONOFF, 0, 0)
#define EDM_RESET(t_) EDM_S((t_), SL_OK, SL_STATE_RESET, 0, 0)
#define EDM_ERROR(t_, diag_) EDM_S((t_), SL_OK, SL_STATE_ERROR, (diag_), EDM_ERR)

static void edm_setup(FB_EDM *fb, uint32_t on_ms, uint32_t off_ms)
{
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0x03;
    fb->tSwitchOnTime = on_ms;
    fb->tSwitchOffTime = off_ms;
}

/* sl_edm_init: status, power-up image (C1), VAR_INPUT bytes 0..31 untouched (ABI §4). */
static void edm_init_check(FB_EDM *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[32];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_edm_init(fb);
    h_check_int(rc, xrc, file, line, "sl_edm_init");
    h_check_fb(file, line, "EDM(init)", SL_TYPE_EDM, 0, rc, fb->nState, fb->nDiag,
               edm_outs(fb), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_edm_init modified a VAR_INPUT byte (ABI §4)");
}
#define EDM_INIT(rc_) edm_init_check(fb, (rc_), __FILE__, __LINE__)

/* ERROR -> RESET -> the state Mon1 asks for (E3). */
static void edm_ack(FB_EDM *fb, uint32_t *t, uint8_t start_state, const char *file, int line)
{
    fb->bErrAck = 1;
    edm_step(fb, *t += 10, SL_OK, SL_STATE_RESET, 0, 0, file, line);
    fb->bErrAck = 0;
    edm_step(fb, *t += 10, SL_OK, start_state, 0, 0, file, line);
}
#define EDM_ACK(st_) edm_ack(fb, &t, (st_), __FILE__, __LINE__)

/* ---- scenarios ---- */

static void edm_monitoring(void)
{
    FB_EDM inst;
    FB_EDM *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("EDM §4.9.1 switch-on / switch-off monitoring: Mon2 follows in time (E2, E4)");
    edm_setup(fb, 100, 200);
    EDM_INIT(SL_OK);
    fb->bMon1 = 0;
    fb->bMon2 = 1;
    EDM_STOP(t += 10);
    fb->bRun = 1;
    EDM_MONOFF(t += 10);                /* state Mon1 asks for (E3); Mon2 already TRUE */
    EDM_MONOFF(t += 1000);
    d = t += 10;
    fb->bMon1 = 1;                      /* switch on: Mon2 must go FALSE within 100 ms */
    EDM_MONON(d);
    EDM_MONON(d + 50);
    fb->bMon2 = 0;
    EDM_MONON(d + 99);                  /* just below the limit */
    EDM_MONON(d + 500);
    fb->bMon2 = 1;                      /* satisfied: not watched until Mon1 switches (E4) */
    EDM_MONON(d + 600);
    EDM_MONON(d + 2000);
    fb->bMon2 = 0;
    EDM_MONON(d + 2010);
    d += 2020;
    fb->bMon1 = 0;                      /* switch off: Mon2 must go TRUE within 200 ms */
    EDM_MONOFF(d);
    EDM_MONOFF(d + 199);
    fb->bMon2 = 1;
    EDM_MONOFF(d + 200);                /* already TRUE in the call the time is reached (E4) */
    EDM_MONOFF(d + 1000);
    t = d + 1000;
    fb->bRun = 0;
    EDM_STOP(t += 10);
    h_end();
}

static void edm_errors(void)
{
    FB_EDM inst;
    FB_EDM *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("EDM switch-on error at the limit (bit 1) and switch-off error (bit 0) (E4, E5)");
    edm_setup(fb, 100, 200);
    EDM_INIT(SL_OK);
    fb->bMon1 = 0;
    fb->bMon2 = 1;
    fb->bRun = 1;
    EDM_MONOFF(t += 10);
    d = t += 10;
    fb->bMon1 = 1;                      /* Mon2 stays TRUE: contactor welded */
    EDM_MONON(d);
    EDM_MONON(d + 99);
    EDM_ERROR(d + 100, SL_DIAG_EDM_SWITCH_ON);
    t = d + 100;
    fb->bErrAck = 1;                    /* Mon1 TRUE, Mon2 TRUE: the error remains (E5) */
    EDM_ERROR(t += 10, SL_DIAG_EDM_SWITCH_ON);
    fb->bErrAck = 0;
    fb->bRun = 0;
    EDM_ERROR(t += 10, SL_DIAG_EDM_SWITCH_ON); /* ERROR stays with bRun FALSE (ABI §7) */
    fb->bRun = 1;
    fb->bMon2 = 0;                      /* the device dropped: no error condition left */
    EDM_ERROR(t += 10, SL_DIAG_EDM_SWITCH_ON);
    EDM_ACK(SL_STATE_EDM_MONON);        /* monitoring restarts, Mon2 already FALSE */
    EDM_MONON(t += 1000);
    d = t += 10;
    fb->bMon1 = 0;                      /* Mon2 stays FALSE */
    EDM_MONOFF(d);
    EDM_MONOFF(d + 199);
    EDM_ERROR(d + 200, SL_DIAG_EDM_SWITCH_OFF);
    t = d + 200;
    fb->bErrAck = 1;
    EDM_ERROR(t += 10, SL_DIAG_EDM_SWITCH_OFF);
    fb->bErrAck = 0;
    fb->bMon2 = 1;
    EDM_ERROR(t += 10, SL_DIAG_EDM_SWITCH_OFF);
    EDM_ACK(SL_STATE_EDM_MONOFF);
    EDM_MONOFF(t += 1000);
    /* a switch-on error acknowledged after switching Mon1 off with Mon2 TRUE (E5) */
    d = t += 10;
    fb->bMon1 = 1;
    EDM_MONON(d);
    EDM_ERROR(d + 100, SL_DIAG_EDM_SWITCH_ON);
    t = d + 100;
    fb->bMon1 = 0;
    EDM_ERROR(t += 10, SL_DIAG_EDM_SWITCH_ON);
    EDM_ACK(SL_STATE_EDM_MONOFF);
    h_end();

    h_begin("EDM start-up: the state Mon1 asks for, its monitoring starts (E3); bRun FALSE (E8)");
    edm_setup(fb, 100, 200);
    EDM_INIT(SL_OK);
    fb->bMon1 = 1;
    fb->bMon2 = 1;                      /* welded while stopped */
    EDM_STOP(t += 10);
    fb->bRun = 1;
    d = t += 10;
    EDM_MONON(d);
    EDM_MONON(d + 99);
    EDM_ERROR(d + 100, SL_DIAG_EDM_SWITCH_ON);
    t = d + 100;
    fb->bMon2 = 0;
    EDM_ACK(SL_STATE_EDM_MONON);
    d = t += 10;
    fb->bMon1 = 0;                      /* switch-off monitoring running ... */
    EDM_MONOFF(d);
    fb->bRun = 0;
    EDM_STOP(d + 100);                  /* ... ends with bRun FALSE, no error (E8) */
    EDM_STOP(d + 1000);
    h_end();

    h_begin("EDM switch-off monitoring off (tSwitchOffTime 0, E1)");
    edm_setup(fb, 100, 0);
    EDM_INIT(SL_OK);
    fb->bRun = 1;
    fb->bMon1 = 0;
    fb->bMon2 = 0;
    EDM_MONOFF(t += 10);
    EDM_MONOFF(t += 20000);
    fb->bMon1 = 1;
    EDM_MONON(t += 10);                 /* switch-on monitoring: Mon2 FALSE is in time */
    EDM_MONON(t += 100);
    fb->bMon1 = 0;
    EDM_MONOFF(t += 10);
    EDM_MONOFF(t += 20000);             /* Mon2 never TRUE: no switch-off monitoring */
    h_end();
}

static void edm_invalid_and_negated(void)
{
    FB_EDM inst;
    FB_EDM *fb = &inst;
    uint32_t t = 1000, d;
    h_begin("EDM invalid BOOL: Mon1 reads FALSE, Mon2 satisfies nothing (E7)");
    edm_setup(fb, 100, 200);
    EDM_INIT(SL_OK);
    fb->bRun = 1;
    fb->bMon1 = 1;
    fb->bMon2 = 0;
    EDM_MONON(t += 10);
    fb->bMon1 = 2;                      /* reads FALSE: switch-off monitoring */
    d = t += 10;
    EDM_S(d, SL_E_INVALID_BOOL, SL_STATE_EDM_MONOFF, 0, 0);
    EDM_S(d + 199, SL_E_INVALID_BOOL, SL_STATE_EDM_MONOFF, 0, 0);
    EDM_S(d + 200, SL_E_INVALID_BOOL, SL_STATE_ERROR, SL_DIAG_EDM_SWITCH_OFF, EDM_ERR);
    t = d + 200;
    fb->bMon1 = 0;
    fb->bMon2 = 1;
    EDM_ACK(SL_STATE_EDM_MONOFF);
    d = t += 10;
    fb->bMon1 = 1;
    fb->bMon2 = 7;                      /* invalid feedback: not FALSE */
    EDM_S(d, SL_E_INVALID_BOOL, SL_STATE_EDM_MONON, 0, 0);
    EDM_S(d + 100, SL_E_INVALID_BOOL, SL_STATE_ERROR, SL_DIAG_EDM_SWITCH_ON, EDM_ERR);
    fb->bErrAck = 1;                    /* an invalid Mon2 keeps the error (E5, E7) */
    EDM_S(d + 110, SL_E_INVALID_BOOL, SL_STATE_ERROR, SL_DIAG_EDM_SWITCH_ON, EDM_ERR);
    fb->bErrAck = 0;
    fb->bMon2 = 0;
    t = d + 110;
    EDM_ERROR(t += 10, SL_DIAG_EDM_SWITCH_ON);
    EDM_ACK(SL_STATE_EDM_MONON);
    h_end();

    h_begin("EDM Mon1 as make contact (wInputNegated bit 0)");
    edm_setup(fb, 100, 200);
    fb->wInputNegated = 0x01;
    fb->bMon1 = 1;                      /* logical FALSE */
    fb->bMon2 = 1;
    EDM_INIT(SL_OK);
    fb->bRun = 1;
    EDM_MONOFF(t += 10);
    fb->bMon1 = 0;                      /* logical TRUE */
    EDM_MONON(t += 10);
    fb->bMon2 = 0;
    EDM_MONON(t += 10);
    EDM_MONON(t += 500);
    h_end();
}

static void edm_config_null_names(void)
{
    FB_EDM inst;
    FB_EDM *fb = &inst;
    uint32_t t = 1000;
    h_begin("EDM configuration errors (SL_E_CONFIG, E1, C6), NULL, names");
    edm_setup(fb, 0, 0);                /* at least one monitoring */
    EDM_INIT(SL_E_CONFIG);
    fb->bRun = 1;
    fb->bMon1 = 1;
    EDM_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    EDM_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    edm_setup(fb, SL_EDM_TIME_MAX + 1u, 0);
    EDM_INIT(SL_E_CONFIG);
    edm_setup(fb, 100, 10001u);
    EDM_INIT(SL_E_CONFIG);
    edm_setup(fb, 100, 100);
    fb->wInputActive = 0x01;            /* Mon2 inactive */
    EDM_INIT(SL_E_CONFIG);
    edm_setup(fb, 100, 100);
    fb->wInputActive = 0x07;
    EDM_INIT(SL_E_CONFIG);
    edm_setup(fb, 100, 100);
    fb->wInputNegated = 0x04;
    EDM_INIT(SL_E_CONFIG);
    edm_setup(fb, 10000u, 10000u);
    fb->wInputNegated = 0x03;
    EDM_INIT(SL_OK);
    edm_setup(fb, 0, 1);
    EDM_INIT(SL_OK);
    CHECK_INT(sl_edm_init(NULL), SL_E_NULL);
    CHECK_INT(sl_edm_cycle(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_EDM, SL_STATE_EDM_MONOFF), "MONOFF");
    CHECK_STR(sl_state_str(SL_TYPE_EDM, SL_STATE_EDM_MONON), "MONON");
    CHECK_STR(sl_state_str(SL_TYPE_EDM, SL_STATE_ERROR), "ERROR");
    CHECK_STR(sl_state_str(SL_TYPE_EDM, SL_STATE_RUN), "?");
    CHECK_DIAG_TEXT(SL_TYPE_EDM, SL_DIAG_EDM_SWITCH_ON, "Switch-ON timer elapsed");
    CHECK_DIAG_TEXT(SL_TYPE_EDM, SL_DIAG_EDM_SWITCH_OFF, "Switch-OFF timer elapsed");
    h_end();
}

void run_edm_scenarios(void)
{
    edm_monitoring();
    edm_errors();
    edm_invalid_and_negated();
    edm_config_null_names();
}
