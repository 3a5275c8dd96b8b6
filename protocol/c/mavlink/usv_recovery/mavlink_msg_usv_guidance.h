#pragma once
// MESSAGE USV_GUIDANCE PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_USV_GUIDANCE 44007


typedef struct __mavlink_usv_guidance_t {
 uint16_t heading_cdeg; /*< [cdeg] Compass heading to steer.*/
 uint16_t speed_cms; /*< [cm/s] Speed through the water.*/
 uint16_t valid_ms; /*< [ms] Validity.*/
 uint8_t target_system; /*<  System ID of the boat.*/
 uint8_t target_component; /*<  Component ID.*/
} mavlink_usv_guidance_t;

#define MAVLINK_MSG_ID_USV_GUIDANCE_LEN 8
#define MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN 8
#define MAVLINK_MSG_ID_44007_LEN 8
#define MAVLINK_MSG_ID_44007_MIN_LEN 8

#define MAVLINK_MSG_ID_USV_GUIDANCE_CRC 153
#define MAVLINK_MSG_ID_44007_CRC 153



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_USV_GUIDANCE { \
    44007, \
    "USV_GUIDANCE", \
    5, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 6, offsetof(mavlink_usv_guidance_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 7, offsetof(mavlink_usv_guidance_t, target_component) }, \
         { "heading_cdeg", NULL, MAVLINK_TYPE_UINT16_T, 0, 0, offsetof(mavlink_usv_guidance_t, heading_cdeg) }, \
         { "speed_cms", NULL, MAVLINK_TYPE_UINT16_T, 0, 2, offsetof(mavlink_usv_guidance_t, speed_cms) }, \
         { "valid_ms", NULL, MAVLINK_TYPE_UINT16_T, 0, 4, offsetof(mavlink_usv_guidance_t, valid_ms) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_USV_GUIDANCE { \
    "USV_GUIDANCE", \
    5, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 6, offsetof(mavlink_usv_guidance_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 7, offsetof(mavlink_usv_guidance_t, target_component) }, \
         { "heading_cdeg", NULL, MAVLINK_TYPE_UINT16_T, 0, 0, offsetof(mavlink_usv_guidance_t, heading_cdeg) }, \
         { "speed_cms", NULL, MAVLINK_TYPE_UINT16_T, 0, 2, offsetof(mavlink_usv_guidance_t, speed_cms) }, \
         { "valid_ms", NULL, MAVLINK_TYPE_UINT16_T, 0, 4, offsetof(mavlink_usv_guidance_t, valid_ms) }, \
         } \
}
#endif

/**
 * @brief Pack a usv_guidance message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param heading_cdeg [cdeg] Compass heading to steer.
 * @param speed_cms [cm/s] Speed through the water.
 * @param valid_ms [ms] Validity.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_guidance_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint16_t heading_cdeg, uint16_t speed_cms, uint16_t valid_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_GUIDANCE_LEN];
    _mav_put_uint16_t(buf, 0, heading_cdeg);
    _mav_put_uint16_t(buf, 2, speed_cms);
    _mav_put_uint16_t(buf, 4, valid_ms);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_GUIDANCE_LEN);
#else
    mavlink_usv_guidance_t packet;
    packet.heading_cdeg = heading_cdeg;
    packet.speed_cms = speed_cms;
    packet.valid_ms = valid_ms;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_GUIDANCE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_GUIDANCE;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_CRC);
}

/**
 * @brief Pack a usv_guidance message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param heading_cdeg [cdeg] Compass heading to steer.
 * @param speed_cms [cm/s] Speed through the water.
 * @param valid_ms [ms] Validity.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_guidance_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint16_t heading_cdeg, uint16_t speed_cms, uint16_t valid_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_GUIDANCE_LEN];
    _mav_put_uint16_t(buf, 0, heading_cdeg);
    _mav_put_uint16_t(buf, 2, speed_cms);
    _mav_put_uint16_t(buf, 4, valid_ms);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_GUIDANCE_LEN);
#else
    mavlink_usv_guidance_t packet;
    packet.heading_cdeg = heading_cdeg;
    packet.speed_cms = speed_cms;
    packet.valid_ms = valid_ms;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_GUIDANCE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_GUIDANCE;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN);
#endif
}

/**
 * @brief Pack a usv_guidance message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param heading_cdeg [cdeg] Compass heading to steer.
 * @param speed_cms [cm/s] Speed through the water.
 * @param valid_ms [ms] Validity.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_guidance_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t target_system,uint8_t target_component,uint16_t heading_cdeg,uint16_t speed_cms,uint16_t valid_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_GUIDANCE_LEN];
    _mav_put_uint16_t(buf, 0, heading_cdeg);
    _mav_put_uint16_t(buf, 2, speed_cms);
    _mav_put_uint16_t(buf, 4, valid_ms);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_GUIDANCE_LEN);
#else
    mavlink_usv_guidance_t packet;
    packet.heading_cdeg = heading_cdeg;
    packet.speed_cms = speed_cms;
    packet.valid_ms = valid_ms;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_GUIDANCE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_GUIDANCE;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_CRC);
}

/**
 * @brief Encode a usv_guidance struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param usv_guidance C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_guidance_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_usv_guidance_t* usv_guidance)
{
    return mavlink_msg_usv_guidance_pack(system_id, component_id, msg, usv_guidance->target_system, usv_guidance->target_component, usv_guidance->heading_cdeg, usv_guidance->speed_cms, usv_guidance->valid_ms);
}

/**
 * @brief Encode a usv_guidance struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param usv_guidance C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_guidance_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_usv_guidance_t* usv_guidance)
{
    return mavlink_msg_usv_guidance_pack_chan(system_id, component_id, chan, msg, usv_guidance->target_system, usv_guidance->target_component, usv_guidance->heading_cdeg, usv_guidance->speed_cms, usv_guidance->valid_ms);
}

/**
 * @brief Encode a usv_guidance struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param usv_guidance C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_guidance_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_usv_guidance_t* usv_guidance)
{
    return mavlink_msg_usv_guidance_pack_status(system_id, component_id, _status, msg,  usv_guidance->target_system, usv_guidance->target_component, usv_guidance->heading_cdeg, usv_guidance->speed_cms, usv_guidance->valid_ms);
}

/**
 * @brief Send a usv_guidance message
 * @param chan MAVLink channel to send the message
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param heading_cdeg [cdeg] Compass heading to steer.
 * @param speed_cms [cm/s] Speed through the water.
 * @param valid_ms [ms] Validity.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_usv_guidance_send(mavlink_channel_t chan, uint8_t target_system, uint8_t target_component, uint16_t heading_cdeg, uint16_t speed_cms, uint16_t valid_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_GUIDANCE_LEN];
    _mav_put_uint16_t(buf, 0, heading_cdeg);
    _mav_put_uint16_t(buf, 2, speed_cms);
    _mav_put_uint16_t(buf, 4, valid_ms);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_GUIDANCE, buf, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_CRC);
#else
    mavlink_usv_guidance_t packet;
    packet.heading_cdeg = heading_cdeg;
    packet.speed_cms = speed_cms;
    packet.valid_ms = valid_ms;
    packet.target_system = target_system;
    packet.target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_GUIDANCE, (const char *)&packet, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_CRC);
#endif
}

/**
 * @brief Send a usv_guidance message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_usv_guidance_send_struct(mavlink_channel_t chan, const mavlink_usv_guidance_t* usv_guidance)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_usv_guidance_send(chan, usv_guidance->target_system, usv_guidance->target_component, usv_guidance->heading_cdeg, usv_guidance->speed_cms, usv_guidance->valid_ms);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_GUIDANCE, (const char *)usv_guidance, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_CRC);
#endif
}

#if MAVLINK_MSG_ID_USV_GUIDANCE_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_usv_guidance_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t target_system, uint8_t target_component, uint16_t heading_cdeg, uint16_t speed_cms, uint16_t valid_ms)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint16_t(buf, 0, heading_cdeg);
    _mav_put_uint16_t(buf, 2, speed_cms);
    _mav_put_uint16_t(buf, 4, valid_ms);
    _mav_put_uint8_t(buf, 6, target_system);
    _mav_put_uint8_t(buf, 7, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_GUIDANCE, buf, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_CRC);
#else
    mavlink_usv_guidance_t *packet = (mavlink_usv_guidance_t *)msgbuf;
    packet->heading_cdeg = heading_cdeg;
    packet->speed_cms = speed_cms;
    packet->valid_ms = valid_ms;
    packet->target_system = target_system;
    packet->target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_GUIDANCE, (const char *)packet, MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_LEN, MAVLINK_MSG_ID_USV_GUIDANCE_CRC);
#endif
}
#endif

#endif

// MESSAGE USV_GUIDANCE UNPACKING


/**
 * @brief Get field target_system from usv_guidance message
 *
 * @return  System ID of the boat.
 */
static inline uint8_t mavlink_msg_usv_guidance_get_target_system(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  6);
}

