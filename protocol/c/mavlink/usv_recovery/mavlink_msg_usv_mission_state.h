#pragma once
// MESSAGE USV_MISSION_STATE PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_USV_MISSION_STATE 44004


typedef struct __mavlink_usv_mission_state_t {
 uint32_t uptime_ms; /*< [ms] Boat uptime (its mission clock).*/
 uint32_t boot_id; /*<  Random per boat boot: a change means the boat rebooted.*/
 uint32_t active_id; /*<  Active mission id (0: none).*/
 uint32_t active_crc32; /*<  Active mission CRC-32.*/
 uint32_t staged_id; /*<  Staged mission id (0: none).*/
 uint32_t staged_crc32; /*<  Staged mission CRC-32.*/
 uint32_t swap_at_ms; /*< [ms] Scheduled hot swap instant (0: none).*/
 uint32_t station_session; /*<  Session of the paired station last heard (0: none).*/
 uint16_t active_count; /*<  Active mission item count.*/
 uint16_t current_seq; /*<  Leg being tracked (index of its start item).*/
 uint16_t staged_received; /*<  Items staged contiguously from 0.*/
 uint16_t staged_count; /*<  Items announced.*/
 uint16_t rejected; /*<  Frames refused since boot (unsigned, bad signature, replayed, wrong sender), saturating.*/
 uint8_t state; /*<  Boat state.*/
 uint8_t staging; /*<  Staging state.*/
 uint8_t flags; /*<  Conditions reported with the state (USV_STATE_FLAG).*/
} mavlink_usv_mission_state_t;

#define MAVLINK_MSG_ID_USV_MISSION_STATE_LEN 45
#define MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN 44
#define MAVLINK_MSG_ID_44004_LEN 45
#define MAVLINK_MSG_ID_44004_MIN_LEN 44

#define MAVLINK_MSG_ID_USV_MISSION_STATE_CRC 100
#define MAVLINK_MSG_ID_44004_CRC 100



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_USV_MISSION_STATE { \
    44004, \
    "USV_MISSION_STATE", \
    16, \
    {  { "uptime_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_state_t, uptime_ms) }, \
         { "boot_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 4, offsetof(mavlink_usv_mission_state_t, boot_id) }, \
         { "state", NULL, MAVLINK_TYPE_UINT8_T, 0, 42, offsetof(mavlink_usv_mission_state_t, state) }, \
         { "active_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_usv_mission_state_t, active_id) }, \
         { "active_crc32", NULL, MAVLINK_TYPE_UINT32_T, 0, 12, offsetof(mavlink_usv_mission_state_t, active_crc32) }, \
         { "active_count", NULL, MAVLINK_TYPE_UINT16_T, 0, 32, offsetof(mavlink_usv_mission_state_t, active_count) }, \
         { "current_seq", NULL, MAVLINK_TYPE_UINT16_T, 0, 34, offsetof(mavlink_usv_mission_state_t, current_seq) }, \
         { "staging", NULL, MAVLINK_TYPE_UINT8_T, 0, 43, offsetof(mavlink_usv_mission_state_t, staging) }, \
         { "staged_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 16, offsetof(mavlink_usv_mission_state_t, staged_id) }, \
         { "staged_crc32", NULL, MAVLINK_TYPE_UINT32_T, 0, 20, offsetof(mavlink_usv_mission_state_t, staged_crc32) }, \
         { "staged_received", NULL, MAVLINK_TYPE_UINT16_T, 0, 36, offsetof(mavlink_usv_mission_state_t, staged_received) }, \
         { "staged_count", NULL, MAVLINK_TYPE_UINT16_T, 0, 38, offsetof(mavlink_usv_mission_state_t, staged_count) }, \
         { "swap_at_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 24, offsetof(mavlink_usv_mission_state_t, swap_at_ms) }, \
         { "station_session", NULL, MAVLINK_TYPE_UINT32_T, 0, 28, offsetof(mavlink_usv_mission_state_t, station_session) }, \
         { "rejected", NULL, MAVLINK_TYPE_UINT16_T, 0, 40, offsetof(mavlink_usv_mission_state_t, rejected) }, \
         { "flags", NULL, MAVLINK_TYPE_UINT8_T, 0, 44, offsetof(mavlink_usv_mission_state_t, flags) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_USV_MISSION_STATE { \
    "USV_MISSION_STATE", \
    16, \
    {  { "uptime_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_state_t, uptime_ms) }, \
         { "boot_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 4, offsetof(mavlink_usv_mission_state_t, boot_id) }, \
         { "state", NULL, MAVLINK_TYPE_UINT8_T, 0, 42, offsetof(mavlink_usv_mission_state_t, state) }, \
         { "active_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_usv_mission_state_t, active_id) }, \
         { "active_crc32", NULL, MAVLINK_TYPE_UINT32_T, 0, 12, offsetof(mavlink_usv_mission_state_t, active_crc32) }, \
         { "active_count", NULL, MAVLINK_TYPE_UINT16_T, 0, 32, offsetof(mavlink_usv_mission_state_t, active_count) }, \
         { "current_seq", NULL, MAVLINK_TYPE_UINT16_T, 0, 34, offsetof(mavlink_usv_mission_state_t, current_seq) }, \
         { "staging", NULL, MAVLINK_TYPE_UINT8_T, 0, 43, offsetof(mavlink_usv_mission_state_t, staging) }, \
         { "staged_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 16, offsetof(mavlink_usv_mission_state_t, staged_id) }, \
         { "staged_crc32", NULL, MAVLINK_TYPE_UINT32_T, 0, 20, offsetof(mavlink_usv_mission_state_t, staged_crc32) }, \
         { "staged_received", NULL, MAVLINK_TYPE_UINT16_T, 0, 36, offsetof(mavlink_usv_mission_state_t, staged_received) }, \
         { "staged_count", NULL, MAVLINK_TYPE_UINT16_T, 0, 38, offsetof(mavlink_usv_mission_state_t, staged_count) }, \
         { "swap_at_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 24, offsetof(mavlink_usv_mission_state_t, swap_at_ms) }, \
         { "station_session", NULL, MAVLINK_TYPE_UINT32_T, 0, 28, offsetof(mavlink_usv_mission_state_t, station_session) }, \
         { "rejected", NULL, MAVLINK_TYPE_UINT16_T, 0, 40, offsetof(mavlink_usv_mission_state_t, rejected) }, \
         { "flags", NULL, MAVLINK_TYPE_UINT8_T, 0, 44, offsetof(mavlink_usv_mission_state_t, flags) }, \
         } \
}
#endif

