package org.parpe.core.text;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The scan the modules' text tests run: it finds prose and passes code, PARSL, comments and what is allowed. */
class ProseLiteralsTest {
    @Test
    void theScanTellsProseFromCode() {
        String java = String.join("\n",
                "class A {",
                "  @Option(names = \"--x\", description = \"annotations are the English help\") String x;",
                "  void f() {",
                "    report(\"bus: \" + \"no reply from any servo\"); // \"a comment\"",
                "    s.replace(\"<states>\", \"\\t\"); x(\"<up angles=\\\"30\\\"/>\"); f(\"*.xml\", \"%.2f s\");",
                "    throw new IllegalStateException(\"the bus thread is not running\");",
                "  }",
                "  String t = \"\"\"",
                "      two words",
                "      \"\"\";",
                "  String ok = \"simulated robot \";",
                "  String de = \"Modul\";",
                "}");
        assertEquals(List.of("A.java:4: \"no reply from any servo\"", "A.java:8: \"\\n      two words\\n      \"",
                "A.java:12: \"Modul\""), ProseLiterals.in("A.java", java, Set.of("simulated robot ")::contains)
                .stream().map(l -> l.replace("\n", "\\n")).toList());
    }
}
