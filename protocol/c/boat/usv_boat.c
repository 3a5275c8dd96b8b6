/*
 * usv_boat.c: the boat side of usv-link 2 (see usv_boat.h and protocol/usv_recovery.xml).
 */
#include "usv_boat.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define COMP_ID MAV_COMP_ID_AUTOPILOT1
#define PI_F 3.14159265358979f
#define E7_TO_M 0.0111319491f /* metres per 1e-7 degree of latitude (R = 6378137 m) */
#define SEQ_LIMIT 16777216.0f  /* command seq and session are integers below 2^24 */
#define DONE_RADIUS_M 5.0f
#define KEEP_RADIUS_M 1.5f
#define KEEP_SPEED_MPS 0.4f
#define TRACK_GAIN 0.4f /* 1/s: position error to velocity correction */
/* approach gates (m from the last waypoint along the final leg), go-around, over capacity */
#define GATES 3
static const float GATE_M[GATES] = {30.0f, 15.0f, 5.0f};
#define GATE_JOIN_M 10.0f    /* a gate less than this inside where the final leg begins: skipped */
#define ARRIVAL_OFFSET_M 0.3f
#define STANDBY_M 50.0f      /* the go-around stands by at the first item this far back */
#define BACK_OFF_M 12.0f     /* a go-around closer to the ramp first backs away to here */
#define OVER_CAPACITY_M 5.0f /* keeping station this far off its point: over capacity */

enum { STAGE_BEGIN = 1, STAGE_ITEM = 2, STAGE_END = 3, STAGE_READ = 4 };

/* ------------------------------------------------------------------ time */

static uint32_t uptime(const usv_boat_t *b)
{
    return b->hal.now_ms(b->hal.ctx) - b->boot_ms;
}

/* a is at or after b on the wrapping millisecond clock */
static int at_or_after(uint32_t a, uint32_t b)
{
    return (int32_t)(a - b) >= 0;
}

/* ------------------------------------------------------------------ CRC-32 */

uint32_t usv_crc32(uint32_t crc, const uint8_t *data, uint32_t len)
{
    uint32_t i;
    int k;
    crc = ~crc;
    for (i = 0; i < len; i++) {
        crc ^= data[i];
        for (k = 0; k < 8; k++) {
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
    }
    return ~crc;
}

static uint8_t *put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
    return p + 4;
}

static uint8_t *put16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    return p + 2;
}

/* Each item's USV_MISSION_ITEM wire payload from mission_id on, without the two target
 * bytes (which differ between upload and readback): mission_id, lat, lon, t_ms, seq,
 * speed_cms, course_cdeg, heading_cdeg, little-endian, 24 bytes, in seq order. */
uint32_t usv_mission_crc32(const usv_mission_t *m)
{
    uint32_t crc = 0;
    uint16_t i;
    for (i = 0; i < m->count; i++) {
        uint8_t buf[24];
        uint8_t *p = buf;
        p = put32(p, m->id);
        p = put32(p, (uint32_t)m->lat[i]);
        p = put32(p, (uint32_t)m->lon[i]);
        p = put32(p, m->t_ms[i]);
        p = put16(p, i);
        p = put16(p, m->speed_cms[i]);
        p = put16(p, m->course_cdeg[i]);
        put16(p, m->heading_cdeg[i]);
        crc = usv_crc32(crc, buf, sizeof buf);
    }
    return crc;
}

/* ------------------------------------------------------------------ geometry */

/* north/east metres of (lat, lon) from (lat0, lon0), flat earth (missions span km) */
static void local_ne(int32_t lat0, int32_t lon0, int32_t lat, int32_t lon, float *n, float *e)
{
    int64_t dlat = (int64_t)lat - lat0;
    int64_t dlon = (int64_t)lon - lon0;
    if (dlon > 1800000000) {
        dlon -= 3600000000LL;
    } else if (dlon < -1800000000) {
        dlon += 3600000000LL;
    }
    *n = (float)dlat * E7_TO_M;
    *e = (float)dlon * E7_TO_M * cosf((float)lat0 * (1e-7f * PI_F / 180.0f));
}

static float wrap_pi(float a)
{
    while (a > PI_F) {
        a -= 2.0f * PI_F;
    }
    while (a < -PI_F) {
        a += 2.0f * PI_F;
    }
    return a;
}

static float clampf(float v, float lo, float hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

static float dist_to(const usv_boat_t *b, int32_t lat, int32_t lon)
{
    float n, e;
    local_ne(lat, lon, b->nav.lat_e7, b->nav.lon_e7, &n, &e);
    return sqrtf(n * n + e * e);
}

/* ------------------------------------------------------------------ sending */

/* Milliseconds of line time for n bytes (8N1: 10 bits a byte). */
static uint32_t line_ms(const usv_boat_t *b, uint16_t n)
{
    return (uint32_t)(((uint64_t)n * 10000u + b->cfg.line_baud - 1u) / b->cfg.line_baud);
}

static void line_send(usv_boat_t *b, const uint8_t *buf, uint16_t n)
{
    if (b->cfg.line_baud != 0u) {
        uint32_t now = uptime(b);
        if (at_or_after(now, b->line_free_ms)) {
            b->line_free_ms = now;
        }
        b->line_free_ms += line_ms(b, n);
    }
    b->hal.send(b->hal.ctx, buf, n);
}

static void sign_clock(usv_boat_t *b);

/* Sign and send the message in tx_msg now (sequence number and signing time of now). */
static void finalize_and_send(usv_boat_t *b)
{
    const mavlink_msg_entry_t *e = mavlink_get_msg_entry(b->tx_msg.msgid);
    uint16_t n;
    if (e == NULL) {
        return;
    }
    sign_clock(b);
    mavlink_finalize_message_buffer(&b->tx_msg, b->cfg.boat_id, COMP_ID, &b->tx_status,
                                    e->min_msg_len, b->tx_msg.len, e->crc_extra);
    n = mavlink_msg_to_send_buffer(b->tx_buf, &b->tx_msg);
    line_send(b, b->tx_buf, n);
}

/* Replies (ACKs, readback, TIMESYNC, STATUSTEXT, HEARTBEAT, USV_MISSION_STATE) are signed
 * and sent at once; telemetry waits unsigned in a small queue (msgid, length, payload)
 * that is released, and only then numbered and signed, while the line is idle
 * (line_baud): a reply never queues behind more than one telemetry frame, and signing
 * timestamps stay in sending order. The queue holds one entry per message: a newer value
 * replaces a waiting one in its place in line (counted as dropped), so every telemetry
 * message keeps its turn when the line is slower than the telemetry rate. */
static void emit(usv_boat_t *b, int urgent)
{
    uint16_t n = (uint16_t)(4u + b->tx_msg.len);
    uint16_t at = 0;
    uint8_t *q;
    if (urgent || b->cfg.line_baud == 0u) {
        finalize_and_send(b);
        return;
    }
    while (at + 4u <= b->tq_len) { /* one entry per message: a newer value replaces it */
        uint16_t m = (uint16_t)(4u + b->tq[at + 3u]);
        uint32_t id = (uint32_t)b->tq[at] | ((uint32_t)b->tq[at + 1u] << 8) |
                      ((uint32_t)b->tq[at + 2u] << 16);
        if (id == b->tx_msg.msgid) {
            memmove(b->tq + at, b->tq + at + m, (size_t)(b->tq_len - at - m));
            b->tq_len = (uint16_t)(b->tq_len - m);
            if (b->telemetry_dropped < UINT16_MAX) {
                b->telemetry_dropped++;
            }
            break;
        }
        at = (uint16_t)(at + m);
    }
    if (at > b->tq_len) {
        at = b->tq_len;
    }
    if (b->tq_len + n > USV_TELEMETRY_QUEUE) {
        if (b->telemetry_dropped < UINT16_MAX) {
            b->telemetry_dropped++;
        }
        return;
    }
    /* the new value takes the old one's place in line (or the end) */
    memmove(b->tq + at + n, b->tq + at, (size_t)(b->tq_len - at));
    q = b->tq + at;
    q[0] = (uint8_t)b->tx_msg.msgid;
    q[1] = (uint8_t)(b->tx_msg.msgid >> 8);
    q[2] = (uint8_t)(b->tx_msg.msgid >> 16);
    q[3] = b->tx_msg.len;
    memcpy(q + 4, _MAV_PAYLOAD(&b->tx_msg), b->tx_msg.len);
    b->tq_len = (uint16_t)(b->tq_len + n);
}

/* Release queued telemetry while the line is idle. */
static void drain_telemetry(usv_boat_t *b, uint32_t now)
{
    while (b->tq_len >= 4u && at_or_after(now, b->line_free_ms)) {
        uint16_t n = (uint16_t)(4u + b->tq[3]);
        if (n > b->tq_len) {
            b->tq_len = 0; /* cannot happen: only whole entries are queued */
            return;
        }
        b->tx_msg.msgid = (uint32_t)b->tq[0] | ((uint32_t)b->tq[1] << 8) |
                          ((uint32_t)b->tq[2] << 16);
        b->tx_msg.len = b->tq[3];
        memcpy(_MAV_PAYLOAD_NON_CONST(&b->tx_msg), b->tq + 4, b->tq[3]);
        memmove(b->tq, b->tq + n, (size_t)(b->tq_len - n));
        b->tq_len = (uint16_t)(b->tq_len - n);
        finalize_and_send(b);
    }
}

/* Advance the outgoing signing timestamp with the boat clock (10 us units). */
static void sign_clock(usv_boat_t *b)
{
    if (b->tx_status.signing != NULL) {
        uint64_t ts = b->cfg.boot_timestamp + (uint64_t)uptime(b) * 100u;
        if (ts > b->signing.timestamp) {
            b->signing.timestamp = ts;
        }
    }
}

/* pack only (the scratch status neither numbers nor signs); emit() finalizes */
#define PACK(name, value)                                                                 \
    mavlink_msg_##name##_encode_status(b->cfg.boat_id, COMP_ID, &b->pack_status, &b->tx_msg, \
                                       (value))
