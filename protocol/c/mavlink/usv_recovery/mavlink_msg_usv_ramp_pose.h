#pragma once
// MESSAGE USV_RAMP_POSE PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_USV_RAMP_POSE 44006


typedef struct __mavlink_usv_ramp_pose_t {
 uint32_t time_boot_ms; /*< [ms] Boat uptime the pose refers to (station clock mapped through TIMESYNC).*/
 int32_t lat; /*< [degE7] Ramp end latitude.*/
 int32_t lon; /*< [degE7] Ramp end longitude.*/
 float vn; /*< [m/s] Ramp end velocity north.*/
 float ve; /*< [m/s] Ramp end velocity east.*/
 float yaw_rate; /*< [rad/s] Mother ship yaw rate (clockwise positive).*/
 uint16_t bearing_cdeg; /*< [cdeg] Compass bearing of the ramp frame's +x axis.*/
 uint8_t target_system; /*<  System ID of the boat.*/
 uint8_t target_component; /*<  Component ID.*/
} mavlink_usv_ramp_pose_t;

#define MAVLINK_MSG_ID_USV_RAMP_POSE_LEN 28
#define MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN 28
#define MAVLINK_MSG_ID_44006_LEN 28
#define MAVLINK_MSG_ID_44006_MIN_LEN 28

#define MAVLINK_MSG_ID_USV_RAMP_POSE_CRC 218
#define MAVLINK_MSG_ID_44006_CRC 218



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_USV_RAMP_POSE { \
    44006, \
    "USV_RAMP_POSE", \
    9, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 26, offsetof(mavlink_usv_ramp_pose_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 27, offsetof(mavlink_usv_ramp_pose_t, target_component) }, \
         { "time_boot_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_ramp_pose_t, time_boot_ms) }, \
         { "lat", NULL, MAVLINK_TYPE_INT32_T, 0, 4, offsetof(mavlink_usv_ramp_pose_t, lat) }, \
         { "lon", NULL, MAVLINK_TYPE_INT32_T, 0, 8, offsetof(mavlink_usv_ramp_pose_t, lon) }, \
         { "bearing_cdeg", NULL, MAVLINK_TYPE_UINT16_T, 0, 24, offsetof(mavlink_usv_ramp_pose_t, bearing_cdeg) }, \
         { "vn", NULL, MAVLINK_TYPE_FLOAT, 0, 12, offsetof(mavlink_usv_ramp_pose_t, vn) }, \
         { "ve", NULL, MAVLINK_TYPE_FLOAT, 0, 16, offsetof(mavlink_usv_ramp_pose_t, ve) }, \
         { "yaw_rate", NULL, MAVLINK_TYPE_FLOAT, 0, 20, offsetof(mavlink_usv_ramp_pose_t, yaw_rate) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_USV_RAMP_POSE { \
    "USV_RAMP_POSE", \
    9, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 26, offsetof(mavlink_usv_ramp_pose_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 27, offsetof(mavlink_usv_ramp_pose_t, target_component) }, \
         { "time_boot_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_ramp_pose_t, time_boot_ms) }, \
         { "lat", NULL, MAVLINK_TYPE_INT32_T, 0, 4, offsetof(mavlink_usv_ramp_pose_t, lat) }, \
         { "lon", NULL, MAVLINK_TYPE_INT32_T, 0, 8, offsetof(mavlink_usv_ramp_pose_t, lon) }, \
         { "bearing_cdeg", NULL, MAVLINK_TYPE_UINT16_T, 0, 24, offsetof(mavlink_usv_ramp_pose_t, bearing_cdeg) }, \
         { "vn", NULL, MAVLINK_TYPE_FLOAT, 0, 12, offsetof(mavlink_usv_ramp_pose_t, vn) }, \
         { "ve", NULL, MAVLINK_TYPE_FLOAT, 0, 16, offsetof(mavlink_usv_ramp_pose_t, ve) }, \
         { "yaw_rate", NULL, MAVLINK_TYPE_FLOAT, 0, 20, offsetof(mavlink_usv_ramp_pose_t, yaw_rate) }, \
         } \
}
#endif

