package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Issue 38: picocli's own parse errors are told in the user's language (before, always in
 * English, whatever {@code --lang} said), each kind by its exception's type, with picocli's
 * suggestions kept; in English they are picocli's words, as picocli 4.7 writes them
 * ({@code CommandLine.java}: {@code UnmatchedArgumentException.describe},
 * {@code createMissingParameterMessage}, {@code createMissingParameterMessageFoundOtherOption},
 * {@code tryConvert}, {@code BuiltIn.fail}, the enum converter, {@code OverwrittenOptionException}'s
 * {@code should be specified only once}, {@code GroupValidationResult}'s {@code specify one of these}).
 */
class ParseErrorsTest {

    /** {@code parpe COMMAND --lang de ARGS}: before the other arguments, so no option takes it for its value. */
    private static Cli german(String... args) {
        List<String> all = new ArrayList<>(List.of(args));
        all.addAll(1, List.of("--lang", "de"));
        return Cli.run(all);
    }

    /** The first line of standard error, after {@code parpe: }. */
    private static String error(Cli c) {
        assertEquals(2, c.code, c.toString());
        String first = c.err.lines().findFirst().orElse("");
        return first.startsWith("parpe: ") ? first.substring("parpe: ".length()) : c.err;
    }

    @Test
    void anUnknownOptionIsToldInGermanWithTheHintToHelp() {
        assertEquals("parpe: Unknown option: '--bogus'\nTry 'parpe check --help' for usage.\n", Cli.run("check", "x.xml", "--bogus").err);
        assertEquals("parpe: unbekannte Option: '--bogus'\nHilfe: 'parpe check --help'.\n", german("check", "x.xml", "--bogus").err);
    }

    /** {@code parpe diagram x.xml --out x.svg ARGS}. */
    private static String[] diagram(String... args) {
        List<String> all = new ArrayList<>(List.of("diagram", "x.xml", "--out", "x.svg"));
        all.addAll(List.of(args));
        return all.toArray(String[]::new);
    }

    @Test
    void anArgumentTooManyIsToldInGerman() {
        String en = error(Cli.run(diagram("y.xml")));
        assertTrue(en.matches("Unmatched argument at index \\d+: 'y.xml'"), en);
        // picocli counts every argument, so in German two more: --lang de
        int at = Integer.parseInt(en.substring("Unmatched argument at index ".length(), en.indexOf(':')));
        assertEquals("überzähliges Argument an Stelle " + (at + 2) + ": 'y.xml'", error(german(diagram("y.xml"))));
    }

    @Test
    void picocliSuggestionsAreKeptInTheChosenLanguage() {
        String en = Cli.run(diagram("--vie", "ring")).err;
        String de = german(diagram("--vie", "ring")).err;
        assertEquals("Unknown options: '--vie', 'ring'", en.lines().findFirst().orElseThrow().substring("parpe: ".length()));
        assertEquals("Possible solutions: --view", en.lines().skip(1).findFirst().orElseThrow());
        assertEquals("parpe: unbekannte Optionen: '--vie', 'ring'\ngemeint ist vielleicht: --view\nHilfe: 'parpe diagram --help'.\n", de);
    }

    @Test
    void aMissingParameterOrValueIsToldInGerman() {
        assertEquals("Missing required parameter: 'FILE|DIR'", error(Cli.run("check")));
        assertEquals("es fehlt der Parameter 'FILE|DIR'", error(german("check")));
        assertEquals("Missing required option: '--out=FILE'", error(Cli.run("diagram", "x.xml")));
        assertEquals("es fehlt die Option '--out=FILE'", error(german("diagram", "x.xml")));
        assertEquals("Missing required parameter for option '--tick' (S)", error(Cli.run(diagram("--tick"))));
        assertEquals("der Wert für die Option '--tick' (S) fehlt", error(german(diagram("--tick"))));
        assertEquals("Expected parameter for option '--tick' but found '--duration'",
                error(Cli.run(diagram("--tick", "--duration", "3"))));
        assertEquals("erwartet wurde ein Wert für die Option '--tick', gefunden wurde aber '--duration'",
                error(german(diagram("--tick", "--duration", "3"))));
    }

    @Test
    void anInvalidValueIsToldInGerman() {
        assertEquals("Invalid value for option '--tick': 'abc' is not a double", error(Cli.run(diagram("--tick", "abc"))));
        assertEquals("ungültiger Wert für die Option '--tick': 'abc' ist keine Zahl",
                error(german(diagram("--tick", "abc"))));
        assertEquals("ungültiger Wert für die Option '--tick': '--bogus' ist keine Zahl",
                error(german(diagram("--tick", "--bogus"))));
        assertEquals("Invalid value for option '--view': expected one of [program, lanes, ring, phase, gait] (case-sensitive) "
                + "but was 'circle'", error(Cli.run(diagram("--view", "circle"))));
        assertEquals("ungültiger Wert für die Option '--view': erwartet wird eines von [program, lanes, ring, phase, gait] "
                + "(Groß- und Kleinschreibung zählen), angegeben ist aber 'circle'", error(german(diagram("--view", "circle"))));
    }

    @Test
    void aValueForAFlagThatIsNoBooleanIsToldInGerman() {
        assertEquals("Invalid value for option '--check': 'yes' is not a boolean", error(Cli.run("robot", "snake:n=4", "--check=yes")));
        assertEquals("ungültiger Wert für die Option '--check': 'yes' ist weder true noch false",
                error(german("robot", "snake:n=4", "--check=yes")));
    }

    @Test
    void anOptionGivenTwiceAndAGroupsChoiceAreToldInGerman() {
        assertEquals("option '--tick' (S) should be specified only once",
                error(Cli.run(diagram("--tick", "0.01", "--tick", "0.02"))));
        assertEquals("die Option '--tick' (S) darf nur einmal angegeben werden",
                error(german(diagram("--tick", "0.01", "--tick", "0.02"))));
        String[] record = {"record", "--port", "/dev/null", "--group", "g", "--out", "r.xml"};
        assertEquals("Error: Missing required argument (specify one of these): (--script=FILE | --modules=IDS)", error(Cli.run(record)));
        assertEquals("es fehlt eines dieser Argumente: (--script=FILE | --modules=IDS)", error(german(record)));
        String[] both = {"record", "--port", "/dev/null", "--group", "g", "--out", "r.xml", "--script", "a.xml", "--modules", "0..3"};
        assertEquals("Error: --script=FILE, --modules=IDS are mutually exclusive (specify only one)", error(Cli.run(both)));
        assertEquals("--script=FILE, --modules=IDS schließen einander aus (gib nur eines davon an)", error(german(both)));
    }
}
