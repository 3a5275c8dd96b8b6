/* usv-link framing: see usv_link.h and protocol/README.md. */
#include "usv_link.h"

#include <string.h>

uint16_t usv_crc16_update(uint16_t crc, const uint8_t *data, size_t len)
{
    size_t i;
    int bit;
    for (i = 0; i < len; i++) {
        crc ^= (uint16_t)((uint16_t)data[i] << 8);
        for (bit = 0; bit < 8; bit++) {
            crc = (crc & 0x8000u) ? (uint16_t)((crc << 1) ^ 0x1021u) : (uint16_t)(crc << 1);
        }
    }
    return crc;
}

uint32_t usv_crc32_update(uint32_t crc, const uint8_t *data, size_t len)
{
    size_t i;
    int bit;
    crc = ~crc;
    for (i = 0; i < len; i++) {
        crc ^= data[i];
        for (bit = 0; bit < 8; bit++) {
            crc = (crc & 1u) ? (crc >> 1) ^ 0xEDB88320UL : crc >> 1;
        }
    }
    return ~crc & 0xFFFFFFFFUL;
}

size_t usv_cobs_encode(const uint8_t *in, size_t len, uint8_t *out)
{
    size_t code_pos = 0, o = 1, i;
    uint8_t code = 1;
    for (i = 0; i < len; i++) {
        if (in[i] == 0) {
            out[code_pos] = code;
            code_pos = o++;
            code = 1;
        } else {
            out[o++] = in[i];
            code++;
        }
    }
    out[code_pos] = code;
    return o;
}

int usv_cobs_decode(uint8_t *buf, size_t len)
{
    size_t i = 0, o = 0, k;
    while (i < len) {
        uint8_t code = buf[i];
        if (code == 0 || i + code > len) {
            return -1;
        }
        for (k = 1; k < code; k++) {
            buf[o++] = buf[i + k];
        }
        i += code;
        if (code != 0xFFu && i < len) {
            buf[o++] = 0;
        }
    }
    return (int)o;
}

size_t usv_frame_encode(uint8_t version, uint8_t msg_id, uint8_t seq,
                        const uint8_t *payload, size_t payload_len, uint8_t *out, size_t cap)
{
    uint8_t body[USV_MAX_BODY];
    size_t n, enc;
    uint16_t crc;
    if (payload_len > USV_MAX_PAYLOAD || cap < USV_HEADER_LEN + payload_len + USV_CRC_LEN + 3u) {
        return 0;
    }
    body[0] = version;
    body[1] = msg_id;
    body[2] = seq;
    if (payload_len > 0) {
        memcpy(body + USV_HEADER_LEN, payload, payload_len);
    }
    n = USV_HEADER_LEN + payload_len;
    crc = usv_crc16_update(0xFFFFu, body, n);
    body[n++] = (uint8_t)(crc >> 8); /* the CRC is big-endian: the body's CRC is then 0 */
    body[n++] = (uint8_t)(crc & 0xFFu);
    out[0] = 0;
    enc = usv_cobs_encode(body, n, out + 1);
    out[1 + enc] = 0;
    return enc + 2u;
}

size_t usv_message_encode(uint8_t msg_id, uint8_t seq, const usv_message_t *msg,
                          uint8_t *out, size_t cap)
{
    uint8_t payload[USV_MAX_PAYLOAD];
    size_t len;
    if (!usv_msg_known(msg_id)) {
        return 0;
    }
    len = usv_pack(msg_id, msg, payload);
    return usv_frame_encode(USV_PROTOCOL_VERSION, msg_id, seq, payload, len, out, cap);
}

void usv_parser_init(usv_parser_t *p)
{
    memset(p, 0, sizeof *p);
}

static int usv_parser_finish(usv_parser_t *p, usv_frame_t *out)
{
    int n = usv_cobs_decode(p->buf, p->len);
    size_t payload_len;
    uint8_t version, msg_id;
    if (n < 0) {
        p->stats.bad_cobs++;
        return 0;
    }
    if ((size_t)n < USV_HEADER_LEN + USV_CRC_LEN
        || usv_crc16_update(0xFFFFu, p->buf, (size_t)n) != 0) {
        p->stats.bad_crc++;
        return 0;
    }
    version = p->buf[0];
    msg_id = p->buf[1];
    payload_len = (size_t)n - USV_HEADER_LEN - USV_CRC_LEN;
    if (version != USV_PROTOCOL_VERSION) {
        if (msg_id != USV_MSG_HEARTBEAT || payload_len < 5u) {
            p->stats.bad_version++;
            return 0;
        }
    } else if (!usv_msg_known(msg_id)) {
        p->stats.unknown_id++;
        return 0;
    } else if (!usv_payload_len_ok(msg_id, payload_len)) {
        p->stats.bad_length++;
        return 0;
    }
    out->version = version;
    out->msg_id = msg_id;
    out->seq = p->buf[2];
    out->payload_len = (uint8_t)payload_len;
    memcpy(out->payload, p->buf + USV_HEADER_LEN, payload_len);
    p->stats.frames++;
    return 1;
}

int usv_parser_feed(usv_parser_t *p, uint8_t byte, usv_frame_t *out)
{
    int ok = 0;
    if (byte != 0) {
        if (p->overflow) {
            return 0;
        }
        if (p->len >= USV_MAX_ENCODED) {
            p->overflow = 1;
            p->len = 0;
            return 0;
        }
        p->buf[p->len++] = byte;
        return 0;
    }
    if (p->overflow) {
        p->stats.oversize++;
    } else if (p->len > 0) {
        ok = usv_parser_finish(p, out);
    }
    p->len = 0;
    p->overflow = 0;
    return ok;
}