/**
 * @brief Pack a usv_mission_state message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param uptime_ms [ms] Boat uptime (its mission clock).
 * @param boot_id  Random per boat boot: a change means the boat rebooted.
 * @param state  Boat state.
 * @param active_id  Active mission id (0: none).
 * @param active_crc32  Active mission CRC-32.
 * @param active_count  Active mission item count.
 * @param current_seq  Leg being tracked (index of its start item).
 * @param staging  Staging state.
 * @param staged_id  Staged mission id (0: none).
 * @param staged_crc32  Staged mission CRC-32.
 * @param staged_received  Items staged contiguously from 0.
 * @param staged_count  Items announced.
 * @param swap_at_ms [ms] Scheduled hot swap instant (0: none).
 * @param station_session  Session of the paired station last heard (0: none).
 * @param rejected  Frames refused since boot (unsigned, bad signature, replayed, wrong sender), saturating.
 * @param flags  Conditions reported with the state (USV_STATE_FLAG).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_state_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint32_t uptime_ms, uint32_t boot_id, uint8_t state, uint32_t active_id, uint32_t active_crc32, uint16_t active_count, uint16_t current_seq, uint8_t staging, uint32_t staged_id, uint32_t staged_crc32, uint16_t staged_received, uint16_t staged_count, uint32_t swap_at_ms, uint32_t station_session, uint16_t rejected, uint8_t flags)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_STATE_LEN];
    _mav_put_uint32_t(buf, 0, uptime_ms);
    _mav_put_uint32_t(buf, 4, boot_id);
    _mav_put_uint32_t(buf, 8, active_id);
    _mav_put_uint32_t(buf, 12, active_crc32);
    _mav_put_uint32_t(buf, 16, staged_id);
    _mav_put_uint32_t(buf, 20, staged_crc32);
    _mav_put_uint32_t(buf, 24, swap_at_ms);
    _mav_put_uint32_t(buf, 28, station_session);
    _mav_put_uint16_t(buf, 32, active_count);
    _mav_put_uint16_t(buf, 34, current_seq);
    _mav_put_uint16_t(buf, 36, staged_received);
    _mav_put_uint16_t(buf, 38, staged_count);
    _mav_put_uint16_t(buf, 40, rejected);
    _mav_put_uint8_t(buf, 42, state);
    _mav_put_uint8_t(buf, 43, staging);
    _mav_put_uint8_t(buf, 44, flags);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN);
#else
    mavlink_usv_mission_state_t packet;
    packet.uptime_ms = uptime_ms;
    packet.boot_id = boot_id;
    packet.active_id = active_id;
    packet.active_crc32 = active_crc32;
    packet.staged_id = staged_id;
    packet.staged_crc32 = staged_crc32;
    packet.swap_at_ms = swap_at_ms;
    packet.station_session = station_session;
    packet.active_count = active_count;
    packet.current_seq = current_seq;
    packet.staged_received = staged_received;
    packet.staged_count = staged_count;
    packet.rejected = rejected;
    packet.state = state;
    packet.staging = staging;
    packet.flags = flags;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_STATE;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_CRC);
}

/**
 * @brief Pack a usv_mission_state message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param uptime_ms [ms] Boat uptime (its mission clock).
 * @param boot_id  Random per boat boot: a change means the boat rebooted.
 * @param state  Boat state.
 * @param active_id  Active mission id (0: none).
 * @param active_crc32  Active mission CRC-32.
 * @param active_count  Active mission item count.
 * @param current_seq  Leg being tracked (index of its start item).
 * @param staging  Staging state.
 * @param staged_id  Staged mission id (0: none).
 * @param staged_crc32  Staged mission CRC-32.
 * @param staged_received  Items staged contiguously from 0.
 * @param staged_count  Items announced.
 * @param swap_at_ms [ms] Scheduled hot swap instant (0: none).
 * @param station_session  Session of the paired station last heard (0: none).
 * @param rejected  Frames refused since boot (unsigned, bad signature, replayed, wrong sender), saturating.
 * @param flags  Conditions reported with the state (USV_STATE_FLAG).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_state_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint32_t uptime_ms, uint32_t boot_id, uint8_t state, uint32_t active_id, uint32_t active_crc32, uint16_t active_count, uint16_t current_seq, uint8_t staging, uint32_t staged_id, uint32_t staged_crc32, uint16_t staged_received, uint16_t staged_count, uint32_t swap_at_ms, uint32_t station_session, uint16_t rejected, uint8_t flags)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_STATE_LEN];
    _mav_put_uint32_t(buf, 0, uptime_ms);
    _mav_put_uint32_t(buf, 4, boot_id);
    _mav_put_uint32_t(buf, 8, active_id);
    _mav_put_uint32_t(buf, 12, active_crc32);
    _mav_put_uint32_t(buf, 16, staged_id);
    _mav_put_uint32_t(buf, 20, staged_crc32);
    _mav_put_uint32_t(buf, 24, swap_at_ms);
    _mav_put_uint32_t(buf, 28, station_session);
    _mav_put_uint16_t(buf, 32, active_count);
    _mav_put_uint16_t(buf, 34, current_seq);
    _mav_put_uint16_t(buf, 36, staged_received);
    _mav_put_uint16_t(buf, 38, staged_count);
    _mav_put_uint16_t(buf, 40, rejected);
    _mav_put_uint8_t(buf, 42, state);
    _mav_put_uint8_t(buf, 43, staging);
    _mav_put_uint8_t(buf, 44, flags);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN);
#else
    mavlink_usv_mission_state_t packet;
    packet.uptime_ms = uptime_ms;
    packet.boot_id = boot_id;
    packet.active_id = active_id;
    packet.active_crc32 = active_crc32;
    packet.staged_id = staged_id;
    packet.staged_crc32 = staged_crc32;
    packet.swap_at_ms = swap_at_ms;
    packet.station_session = station_session;
    packet.active_count = active_count;
    packet.current_seq = current_seq;
    packet.staged_received = staged_received;
    packet.staged_count = staged_count;
    packet.rejected = rejected;
    packet.state = state;
    packet.staging = staging;
    packet.flags = flags;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_STATE;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN);
#endif
}

/**
 * @brief Pack a usv_mission_state message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param uptime_ms [ms] Boat uptime (its mission clock).
 * @param boot_id  Random per boat boot: a change means the boat rebooted.
 * @param state  Boat state.
 * @param active_id  Active mission id (0: none).
 * @param active_crc32  Active mission CRC-32.
 * @param active_count  Active mission item count.
 * @param current_seq  Leg being tracked (index of its start item).
 * @param staging  Staging state.
 * @param staged_id  Staged mission id (0: none).
 * @param staged_crc32  Staged mission CRC-32.
 * @param staged_received  Items staged contiguously from 0.
 * @param staged_count  Items announced.
 * @param swap_at_ms [ms] Scheduled hot swap instant (0: none).
 * @param station_session  Session of the paired station last heard (0: none).
 * @param rejected  Frames refused since boot (unsigned, bad signature, replayed, wrong sender), saturating.
 * @param flags  Conditions reported with the state (USV_STATE_FLAG).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_state_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint32_t uptime_ms,uint32_t boot_id,uint8_t state,uint32_t active_id,uint32_t active_crc32,uint16_t active_count,uint16_t current_seq,uint8_t staging,uint32_t staged_id,uint32_t staged_crc32,uint16_t staged_received,uint16_t staged_count,uint32_t swap_at_ms,uint32_t station_session,uint16_t rejected,uint8_t flags)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_STATE_LEN];
    _mav_put_uint32_t(buf, 0, uptime_ms);
    _mav_put_uint32_t(buf, 4, boot_id);
    _mav_put_uint32_t(buf, 8, active_id);
    _mav_put_uint32_t(buf, 12, active_crc32);
    _mav_put_uint32_t(buf, 16, staged_id);
    _mav_put_uint32_t(buf, 20, staged_crc32);
    _mav_put_uint32_t(buf, 24, swap_at_ms);
    _mav_put_uint32_t(buf, 28, station_session);
    _mav_put_uint16_t(buf, 32, active_count);
    _mav_put_uint16_t(buf, 34, current_seq);
    _mav_put_uint16_t(buf, 36, staged_received);
    _mav_put_uint16_t(buf, 38, staged_count);
    _mav_put_uint16_t(buf, 40, rejected);
    _mav_put_uint8_t(buf, 42, state);
    _mav_put_uint8_t(buf, 43, staging);
    _mav_put_uint8_t(buf, 44, flags);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN);
#else
    mavlink_usv_mission_state_t packet;
    packet.uptime_ms = uptime_ms;
    packet.boot_id = boot_id;
    packet.active_id = active_id;
    packet.active_crc32 = active_crc32;
    packet.staged_id = staged_id;
    packet.staged_crc32 = staged_crc32;
    packet.swap_at_ms = swap_at_ms;
    packet.station_session = station_session;
    packet.active_count = active_count;
    packet.current_seq = current_seq;
    packet.staged_received = staged_received;
    packet.staged_count = staged_count;
    packet.rejected = rejected;
    packet.state = state;
    packet.staging = staging;
    packet.flags = flags;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_STATE;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_CRC);
}

/**
 * @brief Encode a usv_mission_state struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_state C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_state_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_usv_mission_state_t* usv_mission_state)
{
    return mavlink_msg_usv_mission_state_pack(system_id, component_id, msg, usv_mission_state->uptime_ms, usv_mission_state->boot_id, usv_mission_state->state, usv_mission_state->active_id, usv_mission_state->active_crc32, usv_mission_state->active_count, usv_mission_state->current_seq, usv_mission_state->staging, usv_mission_state->staged_id, usv_mission_state->staged_crc32, usv_mission_state->staged_received, usv_mission_state->staged_count, usv_mission_state->swap_at_ms, usv_mission_state->station_session, usv_mission_state->rejected, usv_mission_state->flags);
}

/**
 * @brief Encode a usv_mission_state struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_state C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_state_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_usv_mission_state_t* usv_mission_state)
{
    return mavlink_msg_usv_mission_state_pack_chan(system_id, component_id, chan, msg, usv_mission_state->uptime_ms, usv_mission_state->boot_id, usv_mission_state->state, usv_mission_state->active_id, usv_mission_state->active_crc32, usv_mission_state->active_count, usv_mission_state->current_seq, usv_mission_state->staging, usv_mission_state->staged_id, usv_mission_state->staged_crc32, usv_mission_state->staged_received, usv_mission_state->staged_count, usv_mission_state->swap_at_ms, usv_mission_state->station_session, usv_mission_state->rejected, usv_mission_state->flags);
}

/**
 * @brief Encode a usv_mission_state struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_state C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_state_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_usv_mission_state_t* usv_mission_state)
{
    return mavlink_msg_usv_mission_state_pack_status(system_id, component_id, _status, msg,  usv_mission_state->uptime_ms, usv_mission_state->boot_id, usv_mission_state->state, usv_mission_state->active_id, usv_mission_state->active_crc32, usv_mission_state->active_count, usv_mission_state->current_seq, usv_mission_state->staging, usv_mission_state->staged_id, usv_mission_state->staged_crc32, usv_mission_state->staged_received, usv_mission_state->staged_count, usv_mission_state->swap_at_ms, usv_mission_state->station_session, usv_mission_state->rejected, usv_mission_state->flags);
}

/**
 * @brief Send a usv_mission_state message
 * @param chan MAVLink channel to send the message
 *
 * @param uptime_ms [ms] Boat uptime (its mission clock).
 * @param boot_id  Random per boat boot: a change means the boat rebooted.
 * @param state  Boat state.
 * @param active_id  Active mission id (0: none).
 * @param active_crc32  Active mission CRC-32.
 * @param active_count  Active mission item count.
 * @param current_seq  Leg being tracked (index of its start item).
 * @param staging  Staging state.
 * @param staged_id  Staged mission id (0: none).
 * @param staged_crc32  Staged mission CRC-32.
 * @param staged_received  Items staged contiguously from 0.
 * @param staged_count  Items announced.
 * @param swap_at_ms [ms] Scheduled hot swap instant (0: none).
 * @param station_session  Session of the paired station last heard (0: none).
 * @param rejected  Frames refused since boot (unsigned, bad signature, replayed, wrong sender), saturating.
 * @param flags  Conditions reported with the state (USV_STATE_FLAG).
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_usv_mission_state_send(mavlink_channel_t chan, uint32_t uptime_ms, uint32_t boot_id, uint8_t state, uint32_t active_id, uint32_t active_crc32, uint16_t active_count, uint16_t current_seq, uint8_t staging, uint32_t staged_id, uint32_t staged_crc32, uint16_t staged_received, uint16_t staged_count, uint32_t swap_at_ms, uint32_t station_session, uint16_t rejected, uint8_t flags)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_STATE_LEN];
    _mav_put_uint32_t(buf, 0, uptime_ms);
    _mav_put_uint32_t(buf, 4, boot_id);
    _mav_put_uint32_t(buf, 8, active_id);
    _mav_put_uint32_t(buf, 12, active_crc32);
    _mav_put_uint32_t(buf, 16, staged_id);
    _mav_put_uint32_t(buf, 20, staged_crc32);
    _mav_put_uint32_t(buf, 24, swap_at_ms);
    _mav_put_uint32_t(buf, 28, station_session);
    _mav_put_uint16_t(buf, 32, active_count);
    _mav_put_uint16_t(buf, 34, current_seq);
    _mav_put_uint16_t(buf, 36, staged_received);
    _mav_put_uint16_t(buf, 38, staged_count);
    _mav_put_uint16_t(buf, 40, rejected);
    _mav_put_uint8_t(buf, 42, state);
    _mav_put_uint8_t(buf, 43, staging);
    _mav_put_uint8_t(buf, 44, flags);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_STATE, buf, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_CRC);
#else
    mavlink_usv_mission_state_t packet;
    packet.uptime_ms = uptime_ms;
    packet.boot_id = boot_id;
    packet.active_id = active_id;
    packet.active_crc32 = active_crc32;
    packet.staged_id = staged_id;
    packet.staged_crc32 = staged_crc32;
    packet.swap_at_ms = swap_at_ms;
    packet.station_session = station_session;
    packet.active_count = active_count;
    packet.current_seq = current_seq;
    packet.staged_received = staged_received;
    packet.staged_count = staged_count;
    packet.rejected = rejected;
    packet.state = state;
    packet.staging = staging;
    packet.flags = flags;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_STATE, (const char *)&packet, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_CRC);
#endif
}

/**
 * @brief Send a usv_mission_state message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_usv_mission_state_send_struct(mavlink_channel_t chan, const mavlink_usv_mission_state_t* usv_mission_state)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_usv_mission_state_send(chan, usv_mission_state->uptime_ms, usv_mission_state->boot_id, usv_mission_state->state, usv_mission_state->active_id, usv_mission_state->active_crc32, usv_mission_state->active_count, usv_mission_state->current_seq, usv_mission_state->staging, usv_mission_state->staged_id, usv_mission_state->staged_crc32, usv_mission_state->staged_received, usv_mission_state->staged_count, usv_mission_state->swap_at_ms, usv_mission_state->station_session, usv_mission_state->rejected, usv_mission_state->flags);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_STATE, (const char *)usv_mission_state, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_CRC);
#endif
}

#if MAVLINK_MSG_ID_USV_MISSION_STATE_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_usv_mission_state_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint32_t uptime_ms, uint32_t boot_id, uint8_t state, uint32_t active_id, uint32_t active_crc32, uint16_t active_count, uint16_t current_seq, uint8_t staging, uint32_t staged_id, uint32_t staged_crc32, uint16_t staged_received, uint16_t staged_count, uint32_t swap_at_ms, uint32_t station_session, uint16_t rejected, uint8_t flags)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint32_t(buf, 0, uptime_ms);
    _mav_put_uint32_t(buf, 4, boot_id);
    _mav_put_uint32_t(buf, 8, active_id);
    _mav_put_uint32_t(buf, 12, active_crc32);
    _mav_put_uint32_t(buf, 16, staged_id);
    _mav_put_uint32_t(buf, 20, staged_crc32);
    _mav_put_uint32_t(buf, 24, swap_at_ms);
    _mav_put_uint32_t(buf, 28, station_session);
    _mav_put_uint16_t(buf, 32, active_count);
    _mav_put_uint16_t(buf, 34, current_seq);
    _mav_put_uint16_t(buf, 36, staged_received);
    _mav_put_uint16_t(buf, 38, staged_count);
    _mav_put_uint16_t(buf, 40, rejected);
    _mav_put_uint8_t(buf, 42, state);
    _mav_put_uint8_t(buf, 43, staging);
    _mav_put_uint8_t(buf, 44, flags);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_STATE, buf, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_CRC);
#else
    mavlink_usv_mission_state_t *packet = (mavlink_usv_mission_state_t *)msgbuf;
    packet->uptime_ms = uptime_ms;
    packet->boot_id = boot_id;
    packet->active_id = active_id;
    packet->active_crc32 = active_crc32;
    packet->staged_id = staged_id;
    packet->staged_crc32 = staged_crc32;
    packet->swap_at_ms = swap_at_ms;
    packet->station_session = station_session;
    packet->active_count = active_count;
    packet->current_seq = current_seq;
    packet->staged_received = staged_received;
    packet->staged_count = staged_count;
    packet->rejected = rejected;
    packet->state = state;
    packet->staging = staging;
    packet->flags = flags;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_STATE, (const char *)packet, MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN, MAVLINK_MSG_ID_USV_MISSION_STATE_CRC);
#endif
}
#endif

#endif

// MESSAGE USV_MISSION_STATE UNPACKING


/**
 * @brief Get field uptime_ms from usv_mission_state message
 *
 * @return [ms] Boat uptime (its mission clock).
 */
