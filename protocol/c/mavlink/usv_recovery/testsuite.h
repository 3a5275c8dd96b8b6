/** @file
 *    @brief MAVLink comm protocol testsuite generated from usv_recovery.xml
 *    @see https://mavlink.io/en/
 */
#pragma once
#ifndef USV_RECOVERY_TESTSUITE_H
#define USV_RECOVERY_TESTSUITE_H

#ifdef __cplusplus
extern "C" {
#endif

#ifndef MAVLINK_TEST_ALL
#define MAVLINK_TEST_ALL
static void mavlink_test_common(uint8_t, uint8_t, mavlink_message_t *last_msg);
static void mavlink_test_usv_recovery(uint8_t, uint8_t, mavlink_message_t *last_msg);

static void mavlink_test_all(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
    mavlink_test_common(system_id, component_id, last_msg);
    mavlink_test_usv_recovery(system_id, component_id, last_msg);
}
#endif

#include "../common/testsuite.h"


static void mavlink_test_usv_mission_begin(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_MISSION_BEGIN >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_mission_begin_t packet_in = {
        963497464,963497672,963497880,17859,175,242
    };
    mavlink_usv_mission_begin_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.mission_id = packet_in.mission_id;
        packet1.crc32 = packet_in.crc32;
        packet1.swap_at_ms = packet_in.swap_at_ms;
        packet1.count = packet_in.count;
        packet1.target_system = packet_in.target_system;
        packet1.target_component = packet_in.target_component;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_MISSION_BEGIN_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_begin_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_mission_begin_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_begin_pack(system_id, component_id, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.crc32 , packet1.count , packet1.swap_at_ms );
    mavlink_msg_usv_mission_begin_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_begin_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.crc32 , packet1.count , packet1.swap_at_ms );
    mavlink_msg_usv_mission_begin_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_mission_begin_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_begin_send(MAVLINK_COMM_1 , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.crc32 , packet1.count , packet1.swap_at_ms );
    mavlink_msg_usv_mission_begin_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_MISSION_BEGIN") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_MISSION_BEGIN) != NULL);
#endif
}

static void mavlink_test_usv_mission_item(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_MISSION_ITEM >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_mission_item_t packet_in = {
        963497464,963497672,963497880,963498088,18067,18171,18275,18379,77,144
    };
    mavlink_usv_mission_item_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.mission_id = packet_in.mission_id;
        packet1.lat = packet_in.lat;
        packet1.lon = packet_in.lon;
        packet1.t_ms = packet_in.t_ms;
        packet1.seq = packet_in.seq;
        packet1.speed_cms = packet_in.speed_cms;
        packet1.course_cdeg = packet_in.course_cdeg;
        packet1.heading_cdeg = packet_in.heading_cdeg;
        packet1.target_system = packet_in.target_system;
        packet1.target_component = packet_in.target_component;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_MISSION_ITEM_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_item_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_mission_item_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_item_pack(system_id, component_id, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq , packet1.lat , packet1.lon , packet1.t_ms , packet1.speed_cms , packet1.course_cdeg , packet1.heading_cdeg );
    mavlink_msg_usv_mission_item_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_item_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq , packet1.lat , packet1.lon , packet1.t_ms , packet1.speed_cms , packet1.course_cdeg , packet1.heading_cdeg );
    mavlink_msg_usv_mission_item_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_mission_item_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_item_send(MAVLINK_COMM_1 , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq , packet1.lat , packet1.lon , packet1.t_ms , packet1.speed_cms , packet1.course_cdeg , packet1.heading_cdeg );
    mavlink_msg_usv_mission_item_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_MISSION_ITEM") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_MISSION_ITEM) != NULL);
#endif
}

