// Stand-in for the SoftwareSerial library: the console of an Uno whose hardware UART drives the bus.
#ifndef SHIM_SOFTWARESERIAL_H
#define SHIM_SOFTWARESERIAL_H
#include "Arduino.h"

extern ShimSerial *shim_console;

class SoftwareSerial : public ShimSerial {
public:
    SoftwareSerial(int, int) : ShimSerial("console") { shim_console = this; }
};
#endif