static inline uint32_t mavlink_msg_usv_mission_state_get_uptime_ms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  0);
}

/**
 * @brief Get field boot_id from usv_mission_state message
 *
 * @return  Random per boat boot: a change means the boat rebooted.
 */
static inline uint32_t mavlink_msg_usv_mission_state_get_boot_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  4);
}

/**
 * @brief Get field state from usv_mission_state message
 *
 * @return  Boat state.
 */
static inline uint8_t mavlink_msg_usv_mission_state_get_state(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  42);
}

/**
 * @brief Get field active_id from usv_mission_state message
 *
 * @return  Active mission id (0: none).
 */
static inline uint32_t mavlink_msg_usv_mission_state_get_active_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  8);
}

/**
 * @brief Get field active_crc32 from usv_mission_state message
 *
 * @return  Active mission CRC-32.
 */
static inline uint32_t mavlink_msg_usv_mission_state_get_active_crc32(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  12);
}

/**
 * @brief Get field active_count from usv_mission_state message
 *
 * @return  Active mission item count.
 */
static inline uint16_t mavlink_msg_usv_mission_state_get_active_count(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  32);
}

/**
 * @brief Get field current_seq from usv_mission_state message
 *
 * @return  Leg being tracked (index of its start item).
 */
static inline uint16_t mavlink_msg_usv_mission_state_get_current_seq(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  34);
}

