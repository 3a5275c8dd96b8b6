#pragma once
// MESSAGE USV_MISSION_BEGIN PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_USV_MISSION_BEGIN 44000


typedef struct __mavlink_usv_mission_begin_t {
 uint32_t mission_id; /*<  Mission id chosen by the station (non-zero).*/
 uint32_t crc32; /*<  CRC-32 (IEEE 802.3, as zlib.crc32) over the items in seq order, each as 24 bytes little-endian: mission_id u32, lat i32, lon i32, t_ms u32, seq u16, speed_cms u16, course_cdeg u16, heading_cdeg u16 (the MAVLink wire order of USV_MISSION_ITEM without the target bytes).*/
 uint32_t swap_at_ms; /*< [ms] Boat uptime at which to swap a RUNNING mission for this one; 0: stage for START.*/
 uint16_t count; /*<  Number of items (at least 2).*/
 uint8_t target_system; /*<  System ID of the boat.*/
 uint8_t target_component; /*<  Component ID.*/
} mavlink_usv_mission_begin_t;

#define MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN 16
#define MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN 16
#define MAVLINK_MSG_ID_44000_LEN 16
#define MAVLINK_MSG_ID_44000_MIN_LEN 16

#define MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC 99
#define MAVLINK_MSG_ID_44000_CRC 99



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_USV_MISSION_BEGIN { \
    44000, \
    "USV_MISSION_BEGIN", \
    6, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 14, offsetof(mavlink_usv_mission_begin_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 15, offsetof(mavlink_usv_mission_begin_t, target_component) }, \
         { "mission_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_begin_t, mission_id) }, \
         { "crc32", NULL, MAVLINK_TYPE_UINT32_T, 0, 4, offsetof(mavlink_usv_mission_begin_t, crc32) }, \
         { "count", NULL, MAVLINK_TYPE_UINT16_T, 0, 12, offsetof(mavlink_usv_mission_begin_t, count) }, \
         { "swap_at_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_usv_mission_begin_t, swap_at_ms) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_USV_MISSION_BEGIN { \
    "USV_MISSION_BEGIN", \
    6, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 14, offsetof(mavlink_usv_mission_begin_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 15, offsetof(mavlink_usv_mission_begin_t, target_component) }, \
         { "mission_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_begin_t, mission_id) }, \
         { "crc32", NULL, MAVLINK_TYPE_UINT32_T, 0, 4, offsetof(mavlink_usv_mission_begin_t, crc32) }, \
         { "count", NULL, MAVLINK_TYPE_UINT16_T, 0, 12, offsetof(mavlink_usv_mission_begin_t, count) }, \
         { "swap_at_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_usv_mission_begin_t, swap_at_ms) }, \
         } \
}
#endif

