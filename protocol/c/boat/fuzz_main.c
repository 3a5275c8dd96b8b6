/*
 * usv_boat_fuzz: N fuzzed inputs into the boat core, built with -fsanitize=address,undefined.
 *
 *   usv_boat_fuzz N [SEED]
 *
 * Each input is one of: random bytes; a valid signed frame from the station with random or
 * mission-coherent fields (uploads that verify, STARTs that match, hot swaps); such a frame
 * mutated (bit flips, truncation, insertion, splice) or re-signed after mutation; a replay
 * of an earlier frame; an unsigned or foreign frame. Between inputs the boat clock advances
 * by a random step and the navigation solution moves. After every input the boat's
 * invariants are checked, and every byte the boat sends must parse as a frame signed with
 * the key (a second parser with its own stream table). Any violation aborts; the sanitizers
 * abort on memory or undefined-behaviour errors. Prints a summary line on success.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "usv_boat.h"

#define STATION 255
#define BOAT 1
#define CHECK(cond)                                                                        \
    do {                                                                                   \
        if (!(cond)) {                                                                     \
            fprintf(stderr, "usv_boat_fuzz: invariant failed at input %lu: %s\n", inputs, \
                    #cond);                                                                \
            abort();                                                                       \
        }                                                                                  \
    } while (0)

static unsigned long inputs;
static uint64_t rng_state;
static uint32_t clock_ms;
static unsigned long out_frames, out_bad;
static unsigned long states_seen[8];
static unsigned long activations, swaps, starts_ok;
static uint8_t last_state;
static unsigned long ack_results[4][10], cmd_results[8];

static usv_boat_t boat;
static uint8_t key[32];

/* the verifier of the boat's output */
static mavlink_message_t out_msg;
static mavlink_status_t out_status;
static mavlink_signing_t out_signing;
static mavlink_signing_streams_t out_streams;

/* the station (and the attacker) */
static mavlink_status_t st_status;
static mavlink_signing_t st_signing;
static mavlink_message_t st_msg;
static uint8_t frame[MAVLINK_MAX_PACKET_LEN + 64];
static uint16_t frame_len;
static uint8_t history[64][MAVLINK_MAX_PACKET_LEN];
static uint16_t history_len[64];
static uint64_t st_timestamp;

/* coherent mission state of the fuzzing station */
static uint32_t m_id = 1;
static uint16_t m_count;
static int32_t m_lat[USV_MAX_ITEMS], m_lon[USV_MAX_ITEMS];
static uint32_t m_t[USV_MAX_ITEMS];
static uint32_t m_session = 77;
static uint32_t m_seq;

static uint32_t rnd(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (uint32_t)((rng_state * 2685821657736338717ULL) >> 32);
}

static uint32_t below(uint32_t n)
{
    return n == 0 ? 0 : rnd() % n;
}

/* ---- HAL */
static void hal_send(void *ctx, const uint8_t *buf, uint16_t len)
{
    uint16_t i;
    (void)ctx;
    CHECK(len > 0 && len <= MAVLINK_MAX_PACKET_LEN);
    for (i = 0; i < len; i++) {
        uint8_t r = mavlink_frame_char_buffer(&out_msg, &out_status, buf[i], NULL, NULL);
        if (r == MAVLINK_FRAMING_OK) {
            out_frames++;
            CHECK(out_msg.sysid == BOAT);
            CHECK(out_msg.incompat_flags & MAVLINK_IFLAG_SIGNED);
            if (out_msg.msgid == MAVLINK_MSG_ID_USV_MISSION_ACK) {
                uint8_t res = mavlink_msg_usv_mission_ack_get_result(&out_msg);
                CHECK(res <= USV_MISSION_EXPIRED);
                ack_results[mavlink_msg_usv_mission_ack_get_stage(&out_msg) & 3u][res]++;
            } else if (out_msg.msgid == MAVLINK_MSG_ID_COMMAND_ACK) {
                cmd_results[mavlink_msg_command_ack_get_result(&out_msg) & 7u]++;
            }
        } else if (r != MAVLINK_FRAMING_INCOMPLETE) {
            out_bad++;
        }
    }
    CHECK(out_status.parse_state == MAVLINK_PARSE_STATE_IDLE); /* whole frames only */
}

static uint32_t hal_now(void *ctx)
{
    (void)ctx;
    return clock_ms;
}

