/*
 * The chip under the boat firmware: clocks, pins, the two UARTs, the ESC pulses, SysTick,
 * sleep, and the flash pages (provisioning, non-volatile signing floor). Two builds:
 *   STM32F103C8 (default): 72 MHz from an 8 MHz crystal, the floor in a flash page;
 *   USV_BOARD_QEMU: QEMU's stm32vldiscovery (an STM32F100 at the 24 MHz QEMU gives it,
 *                   no clock tree, no flash controller): the floor goes to the flash page
 *                   image file through semihosting (README "The QEMU image").
 */
#ifndef USV_STM32_BOARD_H
#define USV_STM32_BOARD_H

#include <stdint.h>

#define BOARD_RADIO_BAUD 57600u /* USART1: the radio (SiK-class modem) */
#define BOARD_HIL_BAUD 115200u  /* USART2: navigation in, thrust out */

/* Boat milliseconds since reset, advanced by the 1 kHz SysTick: one a tick at sea,
 * speedup_milli / 1000 a tick when a hardware-in-the-loop run speeds the boat's clock up. */
extern volatile uint32_t board_ms;

/* Clocks, pins, USART1/USART2 (receive interrupts still off), PWM at neutral, SysTick. */
void board_init(uint32_t speedup_milli);
/* Enable the receive interrupt of USART1 (radio) or USART2 (HIL). */
void board_enable_rx(uint32_t usart_base);
/* Send bytes on a UART, waiting for each to be taken (a DMA transfer on a production board). */
void board_uart_send(uint32_t usart_base, const uint8_t *buf, uint16_t len);
/* ESC pulses: per mille -1000..1000 to 1000..2000 us on TIM2 CH1 (left), TIM3 CH1 (right). */
void board_pwm(int16_t left_pm, int16_t right_pm);
/* Sleep until the next interrupt (SysTick at the latest). */
void board_sleep(void);
/* The provisioning page (usv_provision.h). */
const uint8_t *board_config_page(void);
/* The newest signing floor in the non-volatile page (0: none). */
uint64_t board_nv_load(void);
/* Persist a higher signing floor (`nv_path`: the QEMU image's page image file). */
void board_nv_store(uint64_t floor, const char *nv_path);
/* A per-chip, per-boot value for the boot id (unique id on the F103, SysTick phase). */
uint32_t board_entropy(void);
/* Propellers neutral, then a system reset: the boat comes back IDLE. */
void board_fault(void);

#endif
