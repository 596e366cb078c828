package org.parpe.core.export;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The portable C runtime the translation runs on, kept as text resources beside this class ({@code c/}):
 * the tables' layout it reads is not declared there but generated into {@code parsl_program.h} from
 * {@link CLayout}.
 */
public final class CRuntime {
    /** The runtime's files, in every export. */
    public static final List<String> RUNTIME =
            List.of("parsl_rt.h", "parsl_rt.c", "parsl_inst.h", "parsl_inst.c", "parsl_io.c", "parsl_maths.h");
    /** The host trace program's main. */
    public static final String HOST_MAIN = "parsl_host.c";

    private CRuntime() {
    }

    /** The content of resource {@code c/NAME}. */
    public static String read(String name) {
        return read(CRuntime.class, "c/" + name);
    }

    /**
     * The C text of the resource {@code name} beside class {@code owner} (also the board code
     * kept beside the Arduino sketch's writer in parpe-serial).
     */
    public static String read(Class<?> owner, String name) {
        try (InputStream in = owner.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("the runtime file " + name + " is missing from the PARPE jar");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The runtime files, plus the host main if {@code host}. */
    public static Map<String, String> runtime(boolean host) {
        Map<String, String> out = new LinkedHashMap<>();
        for (String f : RUNTIME) {
            out.put(f, read(f));
        }
        if (host) {
            out.put(HOST_MAIN, read(HOST_MAIN));
        }
        return out;
    }
}
