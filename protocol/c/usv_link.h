/* usv-link framing for the boat firmware: CRCs, COBS, frame encoder and a streaming
 * parser fed one byte at a time. C99, no malloc, fixed buffers, only stdint/stddef/string.
 * Specification: protocol/README.md. Messages: usv_messages.h (generated). */
#ifndef USV_LINK_H
#define USV_LINK_H

#include <stddef.h>
#include <stdint.h>

#include "usv_messages.h"

/* CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF): start with crc = 0xFFFF. */
uint16_t usv_crc16_update(uint16_t crc, const uint8_t *data, size_t len);
/* CRC-32 (IEEE 802.3, as zlib): start with crc = 0, pass the previous result to continue. */
uint32_t usv_crc32_update(uint32_t crc, const uint8_t *data, size_t len);

/* COBS-encode len bytes (len < 254) into out (len + 1 bytes); returns the encoded length. */
size_t usv_cobs_encode(const uint8_t *in, size_t len, uint8_t *out);
/* COBS-decode in place; returns the decoded length, or -1 if invalid. */
int usv_cobs_decode(uint8_t *buf, size_t len);

/* Write the wire bytes (0x00, COBS(body), 0x00) of one frame into out, which has room
 * for cap bytes (USV_MAX_WIRE always suffices). Returns the number of bytes, 0 on error. */
size_t usv_frame_encode(uint8_t version, uint8_t msg_id, uint8_t seq,
                        const uint8_t *payload, size_t payload_len, uint8_t *out, size_t cap);

/* Pack a message and frame it with the local protocol version. Returns bytes written. */
size_t usv_message_encode(uint8_t msg_id, uint8_t seq, const usv_message_t *msg,
                          uint8_t *out, size_t cap);

typedef struct {
    uint8_t version;
    uint8_t msg_id;
    uint8_t seq;
    uint8_t payload_len;
    uint8_t payload[USV_MAX_PAYLOAD];
} usv_frame_t;

typedef struct {
    uint32_t frames;      /* valid frames delivered */
    uint32_t bad_cobs;
    uint32_t bad_crc;     /* too short or CRC mismatch */
    uint32_t bad_length;  /* payload length wrong for the message id */
    uint32_t bad_version; /* another protocol version (except its HEARTBEAT) */
    uint32_t unknown_id;
    uint32_t oversize;    /* more than USV_MAX_ENCODED bytes between delimiters */
} usv_parser_stats_t;

typedef struct {
    uint8_t buf[USV_MAX_ENCODED];
    size_t len;
    uint8_t overflow;
    usv_parser_stats_t stats;
} usv_parser_t;

void usv_parser_init(usv_parser_t *p);

/* Feed one received byte. Returns 1 when it completed a valid frame, copied into *out;
 * 0 otherwise. Frames of another protocol version are delivered only for HEARTBEAT with
 * at least its 5 frozen bytes (check out->version before unpacking anything else). */
int usv_parser_feed(usv_parser_t *p, uint8_t byte, usv_frame_t *out);

#endif /* USV_LINK_H */
