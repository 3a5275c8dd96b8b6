/*
 * What a boat's flash holds besides the program (portable C99, no I/O):
 *
 * - the provisioning page (written once at commissioning; 1 KB at USV_CONFIG_PAGE): the
 *   ids, the 32-byte link key and the link settings, little-endian at fixed offsets with a
 *   CRC-32 (layout below; backend/usvstation/hil/provision.py writes the same bytes);
 * - the non-volatile page (1 KB at USV_NV_PAGE): the signing floor (the newest signing
 *   timestamp accepted from the station) as 8-byte records, appended as it rises, the
 *   newest valid record winning. An erased page (0xFF) and an empty one (0x00, QEMU's
 *   flash before a page image is loaded) hold no valid record.
 *
 * Provisioning page (USV_PROVISION_BYTES):
 *   0  u32 magic "USP1"     4  u16 version (1)      6  u8 boat_id   7 u8 station_id
 *   8  u8 flags (bit 0: signed link)   9..11 zero
 *  12  u32 telemetry_period_ms (boat time)   16 u32 link_timeout_ms (link time)
 *  20  u32 staging_expiry_ms (link time)     24 u32 start_radius_mm
 *  28  u32 max_speed_mmps                    32 u32 line_baud (0: no pacing)
 *  36  u32 clock_speedup_milli (1000: real time; above only in hardware-in-the-loop runs)
 *  40  32 bytes key
 *  72  128 bytes nv_path (NUL-terminated; the QEMU image's page image file, see README)
 * 200  u32 CRC-32 (IEEE, as zlib.crc32) of bytes 0..199
 */
#ifndef USV_PROVISION_H
#define USV_PROVISION_H

#include <stdint.h>

#define USV_PROVISION_MAGIC 0x31505355u /* "USP1" */
#define USV_PROVISION_VERSION 1u
#define USV_PROVISION_BYTES 204u
#define USV_NV_PATH_MAX 128u
#define USV_NV_RECORD_BYTES 8u
#define USV_PAGE_BYTES 1024u

typedef struct {
    uint8_t boat_id;
    uint8_t station_id;
    uint8_t signed_link;
    uint32_t telemetry_period_ms;
    uint32_t link_timeout_ms;
    uint32_t staging_expiry_ms;
    uint32_t start_radius_mm;
    uint32_t max_speed_mmps;
    uint32_t line_baud;
    uint32_t clock_speedup_milli;
    uint8_t key[32];
    char nv_path[USV_NV_PATH_MAX];
} usv_provision_t;

/* Parse a provisioning page; 0 when valid, else -1 (bad magic, version, CRC or value). */
int usv_provision_parse(const uint8_t *page, usv_provision_t *out);

/* The newest valid signing floor in a non-volatile page of `len` bytes (0: none). */
uint64_t usv_nv_floor(const uint8_t *page, uint32_t len);
/* The 8-byte record of a 48-bit floor. */
void usv_nv_record(uint64_t floor, uint8_t rec[USV_NV_RECORD_BYTES]);
/* Offset of the first erased (all 0xFF) record slot, or `len` when the page is full. */
uint32_t usv_nv_free_slot(const uint8_t *page, uint32_t len);

#endif
