#pragma once
// MESSAGE USV_MISSION_ACK PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_USV_MISSION_ACK 44002


typedef struct __mavlink_usv_mission_ack_t {
 uint32_t mission_id; /*<  Mission id answered.*/
 uint16_t seq; /*<  Items staged contiguously from 0 (the next the boat needs).*/
 uint8_t target_system; /*<  System ID of the station.*/
 uint8_t target_component; /*<  Component ID.*/
 uint8_t result; /*<  Result.*/
 uint8_t stage; /*<  1: BEGIN, 2: ITEM, 3: END, 4: READ.*/
} mavlink_usv_mission_ack_t;

#define MAVLINK_MSG_ID_USV_MISSION_ACK_LEN 10
#define MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN 10
#define MAVLINK_MSG_ID_44002_LEN 10
#define MAVLINK_MSG_ID_44002_MIN_LEN 10

#define MAVLINK_MSG_ID_USV_MISSION_ACK_CRC 136
#define MAVLINK_MSG_ID_44002_CRC 136



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_USV_MISSION_ACK { \
    44002, \
    "USV_MISSION_ACK", \
    6, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 6, offsetof(mavlink_usv_mission_ack_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 7, offsetof(mavlink_usv_mission_ack_t, target_component) }, \
         { "mission_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_ack_t, mission_id) }, \
         { "seq", NULL, MAVLINK_TYPE_UINT16_T, 0, 4, offsetof(mavlink_usv_mission_ack_t, seq) }, \
         { "result", NULL, MAVLINK_TYPE_UINT8_T, 0, 8, offsetof(mavlink_usv_mission_ack_t, result) }, \
         { "stage", NULL, MAVLINK_TYPE_UINT8_T, 0, 9, offsetof(mavlink_usv_mission_ack_t, stage) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_USV_MISSION_ACK { \
    "USV_MISSION_ACK", \
    6, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 6, offsetof(mavlink_usv_mission_ack_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 7, offsetof(mavlink_usv_mission_ack_t, target_component) }, \
         { "mission_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_ack_t, mission_id) }, \
         { "seq", NULL, MAVLINK_TYPE_UINT16_T, 0, 4, offsetof(mavlink_usv_mission_ack_t, seq) }, \
         { "result", NULL, MAVLINK_TYPE_UINT8_T, 0, 8, offsetof(mavlink_usv_mission_ack_t, result) }, \
         { "stage", NULL, MAVLINK_TYPE_UINT8_T, 0, 9, offsetof(mavlink_usv_mission_ack_t, stage) }, \
         } \
}
#endif