static void mavlink_test_usv_mission_ack(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_MISSION_ACK >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_mission_ack_t packet_in = {
        963497464,17443,151,218,29,96
    };
    mavlink_usv_mission_ack_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.mission_id = packet_in.mission_id;
        packet1.seq = packet_in.seq;
        packet1.target_system = packet_in.target_system;
        packet1.target_component = packet_in.target_component;
        packet1.result = packet_in.result;
        packet1.stage = packet_in.stage;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_MISSION_ACK_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_ack_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_mission_ack_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_ack_pack(system_id, component_id, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq , packet1.result , packet1.stage );
    mavlink_msg_usv_mission_ack_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_ack_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq , packet1.result , packet1.stage );
    mavlink_msg_usv_mission_ack_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_mission_ack_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_ack_send(MAVLINK_COMM_1 , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq , packet1.result , packet1.stage );
    mavlink_msg_usv_mission_ack_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_MISSION_ACK") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_MISSION_ACK) != NULL);
#endif
}

static void mavlink_test_usv_mission_end(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_MISSION_END >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_mission_end_t packet_in = {
        963497464,963497672,17651,163,230
    };
    mavlink_usv_mission_end_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.mission_id = packet_in.mission_id;
        packet1.crc32 = packet_in.crc32;
        packet1.count = packet_in.count;
        packet1.target_system = packet_in.target_system;
        packet1.target_component = packet_in.target_component;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_MISSION_END_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_end_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_mission_end_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_end_pack(system_id, component_id, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.crc32 , packet1.count );
    mavlink_msg_usv_mission_end_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_end_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.crc32 , packet1.count );
    mavlink_msg_usv_mission_end_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_mission_end_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_end_send(MAVLINK_COMM_1 , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.crc32 , packet1.count );
    mavlink_msg_usv_mission_end_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_MISSION_END") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_MISSION_END) != NULL);
#endif
}

static void mavlink_test_usv_mission_state(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_MISSION_STATE >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_mission_state_t packet_in = {
        963497464,963497672,963497880,963498088,963498296,963498504,963498712,963498920,18899,19003,19107,19211,19315,3,70,137
    };
    mavlink_usv_mission_state_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.uptime_ms = packet_in.uptime_ms;
        packet1.boot_id = packet_in.boot_id;
        packet1.active_id = packet_in.active_id;
        packet1.active_crc32 = packet_in.active_crc32;
        packet1.staged_id = packet_in.staged_id;
        packet1.staged_crc32 = packet_in.staged_crc32;
        packet1.swap_at_ms = packet_in.swap_at_ms;
        packet1.station_session = packet_in.station_session;
        packet1.active_count = packet_in.active_count;
        packet1.current_seq = packet_in.current_seq;
        packet1.staged_received = packet_in.staged_received;
        packet1.staged_count = packet_in.staged_count;
        packet1.rejected = packet_in.rejected;
        packet1.state = packet_in.state;
        packet1.staging = packet_in.staging;
        packet1.flags = packet_in.flags;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_MISSION_STATE_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_state_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_mission_state_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_state_pack(system_id, component_id, &msg , packet1.uptime_ms , packet1.boot_id , packet1.state , packet1.active_id , packet1.active_crc32 , packet1.active_count , packet1.current_seq , packet1.staging , packet1.staged_id , packet1.staged_crc32 , packet1.staged_received , packet1.staged_count , packet1.swap_at_ms , packet1.station_session , packet1.rejected , packet1.flags );
    mavlink_msg_usv_mission_state_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_state_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.uptime_ms , packet1.boot_id , packet1.state , packet1.active_id , packet1.active_crc32 , packet1.active_count , packet1.current_seq , packet1.staging , packet1.staged_id , packet1.staged_crc32 , packet1.staged_received , packet1.staged_count , packet1.swap_at_ms , packet1.station_session , packet1.rejected , packet1.flags );
    mavlink_msg_usv_mission_state_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_mission_state_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_state_send(MAVLINK_COMM_1 , packet1.uptime_ms , packet1.boot_id , packet1.state , packet1.active_id , packet1.active_crc32 , packet1.active_count , packet1.current_seq , packet1.staging , packet1.staged_id , packet1.staged_crc32 , packet1.staged_received , packet1.staged_count , packet1.swap_at_ms , packet1.station_session , packet1.rejected , packet1.flags );
    mavlink_msg_usv_mission_state_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_MISSION_STATE") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_MISSION_STATE) != NULL);
