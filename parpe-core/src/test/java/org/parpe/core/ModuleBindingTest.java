package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.EvalContext;
import org.parpe.core.expr.EvalException;
import org.parpe.core.expr.ExprCompiler;
import org.parpe.core.expr.ExprTree;
import org.parpe.core.expr.Expression;
import org.parpe.core.expr.Node;
import org.parpe.core.expr.Scope;
import org.parpe.core.xml.XText;

/**
 * {@link Expression#bind}: a target bound to one module of a group (issue 36, the scheduler
 * computes what depends only on the module once per run) gives what the unbound expression
 * gives with the context entered for that module, bit for bit, and fails with the same message
 * where that one fails; the bound one is evaluated in a context whose {@code $index},
 * {@code $count} and {@code $id} are wrong, to show it no longer reads them.
 */
class ModuleBindingTest {
    private static final Scope MODULE = new Scope(Scope.Kind.MODULE, Map.of("amp", 30.0), Map.of("speed", 0), Map.of(),
            Set.of(), Map.of(), Set.of(), Scope.SensorCatalog.NONE);
    private static final int[] IDS = {10, 11, 12, 13, 14};

    private static Expression compile(String text) {
        DiagnosticList d = new DiagnosticList();
        ExprCompiler.Result r = ExprCompiler.compile(XText.detached(text, new SourcePos("t", 1, 1)), MODULE, d);
        assertNotNull(r, () -> text + ": " + d.all());
        return r.expression();
    }

    private static EvalContext context(int index, int count, int id, double phase) {
        EvalContext c = new EvalContext();
        c.controls = new double[] {1.7};
        c.index = index;
        c.count = count;
        c.id = id;
        c.phase = phase;
        c.cycle = 3;
        c.time = 12.345;
        c.btime = 2.5;
        c.random = new SplittableRandom(7);
        return c;
    }

    /** The value, or the message of the failure. */
    private static String outcome(Expression e, EvalContext c) {
        try {
            return Long.toHexString(Double.doubleToRawLongBits(e.eval(c)));
        } catch (EvalException x) {
            return "fails: " + x.getMessage();
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "amp*sin(2*pi*$phase) + 2*cos(pi*$index/$count)",
        "-amp*sin(2*pi*$phase + 0.5) - 5*$cycle/($cycle+1) + $index",
        "$phase*$index + $id - $count",
        "if($index > 2, sin($phase), $count / 3)",
        "1/($index - 2) + $phase",
        "sqrt($index - 3) * $speed",
        "sum($index, $id, $phase, 0.1)",
        "-$index % 3 + mod($id, 4) ^ 2",
        "($index == 1) || $phase > 0.5",
        "!($index < 2) && atan2($id, $count) > 0.7",
        "rand() * $index + $time - $btime",
        "log($count - $index - 1) + exp($id / 7) + tanh($index)",
        "min($index, 2) * max($phase, $id % 2) + round($id / 3) - floor(-$index / 2) + ceil($count / 4) + abs(-$id)",
    })
    void boundGivesWhatTheModuleSawBitForBit(String text) {
        Expression e = compile(text);
        for (double phase : new double[] {0, 0.3, 0.75}) {
            for (int k = 0; k < IDS.length; k++) {
                Expression bound = e.bind(k, IDS.length, IDS[k]);
                assertEquals(e.text(), bound.text());
                assertEquals(e.pos(), bound.pos());
                assertEquals(outcome(e, context(k, IDS.length, IDS[k], phase)),
                        outcome(bound, context(-99, 1000, -7, phase)), () -> text);
            }
        }
    }

    @Test
    void aPartThatDependsOnlyOnTheModuleIsComputedOnce() {
        assertTrue(compile("2*cos(pi*$index/$count) + $id").bind(3, 5, 13).isConstant());
        Expression wave = compile("amp*sin(2*pi*$phase) + 2*cos(pi*$index/$count)").bind(1, 5, 11);
        assertFalse(wave.isConstant());
        assertFalse(ExprTree.visit(wave.root(), new ExprTree.Question(false) {
            @Override
            public Boolean variable(String name) {
                return name.equals("index") || name.equals("count");
            }

            @Override
            public Boolean function1(String name, Node arg) {
                return name.equals("cos") || operands(arg);
            }
        }), "the cosine of the module is a number now");
    }

    @Test
    void anExpressionThatReadsNoneOfTheModuleIsItself() {
        Expression e = compile("amp*sin(2*pi*$phase) + $speed");
        assertSame(e, e.bind(2, 5, 12));
    }
}
