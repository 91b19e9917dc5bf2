/*
 * Block-independent C ABI functions: NULL pointers (SL_E_NULL), misaligned instance
 * (SL_E_ALIGNMENT), sl_status_str, sl_state_str, sl_version, sl_time_now_ms (ABI.md §4, §5).
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* clock_gettime, nanosleep under -std=c11 */
#endif
#include <time.h>

#include "harness.h"

static int api_is_digits(const char *s, size_t n)
{
    size_t i;
    if (n == 0) {
        return 0;
    }
    for (i = 0; i < n; i++) {
        if (s[i] < '0' || s[i] > '9') {
            return 0;
        }
    }
    return 1;
}

static uint32_t api_monotonic_ms(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) {
        return 0;
    }
    return (uint32_t)((uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u);
}

static void api_null(void)
{
    h_begin("API NULL instance pointers (SL_E_NULL)");
    CHECK_INT(sl_estop_init(NULL), SL_E_NULL);
    CHECK_INT(sl_estop_cycle(NULL, 0), SL_E_NULL);
    CHECK_INT(sl_estop_cycle(NULL, 0xFFFFFFFFu), SL_E_NULL);
    CHECK_INT(sl_mon_init(NULL), SL_E_NULL);
    CHECK_INT(sl_mon_cycle(NULL, 0), SL_E_NULL);
    CHECK_INT(sl_mon_cycle(NULL, 12345u), SL_E_NULL);
    h_end();
}

static void api_alignment(void)
{
    /* Library extension (C11): an instance pointer not 4-byte aligned is refused and
     * nothing is written. */
    uint64_t buf[(sizeof(FB_ESTOP) + 16) / 8];
    unsigned char *p = (unsigned char *)buf + 1;
    unsigned char before[sizeof(FB_ESTOP)];
    FB_ESTOP src;
    h_begin("API misaligned instance (SL_E_ALIGNMENT)");
    memset(&src, 0, sizeof src);
    src.wInputActive = 0x03;
    src.bRun = 1;
    src.bEStopIn1 = 1;
    src.bEStopIn2 = 1;
    memcpy(p, &src, sizeof src);
    memcpy(before, p, sizeof before);
    CHECK_INT(sl_estop_init((FB_ESTOP *)(void *)p), SL_E_ALIGNMENT);
    CHECK_INT(sl_estop_cycle((FB_ESTOP *)(void *)p, 10u), SL_E_ALIGNMENT);
    CHECK_INT(sl_mon_cycle((FB_MON *)(void *)p, 10u), SL_E_ALIGNMENT);
    CHECK(memcmp(before, p, sizeof before) == 0, "misaligned call wrote to the instance");
    h_end();
}

static void api_status_str(void)
{
    static const int32_t codes[] = {SL_OK,           SL_E_NULL,          SL_E_CONFIG,
                                    SL_E_PARAM_CHANGED, SL_E_CORRUPT,    SL_E_INVALID_BOOL,
                                    SL_E_CLOCK,      SL_E_INTERNAL,      SL_E_ALIGNMENT};
    const size_t n = sizeof codes / sizeof codes[0];
    size_t i, j;
    h_begin("API sl_status_str");
    /* ABI §5 values */
    CHECK_INT(SL_OK, 0);
    CHECK_INT(SL_E_NULL, -1);
    CHECK_INT(SL_E_CONFIG, -2);
    CHECK_INT(SL_E_PARAM_CHANGED, -3);
    CHECK_INT(SL_E_CORRUPT, -4);
    CHECK_INT(SL_E_INVALID_BOOL, -5);
    CHECK_INT(SL_E_CLOCK, -6);
    for (i = 0; i < n; i++) {
        const char *s = sl_status_str(codes[i]);
        CHECK(s != NULL && s[0] != '\0', "sl_status_str: NULL or empty text for a known code");
        for (j = 0; j < i; j++) {
            const char *o = sl_status_str(codes[j]);
            CHECK(s != NULL && o != NULL && strcmp(s, o) != 0,
                  "sl_status_str: two status codes share one text");
        }
    }
    CHECK(sl_status_str(12345) != NULL, "sl_status_str(unknown) returned NULL");
    CHECK(sl_status_str(-100) != NULL, "sl_status_str(-100) returned NULL");
    CHECK(sl_status_str(INT32_MIN) != NULL, "sl_status_str(INT32_MIN) returned NULL");
    CHECK(sl_status_str(SL_OK) == sl_status_str(SL_OK), "sl_status_str: text not static");
    h_end();
}

