#pragma once
// MESSAGE USV_THRUST PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_USV_THRUST 44008


typedef struct __mavlink_usv_thrust_t {
 uint32_t time_boot_ms; /*< [ms] Boat uptime.*/
 float cross_track; /*< [m] Signed cross-track error of the active leg (positive: boat left of the track).*/
 float slip; /*< [s] Schedule slip: positive when the boat is behind its timed plan.*/
 int16_t left_pm; /*<  Left propeller command, per mille of full thrust (-1000..1000).*/
 int16_t right_pm; /*<  Right propeller command, per mille of full thrust (-1000..1000).*/
} mavlink_usv_thrust_t;

#define MAVLINK_MSG_ID_USV_THRUST_LEN 16
#define MAVLINK_MSG_ID_USV_THRUST_MIN_LEN 16
#define MAVLINK_MSG_ID_44008_LEN 16
#define MAVLINK_MSG_ID_44008_MIN_LEN 16

#define MAVLINK_MSG_ID_USV_THRUST_CRC 146
#define MAVLINK_MSG_ID_44008_CRC 146



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_USV_THRUST { \
    44008, \
    "USV_THRUST", \
    5, \
    {  { "time_boot_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_thrust_t, time_boot_ms) }, \
         { "left_pm", NULL, MAVLINK_TYPE_INT16_T, 0, 12, offsetof(mavlink_usv_thrust_t, left_pm) }, \
         { "right_pm", NULL, MAVLINK_TYPE_INT16_T, 0, 14, offsetof(mavlink_usv_thrust_t, right_pm) }, \
         { "cross_track", NULL, MAVLINK_TYPE_FLOAT, 0, 4, offsetof(mavlink_usv_thrust_t, cross_track) }, \
         { "slip", NULL, MAVLINK_TYPE_FLOAT, 0, 8, offsetof(mavlink_usv_thrust_t, slip) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_USV_THRUST { \
    "USV_THRUST", \
    5, \
    {  { "time_boot_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_thrust_t, time_boot_ms) }, \
         { "left_pm", NULL, MAVLINK_TYPE_INT16_T, 0, 12, offsetof(mavlink_usv_thrust_t, left_pm) }, \
         { "right_pm", NULL, MAVLINK_TYPE_INT16_T, 0, 14, offsetof(mavlink_usv_thrust_t, right_pm) }, \
         { "cross_track", NULL, MAVLINK_TYPE_FLOAT, 0, 4, offsetof(mavlink_usv_thrust_t, cross_track) }, \
         { "slip", NULL, MAVLINK_TYPE_FLOAT, 0, 8, offsetof(mavlink_usv_thrust_t, slip) }, \
         } \
}
#endif

