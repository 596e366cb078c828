package org.parpe.cli.hw;

import java.nio.file.Path;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.TargetException;
import org.parpe.core.xml.InputFiles;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileReader;

/** Loads the hardware profile named by {@code --hardware}, for run, record and calibrate. */
final class Profiles {
    private Profiles() {
    }

    /**
     * Reads {@code file}; {@code port}, when given, replaces the profile's port.
     *
     * @throws TargetException with every problem of the file, located
     */
    static HardwareProfile load(Path file, String port) throws TargetException {
        try {
            InputFiles.check(file);
        } catch (java.io.IOException e) {
            throw new TargetException(SourcePos.origin("--hardware"), "cannot read the hardware profile '" + file + "': "
                    + e.getMessage());
        }
        DiagnosticList diags = new DiagnosticList();
        HardwareProfile p = ProfileReader.read(file, diags);
        if (p == null) {
            throw new TargetException("the hardware profile " + file + " has " + diags.errorCount() + " error"
                    + (diags.errorCount() == 1 ? "" : "s"), diags.all());
        }
        return port == null ? p : p.withPort(port);
    }
}
