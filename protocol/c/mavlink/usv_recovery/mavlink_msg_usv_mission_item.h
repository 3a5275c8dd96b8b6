#pragma once
// MESSAGE USV_MISSION_ITEM PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_USV_MISSION_ITEM 44001


typedef struct __mavlink_usv_mission_item_t {
 uint32_t mission_id; /*<  Mission id.*/
 int32_t lat; /*< [degE7] Latitude (WGS-84).*/
 int32_t lon; /*< [degE7] Longitude (WGS-84).*/
 uint32_t t_ms; /*< [ms] Time of arrival after the mission start (strictly increasing from 0).*/
 uint16_t seq; /*<  Item index, 0 .. count-1.*/
 uint16_t speed_cms; /*< [cm/s] Speed over ground at the waypoint (at most 3000).*/
 uint16_t course_cdeg; /*< [cdeg] Compass course over ground of the leg leaving the waypoint, 0..35999.*/
 uint16_t heading_cdeg; /*< [cdeg] Compass heading of the hull on that leg (crabbing into current), 0..35999.*/
 uint8_t target_system; /*<  System ID of the receiver.*/
 uint8_t target_component; /*<  Component ID.*/
} mavlink_usv_mission_item_t;

#define MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN 26
#define MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN 26
#define MAVLINK_MSG_ID_44001_LEN 26
#define MAVLINK_MSG_ID_44001_MIN_LEN 26

#define MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC 133
#define MAVLINK_MSG_ID_44001_CRC 133



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_USV_MISSION_ITEM { \
    44001, \
    "USV_MISSION_ITEM", \
    10, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 24, offsetof(mavlink_usv_mission_item_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 25, offsetof(mavlink_usv_mission_item_t, target_component) }, \
         { "mission_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_item_t, mission_id) }, \
         { "seq", NULL, MAVLINK_TYPE_UINT16_T, 0, 16, offsetof(mavlink_usv_mission_item_t, seq) }, \
         { "lat", NULL, MAVLINK_TYPE_INT32_T, 0, 4, offsetof(mavlink_usv_mission_item_t, lat) }, \
         { "lon", NULL, MAVLINK_TYPE_INT32_T, 0, 8, offsetof(mavlink_usv_mission_item_t, lon) }, \
         { "t_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 12, offsetof(mavlink_usv_mission_item_t, t_ms) }, \
         { "speed_cms", NULL, MAVLINK_TYPE_UINT16_T, 0, 18, offsetof(mavlink_usv_mission_item_t, speed_cms) }, \
         { "course_cdeg", NULL, MAVLINK_TYPE_UINT16_T, 0, 20, offsetof(mavlink_usv_mission_item_t, course_cdeg) }, \
         { "heading_cdeg", NULL, MAVLINK_TYPE_UINT16_T, 0, 22, offsetof(mavlink_usv_mission_item_t, heading_cdeg) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_USV_MISSION_ITEM { \
    "USV_MISSION_ITEM", \
    10, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 24, offsetof(mavlink_usv_mission_item_t, target_system) }, \
         { "target_component", NULL, MAVLINK_TYPE_UINT8_T, 0, 25, offsetof(mavlink_usv_mission_item_t, target_component) }, \
         { "mission_id", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_usv_mission_item_t, mission_id) }, \
         { "seq", NULL, MAVLINK_TYPE_UINT16_T, 0, 16, offsetof(mavlink_usv_mission_item_t, seq) }, \
         { "lat", NULL, MAVLINK_TYPE_INT32_T, 0, 4, offsetof(mavlink_usv_mission_item_t, lat) }, \
         { "lon", NULL, MAVLINK_TYPE_INT32_T, 0, 8, offsetof(mavlink_usv_mission_item_t, lon) }, \
         { "t_ms", NULL, MAVLINK_TYPE_UINT32_T, 0, 12, offsetof(mavlink_usv_mission_item_t, t_ms) }, \
         { "speed_cms", NULL, MAVLINK_TYPE_UINT16_T, 0, 18, offsetof(mavlink_usv_mission_item_t, speed_cms) }, \
         { "course_cdeg", NULL, MAVLINK_TYPE_UINT16_T, 0, 20, offsetof(mavlink_usv_mission_item_t, course_cdeg) }, \
         { "heading_cdeg", NULL, MAVLINK_TYPE_UINT16_T, 0, 22, offsetof(mavlink_usv_mission_item_t, heading_cdeg) }, \
         } \
}
#endif

