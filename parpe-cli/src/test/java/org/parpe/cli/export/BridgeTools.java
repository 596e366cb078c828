package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;

/**
 * The other tools a robot export is checked with (issue 34), from Debian's packages and a Python
 * virtual environment that {@code ./test-all} makes: {@code check_urdf} (liburdfdom-tools),
 * {@code ign sdf} (ignition-tools with libsdformat-dev), {@code mujoco-compile} (libmujoco-samples,
 * MuJoCo 2.2.2) and MuJoCo 3's Python package ({@code PARPE_MUJOCO_PYTHON}, else {@code python3}).
 * Missing tools skip the tests on a developer's machine and fail them under CI ({@code CI=true}).
 */
final class BridgeTools {
    static final String PACKAGES = "liburdfdom-tools ignition-tools libsdformat-dev libmujoco-samples";

    private BridgeTools() {
    }

    /** The output of a command that must succeed. */
    static String run(Path dir, List<String> cmd) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(300, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            fail(cmd + " did not finish in 300 s");
        }
        if (p.exitValue() != 0) {
            fail(cmd + " exited " + p.exitValue() + ":\n" + out);
        }
        return out;
    }

    /** Skips (or fails under CI) unless every command runs. */
    static void require(String... commands) {
        List<String> missing = new ArrayList<>();
        for (String c : commands) {
            if (!onPath(c)) {
                missing.add(c);
            }
        }
        if (!missing.isEmpty()) {
            missing(String.join(", ", missing) + ": install them with 'sudo apt-get install " + PACKAGES
                    + "' (./test-all installs them)");
        }
    }

    /** The Python that has MuJoCo 3; skips (or fails under CI) without one. */
    static String python() throws IOException, InterruptedException {
        String py = System.getenv().getOrDefault("PARPE_MUJOCO_PYTHON", "python3");
        Process p = new ProcessBuilder(py, "-c", "import mujoco; print(mujoco.__version__)").redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0 || !out.matches("3\\..*")) {
            missing("MuJoCo 3's Python package (" + py + " says: " + out + "): ./test-all makes a virtual environment"
                    + " with 'pip install mujoco' and names it in PARPE_MUJOCO_PYTHON");
        }
        return py;
    }

    /** Whether an executable {@code name} is on the PATH (these tools have no --version that exits 0). */
    static boolean onPath(String name) {
        for (String d : System.getenv().getOrDefault("PATH", "").split(java.io.File.pathSeparator)) {
            if (!d.isEmpty() && java.nio.file.Files.isExecutable(Path.of(d, name))) {
                return true;
            }
        }
        return false;
    }

    private static void missing(String what) {
        if ("true".equals(System.getenv("CI"))) {
            fail("missing " + what);
        }
        Assumptions.abort("missing " + what);
    }
}