/**
 * @brief Pack a usv_thrust message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_ms [ms] Boat uptime.
 * @param left_pm  Left propeller command, per mille of full thrust (-1000..1000).
 * @param right_pm  Right propeller command, per mille of full thrust (-1000..1000).
 * @param cross_track [m] Signed cross-track error of the active leg (positive: boat left of the track).
 * @param slip [s] Schedule slip: positive when the boat is behind its timed plan.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_thrust_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint32_t time_boot_ms, int16_t left_pm, int16_t right_pm, float cross_track, float slip)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_THRUST_LEN];
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_float(buf, 4, cross_track);
    _mav_put_float(buf, 8, slip);
    _mav_put_int16_t(buf, 12, left_pm);
    _mav_put_int16_t(buf, 14, right_pm);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_THRUST_LEN);
#else
    mavlink_usv_thrust_t packet;
    packet.time_boot_ms = time_boot_ms;
    packet.cross_track = cross_track;
    packet.slip = slip;
    packet.left_pm = left_pm;
    packet.right_pm = right_pm;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_THRUST_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_THRUST;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN, MAVLINK_MSG_ID_USV_THRUST_CRC);
}

/**
 * @brief Pack a usv_thrust message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_ms [ms] Boat uptime.
 * @param left_pm  Left propeller command, per mille of full thrust (-1000..1000).
 * @param right_pm  Right propeller command, per mille of full thrust (-1000..1000).
 * @param cross_track [m] Signed cross-track error of the active leg (positive: boat left of the track).
 * @param slip [s] Schedule slip: positive when the boat is behind its timed plan.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_thrust_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint32_t time_boot_ms, int16_t left_pm, int16_t right_pm, float cross_track, float slip)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_THRUST_LEN];
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_float(buf, 4, cross_track);
    _mav_put_float(buf, 8, slip);
    _mav_put_int16_t(buf, 12, left_pm);
    _mav_put_int16_t(buf, 14, right_pm);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_THRUST_LEN);
#else
    mavlink_usv_thrust_t packet;
    packet.time_boot_ms = time_boot_ms;
    packet.cross_track = cross_track;
    packet.slip = slip;
    packet.left_pm = left_pm;
    packet.right_pm = right_pm;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_THRUST_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_THRUST;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN, MAVLINK_MSG_ID_USV_THRUST_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN);
#endif
}

/**
 * @brief Pack a usv_thrust message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param time_boot_ms [ms] Boat uptime.
 * @param left_pm  Left propeller command, per mille of full thrust (-1000..1000).
 * @param right_pm  Right propeller command, per mille of full thrust (-1000..1000).
 * @param cross_track [m] Signed cross-track error of the active leg (positive: boat left of the track).
 * @param slip [s] Schedule slip: positive when the boat is behind its timed plan.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_thrust_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint32_t time_boot_ms,int16_t left_pm,int16_t right_pm,float cross_track,float slip)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_THRUST_LEN];
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_float(buf, 4, cross_track);
    _mav_put_float(buf, 8, slip);
    _mav_put_int16_t(buf, 12, left_pm);
    _mav_put_int16_t(buf, 14, right_pm);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_THRUST_LEN);
#else
    mavlink_usv_thrust_t packet;
    packet.time_boot_ms = time_boot_ms;
    packet.cross_track = cross_track;
    packet.slip = slip;
    packet.left_pm = left_pm;
    packet.right_pm = right_pm;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_THRUST_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_THRUST;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN, MAVLINK_MSG_ID_USV_THRUST_CRC);
}

/**
 * @brief Encode a usv_thrust struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param usv_thrust C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_thrust_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_usv_thrust_t* usv_thrust)
{
    return mavlink_msg_usv_thrust_pack(system_id, component_id, msg, usv_thrust->time_boot_ms, usv_thrust->left_pm, usv_thrust->right_pm, usv_thrust->cross_track, usv_thrust->slip);
}

/**
 * @brief Encode a usv_thrust struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param usv_thrust C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_thrust_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_usv_thrust_t* usv_thrust)
{
    return mavlink_msg_usv_thrust_pack_chan(system_id, component_id, chan, msg, usv_thrust->time_boot_ms, usv_thrust->left_pm, usv_thrust->right_pm, usv_thrust->cross_track, usv_thrust->slip);
}

/**
 * @brief Encode a usv_thrust struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param usv_thrust C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_thrust_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_usv_thrust_t* usv_thrust)
{
    return mavlink_msg_usv_thrust_pack_status(system_id, component_id, _status, msg,  usv_thrust->time_boot_ms, usv_thrust->left_pm, usv_thrust->right_pm, usv_thrust->cross_track, usv_thrust->slip);
}

/**
 * @brief Send a usv_thrust message
 * @param chan MAVLink channel to send the message
 *
 * @param time_boot_ms [ms] Boat uptime.
 * @param left_pm  Left propeller command, per mille of full thrust (-1000..1000).
 * @param right_pm  Right propeller command, per mille of full thrust (-1000..1000).
 * @param cross_track [m] Signed cross-track error of the active leg (positive: boat left of the track).
 * @param slip [s] Schedule slip: positive when the boat is behind its timed plan.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_usv_thrust_send(mavlink_channel_t chan, uint32_t time_boot_ms, int16_t left_pm, int16_t right_pm, float cross_track, float slip)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_THRUST_LEN];
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_float(buf, 4, cross_track);
    _mav_put_float(buf, 8, slip);
    _mav_put_int16_t(buf, 12, left_pm);
    _mav_put_int16_t(buf, 14, right_pm);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_THRUST, buf, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN, MAVLINK_MSG_ID_USV_THRUST_CRC);
#else
    mavlink_usv_thrust_t packet;
    packet.time_boot_ms = time_boot_ms;
    packet.cross_track = cross_track;
    packet.slip = slip;
    packet.left_pm = left_pm;
    packet.right_pm = right_pm;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_THRUST, (const char *)&packet, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN, MAVLINK_MSG_ID_USV_THRUST_CRC);
#endif
}

/**
 * @brief Send a usv_thrust message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_usv_thrust_send_struct(mavlink_channel_t chan, const mavlink_usv_thrust_t* usv_thrust)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_usv_thrust_send(chan, usv_thrust->time_boot_ms, usv_thrust->left_pm, usv_thrust->right_pm, usv_thrust->cross_track, usv_thrust->slip);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_THRUST, (const char *)usv_thrust, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN, MAVLINK_MSG_ID_USV_THRUST_CRC);
#endif
}

#if MAVLINK_MSG_ID_USV_THRUST_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_usv_thrust_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint32_t time_boot_ms, int16_t left_pm, int16_t right_pm, float cross_track, float slip)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_float(buf, 4, cross_track);
    _mav_put_float(buf, 8, slip);
    _mav_put_int16_t(buf, 12, left_pm);
    _mav_put_int16_t(buf, 14, right_pm);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_THRUST, buf, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN, MAVLINK_MSG_ID_USV_THRUST_CRC);
#else
    mavlink_usv_thrust_t *packet = (mavlink_usv_thrust_t *)msgbuf;
    packet->time_boot_ms = time_boot_ms;
    packet->cross_track = cross_track;
    packet->slip = slip;
    packet->left_pm = left_pm;
    packet->right_pm = right_pm;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_THRUST, (const char *)packet, MAVLINK_MSG_ID_USV_THRUST_MIN_LEN, MAVLINK_MSG_ID_USV_THRUST_LEN, MAVLINK_MSG_ID_USV_THRUST_CRC);
#endif
}
#endif

#endif

// MESSAGE USV_THRUST UNPACKING


/**
 * @brief Get field time_boot_ms from usv_thrust message
 *
 * @return [ms] Boat uptime.
 */
