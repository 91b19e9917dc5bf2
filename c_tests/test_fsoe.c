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

/* One node of the group scenario: a group with its tables, a connection and blocks. */
typedef struct FSOE_NODE {
    SL_GROUP g;
    SL_MEMBER members[4];
    SL_LINK links[8];
    SL_FSOE_CONN c;
    FB_ESTOP estop;
    FB_DECOUPLE dec;
    FB_CONNECTION_SHUTDOWN shut;
} FSOE_NODE;

static int fsoe_node_cycle(FSOE_NODE *n, uint32_t t)
{
    n->c.nSessionIdSeed = (uint16_t)((t * 2654435761u) >> 16) | 1u;
    return sl_group_cycle(&n->g, n->members, n->links, t);
}

/* The black channel: one node's transmit mailbox into the other's receive mailbox. */
static void fsoe_carry(const SL_FSOE_CONN *from, SL_FSOE_CONN *to)
{
    memcpy(to->aRxFrame, from->aTxFrame, sizeof to->aRxFrame);
    to->nRxFrameLen = from->nTxFrameLen;
}

/* One bus cycle of the pair; `slave_alive` 0: the slave neither runs nor answers. */
static void fsoe_bus(FSOE_NODE *m, FSOE_NODE *s, uint32_t t, int slave_alive)
{
    if (slave_alive) {
        fsoe_carry(&s->c, &m->c);
    }
    CHECK_INT(fsoe_node_cycle(m, t), SL_OK);
    if (slave_alive) {
        fsoe_carry(&m->c, &s->c);
        CHECK_INT(fsoe_node_cycle(s, t), SL_OK);
    }
}