/**
 * @brief Get field staging from usv_mission_state message
 *
 * @return  Staging state.
 */
static inline uint8_t mavlink_msg_usv_mission_state_get_staging(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  43);
}

/**
 * @brief Get field staged_id from usv_mission_state message
 *
 * @return  Staged mission id (0: none).
 */
static inline uint32_t mavlink_msg_usv_mission_state_get_staged_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  16);
}

/**
 * @brief Get field staged_crc32 from usv_mission_state message
 *
 * @return  Staged mission CRC-32.
 */
static inline uint32_t mavlink_msg_usv_mission_state_get_staged_crc32(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  20);
}

/**
 * @brief Get field staged_received from usv_mission_state message
 *
 * @return  Items staged contiguously from 0.
 */
static inline uint16_t mavlink_msg_usv_mission_state_get_staged_received(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  36);
}

/**
 * @brief Get field staged_count from usv_mission_state message
 *
 * @return  Items announced.
 */
static inline uint16_t mavlink_msg_usv_mission_state_get_staged_count(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  38);
}

/**
 * @brief Get field swap_at_ms from usv_mission_state message
 *
 * @return [ms] Scheduled hot swap instant (0: none).
 */
static inline uint32_t mavlink_msg_usv_mission_state_get_swap_at_ms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  24);
}

