package org.parpe.gui.sweep;

import java.nio.file.Path;

/** The package-private parts of the Sweep dialog that tests in other packages check. */
public final class SweepDialogAccess {
    private SweepDialogAccess() {
    }

    /** {@link SweepDialog#csvFolder}. */
    public static Path csvFolder(Path script, Path home) {
        return SweepDialog.csvFolder(script, home);
    }
}
