/*
 * The boat firmware on an STM32F1 (Cortex-M3): usv_boat.c on the radio (USART1), its
 * navigation in and thrust out over USART2 (usv_hil.c: standard MAVLink HIL messages, the
 * bench's hardware in the loop and QEMU's), ESC pulses on TIM2/TIM3, SysTick for the
 * clock. `make m3` links it for an STM32F103C8 (stm32f103c8.ld), `make qemu` for QEMU's
 * stm32vldiscovery (stm32vldiscovery.ld, -DUSV_BOARD_QEMU); README.md has the map.
 *
 *   USART1_IRQHandler: usv_boat_rx_byte() only (the ring buffer); nothing parses in the ISR.
 *   USART2_IRQHandler: usv_hil_rx_byte() only.
 *   main loop:         HIL fixes to usv_boat_set_nav(), usv_boat_poll() (at most once a boat
 *                      millisecond; at once when the radio ring fills), HIL_ACTUATOR_CONTROLS
 *                      every HIL_PERIOD_MS, the signing floor to flash once a second, sleep.
 *
 * Boot: provisioning page (ids, key, settings; without a valid one the firmware stays
 * silent with the propellers stopped), signing floor from the non-volatile page, then up to
 * BOOT_FIX_WAIT_MS for the GNSS's first fix and its time: the boat refuses every frame
 * signed before max(GNSS time, floor + 2 s), so a session recorded before a reset replays
 * to nothing.
 */
#include "stm32_board.h"
#include "stm32f1.h"
#include "usv_boat.h"
#include "usv_hil.h"
#include "usv_provision.h"

#define HIL_PERIOD_MS 50u      /* boat ms between HIL_ACTUATOR_CONTROLS */
#define IDLE_POLL_MS 5u        /* boat ms between polls while the radio is quiet */
#define BOOT_FIX_WAIT_MS 2000u /* link ms waiting for the GNSS time at boot */
#define NV_PERIOD_MS 1000u     /* link ms between signing-floor writes */
#define FLOOR_MARGIN 200000u   /* 2 s of signing time: frames of the last unsaved second */
#define UNIX_US_2015 1420070400000000ULL

static usv_boat_t boat; /* the whole boat state: static, no heap */
static usv_hil_t hil;
static usv_provision_t prov;
static int16_t thrust[2];

void USART1_IRQHandler(void);
void USART2_IRQHandler(void);

void USART1_IRQHandler(void)
{
    while (USART_SR(USART1_BASE) & USART_SR_RXNE) {
        usv_boat_rx_byte(&boat, (uint8_t)USART_DR(USART1_BASE));
    }
}

void USART2_IRQHandler(void)
{
    while (USART_SR(USART2_BASE) & USART_SR_RXNE) {
        usv_hil_rx_byte(&hil, (uint8_t)USART_DR(USART2_BASE));
    }
}

static void radio_send(void *ctx, const uint8_t *buf, uint16_t len)
{
    (void)ctx;
    board_uart_send(USART1_BASE, buf, len);
}

static uint32_t now_ms(void *ctx)
{
    (void)ctx;
    return board_ms;
}

static void actuate(void *ctx, int16_t left_pm, int16_t right_pm)
{
    (void)ctx;
    thrust[0] = left_pm;
    thrust[1] = right_pm;
    board_pwm(left_pm, right_pm);
}

/* link (wall-clock) milliseconds in boat milliseconds */
static uint32_t link_ms(uint32_t ms)
{
    return (uint32_t)((uint64_t)ms * prov.clock_speedup_milli / 1000u);
}

static int due(uint32_t now, uint32_t at)
{
    return (int32_t)(now - at) >= 0;
}

/* Parse the HIL link; every HIL_PERIOD_MS the thrust goes out, stamped with the uptime. */
static void service_hil(uint32_t now, uint32_t *next_hil, uint64_t sign_time)
{
    if (usv_hil_poll(&hil, now)) {
        usv_boat_set_nav(&boat, &hil.nav);
    }
    if (due(now, *next_hil)) {
        uint16_t n = usv_hil_actuators(&hil, now, thrust[0], thrust[1], sign_time);
        board_uart_send(USART2_BASE, hil.tx_buf, n);
        *next_hil = now + HIL_PERIOD_MS;
    }
}

