/*
 * Start-up code and vector table of the boat firmware on an STM32F1 (Cortex-M3): the
 * linker scripts (stm32f103c8.ld, stm32vldiscovery.ld) place `vectors` at the start of
 * flash. Reset copies .data from flash, zeroes .bss, paints the free RAM between .bss and
 * the stack pointer with STACK_PAINT (so the stack's high-water mark can be read from a
 * RAM image) and calls main(). Unexpected interrupts and faults call board_fault(), which
 * stops the propellers and resets the chip: the boat comes back IDLE, nothing moving.
 */
#include <stdint.h>

#define STACK_PAINT 0xA5A5A5A5u
#define VECTORS (16 + 61) /* the Cortex-M3 system vectors and the F100/F103 interrupts */

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;

int main(void);
void Reset_Handler(void);
void Default_Handler(void);
void board_fault(void);
void SysTick_Handler(void);
void USART1_IRQHandler(void);
void USART2_IRQHandler(void);

void Reset_Handler(void)
{
    uint32_t *src = &_sidata;
    uint32_t *dst;
    volatile uint32_t here = 0;
    for (dst = &_sdata; dst < &_edata;) {
        *dst++ = *src++;
    }
    for (dst = &_sbss; dst < &_ebss;) {
        *dst++ = 0u;
    }
    /* paint up to 64 bytes below this frame (the stack in use) */
    for (dst = &_ebss; (uintptr_t)dst + 64u < (uintptr_t)&here;) {
        *dst++ = STACK_PAINT;
    }
    (void)main();
    board_fault(); /* main never returns on the chip */
}

void Default_Handler(void)
{
    board_fault();
}

/* The table: initial stack pointer, then handlers, as addresses. */
__attribute__((section(".isr_vector"), used)) const uintptr_t vectors[VECTORS] = {
    [0] = (uintptr_t)&_estack,
    [1] = (uintptr_t)Reset_Handler,
    [2] = (uintptr_t)Default_Handler,  /* NMI */
    [3] = (uintptr_t)Default_Handler,  /* HardFault */
    [4] = (uintptr_t)Default_Handler,  /* MemManage */
    [5] = (uintptr_t)Default_Handler,  /* BusFault */
    [6] = (uintptr_t)Default_Handler,  /* UsageFault */
    [11] = (uintptr_t)Default_Handler, /* SVCall */
    [12] = (uintptr_t)Default_Handler, /* DebugMon */
    [14] = (uintptr_t)Default_Handler, /* PendSV */
    [15] = (uintptr_t)SysTick_Handler,
    [16 + 37] = (uintptr_t)USART1_IRQHandler, /* the radio */
    [16 + 38] = (uintptr_t)USART2_IRQHandler, /* navigation in, thrust out (HIL) */
};
