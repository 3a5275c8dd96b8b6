/*
 * usv_hil: the boat's navigation input and thrust output over a second UART with standard
 * MAVLink hardware-in-the-loop messages (portable C99, no I/O of its own).
 *
 *   in:  HIL_GPS (#113) from the boat's own system id (the GNSS component): position,
 *        ground speed and course, hull heading (`yaw`), fix and satellites, UNIX time
 *   out: HIL_ACTUATOR_CONTROLS (#93): time_usec = chip uptime (us), controls[0] and [1] =
 *        left and right propeller in -1..1 (the ESCs' throttle), mode = MAV_MODE_FLAG_HIL_ENABLED
 *
 * Both directions are signed with the link key like the radio (MAVLink 2 signing, the
 * same key); unsigned or badly signed frames are counted and dropped. Bytes arrive through
 * usv_hil_rx_byte() (interrupt-safe: a single-producer ring), are parsed by usv_hil_poll()
 * in the main loop. The bridge on the other end (backend/usvstation/hil) steps the vessel
 * model to each HIL_ACTUATOR_CONTROLS' time and answers with a HIL_GPS.
 */
#ifndef USV_HIL_H
#define USV_HIL_H

#include <stdint.h>

#include "usv_boat.h"

#ifndef USV_HIL_RING
#define USV_HIL_RING 256 /* receive ring, bytes; a power of two */
#endif
#define USV_HIL_COMPONENT MAV_COMP_ID_GPS /* who speaks for the sensors */

typedef struct {
    uint8_t boat_id;
    volatile uint16_t rx_head;
    volatile uint16_t rx_tail;
    uint8_t rx_ring[USV_HIL_RING];
    mavlink_message_t rx_msg;
    mavlink_status_t rx_status;
    mavlink_status_t tx_status;
    mavlink_signing_t signing;
    mavlink_signing_streams_t streams;
    uint64_t boot_timestamp; /* frames signed earlier are refused */
    mavlink_message_t tx_msg;
    uint8_t tx_buf[MAVLINK_MAX_PACKET_LEN];
    usv_nav_t nav;          /* the latest fix */
    uint32_t fixes;         /* HIL_GPS accepted */
    uint32_t fix_ms;        /* uptime of the latest fix */
    uint64_t unix_us;       /* its UNIX time (0: the GNSS has no time yet) */
    uint16_t refused;       /* unsigned, badly signed or replayed frames (saturating) */
    uint16_t overruns;      /* bytes dropped on a full ring */
} usv_hil_t;

/* Start the HIL link; key NULL: unsigned. `timestamp`: signing time at boot (frames signed
 * earlier are refused). Returns 0. */
int usv_hil_init(usv_hil_t *h, uint8_t boat_id, const uint8_t *key, uint64_t timestamp);
/* Interrupt-safe: one received byte into the ring. */
void usv_hil_rx_byte(usv_hil_t *h, uint8_t byte);
/* Parse what arrived at chip uptime `now_ms`; returns 1 when a new fix is in h->nav. */
int usv_hil_poll(usv_hil_t *h, uint32_t now_ms);
/* Pack a signed HIL_ACTUATOR_CONTROLS into h->tx_buf (returns its length): thrust in per
 * mille, `sign_time` the boat's signing clock now (10 us units since 2015). */
uint16_t usv_hil_actuators(usv_hil_t *h, uint32_t now_ms, int16_t left_pm, int16_t right_pm,
                           uint64_t sign_time);

#endif
