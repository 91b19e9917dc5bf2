/*
 * Behaviour scenarios of FB_ESTOP and FB_MON through the C ABI: harness implementation
 * and main(). Expected values come from the manual (shared/spec/twinsafe-logic-fb-manual.txt
 * §4.4, §4.5), shared/design/ABI.md and docs/semantics.md (row IDs cited in the scenarios),
 * never from running the library.
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
    printf("%d passed, %d failed\n", h_passed, h_failed);
    return h_failed == 0 ? 0 : 1;
}
