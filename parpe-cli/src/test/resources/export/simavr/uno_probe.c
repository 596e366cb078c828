/*
 * uno_probe: runs an Arduino Uno sketch (an ELF built with the Arduino AVR core) on simavr's
 * ATmega328P at 16 MHz and prints what the board does, for the export tests (SimulatedUnoTest):
 *
 *   P pin rise width     a high pulse on a watched pin (CPU cycles at its rising edge, its width in
 *                        cycles); the first pulse of each pin is always printed
 *   E pin cycle level    an edge of a pin watched as a serial line (the SoftwareSerial console)
 *   U cycle byte         a byte the hardware UART sent
 *   R end stack state busy   at the end: the cycle count, the deepest stack use in bytes,
 *                        simavr's CPU state and the cycles the CPU was awake (not sleeping)
 *
 * usage: uno_probe ELF SECONDS FROM_SECONDS END_OF_BSS_HEX [p:PIN | e:PIN | c:PIN:BAUD:AT:TEXT]...
 * c: drives PIN (an input, idle high) as a serial line sending TEXT (8N1, bytes back to back) at
 * BAUD from AT seconds on: what a USB-serial adapter sends to the SoftwareSerial console.
 * Pulses, edges and bytes before FROM_SECONDS are not printed (a long run prints only its end).
 * The RAM between the end of .bss and RAMEND is painted before reset; the stack use is
 * RAMEND + 1 minus the lowest byte that is no longer paint.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/avr_ioport.h>
#include <simavr/avr_uart.h>
#include <simavr/avr_extint.h>

#define PAINT 0xA5
#define FREQ 16000000ULL

static avr_t *avr;
static avr_cycle_count_t from;
static avr_cycle_count_t rise[20];
static int pulses[20];

static int pulse_pin(int pin, char *port, int *bit)
{
    if (pin >= 0 && pin <= 7) {
        *port = 'D';
        *bit = pin;
    } else if (pin >= 8 && pin <= 13) {
        *port = 'B';
        *bit = pin - 8;
    } else if (pin >= 14 && pin <= 19) {
        *port = 'C';
        *bit = pin - 14;
    } else {
        return -1;
    }
    return 0;
}

static void on_pulse(struct avr_irq_t *irq, uint32_t value, void *param)
{
    int pin = (int) (intptr_t) param;
    (void) irq;
    if (value) {
        rise[pin] = avr->cycle;
    } else if (rise[pin] != 0 && (rise[pin] >= from || pulses[pin]++ == 0)) {
        printf("P %d %llu %llu\n", pin, (unsigned long long) rise[pin], (unsigned long long) (avr->cycle - rise[pin]));
    }
}

static void on_edge(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void) irq;
    if (avr->cycle >= from) {
        printf("E %d %llu %u\n", (int) (intptr_t) param, (unsigned long long) avr->cycle, value ? 1u : 0u);
    }
}

static void on_uart(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void) irq;
    (void) param;
    if (avr->cycle >= from) {
        printf("U %llu %u\n", (unsigned long long) avr->cycle, value & 0xFF);
    }
}

/* Serial text driven into an input pin, one level change per bit (c: arguments). */
#define MAX_LINES 64
static struct line_in {
    avr_irq_t *irq;
    avr_cycle_count_t bit;
    const char *text;
    size_t at;       /* the byte being sent */
    int k;           /* its bit: 0 start, 1..8 data, 9 stop */
} lines_in[MAX_LINES];

static avr_cycle_count_t next_bit(avr_t *a, avr_cycle_count_t when, void *param)
{
    struct line_in *l = param;
    uint8_t c = (uint8_t) l->text[l->at];
    (void) a;
    uint32_t level = l->k == 0 ? 0 : l->k == 9 ? 1 : (c >> (l->k - 1)) & 1;
    if (level != l->irq->value) {   /* a pin changes only at a level change (simavr would raise PCINT) */
        avr_raise_irq(l->irq, level);
    }
    if (++l->k == 10) {
        l->k = 0;
        if (l->text[++l->at] == '\0') {
            return 0;
        }
    }
    return when + l->bit;
}