/**
 * @brief Pack a usv_mission_begin message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param mission_id  Mission id chosen by the station (non-zero).
 * @param crc32  CRC-32 (IEEE 802.3, as zlib.crc32) over the items in seq order, each as 24 bytes little-endian: mission_id u32, lat i32, lon i32, t_ms u32, seq u16, speed_cms u16, course_cdeg u16, heading_cdeg u16 (the MAVLink wire order of USV_MISSION_ITEM without the target bytes).
 * @param count  Number of items (at least 2).
 * @param swap_at_ms [ms] Boat uptime at which to swap a RUNNING mission for this one; 0: stage for START.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_begin_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint32_t crc32, uint16_t count, uint32_t swap_at_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint32_t(buf, 8, swap_at_ms);
    _mav_put_uint16_t(buf, 12, count);
    _mav_put_uint8_t(buf, 14, target_system);
    _mav_put_uint8_t(buf, 15, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN);
#else
    mavlink_usv_mission_begin_t packet;
    packet.mission_id = mission_id;
    packet.crc32 = crc32;
    packet.swap_at_ms = swap_at_ms;
    packet.count = count;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_BEGIN;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC);
}

/**
 * @brief Pack a usv_mission_begin message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param mission_id  Mission id chosen by the station (non-zero).
 * @param crc32  CRC-32 (IEEE 802.3, as zlib.crc32) over the items in seq order, each as 24 bytes little-endian: mission_id u32, lat i32, lon i32, t_ms u32, seq u16, speed_cms u16, course_cdeg u16, heading_cdeg u16 (the MAVLink wire order of USV_MISSION_ITEM without the target bytes).
 * @param count  Number of items (at least 2).
 * @param swap_at_ms [ms] Boat uptime at which to swap a RUNNING mission for this one; 0: stage for START.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_begin_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint32_t crc32, uint16_t count, uint32_t swap_at_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint32_t(buf, 8, swap_at_ms);
    _mav_put_uint16_t(buf, 12, count);
    _mav_put_uint8_t(buf, 14, target_system);
    _mav_put_uint8_t(buf, 15, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN);
#else
    mavlink_usv_mission_begin_t packet;
    packet.mission_id = mission_id;
    packet.crc32 = crc32;
    packet.swap_at_ms = swap_at_ms;
    packet.count = count;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_BEGIN;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN);
#endif
}

/**
 * @brief Pack a usv_mission_begin message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param mission_id  Mission id chosen by the station (non-zero).
 * @param crc32  CRC-32 (IEEE 802.3, as zlib.crc32) over the items in seq order, each as 24 bytes little-endian: mission_id u32, lat i32, lon i32, t_ms u32, seq u16, speed_cms u16, course_cdeg u16, heading_cdeg u16 (the MAVLink wire order of USV_MISSION_ITEM without the target bytes).
 * @param count  Number of items (at least 2).
 * @param swap_at_ms [ms] Boat uptime at which to swap a RUNNING mission for this one; 0: stage for START.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_begin_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t target_system,uint8_t target_component,uint32_t mission_id,uint32_t crc32,uint16_t count,uint32_t swap_at_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint32_t(buf, 8, swap_at_ms);
    _mav_put_uint16_t(buf, 12, count);
    _mav_put_uint8_t(buf, 14, target_system);
    _mav_put_uint8_t(buf, 15, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN);
#else
    mavlink_usv_mission_begin_t packet;
    packet.mission_id = mission_id;
    packet.crc32 = crc32;
    packet.swap_at_ms = swap_at_ms;
    packet.count = count;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_BEGIN;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC);
}

/**
 * @brief Encode a usv_mission_begin struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_begin C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_begin_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_usv_mission_begin_t* usv_mission_begin)
{
    return mavlink_msg_usv_mission_begin_pack(system_id, component_id, msg, usv_mission_begin->target_system, usv_mission_begin->target_component, usv_mission_begin->mission_id, usv_mission_begin->crc32, usv_mission_begin->count, usv_mission_begin->swap_at_ms);
}

/**
 * @brief Encode a usv_mission_begin struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_begin C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_begin_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_usv_mission_begin_t* usv_mission_begin)
{
    return mavlink_msg_usv_mission_begin_pack_chan(system_id, component_id, chan, msg, usv_mission_begin->target_system, usv_mission_begin->target_component, usv_mission_begin->mission_id, usv_mission_begin->crc32, usv_mission_begin->count, usv_mission_begin->swap_at_ms);
}

/**
 * @brief Encode a usv_mission_begin struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_begin C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_begin_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_usv_mission_begin_t* usv_mission_begin)
{
    return mavlink_msg_usv_mission_begin_pack_status(system_id, component_id, _status, msg,  usv_mission_begin->target_system, usv_mission_begin->target_component, usv_mission_begin->mission_id, usv_mission_begin->crc32, usv_mission_begin->count, usv_mission_begin->swap_at_ms);
}

/**
 * @brief Send a usv_mission_begin message
 * @param chan MAVLink channel to send the message
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param mission_id  Mission id chosen by the station (non-zero).
 * @param crc32  CRC-32 (IEEE 802.3, as zlib.crc32) over the items in seq order, each as 24 bytes little-endian: mission_id u32, lat i32, lon i32, t_ms u32, seq u16, speed_cms u16, course_cdeg u16, heading_cdeg u16 (the MAVLink wire order of USV_MISSION_ITEM without the target bytes).
 * @param count  Number of items (at least 2).
 * @param swap_at_ms [ms] Boat uptime at which to swap a RUNNING mission for this one; 0: stage for START.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_usv_mission_begin_send(mavlink_channel_t chan, uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint32_t crc32, uint16_t count, uint32_t swap_at_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint32_t(buf, 8, swap_at_ms);
    _mav_put_uint16_t(buf, 12, count);
    _mav_put_uint8_t(buf, 14, target_system);
    _mav_put_uint8_t(buf, 15, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_BEGIN, buf, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC);
#else
    mavlink_usv_mission_begin_t packet;
    packet.mission_id = mission_id;
    packet.crc32 = crc32;
    packet.swap_at_ms = swap_at_ms;
    packet.count = count;
    packet.target_system = target_system;
    packet.target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_BEGIN, (const char *)&packet, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC);
#endif
}

/**
 * @brief Send a usv_mission_begin message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_usv_mission_begin_send_struct(mavlink_channel_t chan, const mavlink_usv_mission_begin_t* usv_mission_begin)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_usv_mission_begin_send(chan, usv_mission_begin->target_system, usv_mission_begin->target_component, usv_mission_begin->mission_id, usv_mission_begin->crc32, usv_mission_begin->count, usv_mission_begin->swap_at_ms);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_BEGIN, (const char *)usv_mission_begin, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC);
#endif
}

#if MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_usv_mission_begin_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint32_t crc32, uint16_t count, uint32_t swap_at_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint32_t(buf, 8, swap_at_ms);
    _mav_put_uint16_t(buf, 12, count);
    _mav_put_uint8_t(buf, 14, target_system);
    _mav_put_uint8_t(buf, 15, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_BEGIN, buf, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC);
#else
    mavlink_usv_mission_begin_t *packet = (mavlink_usv_mission_begin_t *)msgbuf;
    packet->mission_id = mission_id;
    packet->crc32 = crc32;
    packet->swap_at_ms = swap_at_ms;
    packet->count = count;
    packet->target_system = target_system;
    packet->target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_BEGIN, (const char *)packet, MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN, MAVLINK_MSG_ID_USV_MISSION_BEGIN_CRC);
#endif
}
#endif

#endif

// MESSAGE USV_MISSION_BEGIN UNPACKING


/**
 * @brief Get field target_system from usv_mission_begin message
 *
 * @return  System ID of the boat.
 */
