package org.parpe.cli.options;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.cli.text.CliMsg;
import org.parpe.core.lang.Numbers;

/** The {@code --param NAME=VALUE} options of run, sweep, optimize and export. */
public final class ParamValues {
    private ParamValues() {
    }

    /** The values by name, in the order given; a bad option is a usage error naming it. */
    public static Map<String, Double> parse(List<String> params) throws UsageException {
        Map<String, Double> out = new LinkedHashMap<>();
        for (String p : params) {
            int eq = p.indexOf('=');
            if (eq <= 0) {
                throw new UsageException(CliMsg.PARAM_SYNTAX.text(p));
            }
            String name = p.substring(0, eq).trim();
            Double v = Numbers.parsePlain(p.substring(eq + 1));
            if (v == null) {
                throw new UsageException(CliMsg.PARAM_NOT_A_NUMBER.text(name, p.substring(eq + 1)));
            }
            out.put(name, v);
        }
        return out;
    }
}
