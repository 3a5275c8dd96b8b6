/*
 * usv_provision.c: the provisioning page and the signing-floor records (usv_provision.h).
 */
#include "usv_provision.h"

#include <string.h>

#include "usv_boat.h" /* usv_crc32 */

static uint32_t get32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
           ((uint32_t)p[3] << 24);
}

static uint16_t get16(const uint8_t *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

int usv_provision_parse(const uint8_t *page, usv_provision_t *out)
{
    usv_provision_t p;
    memset(&p, 0, sizeof p);
    if (get32(page) != USV_PROVISION_MAGIC || get16(page + 4) != USV_PROVISION_VERSION ||
        usv_crc32(0, page, USV_PROVISION_BYTES - 4u) != get32(page + USV_PROVISION_BYTES - 4u)) {
        return -1;
    }
    p.boat_id = page[6];
    p.station_id = page[7];
    p.signed_link = page[8] & 1u;
    p.telemetry_period_ms = get32(page + 12);
    p.link_timeout_ms = get32(page + 16);
    p.staging_expiry_ms = get32(page + 20);
    p.start_radius_mm = get32(page + 24);
    p.max_speed_mmps = get32(page + 28);
    p.line_baud = get32(page + 32);
    p.clock_speedup_milli = get32(page + 36);
    memcpy(p.key, page + 40, sizeof p.key);
    memcpy(p.nv_path, page + 72, USV_NV_PATH_MAX);
    if (p.nv_path[USV_NV_PATH_MAX - 1u] != '\0' || p.boat_id == 0u || p.station_id == 0u ||
        p.boat_id == p.station_id || p.telemetry_period_ms == 0u || p.link_timeout_ms == 0u ||
        p.start_radius_mm == 0u || p.max_speed_mmps == 0u || p.clock_speedup_milli < 100u ||
        p.clock_speedup_milli > 20000u) {
        return -1;
    }
    *out = p;
    return 0;
}

/* The check half-word: all-zero and all-one records fail it. */
static uint16_t nv_check(uint32_t lo, uint16_t hi)
{
    return (uint16_t)((lo ^ (lo >> 16) ^ hi ^ 0xA55Au) & 0xFFFFu);
}

void usv_nv_record(uint64_t floor, uint8_t rec[USV_NV_RECORD_BYTES])
{
    uint32_t lo = (uint32_t)floor;
    uint16_t hi = (uint16_t)(floor >> 32);
    uint16_t check = nv_check(lo, hi);
    rec[0] = (uint8_t)lo;
    rec[1] = (uint8_t)(lo >> 8);
    rec[2] = (uint8_t)(lo >> 16);
    rec[3] = (uint8_t)(lo >> 24);
    rec[4] = (uint8_t)hi;
    rec[5] = (uint8_t)(hi >> 8);
    rec[6] = (uint8_t)check; /* programmed last: a torn record fails its check */
    rec[7] = (uint8_t)(check >> 8);
}

uint64_t usv_nv_floor(const uint8_t *page, uint32_t len)
{
    uint64_t best = 0;
    uint32_t at;
    for (at = 0; at + USV_NV_RECORD_BYTES <= len; at += USV_NV_RECORD_BYTES) {
        uint32_t lo = get32(page + at);
        uint16_t hi = get16(page + at + 4u);
        if (get16(page + at + 6u) == nv_check(lo, hi)) {
            uint64_t v = ((uint64_t)hi << 32) | lo;
            if (v > best) {
                best = v;
            }
        }
    }
    return best;
}

uint32_t usv_nv_free_slot(const uint8_t *page, uint32_t len)
{
    uint32_t at, k;
    for (at = 0; at + USV_NV_RECORD_BYTES <= len; at += USV_NV_RECORD_BYTES) {
        for (k = 0; k < USV_NV_RECORD_BYTES && page[at + k] == 0xFFu; k++) {
        }
        if (k == USV_NV_RECORD_BYTES) {
            return at;
        }
    }
    return len;
}