/**
 * @brief Pack a usv_mission_ack message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the station.
 * @param target_component  Component ID.
 * @param mission_id  Mission id answered.
 * @param seq  Items staged contiguously from 0 (the next the boat needs).
 * @param result  Result.
 * @param stage  1: BEGIN, 2: ITEM, 3: END, 4: READ.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_ack_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint16_t seq, uint8_t result, uint8_t stage)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_ACK_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint16_t(buf, 4, seq);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);
    _mav_put_uint8_t(buf, 8, result);
    _mav_put_uint8_t(buf, 9, stage);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN);
#else
    mavlink_usv_mission_ack_t packet;
    packet.mission_id = mission_id;
    packet.seq = seq;
    packet.target_system = target_system;
    packet.target_component = target_component;
    packet.result = result;
    packet.stage = stage;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_ACK;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_CRC);
}

/**
 * @brief Pack a usv_mission_ack message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the station.
 * @param target_component  Component ID.
 * @param mission_id  Mission id answered.
 * @param seq  Items staged contiguously from 0 (the next the boat needs).
 * @param result  Result.
 * @param stage  1: BEGIN, 2: ITEM, 3: END, 4: READ.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_ack_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint16_t seq, uint8_t result, uint8_t stage)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_ACK_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint16_t(buf, 4, seq);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);
    _mav_put_uint8_t(buf, 8, result);
    _mav_put_uint8_t(buf, 9, stage);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN);
#else
    mavlink_usv_mission_ack_t packet;
    packet.mission_id = mission_id;
    packet.seq = seq;
    packet.target_system = target_system;
    packet.target_component = target_component;
    packet.result = result;
    packet.stage = stage;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_ACK;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN);
#endif
}

/**
 * @brief Pack a usv_mission_ack message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param target_system  System ID of the station.
 * @param target_component  Component ID.
 * @param mission_id  Mission id answered.
 * @param seq  Items staged contiguously from 0 (the next the boat needs).
 * @param result  Result.
 * @param stage  1: BEGIN, 2: ITEM, 3: END, 4: READ.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_ack_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t target_system,uint8_t target_component,uint32_t mission_id,uint16_t seq,uint8_t result,uint8_t stage)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_ACK_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint16_t(buf, 4, seq);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);
    _mav_put_uint8_t(buf, 8, result);
    _mav_put_uint8_t(buf, 9, stage);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN);
#else
    mavlink_usv_mission_ack_t packet;
    packet.mission_id = mission_id;
    packet.seq = seq;
    packet.target_system = target_system;
    packet.target_component = target_component;
    packet.result = result;
    packet.stage = stage;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_ACK;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_CRC);
}

/**
 * @brief Encode a usv_mission_ack struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_ack C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_ack_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_usv_mission_ack_t* usv_mission_ack)
{
    return mavlink_msg_usv_mission_ack_pack(system_id, component_id, msg, usv_mission_ack->target_system, usv_mission_ack->target_component, usv_mission_ack->mission_id, usv_mission_ack->seq, usv_mission_ack->result, usv_mission_ack->stage);
}

/**
 * @brief Encode a usv_mission_ack struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_ack C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_ack_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_usv_mission_ack_t* usv_mission_ack)
{
    return mavlink_msg_usv_mission_ack_pack_chan(system_id, component_id, chan, msg, usv_mission_ack->target_system, usv_mission_ack->target_component, usv_mission_ack->mission_id, usv_mission_ack->seq, usv_mission_ack->result, usv_mission_ack->stage);
}

/**
 * @brief Encode a usv_mission_ack struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_ack C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_ack_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_usv_mission_ack_t* usv_mission_ack)
{
    return mavlink_msg_usv_mission_ack_pack_status(system_id, component_id, _status, msg,  usv_mission_ack->target_system, usv_mission_ack->target_component, usv_mission_ack->mission_id, usv_mission_ack->seq, usv_mission_ack->result, usv_mission_ack->stage);
}

/**
 * @brief Send a usv_mission_ack message
 * @param chan MAVLink channel to send the message
 *
 * @param target_system  System ID of the station.
 * @param target_component  Component ID.
 * @param mission_id  Mission id answered.
 * @param seq  Items staged contiguously from 0 (the next the boat needs).
 * @param result  Result.
 * @param stage  1: BEGIN, 2: ITEM, 3: END, 4: READ.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_usv_mission_ack_send(mavlink_channel_t chan, uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint16_t seq, uint8_t result, uint8_t stage)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_ACK_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint16_t(buf, 4, seq);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);
    _mav_put_uint8_t(buf, 8, result);
    _mav_put_uint8_t(buf, 9, stage);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ACK, buf, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_CRC);
#else
    mavlink_usv_mission_ack_t packet;
    packet.mission_id = mission_id;
    packet.seq = seq;
    packet.target_system = target_system;
    packet.target_component = target_component;
    packet.result = result;
    packet.stage = stage;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ACK, (const char *)&packet, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_CRC);
#endif
}

/**
 * @brief Send a usv_mission_ack message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_usv_mission_ack_send_struct(mavlink_channel_t chan, const mavlink_usv_mission_ack_t* usv_mission_ack)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_usv_mission_ack_send(chan, usv_mission_ack->target_system, usv_mission_ack->target_component, usv_mission_ack->mission_id, usv_mission_ack->seq, usv_mission_ack->result, usv_mission_ack->stage);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ACK, (const char *)usv_mission_ack, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_CRC);
#endif
}

#if MAVLINK_MSG_ID_USV_MISSION_ACK_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_usv_mission_ack_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint16_t seq, uint8_t result, uint8_t stage)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_uint16_t(buf, 4, seq);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);
    _mav_put_uint8_t(buf, 8, result);
    _mav_put_uint8_t(buf, 9, stage);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ACK, buf, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_CRC);
#else
    mavlink_usv_mission_ack_t *packet = (mavlink_usv_mission_ack_t *)msgbuf;
    packet->mission_id = mission_id;
    packet->seq = seq;
    packet->target_system = target_system;
    packet->target_component = target_component;
    packet->result = result;
    packet->stage = stage;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ACK, (const char *)packet, MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN, MAVLINK_MSG_ID_USV_MISSION_ACK_CRC);
#endif
}
#endif

#endif

// MESSAGE USV_MISSION_ACK UNPACKING


/**
 * @brief Get field target_system from usv_mission_ack message
 *
 * @return  System ID of the station.
 */
static inline uint8_t mavlink_msg_usv_mission_ack_get_target_system(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  6);
}

/**
 * @brief Get field target_component from usv_mission_ack message
 *
 * @return  Component ID.
 */
static inline uint8_t mavlink_msg_usv_mission_ack_get_target_component(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  7);
}

/**
 * @brief Get field mission_id from usv_mission_ack message
 *
 * @return  Mission id answered.
 */
static inline uint32_t mavlink_msg_usv_mission_ack_get_mission_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  0);
}

/**
 * @brief Get field seq from usv_mission_ack message
 *
 * @return  Items staged contiguously from 0 (the next the boat needs).
 */
static inline uint16_t mavlink_msg_usv_mission_ack_get_seq(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  4);
}

/**
 * @brief Get field result from usv_mission_ack message
 *
 * @return  Result.
 */
static inline uint8_t mavlink_msg_usv_mission_ack_get_result(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  8);
}

/**
 * @brief Get field stage from usv_mission_ack message
 *
 * @return  1: BEGIN, 2: ITEM, 3: END, 4: READ.
 */
static inline uint8_t mavlink_msg_usv_mission_ack_get_stage(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  9);
}

/**
 * @brief Decode a usv_mission_ack message into a struct
 *
 * @param msg The message to decode
 * @param usv_mission_ack C-struct to decode the message contents into
 */
static inline void mavlink_msg_usv_mission_ack_decode(const mavlink_message_t* msg, mavlink_usv_mission_ack_t* usv_mission_ack)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    usv_mission_ack->mission_id = mavlink_msg_usv_mission_ack_get_mission_id(msg);
    usv_mission_ack->seq = mavlink_msg_usv_mission_ack_get_seq(msg);
    usv_mission_ack->target_system = mavlink_msg_usv_mission_ack_get_target_system(msg);
    usv_mission_ack->target_component = mavlink_msg_usv_mission_ack_get_target_component(msg);
    usv_mission_ack->result = mavlink_msg_usv_mission_ack_get_result(msg);
    usv_mission_ack->stage = mavlink_msg_usv_mission_ack_get_stage(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_USV_MISSION_ACK_LEN? msg->len : MAVLINK_MSG_ID_USV_MISSION_ACK_LEN;
        memset(usv_mission_ack, 0, MAVLINK_MSG_ID_USV_MISSION_ACK_LEN);
    memcpy(usv_mission_ack, _MAV_PAYLOAD(msg), len);
#endif
}
