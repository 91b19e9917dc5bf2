/*
 * FB_XOR (manual §4.34) and FB_DECOUPLE (manual §4.6) behaviour scenarios through the C ABI
 * (ABI.md §2, §4, §5, §7, §9; docs/semantics.md rows X1-X5, D1-D5, C1-C12).
 *
 * Every step calls sl_<name>_cycle once and checks the status code, nState, nDiag and all
 * eight outputs (bit n-1 of the expected set = XorOutn / DecOutn). Times are simulated ms.
 */
#include "harness.h"

/* ---- helpers (prefixed xor_ / dec_: all scenario files share one TU in the C++ build) ---- */

#define LOGIC_OUT(n) (1u << ((n) - 1))

static uint32_t xor_outs(const FB_XOR *fb)
{
    uint32_t o = 0;
    o = h_pack_bool(o, fb->bXorOut1, 0);
    o = h_pack_bool(o, fb->bXorOut2, 1);
    o = h_pack_bool(o, fb->bXorOut3, 2);
    o = h_pack_bool(o, fb->bXorOut4, 3);
    o = h_pack_bool(o, fb->bXorOut5, 4);
    o = h_pack_bool(o, fb->bXorOut6, 5);
    o = h_pack_bool(o, fb->bXorOut7, 6);
    o = h_pack_bool(o, fb->bXorOut8, 7);
    return o;
}

static void xor_step(FB_XOR *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                     uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_xor_cycle(fb, t);
    h_check_fb(file, line, "XOR", SL_TYPE_XOR, t, rc, fb->nState, fb->nDiag, xor_outs(fb), xrc,
               xst, xdiag, xouts);
}

