/*
 * usv_hil.c: navigation in (HIL_GPS), thrust out (HIL_ACTUATOR_CONTROLS); see usv_hil.h.
 */
#include "usv_hil.h"

#include <string.h>

#define PI_F 3.14159265358979f
#define CDEG_TO_RAD (PI_F / 18000.0f)
#define UNIX_US_2015 1420070400000000ULL /* signing timestamps count from 2015-01-01 */

int usv_hil_init(usv_hil_t *h, uint8_t boat_id, const uint8_t *key, uint64_t timestamp)
{
    memset(h, 0, sizeof *h);
    h->boat_id = boat_id;
    if (key != NULL) {
        memcpy(h->signing.secret_key, key, sizeof h->signing.secret_key);
        h->signing.flags = MAVLINK_SIGNING_FLAG_SIGN_OUTGOING;
        h->signing.link_id = 1; /* the radio is link 0 */
        h->signing.timestamp = timestamp + 1u; /* the bridge refuses 0 */
        h->boot_timestamp = timestamp;
        h->rx_status.signing = &h->signing;
        h->rx_status.signing_streams = &h->streams;
        h->tx_status.signing = &h->signing;
        h->tx_status.signing_streams = &h->streams;
    }
    h->nav.battery_pct = -1; /* no battery monitor on this path */
    return 0;
}

void usv_hil_rx_byte(usv_hil_t *h, uint8_t byte)
{
    uint16_t head = h->rx_head;
    uint16_t next = (uint16_t)((head + 1u) & (USV_HIL_RING - 1u));
    if (next == h->rx_tail) {
        if (h->overruns < UINT16_MAX) {
            h->overruns++;
        }
        return;
    }
    h->rx_ring[head] = byte;
    h->rx_head = next;
}

static void count_refusal(usv_hil_t *h)
{
    if (h->refused < UINT16_MAX) {
        h->refused++;
    }
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

/* A HIL_GPS into the navigation solution; the yaw rate from the previous fix's heading. */
static void take_fix(usv_hil_t *h, const mavlink_message_t *msg, uint32_t now_ms)
{
    mavlink_hil_gps_t g;
    float heading, prev = h->nav.heading_rad;
    mavlink_msg_hil_gps_decode(msg, &g);
    h->nav.lat_e7 = g.lat;
    h->nav.lon_e7 = g.lon;
    h->nav.fix_type = g.fix_type;
    h->nav.satellites = g.satellites_visible;
    h->nav.speed_mps = g.vel == UINT16_MAX ? 0.0f : (float)g.vel * 0.01f;
    heading = g.yaw != 0u ? (float)(g.yaw % 36000u) * CDEG_TO_RAD : prev;
    h->nav.course_rad = g.cog == UINT16_MAX ? heading : (float)g.cog * CDEG_TO_RAD;
    if (h->fixes > 0u && now_ms != h->fix_ms) {
        h->nav.yaw_rate = wrap_pi(heading - prev) / ((float)(now_ms - h->fix_ms) * 1e-3f);
    }
    h->nav.heading_rad = heading;
    h->fix_ms = now_ms;
    if (g.time_usec > UNIX_US_2015) {
        h->unix_us = g.time_usec; /* UNIX time, not time since the simulator's boot */
    }
    h->fixes++;
}

static int signed_before(const mavlink_message_t *msg, uint64_t floor)
{
    uint64_t ts = 0;
    int i;
    if (!(msg->incompat_flags & MAVLINK_IFLAG_SIGNED)) {
        return 0;
    }
    for (i = 6; i >= 1; i--) {
        ts = (ts << 8) | msg->signature[i];
    }
    return ts < floor;
}

int usv_hil_poll(usv_hil_t *h, uint32_t now_ms)
{
    int fresh = 0;
    while (h->rx_tail != h->rx_head) {
        uint16_t tail = h->rx_tail;
        uint8_t c = h->rx_ring[tail];
        uint8_t r;
        h->rx_tail = (uint16_t)((tail + 1u) & (USV_HIL_RING - 1u));
        r = mavlink_frame_char_buffer(&h->rx_msg, &h->rx_status, c, NULL, NULL);
        if (r == MAVLINK_FRAMING_BAD_SIGNATURE ||
            (r == MAVLINK_FRAMING_OK && h->rx_status.signing != NULL &&
             signed_before(&h->rx_msg, h->boot_timestamp))) {
            count_refusal(h); /* unsigned, forged, replayed, or recorded before this boot */
        } else if (r == MAVLINK_FRAMING_OK && h->rx_msg.sysid == h->boat_id &&
                   h->rx_msg.msgid == MAVLINK_MSG_ID_HIL_GPS) {
            take_fix(h, &h->rx_msg, now_ms);
            fresh = 1;
        }
    }
    return fresh;
}

uint16_t usv_hil_actuators(usv_hil_t *h, uint32_t now_ms, int16_t left_pm, int16_t right_pm,
                           uint64_t sign_time)
{
    mavlink_hil_actuator_controls_t a;
    memset(&a, 0, sizeof a);
    a.time_usec = (uint64_t)now_ms * 1000u;
    a.controls[0] = (float)left_pm * 1e-3f;
    a.controls[1] = (float)right_pm * 1e-3f;
    a.mode = MAV_MODE_FLAG_HIL_ENABLED;
    if (sign_time > h->signing.timestamp) {
        h->signing.timestamp = sign_time;
    }
    mavlink_msg_hil_actuator_controls_encode_status(h->boat_id, MAV_COMP_ID_AUTOPILOT1,
                                                    &h->tx_status, &h->tx_msg, &a);
    return mavlink_msg_to_send_buffer(h->tx_buf, &h->tx_msg);
}
