/*
 * The generated MAVLink C headers (protocol/c/mavlink, pymavlink mavgen, wire protocol 2.0)
 * configured for the boat: no convenience send functions (the boat packs into its own
 * buffer and hands bytes to the HAL), one channel, few signing streams. No
 * MAVLINK_CHECK_MESSAGE_LENGTH: MAVLink 2 trims trailing zero bytes, so a valid payload
 * may be shorter than the message's minimum length.
 */
#ifndef USV_MAVLINK_H
#define USV_MAVLINK_H

#define MAVLINK_COMM_NUM_BUFFERS 1
#define MAVLINK_MAX_SIGNING_STREAMS 4
#include "usv_recovery/mavlink.h"

#endif
