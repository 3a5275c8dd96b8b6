/*
 * stm32_board.c: the STM32F103C8 and QEMU stm32vldiscovery chip layer (stm32_board.h).
 * Pin and timer map (README "Pins and timers"):
 *   PA9/PA10 USART1 TX/RX (radio), PA2/PA3 USART2 TX/RX (HIL), PA0 TIM2_CH1 (left ESC),
 *   PA6 TIM3_CH1 (right ESC), SysTick one boat millisecond.
 */
#include "stm32_board.h"

#include <string.h>

#include "stm32f1.h"
#include "usv_provision.h"

extern const uint8_t __usv_config_page[]; /* the linker scripts' two reserved pages */
extern const uint8_t __usv_nv_page[];

volatile uint32_t board_ms;
static uint32_t tick_milli = 1000u; /* boat ms x 1000 a SysTick (1000 at sea) */
static uint32_t tick_acc;

static uint32_t sysclk_hz = 8000000u; /* HSI after reset */
static uint32_t pclk1_hz = 8000000u;
static uint32_t pclk2_hz = 8000000u;

void SysTick_Handler(void);

/* 1 kHz: one boat millisecond a tick at sea, speedup_milli / 1000 of them in a
 * hardware-in-the-loop run that runs the boat's clock faster */
void SysTick_Handler(void)
{
    tick_acc += tick_milli;
    board_ms += tick_acc / 1000u;
    tick_acc %= 1000u;
}

#ifdef USV_BOARD_QEMU
#define QEMU_SYSCLK_HZ 24000000u /* QEMU's stm32vldiscovery: fixed, no RCC model */

static void clock_init(void)
{
    sysclk_hz = pclk1_hz = pclk2_hz = QEMU_SYSCLK_HZ;
}
#else
#define HSE_WAIT 200000u

/* 8 MHz crystal x 9 = 72 MHz, APB1 36 MHz, APB2 72 MHz; stays on the 8 MHz HSI when the
 * crystal does not start. */
static void clock_init(void)
{
    uint32_t n;
    RCC_CR |= RCC_CR_HSEON;
    for (n = 0; n < HSE_WAIT && !(RCC_CR & RCC_CR_HSERDY); n++) {
    }
    if (!(RCC_CR & RCC_CR_HSERDY)) {
        return;
    }
    FLASH_ACR = FLASH_ACR_PRFTBE | FLASH_ACR_LATENCY_2;
    RCC_CFGR = RCC_CFGR_PLLSRC_HSE | RCC_CFGR_PLLMUL9 | RCC_CFGR_PPRE1_DIV2;
    RCC_CR |= RCC_CR_PLLON;
    for (n = 0; n < HSE_WAIT && !(RCC_CR & RCC_CR_PLLRDY); n++) {
    }
    if (!(RCC_CR & RCC_CR_PLLRDY)) {
        return;
    }
    RCC_CFGR |= RCC_CFGR_SW_PLL;
    while ((RCC_CFGR & RCC_CFGR_SWS_MASK) != RCC_CFGR_SWS_PLL) {
    }
    sysclk_hz = 72000000u;
    pclk1_hz = 36000000u;
    pclk2_hz = 72000000u;
}
#endif

static void uart_init(uint32_t base, uint32_t pclk, uint32_t baud)
{
    USART_BRR(base) = (pclk + baud / 2u) / baud;
    USART_CR1(base) = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE;
}

/* 1 MHz timer ticks, 20 ms period: the 50 Hz pulse of a hobby ESC, 1.5 ms neutral. */
static void pwm_init(uint32_t base)
{
    uint32_t timclk = pclk1_hz == sysclk_hz ? pclk1_hz : 2u * pclk1_hz; /* RM0008 7.2 */
    TIM_PSC(base) = timclk / 1000000u - 1u;
    TIM_ARR(base) = 20000u - 1u;
    TIM_CCR1(base) = 1500u;
    TIM_CCMR1(base) = TIM_CCMR1_OC1M_PWM1 | TIM_CCMR1_OC1PE;
    TIM_CCER(base) = TIM_CCER_CC1E;
    TIM_EGR(base) = TIM_EGR_UG;
    TIM_CR1(base) = TIM_CR1_ARPE | TIM_CR1_CEN;
}