#endif
}

static void mavlink_test_usv_mission_read(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_MISSION_READ >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_mission_read_t packet_in = {
        963497464,17443,151,218
    };
    mavlink_usv_mission_read_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.mission_id = packet_in.mission_id;
        packet1.seq = packet_in.seq;
        packet1.target_system = packet_in.target_system;
        packet1.target_component = packet_in.target_component;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_MISSION_READ_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_MISSION_READ_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_read_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_mission_read_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_read_pack(system_id, component_id, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq );
    mavlink_msg_usv_mission_read_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_read_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq );
    mavlink_msg_usv_mission_read_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_mission_read_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_mission_read_send(MAVLINK_COMM_1 , packet1.target_system , packet1.target_component , packet1.mission_id , packet1.seq );
    mavlink_msg_usv_mission_read_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_MISSION_READ") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_MISSION_READ) != NULL);
#endif
}

static void mavlink_test_usv_ramp_pose(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_RAMP_POSE >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_ramp_pose_t packet_in = {
        963497464,963497672,963497880,101.0,129.0,157.0,18483,211,22
    };
    mavlink_usv_ramp_pose_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.time_boot_ms = packet_in.time_boot_ms;
        packet1.lat = packet_in.lat;
        packet1.lon = packet_in.lon;
        packet1.vn = packet_in.vn;
        packet1.ve = packet_in.ve;
        packet1.yaw_rate = packet_in.yaw_rate;
        packet1.bearing_cdeg = packet_in.bearing_cdeg;
        packet1.target_system = packet_in.target_system;
        packet1.target_component = packet_in.target_component;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_RAMP_POSE_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_ramp_pose_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_ramp_pose_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_ramp_pose_pack(system_id, component_id, &msg , packet1.target_system , packet1.target_component , packet1.time_boot_ms , packet1.lat , packet1.lon , packet1.bearing_cdeg , packet1.vn , packet1.ve , packet1.yaw_rate );
    mavlink_msg_usv_ramp_pose_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_ramp_pose_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.target_system , packet1.target_component , packet1.time_boot_ms , packet1.lat , packet1.lon , packet1.bearing_cdeg , packet1.vn , packet1.ve , packet1.yaw_rate );
    mavlink_msg_usv_ramp_pose_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_ramp_pose_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_ramp_pose_send(MAVLINK_COMM_1 , packet1.target_system , packet1.target_component , packet1.time_boot_ms , packet1.lat , packet1.lon , packet1.bearing_cdeg , packet1.vn , packet1.ve , packet1.yaw_rate );
    mavlink_msg_usv_ramp_pose_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_RAMP_POSE") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_RAMP_POSE) != NULL);
#endif
}

static void mavlink_test_usv_guidance(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_GUIDANCE >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_guidance_t packet_in = {
        17235,17339,17443,151,218
    };
    mavlink_usv_guidance_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.heading_cdeg = packet_in.heading_cdeg;
        packet1.speed_cms = packet_in.speed_cms;
        packet1.valid_ms = packet_in.valid_ms;
        packet1.target_system = packet_in.target_system;
        packet1.target_component = packet_in.target_component;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_GUIDANCE_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_guidance_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_guidance_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_guidance_pack(system_id, component_id, &msg , packet1.target_system , packet1.target_component , packet1.heading_cdeg , packet1.speed_cms , packet1.valid_ms );
    mavlink_msg_usv_guidance_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_guidance_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.target_system , packet1.target_component , packet1.heading_cdeg , packet1.speed_cms , packet1.valid_ms );
    mavlink_msg_usv_guidance_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_guidance_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_guidance_send(MAVLINK_COMM_1 , packet1.target_system , packet1.target_component , packet1.heading_cdeg , packet1.speed_cms , packet1.valid_ms );
    mavlink_msg_usv_guidance_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_GUIDANCE") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_GUIDANCE) != NULL);
#endif
}

