package org.parpe.cli.text;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.text.Message;
import picocli.CommandLine.MissingParameterException;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;
import picocli.CommandLine.MutuallyExclusiveArgsException;
import picocli.CommandLine.OverwrittenOptionException;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.TypeConversionException;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * picocli's own parse errors in the user's language (issue 38): an unknown option, a missing
 * parameter, a value that is not a number, an option given twice, ... Each is rebuilt by its
 * exception's type from its parts (the option's name and label, the value, the unmatched words)
 * with {@link CliMsg} keys whose English texts are picocli 4.7's wording. A message whose English
 * rebuild is not picocli's own text word for word (a wording this class does not know, e.g. after
 * a picocli upgrade) is shown as picocli wrote it, in English, rather than wrongly; so {@code --lang
 * en} prints exactly what picocli prints. Used by every picocli command line of PARPE: {@code parpe}
 * and the IDE's own, {@code parpe gui}.
 */
public final class ParseErrors {
    private static final Pattern INDEX = Pattern.compile("^Unmatched arguments? (?:at|from) index (\\d+): ");
    private static final Pattern MISSING_FOR = Pattern.compile("Missing required parameter for (.*)");
    private static final Pattern FOUND = Pattern.compile("Expected parameter for .* but found '(.*)'");
    private static final Pattern ONE_OF = Pattern.compile("Error: Missing required argument \\(specify one of these\\): (.*)");
    private static final Pattern EXCLUSIVE = Pattern.compile("Error: (.*) are mutually exclusive \\(specify only one\\)");
    private static final Pattern NOT_A = Pattern.compile("'(.*)' is not an? (int|long|double|boolean)");
    private static final Pattern ENUM = Pattern.compile("expected one of \\[(.*)\\] \\(case-sensitive\\) but was '(.*)'");

    private ParseErrors() {
    }

    /** The error in the chosen language; picocli's English text where its wording is not known here. */
    public static Message of(ParameterException ex) {
        Message m = rebuilt(ex);
        return m != null && m.format(Locale.ENGLISH).equals(ex.getMessage()) ? m : Message.verbatim(ex.getMessage());
    }

    /**
     * picocli's suggestions for an unknown option ({@code Possible solutions: --lang, --list}) in
     * the chosen language, or picocli's own line for other suggestions; nothing without any.
     */
    public static void printSuggestions(ParameterException ex, PrintStream err) {
        if (ex instanceof UnmatchedArgumentException u && u.isUnknownOption() && !u.getSuggestions().isEmpty()) {
            err.println(CliMsg.PICOCLI_POSSIBLE_SOLUTIONS.text(String.join(", ", u.getSuggestions())));
        } else {
            UnmatchedArgumentException.printSuggestions(ex, err);
        }
    }

    private static Message rebuilt(ParameterException ex) {
        String text = String.valueOf(ex.getMessage());
        if (ex instanceof UnmatchedArgumentException u) {
            return unmatched(u, text);
        }
        if (ex instanceof MissingParameterException m) {
            return missing(m.getMissing(), text);
        }
        if (ex instanceof OverwrittenOptionException o) {
            return Message.of(CliMsg.PICOCLI_ONLY_ONCE, describe(o.getOverwritten(), 0));
        }
        if (ex instanceof MutuallyExclusiveArgsException) {
            Matcher x = EXCLUSIVE.matcher(text);
            return x.matches() ? Message.of(CliMsg.PICOCLI_EXCLUSIVE, x.group(1)) : null;
        }
        if (ex.getCause() instanceof TypeConversionException t && ex.getArgSpec() != null) {
            // picocli names a single value's option without its label, one of several values with it
            int index = ex.getArgSpec().arity().max() > 1 ? 0 : -1;
            return Message.of(CliMsg.PICOCLI_INVALID_VALUE, describe(ex.getArgSpec(), index), conversion(t.getMessage()));
        }
        return null;
    }

