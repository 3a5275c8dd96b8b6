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
/* Field access byte by byte: mavlink_message_t is packed, so its payload is not aligned
 * (UBSan flags the default word loads; 64-bit loads from it can fault on a Cortex-M3). */
#define MAVLINK_ALIGNED_FIELDS 0
#define MAVLINK_MAX_SIGNING_STREAMS 8 /* station, own echo, radios, other boats */
#include "usv_recovery/mavlink.h"

#endif
