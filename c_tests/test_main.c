/*
 * Behaviour scenarios of the safelogic blocks through the C ABI: harness implementation
 * and main(). Expected values come from the manual (shared/spec/twinsafe-logic-fb-manual.txt
 * §4.3-§4.14, §4.34), shared/design/ABI.md and docs/semantics.md (row IDs cited in the
 * scenarios), never from running the library.
 */
#include "harness.h"

int h_passed = 0;
int h_failed = 0;
const char *h_scenario = "(none)";

static int h_scn_passed = 0;
static int h_scn_failed = 0;

void h_begin(const char *name)
{
    h_scenario = name;
    h_scn_passed = 0;
    h_scn_failed = 0;
}

void h_end(void)
{
    printf("%-6s %s (%d checks)\n", h_scn_failed ? "FAILED" : "ok", h_scenario,
           h_scn_passed + h_scn_failed);
    h_scenario = "(none)";
}

static void h_count(int ok)
{
    if (ok) {
        h_passed++;
        h_scn_passed++;
    } else {
        h_failed++;
        h_scn_failed++;
    }
}

void h_check(int ok, const char *file, int line, const char *msg)
{
    h_count(ok);
    if (!ok) {
        printf("FAIL [%s] %s:%d: %s\n", h_scenario, file, line, msg);
    }
}

void h_check_int(long long got, long long expected, const char *file, int line, const char *what)
{
    h_count(got == expected);
    if (got != expected) {
        printf("FAIL [%s] %s:%d: %s: expected %lld, got %lld\n", h_scenario, file, line, what,
               expected, got);
    }
}

void h_check_str(const char *got, const char *expected, const char *file, int line,
                 const char *what)
{
    int ok = got != NULL && expected != NULL && strcmp(got, expected) == 0;
    h_count(ok);
    if (!ok) {
        printf("FAIL [%s] %s:%d: %s: expected \"%s\", got \"%s\"\n", h_scenario, file, line,
               what, expected ? expected : "(null)", got ? got : "(null)");
    }
}

static const char *h_state_name(uint8_t s)
{
    /* ESTOP's states are a subset of MON's, with the same names. */
    const char *n = sl_state_str(SL_TYPE_MON, s);
    return n ? n : "(null)";
}

static const char *h_status_name(int32_t rc)
{
    switch (rc) {
    case SL_OK: return "SL_OK";
    case SL_E_NULL: return "SL_E_NULL";
    case SL_E_CONFIG: return "SL_E_CONFIG";
    case SL_E_PARAM_CHANGED: return "SL_E_PARAM_CHANGED";
    case SL_E_CORRUPT: return "SL_E_CORRUPT";
    case SL_E_INVALID_BOOL: return "SL_E_INVALID_BOOL";
    case SL_E_CLOCK: return "SL_E_CLOCK";
    case SL_E_INTERNAL: return "SL_E_INTERNAL";
    case SL_E_ALIGNMENT: return "SL_E_ALIGNMENT";
    default: return "?";
    }
}

void h_check_step(const char *file, int line, const char *block, uint32_t t,
                  int32_t rc, uint8_t state, uint16_t diag, uint8_t err, uint8_t out,
                  uint8_t del, int32_t xrc, uint8_t xstate, uint16_t xdiag, uint8_t xerr,
                  uint8_t xout, uint8_t xdel)
{
    int ok = rc == xrc && state == xstate && diag == xdiag && err == xerr && out == xout &&
             del == xdel;
    h_count(ok);
    if (ok) {
        return;
    }
    printf("FAIL [%s] %s:%d: %s t=%lu (0x%08lx):", h_scenario, file, line, block,
           (unsigned long)t, (unsigned long)t);
    if (rc != xrc) {
        printf(" rc expected %s(%ld) got %s(%ld);", h_status_name(xrc), (long)xrc,
               h_status_name(rc), (long)rc);
    }
    if (state != xstate) {
        printf(" nState expected %s(%u) got %s(%u);", h_state_name(xstate), (unsigned)xstate,
               h_state_name(state), (unsigned)state);
    }
    if (diag != xdiag) {
        printf(" nDiag expected 0x%04x got 0x%04x;", (unsigned)xdiag, (unsigned)diag);
    }
    if (err != xerr) {
        printf(" bError expected %u got %u;", (unsigned)xerr, (unsigned)err);
    }
    if (out != xout) {
        printf(" Out expected %u got %u;", (unsigned)xout, (unsigned)out);
    }
    if (del != xdel) {
        printf(" DelOut expected %u got %u;", (unsigned)xdel, (unsigned)del);
    }
    printf("\n");
}