static void hal_actuate(void *ctx, int16_t l, int16_t r)
{
    (void)ctx;
    CHECK(l >= -1000 && l <= 1000 && r >= -1000 && r <= 1000);
}

/* ---- frames from the station */
static void finish(void)
{
    frame_len = mavlink_msg_to_send_buffer(frame, &st_msg);
    memcpy(history[inputs % 64u], frame, frame_len);
    history_len[inputs % 64u] = frame_len;
}

static void sign_clock(void)
{
    uint64_t base = boat.cfg.boot_timestamp + (uint64_t)(clock_ms - boat.boot_ms) * 100u;
    st_timestamp += 1u + below(1000);
    if (base > st_timestamp) {
        st_timestamp = base; /* the station's clock runs with the boat's */
    }
    if (st_timestamp > st_signing.timestamp) {
        st_signing.timestamp = st_timestamp;
    }
}

static uint8_t target(void)
{
    uint32_t r = below(20);
    return r == 0 ? (uint8_t)rnd() : (r == 1 ? 0 : BOAT);
}

static void make_mission(void)
{
    uint16_t i;
    int32_t lat = boat.nav.lat_e7, lon = boat.nav.lon_e7;
    m_id = below(4) == 0 ? rnd() : m_id + 1u;
    m_count = (uint16_t)(below(10) == 0 ? 2u + below(USV_MAX_ITEMS - 1u) : 2u + below(6));
    for (i = 0; i < m_count; i++) {
        m_lat[i] = lat + (int32_t)(i * 1000u);
        m_lon[i] = lon;
        m_t[i] = i * (1000u + below(20000));
        if (i > 0 && m_t[i] <= m_t[i - 1]) {
            m_t[i] = m_t[i - 1] + 1u;
        }
    }
}

static uint32_t crc_of_mission(void)
{
    static usv_mission_t m;
    uint16_t i;
    m.id = m_id;
    m.count = m_count;
    for (i = 0; i < m_count; i++) {
        m.lat[i] = m_lat[i];
        m.lon[i] = m_lon[i];
        m.t_ms[i] = m_t[i];
        m.speed_cms[i] = 100;
        m.course_cdeg[i] = 0;
        m.heading_cdeg[i] = 0;
    }
    return usv_mission_crc32(&m);
}