/**
 * @brief Pack a usv_ramp_pose message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param time_boot_ms [ms] Boat uptime the pose refers to (station clock mapped through TIMESYNC).
 * @param lat [degE7] Ramp end latitude.
 * @param lon [degE7] Ramp end longitude.
 * @param bearing_cdeg [cdeg] Compass bearing of the ramp frame's +x axis.
 * @param vn [m/s] Ramp end velocity north.
 * @param ve [m/s] Ramp end velocity east.
 * @param yaw_rate [rad/s] Mother ship yaw rate (clockwise positive).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_ramp_pose_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t time_boot_ms, int32_t lat, int32_t lon, uint16_t bearing_cdeg, float vn, float ve, float yaw_rate)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_RAMP_POSE_LEN];
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_float(buf, 12, vn);
    _mav_put_float(buf, 16, ve);
    _mav_put_float(buf, 20, yaw_rate);
    _mav_put_uint16_t(buf, 24, bearing_cdeg);
    _mav_put_uint8_t(buf, 26, target_system);
    _mav_put_uint8_t(buf, 27, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN);
#else
    mavlink_usv_ramp_pose_t packet;
    packet.time_boot_ms = time_boot_ms;
    packet.lat = lat;
    packet.lon = lon;
    packet.vn = vn;
    packet.ve = ve;
    packet.yaw_rate = yaw_rate;
    packet.bearing_cdeg = bearing_cdeg;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_RAMP_POSE;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_CRC);
}

/**
 * @brief Pack a usv_ramp_pose message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param time_boot_ms [ms] Boat uptime the pose refers to (station clock mapped through TIMESYNC).
 * @param lat [degE7] Ramp end latitude.
 * @param lon [degE7] Ramp end longitude.
 * @param bearing_cdeg [cdeg] Compass bearing of the ramp frame's +x axis.
 * @param vn [m/s] Ramp end velocity north.
 * @param ve [m/s] Ramp end velocity east.
 * @param yaw_rate [rad/s] Mother ship yaw rate (clockwise positive).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_ramp_pose_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t time_boot_ms, int32_t lat, int32_t lon, uint16_t bearing_cdeg, float vn, float ve, float yaw_rate)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_RAMP_POSE_LEN];
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_float(buf, 12, vn);
    _mav_put_float(buf, 16, ve);
    _mav_put_float(buf, 20, yaw_rate);
    _mav_put_uint16_t(buf, 24, bearing_cdeg);
    _mav_put_uint8_t(buf, 26, target_system);
    _mav_put_uint8_t(buf, 27, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN);
#else
    mavlink_usv_ramp_pose_t packet;
    packet.time_boot_ms = time_boot_ms;
    packet.lat = lat;
    packet.lon = lon;
    packet.vn = vn;
    packet.ve = ve;
    packet.yaw_rate = yaw_rate;
    packet.bearing_cdeg = bearing_cdeg;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_RAMP_POSE;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN);
#endif
}

/**
 * @brief Pack a usv_ramp_pose message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param time_boot_ms [ms] Boat uptime the pose refers to (station clock mapped through TIMESYNC).
 * @param lat [degE7] Ramp end latitude.
 * @param lon [degE7] Ramp end longitude.
 * @param bearing_cdeg [cdeg] Compass bearing of the ramp frame's +x axis.
 * @param vn [m/s] Ramp end velocity north.
 * @param ve [m/s] Ramp end velocity east.
 * @param yaw_rate [rad/s] Mother ship yaw rate (clockwise positive).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_ramp_pose_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t target_system,uint8_t target_component,uint32_t time_boot_ms,int32_t lat,int32_t lon,uint16_t bearing_cdeg,float vn,float ve,float yaw_rate)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_RAMP_POSE_LEN];
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_float(buf, 12, vn);
    _mav_put_float(buf, 16, ve);
    _mav_put_float(buf, 20, yaw_rate);
    _mav_put_uint16_t(buf, 24, bearing_cdeg);
    _mav_put_uint8_t(buf, 26, target_system);
    _mav_put_uint8_t(buf, 27, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN);
#else
    mavlink_usv_ramp_pose_t packet;
    packet.time_boot_ms = time_boot_ms;
    packet.lat = lat;
    packet.lon = lon;
    packet.vn = vn;
    packet.ve = ve;
    packet.yaw_rate = yaw_rate;
    packet.bearing_cdeg = bearing_cdeg;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_RAMP_POSE;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_CRC);
}

/**
 * @brief Encode a usv_ramp_pose struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param usv_ramp_pose C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_ramp_pose_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_usv_ramp_pose_t* usv_ramp_pose)
{
    return mavlink_msg_usv_ramp_pose_pack(system_id, component_id, msg, usv_ramp_pose->target_system, usv_ramp_pose->target_component, usv_ramp_pose->time_boot_ms, usv_ramp_pose->lat, usv_ramp_pose->lon, usv_ramp_pose->bearing_cdeg, usv_ramp_pose->vn, usv_ramp_pose->ve, usv_ramp_pose->yaw_rate);
}

/**
 * @brief Encode a usv_ramp_pose struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param usv_ramp_pose C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_ramp_pose_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_usv_ramp_pose_t* usv_ramp_pose)
{
    return mavlink_msg_usv_ramp_pose_pack_chan(system_id, component_id, chan, msg, usv_ramp_pose->target_system, usv_ramp_pose->target_component, usv_ramp_pose->time_boot_ms, usv_ramp_pose->lat, usv_ramp_pose->lon, usv_ramp_pose->bearing_cdeg, usv_ramp_pose->vn, usv_ramp_pose->ve, usv_ramp_pose->yaw_rate);
}

/**
 * @brief Encode a usv_ramp_pose struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param usv_ramp_pose C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_ramp_pose_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_usv_ramp_pose_t* usv_ramp_pose)
{
    return mavlink_msg_usv_ramp_pose_pack_status(system_id, component_id, _status, msg,  usv_ramp_pose->target_system, usv_ramp_pose->target_component, usv_ramp_pose->time_boot_ms, usv_ramp_pose->lat, usv_ramp_pose->lon, usv_ramp_pose->bearing_cdeg, usv_ramp_pose->vn, usv_ramp_pose->ve, usv_ramp_pose->yaw_rate);
}

/**
 * @brief Send a usv_ramp_pose message
 * @param chan MAVLink channel to send the message
 *
 * @param target_system  System ID of the boat.
 * @param target_component  Component ID.
 * @param time_boot_ms [ms] Boat uptime the pose refers to (station clock mapped through TIMESYNC).
 * @param lat [degE7] Ramp end latitude.
 * @param lon [degE7] Ramp end longitude.
 * @param bearing_cdeg [cdeg] Compass bearing of the ramp frame's +x axis.
 * @param vn [m/s] Ramp end velocity north.
 * @param ve [m/s] Ramp end velocity east.
 * @param yaw_rate [rad/s] Mother ship yaw rate (clockwise positive).
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_usv_ramp_pose_send(mavlink_channel_t chan, uint8_t target_system, uint8_t target_component, uint32_t time_boot_ms, int32_t lat, int32_t lon, uint16_t bearing_cdeg, float vn, float ve, float yaw_rate)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_RAMP_POSE_LEN];
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_float(buf, 12, vn);
    _mav_put_float(buf, 16, ve);
    _mav_put_float(buf, 20, yaw_rate);
    _mav_put_uint16_t(buf, 24, bearing_cdeg);
    _mav_put_uint8_t(buf, 26, target_system);
    _mav_put_uint8_t(buf, 27, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_RAMP_POSE, buf, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_CRC);
#else
    mavlink_usv_ramp_pose_t packet;
    packet.time_boot_ms = time_boot_ms;
    packet.lat = lat;
    packet.lon = lon;
    packet.vn = vn;
    packet.ve = ve;
    packet.yaw_rate = yaw_rate;
    packet.bearing_cdeg = bearing_cdeg;
    packet.target_system = target_system;
    packet.target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_RAMP_POSE, (const char *)&packet, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_CRC);
#endif
}

/**
 * @brief Send a usv_ramp_pose message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_usv_ramp_pose_send_struct(mavlink_channel_t chan, const mavlink_usv_ramp_pose_t* usv_ramp_pose)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_usv_ramp_pose_send(chan, usv_ramp_pose->target_system, usv_ramp_pose->target_component, usv_ramp_pose->time_boot_ms, usv_ramp_pose->lat, usv_ramp_pose->lon, usv_ramp_pose->bearing_cdeg, usv_ramp_pose->vn, usv_ramp_pose->ve, usv_ramp_pose->yaw_rate);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_RAMP_POSE, (const char *)usv_ramp_pose, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_CRC);
#endif
}

#if MAVLINK_MSG_ID_USV_RAMP_POSE_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_usv_ramp_pose_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t target_system, uint8_t target_component, uint32_t time_boot_ms, int32_t lat, int32_t lon, uint16_t bearing_cdeg, float vn, float ve, float yaw_rate)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint32_t(buf, 0, time_boot_ms);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_float(buf, 12, vn);
    _mav_put_float(buf, 16, ve);
    _mav_put_float(buf, 20, yaw_rate);
    _mav_put_uint16_t(buf, 24, bearing_cdeg);
    _mav_put_uint8_t(buf, 26, target_system);
    _mav_put_uint8_t(buf, 27, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_RAMP_POSE, buf, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_CRC);
#else
    mavlink_usv_ramp_pose_t *packet = (mavlink_usv_ramp_pose_t *)msgbuf;
    packet->time_boot_ms = time_boot_ms;
    packet->lat = lat;
    packet->lon = lon;
    packet->vn = vn;
    packet->ve = ve;
    packet->yaw_rate = yaw_rate;
    packet->bearing_cdeg = bearing_cdeg;
    packet->target_system = target_system;
    packet->target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_RAMP_POSE, (const char *)packet, MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN, MAVLINK_MSG_ID_USV_RAMP_POSE_CRC);
#endif
}
#endif

#endif

// MESSAGE USV_RAMP_POSE UNPACKING


/**
 * @brief Get field target_system from usv_ramp_pose message
 *
 * @return  System ID of the boat.
 */