/**
 * @brief Get field station_session from usv_mission_state message
 *
 * @return  Session of the paired station last heard (0: none).
 */
static inline uint32_t mavlink_msg_usv_mission_state_get_station_session(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  28);
}

/**
 * @brief Get field rejected from usv_mission_state message
 *
 * @return  Frames refused since boot (unsigned, bad signature, replayed, wrong sender), saturating.
 */
static inline uint16_t mavlink_msg_usv_mission_state_get_rejected(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  40);
}

/**
 * @brief Get field flags from usv_mission_state message
 *
 * @return  Conditions reported with the state (USV_STATE_FLAG).
 */
static inline uint8_t mavlink_msg_usv_mission_state_get_flags(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  44);
}

/**
 * @brief Decode a usv_mission_state message into a struct
 *
 * @param msg The message to decode
 * @param usv_mission_state C-struct to decode the message contents into
 */
static inline void mavlink_msg_usv_mission_state_decode(const mavlink_message_t* msg, mavlink_usv_mission_state_t* usv_mission_state)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    usv_mission_state->uptime_ms = mavlink_msg_usv_mission_state_get_uptime_ms(msg);
    usv_mission_state->boot_id = mavlink_msg_usv_mission_state_get_boot_id(msg);
    usv_mission_state->active_id = mavlink_msg_usv_mission_state_get_active_id(msg);
    usv_mission_state->active_crc32 = mavlink_msg_usv_mission_state_get_active_crc32(msg);
    usv_mission_state->staged_id = mavlink_msg_usv_mission_state_get_staged_id(msg);
    usv_mission_state->staged_crc32 = mavlink_msg_usv_mission_state_get_staged_crc32(msg);
    usv_mission_state->swap_at_ms = mavlink_msg_usv_mission_state_get_swap_at_ms(msg);
    usv_mission_state->station_session = mavlink_msg_usv_mission_state_get_station_session(msg);
    usv_mission_state->active_count = mavlink_msg_usv_mission_state_get_active_count(msg);
    usv_mission_state->current_seq = mavlink_msg_usv_mission_state_get_current_seq(msg);
    usv_mission_state->staged_received = mavlink_msg_usv_mission_state_get_staged_received(msg);
    usv_mission_state->staged_count = mavlink_msg_usv_mission_state_get_staged_count(msg);
    usv_mission_state->rejected = mavlink_msg_usv_mission_state_get_rejected(msg);
    usv_mission_state->state = mavlink_msg_usv_mission_state_get_state(msg);
    usv_mission_state->staging = mavlink_msg_usv_mission_state_get_staging(msg);
    usv_mission_state->flags = mavlink_msg_usv_mission_state_get_flags(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_USV_MISSION_STATE_LEN? msg->len : MAVLINK_MSG_ID_USV_MISSION_STATE_LEN;
        memset(usv_mission_state, 0, MAVLINK_MSG_ID_USV_MISSION_STATE_LEN);
    memcpy(usv_mission_state, _MAV_PAYLOAD(msg), len);
#endif
}