static uint16_t radio_pending(void)
{
    return (uint16_t)((boat.rx_head - boat.rx_tail) & (USV_RX_RING - 1u));
}

static uint64_t boot_timestamp(uint64_t floor)
{
    uint64_t t = floor != 0u ? floor + FLOOR_MARGIN : 0u;
    if (hil.unix_us > UNIX_US_2015 && (hil.unix_us - UNIX_US_2015) / 10u > t) {
        t = (hil.unix_us - UNIX_US_2015) / 10u; /* the GNSS's UTC in 10 us units */
    }
    return t;
}

static void configure(usv_config_t *cfg, uint64_t floor)
{
    uint8_t seed[16];
    uint32_t e = board_entropy();
    uint64_t u = hil.unix_us;
    unsigned i;
    cfg->boat_id = prov.boat_id;
    cfg->station_id = prov.station_id;
    cfg->key = prov.signed_link ? prov.key : NULL;
    cfg->boot_timestamp = boot_timestamp(floor);
    for (i = 0; i < 8u; i++) {
        seed[i] = (uint8_t)(u >> (8u * i));
        seed[8u + i] = (uint8_t)((i < 4u ? e : board_ms) >> (8u * (i % 4u)));
    }
    cfg->boot_id = usv_crc32((uint32_t)floor, seed, sizeof seed);
    cfg->telemetry_period_ms = prov.telemetry_period_ms;
    /* the link's timeouts count link time; the boat clock runs clock_speedup times faster */
    cfg->link_timeout_ms = link_ms(prov.link_timeout_ms);
    cfg->dup_expiry_ms = link_ms(USV_DUP_EXPIRY_MS);
    cfg->staging_expiry_ms = link_ms(prov.staging_expiry_ms != 0u ? prov.staging_expiry_ms
                                                                  : USV_STAGING_EXPIRY_MS);
    cfg->start_radius_m = (float)prov.start_radius_mm * 1e-3f;
    cfg->max_speed_mps = (float)prov.max_speed_mmps * 1e-3f;
    cfg->line_baud = prov.line_baud == 0u ? 0u
        : (uint32_t)((uint64_t)prov.line_baud * 1000u / prov.clock_speedup_milli) + 1u;
}

int main(void)
{
    usv_config_t cfg = {0};
    usv_hal_t hal = {0};
    uint64_t floor, saved;
    uint32_t next_hil = 0, next_nv, last_poll;
    if (usv_provision_parse(board_config_page(), &prov) != 0) {
        board_init(1000u); /* not provisioned: no link, propellers stopped */
        for (;;) {
            board_sleep();
        }
    }
    board_init(prov.clock_speedup_milli);
    floor = saved = board_nv_load();
    usv_hil_init(&hil, prov.boat_id, prov.signed_link ? prov.key : NULL,
                 floor != 0u ? floor + FLOOR_MARGIN : 0u);
    board_enable_rx(USART2_BASE);
    while (hil.fixes == 0u && board_ms < link_ms(BOOT_FIX_WAIT_MS)) {
        service_hil(board_ms, &next_hil, hil.signing.timestamp);
        board_sleep();
    }
    configure(&cfg, floor);
    hal.send = radio_send;
    hal.now_ms = now_ms;
    hal.actuate = actuate;
    if (usv_boat_init(&boat, &cfg, &hal) != 0) {
        board_fault();
    }
    usv_boat_set_nav(&boat, &hil.nav);
    board_enable_rx(USART1_BASE);
    next_nv = board_ms + link_ms(NV_PERIOD_MS);
    last_poll = board_ms - IDLE_POLL_MS;
    for (;;) {
        uint32_t now = board_ms;
        service_hil(now, &next_hil, cfg.boot_timestamp + (uint64_t)(now - boat.boot_ms) * 100u);
        if ((now != last_poll && radio_pending() != 0u) || due(now, last_poll + IDLE_POLL_MS) ||
            radio_pending() >= USV_RX_RING / 2u) {
            usv_boat_poll(&boat);
            last_poll = now;
        }
        if (due(now, next_nv)) {
            uint64_t f = usv_boat_signing_floor(&boat);
            if (f > saved) {
                board_nv_store(f, prov.nv_path);
                saved = f;
            }
            next_nv = now + link_ms(NV_PERIOD_MS);
        }
        board_sleep();
    }
}