    /** {@code Unknown option: '--x'}, {@code Unmatched argument at index 2: 'y'}, ... */
    private static Message unmatched(UnmatchedArgumentException u, String text) {
        List<String> words = u.getUnmatched();
        if (words.isEmpty()) {
            return null;
        }
        List<String> quoted = new ArrayList<>();
        words.forEach(w -> quoted.add("'" + w + "'"));
        String list = String.join(", ", quoted);
        if (u.isUnknownOption()) {
            return Message.of(words.size() == 1 ? CliMsg.PICOCLI_UNKNOWN_OPTION : CliMsg.PICOCLI_UNKNOWN_OPTIONS, list);
        }
        Matcher index = INDEX.matcher(text);
        return index.find() ? Message.of(words.size() == 1 ? CliMsg.PICOCLI_UNMATCHED_ARGUMENT : CliMsg.PICOCLI_UNMATCHED_ARGUMENTS,
                index.group(1), list) : null;
    }

    /** {@code Missing required parameter: '<file>'}, {@code Expected parameter for option '--tick' but found '--x'}, ... */
    private static Message missing(List<ArgSpec> missing, String text) {
        Matcher found = FOUND.matcher(text);
        Matcher oneOf = ONE_OF.matcher(text);
        if (oneOf.matches()) {
            return Message.of(CliMsg.PICOCLI_ONE_OF, oneOf.group(1));
        }
        if (missing.isEmpty()) {
            return null;
        }
        if (found.matches()) {
            return Message.of(CliMsg.PICOCLI_EXPECTED, describe(missing.get(0), -1), found.group(1));
        }
        if (MISSING_FOR.matcher(text).matches()) {
            return Message.of(CliMsg.PICOCLI_MISSING_FOR, describe(missing.get(0), 0));
        }
        long options = missing.stream().filter(ArgSpec::isOption).count();
        boolean many = missing.size() > 1;
        CliMsg key = options == 0 ? (many ? CliMsg.PICOCLI_MISSING_PARAMETERS : CliMsg.PICOCLI_MISSING_PARAMETER)
                : options == missing.size() ? (many ? CliMsg.PICOCLI_MISSING_OPTIONS : CliMsg.PICOCLI_MISSING_OPTION)
                : CliMsg.PICOCLI_MISSING_BOTH;
        List<String> names = new ArrayList<>();
        for (ArgSpec a : missing) {
            names.add("'" + (a instanceof OptionSpec o ? o.longestName() + (a.arity().min() > 0 ? "=" + a.paramLabel() : "")
                    : a.paramLabel()) + "'");
        }
        return Message.of(key, String.join(", ", names));
    }

    /**
     * An option or positional parameter as picocli names it in messages: {@code option '--tick'}
     * without its value ({@code index} < 0), else with its label, {@code option '--tick' (SECONDS)};
     * {@code positional parameter at index 0 (FILE)}.
     */
    private static Message describe(ArgSpec a, int index) {
        if (a instanceof PositionalParamSpec p) {
            return Message.of(CliMsg.PICOCLI_POSITIONAL, p.index(), a.paramLabel());
        }
        String name = ((OptionSpec) a).longestName();
        if (index < 0 || a.arity().max() == 0) {
            return Message.of(CliMsg.PICOCLI_OPTION, name);
        }
        return a.arity().max() > 1 ? Message.of(CliMsg.PICOCLI_OPTION_AT, name, index, a.paramLabel())
                : Message.of(CliMsg.PICOCLI_OPTION_LABEL, name, a.paramLabel());
    }

    /** A converter's complaint: {@code 'x' is not a double}, {@code expected one of [a, b] ...}; else as it is. */
    private static Message conversion(String text) {
        Matcher n = NOT_A.matcher(text);
        if (n.matches()) {
            CliMsg key = switch (n.group(2)) {
                case "int" -> CliMsg.PICOCLI_NOT_INT;
                case "long" -> CliMsg.PICOCLI_NOT_LONG;
                case "double" -> CliMsg.PICOCLI_NOT_DOUBLE;
                default -> CliMsg.PICOCLI_NOT_BOOLEAN;
            };
            return Message.of(key, n.group(1));
        }
        Matcher e = ENUM.matcher(text);
        return e.matches() ? Message.of(CliMsg.PICOCLI_NOT_ONE_OF, e.group(1), e.group(2)) : Message.verbatim(text);
    }
}