static void station_frame(void)
{
    uint32_t kind = below(14);
    uint8_t sys = below(30) == 0 ? (uint8_t)(2u + below(3)) : STATION;
    uint8_t tgt = target();
    sign_clock();
    switch (kind) {
    case 0: { /* a coherent upload: BEGIN */
        if (m_count == 0 || below(3) == 0) {
            make_mission();
        }
        mavlink_msg_usv_mission_begin_pack_status(sys, 190, &st_status, &st_msg, tgt, 1, m_id,
                                                  crc_of_mission(), m_count,
                                                  below(3) == 0 ? clock_ms + below(20000) : 0);
        break;
    }
    case 1:
    case 2:
    case 3: { /* ITEM of the coherent mission (sometimes perturbed) */
        uint16_t i = (uint16_t)below(m_count > 0 ? m_count : 1u);
        if (m_count == 0) {
            make_mission();
        }
        mavlink_msg_usv_mission_item_pack_status(
            sys, 190, &st_status, &st_msg, tgt, 1, m_id, below(40) == 0 ? (uint16_t)rnd() : i,
            below(40) == 0 ? (int32_t)rnd() : m_lat[i], m_lon[i],
            below(40) == 0 ? rnd() : m_t[i], below(40) == 0 ? (uint16_t)rnd() : 100,
            below(40) == 0 ? (uint16_t)rnd() : 0, 0);
        break;
    }
    case 4: /* END */
        mavlink_msg_usv_mission_end_pack_status(sys, 190, &st_status, &st_msg, tgt, 1, m_id,
                                                below(10) == 0 ? rnd() : crc_of_mission(),
                                                below(10) == 0 ? (uint16_t)rnd() : m_count);
        break;
    case 5:
    case 6: { /* a command, mostly well formed */
        static const uint16_t cmds[10] = {
            MAV_CMD_USV_START, MAV_CMD_USV_START, MAV_CMD_USV_START, MAV_CMD_USV_HOLD,
            MAV_CMD_USV_HOLD, MAV_CMD_USV_RESUME, MAV_CMD_USV_RESUME, MAV_CMD_USV_RESUME,
            MAV_CMD_USV_RESUME, MAV_CMD_USV_ABORT};
        uint16_t cmd = cmds[below(10)];
        float p1, p2;
        if (below(20) == 0) {
            cmd = (uint16_t)rnd();
        }
        if (below(5) == 0) {
            m_session = below(4) == 0 ? rnd() : m_session + 1u;
        }
        m_seq = below(4) == 0 ? m_seq : m_seq + 1u;
        p1 = below(30) == 0 ? (float)(int32_t)rnd() * 1.5f : (float)(m_seq & 0xFFFFFu);
        p2 = below(30) == 0 ? (float)(int32_t)rnd() : (float)(m_session & 0xFFFFFu);
        mavlink_msg_command_int_pack_status(sys, 190, &st_status, &st_msg, tgt, 1, 0, cmd, 0, 0,
                                            p1, p2, 0, 0, (int32_t)m_id,
                                            (int32_t)(below(4) == 0 ? rnd() : crc_of_mission()),
                                            0);
        break;
    }
    case 7:
        mavlink_msg_usv_mission_read_pack_status(sys, 190, &st_status, &st_msg, tgt, 1,
                                                 below(2) ? m_id : rnd(),
                                                 (uint16_t)below(USV_MAX_ITEMS + 4u));
        break;
    case 8:
        mavlink_msg_usv_guidance_pack_status(sys, 190, &st_status, &st_msg, tgt, 1,
                                             (uint16_t)rnd(), (uint16_t)rnd(), (uint16_t)rnd());
        break;
    case 9:
        mavlink_msg_usv_ramp_pose_pack_status(sys, 190, &st_status, &st_msg, tgt, 1, rnd(),
                                              (int32_t)rnd(), (int32_t)rnd(), (uint16_t)rnd(),
                                              1.0f, -1.0f, 0.1f);
        break;
    case 10:
        mavlink_msg_timesync_pack_status(sys, 190, &st_status, &st_msg,
                                         below(2) ? 0 : (int64_t)rnd(), (int64_t)rnd());
        break;
    case 11:
        mavlink_msg_command_long_pack_status(sys, 190, &st_status, &st_msg, tgt, 1,
                                             (uint16_t)rnd(), 0, 1, 2, 3, 4, 5, 6, 7);
        break;
    case 12: /* a ground station reading the mission (standard protocol), any sender */
        if (below(3) == 0) {
            mavlink_msg_mission_request_list_pack_status(
                below(2) ? sys : (uint8_t)rnd(), 190, &st_status, &st_msg, tgt, 1,
                below(8) == 0 ? (uint8_t)rnd() : 0);
        } else if (below(2)) {
            mavlink_msg_mission_request_int_pack_status(
                below(2) ? sys : (uint8_t)rnd(), 190, &st_status, &st_msg, tgt, 1,
                (uint16_t)below(2u * USV_MAX_ITEMS + 4u), below(8) == 0 ? (uint8_t)rnd() : 0);
        } else {
            mavlink_msg_mission_request_pack_status(
                below(2) ? sys : (uint8_t)rnd(), 190, &st_status, &st_msg, tgt, 1,
                below(4) == 0 ? (uint16_t)rnd() : (uint16_t)below(2u * USV_MAX_ITEMS),
                below(8) == 0 ? (uint8_t)rnd() : 0);
        }
        break;
    default:
        mavlink_msg_heartbeat_pack_status(sys, 190, &st_status, &st_msg, MAV_TYPE_GCS,
                                          MAV_AUTOPILOT_INVALID, 0, 0, MAV_STATE_ACTIVE);
        break;
    }
    finish();
}

/* A whole coherent upload, one frame per input: BEGIN, every ITEM, END, then START with
 * the mission's id and CRC (boat placed on waypoint 0), or a hot swap when RUNNING. */
static int script_pos = -1;
static uint32_t script_swap;

