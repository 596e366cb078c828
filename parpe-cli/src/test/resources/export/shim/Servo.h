// Stand-in for the Arduino Servo library: prints every pulse as "servo PIN US".
#ifndef SHIM_SERVO_H
#define SHIM_SERVO_H
#include <stdio.h>
#include <stdint.h>

class Servo {
public:
    uint8_t attach(int pin, int min, int max) { pin_ = pin; printf("attach %d %d %d\n", pin, min, max); return 0; }
    void writeMicroseconds(int us) { printf("servo %d %d\n", pin_, us); }
private:
    int pin_ = -1;
};
#endif
