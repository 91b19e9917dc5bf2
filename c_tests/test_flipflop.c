/*
 * FB_RS (manual §4.10) and FB_SR (manual §4.11) behaviour scenarios through the C ABI
 * (ABI.md §2, §4, §5, §7, §9; docs/semantics.md rows R1-R7, C1-C12).
 *
 * Every step calls sl_rs_cycle / sl_sr_cycle once and checks the status code, nState, nDiag
 * and the one output: bit 0 of the expected set (FF_OUT) = bRsOut / bSrOut.
 * Bit 0 of wInputActive/wInputNegated = Reset, bit 1 = Set (ABI §9).
 */
#include "harness.h"

/* ---- helpers (prefixed rs_ / sr_) ---- */

#define FF_OUT 1u

static void rs_step(FB_RS *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                    uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_rs_cycle(fb, t);
    h_check_fb(file, line, "RS", SL_TYPE_RS, t, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bRsOut, 0), xrc, xst, xdiag, xouts);
}

static void sr_step(FB_SR *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                    uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_sr_cycle(fb, t);
    h_check_fb(file, line, "SR", SL_TYPE_SR, t, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bSrOut, 0), xrc, xst, xdiag, xouts);
}

/* RS_S / SR_S(t, rc, state, diag, outputs): one cycle of `rs` / `sr` at time t. */
#define RS_S(t_, rc_, st_, diag_, outs_) \
    rs_step(rs, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define RS_SET(t_) RS_S((t_), SL_OK, SL_STATE_RS_SET, 0, FF_OUT)
#define RS_SAFE(t_) RS_S((t_), SL_OK, SL_STATE_SAFE, 0, 0)
#define RS_STOP(t_) RS_S((t_), SL_OK, SL_STATE_STOP, 0, 0)
#define SR_S(t_, rc_, st_, diag_, outs_) \
    sr_step(sr, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define SR_SET(t_) SR_S((t_), SL_OK, SL_STATE_SR_SET, 0, FF_OUT)
#define SR_SAFE(t_) SR_S((t_), SL_OK, SL_STATE_SAFE, 0, 0)
#define SR_STOP(t_) SR_S((t_), SL_OK, SL_STATE_STOP, 0, 0)

static void rs_setup(FB_RS *fb, uint16_t active, uint16_t negated)
{
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = active;
    fb->wInputNegated = negated;
}

static void sr_setup(FB_SR *fb, uint16_t active, uint16_t negated)
{
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = active;
    fb->wInputNegated = negated;
}

/* init: status, power-up image (C1), VAR_INPUT bytes 0..23 untouched (ABI §4). */
static void rs_init_check(FB_RS *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[24];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_rs_init(fb);
    h_check_int(rc, xrc, file, line, "sl_rs_init");
    h_check_fb(file, line, "RS(init)", SL_TYPE_RS, 0, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bRsOut, 0), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_rs_init modified a VAR_INPUT byte (ABI §4)");
}
#define RS_INIT(rc_) rs_init_check(rs, (rc_), __FILE__, __LINE__)

static void sr_init_check(FB_SR *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[24];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_sr_init(fb);
    h_check_int(rc, xrc, file, line, "sl_sr_init");
    h_check_fb(file, line, "SR(init)", SL_TYPE_SR, 0, rc, fb->nState, fb->nDiag,
               h_pack_bool(0, fb->bSrOut, 0), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_sr_init modified a VAR_INPUT byte (ABI §4)");
}
#define SR_INIT(rc_) sr_init_check(sr, (rc_), __FILE__, __LINE__)

/* ---- FB RS ---- */

static void rs_reset_dominant(void)
{
    FB_RS inst;
    FB_RS *rs = &inst;
    uint32_t t = 1000;
    h_begin("RS §4.10.1: Set/Reset levels, memory, Reset dominant (R4, R5)");
    rs_setup(rs, 0x03, 0);
    RS_INIT(SL_OK);
    RS_STOP(t += 10);
    rs->bSet = 1;
    RS_STOP(t += 10);                   /* bRun FALSE: RsOut = 0 */
    rs->bRun = 1;
    RS_SET(t += 10);                    /* leaves STOP directly into SET (R4) */
    rs->bSet = 0;
    RS_SET(t += 10);                    /* both 0: the output remains */
    RS_SET(t += 1000);
    rs->bReset = 1;
    RS_SAFE(t += 10);                   /* Reset 1, Set 0: 0 */
    rs->bSet = 1;
    RS_SAFE(t += 10);                   /* both 1: Reset dominant */
    rs->bReset = 0;
    RS_SET(t += 10);
    rs->bReset = 1;
    RS_SAFE(t += 10);                   /* from SET, both 1: 0 */
    rs->bReset = 0;
    rs->bSet = 0;
    RS_SAFE(t += 10);                   /* both 0: remains 0 */
    rs->bSet = 1;
    RS_SET(t += 10);
    rs->bRun = 0;
    RS_STOP(t += 10);
    rs->bSet = 0;
    rs->bRun = 1;
    RS_SAFE(t += 10);                   /* the memory does not survive STOP (R4) */
    h_end();

    h_begin("RS invalid BOOL: Reset reads TRUE, Set reads FALSE (R3)");
    rs->bSet = 1;
    RS_SET(t += 10);
    rs->bSet = 0;
    rs->bReset = 2;
    RS_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0); /* invalid Reset switches off */
    rs->bReset = 0;
    rs->bSet = 1;
    RS_SET(t += 10);
    rs->bSet = 2;
    RS_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_RS_SET, 0, FF_OUT); /* no switch-off either */
    rs->bReset = 1;
    RS_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    rs->bReset = 0;
    RS_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0); /* invalid Set never sets */
    rs->bSet = 0;
    RS_SAFE(t += 10);
    rs->bRun = 0xFF;                    /* invalid Run reads FALSE */
    RS_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_STOP, 0, 0);
    h_end();

    h_begin("RS corrupted private state -> ERROR bit 15, output 0 (C3, R7)");
    rs_setup(rs, 0x03, 0);
    RS_INIT(SL_OK);
    rs->bRun = 1;
    rs->bSet = 1;
    RS_SET(t += 10);
    memset(&rs->stPrivate, 0xA5, sizeof rs->stPrivate);
    RS_S(t += 10, SL_E_CORRUPT, SL_STATE_ERROR, SL_DIAG_CORRUPT, 0);
    RS_S(t += 10, SL_OK, SL_STATE_ERROR, SL_DIAG_CORRUPT, 0);
    rs->bErrAck = 1;
    RS_S(t += 10, SL_OK, SL_STATE_RESET, 0, 0);
    rs->bSet = 0;
    rs->bErrAck = 0;
    RS_SAFE(t += 10);                   /* after RESET: output FALSE, SAFE (R4) */
    h_end();
}

