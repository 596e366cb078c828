package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.g1.BusMaster;
import org.parpe.serial.g1.emu.BusEmulator;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.PipeLink;
import org.parpe.serial.g1.Command;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.emu.ServoEmulator;

/** The one emulator console (docs/cli.md, emulate) over a G1 and a Dynamixel emulator: the same words, each protocol's own. */
class ConsoleCommandsTest {

    static String say(ConsoleCommands.Console c, String line) {
        return ConsoleCommands.apply(c, line.trim().split("\\s+"));
    }

    @Test
    void g1ModulesArePosedWhileLimpAndTouched() throws Exception {
        PipeLink[] pipe = PipeLink.pair("console");
        try (BusEmulator emu = BusEmulator.start(() -> pipe[1], EmulatorOptions.of(1, 2), new EmulatorListener() { })) {
            ConsoleCommands.Console c = ConsoleCommands.of(emu);
            assertEquals("module 1 is driven by its servo; it can be posed only while limp", say(c, "pose 1 30"));
            try (BusMaster host = new BusMaster(pipe[0], BusConfig.defaults())) {
                host.send(1, Command.LIMP);
                long deadline = System.nanoTime() + 5_000_000_000L;
                while (!emu.isLimp(1)) {
                    assertTrue(System.nanoTime() < deadline, "module 1 did not go limp");
                    Thread.sleep(5);
                }
            }
            assertEquals("module 1 posed at 30°", say(c, "pose 1 30"));
            assertEquals("module 2 touch left", say(c, "touch 2 left"));
            assertEquals("module 1: 30.00° limp\nmodule 2: 0.00°", say(c, "status").replace(System.lineSeparator(), "\n"));
            assertEquals("usage: touch ID left|right|both|none", say(c, "touch 2"));
            assertEquals("usage: pose ID DEGREES", say(c, "pose 1"));
            assertEquals("error: touch side must be left, right, both or none, got 'up'", say(c, "touch 2 up"));
            assertEquals("unknown command 'fault'; try pose, touch, status or quit", say(c, "fault 1 overload"));
        }
    }

    @Test
    void servosArePosedWhileLimpAndGivenFaults() throws Exception {
        PipeLink[] pipe = PipeLink.pair("console");
        try (ServoEmulator emu = ServoEmulator.start(() -> pipe[1], ServoModel.named("xl430-w250"), EmulatorOptions.of(3),
                new EmulatorListener() { })) {
            ConsoleCommands.Console c = ServoEmulation.console(emu);
            assertEquals("servo 3 posed at 10°", say(c, "pose 3 10"));
            assertEquals("servo 3 fault overload", say(c, "fault 3 overload"));
            assertEquals("servo 3: 10.00° limp error 0x20", say(c, "status"));
            assertEquals("unknown command 'touch'; try pose, fault, status or quit", say(c, "touch 3 left"));
            assertEquals("error: servo 9 is not emulated", say(c, "pose 9 10"));
        }
    }
}
