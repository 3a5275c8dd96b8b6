#pragma once
// MESSAGE USV_MISSION_END PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_USV_MISSION_END 44003


typedef struct __mavlink_usv_mission_end_t {
 uint32_t mission_id; /*<  Mission id.*/
 uint32_t crc32; /*<  CRC-32 announced in BEGIN.*/
 uint16_t count; /*<  Number of items.*/
 uint8_t target_system; /*<  System ID of the boat.*/
 uint8_t target_component; /*<  Component ID.*/
} mavlink_usv_mission_end_t;

#define MAVLINK_MSG_ID_USV_MISSION_END_LEN 12
#define MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN 12
#define MAVLINK_MSG_ID_44003_LEN 12
#define MAVLINK_MSG_ID_44003_MIN_LEN 12

#define MAVLINK_MSG_ID_USV_MISSION_END_CRC 54
#define MAVLINK_MSG_ID_44003_CRC 54



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_USV_MISSION_END { \
    44003, \
    "USV_MISSION_END", \
    5, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 10, offsetof(mavlink_usv_mission_end_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 11, offsetof(mavlink_usv_mission_end_t, target_component) }, \
         { "mission_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_end_t, mission_id) }, \
         { "crc32", NULL, MAVLINK_TYPE_UINT32_T, 0, 4, offsetof(mavlink_usv_mission_end_t, crc32) }, \
         { "count", NULL, MAVLINK_TYPE_UINT16_T, 0, 8, offsetof(mavlink_usv_mission_end_t, count) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_USV_MISSION_END { \
    "USV_MISSION_END", \
    5, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 10, offsetof(mavlink_usv_mission_end_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 11, offsetof(mavlink_usv_mission_end_t, target_component) }, \
         { "mission_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_end_t, mission_id) }, \
         { "crc32", NULL, MAVLINK_TYPE_UINT32_T, 0, 4, offsetof(mavlink_usv_mission_end_t, crc32) }, \
         { "count", NULL, MAVLINK_TYPE_UINT16_T, 0, 8, offsetof(mavlink_usv_mission_end_t, count) }, \
         } \
}
#endif