static void rs_negated_inactive(void)
{
    FB_RS inst;
    FB_RS *rs = &inst;
    uint32_t t = 1000;
    h_begin("RS make contact (negation bit 0) and an inactive Reset (R1, R2)");
    rs_setup(rs, 0x03, 0x01);           /* Reset negated: logical = raw XOR 1 */
    rs->bReset = 1;                     /* logical FALSE */
    RS_INIT(SL_OK);
    rs->bRun = 1;
    RS_SAFE(t += 10);
    rs->bSet = 1;
    RS_SET(t += 10);
    rs->bReset = 0;                     /* logical TRUE: reset */
    RS_SAFE(t += 10);
    rs_setup(rs, 0x02, 0);              /* only Set active */
    rs->bReset = 1;                     /* ignored: reads FALSE (R2) */
    RS_INIT(SL_OK);
    rs->bRun = 1;
    RS_SAFE(t += 10);
    rs->bSet = 1;
    RS_SET(t += 10);
    rs->bSet = 0;
    rs->bReset = 9;                     /* inactive: not read, no SL_E_INVALID_BOOL */
    RS_SET(t += 10);
    RS_SET(t += 10000);                 /* stays set until bRun FALSE */
    rs->bRun = 0;
    RS_STOP(t += 10);
    h_end();
}

/* ---- FB SR ---- */

