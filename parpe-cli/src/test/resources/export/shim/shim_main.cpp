// Runs an exported sketch on a PC: setup(), then loop() every 100 us of simulated time for
// argv[1] ticks of argv[2] microseconds; argv[3] (optional) is typed on the console just before
// tick 5 runs (the sketch runs tick k at (k + 1) * argv[2] us).
#include <stdlib.h>
#include "Arduino.h"

unsigned long shim_micros = 0;
ShimSerial Serial("serial");
ShimSerial Serial2("serial2");
ShimSerial *shim_console = nullptr;

void setup();
void loop();

int main(int argc, char **argv)
{
    long ticks = argc > 1 ? atol(argv[1]) : 10;
    long tick_us = argc > 2 ? atol(argv[2]) : 10000;
    setup();
    for (long t = 0; t < ticks * tick_us + tick_us / 2; t += 100) {
        if (argc > 3 && t == 6 * tick_us) {
            ShimSerial &console = shim_console != nullptr ? *shim_console : Serial;
            console.feed(argv[3]);
            console.feed("\n");
        }
        shim_micros = (unsigned long) t;
        loop();
    }
    return 0;
}