static void api_state_str(void)
{
    unsigned v;
    h_begin("API sl_state_str (manual status values 1..9)");
    CHECK_STR(sl_state_str(SL_TYPE_ESTOP, SL_STATE_FUNCTEST), "?");
    CHECK_STR(sl_state_str(SL_TYPE_ESTOP, SL_STATE_DELAYOUT), "DELAYOUT");
    CHECK_STR(sl_state_str(999, SL_STATE_RUN), "?");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_RUN), "RUN");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_STOP), "STOP");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_SAFE), "SAFE");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_ERROR), "ERROR");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_RESET), "RESET");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_START), "START");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_ERRORDELAY), "ERRORDELAY");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_DELAYOUT), "DELAYOUT");
    CHECK_STR(sl_state_str(SL_TYPE_MON, SL_STATE_FUNCTEST), "FUNCTEST");
    CHECK_INT(SL_STATE_RUN, 1);
    CHECK_INT(SL_STATE_STOP, 2);
    CHECK_INT(SL_STATE_SAFE, 3);
    CHECK_INT(SL_STATE_ERROR, 4);
    CHECK_INT(SL_STATE_RESET, 5);
    CHECK_INT(SL_STATE_START, 6);
    CHECK_INT(SL_STATE_ERRORDELAY, 7);
    CHECK_INT(SL_STATE_DELAYOUT, 8);
    CHECK_INT(SL_STATE_FUNCTEST, 9);
    for (v = 0; v <= 255; v++) {
        const char *s = sl_state_str(SL_TYPE_MON, (uint8_t)v);
        if (s == NULL) {
            CHECK(0, "sl_state_str returned NULL");
            break;
        }
    }
    CHECK(v == 256, "sl_state_str never NULL for 0..255");
    h_end();
}

static void api_version(void)
{
    const char *v = sl_version();
    const char *dot1;
    const char *dot2;
    h_begin("API sl_version (\"MAJOR.MINOR.PATCH\")");
    CHECK(v != NULL, "sl_version returned NULL");
    if (v != NULL) {
        dot1 = strchr(v, '.');
        dot2 = dot1 ? strchr(dot1 + 1, '.') : NULL;
        CHECK(dot1 != NULL && dot2 != NULL && api_is_digits(v, (size_t)(dot1 - v)) &&
                  api_is_digits(dot1 + 1, (size_t)(dot2 - dot1 - 1)) &&
                  api_is_digits(dot2 + 1, strlen(dot2 + 1)),
              "sl_version is not MAJOR.MINOR.PATCH");
        CHECK(sl_version() == v, "sl_version: text not static");
    }
    h_end();
}

/* What docs/release.md tells a program to do: refuse at compile time a header of another
 * major, and at run time a library that does not serve this header. */
#if !defined(SL_VERSION_MAJOR) || !defined(SL_VERSION_MINOR) || !defined(SL_VERSION_PATCH)
#error "safelogic.h defines no SL_VERSION_MAJOR/MINOR/PATCH"
#endif
#if SL_VERSION_MAJOR < 1
#error "these tests are written for the stable C ABI (major 1 or later)"
#endif

static void api_version_compatible(void)
{
    char macros[48];
    h_begin("API sl_version_compatible and the SL_VERSION_* macros");
    snprintf(macros, sizeof macros, "%d.%d.%d", SL_VERSION_MAJOR, SL_VERSION_MINOR, SL_VERSION_PATCH);
    CHECK(strcmp(sl_version(), macros) == 0, "sl_version() differs from the header's SL_VERSION_* macros");
    CHECK(sl_version_compatible(SL_VERSION_MAJOR, SL_VERSION_MINOR) == 1,
          "the library refuses its own header");
    CHECK(sl_version_compatible(SL_VERSION_MAJOR, 0) == 1, "an older minor refused");
    CHECK(sl_version_compatible(SL_VERSION_MAJOR, SL_VERSION_MINOR + 1) == 0, "a newer minor accepted");
    CHECK(sl_version_compatible(SL_VERSION_MAJOR + 1, 0) == 0, "the next major accepted");
    CHECK(sl_version_compatible(SL_VERSION_MAJOR - 1, SL_VERSION_MINOR) == 0, "the previous major accepted");
    h_end();
}

static void api_time_now(void)
{
    uint32_t a, b, c, e;
    struct timespec ts;
    h_begin("API sl_time_now_ms (CLOCK_MONOTONIC in ms, wrapping)");
    a = api_monotonic_ms();
    b = sl_time_now_ms();
    c = api_monotonic_ms();
    /* a <= b <= c in wrapping arithmetic, 1 ms of rounding slack each side */
    CHECK((uint32_t)(b - a + 1u) <= (uint32_t)(c - a + 2u),
          "sl_time_now_ms is not CLOCK_MONOTONIC in milliseconds");
    ts.tv_sec = 0;
    ts.tv_nsec = 30 * 1000000L;
    nanosleep(&ts, NULL);
    e = sl_time_now_ms();
    CHECK((uint32_t)(e - b) >= 29u && (uint32_t)(e - b) < 5000u,
          "sl_time_now_ms did not advance by ~30 ms across a 30 ms sleep");
    h_end();
}

void run_api_scenarios(void)
{
    api_null();
    api_alignment();
    api_status_str();
    api_state_str();
    api_version();
    api_version_compatible();
    api_time_now();
}
