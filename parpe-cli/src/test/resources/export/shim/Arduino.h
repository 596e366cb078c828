// A tiny stand-in for the Arduino core, enough to compile and run an exported sketch on a PC:
// the test driver advances time and feeds input; serial output and servo pulses go to stdout
// as lines "PORT: text", "PORT: HEX BYTES" and "servo PIN US".
#ifndef SHIM_ARDUINO_H
#define SHIM_ARDUINO_H
#include <stdint.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <math.h>

#define HIGH 1
#define LOW 0
#define OUTPUT 1
#define F(s) (s)

extern unsigned long shim_micros;
inline unsigned long micros() { return shim_micros; }
inline unsigned long millis() { return shim_micros / 1000; }
inline void pinMode(uint8_t, uint8_t) {}
inline void digitalWrite(uint8_t, uint8_t) {}

class ShimSerial {
public:
    explicit ShimSerial(const char *name) : name_(name) {}
    void begin(unsigned long) {}
    int available() { return (int) (len_ - pos_); }
    int read() { return pos_ < len_ ? (unsigned char) in_[pos_++] : -1; }
    void feed(const char *s) {
        size_t n = strlen(s);
        if (len_ + n <= sizeof in_) {
            memcpy(in_ + len_, s, n);
            len_ += n;
        }
    }
    size_t write(const uint8_t *b, size_t n) {
        start();
        for (size_t i = 0; i < n; i++) {
            printf("%s%02X", i == 0 ? "" : " ", b[i]);
        }
        end();
        return n;
    }
    void flush() {}
    void print(const char *s) { start(); printf("%s", s); }
    void print(long v) { start(); printf("%ld", v); }
    void print(int v) { print((long) v); }
    void print(unsigned int v) { print((long) v); }
    void print(unsigned long v) { start(); printf("%lu", v); }
    void println(const char *s) { print(s); end(); }
private:
    void start() {
        if (!open_) {
            printf("%s: ", name_);
            open_ = true;
        }
    }
    void end() {
        printf("\n");
        open_ = false;
    }
    const char *name_;
    char in_[1024] = {0};
    size_t len_ = 0;
    size_t pos_ = 0;
    bool open_ = false;
};

extern ShimSerial Serial;
extern ShimSerial Serial2;  // the ESP32's second UART
#endif