static int script_frame(usv_nav_t *nav)
{
    uint32_t crc;
    if (script_pos < 0) {
        return 0;
    }
    sign_clock();
    crc = crc_of_mission();
    if (script_pos == 0 && (boat.staging == USV_STAGING_RECEIVING ||
                            boat.state == USV_BOAT_STATE_HOLD ||
                            boat.state == USV_BOAT_STATE_FAILSAFE)) {
        /* prelude: RESUME a held boat (then hot swap), ABORT a stuck staging */
        m_seq++;
        mavlink_msg_command_int_pack_status(
            STATION, 190, &st_status, &st_msg, BOAT, 1, 0,
            boat.staging == USV_STAGING_RECEIVING ? MAV_CMD_USV_ABORT : MAV_CMD_USV_RESUME, 0, 0,
            (float)(m_seq & 0xFFFFFu), (float)(m_session & 0xFFFFFu), 0, 0, 0, 0, 0);
        finish();
        return 1;
    }
    if (script_pos == 0) {
        script_swap = boat.state == USV_BOAT_STATE_RUNNING ? clock_ms - boat.boot_ms + 2000u +
                                                                 below(8000)
                                                           : 0u;
        mavlink_msg_usv_mission_begin_pack_status(STATION, 190, &st_status, &st_msg, BOAT, 1,
                                                  m_id, crc, m_count, script_swap);
    } else if (script_pos <= m_count) {
        uint16_t i = (uint16_t)(script_pos - 1);
        mavlink_msg_usv_mission_item_pack_status(STATION, 190, &st_status, &st_msg, BOAT, 1,
                                                 m_id, i, m_lat[i], m_lon[i], m_t[i], 100, 0, 0);
    } else if (script_pos == m_count + 1) {
        mavlink_msg_usv_mission_end_pack_status(STATION, 190, &st_status, &st_msg, BOAT, 1,
                                                m_id, crc, m_count);
    } else {
        nav->lat_e7 = m_lat[0];
        nav->lon_e7 = m_lon[0];
        usv_boat_set_nav(&boat, nav);
        m_seq++;
        mavlink_msg_command_int_pack_status(STATION, 190, &st_status, &st_msg, BOAT, 1, 0,
                                            script_swap ? MAV_CMD_USV_RESUME : MAV_CMD_USV_START,
                                            0, 0, (float)(m_seq & 0xFFFFFu),
                                            (float)(m_session & 0xFFFFFu), 0, 0, (int32_t)m_id,
                                            (int32_t)crc, 0);
        script_pos = -1;
        finish();
        return 1;
    }
    script_pos++;
    finish();
    return 1;
}

static void mutate(void)
{
    uint32_t k = below(5), n = 1u + below(8), i;
    if (frame_len == 0) {
        return;
    }
    switch (k) {
    case 0: /* bit flips */
        for (i = 0; i < n; i++) {
            frame[below(frame_len)] ^= (uint8_t)(1u << below(8));
        }
        break;
    case 1: /* truncation */
        frame_len = (uint16_t)below(frame_len);
        break;
    case 2: /* insertion */
        if (frame_len + n < sizeof frame) {
            uint32_t at = below(frame_len);
            memmove(frame + at + n, frame + at, frame_len - at);
            for (i = 0; i < n; i++) {
                frame[at + i] = (uint8_t)rnd();
            }
            frame_len = (uint16_t)(frame_len + n);
        }
        break;
    case 3: { /* splice with an earlier frame */
        uint32_t h = below(64), cut = below(frame_len);
        uint16_t hl = history_len[h];
        if (hl > 0 && cut + hl - below(hl) < sizeof frame) {
            uint32_t from = below(hl);
            memcpy(frame + cut, history[h] + from, hl - from);
            frame_len = (uint16_t)(cut + hl - from);
        }
        break;
    }
    default: { /* payload mutated, then signed again: random field values past the check */
        uint8_t len = st_msg.len;
        if (len > 0) {
            for (i = 0; i < n; i++) {
                _MAV_PAYLOAD_NON_CONST(&st_msg)[below(len)] = (uint8_t)rnd();
            }
            sign_clock();
            mavlink_finalize_message_buffer(&st_msg, st_msg.sysid, st_msg.compid, &st_status,
                                            len, len, mavlink_get_crc_extra(&st_msg));
            frame_len = mavlink_msg_to_send_buffer(frame, &st_msg);
        }
        break;
    }
    }
}

static void feed(const uint8_t *p, uint16_t n)
{
    uint16_t i;
    for (i = 0; i < n; i++) {
        usv_boat_rx_byte(&boat, p[i]);
        if ((i & 127u) == 127u) {
            usv_boat_poll(&boat);
        }
    }
}