/**
 * @brief Pack a usv_mission_item message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the receiver.
 * @param target_component  Component ID.
 * @param mission_id  Mission id.
 * @param seq  Item index, 0 .. count-1.
 * @param lat [degE7] Latitude (WGS-84).
 * @param lon [degE7] Longitude (WGS-84).
 * @param t_ms [ms] Time of arrival after the mission start (strictly increasing from 0).
 * @param speed_cms [cm/s] Speed over ground at the waypoint (at most 3000).
 * @param course_cdeg [cdeg] Compass course over ground of the leg leaving the waypoint, 0..35999.
 * @param heading_cdeg [cdeg] Compass heading of the hull on that leg (crabbing into current), 0..35999.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_item_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint16_t seq, int32_t lat, int32_t lon, uint32_t t_ms, uint16_t speed_cms, uint16_t course_cdeg, uint16_t heading_cdeg)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_uint32_t(buf, 12, t_ms);
    _mav_put_uint16_t(buf, 16, seq);
    _mav_put_uint16_t(buf, 18, speed_cms);
    _mav_put_uint16_t(buf, 20, course_cdeg);
    _mav_put_uint16_t(buf, 22, heading_cdeg);
    _mav_put_uint8_t(buf, 24, target_system);
    _mav_put_uint8_t(buf, 25, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN);
#else
    mavlink_usv_mission_item_t packet;
    packet.mission_id = mission_id;
    packet.lat = lat;
    packet.lon = lon;
    packet.t_ms = t_ms;
    packet.seq = seq;
    packet.speed_cms = speed_cms;
    packet.course_cdeg = course_cdeg;
    packet.heading_cdeg = heading_cdeg;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_ITEM;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC);
}

/**
 * @brief Pack a usv_mission_item message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  System ID of the receiver.
 * @param target_component  Component ID.
 * @param mission_id  Mission id.
 * @param seq  Item index, 0 .. count-1.
 * @param lat [degE7] Latitude (WGS-84).
 * @param lon [degE7] Longitude (WGS-84).
 * @param t_ms [ms] Time of arrival after the mission start (strictly increasing from 0).
 * @param speed_cms [cm/s] Speed over ground at the waypoint (at most 3000).
 * @param course_cdeg [cdeg] Compass course over ground of the leg leaving the waypoint, 0..35999.
 * @param heading_cdeg [cdeg] Compass heading of the hull on that leg (crabbing into current), 0..35999.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_item_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint16_t seq, int32_t lat, int32_t lon, uint32_t t_ms, uint16_t speed_cms, uint16_t course_cdeg, uint16_t heading_cdeg)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_uint32_t(buf, 12, t_ms);
    _mav_put_uint16_t(buf, 16, seq);
    _mav_put_uint16_t(buf, 18, speed_cms);
    _mav_put_uint16_t(buf, 20, course_cdeg);
    _mav_put_uint16_t(buf, 22, heading_cdeg);
    _mav_put_uint8_t(buf, 24, target_system);
    _mav_put_uint8_t(buf, 25, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN);
#else
    mavlink_usv_mission_item_t packet;
    packet.mission_id = mission_id;
    packet.lat = lat;
    packet.lon = lon;
    packet.t_ms = t_ms;
    packet.seq = seq;
    packet.speed_cms = speed_cms;
    packet.course_cdeg = course_cdeg;
    packet.heading_cdeg = heading_cdeg;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_ITEM;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN);
#endif
}

/**
 * @brief Pack a usv_mission_item message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param target_system  System ID of the receiver.
 * @param target_component  Component ID.
 * @param mission_id  Mission id.
 * @param seq  Item index, 0 .. count-1.
 * @param lat [degE7] Latitude (WGS-84).
 * @param lon [degE7] Longitude (WGS-84).
 * @param t_ms [ms] Time of arrival after the mission start (strictly increasing from 0).
 * @param speed_cms [cm/s] Speed over ground at the waypoint (at most 3000).
 * @param course_cdeg [cdeg] Compass course over ground of the leg leaving the waypoint, 0..35999.
 * @param heading_cdeg [cdeg] Compass heading of the hull on that leg (crabbing into current), 0..35999.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_usv_mission_item_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t target_system,uint8_t target_component,uint32_t mission_id,uint16_t seq,int32_t lat,int32_t lon,uint32_t t_ms,uint16_t speed_cms,uint16_t course_cdeg,uint16_t heading_cdeg)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_uint32_t(buf, 12, t_ms);
    _mav_put_uint16_t(buf, 16, seq);
    _mav_put_uint16_t(buf, 18, speed_cms);
    _mav_put_uint16_t(buf, 20, course_cdeg);
    _mav_put_uint16_t(buf, 22, heading_cdeg);
    _mav_put_uint8_t(buf, 24, target_system);
    _mav_put_uint8_t(buf, 25, target_component);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN);
#else
    mavlink_usv_mission_item_t packet;
    packet.mission_id = mission_id;
    packet.lat = lat;
    packet.lon = lon;
    packet.t_ms = t_ms;
    packet.seq = seq;
    packet.speed_cms = speed_cms;
    packet.course_cdeg = course_cdeg;
    packet.heading_cdeg = heading_cdeg;
    packet.target_system = target_system;
    packet.target_component = target_component;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_USV_MISSION_ITEM;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC);
}

/**
 * @brief Encode a usv_mission_item struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_item C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_item_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_usv_mission_item_t* usv_mission_item)
{
    return mavlink_msg_usv_mission_item_pack(system_id, component_id, msg, usv_mission_item->target_system, usv_mission_item->target_component, usv_mission_item->mission_id, usv_mission_item->seq, usv_mission_item->lat, usv_mission_item->lon, usv_mission_item->t_ms, usv_mission_item->speed_cms, usv_mission_item->course_cdeg, usv_mission_item->heading_cdeg);
}

/**
 * @brief Encode a usv_mission_item struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_item C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_item_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_usv_mission_item_t* usv_mission_item)
{
    return mavlink_msg_usv_mission_item_pack_chan(system_id, component_id, chan, msg, usv_mission_item->target_system, usv_mission_item->target_component, usv_mission_item->mission_id, usv_mission_item->seq, usv_mission_item->lat, usv_mission_item->lon, usv_mission_item->t_ms, usv_mission_item->speed_cms, usv_mission_item->course_cdeg, usv_mission_item->heading_cdeg);
}

/**
 * @brief Encode a usv_mission_item struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param usv_mission_item C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_usv_mission_item_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_usv_mission_item_t* usv_mission_item)
{
    return mavlink_msg_usv_mission_item_pack_status(system_id, component_id, _status, msg,  usv_mission_item->target_system, usv_mission_item->target_component, usv_mission_item->mission_id, usv_mission_item->seq, usv_mission_item->lat, usv_mission_item->lon, usv_mission_item->t_ms, usv_mission_item->speed_cms, usv_mission_item->course_cdeg, usv_mission_item->heading_cdeg);
}

/**
 * @brief Send a usv_mission_item message
 * @param chan MAVLink channel to send the message
 *
 * @param target_system  System ID of the receiver.
 * @param target_component  Component ID.
 * @param mission_id  Mission id.
 * @param seq  Item index, 0 .. count-1.
 * @param lat [degE7] Latitude (WGS-84).
 * @param lon [degE7] Longitude (WGS-84).
 * @param t_ms [ms] Time of arrival after the mission start (strictly increasing from 0).
 * @param speed_cms [cm/s] Speed over ground at the waypoint (at most 3000).
 * @param course_cdeg [cdeg] Compass course over ground of the leg leaving the waypoint, 0..35999.
 * @param heading_cdeg [cdeg] Compass heading of the hull on that leg (crabbing into current), 0..35999.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_usv_mission_item_send(mavlink_channel_t chan, uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint16_t seq, int32_t lat, int32_t lon, uint32_t t_ms, uint16_t speed_cms, uint16_t course_cdeg, uint16_t heading_cdeg)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN];
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_uint32_t(buf, 12, t_ms);
    _mav_put_uint16_t(buf, 16, seq);
    _mav_put_uint16_t(buf, 18, speed_cms);
    _mav_put_uint16_t(buf, 20, course_cdeg);
    _mav_put_uint16_t(buf, 22, heading_cdeg);
    _mav_put_uint8_t(buf, 24, target_system);
    _mav_put_uint8_t(buf, 25, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ITEM, buf, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC);
#else
    mavlink_usv_mission_item_t packet;
    packet.mission_id = mission_id;
    packet.lat = lat;
    packet.lon = lon;
    packet.t_ms = t_ms;
    packet.seq = seq;
    packet.speed_cms = speed_cms;
    packet.course_cdeg = course_cdeg;
    packet.heading_cdeg = heading_cdeg;
    packet.target_system = target_system;
    packet.target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ITEM, (const char *)&packet, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC);
#endif
}

/**
 * @brief Send a usv_mission_item message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_usv_mission_item_send_struct(mavlink_channel_t chan, const mavlink_usv_mission_item_t* usv_mission_item)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_usv_mission_item_send(chan, usv_mission_item->target_system, usv_mission_item->target_component, usv_mission_item->mission_id, usv_mission_item->seq, usv_mission_item->lat, usv_mission_item->lon, usv_mission_item->t_ms, usv_mission_item->speed_cms, usv_mission_item->course_cdeg, usv_mission_item->heading_cdeg);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ITEM, (const char *)usv_mission_item, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC);
#endif
}

#if MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_usv_mission_item_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t target_system, uint8_t target_component, uint32_t mission_id, uint16_t seq, int32_t lat, int32_t lon, uint32_t t_ms, uint16_t speed_cms, uint16_t course_cdeg, uint16_t heading_cdeg)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint32_t(buf, 0, mission_id);
    _mav_put_int32_t(buf, 4, lat);
    _mav_put_int32_t(buf, 8, lon);
    _mav_put_uint32_t(buf, 12, t_ms);
    _mav_put_uint16_t(buf, 16, seq);
    _mav_put_uint16_t(buf, 18, speed_cms);
    _mav_put_uint16_t(buf, 20, course_cdeg);
    _mav_put_uint16_t(buf, 22, heading_cdeg);
    _mav_put_uint8_t(buf, 24, target_system);
    _mav_put_uint8_t(buf, 25, target_component);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ITEM, buf, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC);
#else
    mavlink_usv_mission_item_t *packet = (mavlink_usv_mission_item_t *)msgbuf;
    packet->mission_id = mission_id;
    packet->lat = lat;
    packet->lon = lon;
    packet->t_ms = t_ms;
    packet->seq = seq;
    packet->speed_cms = speed_cms;
    packet->course_cdeg = course_cdeg;
    packet->heading_cdeg = heading_cdeg;
    packet->target_system = target_system;
    packet->target_component = target_component;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_USV_MISSION_ITEM, (const char *)packet, MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN, MAVLINK_MSG_ID_USV_MISSION_ITEM_CRC);
#endif
}
#endif

#endif

// MESSAGE USV_MISSION_ITEM UNPACKING


/**
 * @brief Get field target_system from usv_mission_item message
 *
 * @return  System ID of the receiver.
 */
