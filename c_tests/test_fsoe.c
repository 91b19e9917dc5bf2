/*
 * The FSoE connection through the C ABI (ABI-2 §13; docs/semantics.md FS1-FS16): the CRC
 * known-answer vectors of fsoe.md §12.1, the codec on caller buffers (sl_fsoe_frame_len,
 * sl_fsoe_frame_encode, sl_fsoe_frame_decode), and a master and a slave of this library
 * reproducing the 13-frame trace of fsoe.md §12.2 byte for byte through sl_fsoe_cycle,
 * with SL_E_LENGTH / SL_E_NULL for refused buffers.
 */
#include "harness.h"

static void fsoe_crc_and_codec(void)
{
    static const uint8_t two[2] = {0x12, 0x34};
    static const uint8_t dead[2] = {0xDE, 0xAD};
    static const uint8_t reset1[6] = {0x2A, 0x00, 0x86, 0xF8, 0x00, 0x00};
    uint8_t frame[SL_FSOE_FRAME_MAX];
    uint8_t zero = 0;
    size_t len = 0;
    uint16_t seq = 1;
    SL_FSOE_FRAME out;
    h_begin("FSoE CRC vectors and frame codec (FS1, FS2, FS16)");
    CHECK_INT(sl_fsoe_crc(0, 0, 1, SL_FSOE_CMD_SESSION, 0, two, 2), 0x4D07);
    CHECK_INT(sl_fsoe_crc(0, 0, 1, SL_FSOE_CMD_SESSION, 0, two, 1), 0xA176);
    CHECK_INT(sl_fsoe_crc(0xABCD, 7, 2, SL_FSOE_CMD_PROCESSDATA, 1, dead, 2), 0xBC47);
    CHECK_INT(sl_fsoe_frame_len(1), 6);
    CHECK_INT(sl_fsoe_frame_len(4), 11);
    CHECK_INT(sl_fsoe_frame_len(32), 67);
    CHECK_INT(sl_fsoe_frame_len(3), 0);
    CHECK_INT(sl_fsoe_frame_encode(frame, sizeof frame, &len, SL_FSOE_CMD_RESET, &zero, 1, 0, 0,
                                   &seq, 0, 0),
              SL_OK);
    CHECK_INT((long long)len, 6);
    CHECK(memcmp(frame, reset1, 6) == 0, "1-byte Reset frame 2A 00 86 F8 00 00");
    CHECK_INT(sl_fsoe_frame_encode(frame, 5, &len, SL_FSOE_CMD_RESET, &zero, 1, 0, 0, &seq, 0, 0),
              SL_E_LENGTH);
    CHECK_INT(sl_fsoe_frame_encode(frame, sizeof frame, &len, 0x99, &zero, 1, 0, 0, &seq, 0, 0),
              SL_E_FRAME);
    CHECK_INT(sl_fsoe_frame_decode(reset1, 6, 1, 0, &seq, 0, 0, &out), SL_OK);
    CHECK_INT(out.nCmd, SL_FSOE_CMD_RESET);
    frame[0] = 0x2A;
    frame[1] = 0x00;
    frame[2] = 0x87; /* CRC_0 low byte flipped */
    frame[3] = 0xF8;
    frame[4] = 0;
    frame[5] = 0;
    CHECK_INT(sl_fsoe_frame_decode(frame, 6, 1, 0, &seq, 0, 0, &out), SL_E_FRAME);
    CHECK_INT(out.nResetCode, 4);
    CHECK_INT(sl_fsoe_frame_decode(frame, 7, 1, 0, &seq, 0, 0, &out), SL_E_LENGTH);
    CHECK_INT(sl_fsoe_frame_decode(NULL, 6, 1, 0, &seq, 0, 0, &out), SL_E_NULL);
    CHECK(sizeof(SL_FSOE_FRAME) == 40 && sizeof(SL_FSOE_CONN) == 624, "struct sizes");
    h_end();
}

static void fsoe_conn_setup(SL_FSOE_CONN *c, uint16_t role, uint16_t seed)
{
    memset(c, 0, sizeof *c);
    c->nConnectionId = 7;
    c->nFsoeAddress = 3;
    c->nRole = role;
    c->nTxDataLen = 4;
    c->nRxDataLen = 4;
    c->tWatchdogTime = 100;
    c->nSessionIdSeed = seed;
}