static inline uint32_t mavlink_msg_usv_thrust_get_time_boot_ms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  0);
}

/**
 * @brief Get field left_pm from usv_thrust message
 *
 * @return  Left propeller command, per mille of full thrust (-1000..1000).
 */
static inline int16_t mavlink_msg_usv_thrust_get_left_pm(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  12);
}

/**
 * @brief Get field right_pm from usv_thrust message
 *
 * @return  Right propeller command, per mille of full thrust (-1000..1000).
 */
static inline int16_t mavlink_msg_usv_thrust_get_right_pm(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  14);
}

/**
 * @brief Get field cross_track from usv_thrust message
 *
 * @return [m] Signed cross-track error of the active leg (positive: boat left of the track).
 */
static inline float mavlink_msg_usv_thrust_get_cross_track(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  4);
}

/**
 * @brief Get field slip from usv_thrust message
 *
 * @return [s] Schedule slip: positive when the boat is behind its timed plan.
 */
static inline float mavlink_msg_usv_thrust_get_slip(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  8);
}

/**
 * @brief Decode a usv_thrust message into a struct
 *
 * @param msg The message to decode
 * @param usv_thrust C-struct to decode the message contents into
 */
static inline void mavlink_msg_usv_thrust_decode(const mavlink_message_t* msg, mavlink_usv_thrust_t* usv_thrust)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    usv_thrust->time_boot_ms = mavlink_msg_usv_thrust_get_time_boot_ms(msg);
    usv_thrust->cross_track = mavlink_msg_usv_thrust_get_cross_track(msg);
    usv_thrust->slip = mavlink_msg_usv_thrust_get_slip(msg);
    usv_thrust->left_pm = mavlink_msg_usv_thrust_get_left_pm(msg);
    usv_thrust->right_pm = mavlink_msg_usv_thrust_get_right_pm(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_USV_THRUST_LEN? msg->len : MAVLINK_MSG_ID_USV_THRUST_LEN;
        memset(usv_thrust, 0, MAVLINK_MSG_ID_USV_THRUST_LEN);
    memcpy(usv_thrust, _MAV_PAYLOAD(msg), len);
#endif
}