static inline uint8_t mavlink_msg_usv_mission_item_get_target_system(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  24);
}

/**
 * @brief Get field target_component from usv_mission_item message
 *
 * @return  Component ID.
 */
static inline uint8_t mavlink_msg_usv_mission_item_get_target_component(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  25);
}

/**
 * @brief Get field mission_id from usv_mission_item message
 *
 * @return  Mission id.
 */
static inline uint32_t mavlink_msg_usv_mission_item_get_mission_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  0);
}

/**
 * @brief Get field seq from usv_mission_item message
 *
 * @return  Item index, 0 .. count-1.
 */
static inline uint16_t mavlink_msg_usv_mission_item_get_seq(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  16);
}

/**
 * @brief Get field lat from usv_mission_item message
 *
 * @return [degE7] Latitude (WGS-84).
 */
static inline int32_t mavlink_msg_usv_mission_item_get_lat(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int32_t(msg,  4);
}

/**
 * @brief Get field lon from usv_mission_item message
 *
 * @return [degE7] Longitude (WGS-84).
 */
static inline int32_t mavlink_msg_usv_mission_item_get_lon(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int32_t(msg,  8);
}

/**
 * @brief Get field t_ms from usv_mission_item message
 *
 * @return [ms] Time of arrival after the mission start (strictly increasing from 0).
 */