static void sr_set_dominant(void)
{
    FB_SR inst;
    FB_SR *sr = &inst;
    uint32_t t = 1000;
    h_begin("SR §4.11.1: Set/Reset levels, memory, Set dominant (R4, R5)");
    sr_setup(sr, 0x03, 0);
    SR_INIT(SL_OK);
    SR_STOP(t += 10);
    sr->bRun = 1;
    SR_SAFE(t += 10);                   /* both 0 at start-up: SAFE (R4) */
    sr->bReset = 1;
    sr->bSet = 1;
    SR_SET(t += 10);                    /* both 1: Set dominant */
    sr->bSet = 0;
    SR_SAFE(t += 10);                   /* Reset 1, Set 0: 0 */
    sr->bReset = 0;
    SR_SAFE(t += 10);
    sr->bSet = 1;
    SR_SET(t += 10);
    sr->bSet = 0;
    SR_SET(t += 10);                    /* both 0: remains 1 */
    sr->bReset = 1;
    SR_SAFE(t += 10);
    sr->bSet = 1;
    SR_SET(t += 10);
    sr->bRun = 0;
    SR_STOP(t += 10);
    sr->bRun = 1;
    SR_SET(t += 10);                    /* inputs set it in the call leaving STOP (R4) */
    h_end();

    h_begin("SR invalid BOOL: Set dominates an invalid Reset; invalid Set never sets (R3)");
    sr->bReset = 2;                     /* Set 1: still SET */
    SR_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SR_SET, 0, FF_OUT);
    sr->bSet = 0;
    SR_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0); /* invalid Reset alone: reset */
    sr->bReset = 0;
    sr->bSet = 3;
    SR_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SAFE, 0, 0);
    sr->bSet = 1;
    SR_SET(t += 10);
    sr->bSet = 3;
    SR_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_SR_SET, 0, FF_OUT);
    sr->bSet = 0;
    SR_SET(t += 10);
    h_end();
}

static void flipflop_config_null_names(void)
{
    FB_RS rinst;
    FB_SR sinst;
    FB_RS *rs = &rinst;
    FB_SR *sr = &sinst;
    uint32_t t = 1000;
    h_begin("RS/SR configuration errors (SL_E_CONFIG, R1, C6), NULL, names");
    rs_setup(rs, 0, 0);
    RS_INIT(SL_E_CONFIG);
    rs->bRun = 1;
    rs->bSet = 1;
    RS_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    RS_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    rs_setup(rs, 0x07, 0);
    RS_INIT(SL_E_CONFIG);
    rs_setup(rs, 0x03, 0x04);
    RS_INIT(SL_E_CONFIG);
    rs_setup(rs, 0x01, 0x03);
    RS_INIT(SL_OK);
    sr_setup(sr, 0, 0);
    SR_INIT(SL_E_CONFIG);
    sr->bRun = 1;
    sr->bSet = 1;
    SR_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    sr_setup(sr, 0x04, 0);
    SR_INIT(SL_E_CONFIG);
    sr_setup(sr, 0x02, 0);
    SR_INIT(SL_OK);
    CHECK_INT(sl_rs_init(NULL), SL_E_NULL);
    CHECK_INT(sl_rs_cycle(NULL, 0), SL_E_NULL);
    CHECK_INT(sl_sr_init(NULL), SL_E_NULL);
    CHECK_INT(sl_sr_cycle(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_RS, SL_STATE_RS_SET), "SET");
    CHECK_STR(sl_state_str(SL_TYPE_RS, SL_STATE_SAFE), "SAFE");
    CHECK_STR(sl_state_str(SL_TYPE_RS, SL_STATE_STOP), "STOP");
    CHECK_STR(sl_state_str(SL_TYPE_RS, SL_STATE_RUN), "?");
    CHECK_STR(sl_state_str(SL_TYPE_SR, SL_STATE_SR_SET), "SET");
    CHECK_STR(sl_state_str(SL_TYPE_SR, SL_STATE_SAFE), "SAFE");
    CHECK_DIAG_TEXT_HAS(SL_TYPE_RS, SL_DIAG_CORRUPT, "corrupt");
    CHECK_DIAG_TEXT_HAS(SL_TYPE_SR, SL_DIAG_PARAM_CHANGED, "parameter");
    h_end();
}

void run_flipflop_scenarios(void)
{
    rs_reset_dominant();
    rs_negated_inactive();
    sr_set_dominant();
    flipflop_config_null_names();
}