void board_init(uint32_t speedup_milli)
{
    clock_init();
    RCC_APB2ENR |= RCC_APB2ENR_AFIOEN | RCC_APB2ENR_IOPAEN | RCC_APB2ENR_USART1EN;
    RCC_APB1ENR |= RCC_APB1ENR_TIM2EN | RCC_APB1ENR_TIM3EN | RCC_APB1ENR_USART2EN;
    /* PA0 PA2 PA6 alternate push-pull, PA3 input; PA9 alternate push-pull, PA10 input */
    GPIOA_CRL = (GPIO_AF_PP_50MHZ << 0) | (GPIO_IN_FLOATING << 4) | (GPIO_AF_PP_50MHZ << 8) |
                (GPIO_IN_FLOATING << 12) | (GPIO_IN_FLOATING << 16) |
                (GPIO_IN_FLOATING << 20) | (GPIO_AF_PP_50MHZ << 24) | (GPIO_IN_FLOATING << 28);
    GPIOA_CRH = (GPIOA_CRH & ~0xFF0u) | (GPIO_AF_PP_50MHZ << 4) | (GPIO_IN_FLOATING << 8);
    pwm_init(TIM2_BASE);
    pwm_init(TIM3_BASE);
    uart_init(USART1_BASE, pclk2_hz, BOARD_RADIO_BAUD);
    uart_init(USART2_BASE, pclk1_hz, BOARD_HIL_BAUD);
    tick_milli = speedup_milli;
    SYST_RVR = sysclk_hz / 1000u - 1u;
    SYST_CVR = 0u;
    SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_TICKINT | SYST_CSR_ENABLE;
}

void board_enable_rx(uint32_t usart_base)
{
    USART_CR1(usart_base) |= USART_CR1_RXNEIE;
    NVIC_ISER(1) = 1u << ((usart_base == USART1_BASE ? USART1_IRQN : USART2_IRQN) - 32);
}

void board_uart_send(uint32_t usart_base, const uint8_t *buf, uint16_t len)
{
    uint16_t i;
    for (i = 0; i < len; i++) {
        while (!(USART_SR(usart_base) & USART_SR_TXE)) {
        }
        USART_DR(usart_base) = buf[i];
    }
}

static uint32_t pulse_us(int16_t pm)
{
    int32_t v = pm < -1000 ? -1000 : (pm > 1000 ? 1000 : pm);
    return (uint32_t)(1500 + v / 2);
}

void board_pwm(int16_t left_pm, int16_t right_pm)
{
    TIM_CCR1(TIM2_BASE) = pulse_us(left_pm);
    TIM_CCR1(TIM3_BASE) = pulse_us(right_pm);
}

void board_sleep(void)
{
    __asm__ volatile("wfi");
}

const uint8_t *board_config_page(void)
{
    return __usv_config_page;
}

uint64_t board_nv_load(void)
{
    return usv_nv_floor(__usv_nv_page, USV_PAGE_BYTES);
}

void board_fault(void)
{
    __asm__ volatile("cpsid i");
    board_pwm(0, 0);
    SCB_AIRCR = SCB_AIRCR_SYSRESET;
    for (;;) {
    }
}

#ifdef USV_BOARD_QEMU
/* ARM semihosting (the debugger's host calls, QEMU -semihosting-config target=native). */
enum { SYS_OPEN = 0x01, SYS_CLOSE = 0x02, SYS_WRITE = 0x05, SYS_RENAME = 0x0F };
#define SH_MODE_WB 5 /* fopen "wb" */