static void check_invariants(void)
{
    const usv_mission_t *a = &boat.mission[boat.active];
    const usv_mission_t *g = &boat.mission[boat.active ^ 1u];
    uint16_t i;
    CHECK(boat.state <= USV_BOAT_STATE_GO_AROUND);
    CHECK(!boat.at_standby || boat.go_around);
    CHECK(boat.staging <= USV_STAGING_VERIFIED);
    CHECK(boat.active <= 1u);
    CHECK(boat.rx_head < USV_RX_RING && boat.rx_tail < USV_RX_RING);
    CHECK(boat.tq_len <= USV_TELEMETRY_QUEUE);
    {
        uint16_t at = 0, k;
        uint32_t ids[16];
        unsigned nid = 0;
        while (at < boat.tq_len) { /* whole entries, one per message id */
            uint32_t id = (uint32_t)boat.tq[at] | ((uint32_t)boat.tq[at + 1u] << 8) |
                          ((uint32_t)boat.tq[at + 2u] << 16);
            for (k = 0; k < nid; k++) {
                CHECK(ids[k] != id);
            }
            CHECK(nid < 16u);
            ids[nid++] = id;
            at = (uint16_t)(at + 4u + boat.tq[at + 3u]);
        }
        CHECK(at == boat.tq_len);
    }
    if (boat.has_active) {
        CHECK(a->count >= 2u && a->count <= USV_MAX_ITEMS);
        CHECK(a->id != 0u);
        CHECK(boat.current_seq < a->count);
        CHECK(a->t_ms[0] == 0u);
        for (i = 1; i < a->count; i++) {
            CHECK(a->t_ms[i] > a->t_ms[i - 1u]); /* only verified missions are active */
        }
        CHECK(usv_mission_crc32(a) == a->crc32);
    } else {
        CHECK(boat.state == USV_BOAT_STATE_IDLE || boat.state == USV_BOAT_STATE_ABORTED);
    }
    if (boat.staging != USV_STAGING_NONE) {
        CHECK(g->count >= 2u && g->count <= USV_MAX_ITEMS);
        CHECK(boat.staged_received <= g->count);
    }
    if (boat.staging == USV_STAGING_VERIFIED) {
        CHECK(boat.staged_swap_at != 0u);
        CHECK(usv_mission_crc32(g) == g->crc32);
    }
    if (boat.state != last_state) {
        if (boat.state == USV_BOAT_STATE_READY && last_state != USV_BOAT_STATE_HOLD &&
            last_state != USV_BOAT_STATE_FAILSAFE) {
            activations++;
        }
        if (boat.state == USV_BOAT_STATE_RUNNING && last_state == USV_BOAT_STATE_READY) {
            starts_ok++;
        }
        last_state = boat.state;
    }
    states_seen[boat.state]++;
}

