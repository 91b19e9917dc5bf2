/*
 * Layout test (C11): every published offset of FB_ESTOP and FB_MON, written as literal
 * numbers from shared/design/ABI.md §3/§8 and the manual's Offset columns (§4.4.2, §4.5.2):
 *   inputs at the manual's offsets; bRun = 16, bErrAck = 17; parameters as in the header;
 *   outputs at output base 56 + the manual's output offset; nState = 64, nDiag = 66,
 *   stPrivate = 72; sizeof = 136.
 * Also the ABI §3 rules: every member at a multiple of its size, size a multiple of 8, no
 * implicit padding (field sizes add up to sizeof), and the constants of ABI §5/§6/§8.
 *
 * Built twice: normally, and with SL_LAYOUT_PACK4 defined (header included under
 * #pragma pack(4): ABI §3 says the layout is the same under pack mode 8 and pack mode 4).
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef SL_LAYOUT_PACK4
#pragma pack(push, 4)
#endif
#include "safelogic.h"
#ifdef SL_LAYOUT_PACK4
#pragma pack(pop)
#endif

/* offset + natural alignment (ABI §3: every member sits at a multiple of its size; the
 * private-state struct member is checked for 8-byte alignment instead) */
#define SL_AT(T, f, off)                                                      \
    _Static_assert(offsetof(T, f) == (off), "offset of " #T "." #f);          \
    _Static_assert(offsetof(T, f) % sizeof(((T *)0)->f) == 0, "alignment of " #T "." #f)
#define SL_SIZE(T, f, n) _Static_assert(sizeof(((T *)0)->f) == (n), "size of " #T "." #f)

/* ---------------- FB_ESTOP (ABI §8, manual §4.4.2) ---------------- */
/* inputs: manual Offset column 0.0, 1.0, 2.0, 8.0 ... 15.0 */
SL_AT(FB_ESTOP, bRestart, 0);
SL_AT(FB_ESTOP, bEDM1, 1);
SL_AT(FB_ESTOP, bEDM2, 2);
SL_AT(FB_ESTOP, bEStopIn1, 8);
SL_AT(FB_ESTOP, bEStopIn2, 9);
SL_AT(FB_ESTOP, bEStopIn3, 10);
SL_AT(FB_ESTOP, bEStopIn4, 11);
SL_AT(FB_ESTOP, bEStopIn5, 12);
SL_AT(FB_ESTOP, bEStopIn6, 13);
SL_AT(FB_ESTOP, bEStopIn7, 14);
SL_AT(FB_ESTOP, bEStopIn8, 15);
/* group link inputs */
SL_AT(FB_ESTOP, bRun, 16);
SL_AT(FB_ESTOP, bErrAck, 17);
/* parameters */
SL_AT(FB_ESTOP, tDiscTime12, 20);
SL_AT(FB_ESTOP, tDiscTime34, 24);
SL_AT(FB_ESTOP, tDiscTime56, 28);
SL_AT(FB_ESTOP, tDiscTime78, 32);
SL_AT(FB_ESTOP, tEDM1ResetTime, 36);
SL_AT(FB_ESTOP, tEDM2ResetTime, 40);
SL_AT(FB_ESTOP, tEStopDelOutDelay, 44);
SL_AT(FB_ESTOP, wInputActive, 48);
SL_AT(FB_ESTOP, wInputNegated, 50);
SL_AT(FB_ESTOP, dwOptions, 52);
/* outputs: output base 56 + manual Offset 0.0, 1.0, 2.0 */
SL_AT(FB_ESTOP, bError, 56 + 0);
SL_AT(FB_ESTOP, bEStopOut, 56 + 1);
SL_AT(FB_ESTOP, bEStopDelOut, 56 + 2);
/* info data, private state */
SL_AT(FB_ESTOP, nState, 64);
SL_AT(FB_ESTOP, nDiag, 66);
_Static_assert(offsetof(FB_ESTOP, stPrivate) == 72, "offset of FB_ESTOP.stPrivate");
_Static_assert(sizeof(FB_ESTOP) == 136, "size of FB_ESTOP");
_Static_assert(sizeof(FB_ESTOP) % 8 == 0, "size of FB_ESTOP is a multiple of 8");
_Static_assert(offsetof(FB_ESTOP, stPrivate) % 8 == 0, "FB_ESTOP private state 8-aligned");
_Static_assert(offsetof(FB_ESTOP, bEStopOut) - offsetof(FB_ESTOP, bError) == 1,
               "ABI §3 example: EStopOut = output base + 1");
/* field types (ABI §2: BOOL = uint8_t, TIME = uint32_t, BYTE, WORD, DWORD) */
SL_SIZE(FB_ESTOP, bRestart, 1);
SL_SIZE(FB_ESTOP, bEDM1, 1);
SL_SIZE(FB_ESTOP, bEDM2, 1);
SL_SIZE(FB_ESTOP, bEStopIn1, 1);
SL_SIZE(FB_ESTOP, bEStopIn8, 1);
SL_SIZE(FB_ESTOP, bRun, 1);
SL_SIZE(FB_ESTOP, bErrAck, 1);
SL_SIZE(FB_ESTOP, tDiscTime12, 4);
SL_SIZE(FB_ESTOP, tDiscTime34, 4);
SL_SIZE(FB_ESTOP, tDiscTime56, 4);
SL_SIZE(FB_ESTOP, tDiscTime78, 4);
SL_SIZE(FB_ESTOP, tEDM1ResetTime, 4);
SL_SIZE(FB_ESTOP, tEDM2ResetTime, 4);
SL_SIZE(FB_ESTOP, tEStopDelOutDelay, 4);
SL_SIZE(FB_ESTOP, wInputActive, 2);
SL_SIZE(FB_ESTOP, wInputNegated, 2);
SL_SIZE(FB_ESTOP, dwOptions, 4);
SL_SIZE(FB_ESTOP, bError, 1);
SL_SIZE(FB_ESTOP, bEStopOut, 1);
SL_SIZE(FB_ESTOP, bEStopDelOut, 1);
SL_SIZE(FB_ESTOP, nState, 1);
SL_SIZE(FB_ESTOP, nDiag, 2);
SL_SIZE(FB_ESTOP, stPrivate, 64);
/* no implicit padding: named fields (including the reserved ones) add up to sizeof */
_Static_assert(3 * 1 + sizeof(((FB_ESTOP *)0)->aReserved0) + 8 * 1 + 2 * 1 +
                       sizeof(((FB_ESTOP *)0)->aReserved1) + 7 * 4 + 2 * 2 + 4 + 3 * 1 +
                       sizeof(((FB_ESTOP *)0)->aReserved2) + 1 +
                       sizeof(((FB_ESTOP *)0)->aReserved3) + 2 +
                       sizeof(((FB_ESTOP *)0)->aReserved4) + 64 ==
                   136,
               "FB_ESTOP has implicit padding");

/* ---------------- FB_MON (ABI §8, manual §4.5.2) ---------------- */
SL_AT(FB_MON, bRestart, 0);
SL_AT(FB_MON, bEDM1, 1);
SL_AT(FB_MON, bEDM2, 2);
SL_AT(FB_MON, bMonIn1, 8);
SL_AT(FB_MON, bMonIn2, 9);
SL_AT(FB_MON, bMonIn3, 10);
SL_AT(FB_MON, bMonIn4, 11);
SL_AT(FB_MON, bSecure1, 12);
SL_AT(FB_MON, bSecure2, 13);
SL_AT(FB_MON, bRun, 16);
SL_AT(FB_MON, bErrAck, 17);
SL_AT(FB_MON, tDiscTime12, 20);
SL_AT(FB_MON, tDiscTime34, 24);
SL_AT(FB_MON, tDiscTimeSecure12, 28);
SL_AT(FB_MON, tEDM1ResetTime, 32);
SL_AT(FB_MON, tEDM2ResetTime, 36);
SL_AT(FB_MON, tMonDelOutDelay, 40);
SL_AT(FB_MON, wInputActive, 44);
SL_AT(FB_MON, wInputNegated, 46);
SL_AT(FB_MON, dwOptions, 48);
SL_AT(FB_MON, bError, 56 + 0);
SL_AT(FB_MON, bMonOut, 56 + 1);
SL_AT(FB_MON, bMonDelOut, 56 + 2);
SL_AT(FB_MON, nState, 64);
SL_AT(FB_MON, nDiag, 66);
_Static_assert(offsetof(FB_MON, stPrivate) == 72, "offset of FB_MON.stPrivate");
_Static_assert(offsetof(FB_MON, stPrivate) % 8 == 0, "FB_MON private state 8-aligned");
_Static_assert(sizeof(FB_MON) == 136, "size of FB_MON");
_Static_assert(sizeof(FB_MON) % 8 == 0, "size of FB_MON is a multiple of 8");
_Static_assert(offsetof(FB_MON, bSecure2) == 13, "ABI §3 example: offsetof(FB_MON, bSecure2)");
SL_SIZE(FB_MON, bRestart, 1);
SL_SIZE(FB_MON, bEDM1, 1);
SL_SIZE(FB_MON, bEDM2, 1);
SL_SIZE(FB_MON, bMonIn1, 1);
SL_SIZE(FB_MON, bMonIn4, 1);
SL_SIZE(FB_MON, bSecure1, 1);
SL_SIZE(FB_MON, bSecure2, 1);
SL_SIZE(FB_MON, bRun, 1);
SL_SIZE(FB_MON, bErrAck, 1);
SL_SIZE(FB_MON, tDiscTime12, 4);
SL_SIZE(FB_MON, tDiscTime34, 4);
SL_SIZE(FB_MON, tDiscTimeSecure12, 4);
SL_SIZE(FB_MON, tEDM1ResetTime, 4);
SL_SIZE(FB_MON, tEDM2ResetTime, 4);
SL_SIZE(FB_MON, tMonDelOutDelay, 4);
SL_SIZE(FB_MON, wInputActive, 2);
SL_SIZE(FB_MON, wInputNegated, 2);
SL_SIZE(FB_MON, dwOptions, 4);
SL_SIZE(FB_MON, bError, 1);
SL_SIZE(FB_MON, bMonOut, 1);
SL_SIZE(FB_MON, bMonDelOut, 1);
SL_SIZE(FB_MON, nState, 1);
SL_SIZE(FB_MON, nDiag, 2);
SL_SIZE(FB_MON, stPrivate, 64);
_Static_assert(3 * 1 + sizeof(((FB_MON *)0)->aReserved0) + 6 * 1 +
                       sizeof(((FB_MON *)0)->aReserved1) + 2 * 1 +
                       sizeof(((FB_MON *)0)->aReserved2) + 6 * 4 + 2 * 2 + 4 +
                       sizeof(((FB_MON *)0)->aReserved3) + 3 * 1 +
                       sizeof(((FB_MON *)0)->aReserved4) + 1 +
                       sizeof(((FB_MON *)0)->aReserved5) + 2 +
                       sizeof(((FB_MON *)0)->aReserved6) + 64 ==
                   136,
               "FB_MON has implicit padding");

/* ---------------- constants (ABI §2, §5, §6; manual status and diag tables) ---------------- */
_Static_assert(sizeof(SL_BOOL) == 1, "SL_BOOL is uint8_t");
_Static_assert(SL_OK == 0 && SL_E_NULL == -1 && SL_E_CONFIG == -2 && SL_E_PARAM_CHANGED == -3 &&
                   SL_E_CORRUPT == -4 && SL_E_INVALID_BOOL == -5 && SL_E_CLOCK == -6,
               "status codes (ABI §5)");
_Static_assert(SL_OPT_EDM1 == 1 && SL_OPT_EDM2 == 2 && SL_OPT_SAFE_INPUTS_AFTER_DISC == 4 &&
                   SL_OPT_MANUAL_RESTART == 8 && SL_OPT_FUNCTION_TEST == 16,
               "option bits (ABI §6)");
_Static_assert(SL_STATE_RUN == 1 && SL_STATE_STOP == 2 && SL_STATE_SAFE == 3 &&
                   SL_STATE_ERROR == 4 && SL_STATE_RESET == 5 && SL_STATE_START == 6 &&
                   SL_STATE_ERRORDELAY == 7 && SL_STATE_DELAYOUT == 8 && SL_STATE_FUNCTEST == 9,
               "status values (manual §4.4.2, §4.5.2)");
_Static_assert(SL_DIAG_DISC1 == 0x0001 && SL_DIAG_DISC2 == 0x0002 && SL_DIAG_DISC3 == 0x0004 &&
                   SL_DIAG_DISC4 == 0x0008 && SL_DIAG_EDM1 == 0x0010 && SL_DIAG_EDM2 == 0x0020 &&
                   SL_DIAG_SAFE_IN_DISC1 == 0x0100 && SL_DIAG_SAFE_IN_DISC2 == 0x0200 &&
                   SL_DIAG_SAFE_IN_DISC3 == 0x0400 && SL_DIAG_SAFE_IN_DISC4 == 0x0800,
               "diagnostic bits (manual §4.4.2, §4.5.2)");

#define SL_PRINT(T, f) \
    printf("  %-10s %-18s offset %3u size %2u\n", #T, #f, (unsigned)offsetof(T, f), \
           (unsigned)sizeof(((T *)0)->f))

int main(void)
{
#ifdef SL_LAYOUT_PACK4
    const char *mode = " under #pragma pack(4)";
#else
    const char *mode = "";
#endif
    printf("safelogic %s layout%s (all checked at compile time):\n", sl_version(), mode);
    SL_PRINT(FB_ESTOP, bRestart);
    SL_PRINT(FB_ESTOP, bEDM1);
    SL_PRINT(FB_ESTOP, bEDM2);
    SL_PRINT(FB_ESTOP, bEStopIn1);
    SL_PRINT(FB_ESTOP, bEStopIn8);
    SL_PRINT(FB_ESTOP, bRun);
    SL_PRINT(FB_ESTOP, bErrAck);
    SL_PRINT(FB_ESTOP, tDiscTime12);
    SL_PRINT(FB_ESTOP, tDiscTime78);
    SL_PRINT(FB_ESTOP, tEDM1ResetTime);
    SL_PRINT(FB_ESTOP, tEDM2ResetTime);
    SL_PRINT(FB_ESTOP, tEStopDelOutDelay);
    SL_PRINT(FB_ESTOP, wInputActive);
    SL_PRINT(FB_ESTOP, wInputNegated);
    SL_PRINT(FB_ESTOP, dwOptions);
    SL_PRINT(FB_ESTOP, bError);
    SL_PRINT(FB_ESTOP, bEStopOut);
    SL_PRINT(FB_ESTOP, bEStopDelOut);
    SL_PRINT(FB_ESTOP, nState);
    SL_PRINT(FB_ESTOP, nDiag);
    SL_PRINT(FB_ESTOP, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_ESTOP", (unsigned)sizeof(FB_ESTOP));
    SL_PRINT(FB_MON, bRestart);
    SL_PRINT(FB_MON, bEDM1);
    SL_PRINT(FB_MON, bEDM2);
    SL_PRINT(FB_MON, bMonIn1);
    SL_PRINT(FB_MON, bMonIn4);
    SL_PRINT(FB_MON, bSecure1);
    SL_PRINT(FB_MON, bSecure2);
    SL_PRINT(FB_MON, bRun);
    SL_PRINT(FB_MON, bErrAck);
    SL_PRINT(FB_MON, tDiscTime12);
    SL_PRINT(FB_MON, tDiscTime34);
    SL_PRINT(FB_MON, tDiscTimeSecure12);
    SL_PRINT(FB_MON, tEDM1ResetTime);
    SL_PRINT(FB_MON, tEDM2ResetTime);
    SL_PRINT(FB_MON, tMonDelOutDelay);
    SL_PRINT(FB_MON, wInputActive);
    SL_PRINT(FB_MON, wInputNegated);
    SL_PRINT(FB_MON, dwOptions);
    SL_PRINT(FB_MON, bError);
    SL_PRINT(FB_MON, bMonOut);
    SL_PRINT(FB_MON, bMonDelOut);
    SL_PRINT(FB_MON, nState);
    SL_PRINT(FB_MON, nDiag);
    SL_PRINT(FB_MON, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_MON", (unsigned)sizeof(FB_MON));
    printf("layout ok\n");
    return 0;
}
