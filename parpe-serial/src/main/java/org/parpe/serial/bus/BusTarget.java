package org.parpe.serial.bus;

import java.io.IOException;
import java.util.function.Consumer;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunTarget;
import org.parpe.core.run.TargetException;
import org.parpe.serial.link.LinkOpener;

/**
 * Modules on a serial bus as a run target, for the command line's {@code --port} and the IDE's
 * Hardware target alike: opens the bus, pings the script's modules before anything moves
 * (reporting the missing ones), and adds the bus as a plant, as the sensor source (priority
 * {@link org.parpe.core.run.SourceKind#HARDWARE}, above the simulator), and as trace columns {@code hw<ID>}. The run is
 * paced to the wall clock. A run stopped by the user ends in an emergency stop. Bus problems
 * become warnings located at {@code bus PORT}; notes (counts, recoveries) go to {@code notes}.
 */
public final class BusTarget implements RunTarget {
    private final String port;
    private final BusConfig config;
    private final LinkOpener opener;
    private final Consumer<String> notes;
    private HardwareBus bus;

    /** The bus on serial device {@code port} with {@code config}; notes for the user go to {@code notes}. */
    public BusTarget(String port, BusConfig config, Consumer<String> notes) {
        this(port, config, port == null ? null : LinkOpener.serial(port, config.baud()), notes);
    }

    /** The bus reached through {@code opener} (tests, benchmarks), named {@code port} in messages. */
    public BusTarget(String port, BusConfig config, LinkOpener opener, Consumer<String> notes) {
        this.port = port;
        this.config = config;
        this.opener = opener;
        this.notes = notes;
    }

    @Override
    public void attach(Run.Builder run) throws TargetException {
        if (port == null || port.isBlank()) {
            throw new TargetException(SourcePos.origin("hardware"),
                    "no serial port chosen; choose the port the robot is connected to (e.g. /dev/ttyUSB0 or COM3)");
        }
        SourcePos where = SourcePos.origin("bus " + port);
        DiagnosticSink diags = run.diagnostics();
        HardwareBus hw;
        try {
            hw = HardwareBus.open(opener, config, HostPlant.reportTo(where, diags, notes));
        } catch (IOException e) {
            throw new TargetException(where, "cannot open the serial device: " + HostPlant.message(e));
        }
        run.closeAtEnd(hw);
        int[] ids = run.program().moduleIds();
        Discovery d;
        try {
            d = hw.discover(ids);
        } catch (IOException e) {
            throw new TargetException(where, "the bus failed while looking for modules: " + HostPlant.message(e));
        }
        int[] found = d.found().stream().mapToInt(Integer::intValue).toArray();
        notes.accept("bus " + port + ": " + found.length + " of " + ids.length + " modules answer"
                + (found.length == 0 ? "" : " (" + Discovery.format(found) + ")"));
        if (!d.missing().isEmpty()) {
            diags.warning(where, "modules " + Discovery.format(d.missing()) + " of the script do not answer; they will not move");
        }
        if (!d.unaddressable().isEmpty()) {
            diags.warning(where, "modules " + Discovery.format(d.unaddressable())
                    + " cannot be on the bus (IDs 0..254); they will not move");
        }
        if (found.length == 0) {
            throw new TargetException(where, "no module answers on " + port + " at " + config.baud()
                    + " baud (is the robot powered and connected, and is the baud rate right?)");
        }
        HostPlant.attachTo(run, hw, ids);
        bus = hw;
    }

    /** The bus attached last (null before {@link #attach}). */
    public HardwareBus bus() {
        return bus;
    }
}