/**
 * @brief Get field target_component from usv_guidance message
 *
 * @return  Component ID.
 */
static inline uint8_t mavlink_msg_usv_guidance_get_target_component(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  7);
}

/**
 * @brief Get field heading_cdeg from usv_guidance message
 *
 * @return [cdeg] Compass heading to steer.
 */
static inline uint16_t mavlink_msg_usv_guidance_get_heading_cdeg(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  0);
}

/**
 * @brief Get field speed_cms from usv_guidance message
 *
 * @return [cm/s] Speed through the water.
 */
static inline uint16_t mavlink_msg_usv_guidance_get_speed_cms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  2);
}

/**
 * @brief Get field valid_ms from usv_guidance message
 *
 * @return [ms] Validity.
 */
static inline uint16_t mavlink_msg_usv_guidance_get_valid_ms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  4);
}

/**
 * @brief Decode a usv_guidance message into a struct
 *
 * @param msg The message to decode
 * @param usv_guidance C-struct to decode the message contents into
 */
static inline void mavlink_msg_usv_guidance_decode(const mavlink_message_t* msg, mavlink_usv_guidance_t* usv_guidance)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    usv_guidance->heading_cdeg = mavlink_msg_usv_guidance_get_heading_cdeg(msg);
    usv_guidance->speed_cms = mavlink_msg_usv_guidance_get_speed_cms(msg);
    usv_guidance->valid_ms = mavlink_msg_usv_guidance_get_valid_ms(msg);
    usv_guidance->target_system = mavlink_msg_usv_guidance_get_target_system(msg);
    usv_guidance->target_component = mavlink_msg_usv_guidance_get_target_component(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_USV_GUIDANCE_LEN? msg->len : MAVLINK_MSG_ID_USV_GUIDANCE_LEN;
        memset(usv_guidance, 0, MAVLINK_MSG_ID_USV_GUIDANCE_LEN);
    memcpy(usv_guidance, _MAV_PAYLOAD(msg), len);
#endif
}
