// Stand-in for the ESP32Servo library (same interface as Servo).
#include "Servo.h"
