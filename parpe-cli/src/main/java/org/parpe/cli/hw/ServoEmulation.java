package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import org.parpe.cli.options.UsageException;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.emu.ServoEmulator;

/**
 * {@code parpe emulate --protocol dxl2|sts|scs}: serves emulated servos until Ctrl-C, {@code quit}
 * or {@code --duration}. Console lines: {@code pose ID DEG} (move a limp servo by hand),
 * {@code fault ID overload|overheat|voltage|none}, {@code status}.
 */
final class ServoEmulation {
    private final String port;
    private final int baud;
    private final ServoModel model;
    private final EmulatorOptions options;
    private final Double duration;
    private final Path log;
    private final PrintWriter err;

    ServoEmulation(String port, int baud, ServoModel model, EmulatorOptions options, Double duration, Path log,
                   PrintWriter err) {
        this.port = port;
        this.baud = baud;
        this.model = model;
        this.options = options;
        this.duration = duration;
        this.log = log;
        this.err = err;
    }

    int serve(InputStream input) throws UsageException, InterruptedException {
        int[] ids = options.modules();
        EmulateCommand.SetpointLog csv = EmulateCommand.SetpointLog.open(log, ids);
        ServoEmulator emu;
        try {
            emu = ServoEmulator.start(LinkOpener.serial(port, baud), model, options, EmulateCommand.listener(err, csv));
        } catch (IOException | IllegalArgumentException e) {
            csv.close();
            throw new UsageException(e.getMessage());
        }
        err.println("emulate: " + CliMsg.EMULATING_SERVOS.text(ids.length, model.protocol().key(), model.label(),
                ModuleList.format(ids), port, baud));
        return EmulateCommand.serveUntilDone(() -> {
            emu.close();
            csv.close();
            ServoEmulator.Stats s = emu.stats();
            err.println("emulate: " + CliMsg.SERVO_EMULATION_STATS.text(s.packets(), s.checksumErrors(), s.dropped(),
                    s.corrupted(), s.replies()));
        }, w -> ConsoleCommands.apply(console(emu), w), duration, input, err);
    }

    /** The console of emulated servos: {@code fault ID overload|overheat|voltage|none}. */
    static ConsoleCommands.Console console(ServoEmulator emu) {
        return new ConsoleCommands.Console(CliMsg.UNIT_SERVO, emu::backDrive, CliMsg.TORQUE_ON,
                "fault", "fault ID overload|overheat|voltage|none", (id, what) -> {
                    emu.fault(id, faultBits(what));
                    return CliMsg.UNIT_SERVO.text() + " " + id + " fault " + what;
                }, () -> ConsoleCommands.lines(emu.servoIds(), id -> CliMsg.UNIT_SERVO.text() + String.format(Locale.ROOT, " %d: %.2f°%s%s%s", id,
                        emu.angle(id), emu.isLimp(id) ? " " + CliMsg.LIMP.text() : "", emu.watchdogTripped(id) ? " watchdog" : "",
                        emu.hardwareError(id) != 0 ? String.format(" error 0x%02X", emu.hardwareError(id)) : "")));
    }

    /** The same bits on Dynamixel (Hardware Error Status) and Feetech (servo status). */
    private static int faultBits(String what) {
        return switch (what) {
            case "overload" -> 0x20;
            case "overheat" -> 0x04;
            case "voltage" -> 0x01;
            case "none" -> 0;
            default -> throw new IllegalArgumentException(CliMsg.BAD_FAULT.text(what));
        };
    }
}