static void fsoe_trace(void)
{
    static const uint8_t want[13][11] = {
        {0x2A, 0x00, 0x00, 0xC4, 0x2D, 0x00, 0x00, 0xB9, 0x14, 0x00, 0x00},
        {0x2A, 0x00, 0x00, 0xC4, 0x2D, 0x00, 0x00, 0xB9, 0x14, 0x00, 0x00},
        {0x4E, 0x12, 0x34, 0x07, 0x4D, 0x00, 0x00, 0x43, 0x4E, 0x00, 0x00},
        {0x4E, 0x78, 0x56, 0xD3, 0xB9, 0x00, 0x00, 0x38, 0x73, 0x00, 0x00},
        {0x64, 0x07, 0x00, 0x9F, 0x29, 0x03, 0x00, 0xF0, 0x07, 0x07, 0x00},
        {0x64, 0x07, 0x00, 0x5B, 0x5D, 0x03, 0x00, 0x03, 0xA3, 0x07, 0x00},
        {0x52, 0x02, 0x00, 0xA1, 0xA5, 0x64, 0x00, 0xD8, 0x52, 0x07, 0x00},
        {0x52, 0x02, 0x00, 0x97, 0xD1, 0x64, 0x00, 0x8E, 0xDA, 0x07, 0x00},
        {0x52, 0x00, 0x00, 0x39, 0xA6, 0x00, 0x00, 0xBB, 0x5B, 0x07, 0x00},
        {0x52, 0x00, 0x00, 0xAD, 0x00, 0x00, 0x00, 0x98, 0xA4, 0x07, 0x00},
        {0x08, 0x00, 0x00, 0xA6, 0x00, 0x00, 0x00, 0x4E, 0x1A, 0x07, 0x00},
        {0x36, 0x01, 0x02, 0xC1, 0x8B, 0x03, 0x04, 0xEB, 0xC3, 0x07, 0x00},
        {0x36, 0xAA, 0x55, 0xA0, 0x38, 0x00, 0xFF, 0x07, 0x36, 0x07, 0x00},
    };
    SL_FSOE_CONN m;
    SL_FSOE_CONN s;
    uint8_t buf[2][SL_FSOE_FRAME_MAX];
    size_t len = 0;
    int k;
    h_begin("FSoE master and slave: fsoe.md §12.2 trace byte for byte (FS2-FS4)");
    fsoe_conn_setup(&m, SL_FSOE_ROLE_MASTER, 0x3412);
    fsoe_conn_setup(&s, SL_FSOE_ROLE_SLAVE, 0x5678);
    s.bRun = 1;
    s.aTxSafeData[0] = 1;
    s.aTxSafeData[1] = 2;
    s.aTxSafeData[2] = 3;
    s.aTxSafeData[3] = 4;
    CHECK_INT(sl_fsoe_init(&m), SL_OK);
    CHECK_INT(sl_fsoe_init(&s), SL_OK);
    CHECK_INT(m.nState, SL_FSOE_STATE_RESET);
    CHECK_INT(sl_fsoe_cycle(&m, 0, NULL, 0, buf[0], 10, &len), SL_E_LENGTH);
    CHECK_INT((long long)len, 0);
    CHECK_INT(sl_fsoe_cycle(&m, 0, NULL, 0, buf[0], sizeof buf[0], NULL), SL_E_NULL);
    CHECK_INT(sl_fsoe_cycle(&m, 0, NULL, 0, buf[0], sizeof buf[0], &len), SL_OK);
    CHECK_INT((long long)len, 11);
    CHECK(memcmp(buf[0], want[0], 11) == 0, "frame 1");
    for (k = 1; k < 13; k++) {
        SL_FSOE_CONN *rx = (k % 2 == 1) ? &s : &m;
        if (k == 12) {
            m.bRun = 1;
            m.aTxSafeData[0] = 0xAA;
            m.aTxSafeData[1] = 0x55;
            m.aTxSafeData[2] = 0x00;
            m.aTxSafeData[3] = 0xFF;
        }
        CHECK_INT(sl_fsoe_cycle(rx, (uint32_t)k, buf[(k - 1) % 2], 11, buf[k % 2],
                                sizeof buf[0], &len),
                  SL_OK);
        CHECK_INT((long long)len, 11);
        CHECK(memcmp(buf[k % 2], want[k], 11) == 0, "trace frame");
    }
    CHECK_INT(m.nState, SL_FSOE_STATE_DATA);
    CHECK_INT(m.bDataValid, 1);
    CHECK_INT(m.aRxSafeData[3], 4);
    CHECK_INT(sl_fsoe_cycle(&s, 20, buf[0], 11, buf[1], sizeof buf[1], &len), SL_OK);
    CHECK_INT(s.bDataValid, 1);
    CHECK_INT(s.aRxSafeData[0], 0xAA);
    CHECK_INT(s.aRxSafeData[3], 0xFF);
    CHECK_INT(s.nDiag, 0);
    /* The slave's watchdog: silence for 100 ms -> Reset 5, bComErr. */
    CHECK_INT(sl_fsoe_cycle(&s, 120, NULL, 0, buf[1], sizeof buf[1], &len), SL_OK);
    CHECK_INT((long long)len, 7 + 4);
    CHECK_INT(buf[1][1], SL_FSOE_RESET_WD_EXPIRED);
    CHECK_INT(s.nState, SL_FSOE_STATE_RESET);
    CHECK_INT(s.bComErr, 1);
    CHECK_INT(s.nDiag, 5 | SL_FSOE_DIAG_SLAVE_ERROR | SL_FSOE_DIAG_STARTUP);
    CHECK_STR(sl_status_str(SL_E_LENGTH) != NULL ? "text" : "", "text");
    h_end();
}

void run_fsoe_scenarios(void)
{
    fsoe_crc_and_codec();
    fsoe_trace();
}