static void fsoe_group(void)
{
    static FSOE_NODE m;
    static FSOE_NODE s;
    uint16_t idx = 0;
    uint32_t t = 0;
    uint32_t t_kill;
    int k;
    h_begin("FSoE connections in groups: RXBIT/TXBIT, START, ComErr diag 2, ErrAck, "
            "CONNECTION_SHUTDOWN (FS17-FS21, CS1-CS8)");
    memset(&m, 0, sizeof m);
    memset(&s, 0, sizeof s);
    fsoe_conn_setup(&m.c, SL_FSOE_ROLE_MASTER, 1);
    fsoe_conn_setup(&s.c, SL_FSOE_ROLE_SLAVE, 2);
    m.c.nTxDataLen = 2;
    m.c.nRxDataLen = 2;
    s.c.nTxDataLen = 2;
    s.c.nRxDataLen = 2;
    CHECK_INT(sl_fsoe_init(&m.c), SL_OK);
    CHECK_INT(sl_fsoe_init(&s.c), SL_OK);
    m.estop.wInputActive = 0x3;
    CHECK_INT(sl_estop_init(&m.estop), SL_OK);
    m.shut.nConnectionId = 7;
    m.shut.wInputActive = 0x1;
    CHECK_INT(sl_connection_shutdown_init(&m.shut), SL_OK);
    s.dec.wInputActive = 0x7;
    CHECK_INT(sl_decouple_init(&s.dec), SL_OK);
    CHECK_INT(sl_group_init(&m.g, m.members, 4, m.links, 8), SL_OK);
    CHECK_INT(sl_group_init(&s.g, s.members, 4, s.links, 8), SL_OK);
    /* Master: connection first, then the blocks. */
    CHECK_INT(sl_group_add_member(&m.g, m.members, SL_TYPE_FSOE_CONN, &m.c, &idx), SL_OK);
    CHECK_INT(idx, 0);
    CHECK_INT(sl_group_add_member(&m.g, m.members, SL_TYPE_ESTOP, &m.estop, &idx), SL_OK);
    CHECK_INT(sl_group_add_member(&m.g, m.members, SL_TYPE_CONNECTION_SHUTDOWN, &m.shut, &idx),
              SL_OK);
    CHECK_INT(sl_group_add_member(&m.g, m.members, SL_TYPE_FSOE_CONN, &s.c, &idx), SL_E_CONFIG);
    CHECK_INT(sl_group_add_link_kind(&m.g, m.members, m.links, SL_LINK_RXBIT, 0, 0, 1,
                                     (uint16_t)offsetof(FB_ESTOP, bEStopIn1)),
              SL_OK);
    CHECK_INT(sl_group_add_link_kind(&m.g, m.members, m.links, SL_LINK_RXBIT, 0, 1, 1,
                                     (uint16_t)offsetof(FB_ESTOP, bEStopIn2)),
              SL_OK);
    CHECK_INT(sl_group_add_link_kind(&m.g, m.members, m.links, SL_LINK_RXBIT, 0, 16, 1,
                                     (uint16_t)offsetof(FB_ESTOP, bRestart)),
              SL_E_CONFIG);
    CHECK_INT(sl_group_add_link_kind(&m.g, m.members, m.links, SL_LINK_TXBIT, 1,
                                     (uint16_t)offsetof(FB_ESTOP, bEStopOut), 0, 0),
              SL_OK);
    /* Slave ("remote safe I/O"): DecIn1/2 are sent as bits 0/1, bit 0 received -> DecIn3. */
    CHECK_INT(sl_group_add_member(&s.g, s.members, SL_TYPE_FSOE_CONN, &s.c, &idx), SL_OK);
    CHECK_INT(sl_group_add_member(&s.g, s.members, SL_TYPE_DECOUPLE, &s.dec, &idx), SL_OK);
    CHECK_INT(sl_group_add_link_kind(&s.g, s.members, s.links, SL_LINK_TXBIT, 1,
                                     (uint16_t)offsetof(FB_DECOUPLE, bDecOut1), 0, 0),
              SL_OK);
    CHECK_INT(sl_group_add_link_kind(&s.g, s.members, s.links, SL_LINK_TXBIT, 1,
                                     (uint16_t)offsetof(FB_DECOUPLE, bDecOut2), 0, 1),
              SL_OK);
    CHECK_INT(sl_group_add_link_kind(&s.g, s.members, s.links, SL_LINK_RXBIT, 0, 0, 1,
                                     (uint16_t)offsetof(FB_DECOUPLE, bDecIn3)),
              SL_OK);
    m.g.bRun = 1;
    s.g.bRun = 1;
    s.dec.bDecIn1 = 1;
    s.dec.bDecIn2 = 1;
    /* ComStartup: START while the connections start up, then RUN. */
    fsoe_bus(&m, &s, t, 1);
    t += 10;
    CHECK_INT(m.g.nState, SL_GROUP_STATE_START);
    CHECK_INT(m.g.bComStartup, 1);
    for (k = 0; k < 40 && m.g.nState != SL_STATE_RUN; k++, t += 10) {
        fsoe_bus(&m, &s, t, 1);
    }
    CHECK_INT(m.g.nState, SL_STATE_RUN);
    CHECK_INT(m.c.nState, SL_FSOE_STATE_DATA);
    for (k = 0; k < 4; k++, t += 10) {
        fsoe_bus(&m, &s, t, 1);
    }
    /* The slave's channels arrived at the ESTOP; restart; its output reaches the slave. */
    CHECK_INT(m.estop.bEStopIn1, 1);
    CHECK_INT(m.estop.bEStopIn2, 1);
    m.estop.bRestart = 1;
    fsoe_bus(&m, &s, t, 1);
    t += 10;
    m.estop.bRestart = 0;
    for (k = 0; k < 4; k++, t += 10) {
        fsoe_bus(&m, &s, t, 1);
    }
    CHECK_INT(m.estop.bEStopOut, 1);
    CHECK_INT(s.dec.bDecOut3, 1);
    /* The slave stops: ComErr -> group ERROR diag 2, outputs FALSE within the watchdog. */
    t_kill = t;
    for (k = 0; k < 20 && m.g.nState != SL_STATE_ERROR; k++, t += 10) {
        fsoe_bus(&m, &s, t, 0);
    }
    CHECK_INT(m.g.nState, SL_STATE_ERROR);
    CHECK_INT(m.g.nDiag, SL_GROUP_DIAG_COMERROR);
    CHECK_INT(m.g.bComErr, 1);
    CHECK(t - 10 - t_kill <= 110, "ERROR within watchdog + one cycle");
    CHECK_INT(m.estop.bEStopOut, 0);
    /* The slave returns: DATA again, ComErr latched until ErrAck (on both nodes). */
    for (k = 0; k < 40 && m.c.nState != SL_FSOE_STATE_DATA; k++, t += 10) {
        fsoe_bus(&m, &s, t, 1);
    }
    CHECK_INT(m.c.nState, SL_FSOE_STATE_DATA);
    CHECK_INT(m.g.nState, SL_STATE_ERROR);
    m.g.bErrAck = 1;
    s.g.bErrAck = 1;
    fsoe_bus(&m, &s, t, 1);
    t += 10;
    CHECK_INT(m.g.nState, SL_STATE_RESET);
    m.g.bErrAck = 0;
    s.g.bErrAck = 0;
    fsoe_bus(&m, &s, t, 1);
    t += 10;
    CHECK_INT(m.g.nState, SL_STATE_RUN);
    CHECK_INT(m.g.bComErr, 0);
    /* CONNECTION_SHUTDOWN: 106 on the master, 105 on the slave, no group error. */
    m.shut.bDeactivate1 = 1;
    for (k = 0; k < 4; k++, t += 10) {
        fsoe_bus(&m, &s, t, 1);
    }
    CHECK_INT(m.c.nState, SL_FSOE_STATE_SHUTDOWN_DEACTIVE);
    CHECK_INT(s.c.nState, SL_FSOE_STATE_SHUTDOWN);
    CHECK_INT(m.shut.nState, SL_STATE_RUN);
    CHECK_INT(m.shut.bDeactivated, 1);
    CHECK_INT(m.g.nState, SL_STATE_RUN);
    CHECK_INT(m.g.bComErr, 0);
    CHECK_INT(m.g.bComStartup, 0);
    CHECK_INT(s.g.nState, SL_STATE_RUN);
    m.shut.bDeactivate1 = 0;
    for (k = 0; k < 40 && m.shut.nState != SL_STATE_SAFE; k++, t += 10) {
        fsoe_bus(&m, &s, t, 1);
    }
    CHECK_INT(m.shut.nState, SL_STATE_SAFE);
    CHECK_INT(m.c.nState, SL_FSOE_STATE_DATA);
    CHECK_STR(sl_state_str(SL_TYPE_CONNECTION_SHUTDOWN, SL_STATE_RUN), "RUN");
    h_end();
}

void run_fsoe_scenarios(void)
{
    fsoe_crc_and_codec();
    fsoe_trace();
    fsoe_group();
}
