/* Vector tool for the tests (tests/unit/test_protocol_c.py); not part of the firmware.
 *
 *   vector_tool decode   stdin: one hex byte stream per line. Each stream is fed byte by
 *                        byte to a fresh parser; every frame is unpacked, packed and framed
 *                        again, printed as "STREAM HEX FIELDS..." (FIELDS: the decoded
 *                        values, text as hex; "foreign" for another version's HEARTBEAT).
 *   vector_tool encode   stdin: lines "MSG_ID SEQ N V1..VN TEXT_HEX|-"; prints each frame's
 *                        wire bytes as hex.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../usv_link.h"
#include "usv_fields.h"

static void print_hex(const uint8_t *b, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        printf("%02x", (unsigned)b[i]);
    }
}

static int hex_value(int c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

static void emit_frame(long stream, const usv_frame_t *f)
{
    usv_message_t m;
    uint8_t wire[USV_MAX_WIRE];
    size_t n;
    if (f->version != USV_PROTOCOL_VERSION) {
        n = usv_frame_encode(f->version, f->msg_id, f->seq, f->payload, f->payload_len,
                             wire, sizeof wire);
        printf("%ld ", stream);
        print_hex(wire, n);
        printf(" foreign\n");
        return;
    }
    memset(&m, 0, sizeof m);
    if (!usv_unpack(f->msg_id, f->payload, f->payload_len, &m)) {
        printf("%ld unpack-failed\n", stream);
        return;
    }
    n = usv_message_encode(f->msg_id, f->seq, &m, wire, sizeof wire);
    printf("%ld ", stream);
    print_hex(wire, n);
    usv_test_print(stdout, f->msg_id, &m);
    printf("\n");
}

static int run_decode(void)
{
    usv_parser_t parser;
    usv_frame_t frame;
    long stream = 0;
    int c, hi = -1;
    usv_parser_init(&parser);
    while ((c = getchar()) != EOF) {
        if (c == '\n') {
            stream++;
            usv_parser_init(&parser);
            hi = -1;
            continue;
        }
        if (hex_value(c) < 0) {
            continue;
        }
        if (hi < 0) {
            hi = hex_value(c);
            continue;
        }
        if (usv_parser_feed(&parser, (uint8_t)(hi * 16 + hex_value(c)), &frame)) {
            emit_frame(stream, &frame);
        }
        hi = -1;
    }
    return 0;
}

static int run_encode(void)
{
    int msg_id, seq;
    long n, i;
    long long v;
    char text[2 * USV_MAX_PAYLOAD + 2];
    while (scanf("%d %d %ld", &msg_id, &seq, &n) == 3) {
        usv_message_t m;
        uint8_t wire[USV_MAX_WIRE];
        size_t len;
        memset(&m, 0, sizeof m);
        for (i = 0; i < n; i++) {
            if (scanf("%lld", &v) != 1 || !usv_test_set((uint8_t)msg_id, &m, (size_t)i, v)) {
                fprintf(stderr, "bad field %ld of message %d\n", i, msg_id);
                return 2;
            }
        }
        if (scanf("%101s", text) != 1) {
            return 2;
        }
        if (strcmp(text, "-") != 0) {
            char bytes[USV_MAX_PAYLOAD];
            size_t k, nb = strlen(text) / 2;
            for (k = 0; k < nb; k++) {
                bytes[k] = (char)(hex_value(text[2 * k]) * 16 + hex_value(text[2 * k + 1]));
            }
            usv_test_set_text((uint8_t)msg_id, &m, bytes, nb);
        }
        len = usv_message_encode((uint8_t)msg_id, (uint8_t)seq, &m, wire, sizeof wire);
        if (len == 0) {
            fprintf(stderr, "cannot encode message %d\n", msg_id);
            return 2;
        }
        print_hex(wire, len);
        printf("\n");
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "decode") == 0) {
        return run_decode();
    }
    if (argc == 2 && strcmp(argv[1], "encode") == 0) {
        return run_encode();
    }
    fprintf(stderr, "usage: vector_tool decode|encode < input\n");
    return 2;
}