uint32_t h_pack_bool(uint32_t outs, SL_BOOL v, unsigned bit)
{
    if (v != 0) {
        outs |= (uint32_t)1u << bit;
    }
    if (v > 1) {
        outs |= H_OUT_NOT_BOOL;
    }
    return outs;
}

static const char *h_fb_state_name(uint16_t type, uint8_t s)
{
    const char *n = sl_state_str(type, s);
    return n ? n : "(null)";
}

void h_check_fb(const char *file, int line, const char *block, uint16_t type, uint32_t t,
                int32_t rc, uint8_t state, uint16_t diag, uint32_t outs, int32_t xrc,
                uint8_t xstate, uint16_t xdiag, uint32_t xouts)
{
    int ok = rc == xrc && state == xstate && diag == xdiag && outs == xouts;
    h_count(ok);
    if (ok) {
        return;
    }
    printf("FAIL [%s] %s:%d: %s t=%lu (0x%08lx):", h_scenario, file, line, block,
           (unsigned long)t, (unsigned long)t);
    if (rc != xrc) {
        printf(" rc expected %s(%ld) got %s(%ld);", h_status_name(xrc), (long)xrc,
               h_status_name(rc), (long)rc);
    }
    if (state != xstate) {
        printf(" nState expected %s(%u) got %s(%u);", h_fb_state_name(type, xstate),
               (unsigned)xstate, h_fb_state_name(type, state), (unsigned)state);
    }
    if (diag != xdiag) {
        printf(" nDiag expected 0x%04x got 0x%04x;", (unsigned)xdiag, (unsigned)diag);
    }
    if (outs != xouts) {
        printf(" outputs expected 0x%03lx got 0x%03lx%s;", (unsigned long)xouts,
               (unsigned long)(outs & ~H_OUT_NOT_BOOL),
               (outs & H_OUT_NOT_BOOL) ? " (an output byte is not 0/1)" : "");
    }
    printf("\n");
}

static int h_lower(int c)
{
    return (c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : c;
}

static int h_equal_ci(const char *a, const char *b)
{
    while (*a != '\0' && *b != '\0') {
        if (h_lower((unsigned char)*a) != h_lower((unsigned char)*b)) {
            return 0;
        }
        a++;
        b++;
    }
    return *a == *b;
}

static int h_contains_ci(const char *hay, const char *needle)
{
    size_t n = strlen(needle), i;
    for (; *hay != '\0'; hay++) {
        for (i = 0; i < n; i++) {
            if (hay[i] == '\0' ||
                h_lower((unsigned char)hay[i]) != h_lower((unsigned char)needle[i])) {
                break;
            }
        }
        if (i == n) {
            return 1;
        }
    }
    return n == 0;
}

void h_check_diag_text(uint16_t type, uint16_t diag, const char *expected, int contains,
                       const char *file, int line)
{
    char buf[256];
    int32_t rc;
    int ok;
    memset(buf, 0x55, sizeof buf);
    rc = sl_diag_text(type, diag, buf, sizeof buf);
    buf[sizeof buf - 1] = '\0';
    ok = rc == SL_OK && (contains ? h_contains_ci(buf, expected) : h_equal_ci(buf, expected));
    h_count(ok);
    if (!ok) {
        printf("FAIL [%s] %s:%d: sl_diag_text(type %u, 0x%04x): rc %ld, text \"%s\", "
               "expected %s \"%s\" (case ignored)\n",
               h_scenario, file, line, (unsigned)type, (unsigned)diag, (long)rc, buf,
               contains ? "to contain" : "", expected);
    }
}

int main(void)
{
#ifdef __cplusplus
    const char *lang = "compiled as C++";
#else
    const char *lang = "compiled as C";
#endif
    printf("safelogic %s: C ABI behaviour scenarios (%s)\n", sl_version(), lang);
    run_api_scenarios();
    run_estop_scenarios();
    run_mon_scenarios();
    run_group_scenarios();
    run_logic_scenarios();
    run_opmode_scenarios();
    run_twohand_scenarios();
    run_muting_scenarios();
    run_edm_scenarios();
    run_flipflop_scenarios();
    run_timer_scenarios();
    run_arith_scenarios();
    run_scale_speed_scenarios();
    run_sli_scenarios();
    run_loadsensing_scenarios();
    run_envelope_scenarios();
    run_fsoe_scenarios();
    run_slp_scenarios();
    run_sbt_scenarios();
    run_advposmon_scenarios();
    run_cammonitor_scenarios();
    run_plcopen_scenarios();
    run_reason_scenarios();
    printf("%d passed, %d failed\n", h_passed, h_failed);
    return h_failed == 0 ? 0 : 1;
}