int main(int argc, char **argv)
{
    unsigned long n = argc > 1 ? strtoul(argv[1], NULL, 10) : 100000ul;
    unsigned long seed = argc > 2 ? strtoul(argv[2], NULL, 10) : 1ul;
    usv_config_t cfg;
    usv_hal_t hal;
    usv_nav_t nav;
    uint32_t prev_active = 0;
    unsigned i;

    rng_state = 0x9E3779B97F4A7C15ULL ^ ((uint64_t)seed * 0xD1B54A32D192ED03ULL);
    for (i = 0; i < 32; i++) {
        key[i] = (uint8_t)rnd();
    }
    memset(&cfg, 0, sizeof cfg);
    cfg.boat_id = BOAT;
    cfg.station_id = STATION;
    cfg.key = key;
    cfg.boot_timestamp = 1000000;
    cfg.boot_id = 42;
    cfg.telemetry_period_ms = 200;
    cfg.link_timeout_ms = 3000;
    cfg.start_radius_m = 10.0f;
    cfg.max_speed_mps = 4.0f;
    cfg.line_baud = (seed % 2u) ? 9600u : 0u; /* odd seeds pace telemetry on a 9600 line */
    hal.send = hal_send;
    hal.now_ms = hal_now;
    hal.actuate = hal_actuate;
    hal.ctx = NULL;
    clock_ms = 0xFFFF0000u; /* the millisecond clock wraps during the run */
    if (usv_boat_init(&boat, &cfg, &hal) != 0) {
        fprintf(stderr, "usv_boat_fuzz: init failed\n");
        return 1;
    }
    memcpy(out_signing.secret_key, key, 32);
    out_status.signing = &out_signing;
    out_status.signing_streams = &out_streams;
    memcpy(st_signing.secret_key, key, 32);
    st_signing.flags = MAVLINK_SIGNING_FLAG_SIGN_OUTGOING;
    st_timestamp = cfg.boot_timestamp + 1u;
    st_status.signing = &st_signing;
    memset(&nav, 0, sizeof nav);
    nav.lat_e7 = 599000000;
    nav.lon_e7 = 107000000;
    nav.fix_type = 3;

    for (inputs = 0; inputs < n; inputs++) {
        uint32_t kind = below(100);
        if (script_pos >= 0 && below(10) < 8) {
            script_frame(&nav); /* a script runs mostly uninterrupted */
        } else if (kind < 15) { /* random bytes */
            uint16_t len = (uint16_t)(1u + below(300));
            for (i = 0; i < len && i < sizeof frame; i++) {
                frame[i] = (uint8_t)rnd();
            }
            frame_len = (uint16_t)i;
            if (below(2) == 0) {
                frame[0] = MAVLINK_STX;
            }
        } else if (kind < 55) { /* valid station frames */
            if (script_pos < 0 && below(8) == 0) {
                make_mission();
                script_pos = 0;
            }
            if (!script_frame(&nav)) {
                station_frame();
            }
        } else if (kind < 85) { /* mutated */
            station_frame();
            mutate();
        } else if (kind < 92) { /* replay of an earlier frame */
            uint32_t h = below(64);
            frame_len = history_len[h];
            memcpy(frame, history[h], frame_len);
        } else { /* unsigned frame */
            mavlink_signing_t *s = st_status.signing;
            st_status.signing = NULL;
            station_frame();
            st_status.signing = s;
        }
        feed(frame, frame_len);
        if (below(4) == 0) {
            clock_ms += below(below(10) == 0 ? 40000u : 400u);
        }
        if (below(8) == 0) { /* the boat moves; sometimes far, sometimes onto waypoint 0 */
            if (below(6) == 0 && m_count > 0) {
                nav.lat_e7 = m_lat[0];
                nav.lon_e7 = m_lon[0];
            } else if (below(200) == 0) {
                nav.lat_e7 = (int32_t)rnd();
                nav.lon_e7 = (int32_t)rnd();
            } else {
                nav.lat_e7 += (int32_t)below(2001) - 1000;
                nav.lon_e7 += (int32_t)below(2001) - 1000;
            }
            nav.heading_rad = (float)below(6283) * 1e-3f;
            nav.speed_mps = (float)below(500) * 0.01f;
            usv_boat_set_nav(&boat, &nav);
        }
        usv_boat_poll(&boat);
        check_invariants();
        if (boat.has_active && boat.staging == USV_STAGING_NONE &&
            boat.mission[boat.active].id != prev_active && boat.state == USV_BOAT_STATE_RUNNING &&
            prev_active != 0) {
            swaps++;
        }
        prev_active = boat.has_active ? boat.mission[boat.active].id : 0u;
    }
    printf("usv_boat_fuzz: %lu inputs (seed %lu) ok; boat sent %lu frames (%lu unparsable); "
           "refused unsigned %u bad-signature %u replayed %u wrong-sender %u (saturating); "
           "activations %lu, starts %lu, mission changes while running %lu; "
           "inputs per state idle %lu ready %lu running %lu hold %lu done %lu aborted %lu "
           "failsafe %lu\n",
           n, seed, out_frames, out_bad, boat.refused[0], boat.refused[1], boat.refused[2],
           boat.refused[3], activations, starts_ok, swaps, states_seen[0],
           states_seen[1], states_seen[2], states_seen[3], states_seen[4], states_seen[5],
           states_seen[6]);
    if (getenv("USV_FUZZ_VERBOSE") != NULL) {
        int st, r;
        for (st = 0; st < 4; st++) {
            printf("stage %d:", st);
            for (r = 0; r < 10; r++) {
                printf(" %lu", ack_results[st][r]);
            }
            printf("\n");
        }
        printf("command results:");
        for (r = 0; r < 8; r++) {
            printf(" %lu", cmd_results[r]);
        }
        printf("\n");
    }
    return out_bad == 0 ? 0 : 1;
}
