/*
 * Layout test (C11): every published offset of FB_ESTOP and FB_MON, written as literal
 * numbers from shared/design/ABI.md §3/§8 and the manual's Offset columns (§4.4.2, §4.5.2):
 *   inputs at the manual's offsets; bRun = 16, bErrAck = 17; parameters as in the header;
 *   outputs at output base 56 + the manual's output offset; nState = 64, nDiag = 66,
 *   stPrivate = 72; sizeof = 136.
 * The same for the eleven blocks of ABI §9 (XOR, DECOUPLE, OPMODE, TWOHAND, MUTING, EDM, RS,
 * SR, TON, TON2, TOF): inputs at the manual's absolute input offsets, outputs at the
 * header's output base + the manual's output offset, parameters / nState / nDiag /
 * stPrivate / sizeof as written in the header's offset comments.
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
_Static_assert(sizeof(FB_ESTOP) == 152, "size of FB_ESTOP");
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
SL_SIZE(FB_ESTOP, stPrivate, 80);
/* no implicit padding: named fields (including the reserved ones) add up to sizeof */
_Static_assert(3 * 1 + sizeof(((FB_ESTOP *)0)->aReserved0) + 8 * 1 + 2 * 1 +
                       sizeof(((FB_ESTOP *)0)->aReserved1) + 7 * 4 + 2 * 2 + 4 + 3 * 1 +
                       sizeof(((FB_ESTOP *)0)->aReserved2) + 1 +
                       sizeof(((FB_ESTOP *)0)->aReserved3) + 2 +
                       sizeof(((FB_ESTOP *)0)->aReserved4) + 80 ==
                   152,
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
_Static_assert(sizeof(FB_MON) == 152, "size of FB_MON");
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
SL_SIZE(FB_MON, stPrivate, 80);
_Static_assert(3 * 1 + sizeof(((FB_MON *)0)->aReserved0) + 6 * 1 +
                       sizeof(((FB_MON *)0)->aReserved1) + 2 * 1 +
                       sizeof(((FB_MON *)0)->aReserved2) + 6 * 4 + 2 * 2 + 4 +
                       sizeof(((FB_MON *)0)->aReserved3) + 3 * 1 +
                       sizeof(((FB_MON *)0)->aReserved4) + 1 +
                       sizeof(((FB_MON *)0)->aReserved5) + 2 +
                       sizeof(((FB_MON *)0)->aReserved6) + 80 ==
                   152,
               "FB_MON has implicit padding");

/* ======== the other Boolean blocks (ABI §9; parameters, info data, private state and
 * sizes as written in the header's offset comments) ======== */

/* ---------------- FB_XOR (ABI §9, manual §4.34.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_XOR, bXor1In1, 0);
SL_AT(FB_XOR, bXor2In1, 1);
SL_AT(FB_XOR, bXor1In2, 2);
SL_AT(FB_XOR, bXor2In2, 3);
SL_AT(FB_XOR, bXor1In3, 4);
SL_AT(FB_XOR, bXor2In3, 5);
SL_AT(FB_XOR, bXor1In4, 6);
SL_AT(FB_XOR, bXor2In4, 7);
SL_AT(FB_XOR, bXor1In5, 8);
SL_AT(FB_XOR, bXor2In5, 9);
SL_AT(FB_XOR, bXor1In6, 10);
SL_AT(FB_XOR, bXor2In6, 11);
SL_AT(FB_XOR, bXor1In7, 12);
SL_AT(FB_XOR, bXor2In7, 13);
SL_AT(FB_XOR, bXor1In8, 14);
SL_AT(FB_XOR, bXor2In8, 15);
/* group link inputs */
SL_AT(FB_XOR, bRun, 16);
SL_AT(FB_XOR, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_XOR, wInputActive, 20);
/* outputs: output base 24 + the manual's output Offset column */
SL_AT(FB_XOR, bXorOut1, 24 + 8);
SL_AT(FB_XOR, bXorOut2, 24 + 9);
SL_AT(FB_XOR, bXorOut3, 24 + 10);
SL_AT(FB_XOR, bXorOut4, 24 + 11);
SL_AT(FB_XOR, bXorOut5, 24 + 12);
SL_AT(FB_XOR, bXorOut6, 24 + 13);
SL_AT(FB_XOR, bXorOut7, 24 + 14);
SL_AT(FB_XOR, bXorOut8, 24 + 15);
/* info data, private state, size */
SL_AT(FB_XOR, nState, 40);
SL_AT(FB_XOR, nDiag, 42);
_Static_assert(offsetof(FB_XOR, stPrivate) == 48, "offset of FB_XOR.stPrivate");
_Static_assert(offsetof(FB_XOR, stPrivate) % 8 == 0, "FB_XOR private state 8-aligned");
_Static_assert(sizeof(FB_XOR) == 112, "size of FB_XOR");
_Static_assert(sizeof(FB_XOR) % 8 == 0, "size of FB_XOR is a multiple of 8");
SL_SIZE(FB_XOR, bXor1In1, 1);
SL_SIZE(FB_XOR, bXor2In1, 1);
SL_SIZE(FB_XOR, bXor1In2, 1);
SL_SIZE(FB_XOR, bXor2In2, 1);
SL_SIZE(FB_XOR, bXor1In3, 1);
SL_SIZE(FB_XOR, bXor2In3, 1);
SL_SIZE(FB_XOR, bXor1In4, 1);
SL_SIZE(FB_XOR, bXor2In4, 1);
SL_SIZE(FB_XOR, bXor1In5, 1);
SL_SIZE(FB_XOR, bXor2In5, 1);
SL_SIZE(FB_XOR, bXor1In6, 1);
SL_SIZE(FB_XOR, bXor2In6, 1);
SL_SIZE(FB_XOR, bXor1In7, 1);
SL_SIZE(FB_XOR, bXor2In7, 1);
SL_SIZE(FB_XOR, bXor1In8, 1);
SL_SIZE(FB_XOR, bXor2In8, 1);
SL_SIZE(FB_XOR, bRun, 1);
SL_SIZE(FB_XOR, bErrAck, 1);
SL_SIZE(FB_XOR, wInputActive, 2);
SL_SIZE(FB_XOR, bXorOut1, 1);
SL_SIZE(FB_XOR, bXorOut2, 1);
SL_SIZE(FB_XOR, bXorOut3, 1);
SL_SIZE(FB_XOR, bXorOut4, 1);
SL_SIZE(FB_XOR, bXorOut5, 1);
SL_SIZE(FB_XOR, bXorOut6, 1);
SL_SIZE(FB_XOR, bXorOut7, 1);
SL_SIZE(FB_XOR, bXorOut8, 1);
SL_SIZE(FB_XOR, nState, 1);
SL_SIZE(FB_XOR, nDiag, 2);
SL_SIZE(FB_XOR, stPrivate, 64);
/* no implicit padding: 95 bytes of named fields + the reserved fields == sizeof */
_Static_assert(95 +
                   sizeof(((FB_XOR *)0)->aReserved0) +
                   sizeof(((FB_XOR *)0)->aReserved1) +
                   sizeof(((FB_XOR *)0)->aReserved2) +
                   sizeof(((FB_XOR *)0)->aReserved3) +
                   sizeof(((FB_XOR *)0)->aReserved4) ==
                   112,
               "FB_XOR has implicit padding");

/* ---------------- FB_DECOUPLE (ABI §9, manual §4.6.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_DECOUPLE, bDecIn1, 8);
SL_AT(FB_DECOUPLE, bDecIn2, 9);
SL_AT(FB_DECOUPLE, bDecIn3, 10);
SL_AT(FB_DECOUPLE, bDecIn4, 11);
SL_AT(FB_DECOUPLE, bDecIn5, 12);
SL_AT(FB_DECOUPLE, bDecIn6, 13);
SL_AT(FB_DECOUPLE, bDecIn7, 14);
SL_AT(FB_DECOUPLE, bDecIn8, 15);
/* group link inputs */
SL_AT(FB_DECOUPLE, bRun, 16);
SL_AT(FB_DECOUPLE, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_DECOUPLE, wInputActive, 20);
/* outputs: output base 24 + the manual's output Offset column */
SL_AT(FB_DECOUPLE, bDecOut1, 24 + 8);
SL_AT(FB_DECOUPLE, bDecOut2, 24 + 9);
SL_AT(FB_DECOUPLE, bDecOut3, 24 + 10);
SL_AT(FB_DECOUPLE, bDecOut4, 24 + 11);
SL_AT(FB_DECOUPLE, bDecOut5, 24 + 12);
SL_AT(FB_DECOUPLE, bDecOut6, 24 + 13);
SL_AT(FB_DECOUPLE, bDecOut7, 24 + 14);
SL_AT(FB_DECOUPLE, bDecOut8, 24 + 15);
/* info data, private state, size */
SL_AT(FB_DECOUPLE, nState, 40);
SL_AT(FB_DECOUPLE, nDiag, 42);
_Static_assert(offsetof(FB_DECOUPLE, stPrivate) == 48, "offset of FB_DECOUPLE.stPrivate");
_Static_assert(offsetof(FB_DECOUPLE, stPrivate) % 8 == 0, "FB_DECOUPLE private state 8-aligned");
_Static_assert(sizeof(FB_DECOUPLE) == 112, "size of FB_DECOUPLE");
_Static_assert(sizeof(FB_DECOUPLE) % 8 == 0, "size of FB_DECOUPLE is a multiple of 8");
SL_SIZE(FB_DECOUPLE, bDecIn1, 1);
SL_SIZE(FB_DECOUPLE, bDecIn2, 1);
SL_SIZE(FB_DECOUPLE, bDecIn3, 1);
SL_SIZE(FB_DECOUPLE, bDecIn4, 1);
SL_SIZE(FB_DECOUPLE, bDecIn5, 1);
SL_SIZE(FB_DECOUPLE, bDecIn6, 1);
SL_SIZE(FB_DECOUPLE, bDecIn7, 1);
SL_SIZE(FB_DECOUPLE, bDecIn8, 1);
SL_SIZE(FB_DECOUPLE, bRun, 1);
SL_SIZE(FB_DECOUPLE, bErrAck, 1);
SL_SIZE(FB_DECOUPLE, wInputActive, 2);
SL_SIZE(FB_DECOUPLE, bDecOut1, 1);
SL_SIZE(FB_DECOUPLE, bDecOut2, 1);
SL_SIZE(FB_DECOUPLE, bDecOut3, 1);
SL_SIZE(FB_DECOUPLE, bDecOut4, 1);
SL_SIZE(FB_DECOUPLE, bDecOut5, 1);
SL_SIZE(FB_DECOUPLE, bDecOut6, 1);
SL_SIZE(FB_DECOUPLE, bDecOut7, 1);
SL_SIZE(FB_DECOUPLE, bDecOut8, 1);
SL_SIZE(FB_DECOUPLE, nState, 1);
SL_SIZE(FB_DECOUPLE, nDiag, 2);
SL_SIZE(FB_DECOUPLE, stPrivate, 64);
/* no implicit padding: 87 bytes of named fields + the reserved fields == sizeof */
_Static_assert(87 +
                   sizeof(((FB_DECOUPLE *)0)->aReserved0) +
                   sizeof(((FB_DECOUPLE *)0)->aReserved1) +
                   sizeof(((FB_DECOUPLE *)0)->aReserved2) +
                   sizeof(((FB_DECOUPLE *)0)->aReserved3) +
                   sizeof(((FB_DECOUPLE *)0)->aReserved4) +
                   sizeof(((FB_DECOUPLE *)0)->aReserved5) ==
                   112,
               "FB_DECOUPLE has implicit padding");

/* ---------------- FB_OPMODE (ABI §9, manual §4.3.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_OPMODE, bRestart, 0);
SL_AT(FB_OPMODE, bOpIn1, 8);
SL_AT(FB_OPMODE, bOpIn2, 9);
SL_AT(FB_OPMODE, bOpIn3, 10);
SL_AT(FB_OPMODE, bOpIn4, 11);
SL_AT(FB_OPMODE, bOpIn5, 12);
SL_AT(FB_OPMODE, bOpIn6, 13);
SL_AT(FB_OPMODE, bOpIn7, 14);
SL_AT(FB_OPMODE, bOpIn8, 15);
/* group link inputs */
SL_AT(FB_OPMODE, bRun, 16);
SL_AT(FB_OPMODE, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_OPMODE, tDiscTime, 20);
SL_AT(FB_OPMODE, wInputActive, 24);
SL_AT(FB_OPMODE, dwOptions, 28);
/* outputs: output base 32 + the manual's output Offset column */
SL_AT(FB_OPMODE, bError, 32 + 0);
SL_AT(FB_OPMODE, bOpOut1, 32 + 8);
SL_AT(FB_OPMODE, bOpOut2, 32 + 9);
SL_AT(FB_OPMODE, bOpOut3, 32 + 10);
SL_AT(FB_OPMODE, bOpOut4, 32 + 11);
SL_AT(FB_OPMODE, bOpOut5, 32 + 12);
SL_AT(FB_OPMODE, bOpOut6, 32 + 13);
SL_AT(FB_OPMODE, bOpOut7, 32 + 14);
SL_AT(FB_OPMODE, bOpOut8, 32 + 15);
/* info data, private state, size */
SL_AT(FB_OPMODE, nState, 48);
SL_AT(FB_OPMODE, nDiag, 50);
_Static_assert(offsetof(FB_OPMODE, stPrivate) == 56, "offset of FB_OPMODE.stPrivate");
_Static_assert(offsetof(FB_OPMODE, stPrivate) % 8 == 0, "FB_OPMODE private state 8-aligned");
_Static_assert(sizeof(FB_OPMODE) == 88, "size of FB_OPMODE");
_Static_assert(sizeof(FB_OPMODE) % 8 == 0, "size of FB_OPMODE is a multiple of 8");
_Static_assert(offsetof(FB_OPMODE, bOpOut1) - offsetof(FB_OPMODE, bError) == 8,
               "FB_OPMODE.bOpOut1 = output base + 8");
_Static_assert(offsetof(FB_OPMODE, bOpOut2) - offsetof(FB_OPMODE, bError) == 9,
               "FB_OPMODE.bOpOut2 = output base + 9");
_Static_assert(offsetof(FB_OPMODE, bOpOut3) - offsetof(FB_OPMODE, bError) == 10,
               "FB_OPMODE.bOpOut3 = output base + 10");
_Static_assert(offsetof(FB_OPMODE, bOpOut4) - offsetof(FB_OPMODE, bError) == 11,
               "FB_OPMODE.bOpOut4 = output base + 11");
_Static_assert(offsetof(FB_OPMODE, bOpOut5) - offsetof(FB_OPMODE, bError) == 12,
               "FB_OPMODE.bOpOut5 = output base + 12");
_Static_assert(offsetof(FB_OPMODE, bOpOut6) - offsetof(FB_OPMODE, bError) == 13,
               "FB_OPMODE.bOpOut6 = output base + 13");
_Static_assert(offsetof(FB_OPMODE, bOpOut7) - offsetof(FB_OPMODE, bError) == 14,
               "FB_OPMODE.bOpOut7 = output base + 14");
_Static_assert(offsetof(FB_OPMODE, bOpOut8) - offsetof(FB_OPMODE, bError) == 15,
               "FB_OPMODE.bOpOut8 = output base + 15");
SL_SIZE(FB_OPMODE, bRestart, 1);
SL_SIZE(FB_OPMODE, bOpIn1, 1);
SL_SIZE(FB_OPMODE, bOpIn2, 1);
SL_SIZE(FB_OPMODE, bOpIn3, 1);
SL_SIZE(FB_OPMODE, bOpIn4, 1);
SL_SIZE(FB_OPMODE, bOpIn5, 1);
SL_SIZE(FB_OPMODE, bOpIn6, 1);
SL_SIZE(FB_OPMODE, bOpIn7, 1);
SL_SIZE(FB_OPMODE, bOpIn8, 1);
SL_SIZE(FB_OPMODE, bRun, 1);
SL_SIZE(FB_OPMODE, bErrAck, 1);
SL_SIZE(FB_OPMODE, tDiscTime, 4);
SL_SIZE(FB_OPMODE, wInputActive, 2);
SL_SIZE(FB_OPMODE, dwOptions, 4);
SL_SIZE(FB_OPMODE, bError, 1);
SL_SIZE(FB_OPMODE, bOpOut1, 1);
SL_SIZE(FB_OPMODE, bOpOut2, 1);
SL_SIZE(FB_OPMODE, bOpOut3, 1);
SL_SIZE(FB_OPMODE, bOpOut4, 1);
SL_SIZE(FB_OPMODE, bOpOut5, 1);
SL_SIZE(FB_OPMODE, bOpOut6, 1);
SL_SIZE(FB_OPMODE, bOpOut7, 1);
SL_SIZE(FB_OPMODE, bOpOut8, 1);
SL_SIZE(FB_OPMODE, nState, 1);
SL_SIZE(FB_OPMODE, nDiag, 2);
SL_SIZE(FB_OPMODE, stPrivate, 32);
/* no implicit padding: 65 bytes of named fields + the reserved fields == sizeof */
_Static_assert(65 +
                   sizeof(((FB_OPMODE *)0)->aReserved0) +
                   sizeof(((FB_OPMODE *)0)->aReserved1) +
                   sizeof(((FB_OPMODE *)0)->aReserved2) +
                   sizeof(((FB_OPMODE *)0)->aReserved3) +
                   sizeof(((FB_OPMODE *)0)->aReserved4) +
                   sizeof(((FB_OPMODE *)0)->aReserved5) ==
                   88,
               "FB_OPMODE has implicit padding");

/* ---------------- FB_TWOHAND (ABI §9, manual §4.7.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_TWOHAND, bTwoHand1, 8);
SL_AT(FB_TWOHAND, bTwoHand2, 9);
SL_AT(FB_TWOHAND, bTwoHand3, 10);
SL_AT(FB_TWOHAND, bTwoHand4, 11);
/* group link inputs */
SL_AT(FB_TWOHAND, bRun, 16);
SL_AT(FB_TWOHAND, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_TWOHAND, tDiscTime12, 20);
SL_AT(FB_TWOHAND, tDiscTime34, 24);
SL_AT(FB_TWOHAND, tDiscTimePairs, 28);
SL_AT(FB_TWOHAND, wInputActive, 32);
SL_AT(FB_TWOHAND, wInputNegated, 34);
SL_AT(FB_TWOHAND, dwOptions, 36);
/* outputs: output base 40 + the manual's output Offset column */
SL_AT(FB_TWOHAND, bError, 40 + 0);
SL_AT(FB_TWOHAND, bTwoHandOut, 40 + 1);
/* info data, private state, size */
SL_AT(FB_TWOHAND, nState, 48);
SL_AT(FB_TWOHAND, nDiag, 50);
_Static_assert(offsetof(FB_TWOHAND, stPrivate) == 56, "offset of FB_TWOHAND.stPrivate");
_Static_assert(offsetof(FB_TWOHAND, stPrivate) % 8 == 0, "FB_TWOHAND private state 8-aligned");
_Static_assert(sizeof(FB_TWOHAND) == 104, "size of FB_TWOHAND");
_Static_assert(sizeof(FB_TWOHAND) % 8 == 0, "size of FB_TWOHAND is a multiple of 8");
_Static_assert(offsetof(FB_TWOHAND, bTwoHandOut) - offsetof(FB_TWOHAND, bError) == 1,
               "FB_TWOHAND.bTwoHandOut = output base + 1");
SL_SIZE(FB_TWOHAND, bTwoHand1, 1);
SL_SIZE(FB_TWOHAND, bTwoHand2, 1);
SL_SIZE(FB_TWOHAND, bTwoHand3, 1);
SL_SIZE(FB_TWOHAND, bTwoHand4, 1);
SL_SIZE(FB_TWOHAND, bRun, 1);
SL_SIZE(FB_TWOHAND, bErrAck, 1);
SL_SIZE(FB_TWOHAND, tDiscTime12, 4);
SL_SIZE(FB_TWOHAND, tDiscTime34, 4);
SL_SIZE(FB_TWOHAND, tDiscTimePairs, 4);
SL_SIZE(FB_TWOHAND, wInputActive, 2);
SL_SIZE(FB_TWOHAND, wInputNegated, 2);
SL_SIZE(FB_TWOHAND, dwOptions, 4);
SL_SIZE(FB_TWOHAND, bError, 1);
SL_SIZE(FB_TWOHAND, bTwoHandOut, 1);
SL_SIZE(FB_TWOHAND, nState, 1);
SL_SIZE(FB_TWOHAND, nDiag, 2);
SL_SIZE(FB_TWOHAND, stPrivate, 48);
/* no implicit padding: 79 bytes of named fields + the reserved fields == sizeof */
_Static_assert(79 +
                   sizeof(((FB_TWOHAND *)0)->aReserved0) +
                   sizeof(((FB_TWOHAND *)0)->aReserved1) +
                   sizeof(((FB_TWOHAND *)0)->aReserved2) +
                   sizeof(((FB_TWOHAND *)0)->aReserved3) +
                   sizeof(((FB_TWOHAND *)0)->aReserved4) +
                   sizeof(((FB_TWOHAND *)0)->aReserved5) ==
                   104,
               "FB_TWOHAND has implicit padding");

/* ---------------- FB_MUTING (ABI §9, manual §4.8.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_MUTING, bMutingEnable, 0);
SL_AT(FB_MUTING, bEDM1, 1);
SL_AT(FB_MUTING, bEDM2, 2);
SL_AT(FB_MUTING, bMutingIn1, 8);
SL_AT(FB_MUTING, bMutingIn2, 9);
SL_AT(FB_MUTING, bOSSDIn1, 10);
SL_AT(FB_MUTING, bOSSDIn2, 11);
SL_AT(FB_MUTING, bMutingIn3, 12);
SL_AT(FB_MUTING, bMutingIn4, 13);
/* group link inputs */
SL_AT(FB_MUTING, bRun, 16);
SL_AT(FB_MUTING, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_MUTING, tDiscTime12, 20);
SL_AT(FB_MUTING, tDiscTimeOSSD, 24);
SL_AT(FB_MUTING, tDiscTime34, 28);
SL_AT(FB_MUTING, tFilterTime, 32);
SL_AT(FB_MUTING, tMaxMutingTime, 36);
SL_AT(FB_MUTING, tMuteDelOutDelay, 40);
SL_AT(FB_MUTING, wInputActive, 44);
SL_AT(FB_MUTING, wInputNegated, 46);
SL_AT(FB_MUTING, dwOptions, 48);
/* outputs: output base 56 + the manual's output Offset column */
SL_AT(FB_MUTING, bError, 56 + 0);
SL_AT(FB_MUTING, bMutingActive, 56 + 1);
SL_AT(FB_MUTING, bMuteOut, 56 + 2);
SL_AT(FB_MUTING, bMuteDelOut, 56 + 3);
/* info data, private state, size */
SL_AT(FB_MUTING, nState, 64);
SL_AT(FB_MUTING, nDiag, 66);
_Static_assert(offsetof(FB_MUTING, stPrivate) == 72, "offset of FB_MUTING.stPrivate");
_Static_assert(offsetof(FB_MUTING, stPrivate) % 8 == 0, "FB_MUTING private state 8-aligned");
_Static_assert(sizeof(FB_MUTING) == 144, "size of FB_MUTING");
_Static_assert(sizeof(FB_MUTING) % 8 == 0, "size of FB_MUTING is a multiple of 8");
_Static_assert(offsetof(FB_MUTING, bMutingActive) - offsetof(FB_MUTING, bError) == 1,
               "FB_MUTING.bMutingActive = output base + 1");
_Static_assert(offsetof(FB_MUTING, bMuteOut) - offsetof(FB_MUTING, bError) == 2,
               "FB_MUTING.bMuteOut = output base + 2");
_Static_assert(offsetof(FB_MUTING, bMuteDelOut) - offsetof(FB_MUTING, bError) == 3,
               "FB_MUTING.bMuteDelOut = output base + 3");
SL_SIZE(FB_MUTING, bMutingEnable, 1);
SL_SIZE(FB_MUTING, bEDM1, 1);
SL_SIZE(FB_MUTING, bEDM2, 1);
SL_SIZE(FB_MUTING, bMutingIn1, 1);
SL_SIZE(FB_MUTING, bMutingIn2, 1);
SL_SIZE(FB_MUTING, bOSSDIn1, 1);
SL_SIZE(FB_MUTING, bOSSDIn2, 1);
SL_SIZE(FB_MUTING, bMutingIn3, 1);
SL_SIZE(FB_MUTING, bMutingIn4, 1);
SL_SIZE(FB_MUTING, bRun, 1);
SL_SIZE(FB_MUTING, bErrAck, 1);
SL_SIZE(FB_MUTING, tDiscTime12, 4);
SL_SIZE(FB_MUTING, tDiscTimeOSSD, 4);
SL_SIZE(FB_MUTING, tDiscTime34, 4);
SL_SIZE(FB_MUTING, tFilterTime, 4);
SL_SIZE(FB_MUTING, tMaxMutingTime, 4);
SL_SIZE(FB_MUTING, tMuteDelOutDelay, 4);
SL_SIZE(FB_MUTING, wInputActive, 2);
SL_SIZE(FB_MUTING, wInputNegated, 2);
SL_SIZE(FB_MUTING, dwOptions, 4);
SL_SIZE(FB_MUTING, bError, 1);
SL_SIZE(FB_MUTING, bMutingActive, 1);
SL_SIZE(FB_MUTING, bMuteOut, 1);
SL_SIZE(FB_MUTING, bMuteDelOut, 1);
SL_SIZE(FB_MUTING, nState, 1);
SL_SIZE(FB_MUTING, nDiag, 2);
SL_SIZE(FB_MUTING, stPrivate, 72);
/* no implicit padding: 122 bytes of named fields + the reserved fields == sizeof */
_Static_assert(122 +
                   sizeof(((FB_MUTING *)0)->aReserved0) +
                   sizeof(((FB_MUTING *)0)->aReserved1) +
                   sizeof(((FB_MUTING *)0)->aReserved2) +
                   sizeof(((FB_MUTING *)0)->aReserved3) +
                   sizeof(((FB_MUTING *)0)->aReserved4) +
                   sizeof(((FB_MUTING *)0)->aReserved5) +
                   sizeof(((FB_MUTING *)0)->aReserved6) ==
                   144,
               "FB_MUTING has implicit padding");

/* ---------------- FB_EDM (ABI §9, manual §4.9.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_EDM, bMon1, 8);
SL_AT(FB_EDM, bMon2, 9);
/* group link inputs */
SL_AT(FB_EDM, bRun, 16);
SL_AT(FB_EDM, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_EDM, tSwitchOnTime, 20);
SL_AT(FB_EDM, tSwitchOffTime, 24);
SL_AT(FB_EDM, wInputActive, 28);
SL_AT(FB_EDM, wInputNegated, 30);
/* outputs: output base 32 + the manual's output Offset column */
SL_AT(FB_EDM, bError, 32 + 0);
/* info data, private state, size */
SL_AT(FB_EDM, nState, 40);
SL_AT(FB_EDM, nDiag, 42);
_Static_assert(offsetof(FB_EDM, stPrivate) == 48, "offset of FB_EDM.stPrivate");
_Static_assert(offsetof(FB_EDM, stPrivate) % 8 == 0, "FB_EDM private state 8-aligned");
_Static_assert(sizeof(FB_EDM) == 80, "size of FB_EDM");
_Static_assert(sizeof(FB_EDM) % 8 == 0, "size of FB_EDM is a multiple of 8");
SL_SIZE(FB_EDM, bMon1, 1);
SL_SIZE(FB_EDM, bMon2, 1);
SL_SIZE(FB_EDM, bRun, 1);
SL_SIZE(FB_EDM, bErrAck, 1);
SL_SIZE(FB_EDM, tSwitchOnTime, 4);
SL_SIZE(FB_EDM, tSwitchOffTime, 4);
SL_SIZE(FB_EDM, wInputActive, 2);
SL_SIZE(FB_EDM, wInputNegated, 2);
SL_SIZE(FB_EDM, bError, 1);
SL_SIZE(FB_EDM, nState, 1);
SL_SIZE(FB_EDM, nDiag, 2);
SL_SIZE(FB_EDM, stPrivate, 32);
/* no implicit padding: 52 bytes of named fields + the reserved fields == sizeof */
_Static_assert(52 +
                   sizeof(((FB_EDM *)0)->aReserved0) +
                   sizeof(((FB_EDM *)0)->aReserved1) +
                   sizeof(((FB_EDM *)0)->aReserved2) +
                   sizeof(((FB_EDM *)0)->aReserved3) +
                   sizeof(((FB_EDM *)0)->aReserved4) +
                   sizeof(((FB_EDM *)0)->aReserved5) ==
                   80,
               "FB_EDM has implicit padding");

/* ---------------- FB_RS (ABI §9, manual §4.10.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_RS, bReset, 8);
SL_AT(FB_RS, bSet, 9);
/* group link inputs */
SL_AT(FB_RS, bRun, 16);
SL_AT(FB_RS, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_RS, wInputActive, 20);
SL_AT(FB_RS, wInputNegated, 22);
/* outputs: output base 24 + the manual's output Offset column */
SL_AT(FB_RS, bRsOut, 24 + 1);
/* info data, private state, size */
SL_AT(FB_RS, nState, 32);
SL_AT(FB_RS, nDiag, 34);
_Static_assert(offsetof(FB_RS, stPrivate) == 40, "offset of FB_RS.stPrivate");
_Static_assert(offsetof(FB_RS, stPrivate) % 8 == 0, "FB_RS private state 8-aligned");
_Static_assert(sizeof(FB_RS) == 104, "size of FB_RS");
_Static_assert(sizeof(FB_RS) % 8 == 0, "size of FB_RS is a multiple of 8");
SL_SIZE(FB_RS, bReset, 1);
SL_SIZE(FB_RS, bSet, 1);
SL_SIZE(FB_RS, bRun, 1);
SL_SIZE(FB_RS, bErrAck, 1);
SL_SIZE(FB_RS, wInputActive, 2);
SL_SIZE(FB_RS, wInputNegated, 2);
SL_SIZE(FB_RS, bRsOut, 1);
SL_SIZE(FB_RS, nState, 1);
SL_SIZE(FB_RS, nDiag, 2);
SL_SIZE(FB_RS, stPrivate, 64);
/* no implicit padding: 76 bytes of named fields + the reserved fields == sizeof */
_Static_assert(76 +
                   sizeof(((FB_RS *)0)->aReserved0) +
                   sizeof(((FB_RS *)0)->aReserved1) +
                   sizeof(((FB_RS *)0)->aReserved2) +
                   sizeof(((FB_RS *)0)->aReserved3) +
                   sizeof(((FB_RS *)0)->aReserved4) +
                   sizeof(((FB_RS *)0)->aReserved5) +
                   sizeof(((FB_RS *)0)->aReserved6) ==
                   104,
               "FB_RS has implicit padding");

/* ---------------- FB_SR (ABI §9, manual §4.11.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_SR, bReset, 8);
SL_AT(FB_SR, bSet, 9);
/* group link inputs */
SL_AT(FB_SR, bRun, 16);
SL_AT(FB_SR, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_SR, wInputActive, 20);
SL_AT(FB_SR, wInputNegated, 22);
/* outputs: output base 24 + the manual's output Offset column */
SL_AT(FB_SR, bSrOut, 24 + 1);
/* info data, private state, size */
SL_AT(FB_SR, nState, 32);
SL_AT(FB_SR, nDiag, 34);
_Static_assert(offsetof(FB_SR, stPrivate) == 40, "offset of FB_SR.stPrivate");
_Static_assert(offsetof(FB_SR, stPrivate) % 8 == 0, "FB_SR private state 8-aligned");
_Static_assert(sizeof(FB_SR) == 104, "size of FB_SR");
_Static_assert(sizeof(FB_SR) % 8 == 0, "size of FB_SR is a multiple of 8");
SL_SIZE(FB_SR, bReset, 1);
SL_SIZE(FB_SR, bSet, 1);
SL_SIZE(FB_SR, bRun, 1);
SL_SIZE(FB_SR, bErrAck, 1);
SL_SIZE(FB_SR, wInputActive, 2);
SL_SIZE(FB_SR, wInputNegated, 2);
SL_SIZE(FB_SR, bSrOut, 1);
SL_SIZE(FB_SR, nState, 1);
SL_SIZE(FB_SR, nDiag, 2);
SL_SIZE(FB_SR, stPrivate, 64);
/* no implicit padding: 76 bytes of named fields + the reserved fields == sizeof */
_Static_assert(76 +
                   sizeof(((FB_SR *)0)->aReserved0) +
                   sizeof(((FB_SR *)0)->aReserved1) +
                   sizeof(((FB_SR *)0)->aReserved2) +
                   sizeof(((FB_SR *)0)->aReserved3) +
                   sizeof(((FB_SR *)0)->aReserved4) +
                   sizeof(((FB_SR *)0)->aReserved5) +
                   sizeof(((FB_SR *)0)->aReserved6) ==
                   104,
               "FB_SR has implicit padding");

/* ---------------- FB_TON (ABI §9, manual §4.12.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_TON, bTonIn1, 8);
/* group link inputs */
SL_AT(FB_TON, bRun, 16);
SL_AT(FB_TON, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_TON, tDelay, 20);
SL_AT(FB_TON, nTimeBase, 24);
SL_AT(FB_TON, wInputActive, 26);
SL_AT(FB_TON, wInputNegated, 28);
/* outputs: output base 32 + the manual's output Offset column */
SL_AT(FB_TON, bTonOut, 32 + 1);
/* info data, private state, size */
SL_AT(FB_TON, nState, 40);
SL_AT(FB_TON, nDiag, 42);
_Static_assert(offsetof(FB_TON, stPrivate) == 48, "offset of FB_TON.stPrivate");
_Static_assert(offsetof(FB_TON, stPrivate) % 8 == 0, "FB_TON private state 8-aligned");
_Static_assert(sizeof(FB_TON) == 112, "size of FB_TON");
_Static_assert(sizeof(FB_TON) % 8 == 0, "size of FB_TON is a multiple of 8");
SL_SIZE(FB_TON, bTonIn1, 1);
SL_SIZE(FB_TON, bRun, 1);
SL_SIZE(FB_TON, bErrAck, 1);
SL_SIZE(FB_TON, tDelay, 4);
SL_SIZE(FB_TON, nTimeBase, 2);
SL_SIZE(FB_TON, wInputActive, 2);
SL_SIZE(FB_TON, wInputNegated, 2);
SL_SIZE(FB_TON, bTonOut, 1);
SL_SIZE(FB_TON, nState, 1);
SL_SIZE(FB_TON, nDiag, 2);
SL_SIZE(FB_TON, stPrivate, 64);
/* no implicit padding: 81 bytes of named fields + the reserved fields == sizeof */
_Static_assert(81 +
                   sizeof(((FB_TON *)0)->aReserved0) +
                   sizeof(((FB_TON *)0)->aReserved1) +
                   sizeof(((FB_TON *)0)->aReserved2) +
                   sizeof(((FB_TON *)0)->aReserved3) +
                   sizeof(((FB_TON *)0)->aReserved4) +
                   sizeof(((FB_TON *)0)->aReserved5) +
                   sizeof(((FB_TON *)0)->aReserved6) +
                   sizeof(((FB_TON *)0)->aReserved7) ==
                   112,
               "FB_TON has implicit padding");

/* ---------------- FB_TON2 (ABI §9, manual §4.13.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_TON2, bTonIn1, 8);
SL_AT(FB_TON2, bEnable, 9);
/* group link inputs */
SL_AT(FB_TON2, bRun, 16);
SL_AT(FB_TON2, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_TON2, tDelay, 20);
SL_AT(FB_TON2, nTimeBase, 24);
SL_AT(FB_TON2, wInputActive, 26);
SL_AT(FB_TON2, wInputNegated, 28);
SL_AT(FB_TON2, dwOptions, 32);
/* outputs: output base 40 + the manual's output Offset column */
SL_AT(FB_TON2, bTonOut, 40 + 1);
/* info data, private state, size */
SL_AT(FB_TON2, nState, 48);
SL_AT(FB_TON2, nDiag, 50);
_Static_assert(offsetof(FB_TON2, stPrivate) == 56, "offset of FB_TON2.stPrivate");
_Static_assert(offsetof(FB_TON2, stPrivate) % 8 == 0, "FB_TON2 private state 8-aligned");
_Static_assert(sizeof(FB_TON2) == 120, "size of FB_TON2");
_Static_assert(sizeof(FB_TON2) % 8 == 0, "size of FB_TON2 is a multiple of 8");
SL_SIZE(FB_TON2, bTonIn1, 1);
SL_SIZE(FB_TON2, bEnable, 1);
SL_SIZE(FB_TON2, bRun, 1);
SL_SIZE(FB_TON2, bErrAck, 1);
SL_SIZE(FB_TON2, tDelay, 4);
SL_SIZE(FB_TON2, nTimeBase, 2);
SL_SIZE(FB_TON2, wInputActive, 2);
SL_SIZE(FB_TON2, wInputNegated, 2);
SL_SIZE(FB_TON2, dwOptions, 4);
SL_SIZE(FB_TON2, bTonOut, 1);
SL_SIZE(FB_TON2, nState, 1);
SL_SIZE(FB_TON2, nDiag, 2);
SL_SIZE(FB_TON2, stPrivate, 64);
/* no implicit padding: 86 bytes of named fields + the reserved fields == sizeof */
_Static_assert(86 +
                   sizeof(((FB_TON2 *)0)->aReserved0) +
                   sizeof(((FB_TON2 *)0)->aReserved1) +
                   sizeof(((FB_TON2 *)0)->aReserved2) +
                   sizeof(((FB_TON2 *)0)->aReserved3) +
                   sizeof(((FB_TON2 *)0)->aReserved4) +
                   sizeof(((FB_TON2 *)0)->aReserved5) +
                   sizeof(((FB_TON2 *)0)->aReserved6) +
                   sizeof(((FB_TON2 *)0)->aReserved7) +
                   sizeof(((FB_TON2 *)0)->aReserved8) ==
                   120,
               "FB_TON2 has implicit padding");

/* ---------------- FB_TOF (ABI §9, manual §4.14.2) ---------------- */
/* inputs: the manual's input Offset column (absolute) */
SL_AT(FB_TOF, bTofIn1, 8);
/* group link inputs */
SL_AT(FB_TOF, bRun, 16);
SL_AT(FB_TOF, bErrAck, 17);
/* parameters (header) */
SL_AT(FB_TOF, tDelay, 20);
SL_AT(FB_TOF, nTimeBase, 24);
SL_AT(FB_TOF, wInputActive, 26);
SL_AT(FB_TOF, wInputNegated, 28);
/* outputs: output base 32 + the manual's output Offset column */
SL_AT(FB_TOF, bTofOut, 32 + 1);
/* info data, private state, size */
SL_AT(FB_TOF, nState, 40);
SL_AT(FB_TOF, nDiag, 42);
_Static_assert(offsetof(FB_TOF, stPrivate) == 48, "offset of FB_TOF.stPrivate");
_Static_assert(offsetof(FB_TOF, stPrivate) % 8 == 0, "FB_TOF private state 8-aligned");
_Static_assert(sizeof(FB_TOF) == 112, "size of FB_TOF");
_Static_assert(sizeof(FB_TOF) % 8 == 0, "size of FB_TOF is a multiple of 8");
SL_SIZE(FB_TOF, bTofIn1, 1);
SL_SIZE(FB_TOF, bRun, 1);
SL_SIZE(FB_TOF, bErrAck, 1);
SL_SIZE(FB_TOF, tDelay, 4);
SL_SIZE(FB_TOF, nTimeBase, 2);
SL_SIZE(FB_TOF, wInputActive, 2);
SL_SIZE(FB_TOF, wInputNegated, 2);
SL_SIZE(FB_TOF, bTofOut, 1);
SL_SIZE(FB_TOF, nState, 1);
SL_SIZE(FB_TOF, nDiag, 2);
SL_SIZE(FB_TOF, stPrivate, 64);
/* no implicit padding: 81 bytes of named fields + the reserved fields == sizeof */
_Static_assert(81 +
                   sizeof(((FB_TOF *)0)->aReserved0) +
                   sizeof(((FB_TOF *)0)->aReserved1) +
                   sizeof(((FB_TOF *)0)->aReserved2) +
                   sizeof(((FB_TOF *)0)->aReserved3) +
                   sizeof(((FB_TOF *)0)->aReserved4) +
                   sizeof(((FB_TOF *)0)->aReserved5) +
                   sizeof(((FB_TOF *)0)->aReserved6) +
                   sizeof(((FB_TOF *)0)->aReserved7) ==
                   112,
               "FB_TOF has implicit padding");

/* ---------------- constants (ABI §2, §5, §6; manual status and diag tables) ---------------- */
_Static_assert(sizeof(SL_BOOL) == 1, "SL_BOOL is uint8_t");
_Static_assert(SL_OK == 0 && SL_E_NULL == -1 && SL_E_CONFIG == -2 && SL_E_PARAM_CHANGED == -3 &&
                   SL_E_CORRUPT == -4 && SL_E_INVALID_BOOL == -5 && SL_E_CLOCK == -6,
               "status codes (ABI §5)");
_Static_assert(SL_OPT_EDM1 == 1 && SL_OPT_EDM2 == 2 && SL_OPT_SAFE_INPUTS_AFTER_DISC == 4 &&
                   SL_OPT_MANUAL_RESTART == 8 && SL_OPT_FUNCTION_TEST == 16,
               "option bits (ABI §6)");
/* Unsigned 32-bit constants are unsigned in C too, whatever the platform's int (build.rs
 * writes them with U): a literal above INT_MAX, or 1 << 31, would be signed or overflow. */
#define SL_IS_UNSIGNED(x) _Generic((x), unsigned int: 1, unsigned long: 1, default: 0)
_Static_assert(SL_IS_UNSIGNED(SL_SBT_TIME_MAX) && SL_SBT_TIME_MAX == 4294967000u &&
                   SL_IS_UNSIGNED(SL_OPT_EDM1) && SL_IS_UNSIGNED(SL_FSOE_OPT_PIN_CONNID) &&
                   SL_IS_UNSIGNED(SL_SF_TIME_MAX) && SL_IS_UNSIGNED(SL_TIME_PARAM_MAX),
               "u32 constants are unsigned");
/* Text IDs as the manual lists them (§4.21: 0x4090). */
_Static_assert(SL_TEXT_LIMIT_MIN_ABOVE_MAX == 0x4090, "Text ID of LIMIT Minimum > Maximum");
_Static_assert(SL_STATE_RUN == 1 && SL_STATE_STOP == 2 && SL_STATE_SAFE == 3 &&
                   SL_STATE_ERROR == 4 && SL_STATE_RESET == 5 && SL_STATE_START == 6 &&
                   SL_STATE_ERRORDELAY == 7 && SL_STATE_DELAYOUT == 8 && SL_STATE_FUNCTEST == 9,
               "status values (manual §4.4.2, §4.5.2)");
_Static_assert(SL_DIAG_DISC1 == 0x0001 && SL_DIAG_DISC2 == 0x0002 && SL_DIAG_DISC3 == 0x0004 &&
                   SL_DIAG_DISC4 == 0x0008 && SL_DIAG_EDM1 == 0x0010 && SL_DIAG_EDM2 == 0x0020 &&
                   SL_DIAG_SAFE_IN_DISC1 == 0x0100 && SL_DIAG_SAFE_IN_DISC2 == 0x0200 &&
                   SL_DIAG_SAFE_IN_DISC3 == 0x0400 && SL_DIAG_SAFE_IN_DISC4 == 0x0800,
               "diagnostic bits (manual §4.4.2, §4.5.2)");
_Static_assert(SL_E_RESTORE == -10, "SL_E_RESTORE (docs/semantics.md T13)");
_Static_assert(SL_OPT_MUTING_SEQUENTIAL == 0x100 && SL_OPT_MUTING_BACKWARDS == 0x200 &&
                   SL_OPT_MUTING_OSSD_CHECK_OPTIONAL == 0x400 &&
                   SL_OPT_TON2_REMAINING_TIME == 0x100,
               "block option bits (ABI §9: MUTING bits 8, 9, 10; TON2 bit 8)");
_Static_assert(SL_STATE_TWOHAND_1BUTTON == 11 && SL_STATE_TWOHAND_2BUTTON == 12 &&
                   SL_STATE_TWOHAND_RELEASE == 13,
               "TWOHAND status values (manual §4.7.2)");
_Static_assert(SL_STATE_MUTING_MUTING1 == 9 && SL_STATE_MUTING_MUTING2 == 10 &&
                   SL_STATE_MUTING_MUTING3 == 11 && SL_STATE_MUTING_MUTING4 == 12 &&
                   SL_STATE_MUTING_MUTING5 == 13 && SL_STATE_MUTING_MUTING6 == 14 &&
                   SL_STATE_MUTING_MUTING7 == 15 && SL_STATE_MUTING_MUTING8 == 16 &&
                   SL_STATE_MUTING_MUTING9 == 17,
               "MUTING status values (manual §4.8.2)");
_Static_assert(SL_STATE_EDM_MONOFF == 14 && SL_STATE_EDM_MONON == 15,
               "EDM status values (manual §4.9.2)");
_Static_assert(SL_STATE_RS_SET == 9 && SL_STATE_SR_SET == 9,
               "RS/SR status value SET (manual §4.10.2, §4.11.2)");
_Static_assert(SL_STATE_TON_DELAYIN == 9 && SL_STATE_TON2_DELAYIN == 9,
               "TON/TON2 status value DELAYIN (manual §4.12.2, §4.13.2)");
_Static_assert(SL_DIAG_OPMODE_DISC == 0x0001, "OPMODE diag bit 0 (manual §4.3.2)");
_Static_assert(SL_DIAG_TWOHAND_PAIRS == 0x0004 && SL_DIAG_TWOHAND_ERROR == 0x0040 &&
                   SL_DIAG_TWOHAND_SAFE_IN_PAIRS == 0x0400,
               "TWOHAND diag bits 2, 6, 10 (manual §4.7.2)");
_Static_assert(SL_DIAG_MUTING_SEQUENCE == 0x0040 && SL_DIAG_MUTING_MAX_TIME == 0x0080,
               "MUTING diag bits 6, 7 (manual §4.8.2)");
_Static_assert(SL_DIAG_EDM_SWITCH_OFF == 0x0001 && SL_DIAG_EDM_SWITCH_ON == 0x0002,
               "EDM diag bits 0, 1 (manual §4.9.2)");
_Static_assert(SL_DIAG_TON2_RESTORE == 0x1000 && SL_DIAG_PARAM_CHANGED == 0x2000 &&
                   SL_DIAG_CLOCK == 0x4000 && SL_DIAG_CORRUPT == 0x8000,
               "library diag bits 12-15 (docs/semantics.md C11, T13)");

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
    SL_PRINT(FB_XOR, bXor1In1);
    SL_PRINT(FB_XOR, bXor2In8);
    SL_PRINT(FB_XOR, bRun);
    SL_PRINT(FB_XOR, bErrAck);
    SL_PRINT(FB_XOR, wInputActive);
    SL_PRINT(FB_XOR, bXorOut1);
    SL_PRINT(FB_XOR, bXorOut8);
    SL_PRINT(FB_XOR, nState);
    SL_PRINT(FB_XOR, nDiag);
    SL_PRINT(FB_XOR, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_XOR", (unsigned)sizeof(FB_XOR));
    SL_PRINT(FB_DECOUPLE, bDecIn1);
    SL_PRINT(FB_DECOUPLE, bDecIn8);
    SL_PRINT(FB_DECOUPLE, bRun);
    SL_PRINT(FB_DECOUPLE, bErrAck);
    SL_PRINT(FB_DECOUPLE, wInputActive);
    SL_PRINT(FB_DECOUPLE, bDecOut1);
    SL_PRINT(FB_DECOUPLE, bDecOut8);
    SL_PRINT(FB_DECOUPLE, nState);
    SL_PRINT(FB_DECOUPLE, nDiag);
    SL_PRINT(FB_DECOUPLE, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_DECOUPLE", (unsigned)sizeof(FB_DECOUPLE));
    SL_PRINT(FB_OPMODE, bRestart);
    SL_PRINT(FB_OPMODE, bOpIn8);
    SL_PRINT(FB_OPMODE, bRun);
    SL_PRINT(FB_OPMODE, bErrAck);
    SL_PRINT(FB_OPMODE, tDiscTime);
    SL_PRINT(FB_OPMODE, wInputActive);
    SL_PRINT(FB_OPMODE, dwOptions);
    SL_PRINT(FB_OPMODE, bError);
    SL_PRINT(FB_OPMODE, bOpOut8);
    SL_PRINT(FB_OPMODE, nState);
    SL_PRINT(FB_OPMODE, nDiag);
    SL_PRINT(FB_OPMODE, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_OPMODE", (unsigned)sizeof(FB_OPMODE));
    SL_PRINT(FB_TWOHAND, bTwoHand1);
    SL_PRINT(FB_TWOHAND, bTwoHand4);
    SL_PRINT(FB_TWOHAND, bRun);
    SL_PRINT(FB_TWOHAND, bErrAck);
    SL_PRINT(FB_TWOHAND, tDiscTime12);
    SL_PRINT(FB_TWOHAND, tDiscTime34);
    SL_PRINT(FB_TWOHAND, tDiscTimePairs);
    SL_PRINT(FB_TWOHAND, wInputActive);
    SL_PRINT(FB_TWOHAND, wInputNegated);
    SL_PRINT(FB_TWOHAND, dwOptions);
    SL_PRINT(FB_TWOHAND, bError);
    SL_PRINT(FB_TWOHAND, bTwoHandOut);
    SL_PRINT(FB_TWOHAND, nState);
    SL_PRINT(FB_TWOHAND, nDiag);
    SL_PRINT(FB_TWOHAND, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_TWOHAND", (unsigned)sizeof(FB_TWOHAND));
    SL_PRINT(FB_MUTING, bMutingEnable);
    SL_PRINT(FB_MUTING, bMutingIn4);
    SL_PRINT(FB_MUTING, bRun);
    SL_PRINT(FB_MUTING, bErrAck);
    SL_PRINT(FB_MUTING, tDiscTime12);
    SL_PRINT(FB_MUTING, tDiscTimeOSSD);
    SL_PRINT(FB_MUTING, tDiscTime34);
    SL_PRINT(FB_MUTING, tFilterTime);
    SL_PRINT(FB_MUTING, tMaxMutingTime);
    SL_PRINT(FB_MUTING, tMuteDelOutDelay);
    SL_PRINT(FB_MUTING, wInputActive);
    SL_PRINT(FB_MUTING, wInputNegated);
    SL_PRINT(FB_MUTING, dwOptions);
    SL_PRINT(FB_MUTING, bError);
    SL_PRINT(FB_MUTING, bMuteDelOut);
    SL_PRINT(FB_MUTING, nState);
    SL_PRINT(FB_MUTING, nDiag);
    SL_PRINT(FB_MUTING, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_MUTING", (unsigned)sizeof(FB_MUTING));
    SL_PRINT(FB_EDM, bMon1);
    SL_PRINT(FB_EDM, bMon2);
    SL_PRINT(FB_EDM, bRun);
    SL_PRINT(FB_EDM, bErrAck);
    SL_PRINT(FB_EDM, tSwitchOnTime);
    SL_PRINT(FB_EDM, tSwitchOffTime);
    SL_PRINT(FB_EDM, wInputActive);
    SL_PRINT(FB_EDM, wInputNegated);
    SL_PRINT(FB_EDM, bError);
    SL_PRINT(FB_EDM, bError);
    SL_PRINT(FB_EDM, nState);
    SL_PRINT(FB_EDM, nDiag);
    SL_PRINT(FB_EDM, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_EDM", (unsigned)sizeof(FB_EDM));
    SL_PRINT(FB_RS, bReset);
    SL_PRINT(FB_RS, bSet);
    SL_PRINT(FB_RS, bRun);
    SL_PRINT(FB_RS, bErrAck);
    SL_PRINT(FB_RS, wInputActive);
    SL_PRINT(FB_RS, wInputNegated);
    SL_PRINT(FB_RS, bRsOut);
    SL_PRINT(FB_RS, bRsOut);
    SL_PRINT(FB_RS, nState);
    SL_PRINT(FB_RS, nDiag);
    SL_PRINT(FB_RS, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_RS", (unsigned)sizeof(FB_RS));
    SL_PRINT(FB_SR, bReset);
    SL_PRINT(FB_SR, bSet);
    SL_PRINT(FB_SR, bRun);
    SL_PRINT(FB_SR, bErrAck);
    SL_PRINT(FB_SR, wInputActive);
    SL_PRINT(FB_SR, wInputNegated);
    SL_PRINT(FB_SR, bSrOut);
    SL_PRINT(FB_SR, bSrOut);
    SL_PRINT(FB_SR, nState);
    SL_PRINT(FB_SR, nDiag);
    SL_PRINT(FB_SR, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_SR", (unsigned)sizeof(FB_SR));
    SL_PRINT(FB_TON, bTonIn1);
    SL_PRINT(FB_TON, bTonIn1);
    SL_PRINT(FB_TON, bRun);
    SL_PRINT(FB_TON, bErrAck);
    SL_PRINT(FB_TON, tDelay);
    SL_PRINT(FB_TON, nTimeBase);
    SL_PRINT(FB_TON, wInputActive);
    SL_PRINT(FB_TON, wInputNegated);
    SL_PRINT(FB_TON, bTonOut);
    SL_PRINT(FB_TON, bTonOut);
    SL_PRINT(FB_TON, nState);
    SL_PRINT(FB_TON, nDiag);
    SL_PRINT(FB_TON, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_TON", (unsigned)sizeof(FB_TON));
    SL_PRINT(FB_TON2, bTonIn1);
    SL_PRINT(FB_TON2, bEnable);
    SL_PRINT(FB_TON2, bRun);
    SL_PRINT(FB_TON2, bErrAck);
    SL_PRINT(FB_TON2, tDelay);
    SL_PRINT(FB_TON2, nTimeBase);
    SL_PRINT(FB_TON2, wInputActive);
    SL_PRINT(FB_TON2, wInputNegated);
    SL_PRINT(FB_TON2, dwOptions);
    SL_PRINT(FB_TON2, bTonOut);
    SL_PRINT(FB_TON2, bTonOut);
    SL_PRINT(FB_TON2, nState);
    SL_PRINT(FB_TON2, nDiag);
    SL_PRINT(FB_TON2, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_TON2", (unsigned)sizeof(FB_TON2));
    SL_PRINT(FB_TOF, bTofIn1);
    SL_PRINT(FB_TOF, bTofIn1);
    SL_PRINT(FB_TOF, bRun);
    SL_PRINT(FB_TOF, bErrAck);
    SL_PRINT(FB_TOF, tDelay);
    SL_PRINT(FB_TOF, nTimeBase);
    SL_PRINT(FB_TOF, wInputActive);
    SL_PRINT(FB_TOF, wInputNegated);
    SL_PRINT(FB_TOF, bTofOut);
    SL_PRINT(FB_TOF, bTofOut);
    SL_PRINT(FB_TOF, nState);
    SL_PRINT(FB_TOF, nDiag);
    SL_PRINT(FB_TOF, stPrivate);
    printf("  %-10s sizeof %u\n", "FB_TOF", (unsigned)sizeof(FB_TOF));
    printf("layout ok\n");
    return 0;
}
