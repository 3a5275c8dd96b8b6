/*
 * The boat on an STM32F103 (Cortex-M3), as a firmware engineer wires it: this file is the
 * size reference for `make m3` (static RAM with 256-item missions) and the shape of the
 * integration. The register-level drivers are the board's; here they are reduced to the
 * three HAL functions over USART1, SysTick and TIM2/TIM3 PWM, with the register addresses
 * of the STM32F103 reference manual (RM0008).
 *
 *   USART1_IRQHandler: usv_boat_rx_byte() only (the ring buffer); nothing parses in the ISR.
 *   main loop:         usv_boat_set_nav() from the GNSS/compass driver, usv_boat_poll().
 */
#include "usv_boat.h"

#define REG(addr) (*(volatile uint32_t *)(addr))
#define USART1_SR REG(0x40013800u)
#define USART1_DR REG(0x40013804u)
#define USART_SR_RXNE (1u << 5)
#define USART_SR_TXE (1u << 7)
#define TIM2_CCR1 REG(0x40000034u) /* left propeller ESC, 1000..2000 us */
#define TIM3_CCR1 REG(0x40000434u) /* right propeller ESC */

static usv_boat_t boat; /* the whole boat state: static, no heap */
static volatile uint32_t ticks_ms;
static const uint8_t link_key[32] = {0}; /* provisioned into flash at commissioning */

void SysTick_Handler(void);
void USART1_IRQHandler(void);

void SysTick_Handler(void)
{
    ticks_ms++;
}

void USART1_IRQHandler(void)
{
    while (USART1_SR & USART_SR_RXNE) {
        usv_boat_rx_byte(&boat, (uint8_t)USART1_DR);
    }
}

static void uart_send(void *ctx, const uint8_t *buf, uint16_t len)
{
    uint16_t i;
    (void)ctx;
    for (i = 0; i < len; i++) { /* a DMA transfer on the real board */
        while (!(USART1_SR & USART_SR_TXE)) {
        }
        USART1_DR = buf[i];
    }
}

static uint32_t now_ms(void *ctx)
{
    (void)ctx;
    return ticks_ms;
}

static void actuate(void *ctx, int16_t left_pm, int16_t right_pm)
{
    (void)ctx;
    TIM2_CCR1 = (uint32_t)(1500 + left_pm / 2);
    TIM3_CCR1 = (uint32_t)(1500 + right_pm / 2);
}

static void read_nav(usv_nav_t *nav)
{
    /* the GNSS/compass driver fills this; a fixed fix stands in for it here */
    nav->lat_e7 = 599000000;
    nav->lon_e7 = 107000000;
    nav->fix_type = 3;
}

int main(void)
{
    usv_config_t cfg = {0};
    usv_hal_t hal = {0};
    usv_nav_t nav = {0};
    cfg.boat_id = 1;
    cfg.station_id = 255;
    cfg.key = link_key;
    cfg.boot_timestamp = 0; /* from the GNSS time at boot on the real board */
    cfg.boot_id = 0x5eed;   /* from the unique id and a hardware random source */
    cfg.telemetry_period_ms = 200;
    cfg.link_timeout_ms = 3000;
    cfg.start_radius_m = 10.0f;
    cfg.max_speed_mps = 4.0f;
    hal.send = uart_send;
    hal.now_ms = now_ms;
    hal.actuate = actuate;
    if (usv_boat_init(&boat, &cfg, &hal) != 0) {
        return 1;
    }
    for (;;) {
        read_nav(&nav);
        usv_boat_set_nav(&boat, &nav);
        usv_boat_poll(&boat);
    }
}
