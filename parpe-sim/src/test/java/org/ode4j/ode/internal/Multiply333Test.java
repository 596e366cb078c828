package org.ode4j.ode.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.ode4j.math.DMatrix3;
import org.ode4j.math.DVector3;
import org.ode4j.ode.OdeMath;

/**
 * {@link Multiply333}'s products are bit for bit ODE4j's ({@code OdeMath.dMultiply0_333},
 * {@code dMultiply2_333} and {@code dMultiply0_331} in the ODE4j 0.5.3 jar, which PARPE does not
 * patch): the same roundings, so every trace stays as it was. Entries of every size and sign and
 * signed zeros, where a different order of the additions would round differently; and a product
 * into one of its own factors, where the order the entries are written in shows.
 */
class Multiply333Test {
    private final SplittableRandom pick = new SplittableRandom(36);

    @Test
    void productsAreOdesBitForBit() {
        for (int n = 0; n < 20000; n++) {
            DMatrix3 b = matrix();
            DMatrix3 c = matrix();
            DMatrix3 ode = new DMatrix3();
            DMatrix3 own = new DMatrix3();
            OdeMath.dMultiply0_333(ode, b, c);
            Multiply333.multiply0(own, b, c);
            assertSame(ode, own, "b c, case " + n);
            OdeMath.dMultiply2_333(ode, b, c);
            Multiply333.multiply2(own, b, c);
            assertSame(ode, own, "b c^T, case " + n);

            double[] odeRows = new double[16];
            double[] ownRows = new double[16];
            int ofs = pick.nextInt(5);
            OdeMath.dMultiply0_333(odeRows, ofs, b, c);
            Multiply333.multiply0(ownRows, ofs, b, c);
            for (int i = 0; i < odeRows.length; i++) {
                assertEquals(Double.doubleToRawLongBits(odeRows[i]), Double.doubleToRawLongBits(ownRows[i]),
                        "b c into rows at " + ofs + ", number " + i + ", case " + n);
            }
        }
    }

    @Test
    void aMatrixTimesAVectorInArraysIsOdesBitForBit() {
        for (int n = 0; n < 20000; n++) {
            double[] b = new double[16];
            double[] c = new double[8];
            for (int i = 0; i < b.length; i++) {
                b[i] = entry();
            }
            for (int i = 0; i < c.length; i++) {
                c[i] = entry();
            }
            int ofsA = pick.nextInt(5);
            int ofsB = pick.nextInt(5);
            int ofsC = pick.nextInt(5);
            double[] ode = new double[8];
            double[] own = new double[8];
            OdeMath.dMultiply0_331(ode, ofsA, b, ofsB, c, ofsC);
            Multiply333.multiply0_331(own, ofsA, b, ofsB, c, ofsC);
            for (int i = 0; i < ode.length; i++) {
                assertEquals(Double.doubleToRawLongBits(ode[i]), Double.doubleToRawLongBits(own[i]),
                        "B c at " + ofsA + ", " + ofsB + ", " + ofsC + ", number " + i + ", case " + n);
            }
        }
    }

    @Test
    void aMatrixTimesAVectorIsOdesBitForBit() {
        for (int n = 0; n < 20000; n++) {
            DMatrix3 b = matrix();
            DVector3 c = new DVector3(entry(), entry(), entry());
            DVector3 ode = new DVector3();
            DVector3 own = new DVector3();
            OdeMath.dMultiply0_331(ode, b, c);
            Multiply333.multiply0_331(own, b, c);
            assertSame(ode, own, "b c, case " + n);
            ode.set(c);
            own.set(c);
            OdeMath.dMultiply0_331(ode, b, ode);
            Multiply333.multiply0_331(own, b, own);
            assertSame(ode, own, "c := b c, case " + n);
        }
    }

    /** QuickStep's stage 0 builds its implicit gyroscopic tensor as ODE4j's calls did. */
    @Test
    void theImplicitInertiaIsOdesBitForBit() {
        for (int n = 0; n < 20000; n++) {
            DMatrix3 inertia = matrix();
            DVector3 momentum = new DVector3(entry(), entry(), entry());
            double h = pick.nextInt(4) == 0 ? entry() : 0.005;
            DMatrix3 ode = matrix();
            ode.setZero();
            OdeMath.dSetCrossMatrixMinus(ode, momentum);
            ode.scale(h);
            ode.add(inertia);
            DMatrix3 own = matrix();
            DxQuickStep.implicitInertia(own, momentum, h, inertia);
            assertSame(ode, own, "h [L]x- + I, case " + n);
        }
    }

    @Test
    void aProductIntoItsOwnFactorIsOdes() {
        for (int n = 0; n < 2000; n++) {
            DMatrix3 b = matrix();
            DMatrix3 c = matrix();
            DMatrix3 ode = new DMatrix3(b);
            DMatrix3 own = new DMatrix3(b);
            OdeMath.dMultiply0_333(ode, ode, c);
            Multiply333.multiply0(own, own, c);
            assertSame(ode, own, "b := b c, case " + n);
            ode.set(c);
            own.set(c);
            OdeMath.dMultiply2_333(ode, b, ode);
            Multiply333.multiply2(own, b, own);
            assertSame(ode, own, "c := b c^T, case " + n);
        }
    }

    private DMatrix3 matrix() {
        DMatrix3 m = new DMatrix3();
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m.set(i, j, entry());
            }
        }
        return m;
    }

    private double entry() {
        switch (pick.nextInt(8)) {
            case 0:
                return 0.0;
            case 1:
                return -0.0;
            case 2:
                return pick.nextDouble(-1, 1) * Math.pow(10, pick.nextInt(-12, 12));
            default:
                return pick.nextDouble(-1, 1);
        }
    }

    private static void assertSame(DMatrix3 expected, DMatrix3 actual, String what) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                assertEquals(Double.doubleToRawLongBits(expected.get(i, j)), Double.doubleToRawLongBits(actual.get(i, j)),
                        what + ", entry " + i + j);
            }
        }
    }

    private static void assertSame(DVector3 expected, DVector3 actual, String what) {
        for (int i = 0; i < 3; i++) {
            assertEquals(Double.doubleToRawLongBits(expected.get(i)), Double.doubleToRawLongBits(actual.get(i)),
                    what + ", entry " + i);
        }
    }
}