static int32_t semihost(uint32_t op, const uint32_t *args)
{
    register uint32_t r0 __asm__("r0") = op;
    register const uint32_t *r1 __asm__("r1") = args;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return (int32_t)r0;
}

/* The page image file holds one record; written beside and renamed over the old one, so a
 * QEMU killed at any instant leaves the old floor or the new one, never a torn file. */
void board_nv_store(uint64_t floor, const char *nv_path)
{
    char tmp[USV_NV_PATH_MAX + 4];
    uint8_t rec[USV_NV_RECORD_BYTES];
    uint32_t a[4];
    int32_t fd;
    size_t n = strlen(nv_path);
    if (n == 0u || n + 4u >= sizeof tmp) {
        return;
    }
    memcpy(tmp, nv_path, n);
    memcpy(tmp + n, ".tmp", 5);
    usv_nv_record(floor, rec);
    a[0] = (uint32_t)(uintptr_t)tmp;
    a[1] = SH_MODE_WB;
    a[2] = (uint32_t)(n + 4u);
    fd = semihost(SYS_OPEN, a);
    if (fd < 0) {
        return;
    }
    a[0] = (uint32_t)fd;
    a[1] = (uint32_t)(uintptr_t)rec;
    a[2] = sizeof rec;
    (void)semihost(SYS_WRITE, a);
    a[0] = (uint32_t)fd;
    (void)semihost(SYS_CLOSE, a);
    a[0] = (uint32_t)(uintptr_t)tmp;
    a[1] = (uint32_t)(n + 4u);
    a[2] = (uint32_t)(uintptr_t)nv_path;
    a[3] = (uint32_t)n;
    (void)semihost(SYS_RENAME, a);
}

uint32_t board_entropy(void)
{
    return SYST_CVR ^ board_ms;
}
#else
static int flash_wait(void)
{
    uint32_t sr;
    while (FLASH_SR & FLASH_SR_BSY) {
    }
    sr = FLASH_SR;
    FLASH_SR = FLASH_SR_EOP | FLASH_SR_PGERR | FLASH_SR_WRPRTERR; /* write 1 to clear */
    return (sr & (FLASH_SR_PGERR | FLASH_SR_WRPRTERR)) ? -1 : 0;
}

/* Append a record to the page (PM0075 2.3): half-word programming, the check half-word
 * last; a full page is erased first. The CPU stalls on flash while it programs (about
 * 50 us a half-word, 20-40 ms for an erase once in 128 records): the link's CRCs and
 * retries cover a byte the radio UART loses meanwhile. */
void board_nv_store(uint64_t floor, const char *nv_path)
{
    uint8_t rec[USV_NV_RECORD_BYTES];
    uint32_t slot = usv_nv_free_slot(__usv_nv_page, USV_PAGE_BYTES);
    uint32_t addr, i;
    (void)nv_path;
    usv_nv_record(floor, rec);
    FLASH_KEYR = FLASH_KEY1;
    FLASH_KEYR = FLASH_KEY2;
    if (slot >= USV_PAGE_BYTES) {
        FLASH_CR = FLASH_CR_PER;
        FLASH_AR = (uint32_t)(uintptr_t)__usv_nv_page;
        FLASH_CR = FLASH_CR_PER | FLASH_CR_STRT;
        (void)flash_wait();
        slot = 0;
    }
    addr = (uint32_t)(uintptr_t)__usv_nv_page + slot;
    FLASH_CR = FLASH_CR_PG;
    for (i = 0; i < USV_NV_RECORD_BYTES; i += 2u) {
        *(volatile uint16_t *)(addr + i) = (uint16_t)(rec[i] | (rec[i + 1u] << 8));
        if (flash_wait() != 0) {
            break;
        }
    }
    FLASH_CR = FLASH_CR_LOCK;
}

uint32_t board_entropy(void)
{
    return REG32(UID_BASE) ^ REG32(UID_BASE + 4u) ^ REG32(UID_BASE + 8u) ^ SYST_CVR;
}
#endif