#define SEND(name, value)                                                                 \
    do {                                                                                  \
        PACK(name, value);                                                                \
        emit(b, 1);                                                                       \
    } while (0)
#define TELEMETRY(name, value)                                                            \
    do {                                                                                  \
        PACK(name, value);                                                                \
        emit(b, 0);                                                                       \
    } while (0)

/* A small text builder (no printf on the boat). */
typedef struct {
    char s[MAVLINK_MSG_STATUSTEXT_FIELD_TEXT_LEN + 1];
    unsigned n;
} text_t;

static void tx_str(text_t *t, const char *s)
{
    while (*s != '\0' && t->n < MAVLINK_MSG_STATUSTEXT_FIELD_TEXT_LEN) {
        t->s[t->n++] = *s++;
    }
    t->s[t->n] = '\0';
}

static void tx_uint(text_t *t, uint32_t v)
{
    char d[11];
    int k = 0;
    do {
        d[k++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    while (k > 0 && t->n < MAVLINK_MSG_STATUSTEXT_FIELD_TEXT_LEN) {
        t->s[t->n++] = d[--k];
    }
    t->s[t->n] = '\0';
}

/* metres with one decimal */
static void tx_metres(text_t *t, float m)
{
    uint32_t dm = (uint32_t)(clampf(m, 0.0f, 4.0e8f) * 10.0f + 0.5f);
    tx_uint(t, dm / 10u);
    tx_str(t, ".");
    tx_uint(t, dm % 10u);
    tx_str(t, " m");
}

static void send_text(usv_boat_t *b, uint8_t severity, const text_t *t)
{
    mavlink_statustext_t s;
    memset(&s, 0, sizeof s);
    s.severity = severity;
    memcpy(s.text, t->s, t->n);
    SEND(statustext, &s);
}

static void text_begin(text_t *t, const char *s)
{
    t->n = 0;
    t->s[0] = '\0';
    tx_str(t, s);
}

/* ------------------------------------------------------------------ reports */

static usv_mission_t *active_mission(usv_boat_t *b)
{
    return &b->mission[b->active];
}

static usv_mission_t *staged_mission(usv_boat_t *b)
{
    return &b->mission[b->active ^ 1u];
}

static void fill_state(usv_boat_t *b, mavlink_usv_mission_state_t *s)
{
    const usv_mission_t *a = active_mission(b);
    const usv_mission_t *g = staged_mission(b);
    memset(s, 0, sizeof *s);
    s->boot_id = b->cfg.boot_id;
    s->state = b->state;
    if (b->has_active) {
        s->active_id = a->id;
        s->active_crc32 = a->crc32;
        s->active_count = a->count;
        s->current_seq = b->current_seq;
    }
    s->staging = b->staging;
    if (b->staging != USV_STAGING_NONE) {
        s->staged_id = g->id;
        s->staged_crc32 = g->crc32;
        s->staged_received = b->staged_received;
        s->staged_count = g->count;
        s->swap_at_ms = b->staging == USV_STAGING_VERIFIED ? b->staged_swap_at : 0u;
    }
    s->station_session = b->station_session;
    s->flags = b->flags;
}

static void swap_if_due(usv_boat_t *b, uint32_t now);
static const char *swap_problem(usv_boat_t *b, int at_instant);
static int final_leg(usv_boat_t *b, float *d, float *x, float *course);
static void start_go_around(usv_boat_t *b, float gate, const char *why, float value);

static void send_state(usv_boat_t *b)
{
    mavlink_usv_mission_state_t s;
    uint32_t at = uptime(b);
    swap_if_due(b, at); /* a report stamped at or after the swap instant shows the swap */
    fill_state(b, &s);
    b->last_state = s;
    s.uptime_ms = at;
    s.rejected = b->rejected;
    SEND(usv_mission_state, &s);
}

static uint32_t std_mode(uint8_t state);
static int std_armed(uint8_t state);

static void send_heartbeat(usv_boat_t *b)
{
    mavlink_heartbeat_t h;
    memset(&h, 0, sizeof h);
    h.type = MAV_TYPE_SURFACE_BOAT;
    h.autopilot = MAV_AUTOPILOT_GENERIC;
    h.base_mode = MAV_MODE_FLAG_CUSTOM_MODE_ENABLED;
    if (b->state == USV_BOAT_STATE_RUNNING) {
        h.base_mode |= MAV_MODE_FLAG_AUTO_ENABLED;
    }
    h.custom_mode = std_mode(b->state);
    if (std_armed(b->state)) {
        h.base_mode |= MAV_MODE_FLAG_SAFETY_ARMED;
    }
    if (b->state == USV_BOAT_STATE_FAILSAFE) {
        h.system_status = MAV_STATE_CRITICAL;
    } else if (b->state == USV_BOAT_STATE_RUNNING || b->state == USV_BOAT_STATE_HOLD ||
               b->state == USV_BOAT_STATE_GO_AROUND) {
        h.system_status = MAV_STATE_ACTIVE;
    } else {
        h.system_status = MAV_STATE_STANDBY;
    }
    h.mavlink_version = 3;
    SEND(heartbeat, &h);
}

static uint16_t cdeg(float rad)
{
    float d = rad * (18000.0f / PI_F);
    while (d < 0.0f) {
        d += 36000.0f;
    }
    while (d >= 36000.0f) {
        d -= 36000.0f;
    }
    return (uint16_t)d;
}

static void send_slow_telemetry(usv_boat_t *b)
{
    mavlink_gps_raw_int_t g;
    mavlink_sys_status_t s;
    uint32_t t = uptime(b);
    memset(&g, 0, sizeof g);
    g.time_usec = (uint64_t)t * 1000u;
    g.lat = b->nav.lat_e7;
    g.lon = b->nav.lon_e7;
    g.fix_type = b->nav.fix_type;
    g.satellites_visible = b->nav.satellites;
    g.eph = UINT16_MAX;
    g.epv = UINT16_MAX;
    g.vel = (uint16_t)clampf(b->nav.speed_mps * 100.0f, 0.0f, 65534.0f);
    g.cog = cdeg(b->nav.course_rad);
    TELEMETRY(gps_raw_int, &g);
    memset(&s, 0, sizeof s);
    s.voltage_battery = b->nav.battery_mv;
    s.current_battery = -1;
    s.battery_remaining = b->nav.battery_pct;
    s.errors_comm = b->rx_overruns;
    s.errors_count1 = b->rejected;
    s.errors_count2 = b->telemetry_dropped;
    s.onboard_control_sensors_present = MAV_SYS_STATUS_SENSOR_GPS | MAV_SYS_STATUS_SENSOR_MOTOR_OUTPUTS;
    s.onboard_control_sensors_enabled = s.onboard_control_sensors_present;
    s.onboard_control_sensors_health = MAV_SYS_STATUS_SENSOR_MOTOR_OUTPUTS |
        (b->nav.fix_type >= GPS_FIX_TYPE_3D_FIX ? MAV_SYS_STATUS_SENSOR_GPS : 0u);
    TELEMETRY(sys_status, &s);
}

/* t: the telemetry grid instant (boat uptime) */
static void send_fast_telemetry(usv_boat_t *b, uint32_t t)
{
    mavlink_global_position_int_t p;
    mavlink_attitude_t a;
    mavlink_vfr_hud_t v;
    mavlink_usv_thrust_t th;
    memset(&p, 0, sizeof p);
    p.time_boot_ms = t;
    p.lat = b->nav.lat_e7;
    p.lon = b->nav.lon_e7;
    p.vx = (int16_t)clampf(b->nav.speed_mps * cosf(b->nav.course_rad) * 100.0f, -32000, 32000);
    p.vy = (int16_t)clampf(b->nav.speed_mps * sinf(b->nav.course_rad) * 100.0f, -32000, 32000);
    p.hdg = cdeg(b->nav.heading_rad);
    TELEMETRY(global_position_int, &p);
    memset(&a, 0, sizeof a);
    a.time_boot_ms = t;
    a.yaw = wrap_pi(b->nav.heading_rad);
    a.yawspeed = b->nav.yaw_rate;
    TELEMETRY(attitude, &a);
    memset(&v, 0, sizeof v);
    v.groundspeed = b->nav.speed_mps;
    v.airspeed = b->nav.speed_mps;
    v.heading = (int16_t)(cdeg(b->nav.heading_rad) / 100u);
    v.throttle = (uint16_t)((abs(b->thrust_left) + abs(b->thrust_right)) / 20);
    TELEMETRY(vfr_hud, &v);
    memset(&th, 0, sizeof th);
    th.time_boot_ms = t;
    th.left_pm = b->thrust_left;
    th.right_pm = b->thrust_right;
    th.cross_track = b->cross_track;
    th.slip = b->slip;
    TELEMETRY(usv_thrust, &th);
}

/* ------------------------------------------------------------------ refusals */

static void refuse(usv_boat_t *b, int kind)
{
    if (b->refused[kind] < UINT16_MAX) {
        b->refused[kind]++;
    }
    if (b->rejected < UINT16_MAX) {
        b->rejected++;
    }
    b->last_refusal = (uint8_t)kind;
    b->last_refusal_msgid = b->rx_msg.msgid;
    b->last_refusal_sysid = b->rx_msg.sysid;
    b->text_pending = 1;
}

static void report_refusals(usv_boat_t *b, uint32_t now)
{
    static const char *const why[USV_REFUSE_KINDS] = {
        "unsigned", "bad signature", "replayed", "wrong sender"};
    text_t t;
    if (!b->text_pending || !at_or_after(now, b->last_text_ms + USV_TEXT_MIN_MS)) {
        return;
    }
    b->text_pending = 0;
    b->last_text_ms = now;
    text_begin(&t, "refused ");
    tx_str(&t, why[b->last_refusal]);
    tx_str(&t, " frame from ");
    tx_uint(&t, b->last_refusal_sysid);
    tx_str(&t, " (");
    tx_uint(&t, b->rejected);
    tx_str(&t, " total)");
    send_text(b, MAV_SEVERITY_WARNING, &t);
}

/* ------------------------------------------------------------------ staging */

static void drop_staging(usv_boat_t *b)
{
    if (b->staging != USV_STAGING_NONE) {
        b->dropped_id = staged_mission(b)->id;
    }
    b->staging = USV_STAGING_NONE;
    b->staged_received = 0;
    b->staged_swap_at = 0;
}

static void send_mission_ack(usv_boat_t *b, const mavlink_message_t *req, uint32_t id,
                             uint16_t seq, uint8_t result, uint8_t stage)
{
    mavlink_usv_mission_ack_t a;
    memset(&a, 0, sizeof a);
    a.target_system = req->sysid;
    a.target_component = req->compid;
    a.mission_id = id;
    a.seq = seq;
    a.result = result;
    a.stage = stage;
    SEND(usv_mission_ack, &a);
}

static int active_is(usv_boat_t *b, uint32_t id)
{
    return b->has_active && active_mission(b)->id == id;
}

static void hold_here(usv_boat_t *b)
{
    b->hold_lat = b->nav.lat_e7;
    b->hold_lon = b->nav.lon_e7;
}

static int idle_like(uint8_t state)
{
    return state == USV_BOAT_STATE_IDLE || state == USV_BOAT_STATE_READY ||
           state == USV_BOAT_STATE_DONE || state == USV_BOAT_STATE_ABORTED;
}

static void on_begin(usv_boat_t *b, const mavlink_message_t *msg, uint32_t now)
{
    mavlink_usv_mission_begin_t m;
    usv_mission_t *g = staged_mission(b);
    text_t t;
    int under_way = b->state == USV_BOAT_STATE_RUNNING || b->state == USV_BOAT_STATE_HOLD ||
                    b->state == USV_BOAT_STATE_FAILSAFE || b->state == USV_BOAT_STATE_GO_AROUND;
    mavlink_msg_usv_mission_begin_decode(msg, &m);
    if (m.mission_id == 0u) {
        send_mission_ack(b, msg, 0, 0, USV_MISSION_UNKNOWN_MISSION, STAGE_BEGIN);
        return;
    }
    if (m.count < 2u || m.count > USV_MAX_ITEMS) {
        send_mission_ack(b, msg, m.mission_id, 0, USV_MISSION_BAD_COUNT, STAGE_BEGIN);
        text_begin(&t, "mission ");
        tx_uint(&t, m.mission_id);
        tx_str(&t, ": count ");
        tx_uint(&t, m.count);
        tx_str(&t, " outside 2..");
        tx_uint(&t, USV_MAX_ITEMS);
        send_text(b, MAV_SEVERITY_WARNING, &t);
        return;
    }
    if ((m.swap_at_ms == 0u && under_way) ||
        (m.swap_at_ms != 0u && b->state != USV_BOAT_STATE_RUNNING &&
         b->state != USV_BOAT_STATE_GO_AROUND)) {
        send_mission_ack(b, msg, m.mission_id, 0, USV_MISSION_DENIED, STAGE_BEGIN);
        return;
    }
    if (b->staging != USV_STAGING_NONE && g->id == m.mission_id && g->crc32 == m.crc32 &&
        g->count == m.count && b->staged_swap_at == m.swap_at_ms) {
        b->staging_touch_ms = now; /* a retry keeps what was staged */
        send_mission_ack(b, msg, m.mission_id,
                         b->staging == USV_STAGING_VERIFIED ? g->count : b->staged_received,
                         USV_MISSION_ACCEPTED, STAGE_BEGIN);
        return;
    }
    if (b->staging == USV_STAGING_VERIFIED) { /* a swap is scheduled: ABORT it first */
        send_mission_ack(b, msg, m.mission_id, 0, USV_MISSION_BUSY, STAGE_BEGIN);
        return;
    }
    /* a new staging (an unfinished one of another mission is replaced) */
    g->id = m.mission_id;
    g->crc32 = m.crc32;
    g->count = m.count;
    memset(b->staged_bits, 0, sizeof b->staged_bits);
    b->staged_received = 0;
    b->staged_swap_at = m.swap_at_ms;
    b->staging = USV_STAGING_RECEIVING;
    b->staging_touch_ms = now;
    send_mission_ack(b, msg, m.mission_id, 0, USV_MISSION_ACCEPTED, STAGE_BEGIN);
}

static int staged_bit(const usv_boat_t *b, uint16_t i)
{
    return (b->staged_bits[i >> 3] >> (i & 7u)) & 1u;
}

/* The field of an item that is out of range, or NULL (the per-item check). */
static const char *item_problem(const mavlink_usv_mission_item_t *it)
{
    if (it->lat < -900000000 || it->lat > 900000000) {
        return "lat";
    }
    if (it->lon < -1800000000 || it->lon > 1800000000) {
        return "lon";
    }
    if (it->speed_cms > 3000u) {
        return "speed_cms";
    }
    if (it->course_cdeg > 35999u) {
        return "course_cdeg";
    }
    if (it->heading_cdeg > 35999u) {
        return "heading_cdeg";
    }
    if (it->seq == 0u && it->t_ms != 0u) {
        return "t_ms";
    }
    return NULL;
}

static int item_equals(const usv_mission_t *m, const mavlink_usv_mission_item_t *it)
{
    return it->seq < m->count && m->lat[it->seq] == it->lat && m->lon[it->seq] == it->lon &&
           m->t_ms[it->seq] == it->t_ms && m->speed_cms[it->seq] == it->speed_cms &&
           m->course_cdeg[it->seq] == it->course_cdeg &&
           m->heading_cdeg[it->seq] == it->heading_cdeg;
}

static void on_item(usv_boat_t *b, const mavlink_message_t *msg, uint32_t now)
{
    mavlink_usv_mission_item_t it;
    usv_mission_t *g = staged_mission(b);
    const char *bad;
    text_t t;
    mavlink_msg_usv_mission_item_decode(msg, &it);
    if (b->staging == USV_STAGING_NONE || g->id != it.mission_id) {
        if (active_is(b, it.mission_id) && item_equals(active_mission(b), &it)) {
            send_mission_ack(b, msg, it.mission_id, active_mission(b)->count,
                             USV_MISSION_ACCEPTED, STAGE_ITEM); /* a late retry */
        } else {
            send_mission_ack(b, msg, it.mission_id, 0,
                             it.mission_id == b->dropped_id ? USV_MISSION_EXPIRED
                                                            : USV_MISSION_UNKNOWN_MISSION,
                             STAGE_ITEM);
        }
        return;
    }
    if (b->staging == USV_STAGING_VERIFIED) {
        send_mission_ack(b, msg, it.mission_id, g->count, USV_MISSION_ACCEPTED, STAGE_ITEM);
        return;
    }
    if (it.seq >= g->count) {
        send_mission_ack(b, msg, it.mission_id, b->staged_received, USV_MISSION_BAD_SEQ,
                         STAGE_ITEM);
        return;
    }
    bad = item_problem(&it);
    if (bad != NULL) {
        send_mission_ack(b, msg, it.mission_id, it.seq, USV_MISSION_OUT_OF_RANGE, STAGE_ITEM);
        text_begin(&t, "item ");
        tx_uint(&t, it.seq);
        tx_str(&t, ": ");
        tx_str(&t, bad);
        tx_str(&t, " out of range");
        send_text(b, MAV_SEVERITY_WARNING, &t);
        return;
    }
    g->lat[it.seq] = it.lat;
    g->lon[it.seq] = it.lon;
    g->t_ms[it.seq] = it.t_ms;
    g->speed_cms[it.seq] = it.speed_cms;
    g->course_cdeg[it.seq] = it.course_cdeg;
    g->heading_cdeg[it.seq] = it.heading_cdeg;
    b->staged_bits[it.seq >> 3] = (uint8_t)(b->staged_bits[it.seq >> 3] | (1u << (it.seq & 7u)));
    while (b->staged_received < g->count && staged_bit(b, b->staged_received)) {
        b->staged_received++;
    }
    b->staging_touch_ms = now;
    send_mission_ack(b, msg, it.mission_id, b->staged_received, USV_MISSION_ACCEPTED, STAGE_ITEM);
}

static void on_end(usv_boat_t *b, const mavlink_message_t *msg, uint32_t now)
{
    mavlink_usv_mission_end_t e;
    usv_mission_t *g = staged_mission(b);
    uint16_t i;
    text_t t;
    mavlink_msg_usv_mission_end_decode(msg, &e);
    if (b->staging == USV_STAGING_NONE || g->id != e.mission_id) {
        if (active_is(b, e.mission_id) && active_mission(b)->crc32 == e.crc32) {
            send_mission_ack(b, msg, e.mission_id, active_mission(b)->count,
                             USV_MISSION_ACCEPTED, STAGE_END); /* a retry after activation */
        } else {
            send_mission_ack(b, msg, e.mission_id, 0,
                             e.mission_id == b->dropped_id ? USV_MISSION_EXPIRED
                                                           : USV_MISSION_UNKNOWN_MISSION,
                             STAGE_END);
        }
        return;
    }
    if (b->staging == USV_STAGING_VERIFIED) {
        send_mission_ack(b, msg, e.mission_id, g->count, USV_MISSION_ACCEPTED, STAGE_END);
        return;
    }
    if (e.count != g->count || e.crc32 != g->crc32) {
        send_mission_ack(b, msg, e.mission_id, b->staged_received, USV_MISSION_CRC_MISMATCH,
                         STAGE_END);
        return;
    }
    if (b->staged_received < g->count) {
        send_mission_ack(b, msg, e.mission_id, b->staged_received, USV_MISSION_MISSING_ITEMS,
                         STAGE_END);
        return;
    }
    for (i = 1; i < g->count; i++) {
        if (g->t_ms[i] <= g->t_ms[i - 1u]) {
            drop_staging(b);
            send_mission_ack(b, msg, e.mission_id, i, USV_MISSION_OUT_OF_RANGE, STAGE_END);
            text_begin(&t, "item ");
            tx_uint(&t, i);
            tx_str(&t, ": t_ms not increasing");
            send_text(b, MAV_SEVERITY_WARNING, &t);
            return;
        }
    }
    if (usv_mission_crc32(g) != g->crc32) {
        drop_staging(b);
        send_mission_ack(b, msg, e.mission_id, 0, USV_MISSION_CRC_MISMATCH, STAGE_END);
        text_begin(&t, "mission ");
        tx_uint(&t, e.mission_id);
        tx_str(&t, ": CRC-32 mismatch, dropped");
        send_text(b, MAV_SEVERITY_WARNING, &t);
        return;
    }
    if (b->staged_swap_at != 0u) {
        const char *why = !at_or_after(b->staged_swap_at, now + 1u) ? "instant passed"
                                                                     : swap_problem(b, 0);
        if (why != NULL) {
            drop_staging(b);
            send_mission_ack(b, msg, e.mission_id, 0, USV_MISSION_DENIED, STAGE_END);
            text_begin(&t, "swap of ");
            tx_uint(&t, e.mission_id);
            tx_str(&t, " refused: ");
            tx_str(&t, why);
            send_text(b, MAV_SEVERITY_WARNING, &t);
            return;
        }
        b->staging = USV_STAGING_VERIFIED;
        send_mission_ack(b, msg, e.mission_id, g->count, USV_MISSION_ACCEPTED, STAGE_END);
        return;
    }
    if (!idle_like(b->state)) {
        drop_staging(b);
        send_mission_ack(b, msg, e.mission_id, 0, USV_MISSION_DENIED, STAGE_END);
        return;
    }
    b->active ^= 1u; /* atomic activation: the verified buffer becomes the active one */
    b->has_active = 1;
    b->staging = USV_STAGING_NONE;
    b->staged_received = 0;
    b->staged_swap_at = 0;
    b->state = USV_BOAT_STATE_READY;
    b->started = 0;
    b->current_seq = 0;
    hold_here(b);
    send_mission_ack(b, msg, e.mission_id, active_mission(b)->count, USV_MISSION_ACCEPTED,
                     STAGE_END);
    text_begin(&t, "mission ");
    tx_uint(&t, e.mission_id);
    tx_str(&t, " active: ");
    tx_uint(&t, active_mission(b)->count);
    tx_str(&t, " waypoints");
    send_text(b, MAV_SEVERITY_INFO, &t);
}

static void on_read(usv_boat_t *b, const mavlink_message_t *msg)
{
    mavlink_usv_mission_read_t r;
    const usv_mission_t *m = NULL;
    mavlink_msg_usv_mission_read_decode(msg, &r);
    if (active_is(b, r.mission_id)) {
        m = active_mission(b);
    } else if (b->staging != USV_STAGING_NONE && staged_mission(b)->id == r.mission_id) {
        m = staged_mission(b);
    }
    if (m == NULL) {
        send_mission_ack(b, msg, r.mission_id, 0, USV_MISSION_UNKNOWN_MISSION, STAGE_READ);
        return;
    }
    if (r.seq >= m->count || (m != active_mission(b) && !staged_bit(b, r.seq))) {
        send_mission_ack(b, msg, r.mission_id, r.seq, USV_MISSION_BAD_SEQ, STAGE_READ);
        return;
    }
    {
        mavlink_usv_mission_item_t it;
        memset(&it, 0, sizeof it);
        it.target_system = msg->sysid;
        it.target_component = msg->compid;
        it.mission_id = m->id;
        it.seq = r.seq;
        it.lat = m->lat[r.seq];
        it.lon = m->lon[r.seq];
        it.t_ms = m->t_ms[r.seq];
        it.speed_cms = m->speed_cms[r.seq];
        it.course_cdeg = m->course_cdeg[r.seq];
        it.heading_cdeg = m->heading_cdeg[r.seq];
        SEND(usv_mission_item, &it);
    }
}

/* ------------------------------------------------------------------ commands */

/* Execute a recovery command; returns the MAV_RESULT and sets the USV_COMMAND_REASON. */
static uint8_t do_command(usv_boat_t *b, uint16_t cmd, const mavlink_command_int_t *c,
                          uint32_t now, uint8_t *reason, float *distance)
{
    usv_mission_t *a = active_mission(b);
    *reason = USV_COMMAND_REASON_NONE;
    switch (cmd) {
    case MAV_CMD_USV_START:
        if (!b->has_active) {
            *reason = USV_COMMAND_REASON_NO_MISSION;
            return MAV_RESULT_DENIED;
        }
        if ((uint32_t)c->x != a->id || (uint32_t)c->y != a->crc32) {
            *reason = USV_COMMAND_REASON_MISSION_MISMATCH;
            return MAV_RESULT_DENIED;
        }
        if (b->state != USV_BOAT_STATE_READY) {
            *reason = USV_COMMAND_REASON_WRONG_STATE;
            return MAV_RESULT_DENIED;
        }
        *distance = dist_to(b, a->lat[0], a->lon[0]);
        if (*distance > b->cfg.start_radius_m) {
            *reason = USV_COMMAND_REASON_TOO_FAR;
            return MAV_RESULT_DENIED;
        }
        b->state = USV_BOAT_STATE_RUNNING;
        b->started = 1;
        b->t0_ms = now;
        b->current_seq = 0;
        b->gate_next = b->gate_leg = b->go_around = 0;
        return MAV_RESULT_ACCEPTED;
    case MAV_CMD_USV_HOLD: /* always acts: whatever moves stops and keeps station */
        if (b->state == USV_BOAT_STATE_RUNNING) {
            b->hold_since_ms = now;
            hold_here(b);
        }
        if (b->state == USV_BOAT_STATE_GO_AROUND) {
            hold_here(b);
        }
        if (b->state == USV_BOAT_STATE_RUNNING || b->state == USV_BOAT_STATE_FAILSAFE ||
            b->state == USV_BOAT_STATE_HOLD || b->state == USV_BOAT_STATE_GO_AROUND) {
            b->state = USV_BOAT_STATE_HOLD;
            b->guidance_on = 0;
        }
        return MAV_RESULT_ACCEPTED; /* IDLE, READY, DONE, ABORTED: nothing moves */
    case MAV_CMD_USV_RESUME:
        if (b->state == USV_BOAT_STATE_RUNNING) {
            return MAV_RESULT_ACCEPTED;
        }
        if (b->state == USV_BOAT_STATE_GO_AROUND) { /* a new approach, from standby only */
            if (!b->at_standby) {
                *reason = USV_COMMAND_REASON_WRONG_STATE;
                return MAV_RESULT_DENIED;
            }
            b->t0_ms = now - a->t_ms[b->standby_seq]; /* the mission from the standby item */
            b->current_seq = b->standby_seq;
            b->gate_next = b->gate_leg = b->go_around = b->at_standby = 0;
            b->state = USV_BOAT_STATE_RUNNING;
            return MAV_RESULT_ACCEPTED;
        }
        if ((b->state != USV_BOAT_STATE_HOLD && b->state != USV_BOAT_STATE_FAILSAFE) ||
            !b->has_active) {
            *reason = USV_COMMAND_REASON_WRONG_STATE;
            return MAV_RESULT_DENIED;
        }
        if (b->go_around) { /* back to the go-around it was flying */
            b->state = USV_BOAT_STATE_GO_AROUND;
            return MAV_RESULT_ACCEPTED;
        }
        b->t0_ms += now - b->hold_since_ms; /* the schedule shifted by the time held */
        b->state = USV_BOAT_STATE_RUNNING;
        if (b->gate_leg) { /* held on the final leg: the gates still ahead are armed again */
            float d, x, course;
            uint8_t k = 0;
            if (final_leg(b, &d, &x, &course) && d <= GATE_M[GATES - 1]) {
                start_go_around(b, 0.0f, "resumed inside the last gate", -1.0f);
                return MAV_RESULT_ACCEPTED;
            }
            while (k < GATES && GATE_M[k] >= d) {
                k++;
            }
            b->gate_next = k;
            b->gate_leg = 0; /* joined again: gates too close inside it are skipped */
        }
        return MAV_RESULT_ACCEPTED;
    case MAV_CMD_USV_ABORT: /* always acts: propellers stop, missions and staging dropped */
        drop_staging(b);
        b->has_active = 0;
        b->started = 0;
        b->guidance_on = 0;
        b->current_seq = 0;
        b->go_around = b->at_standby = 0;
        b->state = USV_BOAT_STATE_ABORTED;
        return MAV_RESULT_ACCEPTED;
    default:
        *reason = USV_COMMAND_REASON_UNKNOWN_COMMAND;
        return MAV_RESULT_UNSUPPORTED;
    }
}

static void send_command_ack(usv_boat_t *b, const mavlink_message_t *req, uint16_t cmd,
                             uint8_t result, uint8_t reason, int32_t seq)
{
    mavlink_command_ack_t a;
    memset(&a, 0, sizeof a);
    a.command = cmd;
    a.result = result;
    a.progress = reason; /* USV_COMMAND_REASON */
    a.result_param2 = seq;
    a.target_system = req->sysid;
    a.target_component = req->compid;
    SEND(command_ack, &a);
}

static int as_counter(float v, uint32_t *out)
{
    if (!(v >= 0.0f && v < SEQ_LIMIT) || v != (float)(uint32_t)v) {
        return 0;
    }
    *out = (uint32_t)v;
    return 1;
}

static void on_command_int(usv_boat_t *b, const mavlink_message_t *msg, uint32_t now)
{
    mavlink_command_int_t c;
    uint32_t seq, session;
    usv_dup_t *d = NULL, *slot = NULL;
    unsigned i;
    uint8_t reason = USV_COMMAND_REASON_NONE;
    float distance = 0.0f;
    uint8_t result;
    text_t t;
    mavlink_msg_command_int_decode(msg, &c);
    if (c.command < MAV_CMD_USV_START || c.command > MAV_CMD_USV_ABORT) {
        send_command_ack(b, msg, c.command, MAV_RESULT_UNSUPPORTED,
                         USV_COMMAND_REASON_UNKNOWN_COMMAND, 0);
        return;
    }
    if (!as_counter(c.param1, &seq) || !as_counter(c.param2, &session)) {
        send_command_ack(b, msg, c.command, MAV_RESULT_DENIED, USV_COMMAND_REASON_NONE, 0);
        text_begin(&t, "command refused: param1/param2 not integers below 2^24");
        send_text(b, MAV_SEVERITY_WARNING, &t);
        return;
    }
    if (session != b->station_session) { /* a new station session: forget the old one */
        memset(b->dup, 0, sizeof b->dup);
        b->station_session = session;
    }
    for (i = 0; i < USV_DUP_SLOTS; i++) {
        usv_dup_t *e = &b->dup[i];
        if (e->used && at_or_after(now, e->at_ms + b->cfg.dup_expiry_ms)) {
            e->used = 0; /* expired */
        }
        if (e->used && e->session == session && e->seq == seq && e->command == c.command) {
            d = e;
        }
        if (slot == NULL || (slot->used && (!e->used || at_or_after(slot->at_ms, e->at_ms)))) {
            slot = e; /* a free slot, else the oldest */
        }
    }
    if (d != NULL && c.command != MAV_CMD_USV_HOLD && c.command != MAV_CMD_USV_ABORT) {
        /* a retry: the same answer, not executed again */
        send_command_ack(b, msg, c.command, d->result, d->reason, (int32_t)seq);
        return;
    }
    result = do_command(b, c.command, &c, now, &reason, &distance);
    if (d == NULL) {
        d = slot;
        d->used = 1;
        d->session = session;
        d->seq = seq;
        d->command = c.command;
    }
    d->result = result;
    d->reason = reason;
    d->at_ms = now;
    send_command_ack(b, msg, c.command, result, reason, (int32_t)seq); /* the ACK first */
    if (reason == USV_COMMAND_REASON_TOO_FAR) {
        text_begin(&t, "START refused: ");
        tx_metres(&t, distance);
        tx_str(&t, " from waypoint 0 > "); /* fits the 50 characters up to 99999.9 m */
        tx_metres(&t, b->cfg.start_radius_m);
        send_text(b, MAV_SEVERITY_WARNING, &t);
    } else if (reason == USV_COMMAND_REASON_MISSION_MISMATCH) {
        text_begin(&t, "START refused: holds mission ");
        tx_uint(&t, active_mission(b)->id);
        send_text(b, MAV_SEVERITY_WARNING, &t);
    }
}

/* ------------------------------------------------ standard MAVLink for ground stations */
/* Any ground station reads the active mission with the standard mission protocol
 * (MISSION_REQUEST_LIST, MISSION_REQUEST_INT / MISSION_REQUEST): one NAV_WAYPOINT per
 * waypoint, each but the last followed by DO_CHANGE_SPEED with the leg's planned speed
 * (length / duration). HEARTBEAT names a mode (ArduPilot Rover's numbers, which
 * ground stations use for a SURFACE_BOAT), MISSION_CURRENT follows it, and
 * MISSION_ITEM_REACHED reports each waypoint passed (protocol/README.md section 3). */

#define STD_HOLD 4u   /* motors stopped */
#define STD_LOITER 5u /* keeping station */
#define STD_AUTO 10u  /* following the mission */
#define WGS84_A 6378137.0f
#define WGS84_E2 6.69437999014e-3f

static uint32_t std_mode(uint8_t state)
{
    switch (state) {
    case USV_BOAT_STATE_IDLE:
    case USV_BOAT_STATE_ABORTED:
        return STD_HOLD;
    case USV_BOAT_STATE_READY:
    case USV_BOAT_STATE_HOLD:
    case USV_BOAT_STATE_DONE:
    case USV_BOAT_STATE_FAILSAFE:
        return STD_LOITER;
    default:
        return STD_AUTO; /* RUNNING, GO_AROUND, and states this table does not name */
    }
}

static int std_armed(uint8_t state)
{
    return state == USV_BOAT_STATE_RUNNING || state == USV_BOAT_STATE_HOLD ||
           state == USV_BOAT_STATE_FAILSAFE || state == USV_BOAT_STATE_GO_AROUND;
}

static uint8_t std_mission_state(uint8_t state)
{
    switch (state) {
    case USV_BOAT_STATE_READY:
        return MISSION_STATE_NOT_STARTED;
    case USV_BOAT_STATE_RUNNING:
        return MISSION_STATE_ACTIVE;
    case USV_BOAT_STATE_HOLD:
    case USV_BOAT_STATE_FAILSAFE:
        return MISSION_STATE_PAUSED;
    case USV_BOAT_STATE_DONE:
        return MISSION_STATE_COMPLETE;
    case USV_BOAT_STATE_IDLE:
    case USV_BOAT_STATE_ABORTED:
        return MISSION_STATE_NO_MISSION;
    default:
        return MISSION_STATE_ACTIVE;
    }
}

static uint16_t std_count(usv_boat_t *b)
{
    return b->has_active ? (uint16_t)(2u * active_mission(b)->count - 1u) : 0u;
}

/* Leg length on the WGS-84 ellipsoid: meridian and prime-vertical radii of curvature at
 * the mid latitude (as link/standard_mission.py leg_length_m). */
static float std_leg_m(int32_t lat1, int32_t lon1, int32_t lat2, int32_t lon2)
{
    float phi = ((float)lat1 + (float)lat2) * (0.5e-7f * PI_F / 180.0f);
    float s = sinf(phi);
    float w = 1.0f - WGS84_E2 * s * s;
    float sw = sqrtf(w);
    float dn = (float)(lat2 - lat1) * (1e-7f * PI_F / 180.0f) * (WGS84_A * (1.0f - WGS84_E2) /
                                                               (w * sw));
    float de = (float)(lon2 - lon1) * (1e-7f * PI_F / 180.0f) * (WGS84_A / sw) * cosf(phi);
    return sqrtf(dn * dn + de * de);
}

/* The leg's planned speed (as link/standard_mission.py leg_speed): length / duration,
 * or the mean of its end speeds where the plan follows eq. 11 (dT = 2 L / (v_a + v_b))
 * within the wire's rounding (1e-7 deg positions, 1 ms, 1 cm/s). */
static float std_leg_speed(const usv_mission_t *m, uint16_t w)
{
    uint32_t dt = m->t_ms[w + 1u] - m->t_ms[w];
    float dt_s, geometric, mean;
    if (dt == 0u) {
        return 0.0f;
    }
    dt_s = (float)dt * 1e-3f;
    geometric = std_leg_m(m->lat[w], m->lon[w], m->lat[w + 1u], m->lon[w + 1u]) / dt_s;
    mean = (float)(m->speed_cms[w] + m->speed_cms[w + 1u]) * 0.005f;
    return fabsf(mean - geometric) <= 0.01f + (0.02f + 0.001f * geometric) / dt_s ? mean
                                                                                 : geometric;
}

static int std_is_read(uint32_t msgid)
{
    return msgid == MAVLINK_MSG_ID_MISSION_REQUEST_LIST ||
           msgid == MAVLINK_MSG_ID_MISSION_REQUEST_INT || msgid == MAVLINK_MSG_ID_MISSION_REQUEST;
}

/* standard messages that would command the boat: refused from anyone but the station */
static int std_is_control(uint32_t msgid)
{
    switch (msgid) {
    case MAVLINK_MSG_ID_MISSION_COUNT:
    case MAVLINK_MSG_ID_MISSION_ITEM_INT:
    case MAVLINK_MSG_ID_MISSION_ITEM:
    case MAVLINK_MSG_ID_MISSION_CLEAR_ALL:
    case MAVLINK_MSG_ID_MISSION_SET_CURRENT:
    case MAVLINK_MSG_ID_MISSION_WRITE_PARTIAL_LIST:
    case MAVLINK_MSG_ID_SET_MODE:
    case MAVLINK_MSG_ID_SET_POSITION_TARGET_GLOBAL_INT:
    case MAVLINK_MSG_ID_SET_POSITION_TARGET_LOCAL_NED:
    case MAVLINK_MSG_ID_MANUAL_CONTROL:
    case MAVLINK_MSG_ID_RC_CHANNELS_OVERRIDE:
    case MAVLINK_MSG_ID_SETUP_SIGNING:
    case MAVLINK_MSG_ID_PARAM_SET:
        return 1;
    default:
        return 0;
    }
}

static void std_send_ack(usv_boat_t *b, const mavlink_message_t *req, uint8_t result,
                         uint8_t type)
{
    mavlink_mission_ack_t a;
    memset(&a, 0, sizeof a);
    a.target_system = req->sysid;
    a.target_component = req->compid;
    a.type = result;
    a.mission_type = type;
    SEND(mission_ack, &a);
}

static void std_on_read(usv_boat_t *b, const mavlink_message_t *msg)
{
    uint8_t target, type;
    uint16_t seq = 0, count = std_count(b);
    if (msg->msgid == MAVLINK_MSG_ID_MISSION_REQUEST_LIST) {
        mavlink_mission_count_t c;
        target = mavlink_msg_mission_request_list_get_target_system(msg);
        type = mavlink_msg_mission_request_list_get_mission_type(msg);
        if (target != 0u && target != b->cfg.boat_id) {
            return;
        }
        memset(&c, 0, sizeof c);
        c.target_system = msg->sysid;
        c.target_component = msg->compid;
        c.count = type == MAV_MISSION_TYPE_MISSION ? count : 0u;
        c.mission_type = type;
        SEND(mission_count, &c);
        return;
    }
    if (msg->msgid == MAVLINK_MSG_ID_MISSION_REQUEST_INT) {
        target = mavlink_msg_mission_request_int_get_target_system(msg);
        type = mavlink_msg_mission_request_int_get_mission_type(msg);
        seq = mavlink_msg_mission_request_int_get_seq(msg);
    } else {
        target = mavlink_msg_mission_request_get_target_system(msg);
        type = mavlink_msg_mission_request_get_mission_type(msg);
        seq = mavlink_msg_mission_request_get_seq(msg);
    }
    if (target != 0u && target != b->cfg.boat_id) {
        return;
    }
    if (type != MAV_MISSION_TYPE_MISSION || seq >= count) {
        std_send_ack(b, msg, MAV_MISSION_INVALID_SEQUENCE, type);
        return;
    }
    {
        const usv_mission_t *m = active_mission(b);
        uint16_t w = (uint16_t)(seq / 2u);
        mavlink_mission_item_int_t it;
        memset(&it, 0, sizeof it);
        it.target_system = msg->sysid;
        it.target_component = msg->compid;
        it.seq = seq;
        it.autocontinue = 1;
        it.mission_type = MAV_MISSION_TYPE_MISSION;
        if (seq % 2u == 0u) {
            it.frame = MAV_FRAME_GLOBAL_RELATIVE_ALT;
            it.command = MAV_CMD_NAV_WAYPOINT;
            it.x = m->lat[w];
            it.y = m->lon[w];
        } else {
            it.frame = MAV_FRAME_MISSION;
            it.command = MAV_CMD_DO_CHANGE_SPEED;
            it.param1 = 1.0f; /* ground speed */
            it.param2 = std_leg_speed(m, w);
            it.param3 = -1.0f; /* throttle unchanged */
        }
        if (msg->msgid == MAVLINK_MSG_ID_MISSION_REQUEST_INT) {
            SEND(mission_item_int, &it);
        } else { /* the deprecated float form, answered in kind */
            mavlink_mission_item_t f;
            memset(&f, 0, sizeof f);
            f.target_system = it.target_system;
            f.target_component = it.target_component;
            f.seq = it.seq;
            f.frame = it.frame;
            f.command = it.command;
            f.autocontinue = 1;
            f.param1 = it.param1;
            f.param2 = it.param2;
            f.param3 = it.param3;
            f.x = (float)it.x * 1e-7f;
            f.y = (float)it.y * 1e-7f;
            f.mission_type = MAV_MISSION_TYPE_MISSION;
            SEND(mission_item, &f);
        }
    }
}

/* MISSION_CURRENT with the heartbeat: the NAV item of the waypoint steered to */
static void std_send_mission_current(usv_boat_t *b)
{
    mavlink_mission_current_t c;
    memset(&c, 0, sizeof c);
    if (b->has_active) { /* current_seq is the leg: the waypoint after it is steered to */
        uint16_t last = (uint16_t)(active_mission(b)->count - 1u);
        uint16_t w = b->state == USV_BOAT_STATE_RUNNING || b->state == USV_BOAT_STATE_HOLD ||
                             b->state == USV_BOAT_STATE_FAILSAFE
                         ? (b->current_seq < last ? (uint16_t)(b->current_seq + 1u) : last)
                         : (b->state == USV_BOAT_STATE_DONE ? last : 0u);
        c.seq = (uint16_t)(2u * w);
    }
    c.total = std_count(b);
    c.mission_state = std_mission_state(b->state);
    c.mission_mode = b->state == USV_BOAT_STATE_RUNNING ? 1u : 0u;
    TELEMETRY(mission_current, &c);
}

/* MISSION_ITEM_REACHED for every waypoint passed since the last report (all of them when
 * the mission is done) */
static void std_items_reached(usv_boat_t *b)
{
    uint16_t reached;
    mavlink_mission_item_reached_t r;
    if (!b->has_active || !(b->state == USV_BOAT_STATE_RUNNING ||
                            b->state == USV_BOAT_STATE_HOLD ||
                            b->state == USV_BOAT_STATE_FAILSAFE ||
                            b->state == USV_BOAT_STATE_DONE)) {
        return;
    }
    if (b->std_reached_id != active_mission(b)->id) {
        b->std_reached_id = active_mission(b)->id;
        b->std_reached = 0;
    }
    reached = b->state == USV_BOAT_STATE_DONE ? active_mission(b)->count
                                              : (uint16_t)(b->current_seq + 1u);
    if (reached > active_mission(b)->count) {
        reached = active_mission(b)->count;
    }
    while (b->std_reached < reached) {
        r.seq = (uint16_t)(2u * b->std_reached);
        SEND(mission_item_reached, &r);
        b->std_reached++;
    }
}

/* ------------------------------------------------------------------ receiving */

static uint8_t target_of(const mavlink_message_t *msg)
{
    switch (msg->msgid) {
    case MAVLINK_MSG_ID_COMMAND_INT:
        return mavlink_msg_command_int_get_target_system(msg);
    case MAVLINK_MSG_ID_COMMAND_LONG:
        return mavlink_msg_command_long_get_target_system(msg);
    case MAVLINK_MSG_ID_USV_MISSION_BEGIN:
        return mavlink_msg_usv_mission_begin_get_target_system(msg);
    case MAVLINK_MSG_ID_USV_MISSION_ITEM:
        return mavlink_msg_usv_mission_item_get_target_system(msg);
    case MAVLINK_MSG_ID_USV_MISSION_END:
        return mavlink_msg_usv_mission_end_get_target_system(msg);
    case MAVLINK_MSG_ID_USV_MISSION_READ:
        return mavlink_msg_usv_mission_read_get_target_system(msg);
    case MAVLINK_MSG_ID_USV_RAMP_POSE:
        return mavlink_msg_usv_ramp_pose_get_target_system(msg);
    case MAVLINK_MSG_ID_USV_GUIDANCE:
        return mavlink_msg_usv_guidance_get_target_system(msg);
    default:
        return 0;
    }
}

/* messages that command, upload or steer: only from the paired station, addressed here */
static int is_control(uint32_t msgid)
{
    switch (msgid) {
    case MAVLINK_MSG_ID_COMMAND_INT:
    case MAVLINK_MSG_ID_COMMAND_LONG:
    case MAVLINK_MSG_ID_USV_MISSION_BEGIN:
    case MAVLINK_MSG_ID_USV_MISSION_ITEM:
    case MAVLINK_MSG_ID_USV_MISSION_END:
    case MAVLINK_MSG_ID_USV_MISSION_READ:
    case MAVLINK_MSG_ID_USV_RAMP_POSE:
    case MAVLINK_MSG_ID_USV_GUIDANCE:
        return 1;
    default:
        return 0;
    }
}

static int has_target(uint32_t msgid)
{
    return is_control(msgid) || msgid == MAVLINK_MSG_ID_USV_RAMP_POSE;
}

static void on_frame(usv_boat_t *b, const mavlink_message_t *msg, uint32_t now)
{
    text_t t;
    if (msg->sysid == b->cfg.boat_id) {
        return; /* our own frames heard back: never the station */
    }
    if (std_is_read(msg->msgid)) {
        std_on_read(b, msg); /* any ground station may read (with the key): never a command */
        return;
    }
    if (msg->sysid != b->cfg.station_id) {
        if (is_control(msg->msgid) || std_is_control(msg->msgid)) {
            refuse(b, USV_REFUSE_SENDER);
        }
        return; /* other systems on the channel: never obeyed, never refresh the link */
    }
    if (msg->msgid == MAVLINK_MSG_ID_RADIO_STATUS) {
        return; /* the radio's unsigned report: not the station speaking */
    }
    if (has_target(msg->msgid) && target_of(msg) != b->cfg.boat_id) {
        return; /* for another boat */
    }
    b->last_station_ms = now; /* only the paired station's valid frames refresh the timer */
    if (!b->station_heard) {
        b->station_heard = 1;
        text_begin(&t, b->state == USV_BOAT_STATE_FAILSAFE
                           ? "link back; failsafe hold: RESUME or ABORT" : "link up");
        send_text(b, MAV_SEVERITY_INFO, &t);
    }
    switch (msg->msgid) {
    case MAVLINK_MSG_ID_COMMAND_INT:
        on_command_int(b, msg, now);
        break;
    case MAVLINK_MSG_ID_COMMAND_LONG:
        send_command_ack(b, msg, mavlink_msg_command_long_get_command(msg),
                         MAV_RESULT_UNSUPPORTED, USV_COMMAND_REASON_UNKNOWN_COMMAND, 0);
        break;
    case MAVLINK_MSG_ID_USV_MISSION_BEGIN:
        on_begin(b, msg, now);
        break;
    case MAVLINK_MSG_ID_USV_MISSION_ITEM:
        on_item(b, msg, now);
        break;
    case MAVLINK_MSG_ID_USV_MISSION_END:
        on_end(b, msg, now);
        break;
    case MAVLINK_MSG_ID_USV_MISSION_READ:
        on_read(b, msg);
        break;
    case MAVLINK_MSG_ID_USV_RAMP_POSE:
        b->ramp_time_ms = mavlink_msg_usv_ramp_pose_get_time_boot_ms(msg);
        b->ramp_lat = mavlink_msg_usv_ramp_pose_get_lat(msg);
        b->ramp_lon = mavlink_msg_usv_ramp_pose_get_lon(msg);
        b->ramp_bearing_cdeg = mavlink_msg_usv_ramp_pose_get_bearing_cdeg(msg);
        break;
    case MAVLINK_MSG_ID_USV_GUIDANCE:
        if (b->state == USV_BOAT_STATE_RUNNING) {
            uint16_t h = mavlink_msg_usv_guidance_get_heading_cdeg(msg);
            if (h < 36000u) {
                b->guidance_heading = (float)h * (PI_F / 18000.0f);
                b->guidance_speed = (float)mavlink_msg_usv_guidance_get_speed_cms(msg) * 0.01f;
                b->guidance_until_ms = now + mavlink_msg_usv_guidance_get_valid_ms(msg);
                b->guidance_on = 1;
            }
        }
        break;
    case MAVLINK_MSG_ID_TIMESYNC:
        if (mavlink_msg_timesync_get_tc1(msg) == 0) {
            mavlink_timesync_t ts;
            ts.tc1 = (int64_t)uptime(b) * 1000000 + 1; /* never 0 (that is a request) */
            ts.ts1 = mavlink_msg_timesync_get_ts1(msg);
            SEND(timesync, &ts);
        }
        break;
    default:
        break;
    }
}

static uint64_t signed_timestamp(const mavlink_message_t *msg)
{
    uint64_t ts = 0;
    int i;
    for (i = 6; i >= 1; i--) {
        ts = (ts << 8) | msg->signature[i];
    }
    return ts;
}

static void on_byte(usv_boat_t *b, uint8_t c, uint32_t now)
{
    uint8_t r = mavlink_frame_char_buffer(&b->rx_msg, &b->rx_status, c, NULL, NULL);
    if (r == MAVLINK_FRAMING_OK) {
        if (b->rx_status.signing != NULL && (b->rx_msg.incompat_flags & MAVLINK_IFLAG_SIGNED) &&
            signed_timestamp(&b->rx_msg) < b->cfg.boot_timestamp) {
            refuse(b, USV_REFUSE_REPLAY); /* signed before this boot: a replay */
            return;
        }
        if (b->rx_msg.sysid == b->cfg.station_id &&
            (b->rx_msg.incompat_flags & MAVLINK_IFLAG_SIGNED) &&
            signed_timestamp(&b->rx_msg) > b->station_ts) {
            b->station_ts = signed_timestamp(&b->rx_msg); /* the replay floor to persist */
        }
        on_frame(b, &b->rx_msg, now);
    } else if (r == MAVLINK_FRAMING_BAD_SIGNATURE) {
        if (!(b->rx_msg.incompat_flags & MAVLINK_IFLAG_SIGNED)) {
            refuse(b, USV_REFUSE_UNSIGNED);
        } else if (b->signing.last_status == MAVLINK_SIGNING_STATUS_BAD_SIGNATURE) {
            refuse(b, USV_REFUSE_BAD_SIGNATURE);
        } else {
            refuse(b, USV_REFUSE_REPLAY);
        }
    }
}

/* Unsigned frames accepted with signing on: RADIO_STATUS from SiK radios only. They never
 * count as the station's (the link timer needs a signed frame). */
static bool accept_unsigned(const mavlink_status_t *status, uint32_t msgid)
{
    (void)status;
    return msgid == MAVLINK_MSG_ID_RADIO_STATUS;
}

/* ------------------------------------------------------------------ control */

static void set_thrust(usv_boat_t *b, float left, float right)
{
    b->thrust_left = (int16_t)clampf(left, -1000.0f, 1000.0f);
    b->thrust_right = (int16_t)clampf(right, -1000.0f, 1000.0f);
}

/* steer a compass course at a speed: differential thrust on the heading error */
static void steer(usv_boat_t *b, float course, float speed)
{
    float err = wrap_pi(course - b->nav.heading_rad);
    float diff = clampf(err * 800.0f, -700.0f, 700.0f);
    float surge = clampf(speed / b->cfg.max_speed_mps, 0.0f, 1.0f) * 1000.0f;
    float c = cosf(err);
    surge *= c > 0.0f ? c : 0.0f;
    if (surge + fabsf(diff) > 1000.0f) {
        surge = 1000.0f - fabsf(diff);
    }
    set_thrust(b, surge + diff, surge - diff);
}

static void keep_station(usv_boat_t *b)
{
    float n, e, d;
    text_t t;
    local_ne(b->nav.lat_e7, b->nav.lon_e7, b->hold_lat, b->hold_lon, &n, &e);
    d = sqrtf(n * n + e * e);
    if (d > OVER_CAPACITY_M && !(b->flags & USV_STATE_FLAG_OVER_CAPACITY)) {
        b->flags |= USV_STATE_FLAG_OVER_CAPACITY;
        text_begin(&t, "current exceeds what the boat can hold: drifting");
        send_text(b, MAV_SEVERITY_WARNING, &t);
    } else if (d < 2.0f * KEEP_RADIUS_M) {
        b->flags &= (uint8_t)~USV_STATE_FLAG_OVER_CAPACITY;
    }
    if (d < KEEP_RADIUS_M) {
        set_thrust(b, 0.0f, 0.0f);
        return;
    }
    steer(b, atan2f(e, n), clampf(0.3f * d, 0.0f, KEEP_SPEED_MPS));
}

/* A missed approach gate: back away from the ramp if close, then go to the standby item
 * (the first mission item at least STANDBY_M back from the last) and keep station there. */
static void start_go_around(usv_boat_t *b, float gate, const char *why, float value)
{
    const usv_mission_t *m = active_mission(b);
    uint16_t last = (uint16_t)(m->count - 1u), k = last;
    text_t t;
    while (k > 0u) {
        float n, e;
        k--;
        local_ne(m->lat[last], m->lon[last], m->lat[k], m->lon[k], &n, &e);
        if (sqrtf(n * n + e * e) >= STANDBY_M) {
            break;
        }
    }
    b->standby_seq = k;
    b->go_around = 1;
    b->at_standby = 0;
    b->guidance_on = 0;
    b->state = USV_BOAT_STATE_GO_AROUND;
    text_begin(&t, "go-around: ");
    if (gate > 0.0f) {
        tx_str(&t, "gate ");
        tx_uint(&t, (uint32_t)gate);
        tx_str(&t, " m: ");
    }
    tx_str(&t, why);
    if (value >= 0.0f) {
        tx_str(&t, " ");
        tx_metres(&t, value);
    }
    send_text(b, MAV_SEVERITY_WARNING, &t);
}

/* The gates of the final leg; `d`: metres to go along it, `xte`: cross-track (m). Returns 1
 * when a gate was missed (the boat now goes around). */
static int check_gates(usv_boat_t *b, float d, float xte, float leg_course)
{
    if (!b->gate_leg) { /* joined the final leg: gates too close inside it cannot be met */
        b->gate_leg = 1;
        while (b->gate_next < GATES - 1 && GATE_M[b->gate_next] > d - GATE_JOIN_M) {
            b->gate_next++;
        }
    }
    if (b->gate_next < GATES && d <= GATE_M[b->gate_next]) {
        float gate = GATE_M[b->gate_next];
        float herr = fabsf(wrap_pi(b->nav.heading_rad - leg_course)) * (180.0f / PI_F);
        b->gate_next++;
        if (b->nav.fix_type < GPS_FIX_TYPE_RTK_FIXED) {
            start_go_around(b, gate, "no RTK-class fix", -1.0f);
            return 1;
        }
        if (fabsf(xte) > ARRIVAL_OFFSET_M * (0.5f + gate / 4.0f)) {
            start_go_around(b, gate, "cross-track", fabsf(xte));
            return 1;
        }
        if (herr > (gate > 5.0f ? gate : 5.0f)) {
            start_go_around(b, gate, "heading off (deg)", herr);
            return 1;
        }
    }
    return 0;
}

static void fly_go_around(usv_boat_t *b)
{
    const usv_mission_t *m = active_mission(b);
    uint16_t last = (uint16_t)(m->count - 1u);
    float n, e, d;
    text_t t;
    if (b->at_standby) {
        keep_station(b);
        return;
    }
    if (dist_to(b, m->lat[last], m->lon[last]) < BACK_OFF_M) {
        set_thrust(b, -400.0f, -400.0f); /* astern, away from the ramp */
        return;
    }
    local_ne(b->nav.lat_e7, b->nav.lon_e7, m->lat[b->standby_seq], m->lon[b->standby_seq], &n,
             &e);
    d = sqrtf(n * n + e * e);
    if (d <= 2.0f * KEEP_RADIUS_M) {
        b->at_standby = 1;
        b->hold_lat = m->lat[b->standby_seq];
        b->hold_lon = m->lon[b->standby_seq];
        text_begin(&t, "go-around: at standby, RESUME to approach");
        send_text(b, MAV_SEVERITY_INFO, &t);
        keep_station(b);
        return;
    }
    steer(b, atan2f(e, n), clampf(TRACK_GAIN * d, 0.5f, 1.5f));
}

/* On the final leg (steering to the last item): `d` metres to go along it, `x` the
 * cross-track (m, left positive), `course` the leg's direction (rad from north). Returns 0
 * when not on it. */
static int final_leg(usv_boat_t *b, float *d, float *x, float *course)
{
    const usv_mission_t *m = active_mission(b);
    uint16_t last = (uint16_t)(m->count - 1u);
    float fn, fe, gn, ge, flen;
    if (!b->has_active || last == 0u || b->current_seq + 1u < last) {
        return 0;
    }
    local_ne(m->lat[last - 1u], m->lon[last - 1u], m->lat[last], m->lon[last], &fn, &fe);
    local_ne(m->lat[last], m->lon[last], b->nav.lat_e7, b->nav.lon_e7, &gn, &ge);
    flen = sqrtf(fn * fn + fe * fe);
    if (flen <= 1e-3f) {
        return 0;
    }
    *d = -(gn * fn + ge * fe) / flen;
    *x = (fe * gn - fn * ge) / flen;
    *course = atan2f(fe, fn);
    return 1;
}

/* Why a hot swap cannot be taken now (NULL: it can): RUNNING and not committed to the
 * final approach (on the final leg inside the first gate: the gates decide), or GO_AROUND
 * keeping station at the standby item (the station's new approach), the new mission's
 * item 0 then within the START radius (`at_instant`: the staged mission is checked). */
static const char *swap_problem(usv_boat_t *b, int at_instant)
{
    float d, x, course;
    if (b->state == USV_BOAT_STATE_RUNNING) {
        if (b->gate_leg && final_leg(b, &d, &x, &course) && d <= GATE_M[0]) {
            return "on the final approach";
        }
        return NULL;
    }
    if (b->state != USV_BOAT_STATE_GO_AROUND) {
        return "not running";
    }
    if (!b->at_standby) {
        return "go-around not at standby yet";
    }
    if (at_instant) {
        const usv_mission_t *g = staged_mission(b);
        if (dist_to(b, g->lat[0], g->lon[0]) > b->cfg.start_radius_m) {
            return "too far from waypoint 0";
        }
    }
    return NULL;
}

/* Track the timed waypoints: the reference point moves linearly in time along each leg;
 * velocity command = leg velocity + TRACK_GAIN * position error. */
static void track(usv_boat_t *b, uint32_t now)
{
    const usv_mission_t *m = active_mission(b);
    uint32_t tm = now - b->t0_ms;
    uint16_t i = b->current_seq;
    uint16_t last = (uint16_t)(m->count - 1u);
    float bn, be, vn, ve, rn, re, ln, le, len, dt, frac;
    if (i > last) {
        i = 0;
    }
    while (i < last && m->t_ms[i + 1u] <= tm) {
        i++;
    }
    b->current_seq = i;
    if (last > 0u) { /* the approach gates on the final leg */
        float fd, fx, course;
        if (final_leg(b, &fd, &fx, &course) && fd > 0.0f && check_gates(b, fd, fx, course)) {
            return;
        }
    }
    if (i >= last) {
        float d = dist_to(b, m->lat[last], m->lon[last]);
        b->cross_track = 0.0f;
        b->slip = (float)(tm - m->t_ms[last]) * 1e-3f;
        if (d <= DONE_RADIUS_M) {
            b->state = USV_BOAT_STATE_DONE;
            b->guidance_on = 0;
            set_thrust(b, 0.0f, 0.0f);
            return;
        }
        local_ne(m->lat[last], m->lon[last], b->nav.lat_e7, b->nav.lon_e7, &bn, &be);
        steer(b, atan2f(-be, -bn), clampf(TRACK_GAIN * d, 0.0f, b->cfg.max_speed_mps));
        return;
    }
    local_ne(m->lat[i], m->lon[i], m->lat[i + 1u], m->lon[i + 1u], &ln, &le);
    local_ne(m->lat[i], m->lon[i], b->nav.lat_e7, b->nav.lon_e7, &bn, &be);
    dt = (float)(m->t_ms[i + 1u] - m->t_ms[i]) * 1e-3f;
    frac = (float)(tm - m->t_ms[i]) * 1e-3f / dt;
    rn = ln * frac;
    re = le * frac;
    vn = ln / dt + TRACK_GAIN * (rn - bn);
    ve = le / dt + TRACK_GAIN * (re - be);
    len = sqrtf(ln * ln + le * le);
    if (len > 1e-3f) {
        float along_b = (bn * ln + be * le) / len;
        b->cross_track = (le * bn - ln * be) / len; /* positive: boat left of the track */
        b->slip = (len * frac - along_b) / (len / dt);
    } else {
        b->cross_track = 0.0f;
        b->slip = 0.0f;
    }
    if (b->guidance_on && !at_or_after(now, b->guidance_until_ms)) {
        steer(b, b->guidance_heading, b->guidance_speed);
        return;
    }
    b->guidance_on = 0;
    steer(b, atan2f(ve, vn), clampf(sqrtf(vn * vn + ve * ve), 0.0f, b->cfg.max_speed_mps));
}

/* hot swap at the instant on the boat clock: a verified staged mission becomes the active
 * one once `now` reaches its instant (dropped if the boat is not running then) */
static void swap_if_due(usv_boat_t *b, uint32_t now)
{
    text_t t;
    if (b->staging == USV_STAGING_VERIFIED && at_or_after(now, b->staged_swap_at)) {
        uint32_t at = b->staged_swap_at;
        const char *why = swap_problem(b, 1);
        if (why == NULL) {
            int approach = b->state == USV_BOAT_STATE_GO_AROUND;
            b->active ^= 1u;
            b->staging = USV_STAGING_NONE;
            b->staged_received = 0;
            b->staged_swap_at = 0;
            b->t0_ms = at; /* item times count from the swap instant */
            b->current_seq = 0;
            b->guidance_on = 0;
            b->gate_next = b->gate_leg = 0;
            b->go_around = b->at_standby = 0;
            b->state = USV_BOAT_STATE_RUNNING;
            text_begin(&t, approach ? "new approach: mission " : "swapped to mission ");
            tx_uint(&t, active_mission(b)->id);
            tx_str(&t, " at ");
            tx_uint(&t, at);
            tx_str(&t, " ms");
            send_text(b, MAV_SEVERITY_INFO, &t);
        } else {
            text_begin(&t, "swap to ");
            tx_uint(&t, staged_mission(b)->id);
            tx_str(&t, " dropped: ");
            tx_str(&t, why);
            drop_staging(b);
            send_text(b, MAV_SEVERITY_WARNING, &t);
        }
    }
}

static void tick(usv_boat_t *b, uint32_t now)
{
    text_t t;
    /* failsafe: no valid frame from the paired station for the link timeout */
    if (b->station_heard && at_or_after(now, b->last_station_ms + b->cfg.link_timeout_ms)) {
        b->station_heard = 0;
        if (b->state == USV_BOAT_STATE_RUNNING || b->state == USV_BOAT_STATE_HOLD ||
            b->state == USV_BOAT_STATE_GO_AROUND) {
            if (b->state != USV_BOAT_STATE_HOLD) {
                b->hold_since_ms = now;
                hold_here(b);
            }
            b->state = USV_BOAT_STATE_FAILSAFE;
            b->guidance_on = 0;
            text_begin(&t, "failsafe: no station for ");
            tx_uint(&t, b->cfg.link_timeout_ms);
            tx_str(&t, " ms, keeping station");
            send_text(b, MAV_SEVERITY_CRITICAL, &t);
        } else {
            text_begin(&t, "link lost");
            send_text(b, MAV_SEVERITY_WARNING, &t);
        }
    }
    /* staging expiry */
    if (b->staging == USV_STAGING_RECEIVING &&
        at_or_after(now, b->staging_touch_ms + b->cfg.staging_expiry_ms)) {
        text_begin(&t, "staging of mission ");
        tx_uint(&t, staged_mission(b)->id);
        tx_str(&t, " expired");
        drop_staging(b);
        send_text(b, MAV_SEVERITY_WARNING, &t);
    }
    swap_if_due(b, now);
    switch (b->state) {
    case USV_BOAT_STATE_RUNNING:
        track(b, now);
        break;
    case USV_BOAT_STATE_GO_AROUND:
        fly_go_around(b);
        break;
    case USV_BOAT_STATE_READY:
    case USV_BOAT_STATE_HOLD:
    case USV_BOAT_STATE_FAILSAFE:
        keep_station(b);
        break;
    default:
        set_thrust(b, 0.0f, 0.0f);
        break;
    }
    b->hal.actuate(b->hal.ctx, b->thrust_left, b->thrust_right);
}

/* ------------------------------------------------------------------ API */

int usv_boat_init(usv_boat_t *b, const usv_config_t *cfg, const usv_hal_t *hal)
{
    if (cfg == NULL || hal == NULL || hal->send == NULL || hal->now_ms == NULL ||
        hal->actuate == NULL || cfg->boat_id == 0u || cfg->station_id == 0u ||
        cfg->boat_id == cfg->station_id || cfg->telemetry_period_ms == 0u ||
        cfg->link_timeout_ms == 0u || !(cfg->start_radius_m > 0.0f) ||
        !(cfg->max_speed_mps > 0.0f)) {
        return -1;
    }
    memset(b, 0, sizeof *b);
    b->cfg = *cfg;
    if (b->cfg.dup_expiry_ms == 0u) {
        b->cfg.dup_expiry_ms = USV_DUP_EXPIRY_MS;
    }
    if (b->cfg.staging_expiry_ms == 0u) {
        b->cfg.staging_expiry_ms = USV_STAGING_EXPIRY_MS;
    }
    b->hal = *hal;
    b->boot_ms = hal->now_ms(hal->ctx);
    b->state = USV_BOAT_STATE_IDLE;
    b->staging = USV_STAGING_NONE;
    if (cfg->key != NULL) {
        memcpy(b->key, cfg->key, sizeof b->key);
        memcpy(b->signing.secret_key, b->key, sizeof b->key);
        b->signing.flags = MAVLINK_SIGNING_FLAG_SIGN_OUTGOING;
        b->signing.link_id = 0;
        b->signing.timestamp = cfg->boot_timestamp;
        b->signing.accept_unsigned_callback = accept_unsigned;
        b->rx_status.signing = &b->signing;
        b->rx_status.signing_streams = &b->streams;
        b->tx_status.signing = &b->signing;
        b->tx_status.signing_streams = &b->streams;
        b->cfg.key = b->key;
    }
    b->last_station_ms = 0;
    b->next_heartbeat_ms = 0;
    b->next_telemetry_ms = 0;
    b->last_text_ms = 0u - USV_TEXT_MIN_MS;
    return 0;
}

void usv_boat_rx_byte(usv_boat_t *b, uint8_t byte)
{
    uint16_t head = b->rx_head;
    uint16_t next = (uint16_t)((head + 1u) & (USV_RX_RING - 1u));
    if (next == b->rx_tail) {
        b->rx_overruns++; /* the main loop fell behind: drop the byte, the CRC catches it */
        return;
    }
    b->rx_ring[head] = byte;
    b->rx_head = next;
}

uint64_t usv_boat_signing_floor(const usv_boat_t *b)
{
    return b->station_ts;
}

void usv_boat_set_nav(usv_boat_t *b, const usv_nav_t *nav)
{
    b->nav = *nav;
}

void usv_boat_poll(usv_boat_t *b)
{
    uint32_t now = uptime(b);
    mavlink_usv_mission_state_t s;
    while (b->rx_tail != b->rx_head) {
        uint16_t tail = b->rx_tail;
        uint8_t c = b->rx_ring[tail];
        b->rx_tail = (uint16_t)((tail + 1u) & (USV_RX_RING - 1u));
        on_byte(b, c, now); /* replies (ACKs, readback, TIMESYNC) go out right here */
    }
    tick(b, now);
    std_items_reached(b);
    if (at_or_after(now, b->next_heartbeat_ms)) {
        b->next_heartbeat_ms = at_or_after(now, b->next_heartbeat_ms + USV_HEARTBEAT_MS)
                                   ? now + USV_HEARTBEAT_MS
                                   : b->next_heartbeat_ms + USV_HEARTBEAT_MS;
        send_heartbeat(b);
        send_state(b);
        send_slow_telemetry(b);
        std_send_mission_current(b);
    } else {
        fill_state(b, &s);
        if (memcmp(&s, &b->last_state, sizeof s) != 0) {
            send_state(b);
        }
    }
    if (at_or_after(now, b->next_telemetry_ms)) {
        uint32_t due = b->next_telemetry_ms;
        if (at_or_after(now, due + b->cfg.telemetry_period_ms)) {
            due = now; /* fell behind by a whole period: restart the grid here */
        }
        b->next_telemetry_ms = due + b->cfg.telemetry_period_ms;
        send_fast_telemetry(b, due);
    }
    report_refusals(b, now);
    drain_telemetry(b, now);
}