/* XOR_S(t, rc, state, diag, outputs): one cycle of `fb` at time t. */
#define XOR_S(t_, rc_, st_, diag_, outs_) \
    xor_step(fb, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define XOR_RUN(t_, outs_) XOR_S((t_), SL_OK, SL_STATE_RUN, 0, (outs_))
#define XOR_STOP(t_) XOR_S((t_), SL_OK, SL_STATE_STOP, 0, 0)

/* Inputs of XOR function y (1..8). */
static void xor_set(FB_XOR *fb, int y, uint8_t in1, uint8_t in2)
{
    switch (y) {
    case 1: fb->bXor1In1 = in1; fb->bXor2In1 = in2; break;
    case 2: fb->bXor1In2 = in1; fb->bXor2In2 = in2; break;
    case 3: fb->bXor1In3 = in1; fb->bXor2In3 = in2; break;
    case 4: fb->bXor1In4 = in1; fb->bXor2In4 = in2; break;
    case 5: fb->bXor1In5 = in1; fb->bXor2In5 = in2; break;
    case 6: fb->bXor1In6 = in1; fb->bXor2In6 = in2; break;
    case 7: fb->bXor1In7 = in1; fb->bXor2In7 = in2; break;
    default: fb->bXor1In8 = in1; fb->bXor2In8 = in2; break;
    }
}

/* sl_xor_init: status, power-up image (C1: STOP, diag 0, outputs FALSE), inputs untouched
 * (ABI §4: every byte before the output base 24 is VAR_INPUT). */
static void xor_init_check(FB_XOR *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[24];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_xor_init(fb);
    h_check_int(rc, xrc, file, line, "sl_xor_init");
    h_check_fb(file, line, "XOR(init)", SL_TYPE_XOR, 0, rc, fb->nState, fb->nDiag,
               xor_outs(fb), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_xor_init modified a VAR_INPUT byte (ABI §4)");
}
#define XOR_INIT(rc_) xor_init_check(fb, (rc_), __FILE__, __LINE__)

static uint32_t dec_outs(const FB_DECOUPLE *fb)
{
    uint32_t o = 0;
    o = h_pack_bool(o, fb->bDecOut1, 0);
    o = h_pack_bool(o, fb->bDecOut2, 1);
    o = h_pack_bool(o, fb->bDecOut3, 2);
    o = h_pack_bool(o, fb->bDecOut4, 3);
    o = h_pack_bool(o, fb->bDecOut5, 4);
    o = h_pack_bool(o, fb->bDecOut6, 5);
    o = h_pack_bool(o, fb->bDecOut7, 6);
    o = h_pack_bool(o, fb->bDecOut8, 7);
    return o;
}

static void dec_step(FB_DECOUPLE *fb, uint32_t t, int32_t xrc, uint8_t xst, uint16_t xdiag,
                     uint32_t xouts, const char *file, int line)
{
    int32_t rc = sl_decouple_cycle(fb, t);
    h_check_fb(file, line, "DECOUPLE", SL_TYPE_DECOUPLE, t, rc, fb->nState, fb->nDiag,
               dec_outs(fb), xrc, xst, xdiag, xouts);
}

#define DEC_S(t_, rc_, st_, diag_, outs_) \
    dec_step(fb, (t_), (rc_), (st_), (diag_), (outs_), __FILE__, __LINE__)
#define DEC_RUN(t_, outs_) DEC_S((t_), SL_OK, SL_STATE_RUN, 0, (outs_))
#define DEC_STOP(t_) DEC_S((t_), SL_OK, SL_STATE_STOP, 0, 0)

static void dec_init_check(FB_DECOUPLE *fb, int32_t xrc, const char *file, int line)
{
    unsigned char before[24];
    int32_t rc;
    memcpy(before, fb, sizeof before);
    rc = sl_decouple_init(fb);
    h_check_int(rc, xrc, file, line, "sl_decouple_init");
    h_check_fb(file, line, "DECOUPLE(init)", SL_TYPE_DECOUPLE, 0, rc, fb->nState, fb->nDiag,
               dec_outs(fb), xrc, SL_STATE_STOP, 0, 0);
    h_check(memcmp(before, fb, sizeof before) == 0, file, line,
            "sl_decouple_init modified a VAR_INPUT byte (ABI §4)");
}
#define DEC_INIT(rc_) dec_init_check(fb, (rc_), __FILE__, __LINE__)

/* ---- FB XOR ---- */

static void xor_function(void)
{
    FB_XOR inst;
    FB_XOR *fb = &inst;
    uint32_t t = 1000;
    h_begin("XOR §4.34.2: XorOutY = (Xor1InY XOR Xor2InY) AND active(Y), RUN/STOP (X1, X4)");
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0x05; /* XOR1 and XOR3 */
    XOR_INIT(SL_OK);
    XOR_STOP(t += 10);                       /* bRun FALSE: STOP, XorOutY = 0 */
    xor_set(fb, 1, 1, 0);
    xor_set(fb, 2, 1, 0);                    /* XOR2 inactive: its output stays FALSE */
    xor_set(fb, 3, 1, 1);
    XOR_STOP(t += 10);                       /* inputs alone do nothing in STOP */
    fb->bRun = 1;
    XOR_RUN(t += 10, LOGIC_OUT(1));          /* STOP -> RUN in the call bRun rises (X4) */
    xor_set(fb, 1, 1, 1);
    xor_set(fb, 3, 0, 1);
    XOR_RUN(t += 10, LOGIC_OUT(3));          /* same call (X4) */
    xor_set(fb, 1, 0, 1);
    XOR_RUN(t += 10, LOGIC_OUT(1) | LOGIC_OUT(3));
    xor_set(fb, 1, 0, 0);
    xor_set(fb, 3, 0, 0);
    XOR_RUN(t += 10, 0);                     /* RUN although every output is FALSE (X4) */
    xor_set(fb, 2, 7, 9);                    /* inactive function: bytes not read (X1) */
    XOR_RUN(t += 10, 0);
    fb->bRun = 0;
    XOR_STOP(t += 10);
    h_end();

    h_begin("XOR all eight functions, every input combination in one call");
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0xFF;
    XOR_INIT(SL_OK);
    fb->bRun = 1;
    xor_set(fb, 1, 0, 0);
    xor_set(fb, 2, 0, 1);
    xor_set(fb, 3, 1, 0);
    xor_set(fb, 4, 1, 1);
    xor_set(fb, 5, 1, 0);
    xor_set(fb, 6, 0, 0);
    xor_set(fb, 7, 0, 1);
    xor_set(fb, 8, 1, 1);
    XOR_RUN(t += 10, LOGIC_OUT(2) | LOGIC_OUT(3) | LOGIC_OUT(5) | LOGIC_OUT(7));
    xor_set(fb, 1, 1, 0);
    xor_set(fb, 2, 1, 1);
    xor_set(fb, 3, 0, 0);
    xor_set(fb, 4, 0, 1);
    xor_set(fb, 5, 0, 0);
    xor_set(fb, 6, 1, 1);
    xor_set(fb, 7, 1, 0);
    xor_set(fb, 8, 0, 0);
    XOR_RUN(t += 10, LOGIC_OUT(1) | LOGIC_OUT(4) | LOGIC_OUT(7));
    h_end();
}

static void xor_invalid_and_envelope(void)
{
    FB_XOR inst;
    FB_XOR *fb = &inst;
    uint32_t t = 1000;
    h_begin("XOR invalid BOOL: that function FALSE, the others computed (X3); invalid bRun");
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0x05;
    XOR_INIT(SL_OK);
    fb->bRun = 1;
    xor_set(fb, 1, 1, 0);
    xor_set(fb, 3, 0, 1);
    XOR_RUN(t += 10, LOGIC_OUT(1) | LOGIC_OUT(3));
    xor_set(fb, 1, 2, 0);                    /* invalid Xor1In1 */
    XOR_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_RUN, 0, LOGIC_OUT(3));
    xor_set(fb, 1, 2, 1);                    /* whatever the other input */
    XOR_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_RUN, 0, LOGIC_OUT(3));
    xor_set(fb, 1, 0, 0xFF);
    XOR_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_RUN, 0, LOGIC_OUT(3));
    xor_set(fb, 1, 0, 1);
    XOR_RUN(t += 10, LOGIC_OUT(1) | LOGIC_OUT(3));
    fb->bRun = 2;                            /* invalid Run reads FALSE (ABI §2) */
    XOR_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_STOP, 0, 0);
    fb->bRun = 1;
    XOR_RUN(t += 10, LOGIC_OUT(1) | LOGIC_OUT(3));
    h_end();

    h_begin("XOR library error through the envelope: clock backwards, ErrAck (ABI §5, C4)");
    XOR_S(t - 10, SL_E_CLOCK, SL_STATE_ERROR, SL_DIAG_CLOCK, 0);
    t -= 10;
    XOR_S(t += 10, SL_OK, SL_STATE_ERROR, SL_DIAG_CLOCK, 0);
    fb->bErrAck = 1;
    XOR_S(t += 10, SL_OK, SL_STATE_RESET, 0, 0);
    fb->bErrAck = 0;
    XOR_RUN(t += 10, LOGIC_OUT(1) | LOGIC_OUT(3));
    h_end();
}

