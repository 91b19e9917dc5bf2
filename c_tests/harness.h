/*
 * Minimal self-contained test harness for the safelogic C ABI scenarios.
 *
 * No external framework: every check counts as one "passed" or one "failed"; a failed
 * check prints the scenario, file:line, the simulated time and every field that differs.
 * test_main.c prints "N passed, N failed" and returns non-zero when anything failed.
 *
 * The scenario sources (test_*.c) compile as C11 and as C++17 (scenarios_cxx.cpp includes
 * all of them into one translation unit), so: no designated initialisers, no compound
 * literals, no implicit void* conversions, and helper names unique across all files.
 */
#ifndef SL_C_TESTS_HARNESS_H
#define SL_C_TESTS_HARNESS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "safelogic.h"

/* Counters and the current scenario (defined in test_main.c). */
extern int h_passed;
extern int h_failed;
extern const char *h_scenario;

/* Starts a scenario: name printed in every failure message and in the summary line. */
void h_begin(const char *name);
/* Ends the current scenario and prints one line "ok"/"FAILED" with its counts. */
void h_end(void);

/* One check: `ok` true = pass. `msg` is printed (with file:line) only on failure. */
void h_check(int ok, const char *file, int line, const char *msg);
/* Integer equality check, printing expected and actual values on failure. */
void h_check_int(long long got, long long expected, const char *file, int line, const char *what);
/* String equality check. */
void h_check_str(const char *got, const char *expected, const char *file, int line,
                 const char *what);

/*
 * Checks one block step: status code of the call, nState, nDiag and the three BOOL outputs
 * (bError, first output, delayed output). Counts as ONE check; on failure prints every field
 * that differs. `t` is the simulated time of the call (for the message only).
 */
void h_check_step(const char *file, int line, const char *block, uint32_t t,
                  int32_t rc, uint8_t state, uint16_t diag, uint8_t err, uint8_t out,
                  uint8_t del, int32_t xrc, uint8_t xstate, uint16_t xdiag, uint8_t xerr,
                  uint8_t xout, uint8_t xdel);

/*
 * Generic block step (the blocks of ABI §9): status code, nState, nDiag and EVERY BOOL
 * output of the block packed into a bit set `outs` (bit order defined by each scenario file;
 * a byte other than 0/1 in any output sets H_OUT_NOT_BOOL). Counts as ONE check; on failure
 * prints every field that differs, with state names from sl_state_str(`type`, ...).
 */
#define H_OUT_NOT_BOOL 0x80000000u
uint32_t h_pack_bool(uint32_t outs, SL_BOOL v, unsigned bit);
void h_check_fb(const char *file, int line, const char *block, uint16_t type, uint32_t t,
                int32_t rc, uint8_t state, uint16_t diag, uint32_t outs, int32_t xrc,
                uint8_t xstate, uint16_t xdiag, uint32_t xouts);

/*
 * sl_diag_text(type, diag) returns SL_OK and a text equal to `expected` (mode 0) or
 * containing `expected` (mode 1), ASCII case ignored in both (the manual's texts begin
 * with a capital, the library may lower it).
 */
void h_check_diag_text(uint16_t type, uint16_t diag, const char *expected, int contains,
                       const char *file, int line);

#define CHECK(cond, msg) h_check((cond) ? 1 : 0, __FILE__, __LINE__, (msg))
#define CHECK_INT(got, expected) \
    h_check_int((long long)(got), (long long)(expected), __FILE__, __LINE__, #got)
#define CHECK_STR(got, expected) h_check_str((got), (expected), __FILE__, __LINE__, #got)

#define CHECK_DIAG_TEXT(type, diag, text) \
    h_check_diag_text((type), (diag), (text), 0, __FILE__, __LINE__)
#define CHECK_DIAG_TEXT_HAS(type, diag, text) \
    h_check_diag_text((type), (diag), (text), 1, __FILE__, __LINE__)

/* Scenario groups (test_estop.c, test_mon.c, test_api.c, test_group.c, test_logic.c,
 * test_opmode.c, test_twohand.c, test_muting.c, test_edm.c, test_flipflop.c,
 * test_timers.c, test_arith.c, test_scale_speed.c, test_sli.c, test_loadsensing.c,
 * test_envelope.c, test_fsoe.c, test_slp.c, test_sbt.c, test_advposmon.c, test_cammonitor.c,
 * test_plcopen.c, test_reasons.c). */
void run_estop_scenarios(void);
void run_reason_scenarios(void);
void run_plcopen_scenarios(void);
void run_mon_scenarios(void);
void run_api_scenarios(void);
void run_group_scenarios(void);
void run_logic_scenarios(void);
void run_opmode_scenarios(void);
void run_twohand_scenarios(void);
void run_muting_scenarios(void);
void run_arith_scenarios(void);
void run_scale_speed_scenarios(void);
void run_loadsensing_scenarios(void);
void run_envelope_scenarios(void);
void run_fsoe_scenarios(void);
void run_edm_scenarios(void);
void run_flipflop_scenarios(void);
void run_timer_scenarios(void);
void run_sli_scenarios(void);
void run_slp_scenarios(void);
void run_sbt_scenarios(void);
void run_advposmon_scenarios(void);
void run_cammonitor_scenarios(void);

#endif /* SL_C_TESTS_HARNESS_H */
