package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.EvalContext;
import org.parpe.core.expr.EvalException;
import org.parpe.core.expr.ExprCompiler;
import org.parpe.core.expr.Scope;
import org.parpe.core.xml.XText;

/** JEP compatibility of PARSL expressions (PARSL.md §8, §13 rule 16). */
class ExpressionTest {
    private static final Scope SCOPE = new Scope(Scope.Kind.ENTRY, Map.of("a", 2.0, "speed", 3.0),
            Map.of("pick", 0), Map.of("red", 1, "green", 2, "blue", 3), Set.of("legs"), Map.of(), Set.of(),
            Scope.SensorCatalog.NONE);

    static double eval(String text) {
        DiagnosticList d = new DiagnosticList();
        ExprCompiler.Result r = ExprCompiler.compile(XText.detached(text, new SourcePos("t", 1, 1)), SCOPE, d);
        assertNotNull(r, () -> text + ": " + d.all());
        EvalContext c = new EvalContext();
        c.controls = new double[] {2};
        return r.expression().eval(c);
    }

    @ParameterizedTest(name = "{0} = {1}")
    @CsvSource(delimiter = ';', value = {
        "log(1000); 3",
        "ln(e^2); 2",
        "2^3^2; 512",
        "-2^2; -4",
        "2^-1; 0.5",
        "(-2)^2; 4",
        "7 % 3; 1",
        "-7 % 3; -1",
        "7 % -3; 1",
        "mod(-7, 3); -1",
        "1 + 2 * 3; 7",
        "(1 + 2) * 3; 9",
        "12 / 4 / 3; 1",
        "1 - 2 - 3; -4",
        "2 * 3 ^ 2; 18",
        "-3 * -2; 6",
        "1 < 2; 1",
        "2 <= 1; 0",
        "1 == 1 && 0 || 1; 1",
        "1 || 0 && 0; 1",
        "!0 + 1; 2",
        "!(1 == 2); 1",
        "1 + 1 == 2; 1",
        "3 > 2 == 1; 1",
        "round(-2.5); -2",
        "round(2.5); 3",
        "round(-2.4); -2",
        "floor(-1.5) + ceil(1.2); 0",
        "if(0, 100, 5); 5",
        "if(a > 1, 10, 20); 10",
        "sum(1, 2, 3, 4); 10",
        "sum(7); 7",
        "min(3, 4) + max(1, 2); 5",
        "abs(-3) + sqrt(16); 7",
        "deg(atan2(1, 1)); 45",
        "rad(180) - pi; 0",
        "sin(pi/6) * 2; 1",
        "$pick == green; 1",
        "$pick == \"green\"; 1",
        "$pick != blue; 1",
        "green; 2",
        "a * speed; 6",
        ".5 + 1e1 + 1E-1; 10.6",
        "true + false; 1",
        "sinh(0) + cosh(0) + tanh(0) + asinh(0) + atanh(0); 1",
        "acosh(1) + asin(1) * 2 / pi + acos(1) + atan(0); 1",
        "exp(0) + tan(0); 1"
    })
    void jep(String expr, double expected) {
        assertEquals(expected, eval(expr), 1e-12, expr);
    }

    @ParameterizedTest(name = "{0} fails at run time")
    @CsvSource(delimiter = ';', value = {"log(0)", "asin(2)", "0^-1", "1/0", "sqrt(-1)", "mod(1, 0)", "ln(-1)", "1 % 0"})
    void nonFiniteValuesAreErrors(String expr) {
        assertThrows(EvalException.class, () -> eval("a * 0 + " + expr.replace("0", "(a - 2)").replace("1", "(a - 1)")));
    }

    @Test
    void shortCircuitAvoidsErrorsInTheBranchNotTaken() {
        assertEquals(0, eval("if(a > 5, log(a - 2), 0)"));
        assertEquals(0, eval("a < 1 && log(a - 2) > 0"));
        assertEquals(1, eval("a > 1 || log(a - 2) > 0"));
    }

    @Test
    void constantsAreFoldedButVariablesAreNot() {
        DiagnosticList d = new DiagnosticList();
        assertTrue(ExprCompiler.compile(XText.detached("2 * a + sin(0)", SourcePos.NONE), SCOPE, d).expression().isConstant());
        assertTrue(!ExprCompiler.compile(XText.detached("$pick + 1", SourcePos.NONE), SCOPE, d).expression().isConstant());
    }

    @Test
    void implicitMultiplicationIsOff() {
        DiagnosticList d = new DiagnosticList();
        assertNull(ExprCompiler.compile(XText.detached("speeda", SourcePos.NONE), SCOPE, d));
        assertTrue(d.all().get(0).message().contains("unknown name 'speeda'"), d.all().toString());
        DiagnosticList d2 = new DiagnosticList();
        assertNull(ExprCompiler.compile(XText.detached("2a", SourcePos.NONE), SCOPE, d2));
    }

    @Test
    void errorColumnsPointInsideTheAttribute() {
        DiagnosticList d = new DiagnosticList();
        ExprCompiler.compile(XText.detached("1 + nope", new SourcePos("f", 3, 10)), SCOPE, d);
        assertEquals(1, d.all().size());
    }
}