static inline uint8_t mavlink_msg_usv_ramp_pose_get_target_system(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  26);
}

/**
 * @brief Get field target_component from usv_ramp_pose message
 *
 * @return  Component ID.
 */
static inline uint8_t mavlink_msg_usv_ramp_pose_get_target_component(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  27);
}

/**
 * @brief Get field time_boot_ms from usv_ramp_pose message
 *
 * @return [ms] Boat uptime the pose refers to (station clock mapped through TIMESYNC).
 */
static inline uint32_t mavlink_msg_usv_ramp_pose_get_time_boot_ms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  0);
}

/**
 * @brief Get field lat from usv_ramp_pose message
 *
 * @return [degE7] Ramp end latitude.
 */
static inline int32_t mavlink_msg_usv_ramp_pose_get_lat(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int32_t(msg,  4);
}

/**
 * @brief Get field lon from usv_ramp_pose message
 *
 * @return [degE7] Ramp end longitude.
 */
static inline int32_t mavlink_msg_usv_ramp_pose_get_lon(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int32_t(msg,  8);
}

/**
 * @brief Get field bearing_cdeg from usv_ramp_pose message
 *
 * @return [cdeg] Compass bearing of the ramp frame's +x axis.
 */
static inline uint16_t mavlink_msg_usv_ramp_pose_get_bearing_cdeg(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  24);
}