static void mavlink_test_usv_thrust(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
    mavlink_status_t *status = mavlink_get_channel_status(MAVLINK_COMM_0);
        if ((status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) && MAVLINK_MSG_ID_USV_THRUST >= 256) {
            return;
        }
#endif
    mavlink_message_t msg;
        uint8_t buffer[MAVLINK_MAX_PACKET_LEN];
        uint16_t i;
    mavlink_usv_thrust_t packet_in = {
        963497464,45.0,73.0,17859,17963
    };
    mavlink_usv_thrust_t packet1, packet2;
        memset(&packet1, 0, sizeof(packet1));
        packet1.time_boot_ms = packet_in.time_boot_ms;
        packet1.cross_track = packet_in.cross_track;
        packet1.slip = packet_in.slip;
        packet1.left_pm = packet_in.left_pm;
        packet1.right_pm = packet_in.right_pm;
        
        
#ifdef MAVLINK_STATUS_FLAG_OUT_MAVLINK1
        if (status->flags & MAVLINK_STATUS_FLAG_OUT_MAVLINK1) {
           // cope with extensions
           memset(MAVLINK_MSG_ID_USV_THRUST_MIN_LEN + (char *)&packet1, 0, sizeof(packet1)-MAVLINK_MSG_ID_USV_THRUST_MIN_LEN);
        }
#endif
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_thrust_encode(system_id, component_id, &msg, &packet1);
    mavlink_msg_usv_thrust_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_thrust_pack(system_id, component_id, &msg , packet1.time_boot_ms , packet1.left_pm , packet1.right_pm , packet1.cross_track , packet1.slip );
    mavlink_msg_usv_thrust_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_thrust_pack_chan(system_id, component_id, MAVLINK_COMM_0, &msg , packet1.time_boot_ms , packet1.left_pm , packet1.right_pm , packet1.cross_track , packet1.slip );
    mavlink_msg_usv_thrust_decode(&msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

        memset(&packet2, 0, sizeof(packet2));
        mavlink_msg_to_send_buffer(buffer, &msg);
        for (i=0; i<mavlink_msg_get_send_buffer_length(&msg); i++) {
            comm_send_ch(MAVLINK_COMM_0, buffer[i]);
        }
    mavlink_msg_usv_thrust_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);
        
        memset(&packet2, 0, sizeof(packet2));
    mavlink_msg_usv_thrust_send(MAVLINK_COMM_1 , packet1.time_boot_ms , packet1.left_pm , packet1.right_pm , packet1.cross_track , packet1.slip );
    mavlink_msg_usv_thrust_decode(last_msg, &packet2);
        MAVLINK_ASSERT(memcmp(&packet1, &packet2, sizeof(packet1)) == 0);

#ifdef MAVLINK_HAVE_GET_MESSAGE_INFO
    MAVLINK_ASSERT(mavlink_get_message_info_by_name("USV_THRUST") != NULL);
    MAVLINK_ASSERT(mavlink_get_message_info_by_id(MAVLINK_MSG_ID_USV_THRUST) != NULL);
#endif
}

static void mavlink_test_usv_recovery(uint8_t system_id, uint8_t component_id, mavlink_message_t *last_msg)
{
    mavlink_test_usv_mission_begin(system_id, component_id, last_msg);
    mavlink_test_usv_mission_item(system_id, component_id, last_msg);
    mavlink_test_usv_mission_ack(system_id, component_id, last_msg);
    mavlink_test_usv_mission_end(system_id, component_id, last_msg);
    mavlink_test_usv_mission_state(system_id, component_id, last_msg);
    mavlink_test_usv_mission_read(system_id, component_id, last_msg);
    mavlink_test_usv_ramp_pose(system_id, component_id, last_msg);
    mavlink_test_usv_guidance(system_id, component_id, last_msg);
    mavlink_test_usv_thrust(system_id, component_id, last_msg);
}

#ifdef __cplusplus
}
#endif // __cplusplus
#endif // USV_RECOVERY_TESTSUITE_H