static void xor_config_null_names(void)
{
    FB_XOR inst;
    FB_XOR *fb = &inst;
    uint32_t t = 1000;
    h_begin("XOR configuration errors (SL_E_CONFIG, X1, C6), NULL, names");
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0;                    /* no active function */
    XOR_INIT(SL_E_CONFIG);
    fb->bRun = 1;
    xor_set(fb, 1, 1, 0);
    XOR_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    XOR_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    fb->bRun = 0;
    XOR_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0x0101;               /* bit 8: no XOR9 */
    XOR_INIT(SL_E_CONFIG);
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0x80;
    XOR_INIT(SL_OK);
    CHECK_INT(sl_xor_init(NULL), SL_E_NULL);
    CHECK_INT(sl_xor_cycle(NULL, 0), SL_E_NULL);
    CHECK_INT(sl_xor_cycle(NULL, 0xFFFFFFFFu), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_XOR, SL_STATE_RUN), "RUN");
    CHECK_STR(sl_state_str(SL_TYPE_XOR, SL_STATE_STOP), "STOP");
    CHECK_STR(sl_state_str(SL_TYPE_XOR, SL_STATE_SAFE), "?"); /* XOR has no SAFE (X4) */
    CHECK_DIAG_TEXT_HAS(SL_TYPE_XOR, SL_DIAG_CLOCK, "clock");
    h_end();
}

/* ---- FB DECOUPLE ---- */