static inline uint8_t mavlink_msg_usv_mission_begin_get_target_system(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  14);
}

/**
 * @brief Get field target_component from usv_mission_begin message
 *
 * @return  Component ID.
 */
static inline uint8_t mavlink_msg_usv_mission_begin_get_target_component(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  15);
}

/**
 * @brief Get field mission_id from usv_mission_begin message
 *
 * @return  Mission id chosen by the station (non-zero).
 */
static inline uint32_t mavlink_msg_usv_mission_begin_get_mission_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  0);
}

/**
 * @brief Get field crc32 from usv_mission_begin message
 *
 * @return  CRC-32 (IEEE 802.3, as zlib.crc32) over the items in seq order, each as 24 bytes little-endian: mission_id u32, lat i32, lon i32, t_ms u32, seq u16, speed_cms u16, course_cdeg u16, heading_cdeg u16 (the MAVLink wire order of USV_MISSION_ITEM without the target bytes).
 */
static inline uint32_t mavlink_msg_usv_mission_begin_get_crc32(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  4);
}

/**
 * @brief Get field count from usv_mission_begin message
 *
 * @return  Number of items (at least 2).
 */
static inline uint16_t mavlink_msg_usv_mission_begin_get_count(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  12);
}

/**
 * @brief Get field swap_at_ms from usv_mission_begin message
 *
 * @return [ms] Boat uptime at which to swap a RUNNING mission for this one; 0: stage for START.
 */
static inline uint32_t mavlink_msg_usv_mission_begin_get_swap_at_ms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  8);
}

/**
 * @brief Decode a usv_mission_begin message into a struct
 *
 * @param msg The message to decode
 * @param usv_mission_begin C-struct to decode the message contents into
 */
static inline void mavlink_msg_usv_mission_begin_decode(const mavlink_message_t* msg, mavlink_usv_mission_begin_t* usv_mission_begin)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    usv_mission_begin->mission_id = mavlink_msg_usv_mission_begin_get_mission_id(msg);
    usv_mission_begin->crc32 = mavlink_msg_usv_mission_begin_get_crc32(msg);
    usv_mission_begin->swap_at_ms = mavlink_msg_usv_mission_begin_get_swap_at_ms(msg);
    usv_mission_begin->count = mavlink_msg_usv_mission_begin_get_count(msg);
    usv_mission_begin->target_system = mavlink_msg_usv_mission_begin_get_target_system(msg);
    usv_mission_begin->target_component = mavlink_msg_usv_mission_begin_get_target_component(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN? msg->len : MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN;
        memset(usv_mission_begin, 0, MAVLINK_MSG_ID_USV_MISSION_BEGIN_LEN);
    memcpy(usv_mission_begin, _MAV_PAYLOAD(msg), len);
#endif
}