/**
 * @brief Pack a usv_mission_end message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param mission_id  Mission id.
 * @param crc32  CRC-32 announced in BEGIN.
 * @param count  Number of items.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_end_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint32_t crc32, uint16_t count)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_END_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint16_t(buf, 8, count);
    _mav_put_uint8_t(buf, 10, target_system);
    _mav_put_uint8_t(buf, 11, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_END_LEN);
#else
    mavlink_usv_mission_end_t packet;
    packet.mission_id = mission_id;
    packet.crc32 = crc32;
    packet.count = count;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_END_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_END;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN, MAVLINK_MSG_ID_USV_MISSION_END_CRC);
}

/**
 * @brief Pack a usv_mission_end message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param mission_id  Mission id.
 * @param crc32  CRC-32 announced in BEGIN.
 * @param count  Number of items.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_end_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint32_t crc32, uint16_t count)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_END_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint16_t(buf, 8, count);
    _mav_put_uint8_t(buf, 10, target_system);
    _mav_put_uint8_t(buf, 11, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_END_LEN);
#else
    mavlink_usv_mission_end_t packet;
    packet.mission_id = mission_id;
    packet.crc32 = crc32;
    packet.count = count;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_END_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_END;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN, MAVLINK_MSG_ID_USV_MISSION_END_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN);
#endif
}

/**
 * @brief Pack a usv_mission_end message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param mission_id  Mission id.
 * @param crc32  CRC-32 announced in BEGIN.
 * @param count  Number of items.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_end_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t target_system,uint8_t target_component,uint32_t mission_id,uint32_t crc32,uint16_t count)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_END_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint16_t(buf, 8, count);
    _mav_put_uint8_t(buf, 10, target_system);
    _mav_put_uint8_t(buf, 11, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_END_LEN);
#else
    mavlink_usv_mission_end_t packet;
    packet.mission_id = mission_id;
    packet.crc32 = crc32;
    packet.count = count;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_END_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_END;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN, MAVLINK_MSG_ID_USV_MISSION_END_CRC);
}

/**
 * @brief Encode a usv_mission_end struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_end C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_end_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_usv_mission_end_t* usv_mission_end)
{
    return mavlink_msg_usv_mission_end_pack(system_id, component_id, msg, usv_mission_end->target_system, usv_mission_end->target_component, usv_mission_end->mission_id, usv_mission_end->crc32, usv_mission_end->count);
}

/**
 * @brief Encode a usv_mission_end struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_end C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_end_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_usv_mission_end_t* usv_mission_end)
{
    return mavlink_msg_usv_mission_end_pack_chan(system_id, component_id, chan, msg, usv_mission_end->target_system, usv_mission_end->target_component, usv_mission_end->mission_id, usv_mission_end->crc32, usv_mission_end->count);
}

/**
 * @brief Encode a usv_mission_end struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_end C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_end_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_usv_mission_end_t* usv_mission_end)
{
    return mavlink_msg_usv_mission_end_pack_status(system_id, component_id, _status, msg,  usv_mission_end->target_system, usv_mission_end->target_component, usv_mission_end->mission_id, usv_mission_end->crc32, usv_mission_end->count);
}

/**
 * @brief Send a usv_mission_end message
 * @param chan MAVLink channel to send the message
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param mission_id  Mission id.
 * @param crc32  CRC-32 announced in BEGIN.
 * @param count  Number of items.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_usv_mission_end_send(mavlink_channel_t chan, uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint32_t crc32, uint16_t count)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_END_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint16_t(buf, 8, count);
    _mav_put_uint8_t(buf, 10, target_system);
    _mav_put_uint8_t(buf, 11, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_END, buf, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN, MAVLINK_MSG_ID_USV_MISSION_END_CRC);
#else
    mavlink_usv_mission_end_t packet;
    packet.mission_id = mission_id;
    packet.crc32 = crc32;
    packet.count = count;
    packet.target_system = target_system;
    packet.target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_END, (const char *)&packet, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN, MAVLINK_MSG_ID_USV_MISSION_END_CRC);
#endif
}

/**
 * @brief Send a usv_mission_end message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_usv_mission_end_send_struct(mavlink_channel_t chan, const mavlink_usv_mission_end_t* usv_mission_end)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_usv_mission_end_send(chan, usv_mission_end->target_system, usv_mission_end->target_component, usv_mission_end->mission_id, usv_mission_end->crc32, usv_mission_end->count);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_END, (const char *)usv_mission_end, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN, MAVLINK_MSG_ID_USV_MISSION_END_CRC);
#endif
}

#if MAVLINK_MSG_ID_USV_MISSION_END_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_usv_mission_end_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint32_t crc32, uint16_t count)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint32_t(buf, 4, crc32);
    _mav_put_uint16_t(buf, 8, count);
    _mav_put_uint8_t(buf, 10, target_system);
    _mav_put_uint8_t(buf, 11, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_END, buf, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN, MAVLINK_MSG_ID_USV_MISSION_END_CRC);
#else
    mavlink_usv_mission_end_t *packet = (mavlink_usv_mission_end_t *)msgbuf;
    packet->mission_id = mission_id;
    packet->crc32 = crc32;
    packet->count = count;
    packet->target_system = target_system;
    packet->target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_END, (const char *)packet, MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_END_LEN, MAVLINK_MSG_ID_USV_MISSION_END_CRC);
#endif
}
#endif

#endif

// MESSAGE USV_MISSION_END UNPACKING


/**
 * @brief Get field target_system from usv_mission_end message
 *
 * @return  System ID of the boat.
 */
static inline uint8_t mavlink_msg_usv_mission_end_get_target_system(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  10);
}

/**
 * @brief Get field target_component from usv_mission_end message
 *
 * @return  Component ID.
 */
static inline uint8_t mavlink_msg_usv_mission_end_get_target_component(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  11);
}

/**
 * @brief Get field mission_id from usv_mission_end message
 *
 * @return  Mission id.
 */
static inline uint32_t mavlink_msg_usv_mission_end_get_mission_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  0);
}

/**
 * @brief Get field crc32 from usv_mission_end message
 *
 * @return  CRC-32 announced in BEGIN.
 */
static inline uint32_t mavlink_msg_usv_mission_end_get_crc32(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  4);
}

/**
 * @brief Get field count from usv_mission_end message
 *
 * @return  Number of items.
 */
static inline uint16_t mavlink_msg_usv_mission_end_get_count(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  8);
}

/**
 * @brief Decode a usv_mission_end message into a struct
 *
 * @param msg The message to decode
 * @param usv_mission_end C-struct to decode the message contents into
 */
static inline void mavlink_msg_usv_mission_end_decode(const mavlink_message_t* msg, mavlink_usv_mission_end_t* usv_mission_end)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    usv_mission_end->mission_id = mavlink_msg_usv_mission_end_get_mission_id(msg);
    usv_mission_end->crc32 = mavlink_msg_usv_mission_end_get_crc32(msg);
    usv_mission_end->count = mavlink_msg_usv_mission_end_get_count(msg);
    usv_mission_end->target_system = mavlink_msg_usv_mission_end_get_target_system(msg);
    usv_mission_end->target_component = mavlink_msg_usv_mission_end_get_target_component(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_USV_MISSION_END_LEN? msg->len : MAVLINK_MSG_ID_USV_MISSION_END_LEN;
        memset(usv_mission_end, 0, MAVLINK_MSG_ID_USV_MISSION_END_LEN);
    memcpy(usv_mission_end, _MAV_PAYLOAD(msg), len);
#endif
}