/**
 * @brief Get field vn from usv_ramp_pose message
 *
 * @return [m/s] Ramp end velocity north.
 */
static inline float mavlink_msg_usv_ramp_pose_get_vn(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  12);
}

/**
 * @brief Get field ve from usv_ramp_pose message
 *
 * @return [m/s] Ramp end velocity east.
 */
static inline float mavlink_msg_usv_ramp_pose_get_ve(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  16);
}

/**
 * @brief Get field yaw_rate from usv_ramp_pose message
 *
 * @return [rad/s] Mother ship yaw rate (clockwise positive).
 */
static inline float mavlink_msg_usv_ramp_pose_get_yaw_rate(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  20);
}

/**
 * @brief Decode a usv_ramp_pose message into a struct
 *
 * @param msg The message to decode
 * @param usv_ramp_pose C-struct to decode the message contents into
 */
static inline void mavlink_msg_usv_ramp_pose_decode(const mavlink_message_t* msg, mavlink_usv_ramp_pose_t* usv_ramp_pose)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    usv_ramp_pose->time_boot_ms = mavlink_msg_usv_ramp_pose_get_time_boot_ms(msg);
    usv_ramp_pose->lat = mavlink_msg_usv_ramp_pose_get_lat(msg);
    usv_ramp_pose->lon = mavlink_msg_usv_ramp_pose_get_lon(msg);
    usv_ramp_pose->vn = mavlink_msg_usv_ramp_pose_get_vn(msg);
    usv_ramp_pose->ve = mavlink_msg_usv_ramp_pose_get_ve(msg);
    usv_ramp_pose->yaw_rate = mavlink_msg_usv_ramp_pose_get_yaw_rate(msg);
    usv_ramp_pose->bearing_cdeg = mavlink_msg_usv_ramp_pose_get_bearing_cdeg(msg);
    usv_ramp_pose->target_system = mavlink_msg_usv_ramp_pose_get_target_system(msg);
    usv_ramp_pose->target_component = mavlink_msg_usv_ramp_pose_get_target_component(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_USV_RAMP_POSE_LEN? msg->len : MAVLINK_MSG_ID_USV_RAMP_POSE_LEN;
        memset(usv_ramp_pose, 0, MAVLINK_MSG_ID_USV_RAMP_POSE_LEN);
    memcpy(usv_ramp_pose, _MAV_PAYLOAD(msg), len);
#endif
}