static inline uint32_t mavlink_msg_usv_mission_item_get_t_ms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  12);
}

/**
 * @brief Get field speed_cms from usv_mission_item message
 *
 * @return [cm/s] Speed over ground at the waypoint (at most 3000).
 */
static inline uint16_t mavlink_msg_usv_mission_item_get_speed_cms(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  18);
}

/**
 * @brief Get field course_cdeg from usv_mission_item message
 *
 * @return [cdeg] Compass course over ground of the leg leaving the waypoint, 0..35999.
 */
static inline uint16_t mavlink_msg_usv_mission_item_get_course_cdeg(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  20);
}

/**
 * @brief Get field heading_cdeg from usv_mission_item message
 *
 * @return [cdeg] Compass heading of the hull on that leg (crabbing into current), 0..35999.
 */
static inline uint16_t mavlink_msg_usv_mission_item_get_heading_cdeg(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  22);
}

/**
 * @brief Decode a usv_mission_item message into a struct
 *
 * @param msg The message to decode
 * @param usv_mission_item C-struct to decode the message contents into
 */
static inline void mavlink_msg_usv_mission_item_decode(const mavlink_message_t* msg, mavlink_usv_mission_item_t* usv_mission_item)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    usv_mission_item->mission_id = mavlink_msg_usv_mission_item_get_mission_id(msg);
    usv_mission_item->lat = mavlink_msg_usv_mission_item_get_lat(msg);
    usv_mission_item->lon = mavlink_msg_usv_mission_item_get_lon(msg);
    usv_mission_item->t_ms = mavlink_msg_usv_mission_item_get_t_ms(msg);
    usv_mission_item->seq = mavlink_msg_usv_mission_item_get_seq(msg);
    usv_mission_item->speed_cms = mavlink_msg_usv_mission_item_get_speed_cms(msg);
    usv_mission_item->course_cdeg = mavlink_msg_usv_mission_item_get_course_cdeg(msg);
    usv_mission_item->heading_cdeg = mavlink_msg_usv_mission_item_get_heading_cdeg(msg);
    usv_mission_item->target_system = mavlink_msg_usv_mission_item_get_target_system(msg);
    usv_mission_item->target_component = mavlink_msg_usv_mission_item_get_target_component(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN? msg->len : MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN;
        memset(usv_mission_item, 0, MAVLINK_MSG_ID_USV_MISSION_ITEM_LEN);
    memcpy(usv_mission_item, _MAV_PAYLOAD(msg), len);
#endif
}