/* simavr's own sleep waits in real time; the probe skips the idle time at once. */
static void no_wait(avr_t *a, avr_cycle_count_t how_long)
{
    (void) a;
    (void) how_long;
}

int main(int argc, char **argv)
{
    elf_firmware_t f;
    avr_cycle_count_t end;
    uint16_t bss_end;
    int i;
    int state = cpu_Running;
    int n_in = 0;
    avr_cycle_count_t busy = 0;
    static char buf[1 << 16];
    setvbuf(stdout, buf, _IOFBF, sizeof buf);
    if (argc < 5) {
        fprintf(stderr, "usage: uno_probe ELF SECONDS FROM_SECONDS END_OF_BSS_HEX [p:PIN | e:PIN]...\n");
        return 2;
    }
    memset(&f, 0, sizeof f);
    if (elf_read_firmware(argv[1], &f) != 0) {
        fprintf(stderr, "uno_probe: cannot read %s\n", argv[1]);
        return 2;
    }
    strcpy(f.mmcu, "atmega328p");
    f.frequency = FREQ;
    end = (avr_cycle_count_t) (atof(argv[2]) * FREQ);
    from = (avr_cycle_count_t) (atof(argv[3]) * FREQ);
    bss_end = (uint16_t) strtoul(argv[4], NULL, 16);
    avr = avr_make_mcu_by_name(f.mmcu);
    if (avr == NULL || avr_init(avr) != 0) {
        fprintf(stderr, "uno_probe: no atmega328p in simavr\n");
        return 2;
    }
    avr_load_firmware(avr, &f);
    avr->log = 0;
    avr->sleep = no_wait;
    /* simavr polls INT0/INT1 every cycle while their pins are low (pin 2 is); the sketch does not use them */
    avr_extint_set_strict_lvl_trig(avr, 0, 0);
    avr_extint_set_strict_lvl_trig(avr, 1, 0);
    {
        uint32_t flags = 0;   /* no stdio echo, no sleeping while the UART is polled */
        avr_ioctl(avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
    }
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT), on_uart, NULL);
    for (i = 5; i < argc; i++) {
        char port;
        int bit;
        int pin = atoi(argv[i] + 2);
        if (pulse_pin(pin, &port, &bit) != 0 || (argv[i][0] != 'p' && argv[i][0] != 'e' && argv[i][0] != 'c')
                || argv[i][1] != ':') {
            fprintf(stderr, "uno_probe: bad pin argument '%s'\n", argv[i]);
            return 2;
        }
        if (argv[i][0] == 'c') {
            char *baud = strchr(argv[i] + 2, ':');
            char *at = baud == NULL ? NULL : strchr(baud + 1, ':');
            char *text = at == NULL ? NULL : strchr(at + 1, ':');
            if (text == NULL || text[1] == '\0' || n_in == MAX_LINES) {
                fprintf(stderr, "uno_probe: bad console argument '%s'\n", argv[i]);
                return 2;
            }
            lines_in[n_in].irq = avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(port), bit);
            lines_in[n_in].bit = FREQ / strtoull(baud + 1, NULL, 10);
            lines_in[n_in].text = text + 1;
            avr_raise_irq(lines_in[n_in].irq, 1);
            avr_cycle_timer_register(avr, (avr_cycle_count_t) (atof(at + 1) * FREQ), next_bit, &lines_in[n_in]);
            n_in++;
            continue;
        }
        avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ(port), bit),
                argv[i][0] == 'p' ? on_pulse : on_edge, (void *) (intptr_t) pin);
    }
    for (i = bss_end; i <= avr->ramend; i++) {
        avr->data[i] = PAINT;
    }
    while (avr->cycle < end && state != cpu_Done && state != cpu_Crashed) {
        avr_cycle_count_t before = avr->cycle;
        int awake = avr->state == cpu_Running;
        state = avr_run(avr);
        if (awake) {
            busy += avr->cycle - before;
        }
    }
    for (i = bss_end; i <= avr->ramend && avr->data[i] == PAINT; i++) {
    }
    printf("R %llu %d %d %llu\n", (unsigned long long) avr->cycle, avr->ramend + 1 - i, state, (unsigned long long) busy);
    return 0;
}