static void dec_loop_through(void)
{
    FB_DECOUPLE inst;
    FB_DECOUPLE *fb = &inst;
    uint32_t t = 1000;
    h_begin("DECOUPLE §4.6: RUN DcOutX = DcInX for used channels, STOP DcOutX = 0 (D1, D2)");
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0x83; /* channels 1, 2, 8 */
    DEC_INIT(SL_OK);
    DEC_STOP(t += 10);
    fb->bDecIn1 = 1;
    fb->bDecIn3 = 1;         /* unused channel: output stays FALSE */
    fb->bDecIn8 = 1;
    DEC_STOP(t += 10);
    fb->bRun = 1;
    DEC_RUN(t += 10, LOGIC_OUT(1) | LOGIC_OUT(8)); /* RUN in the call bRun rises */
    fb->bDecIn1 = 0;
    fb->bDecIn2 = 1;
    DEC_RUN(t += 10, LOGIC_OUT(2) | LOGIC_OUT(8));
    fb->bDecIn8 = 0;
    DEC_RUN(t += 10, LOGIC_OUT(2));
    fb->bDecIn8 = 1;
    fb->bDecIn4 = 5;         /* unused channel: byte not read (D2) */
    DEC_RUN(t += 10, LOGIC_OUT(2) | LOGIC_OUT(8));
    fb->bDecIn2 = 5;         /* invalid byte on a used channel: that output FALSE (D3) */
    DEC_S(t += 10, SL_E_INVALID_BOOL, SL_STATE_RUN, 0, LOGIC_OUT(8));
    fb->bDecIn2 = 1;
    DEC_RUN(t += 10, LOGIC_OUT(2) | LOGIC_OUT(8));
    fb->bRun = 0;
    DEC_STOP(t += 10);
    fb->bRun = 1;
    DEC_RUN(t += 10, LOGIC_OUT(2) | LOGIC_OUT(8));
    h_end();

    h_begin("DECOUPLE parameter change while running (C5), adopted at STOP->run");
    fb->wInputActive = 0x03;
    DEC_S(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 0);
    DEC_S(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 0);
    fb->bErrAck = 1;         /* the condition remains while bRun is TRUE */
    DEC_S(t += 10, SL_E_PARAM_CHANGED, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 0);
    fb->bErrAck = 0;
    fb->wInputActive = 0x83; /* old value back: the condition is gone */
    DEC_S(t += 10, SL_OK, SL_STATE_ERROR, SL_DIAG_PARAM_CHANGED, 0);
    fb->bErrAck = 1;
    DEC_S(t += 10, SL_OK, SL_STATE_RESET, 0, 0);
    fb->bErrAck = 0;
    DEC_RUN(t += 10, LOGIC_OUT(2) | LOGIC_OUT(8));
    fb->bRun = 0;
    DEC_STOP(t += 10);
    fb->wInputActive = 0x01; /* changed in STOP: latched at the next STOP->run */
    DEC_STOP(t += 10);
    fb->bRun = 1;
    fb->bDecIn1 = 1;
    DEC_RUN(t += 10, LOGIC_OUT(1));
    h_end();
}

static void dec_config_null_names(void)
{
    FB_DECOUPLE inst;
    FB_DECOUPLE *fb = &inst;
    uint32_t t = 1000;
    h_begin("DECOUPLE configuration errors (SL_E_CONFIG, D2, C6), NULL, names");
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0;
    DEC_INIT(SL_E_CONFIG);
    fb->bRun = 1;
    fb->bDecIn1 = 1;
    DEC_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0x1FF;
    DEC_INIT(SL_E_CONFIG);
    fb->bRun = 1;
    DEC_S(t += 10, SL_E_CONFIG, SL_STATE_STOP, 0, 0);
    memset(fb, 0, sizeof *fb);
    fb->wInputActive = 0xFF;
    DEC_INIT(SL_OK);
    CHECK_INT(sl_decouple_init(NULL), SL_E_NULL);
    CHECK_INT(sl_decouple_cycle(NULL, 0), SL_E_NULL);
    CHECK_STR(sl_state_str(SL_TYPE_DECOUPLE, SL_STATE_RUN), "RUN");
    CHECK_STR(sl_state_str(SL_TYPE_DECOUPLE, SL_STATE_STOP), "STOP");
    CHECK_DIAG_TEXT_HAS(SL_TYPE_DECOUPLE, SL_DIAG_PARAM_CHANGED, "parameter");
    h_end();
}

void run_logic_scenarios(void)
{
    xor_function();
    xor_invalid_and_envelope();
    xor_config_null_names();
    dec_loop_through();
    dec_config_null_names();
}
